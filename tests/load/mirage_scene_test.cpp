// The floor every command loads a scene through: one check, one message, for each value.
#include "load/mirage_scene.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/ground.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

class MirageSceneLoad : public ::testing::Test {
  protected:
    fs::path dir_ = fs::path(::testing::TempDir()) / ("mirage_load_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }

    /// A scene with `settings` before a level camera at `location` and a sphere.
    std::string scene(const std::string& settings, const std::string& location = "<0, 1.5, 0>") {
        const fs::path p = dir_ / "s.pov";
        std::ofstream(p) << settings << "\ncamera { location " << location
                         << " look_at <0, 1.5, 10> }\nsphere { <0, 1, 10>, 1 }\n";
        return p.string();
    }

    std::string load_error(const std::string& path, SceneLoadOptions o = {}) {
        o.scene = path;
        auto r = load_mirage_scene(o);
        EXPECT_FALSE(r.ok());
        return r.ok() ? std::string() : r.message();
    }
};

TEST_F(MirageSceneLoad, ReadsTheSettingsAndTheFilesOfTheScene) {
    std::ofstream(dir_ / "air.inc") << "#declare Mirage_Preset = \"hot-road\";\n";
    SceneLoadOptions o;
    o.scene = scene("#include \"air.inc\"\n#declare Mirage_Tolerance = 0.25;");
    o.width = 64;
    o.height = 48;
    auto r = load_mirage_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_TRUE(r->settings.declared);
    EXPECT_EQ(r->settings.profile_label, "hot-road (inferior)");
    EXPECT_DOUBLE_EQ(r->settings.tolerance_px, 0.25);
    ASSERT_EQ(r->scene.files.size(), 2u);
    EXPECT_EQ(r->scene.files[1], (dir_ / "air.inc").string());
    // The include paths: the user's first, then the scene's directory and the defaults.
    EXPECT_EQ(r->parse_options.library_paths.front(), fs::absolute(dir_).string());
    EXPECT_EQ(r->parse_options.image_width, 64);
    // The options replace the scene's values.
    o.tolerance_px = 2.0;
    o.layers = LayerMode::Uniform;
    o.layer_count = 12;
    auto replaced = load_mirage_scene(o);
    ASSERT_TRUE(replaced.ok()) << replaced.message();
    EXPECT_DOUBLE_EQ(replaced->settings.tolerance_px, 2.0);
    EXPECT_EQ(replaced->settings.layers, LayerMode::Uniform);
    EXPECT_EQ(replaced->settings.layer_count, 12);
}

TEST_F(MirageSceneLoad, OneMessageForEachValueOutOfRange) {
    const std::string s = scene("#declare Mirage_Preset = \"paper\";");
    SceneLoadOptions o;
    o.width = 0;
    EXPECT_EQ(load_error(s, o), "image size 0x240 must be 1 to 20000 pixels each way");
    o = {};
    o.tolerance_px = 1e-300;
    EXPECT_EQ(load_error(s, o),
              "--tolerance 1e-300: the tolerance must be from 0.001 to 1000 pixels");
    o = {};
    o.layer_count = 1000000000;
    EXPECT_EQ(load_error(s, o),
              "--count 1e+09: the layer count must be a whole number from 1 to 4096");
    // The same checks for the scene's own values, with their place.
    EXPECT_EQ(load_error(scene("#declare Mirage_Preset = \"paper\";\n"
                               "#declare Mirage_Tolerance = 1e-300;")),
              s + ":2:10: Mirage_Tolerance = 1e-300: the tolerance must be from 0.001 to 1000 "
                  "pixels");
    EXPECT_EQ(load_error(scene("#declare Mirage_Preset = \"paper\";\n"
                               "#declare Mirage_Layer_Count = 1e9;")),
              s + ":2:10: Mirage_Layer_Count = 1e+09: the layer count must be a whole number "
                  "from 1 to 4096");
    EXPECT_EQ(load_error(scene("#declare Mirage_Profile = \"inferior\";\n"
                               "#declare Mirage_Eta0 = 1.0003;\n"
                               "#declare Mirage_Eta1 = 0.1;\n"
                               "#declare Mirage_Alpha = 1e308;")),
              s + ":4:10: Mirage_Alpha = 1e+308 must be from 1e-09 to 1e+09 (1/m)");
    EXPECT_EQ(load_error(scene("#declare Mirage_Profile = \"inferior\";\n"
                               "#declare Mirage_Eta0 = 1e308;\n"
                               "#declare Mirage_Eta1 = 0.1;\n"
                               "#declare Mirage_Alpha = 1;")),
              s + ":2:10: Mirage_Eta0 = 1e+308 must be a refractive index from 1 to 10");
    EXPECT_EQ(load_error(scene("#declare Mirage_Preset = \"paper\";\n"
                               "#declare Mirage_Unit = 1e6;")),
              s + ":2:10: Mirage_Unit = 1e+06 must be from 0.001 to 1000 (metres per unit)");
    EXPECT_EQ(load_error(scene("#declare Mirage_Profile = \"inferior\";\n"
                               "#declare Mirage_Eta0 = 1.0003;\n"
                               "#declare Mirage_Eta1 = 0.1;\n"
                               "#declare Mirage_Alpha = 1e8;\n"
                               "#declare Mirage_Unit = 100;")),
              s + ":5:10: Mirage_Unit = 100 makes alpha 1e+10 per scene unit, outside 1e-09 to "
                  "1e+09");
}

TEST_F(MirageSceneLoad, TheCameraMustBeWithinReach) {
    const std::string far = scene("#declare Mirage_Preset = \"paper\";", "<0, 1e308, 0>");
    EXPECT_EQ(load_error(far),
              far +
                  ":2:1: the camera is at y = 1e+308: mirage follows scenes within 1e+09 units "
                  "of the origin");
    // A camera whose pixels are finer than paths are sampled to.
    const fs::path p = dir_ / "narrow.pov";
    std::ofstream(p) << "camera { location <0, 1.5, 0> look_at <0, 1.5, 10> angle 1e-6 }\n";
    EXPECT_EQ(load_error(p.string()),
              p.string() +
                  ":1:1: one pixel of this camera spans 5.47e-11 rad at 320x240, "
                  "less than the 1e-07 rad mirage samples paths for (widen the view)");
}

TEST_F(MirageSceneLoad, AFileThatIsNoSceneSaysWhy) {
    EXPECT_EQ(load_error(dir_.string()), dir_.string() + ": is a directory, not a scene file");
    const fs::path empty = dir_ / "empty.pov";
    std::ofstream{empty};
    EXPECT_EQ(load_error(empty.string()),
              empty.string() + ": the file is empty: there is no scene to read");
    EXPECT_EQ(load_error("/dev/zero"),
              "/dev/zero: is not a regular file (a device, a pipe or a socket?): scenes are read "
              "from files");
}

TEST_F(MirageSceneLoad, ASceneWithoutACameraIsRefusedFirst) {
    // Before its settings are read: the bad tolerance is not the message.
    const fs::path p = dir_ / "nocam.pov";
    std::ofstream(p) << "#declare Mirage_Preset = \"paper\";\n#declare Mirage_Tolerance = 0;\n"
                        "sphere { <0, 1, 10>, 1 }\n";
    EXPECT_EQ(load_error(p.string()),
              p.string() +
                  ": the scene has no camera: POV-Ray would render it from its default camera at "
                  "the origin, on the ground; add one, such as camera { location <0, 1.7, -10> "
                  "look_at <0, 1.7, 0> }");
}

TEST_F(MirageSceneLoad, TheIncludeOfMirageIncIsCheckedAsTheCommandAsks) {
    const std::string message =
        ": add #include \"mirage.inc\" after its #version line (plain POV-Ray finds it with "
        "+Lpov_includes)";
    // Settings without the include: POV-Ray would render no mirage.
    const std::string bare = scene("#version 3.7;\n#declare Mirage_Preset = \"paper\";");
    SceneLoadOptions o;
    o.mirage_inc = MirageIncCheck::IfDeclared;
    EXPECT_EQ(load_error(bare, o),
              bare +
                  ": the scene never includes mirage.inc, so POV-Ray renders it without the "
                  "atmosphere it declares (Mirage_Preset at " +
                  bare + ":2:10)" + message);
    o.mirage_inc = MirageIncCheck::Always;
    EXPECT_NE(load_error(bare, o).find("never includes mirage.inc"), std::string::npos);
    o.mirage_inc = MirageIncCheck::None;  // the loader's own default: not checked
    o.scene = bare;
    EXPECT_TRUE(load_mirage_scene(o).ok());
    // No atmosphere and no include: a plain scene, refused only where the include is required.
    const std::string plain = scene("#version 3.7;");
    o.mirage_inc = MirageIncCheck::IfDeclared;
    o.scene = plain;
    EXPECT_TRUE(load_mirage_scene(o).ok());
    o.mirage_inc = MirageIncCheck::Always;
    EXPECT_EQ(load_error(plain, o),
              plain +
                  ": the scene never includes mirage.inc and declares no atmosphere: there is "
                  "nothing to compile; add #include \"mirage.inc\" after its #version line "
                  "(plain POV-Ray finds it with +Lpov_includes), after a Mirage_ setting such "
                  "as #declare Mirage_Preset = \"hot-road\"; (pov_includes/mirage.inc lists "
                  "them)");
    // Included through another include: found.
    std::ofstream(dir_ / "air.inc") << "#declare Mirage_Preset = \"paper\";\n"
                                       "#include \"mirage.inc\"\n";
    o.scene = scene("#version 3.7;\n#include \"air.inc\"");
    auto loaded = load_mirage_scene(o);
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    EXPECT_TRUE(includes_mirage_inc(loaded->scene));
}

TEST_F(MirageSceneLoad, TheShippedScenesIncludeMirageInc) {
    for (const auto& e : fs::directory_iterator(fs::path(MIRAGE_SOURCE_DIR) / "scenes")) {
        if (e.path().extension() != ".pov") continue;
        SceneLoadOptions o;
        o.scene = e.path().string();
        o.strict = false;
        o.width = 64;
        o.height = 48;
        o.mirage_inc = MirageIncCheck::Always;
        auto r = load_mirage_scene(o);
        EXPECT_TRUE(r.ok()) << r.message();
    }
}

TEST_F(MirageSceneLoad, ACameraUnderTheGroundHasOneMessage) {
    SceneLoadOptions o;
    o.scene = scene("#declare Mirage_Preset = \"paper\";\nplane { y, 0 }", "<0, -0.5, 0>");
    auto r = load_mirage_scene(o);
    ASSERT_TRUE(r.ok()) << r.message();
    int asked = 0;
    auto lowest = [&]() -> std::optional<double> {
        ++asked;
        return 0.0;
    };
    const Status s = check_camera_above_ground(r->scene, 0.0, lowest);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message(), camera_below_ground_message(r->scene, 0.0, 0.0));
    EXPECT_NE(s.message().find(o.scene + ":3:1: the camera at y = -0.5 is not above the ground"),
              std::string::npos)
        << s.message();
    // Above the ground (Mirage_Ground_Height lowers it): accepted, the objects not looked at.
    asked = 0;
    EXPECT_TRUE(check_camera_above_ground(r->scene, -1.0, lowest).ok());
    EXPECT_EQ(asked, 0);
    EXPECT_FALSE(check_camera_above_ground(r->scene, -0.5, lowest).ok());  // on it: refused
}

