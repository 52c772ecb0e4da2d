// Issue 27's silent failures of the command line and of scene loading, through the built
// tool: each is refused (or done) with a message naming the file or the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "../trace/povray_runner.h"
#include "image/image_io.h"
#include "run_tool.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::read_bytes;
using testing::run_tool;
using testing::test_dir;
using testing::write_bytes;

// A scene with the paper's air, a level camera at `camera_y`, the ground and a sphere;
// `include` false leaves out mirage.inc, `camera` false the camera.
std::string scene_text(bool include, bool camera, double camera_y = 1.5) {
    std::string s = "#version 3.7;\n#declare Mirage_Preset = \"paper\";\n";
    if (include) s += "#include \"mirage.inc\"\n";
    if (camera)
        s += "camera { location <0, " + std::to_string(camera_y) + ", 0> look_at <0, " +
             std::to_string(camera_y) + ", 10> }\n";
    s += "plane { y, 0 pigment { checker rgb 1 rgb 0.5 } }\n"
         "sphere { <0, 1, 10>, 1 pigment { rgb <1, 0, 0> } }\n";
    return s;
}

// The files under `dir`, relative to it.
std::set<std::string> files_under(const fs::path& dir) {
    std::set<std::string> s;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        s.insert(fs::relative(e.path(), dir).string());
    return s;
}

TEST(CommandLineCli, ASceneWithoutMirageIncIsRefusedByCompileAndTrace) {
    const auto dir = test_dir("command_line_cli", "no_include");
    const auto scene = dir / "s.pov";
    write_bytes(scene, scene_text(false, true));
    const std::string why =
        scene.string() +
        ": the scene never includes mirage.inc, so POV-Ray renders it without the atmosphere it "
        "declares (Mirage_Preset at " +
        scene.string() +
        ":2:10): add #include \"mirage.inc\" after its #version line (plain POV-Ray finds it "
        "with +Lpov_includes)\n";
    auto compiled =
        run_tool("compile " + quoted(scene) + " -o " + quoted(dir / "out") + " -W 16 -H 12");
    EXPECT_EQ(compiled.exit_code, 1);
    EXPECT_EQ(compiled.err, "mirage compile: " + why);
    EXPECT_FALSE(fs::exists(dir / "out"));
    auto traced =
        run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") + " -W 16 -H 12");
    EXPECT_EQ(traced.exit_code, 1);
    EXPECT_EQ(traced.err, "mirage trace: " + why);
    EXPECT_FALSE(fs::exists(dir / "t.png"));
    // Straight rays need no mirage.inc.
    auto straight = run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") +
                             " -W 16 -H 12 --no-atmosphere -q");
    EXPECT_EQ(straight.exit_code, 0) << straight.err;
    EXPECT_TRUE(fs::exists(dir / "t.png"));
    // With the include both accept it.
    write_bytes(scene, scene_text(true, true));
    EXPECT_EQ(
        run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") + " -W 16 -H 12 -q")
            .exit_code,
        0);
    EXPECT_EQ(
        run_tool("compile " + quoted(scene) + " -o " + quoted(dir / "out") + " -W 16 -H 12 -q")
            .exit_code,
        0);
}

TEST(CommandLineCli, ASceneWithoutACameraIsRefusedFirstByBoth) {
    const auto dir = test_dir("command_line_cli", "no_camera");
    const auto scene = dir / "s.pov";
    write_bytes(scene, scene_text(true, false));
    const std::string why =
        scene.string() +
        ": the scene has no camera: POV-Ray would render it from its default camera at the "
        "origin, on the ground; add one, such as camera { location <0, 1.7, -10> look_at <0, "
        "1.7, 0> }\n";
    auto compiled =
        run_tool("compile " + quoted(scene) + " -o " + quoted(dir / "out") + " -W 16 -H 12");
    EXPECT_EQ(compiled.exit_code, 1);
    EXPECT_EQ(compiled.err, "mirage compile: " + why);  // no Mirage_Ground_Height to declare
    auto traced = run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") +
                           " -W 16 -H 12 --no-atmosphere");
    EXPECT_EQ(traced.exit_code, 1);
    EXPECT_EQ(traced.err, "mirage trace: " + why);
    EXPECT_FALSE(fs::exists(dir / "t.png"));
}

