// Every command as a hostile or careless user runs it: each reproducer of issue 9 gives a
// clear message and a non-zero exit, and changes no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "../trace/povray_runner.h"
#include "run_tool.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::read_bytes;
using testing::write_bytes;
using testing::run_tool;
using testing::test_dir;

const std::string kDesert = std::string(MIRAGE_SOURCE_DIR) + "/scenes/desert.pov";

/// Every file under `dir` and its content.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = read_bytes(e.path());
    return files;
}

/// The desert scene with `from` replaced by `to`, as dir/name.
fs::path desert_with(const fs::path& dir, const std::string& name, const std::string& from,
                     const std::string& to) {
    std::string text = read_bytes(kDesert);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    write_bytes(dir / name, text);
    return dir / name;
}

TEST(HostileCli, NoOutputReplacesAnInput) {
    const auto dir = test_dir("hostile_cli", "inputs");
    // The scene named like the image it is asked to write.
    write_bytes(dir / "s.png", read_bytes(kDesert));
    auto before = snapshot(dir);
    auto r = run_tool("trace " + quoted(dir / "s.png") + " -o " + quoted(dir / "s.png") +
                      " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage trace: " + (dir / "s.png").string() +
                         ": the output would overwrite an input of this command (the scene or a "
                         "file it includes)\n");
    EXPECT_EQ(snapshot(dir), before);
    // compile -o into the directory that holds the scene, named like one of its outputs.
    fs::create_directories(dir / "same");
    write_bytes(dir / "same" / "layers.csv", read_bytes(kDesert));
    before = snapshot(dir);
    r = run_tool("compile " + quoted(dir / "same" / "layers.csv") + " -o " + quoted(dir / "same") +
                 " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage compile: " + (fs::absolute(dir) / "same" / "layers.csv").string() +
                         ": the output would overwrite an input of this command (the scene or a "
                         "file it includes)\n");
    EXPECT_EQ(snapshot(dir), before);
    // The error map named like the scene, refused before any work.
    write_bytes(dir / "s.exr", read_bytes(kDesert));
    before = snapshot(dir);
    r = run_tool("compile " + quoted(dir / "s.exr") + " -o " + quoted(dir / "out") +
                 " -W 16 -H 12 --error-map " + quoted(dir / "s.exr"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage compile: " + (dir / "s.exr").string() +
                         ": the output would overwrite an input of this command (the scene or a "
                         "file it includes)\n");
    EXPECT_EQ(snapshot(dir), before);
    // An included file is an input too.
    write_bytes(dir / "air.inc", "#declare Mirage_Preset = \"paper\";\n#include \"mirage.inc\"\n");
    write_bytes(dir / "inc.pov",
          "#include \"air.inc\"\ncamera { location <0, 1.5, 0> look_at <0, 1.5, 1> }\n");
    before = snapshot(dir);
    r = run_tool("compile " + quoted(dir / "inc.pov") + " -o " + quoted(dir / "o") +
                 " -W 16 -H 12 --error-map " + quoted(dir / "air.inc"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("the error map is written as OpenEXR"), std::string::npos) << r.err;
    r = run_tool("compile " + quoted(dir / "inc.pov") + " -W 16 -H 12 --image " +
                 quoted(dir / "air.inc"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage compile: " + (dir / "air.inc").string() +
                         ": the output would overwrite an input of this command (the scene or a "
                         "file it includes)\n");
    EXPECT_EQ(snapshot(dir), before);
}

TEST(HostileCli, NoOutputReplacesAFontOrAnImageTheSceneUses) {
    const auto dir = test_dir("hostile_cli", "font_image");
    // A font and an image map, named like the image asked for.
    fs::copy_file("/usr/share/povray-3.7/include/timrom.ttf", dir / "font.png",
                  fs::copy_options::overwrite_existing);
    write_bytes(dir / "s.pov",
          "camera { location <0, 1, -4> look_at <0, 1, 0> }\n"
          "light_source { <2, 4, -3>, rgb 1 }\n"
          "text { ttf \"font.png\" \"A\" 0.2, 0 pigment { rgb 1 } }\n");
    auto before = snapshot(dir);
    auto r = run_tool("trace " + quoted(dir / "s.pov") + " -o " + quoted(dir / "font.png") +
                      " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("the output would overwrite an input of this command"), std::string::npos)
        << r.err;
    EXPECT_EQ(snapshot(dir), before);
    // An image map: made by a first trace, then used by the scene and asked for again.
    write_bytes(dir / "plain.pov",
          "camera { location <0, 1, -4> look_at <0, 1, 0> }\n"
          "light_source { <2, 4, -3>, rgb 1 }\nsphere { <0, 1, 0>, 1 pigment { rgb x } }\n");
    r = run_tool("trace " + quoted(dir / "plain.pov") + " -o " + quoted(dir / "map.png") +
                 " -W 16 -H 12");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    write_bytes(dir / "m.pov",
          "camera { location <0, 1, -4> look_at <0, 1, 0> }\n"
          "light_source { <2, 4, -3>, rgb 1 }\n"
          "plane { z, 2 pigment { image_map { png \"map.png\" } } }\n");
    before = snapshot(dir);
    r = run_tool("trace " + quoted(dir / "m.pov") + " -o " + quoted(dir / "map.png") +
                 " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("the output would overwrite an input of this command"), std::string::npos)
        << r.err;
    EXPECT_EQ(snapshot(dir), before);
}

TEST(HostileCli, AllOutputsOrNone) {
    const auto dir = test_dir("hostile_cli", "all_or_none");
    // report.json cannot be written (a directory holds its name): no other output appears.
    fs::create_directories(dir / "out" / "report.json");
    write_bytes(dir / "out" / "layers.csv", "old\n");
    const auto before = snapshot(dir);
    auto r = run_tool("compile " + kDesert + " -o " + quoted(dir / "out") + " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage compile: " + (fs::absolute(dir) / "out" / "report.json").string() +
                         ": is a directory; an output must be a file\n");
    EXPECT_EQ(snapshot(dir), before);
    // The error map in a directory that does not exist: nothing else is written either.
    r = run_tool("compile " + kDesert + " -o " + quoted(dir / "fresh") +
                 " -W 16 -H 12 --error-map " + quoted(dir / "missing" / "map.exr"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find((dir / "missing" / "map.exr").string()), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "fresh"));  // the folder made for the outputs, taken away
    // A failed write to the standard output is an error.
    r = run_tool("path --batch " + std::string(MIRAGE_SOURCE_DIR) +
                 "/tests/data/path_public.csv > /dev/full");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage: cannot write the standard output: No space left on device\n");
}

TEST(HostileCli, ExtremeAtmospheresAreRefusedWithTheirName) {
    const auto dir = test_dir("hostile_cli", "atmosphere");
    auto r = run_tool(
        "path --profile inferior --eta0 1.0003 --eta1 1e200 --alpha 1 --eye-height 1.5 "
        "--elevation-deg -10");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage path: --eta1 = 1e+200 must be 0 or from 1e-10 to 10\n");
    write_bytes(dir / "rows.csv",
          "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n"
          "A,inferior,1.0003,1e200,1,1.5,1.9,1,2,3\n");
    r = run_tool("path --batch " + quoted(dir / "rows.csv"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "mirage path: " + (dir / "rows.csv").string() +
                         ":2:19: eta1 = 1e+200 must be 0 or from 1e-10 to 10\n");
    const auto alpha = desert_with(dir, "alpha.pov", "#declare Mirage_Preset    = \"paper\";",
                                   "#declare Mirage_Profile = \"inferior\";\n"
                                   "#declare Mirage_Eta0 = 1.0003;\n#declare Mirage_Eta1 = 0.1;\n"
                                   "#declare Mirage_Alpha = 1e308;");
    r = run_tool("compile " + quoted(alpha) + " -o " + quoted(dir / "a") + " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(": Mirage_Alpha = 1e+308 must be from 1e-09 to 1e+09 (1/m)\n"),
              std::string::npos)
        << r.err;
    const auto high =
        desert_with(dir, "high.pov", "location <0, 1.5, 0>", "location <0, 1e308, 0>");
    r = run_tool("trace " + quoted(high) + " -o " + quoted(dir / "h.png") + " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(": the camera is at y = 1e+308: mirage follows scenes within 1e+09 units "
                         "of the origin\n"),
              std::string::npos)
        << r.err;
    const auto inf =
        desert_with(dir, "inf.pov", "location <0, 1.5, 0>", "location <0, 1.5, 1e999>");
    r = run_tool("compile " + quoted(inf) + " -o " + quoted(dir / "i") + " -W 16 -H 12");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(": the number 1e999 is out of the range of a double\n"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "a") || fs::exists(dir / "h.png") || fs::exists(dir / "i"));
}

TEST(HostileCli, ValuesThatWouldHangAreRefusedAtOnce) {
    const auto dir = test_dir("hostile_cli", "hangs");
    auto r = run_tool("trace " + kDesert + " -o " + quoted(dir / "t.png") + " --tolerance 1e-300");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(
        r.err,
        "mirage trace: --tolerance 1e-300: the tolerance must be from 0.001 to 1000 pixels\n");
    r = run_tool("compile " + kDesert + " -o " + quoted(dir / "c") + " --tolerance 1e-300");
    EXPECT_EQ(r.err,
              "mirage compile: --tolerance 1e-300: the tolerance must be from 0.001 to 1000 "
              "pixels\n");
    const auto tol = desert_with(dir, "tol.pov", "#declare Mirage_Tolerance = 0.5;",
                                 "#declare Mirage_Tolerance = 1e-300;");
    r = run_tool("trace " + quoted(tol) + " -o " + quoted(dir / "t.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find(": Mirage_Tolerance = 1e-300: the tolerance must be from 0.001 to 1000 "
                         "pixels\n"),
              std::string::npos)
        << r.err;
    r = run_tool("path --preset paper --eye-height 1.5 --elevation-deg -10 --tolerance 1e-300");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage path: --tolerance 1e-300: must be 0 or from 1e-10 to 1 rad\n");
    r = run_tool("compile " + kDesert + " -o " + quoted(dir / "c") +
                 " --layers uniform --count 1000000000");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage compile: --count 1e+09: the layer count must be a whole number from 1 to "
              "4096\n");
    // Index steps are real air's design: asked for on the desert's exponential profile, refused
    // with what to do, nothing written.
    r = run_tool("compile " + kDesert + " -o " + quoted(dir / "steps") +
                 " --layers index-steps --count 16");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("desert.pov: index steps (layers at equal steps of the index) are the "
                         "design for real air"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "steps"));
    const auto count = desert_with(dir, "count.pov", "#declare Mirage_Tolerance = 0.5;",
                                   "#declare Mirage_Layer_Count = 1e9;");
    r = run_tool("compile " + quoted(count) + " -o " + quoted(dir / "c"));
    EXPECT_NE(r.err.find(": Mirage_Layer_Count = 1e+09: the layer count must be a whole number "
                         "from 1 to 4096\n"),
              std::string::npos)
        << r.err;
    r = run_tool("path --preset paper --eye-height 1.5 --elevation-deg -10 --svg " +
                 quoted(dir / "f.svg") + " --fan-count 100000000");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err,
              "--fan-count: Value 100000000 not in range 1 to 500\n"
              "Run with --help for more information.\n");
    r = run_tool("trace /dev/zero -o " + quoted(dir / "z.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage trace: /dev/zero: is not a regular file (a device, a pipe or a socket?): "
              "scenes are read from files\n");
    write_bytes(dir / "loop.pov", "#while (1)\n#end\n");
    r = run_tool("compile " + quoted(dir / "loop.pov") + " -o " + quoted(dir / "c"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("loop.pov:1:1: '#while' reached mirage's limit of 1000000 loop passes "
                         "(all loops together): an endless loop?\n"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "c") || fs::exists(dir / "t.png") || fs::exists(dir / "f.svg"));
}

TEST(HostileCli, AFileThatIsNoSceneSaysWhatIsWrong) {
    const auto dir = test_dir("hostile_cli", "files");
    auto r = run_tool("trace " + quoted(dir) + " -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage trace: " + dir.string() + ": is a directory, not a scene file\n");
    write_bytes(dir / "empty.pov", "");
    r = run_tool("compile " + quoted(dir / "empty.pov") + " -o " + quoted(dir / "out"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage compile: " + (dir / "empty.pov").string() +
                         ": the file is empty: there is no scene to read\n");
    // A line of 200 KB (or binary) is echoed cut around the caret.
    write_bytes(dir / "long.pov", "#declare X = " + std::string(200000, '1') + " spere;\n");
    r = run_tool("trace " + quoted(dir / "long.pov") + " -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_LT(r.err.size(), 700u);
    EXPECT_NE(r.err.find("the number 1111"), std::string::npos);
    EXPECT_NE(r.err.find("11111 ... 11111"), std::string::npos);
    EXPECT_NE(r.err.find("\n#declare X = 1111"), std::string::npos);
    EXPECT_NE(r.err.find("111...\n             ^\n"), std::string::npos);
    write_bytes(dir / "binary.pov", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
    r = run_tool("trace " + quoted(dir / "binary.pov") + " -o " + quoted(dir / "x.png"));
    EXPECT_EQ(r.exit_code, 1);
    for (char c : r.err) EXPECT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7F)) << r.err;
    EXPECT_EQ(fs::directory_iterator(dir) == fs::directory_iterator(), false);
    EXPECT_FALSE(fs::exists(dir / "x.png") || fs::exists(dir / "out"));
}

TEST(HostileCli, BatchRowsAreReadStrictly) {
    const auto dir = test_dir("hostile_cli", "batch");
    const std::string header = "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n";
    write_bytes(dir / "bom.csv",
          "\xEF\xBB\xBF" + header + "A,inferior,1.000233,0.4584,2.303,1.0,1.9,1,2,3\n");
    auto r = run_tool("path --batch " + quoted(dir / "bom.csv"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("case_id,k2,", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("\nA,"), std::string::npos) << r.out;
    const std::pair<std::string, std::string> rows[] = {
        {"1e999", "2:42: column 'd1': '1e999' is out of the range of a double"},
        {"0x1p3", "2:42: column 'd1': '0x1p3' is not a decimal number"},
        {"-5", "2:42: d1 = -5: a distance must be finite and >= 0 (m)"},
    };
    for (const auto& [value, message] : rows) {
        write_bytes(dir / "rows.csv",
              header + "A,inferior,1.000233,0.4584,2.303,1.0,1.9," + value + ",2,3\n");
        r = run_tool("path --batch " + quoted(dir / "rows.csv"));
        EXPECT_EQ(r.exit_code, 1) << value;
        EXPECT_EQ(r.out, "");
        EXPECT_EQ(r.err, "mirage path: " + (dir / "rows.csv").string() + ":" + message + "\n");
    }
}

}  // namespace
}  // namespace mirage
