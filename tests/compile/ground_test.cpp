// Mirage_Ground_Height: the atmosphere's ground where the scene's floor is (scene/ground.h).
#include "scene/ground.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compile/compile.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "scene/parser.h"
#include "test_temp.h"
#include "shading/fog.h"
#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::string temp_dir(const std::string& name) {
    const fs::path d = mirage::testing::test_temp_path("ground_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d.string();
}

std::string write_scene(const std::string& dir, const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The paper's desert with its floor at y = `floor` (and everything else moved with it).
std::string desert(double floor, const std::string& ground_line) {
    auto y = [&](double v) {
        std::ostringstream s;
        s << v + floor;
        return s.str();
    };
    return "#version 3.7;\n#declare Mirage_Preset = \"paper\";\n" + ground_line +
           "#include \"mirage.inc\"\n"
           "global_settings { assumed_gamma 1.0 }\n"
           "camera { location <0, " +
           y(1.5) + ", 0> look_at <0, " + y(1.5) +
           ", 10> right x * image_width / image_height angle 60 }\n"
           "light_source { <-30, " +
           y(60) +
           ", -20>, color rgb 1 }\n"
           "sky_sphere { pigment { gradient y color_map { [0 color rgb <0.8, 0.85, 0.95>] "
           "[1 color rgb <0.1, 0.25, 0.7>] } } }\n"
           "plane { y, " +
           y(0) +
           " pigment { checker color rgb <0.85, 0.72, 0.5>, color rgb "
           "<0.7, 0.55, 0.35> scale 2 translate <0, " +
           y(0) +
           ", 0> } }\n"
           "sphere { <-2.5, " +
           y(1.6) +
           ", 14>, 1 pigment { color rgb <0.8, 0.15, 0.1> } }\n"
           "sphere { < 2.5, " +
           y(1.6) + ", 14>, 1 pigment { color rgb <0.15, 0.35, 0.8> } }\n";
}

CompileOptions options(const std::string& scene, const std::string& out) {
    CompileOptions o;
    o.scene = scene;
    o.width = 48;
    o.height = 36;
    o.out_dir = out;
    return o;
}

TEST(Ground, TheMessageNamesThePlaneUnderTheCameraAndTheDeclaration) {
    const std::string dir = temp_dir("message");
    // A floor at y = -1 and a lower plane at -5, the camera at y = 0.
    const std::string scene = write_scene(dir, "floor.pov", R"(#declare Mirage_Preset = "hot-road";
#include "mirage.inc"
camera { location <0, 0, -10> look_at <0, 0, 0> }
plane { y, -1 pigment { rgb 1 } }
plane { y, -5 pigment { rgb 1 } }
sphere { <0, 0, 20>, 1 pigment { rgb 1 } }
)");
    auto r = compile_scene(options(scene, dir + "/out"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), scene +
                               ":3:1: the camera at y = 0 is not above the ground of the "
                               "atmosphere (y = 0; Mirage_Ground_Height moves it); the scene's "
                               "horizontal plane under the camera, at y = -1 (" +
                               scene +
                               ":4:1), is a likely ground: #declare Mirage_Ground_Height = -1; "
                               "(its lowest horizontal plane is at y = -5, " +
                               scene + ":5:1)");
    EXPECT_FALSE(fs::exists(dir + "/out/mirage_layers.inc"));
}

TEST(Ground, WithoutAPlaneTheMessageSaysHowLowTheObjectsReach) {
    const std::string dir = temp_dir("no_plane");
    const std::string scene = write_scene(dir, "float.pov", R"(#declare Mirage_Preset = "hot-road";
#include "mirage.inc"
camera { location <0, 0, -10> look_at <0, 0, 0> }
sphere { <0, 0, 20>, 1 pigment { rgb 1 } }
)");
    auto r = compile_scene(options(scene, dir + "/out"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find("no horizontal plane below the camera; its objects reach down "
                               "to y = -1: #declare Mirage_Ground_Height = -1; puts the ground "
                               "there"),
              std::string::npos)
        << r.message();
}

TEST(Ground, AMisspeltSettingIsCaught) {
    const std::string dir = temp_dir("typo");
    const std::string scene =
        write_scene(dir, "typo.pov", desert(-1.0, "#declare Mirage_Ground_Hieght = -1;\n"));
    auto r = compile_scene(options(scene, dir + "/out"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), scene +
                               ":3:10: unknown setting Mirage_Ground_Hieght (did you mean "
                               "Mirage_Ground_Height?)");
}

TEST(Ground, TheLayersOfALowerFloorAreTheSameLayersMovedDown) {
    const std::string dir = temp_dir("layers");
    const std::string at_zero = write_scene(dir, "zero.pov", desert(0.0, ""));
    const std::string lowered =
        write_scene(dir, "lowered.pov", desert(-1.0, "#declare Mirage_Ground_Height = -1;\n"));
    auto a = compile_scene(options(at_zero, dir + "/zero"));
    auto b = compile_scene(options(lowered, dir + "/lowered"));
    ASSERT_TRUE(a.ok()) << a.message();
    ASSERT_TRUE(b.ok()) << b.message();
    EXPECT_GT(a->layers, 10);
    EXPECT_EQ(a->layers, b->layers);
    EXPECT_NEAR(a->max_error_px, b->max_error_px, 1e-6);
    // The layer table holds heights above the ground: the same in both.
    EXPECT_EQ(read_text(a->csv_path), read_text(b->csv_path));
    // Every layer object of the include is moved up to the ground.
    const std::string inc = read_text(b->include_path);
    std::size_t objects = 0, moved = 0;
    for (std::size_t at = inc.find("interior {"); at != std::string::npos;
         at = inc.find("interior {", at + 1)) {
        ++objects;
    }
    for (std::size_t at = inc.find("translate <0, -1, 0>"); at != std::string::npos;
         at = inc.find("translate <0, -1, 0>", at + 1)) {
        ++moved;
    }
    EXPECT_GT(objects, 0u);
    EXPECT_EQ(objects, moved);
    EXPECT_EQ(read_text(a->include_path).find("translate"), std::string::npos);
}

TEST(Ground, TheTracerSeesTheSameMirageOverALowerFloor) {
    const std::string dir = temp_dir("trace");
    const std::string at_zero = write_scene(dir, "zero.pov", desert(0.0, ""));
    const std::string lowered =
        write_scene(dir, "lowered.pov", desert(-1.0, "#declare Mirage_Ground_Height = -1;\n"));
    const std::string wrong = write_scene(dir, "wrong.pov", desert(-1.0, ""));
    auto trace = [&](const std::string& scene, const std::string& png) {
        TraceOptions o;
        o.scene = scene;
        o.output = dir + "/" + png;
        o.width = 80;
        o.height = 60;
        o.progress = false;
        auto r = trace_scene(o);
        EXPECT_TRUE(r.ok()) << r.message();
        auto im = read_image(o.output);
        EXPECT_TRUE(im.ok());
        return im.ok() ? *im : Image(1, 1);
    };
    const Image a = trace(at_zero, "zero.png");
    const Image b = trace(lowered, "lowered.png");
    const Image c = trace(wrong, "wrong.png");
    auto same = compare_images(a, b, 2.5 / 255.0);
    auto other = compare_images(a, c, 2.5 / 255.0);
    ASSERT_TRUE(same.ok() && other.ok());
    EXPECT_LE(same->pixels_over, 3) << "PSNR " << same->psnr_db;
    // Without the setting the mirage is another one (the ground 1 m below the floor).
    EXPECT_GT(other->pixels_over, 200) << "PSNR " << other->psnr_db;
}

TEST(Ground, TheShadingIsTheSameOverALowerFloor) {
    // What the shading places in space moves down with the scene: a spotlight's point_at, a
    // patterned texture, a normal, a layered texture, an interior_texture and a ground fog
    // (the scene's textures move with its floor; the fog's turbulence cannot move in POV-Ray:
    // LowerSceneMovesEverythingWithAPlace checks it stays where it was).
    auto scene = [](double floor, const std::string& ground_line) {
        auto y = [&](double v) {
            std::ostringstream s;
            s << v + floor;
            return s.str();
        };
        const std::string up = "translate <0, " + y(0) + ", 0>";
        return "#version 3.7;\n#declare Mirage_Preset = \"paper\";\n" + ground_line +
               "#include \"mirage.inc\"\n"
               "global_settings { assumed_gamma 1.0 }\n"
               "camera { location <0, " +
               y(1.5) + ", 0> look_at <0, " + y(1.2) +
               ", 10> right x * image_width / image_height angle 60 }\n"
               "light_source { <-3, " +
               y(8) + ", 2>, color rgb 1 spotlight point_at <0, " + y(0) +
               ", 12> radius 12 falloff 20 }\n"
               "light_source { <30, " +
               y(40) +
               ", -20>, color rgb 0.4 }\n"
               "fog { fog_type 2 distance 30 color rgb <0.8, 0.8, 0.9> fog_offset " +
               y(0.3) +
               " fog_alt 0.6 }\n"
               "plane { y, " +
               y(0) +
               " texture { pigment { bozo color_map { [0 rgb <0.8, 0.7, 0.5>] [1 rgb "
               "<0.4, 0.3, 0.2>] } scale 0.7 } normal { bumps 0.6 scale 0.3 } " +
               up +
               " } }\n"
               "sphere { <-2, " +
               y(1.2) +
               ", 12>, 1 texture { pigment { rgb <0.2, 0.4, 0.9> } } texture { pigment { "
               "gradient y color_map { [0.5 rgbt 1] [0.5 rgb <1, 0.9, 0.1>] } scale 0.5 } " +
               up +
               " } }\n"
               "cylinder { <2, " +
               y(0) + ", 12>, <2, " + y(2) +
               ", 12>, 0.9 open texture { pigment { rgb 0.9 } } interior_texture { pigment "
               "{ marble color_map { [0 rgb <0.9, 0.1, 0.1>] [1 rgb <0.1, 0.9, 0.1>] } scale "
               "0.4 } " +
               up + " } }\n";
    };
    const std::string dir = temp_dir("shading");
    const std::string at_zero = write_scene(dir, "zero.pov", scene(0.0, ""));
    const std::string lowered =
        write_scene(dir, "lowered.pov", scene(-1.0, "#declare Mirage_Ground_Height = -1;\n"));
    auto trace = [&](const std::string& file, const std::string& png) {
        TraceOptions o;
        o.scene = file;
        o.output = dir + "/" + png;
        o.width = 80;
        o.height = 60;
        o.progress = false;
        auto r = trace_scene(o);
        EXPECT_TRUE(r.ok()) << r.message();
        auto im = read_image(o.output);
        EXPECT_TRUE(im.ok());
        return im.ok() ? *im : Image(1, 1);
    };
    const Image a = trace(at_zero, "zero.png");
    const Image b = trace(lowered, "lowered.png");
    auto same = compare_images(a, b, 2.5 / 255.0);
    ASSERT_TRUE(same.ok());
    EXPECT_LE(same->pixels_over, 3) << "PSNR " << same->psnr_db;
}

TEST(Ground, LowerSceneMovesEverythingWithAPlace) {
    auto s = parse_scene_text(R"(
camera { location <0, 2, -5> look_at <0, 2, 0> }
light_source { <1, 10, 1> color rgb 1 }
sphere { <0, 3, 0>, 1 pigment { gradient y } }
)",
                              "scene.pov", ParseOptions{});
    ASSERT_TRUE(s.ok()) << s.message();
    Scene scene = *s;
    lower_scene(scene, 2.5);
    EXPECT_DOUBLE_EQ(scene.camera.location.y, -0.5);
    EXPECT_EQ(scene.camera.direction, s->camera.direction);
    EXPECT_DOUBLE_EQ(scene.lights[0].location.y, 7.5);
    EXPECT_DOUBLE_EQ(scene.primitives[0].transform.matrix[3][1], -2.5);
    EXPECT_DOUBLE_EQ(scene.primitives[0].texture.pigment.transform.matrix[3][1], -2.5);
}

TEST(Ground, LowerSceneKeepsTheShadingWhereItWas) {
    auto s = parse_scene_text(R"(
camera { location <0, 2, -5> look_at <0, 2, 0> }
light_source { <1, 10, 1> color rgb 1 spotlight point_at <0, 3, 4> }
fog { fog_type 2 distance 5 color rgb 0.8 fog_offset 1.5 fog_alt 0.5 turbulence 0.7 }
cylinder { <0, 3, 0>, <0, 4, 0>, 1 open
           texture { pigment { rgb 1 } normal { bumps 0.5 } }
           interior_texture { pigment { marble } } }
)",
                              "scene.pov", ParseOptions{});
    ASSERT_TRUE(s.ok()) << s.message();
    Scene scene = *s;
    lower_scene(scene, 2.5);
    EXPECT_DOUBLE_EQ(scene.lights[0].point_at.y, 0.5);
    const Primitive& p = scene.primitives[0];
    ASSERT_TRUE(p.texture.normal && p.interior_texture);
    EXPECT_DOUBLE_EQ(p.texture.normal->transform.matrix[3][1], -2.5);
    EXPECT_DOUBLE_EQ(p.interior_texture->pigment.transform.matrix[3][1], -2.5);
    // The fog seen along a ray is the same ray's fog before lowering, its turbulence too.
    const glm::dvec3 origin(0.3, 2.0, -5.0), direction = glm::normalize(glm::dvec3(0.1, -0.2, 1));
    const glm::dvec3 down(0.0, 2.5, 0.0);
    for (double depth : {1.0, 3.0, 7.0}) {
        const glm::dvec3 before = apply_fog(s->fogs, origin, direction, depth, glm::dvec3(0.2), 2);
        const glm::dvec3 after =
            apply_fog(scene.fogs, origin - down, direction, depth, glm::dvec3(0.2), 2);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(after[i], before[i], 1e-12) << depth;
    }
    // Without the turbulence's correction the fog would differ: the check can fail.
    std::vector<Fog> moved = scene.fogs;
    moved[0].lowered_by = glm::dvec3(0.0);
    const glm::dvec3 before = apply_fog(s->fogs, origin, direction, 7.0, glm::dvec3(0.2), 2);
    const glm::dvec3 wrong = apply_fog(moved, origin - down, direction, 7.0, glm::dvec3(0.2), 2);
    EXPECT_GT(glm::length(wrong - before), 1e-6);
}

}  // namespace
}  // namespace mirage