TEST(CommandLineCli, TraceRefusesACameraUnderTheGroundAsCompileDoes) {
    const auto dir = test_dir("command_line_cli", "under_ground");
    const auto scene = dir / "s.pov";
    write_bytes(scene, scene_text(true, true, -0.5));
    auto compiled =
        run_tool("compile " + quoted(scene) + " -o " + quoted(dir / "out") + " -W 16 -H 12");
    auto traced =
        run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") + " -W 16 -H 12");
    EXPECT_EQ(compiled.exit_code, 1);
    EXPECT_EQ(traced.exit_code, 1);
    const std::string why = scene.string() +
                            ":4:1: the camera at y = -0.5 is not above the ground of the "
                            "atmosphere (y = 0; Mirage_Ground_Height moves it)";
    EXPECT_EQ(compiled.err.rfind("mirage compile: " + why, 0), 0u) << compiled.err;
    EXPECT_EQ(traced.err.rfind("mirage trace: " + why, 0), 0u) << traced.err;
    // The same message after the command's name.
    EXPECT_EQ(compiled.err.substr(std::string("mirage compile: ").size()),
              traced.err.substr(std::string("mirage trace: ").size()));
    EXPECT_FALSE(fs::exists(dir / "t.png"));
    // Without the atmosphere there is no ground to be under.
    EXPECT_EQ(run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") +
                       " -W 16 -H 12 -q --no-atmosphere")
                  .exit_code,
              0);
}

TEST(CommandLineCli, AMisspeltOptionGetsTheNearestName) {
    const auto dir = test_dir("command_line_cli", "misspelt");
    const auto scene = dir / "s.pov";
    write_bytes(scene, scene_text(true, true));
    auto r = run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") + " --widht 640");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "mirage trace: unknown option --widht (did you mean --width?)\n");
    r = run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") + " --hieght=480");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "mirage trace: unknown option --hieght (did you mean --height?)\n");
    r = run_tool("compile " + quoted(scene) + " --rendr");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "mirage compile: unknown option --rendr (did you mean --render?)\n");
    // The value of an option is no option, whatever it looks like.
    r = run_tool("trace " + quoted(scene) + " -W 8 -H 6 -q -o " + quoted(dir / "--widht.png"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.png"));
}

TEST(CommandLineCli, LowerCaseSizeOptionsAreRefusedNotTakenForHelp) {
    const auto dir = test_dir("command_line_cli", "lower_case");
    const auto scene = dir / "s.pov";
    write_bytes(scene, scene_text(true, true));
    const std::string size =
        ": the image size is -W and -H (--width, --height), as POV-Ray's +W and +H; -h is the "
        "help\n";
    auto r = run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "t.png") + " -w 160 -h 120");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.out, "");  // not the help
    EXPECT_EQ(r.err, "mirage trace: -w 160" + size);
    r = run_tool("compile " + quoted(scene) + " -h 120");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "mirage compile: -h 120" + size);
    EXPECT_FALSE(fs::exists(dir / "t.png"));
    // -h alone is the help, as before.
    r = run_tool("trace -h");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("Usage:"), std::string::npos);
    EXPECT_NE(r.out.find("POV-Ray's spellings are accepted too"), std::string::npos);
}

TEST(CommandLineCli, AnUnknownSubcommandOrNoneListsThem) {
    auto r = run_tool("render scene.pov");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err.rfind("mirage: no subcommand 'render'\nThe subcommands:\n", 0), 0u) << r.err;
    for (const char* name : {"path", "compile", "trace", "compare", "animate", "study"})
        EXPECT_NE(r.err.find("\n  " + std::string(name) + " "), std::string::npos) << name;
    EXPECT_NE(r.err.find("mirage compile SCENE.pov --render"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("mirage trace SCENE.pov -o OUT.png"), std::string::npos) << r.err;
    auto none = run_tool("");
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_EQ(none.err.rfind("mirage: give a subcommand", 0), 0u) << none.err;
    EXPECT_NE(none.err.find("mirage compile SCENE.pov --render"), std::string::npos);
    auto near = run_tool("trac scene.pov");
    EXPECT_EQ(near.exit_code, 2);
    EXPECT_EQ(near.err.rfind("mirage: no subcommand 'trac' (did you mean trace?)\n", 0), 0u)
        << near.err;
}

