#include "compile/compile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../cli/run_tool.h"
#include "image/image_io.h"
#include "pov/emit_camera.h"
#include "test_temp.h"
#include "util/atomic_file.h"
#include "util/csv.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::string temp_dir(const std::string& name) {
    const fs::path d = mirage::testing::test_temp_path("mirage_compile_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d.string();
}

// A small desert: the paper profile, a level camera, two spheres.
const char* kDesert = R"(#version 3.7;
#declare Mirage_Preset = "paper";
#declare Mirage_Tolerance = 0.5;
#include "mirage.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, 0> look_at <0, 1.5, 10> right x * image_width / image_height angle 60 }
light_source { <-30, 60, -20>, color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 color rgb <0.8, 0.85, 0.95>] [1 color rgb <0.1, 0.25, 0.7>] } } }
plane { y, 0 pigment { checker color rgb <0.85, 0.72, 0.5>, color rgb <0.7, 0.55, 0.35> scale 2 } }
sphere { <-2.5, 1.6, 14>, 1 pigment { color rgb <0.8, 0.15, 0.1> } finish { reflection 0.25 } }
sphere { < 2.5, 1.6, 14>, 1 pigment { color rgb <0.15, 0.35, 0.8> } }
)";

CompileOptions options(const std::string& scene, const std::string& dir, int width, int height) {
    CompileOptions o;
    o.scene = scene;
    o.width = width;
    o.height = height;
    o.out_dir = dir + "/out";
    return o;
}

std::string write_scene(const std::string& dir, const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

TEST(Compile, WritesTheIncludeIniTableAndReport) {
    const std::string dir = temp_dir("outputs");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    CompileOptions o = options(scene, dir, 64, 48);
    auto r = compile_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_GT(r->layers, 10);
    EXPECT_EQ(r->layout, "nested");
    EXPECT_LE(r->max_trace_level, 255);
    EXPECT_EQ(r->pixels, 64 * 48);
    EXPECT_LE(r->p50_error_px, r->p95_error_px);
    EXPECT_LE(r->p95_error_px, r->max_error_px);
    for (const auto& p : {r->include_path, r->ini_path, r->csv_path, r->report_path})
        EXPECT_TRUE(fs::exists(p)) << p;
    // The layer table reads back: one row per layer, indices as POV-Ray gets them.
    auto csv = read_csv_file(r->csv_path);
    ASSERT_TRUE(csv.ok()) << csv.message();
    EXPECT_EQ(static_cast<int>(csv->rows.size()), r->layers + 1);
    // The .ini names the template, the size and the declaration mirage.inc looks for.
    auto ini = read_file(r->ini_path);
    ASSERT_TRUE(ini.ok());
    EXPECT_NE(ini->find("Width=64"), std::string::npos);
    EXPECT_NE(ini->find("Declare=Mirage_Compiled=1"), std::string::npos);
    EXPECT_NE(ini->find("Bounding_Method=2"), std::string::npos);
    EXPECT_NE(ini->find("Antialias=Off"), std::string::npos);
    auto inc = read_file(r->include_path);
    ASSERT_TRUE(inc.ok());
    EXPECT_NE(inc->find("max_trace_level 256"), std::string::npos);
    EXPECT_NE(inc->find("no_shadow"), std::string::npos);
    // The template is untouched.
    EXPECT_EQ(*read_file(scene), kDesert);
}

TEST(Compile, NoAtmosphereMeansNoLayers) {
    const std::string dir = temp_dir("plain");
    std::string text = kDesert;
    text.replace(text.find("#declare Mirage_Preset = \"paper\";"), 34, "");
    const std::string scene = write_scene(dir, "plain.pov", text);
    CompileOptions o = options(scene, dir, 32, 24);
    auto r = compile_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->layers, 0);
    EXPECT_EQ(r->mode, "none");
    EXPECT_EQ(r->max_error_px, 0.0);
}

