// `mirage trace` from the command line: its messages, its output, and every shipped scene
// against POV-Ray with the atmosphere off.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../trace/povray_runner.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "run_tool.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::test_dir;

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
}

TEST(TraceCli, TracesAScene) {
    const auto dir = test_dir("trace_cli", "traces");
    const auto out = dir / "desert.png";
    auto r = run_tool("trace " + std::string(MIRAGE_SOURCE_DIR) + "/scenes/desert.pov -o " +
                      quoted(out) + " -W 64 -H 48 --threads 2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");  // no progress bar when stderr is not a terminal
    EXPECT_NE(r.out.find("desert.pov: atmosphere paper (inferior), per-ray paths within 0.5 px"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("64x48: 3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" segments/ray, "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" Mrays/s on 2 threads\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("wrote " + out.string() + "\n"), std::string::npos) << r.out;
    auto image = read_image(out.string());
    ASSERT_TRUE(image.ok()) << image.message();
    EXPECT_EQ(image->width, 64);
    EXPECT_EQ(image->height, 48);
    // Nothing but the image is left in the directory (the temporary name was renamed).
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1);

    auto exr = run_tool("trace " + std::string(MIRAGE_SOURCE_DIR) + "/scenes/road.pov -o " +
                        quoted(dir / "road.exr") + " -W 32 -H 24 --scanline-paths -q");
    ASSERT_EQ(exr.exit_code, 0) << exr.err;
    EXPECT_EQ(exr.out, "");
    EXPECT_TRUE(read_image((dir / "road.exr").string()).ok());
}

TEST(TraceCli, AnObjectOutsideTheSubsetIsRefusedWithItsPlace) {
    const auto dir = test_dir("trace_cli", "strict");
    const auto scene = dir / "ovus.pov";
    write_text(scene,
               "#version 3.7;\ncamera { location <0, 1, -3> look_at 0 }\n"
               "  ovus { 1, 0.6 pigment { rgb 1 } }\n");
    auto r = run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "out.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "mirage trace: " + scene.string() +
                         ":3:3: unsupported object 'ovus'\n"
                         "  ovus { 1, 0.6 pigment { rgb 1 } }\n"
                         "  ^\n");
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(TraceCli, AMissingSceneFile) {
    const auto dir = test_dir("trace_cli", "missing");
    auto r = run_tool("trace " + quoted(dir / "nowhere.pov") + " -o " + quoted(dir / "out.png"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage trace: " + (dir / "nowhere.pov").string() +
                         ": cannot be opened: No such file or directory\n");
}

TEST(TraceCli, UsageErrorsComeFromTheCommandLineParser) {
    const std::string scene = std::string(MIRAGE_SOURCE_DIR) + "/scenes/desert.pov";
    auto flag = run_tool("trace " + scene + " -o /tmp/x.png --bogus");
    EXPECT_EQ(flag.exit_code, 2);
    EXPECT_EQ(flag.err,
              "mirage trace: unknown option --bogus (mirage trace --help lists its options)\n");
    auto no_output = run_tool("trace " + scene);
    EXPECT_EQ(no_output.exit_code, 2);
    EXPECT_EQ(no_output.err, "--output is required\nRun with --help for more information.\n");
    auto not_a_number = run_tool("trace " + scene + " -o /tmp/x.png --tolerance half");
    EXPECT_EQ(not_a_number.exit_code, 2);
    EXPECT_NE(not_a_number.err.find("--tolerance"), std::string::npos) << not_a_number.err;
    auto bad_value = run_tool("trace " + scene + " -o /tmp/x.png --tolerance 0");
    EXPECT_EQ(bad_value.exit_code, 1);
    EXPECT_EQ(bad_value.err,
              "mirage trace: --tolerance 0: the tolerance must be from 0.001 to 1000 pixels\n");
    auto bad_type = run_tool("trace " + scene + " -o /tmp/x.tiff");
    EXPECT_EQ(bad_type.exit_code, 1);
    EXPECT_EQ(bad_type.err,
              "mirage trace: /tmp/x.tiff: unknown image type '.tiff' (use .png or .exr)\n");
}

TEST(TraceCli, ScanlinePathsRefuseATiltedCamera) {
    const auto dir = test_dir("trace_cli", "tilted");
    const auto scene = dir / "tilted.pov";
    write_text(scene,
               "#version 3.7;\n#declare Mirage_Preset = \"paper\";\n#include \"mirage.inc\"\n"
               "camera { location <0, 1.5, 0> look_at <0, 2.5, 10> }\n"
               "plane { y, 0 pigment { rgb 1 } }\n");
    auto r = run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "out.png") +
                      " --scanline-paths -W 32 -H 24");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mirage trace: " + scene.string() +
                         ":4:1: scanline paths need a level camera (one path per image row is "
                         "rotated about the vertical): the camera looks 5.71 degrees up\n");
    auto per_ray =
        run_tool("trace " + quoted(scene) + " -o " + quoted(dir / "out.png") + " -W 32 -H 24 -q");
    EXPECT_EQ(per_ray.exit_code, 0) << per_ray.err;
}

}  // namespace
}  // namespace mirage