// A frame that POV-Ray and mirage parse only at clock 0.5 with Lift declared 2.
const char* kFrame = R"(#version 3.7;
#declare Mirage_Preset = "paper";
#include "mirage.inc"
#if (clock != 0.5 | !clock_on) #error concat("not the frame: clock ", str(clock, 0, 3)) #end
#if (Lift != 2) #error "Lift is not 2" #end
camera { location <0, Lift, 0> look_at <0, Lift, 10> }
plane { y, 0 pigment { checker rgb 1 rgb 0.5 } }
sphere { <0, 1, 10>, 1 pigment { rgb <1, 0, 0> } }
)";

TEST(CommandLineCli, TraceRendersOneFrameWithPovRaysSpellings) {
    const auto dir = test_dir("command_line_cli", "trace_frame");
    const auto scene = dir / "frame.pov";
    write_bytes(scene, kFrame);
    auto r = run_tool("trace " + quoted(scene) + " +W40 +H30 +K0.5 Declare=Lift=2 -q +O" +
                      quoted(dir / "pov.png"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto image = read_image((dir / "pov.png").string());
    ASSERT_TRUE(image.ok()) << image.message();
    EXPECT_EQ(image->width, 40);
    EXPECT_EQ(image->height, 30);
    // The long options give the same image.
    r = run_tool("trace --declare Lift=2 " + quoted(scene) + " -W 40 -H 30 --clock 0.5 -q -o " +
                 quoted(dir / "long.png"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_bytes(dir / "long.png"), read_bytes(dir / "pov.png"));
    // Another clock is another frame, which this scene refuses.
    r = run_tool("trace " + quoted(scene) + " +K0.25 Declare=Lift=2 -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("not the frame: clock 0.250"), std::string::npos) << r.err;
    // A declared value must be a number, and a switch's value attached.
    r = run_tool("trace " + quoted(scene) + " Declare=Lift=high -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err.rfind("--declare: Lift=high: 'high' is not a number (POV-Ray 3.7's Declare= "
                          "takes numbers only)\n",
                          0),
              0u)
        << r.err;
    r = run_tool("trace " + quoted(scene) + " +W 40 -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "mirage trace: +W: POV-Ray's switches take their value attached: +W640\n");
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// trace's antialiasing options (--antialias [THRESHOLD], --antialias-method, --antialias-depth)
// reached through POV-Ray's +A, +AM and +R; run once trace has them.
TEST(CommandLineCli, TraceTakesPovRaysAntialiasingSpellings) {
    if (run_tool("trace --help").out.find("--antialias-method") == std::string::npos)
        GTEST_SKIP() << "mirage trace has no --antialias-method yet";
    const auto dir = test_dir("command_line_cli", "trace_antialias");
    const auto scene = dir / "s.pov";
    write_bytes(scene, scene_text(true, true));
    const std::string common = "trace " + quoted(scene) + " -W 24 -H 18 -q -o ";
    auto pov = run_tool(common + quoted(dir / "pov.png") + " +A0.1 +AM2 +R2");
    ASSERT_EQ(pov.exit_code, 0) << pov.err;
    auto lng = run_tool(common + quoted(dir / "long.png") +
                        " --antialias=0.1 --antialias-method=2 --antialias-depth=2");
    ASSERT_EQ(lng.exit_code, 0) << lng.err;
    EXPECT_EQ(read_bytes(dir / "pov.png"), read_bytes(dir / "long.png"));
    auto plain = run_tool(common + quoted(dir / "plain.png"));
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_NE(read_bytes(dir / "pov.png"), read_bytes(dir / "plain.png"));  // antialiased
    // +A alone: POV-Ray's default threshold.
    auto a = run_tool(common + quoted(dir / "a.png") + " +A");
    auto a03 = run_tool(common + quoted(dir / "a03.png") + " --antialias=0.3");
    ASSERT_EQ(a.exit_code, 0) << a.err;
    ASSERT_EQ(a03.exit_code, 0) << a03.err;
    EXPECT_EQ(read_bytes(dir / "a.png"), read_bytes(dir / "a03.png"));
}

// One frame of an animation renders alone: trace at +K0.5 is frame 2 of 3 of mirage animate.
TEST(CommandLineCli, TraceAtAClockIsThatFrameOfTheAnimation) {
    const auto dir = test_dir("command_line_cli", "walk_frame");
    const std::string walk = std::string(MIRAGE_SOURCE_DIR) + "/scenes/walk.pov";
    auto r = run_tool("animate " + walk + " --frames 3 --model trace -W 48 -H 36 -q -o " +
                      quoted(dir / "anim"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto frame = read_image((dir / "anim" / "frames" / "frame_0002.png").string());
    ASSERT_TRUE(frame.ok()) << frame.message();
    for (const std::string clock : {"0.5", "0.25"}) {
        const auto still = dir / ("still_" + clock + ".png");
        r = run_tool("trace " + walk + " +W48 +H36 -q +K" + clock + " +O" + quoted(still));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        auto image = read_image(still.string());
        ASSERT_TRUE(image.ok()) << image.message();
        if (clock == "0.5")
            EXPECT_EQ(image->pixels, frame->pixels);
        else
            EXPECT_NE(image->pixels, frame->pixels);  // another frame
    }
}

TEST(CommandLineCli, CompileGivesTheFrameToPovRayToo) {
    const auto dir = test_dir("command_line_cli", "compile_frame");
    const auto scene = dir / "frame.pov";
    write_bytes(scene, kFrame);
    const auto out = dir / "out";
    auto r = run_tool("compile " + quoted(scene) + " +W32 +H24 +A +K0.5 Declare=Lift=2 -q -o " +
                      quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string ini = read_bytes(out / "frame.ini");
    EXPECT_NE(ini.find("\nWidth=32\n"), std::string::npos) << ini;
    EXPECT_NE(ini.find("\nClock=0.5\n"), std::string::npos) << ini;
    EXPECT_NE(ini.find("\nDeclare=Lift=2\n"), std::string::npos) << ini;
    // The corrected camera antialiased: five rays in every pixel of its meshes.
    EXPECT_NE(read_bytes(out / "mirage_camera.inc").find("mesh_camera {\n        5 0"),
              std::string::npos);
    // A threshold other than POV-Ray's default is refused, naming the switch.
    r = run_tool("compile " + quoted(scene) + " +A0.1 +K0.5 Declare=Lift=2 -o " +
                 quoted(dir / "x"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err.rfind("mirage compile: +A0.1: mirage compile antialiases at POV-Ray's "
                          "threshold 0.3 only",
                          0),
              0u)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "x"));
    // POV-Ray renders the .ini: the scene's guards pass only with the clock and the number.
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    r = run_tool("compile " + quoted(scene) + " +W32 +H24 +K0.5 Declare=Lift=2 -q --render -o " +
                 quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto image = read_image((out / "frame.png").string());
    ASSERT_TRUE(image.ok()) << image.message();
    EXPECT_EQ(image->width, 32);
    EXPECT_EQ(image->height, 24);
}

TEST(CommandLineCli, CompileWritesInsideItsFolderAndNamesEveryFile) {
    const auto dir = test_dir("command_line_cli", "outputs");
    const auto scene = dir / "s.pov";
    write_bytes(scene, scene_text(true, true));
    const bool render = testing::povray_available();
    for (const std::string folder : {"a", "b"}) {
        auto r = run_tool("compile " + quoted(scene) + " -W 16 -H 12 -o " + quoted(dir / folder) +
                          (render ? " --render" : "") + " --error-map " +
                          quoted(dir / folder / "errors.exr"));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        // Every file written is in the folder, and named in the output.
        const auto written = files_under(dir / folder);
        EXPECT_TRUE(written.count("report.json")) << r.out;
        EXPECT_TRUE(written.count("errors.exr"));
        if (render) {
            EXPECT_TRUE(written.count("s.png"));
            EXPECT_TRUE(written.count("povray.log"));
        }
        for (const auto& f : written) {
            const std::string path = (dir / folder / f).string();
            EXPECT_TRUE(r.out.find(path + "\n") != std::string::npos ||
                        r.out.find(path + " (") != std::string::npos)
                << f << " is not named:\n"
                << r.out;
        }
    }
    // Nothing beside the folders: two compiles into sibling folders keep their own files.
    EXPECT_EQ(files_under(dir).size(), 1 + 2 * (files_under(dir / "a").size() + 1));
}

}  // namespace
}  // namespace mirage