TEST(Compile, ATinyIndexChangeNeedsNoLayers) {
    // eta1 = 1e-9: no camera ray bends by a tenth of a pixel within 60 m.
    const std::string dir = temp_dir("flat");
    std::string text = kDesert;
    text.replace(text.find("#declare Mirage_Preset = \"paper\";"), 34,
                 "#declare Mirage_Profile = \"inferior\"; #declare Mirage_Eta0 = 1.0003; "
                 "#declare Mirage_Eta1 = 1e-9; #declare Mirage_Alpha = 2.3;");
    const std::string scene = write_scene(dir, "flat.pov", text);
    CompileOptions o = options(scene, dir, 32, 24);
    auto r = compile_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->layers, 0);
    ASSERT_FALSE(r->left_out.empty());
    EXPECT_NE(r->left_out.front().find("no camera ray bends"), std::string::npos);
}

TEST(Compile, ErrorMapHoldsEveryPixelCentresError) {
    const std::string dir = temp_dir("error_map");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    CompileOptions o = options(scene, dir, 32, 24);
    o.error_map = dir + "/errors.exr";
    auto r = compile_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_EQ(r->pixel_error_px.size(), 32u * 24u);
    auto map = read_image(o.error_map);
    ASSERT_TRUE(map.ok()) << map.message();
    ASSERT_EQ(map->width, 32);
    ASSERT_EQ(map->height, 24);
    float worst = 0.0f;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            EXPECT_EQ(map->at(x, y).x, r->pixel_error_px[y * 32 + x]);
            EXPECT_EQ(map->at(x, y).y, r->pixel_shift_rows[y * 32 + x]);
            EXPECT_EQ(map->at(x, y).z, r->pixel_reflection_error_px[y * 32 + x]);
            worst = std::max(worst, map->at(x, y).x);
        }
    EXPECT_FLOAT_EQ(worst, static_cast<float>(r->max_seen_error_px));
    o.error_map = dir + "/errors.png";
    auto refused = compile_scene(o);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.message(),
              "--error-map " + o.error_map + ": the error map is written as OpenEXR, name it .exr");
}

TEST(Compile, AReplacedAtmosphereIsTheOneFitted) {
    // The same scene fitted to another profile: other layers, and the report names it.
    const std::string dir = temp_dir("replaced");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    CompileOptions o = options(scene, dir, 32, 24);
    auto own = compile_scene(o);
    ASSERT_TRUE(own.ok()) << own.message();
    o.profile = Profile{ProfileKind::Inferior, 1.000233, 0.4584, 2.0 * 2.303};
    o.profile_label = "paper, alpha doubled";
    auto other = compile_scene(o);
    ASSERT_TRUE(other.ok()) << other.message();
    EXPECT_EQ(other->atmosphere, "paper, alpha doubled");
    EXPECT_LT(other->highest, 0.75 * own->highest);  // the index levels off twice as low
}

TEST(Compile, UniformModeGivesEqualLayers) {
    const std::string dir = temp_dir("uniform");
    const std::string scene = write_scene(dir, "u.pov", kDesert);
    CompileOptions o = options(scene, dir, 32, 24);
    o.layers = LayerMode::Uniform;
    o.layer_count = 20;
    auto r = compile_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->layers, 20);
    auto csv = read_csv_file(r->csv_path);
    ASSERT_TRUE(csv.ok());
    const double h1 = std::stod(csv->rows[0].fields[2]);
    for (int k = 1; k < 20; ++k)
        EXPECT_NEAR(std::stod(csv->rows[k].fields[2]), h1 * (k + 1), 1e-6 * (k + 1));
}

TEST(Compile, ErrorsNameTheDeclaration) {
    const std::string dir = temp_dir("errors");
    std::string text = kDesert;
    text.replace(text.find("#declare Mirage_Tolerance = 0.5;"), 32,
                 "#declare Mirage_Tolerence = 0.5;");
    const std::string scene = write_scene(dir, "typo.pov", text);
    CompileOptions o = options(scene, dir, 32, 24);
    auto r = compile_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(),
              scene + ":3:10: unknown setting Mirage_Tolerence (did you mean Mirage_Tolerance?)");
    EXPECT_FALSE(fs::exists(dir + "/out/mirage_layers.inc"));

    text = kDesert;
    text.replace(text.find("location <0, 1.5, 0>"), 20, "location <0, -1, 0>");
    write_scene(dir, "under.pov", text);
    o.scene = dir + "/under.pov";
    r = compile_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find("the camera at y = -1 is not above the ground of the atmosphere"),
              std::string::npos)
        << r.message();

    text = kDesert;
    text.replace(text.find("\"paper\""), 7, "\"sahara\"");
    write_scene(dir, "preset.pov", text);
    o.scene = dir + "/preset.pov";
    r = compile_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), dir +
                               "/preset.pov:2:10: Mirage_Preset: unknown preset 'sahara' (known: "
                               "paper, paper-superior, hot-road, cold-sea)");
}