TEST_F(MirageSceneLoad, TheClockAndTheDeclaredNumbersReachTheParse) {
    const fs::path p = dir_ / "frame.pov";
    std::ofstream(p) << "camera { location <0, 1 + clock + Lift, 0> look_at <0, 1, 10> }\n"
                        "#declare On = clock_on;\n";
    SceneLoadOptions o;
    o.scene = p.string();
    o.declares = {{"Lift", 2.0}};
    auto still = load_mirage_scene(o);
    ASSERT_TRUE(still.ok()) << still.message();
    EXPECT_DOUBLE_EQ(still->scene.camera.location.y, 3.0);
    EXPECT_EQ(std::get<double>(still->scene.symbols.at("On").value), 0.0);
    o.clock = 0.1;
    auto frame = load_mirage_scene(o);
    ASSERT_TRUE(frame.ok()) << frame.message();
    // POV-Ray's clock is a float: 0.1 as that float.
    EXPECT_EQ(frame->scene.camera.location.y, 1.0 + static_cast<float>(0.1) + 2.0);
    EXPECT_EQ(std::get<double>(frame->scene.symbols.at("On").value), 1.0);
    o.clock = 1e39;
    EXPECT_EQ(load_error(p.string(), o),
              "--clock 1e+39: beyond the range of POV-Ray's clock (a float, at most 3.4e+38)");
}

