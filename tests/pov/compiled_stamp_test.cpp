// A compiled atmosphere stops POV-Ray at parse time when it is rendered for something it was
// not compiled for (pov/emit_stamp.h):
//
//  1. settings_check, read by POV-Ray itself: a number, a vector and a string setting pass as
//     declared (an expression included) and stop the parse, naming the setting and both
//     values, when another value, a missing declaration or a new one comes instead.
//  2. End to end: the compiled desert renders as compiled; after the template's Mirage_
//     settings change it stops with the setting named; the layers rendered through the
//     template's own camera stop with the .ini to render instead; the perspective camera's
//     layers rendered at another size stop with both sizes.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../trace/povray_runner.h"
#include "compile/compile.h"
#include "pov/emit_stamp.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::povray_available;
using testing::PovRayRun;
using testing::run_povray;
using testing::test_dir;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

Declared declared(std::variant<double, glm::dvec3, std::string> v) {
    Declared d;
    d.value = std::move(v);
    return d;
}

// The three settings as compiled: a number, a vector, a string, and one not declared.
std::string compiled_check() {
    return settings_check({{"Mirage_Eta0", declared(1.000233)},
                           {"Mirage_Inversion", declared(glm::dvec3(50, 60, 2))},
                           {"Mirage_Preset", declared(std::string("hot-road"))},
                           {"Mirage_Extent", std::nullopt}});
}

// A scene that declares `declarations`, then runs the check.
PovRayRun parse_with(const fs::path& dir, const std::string& declarations) {
    write(dir / "check.inc", compiled_check());
    write(dir / "scene.pov", "#version 3.7;\n" + declarations +
                                 "\n#include \"check.inc\"\n"
                                 "camera { location -3 * z look_at 0 }\n"
                                 "sphere { 0, 1 pigment { rgb 1 } }\n");
    return run_povray(dir, "+W8 +H8 scene.pov");
}

const char* kAsCompiled =
    "#declare Mirage_Eta0 = 1 + 2.33e-4;\n"
    "#declare Mirage_Inversion = <50, 60, 2>;\n"
    "#declare Mirage_Preset = \"hot-road\";";

TEST(SettingsCheck, TheSettingsAsCompiledPass) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const PovRayRun r = parse_with(test_dir("compiled_stamp", "same"), kAsCompiled);
    EXPECT_TRUE(r.ok) << r.log;
}

struct Changed {
    const char* name;
    std::string declarations;
    std::string message;  // what POV-Ray's log must hold
};

class SettingsChanged : public ::testing::TestWithParam<Changed> {};

TEST_P(SettingsChanged, StopTheParseNamingTheSetting) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Changed& c = GetParam();
    const PovRayRun r = parse_with(test_dir("compiled_stamp", c.name), c.declarations);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.log.find("Parse halted by #error"), std::string::npos) << r.log;
    EXPECT_NE(r.log.find(c.message), std::string::npos) << r.log;
}

std::string with(const std::string& from, const std::string& to) {
    std::string s = kAsCompiled;
    s.replace(s.find(from), from.size(), to);
    return s;
}

INSTANTIATE_TEST_SUITE_P(
    Each, SettingsChanged,
    ::testing::Values(
        Changed{"number", with("1 + 2.33e-4", "1.000234"),
                "mirage: Mirage_Eta0 = 1.000234 now, compiled with 1.000233: run mirage compile "
                "again"},
        Changed{"vector", with("<50, 60, 2>", "<50, 61, 2>"),
                "mirage: Mirage_Inversion = <50.000000, 61.000000, 2.000000> now, compiled with "
                "<50, 60, 2>"},
        Changed{"string", with("\"hot-road\"", "\"paper\""),
                "mirage: Mirage_Preset = \"paper\" now, compiled with \"hot-road\""},
        Changed{"missing", with("#declare Mirage_Eta0 = 1 + 2.33e-4;", ""),
                "mirage: Mirage_Eta0 is not declared now, compiled with 1.000233"},
        Changed{"added", std::string(kAsCompiled) + "\n#declare Mirage_Extent = 100;",
                "mirage: Mirage_Extent is declared now, compiled without it"}),
    [](const ::testing::TestParamInfo<Changed>& i) { return std::string(i.param.name); });