// The compiled scene renders in stock POV-Ray with no ray cut off: its statistics show a
// largest trace level under 256, the one the compile report predicts.
TEST(Compile, PovRayRendersTheCompiledSceneWithinTheTraceLevelCeiling) {
    if (std::system("povray --version >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "povray not installed";
    const std::string dir = temp_dir("render");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    CompileOptions o = options(scene, dir, 80, 60);
    auto r = compile_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    const std::string log = dir + "/povray.log";
    ASSERT_EQ(std::system(("povray " + r->ini_path + " >" + log + " 2>&1").c_str()), 0);
    ASSERT_EQ(r->camera, "corrected");
    ASSERT_TRUE(crop_mesh_camera_render(r->image_path).ok());
    const std::string text = *read_file(log);
    const auto at = text.find("Max Level: ");
    ASSERT_NE(at, std::string::npos) << text;
    const int level = std::stoi(text.substr(at + 11));
    EXPECT_LT(level, 256);
    EXPECT_EQ(level, r->max_trace_level);
    EXPECT_TRUE(fs::exists(r->image_path));
}

// A corrected camera whose meshes would pass the face limit is refused before any work, with
// the figure, and nothing is written.
TEST(Compile, ACorrectedCameraTooLargeIsRefusedAtOnce) {
    const std::string dir = temp_dir("mesh_limit");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    CompileOptions o = options(scene, dir, 4000, 3000);
    auto r = compile_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find("--width 4000 --height 3000: the corrected camera would need "
                               "1.2e+07 mesh faces"),
              std::string::npos)
        << r.message();
    EXPECT_FALSE(fs::exists(o.out_dir));
    o.camera = CameraModel::Perspective;  // the scene's own camera needs no mesh
    o.width = 40;
    o.height = 30;
    EXPECT_TRUE(compile_scene(o).ok());
}

// POV-Ray's render through the corrected camera is cropped in place after it is written: an
// image that is a device is refused by name (the scene's own camera renders into it as it is).
TEST(Compile, TheCorrectedCamerasImageMustBeAFile) {
    const std::string dir = temp_dir("image_device");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    CompileOptions o = options(scene, dir, 16, 12);
    o.image = "/dev/null";
    auto r = compile_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find("/dev/null: POV-Ray's render through the corrected camera is read "
                               "back and cropped"),
              std::string::npos)
        << r.message();
    EXPECT_FALSE(fs::exists(o.out_dir));
    o.camera = CameraModel::Perspective;
    EXPECT_TRUE(compile_scene(o).ok());
}

TEST(CompileCli, JsonReportHasTheRequiredKeys) {
    const std::string dir = temp_dir("cli");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    auto run = testing::run_tool("compile " + scene + " -W 32 -H 24 -o " + dir + "/out --json");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    auto j = nlohmann::json::parse(run.out);
    for (const char* key : {"layers", "max_error_px", "p95_error_px", "max_crossings", "seconds"})
        EXPECT_TRUE(j.contains(key)) << key;
    run = testing::run_tool("compile " + dir + "/missing.pov -o " + dir + "/out");
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("missing.pov"), std::string::npos) << run.err;
}

TEST(Compile, IndexStepsAreRefusedForTheExponentialProfileWithWhatToDo) {
    const std::string dir = temp_dir("index_steps");
    const std::string scene = write_scene(dir, "small.pov", kDesert);
    CompileOptions o = options(scene, dir, 64, 48);
    o.layers = LayerMode::IndexSteps;
    o.layer_count = 32;
    auto r = compile_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find("small.pov: index steps"), std::string::npos) << r.message();
    EXPECT_NE(r.message().find("exponential profile"), std::string::npos) << r.message();
    EXPECT_NE(r.message().find("--layers uniform"), std::string::npos) << r.message();
    EXPECT_FALSE(fs::exists(dir + "/out"));
    EXPECT_EQ(*read_file(scene), kDesert);
}

}  // namespace
}  // namespace mirage