TEST(ParseDeclare, NameAndNumber) {
    auto d = parse_declare("Lift=2.5e-1");
    ASSERT_TRUE(d.ok()) << d.message();
    EXPECT_EQ(d->first, "Lift");
    EXPECT_DOUBLE_EQ(d->second, 0.25);
    EXPECT_EQ(parse_declare("Lift").message(),
              "Lift: give NAME=VALUE, as POV-Ray's Declare=NAME=VALUE");
    EXPECT_EQ(parse_declare("Lift=high").message(),
              "Lift=high: 'high' is not a number (POV-Ray 3.7's Declare= takes numbers only)");
    EXPECT_EQ(parse_declare("Lift=").message(),
              "Lift=: '' is not a number (POV-Ray 3.7's Declare= takes numbers only)");
    EXPECT_EQ(parse_declare("Lift=1e999").message(),
              "Lift=1e999: '1e999' is not a number (POV-Ray 3.7's Declare= takes numbers only)");
    EXPECT_EQ(parse_declare("2x=1").message(),
              "2x=1: '2x' is not a name POV-Ray can declare (letters, digits and '_', not "
              "beginning with a digit)");
    EXPECT_EQ(parse_declare("sphere=1").message(),
              "sphere=1: 'sphere' is a word of POV-Ray's language");
}

}  // namespace
}  // namespace mirage