const char* kDesert = R"(#version 3.7;
#declare Mirage_Profile   = "inferior";
#declare Mirage_Eta0      = 1.000233;
#declare Mirage_Eta1      = 0.4584;
#declare Mirage_Alpha     = 2.303;
#declare Mirage_Tolerance = 0.5;
#include "mirage.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, 0> look_at <0, 1.5, 10> right x * image_width / image_height angle 60 }
sky_sphere { pigment { color rgb <0, 0, 1> } }
plane { y, 0 pigment { color rgb <1, 1, 0> } finish { ambient 1 diffuse 0 } }
sphere { <-2.5, 1.6, 14>, 1 pigment { color rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }
)";

Result<CompileReport> compile_desert(const fs::path& dir, CameraModel camera) {
    write(dir / "desert.pov", kDesert);
    CompileOptions o;
    o.scene = (dir / "desert.pov").string();
    o.width = 32;
    o.height = 24;
    o.out_dir = (dir / "out").string();
    o.camera = camera;
    o.progress = false;
    o.library_paths = {std::string(MIRAGE_SOURCE_DIR) + "/pov_includes"};
    return compile_scene(o);
}

TEST(CompiledStamp, TheTemplateChangedAfterTheCompileStopsTheRender) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = test_dir("compiled_stamp", "template");
    auto r = compile_desert(dir, CameraModel::Corrected);
    ASSERT_TRUE(r.ok()) << r.message();
    const PovRayRun as_compiled = run_povray(dir, q(r->ini_path));
    EXPECT_TRUE(as_compiled.ok) << as_compiled.log;
    std::string text = kDesert;
    text.replace(text.find("0.4584"), 6, "0.5");
    write(dir / "desert.pov", text);
    const PovRayRun changed = run_povray(dir, q(r->ini_path));
    EXPECT_FALSE(changed.ok);
    EXPECT_NE(
        changed.log.find(
            "mirage: Mirage_Eta1 = 0.500000 now, compiled with 0.4584: run mirage compile again"),
        std::string::npos)
        << changed.log;
}

TEST(CompiledStamp, CorrectedLayersThroughTheTemplatesOwnCameraStop) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = test_dir("compiled_stamp", "own_camera");
    auto r = compile_desert(dir, CameraModel::Corrected);
    ASSERT_TRUE(r.ok()) << r.message();
    const PovRayRun own = run_povray(dir, "+W32 +H24 +L" + q(dir / "out") + " +L" +
                                              q(fs::path(MIRAGE_SOURCE_DIR) / "pov_includes") +
                                              " Declare=Mirage_Compiled=1 desert.pov");
    EXPECT_FALSE(own.ok);
    EXPECT_NE(own.log.find("mirage: these layers are for the corrected camera: render desert.ini "
                           "beside them"),
              std::string::npos)
        << own.log;
}

TEST(CompiledStamp, PerspectiveLayersAtAnotherSizeStopWithBothSizes) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = test_dir("compiled_stamp", "perspective_size");
    auto r = compile_desert(dir, CameraModel::Perspective);
    ASSERT_TRUE(r.ok()) << r.message();
    const PovRayRun same = run_povray(dir, q(r->ini_path));
    EXPECT_TRUE(same.ok) << same.log;
    const PovRayRun other = run_povray(dir, q(r->ini_path) + " +W64 +H48");
    EXPECT_FALSE(other.ok);
    EXPECT_NE(other.log.find("this atmosphere was compiled for 32x24, not 64x48"),
              std::string::npos)
        << other.log;
}

}  // namespace
}  // namespace mirage
