// `mirage compare` from the command line: progress, output and the exact messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../trace/povray_runner.h"
#include "run_tool.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::test_dir;

const std::string kDesert = std::string(MIRAGE_SOURCE_DIR) + "/scenes/desert.pov";

TEST(CompareCli, ReportsEachSettingAndWhereTheResultsAre) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const auto dir = test_dir("compare_cli", "runs");
    auto r = run_tool("compare " + kDesert + " -W 32 -H 24 -o " + quoted(dir / "out") +
                      " --counts 8 --tolerances 2 --trace-tolerances 2 --reference-tolerance 0.5");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.rfind("reference 0.5 px: per-ray paths, tracer ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("\nuniform 8 layers: POV-Ray "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\nadaptive 2 px: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\npolyline 2 px: "), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("wrote " + (dir / "out" / "summary.md").string() + "\n"),
              std::string::npos)
        << r.out;
    EXPECT_TRUE(fs::exists(dir / "out" / "results.csv"));
    // The scene template is untouched.
    EXPECT_TRUE(fs::exists(kDesert));
}

TEST(CompareCli, BadValuesAreRefusedWithTheirName) {
    const auto dir = test_dir("compare_cli", "bad");
    const std::string out = " -o " + quoted(dir / "out");
    auto counts = run_tool("compare " + kDesert + out + " --counts 8,0");
    EXPECT_EQ(counts.exit_code, 1);
    EXPECT_EQ(
        counts.err,
        "mirage compare: --counts 0: the layer count must be a whole number from 1 to 4096\n");
    auto steps = run_tool("compare " + kDesert + out + " --steps 64,5000");
    EXPECT_EQ(steps.exit_code, 1);
    EXPECT_EQ(
        steps.err,
        "mirage compare: --steps 5000: the layer count must be a whole number from 1 to 4096\n");
    auto tol = run_tool("compare " + kDesert + out + " --trace-tolerances 1,-2");
    EXPECT_EQ(tol.exit_code, 1);
    EXPECT_EQ(
        tol.err,
        "mirage compare: --trace-tolerances -2: the tolerance must be from 0.001 to 1000 pixels\n");
    auto coarse = run_tool("compare " + kDesert + out + " --reference-tolerance 0.5");
    EXPECT_EQ(coarse.exit_code, 1);
    EXPECT_EQ(coarse.err,
              "mirage compare: --reference-tolerance 0.5 px is not finer than 0.5 px in "
              "--tolerances: the reference must be finer than every setting it judges\n");
    auto threshold = run_tool("compare " + kDesert + out + " --threshold 0");
    EXPECT_EQ(threshold.exit_code, 1);
    EXPECT_EQ(threshold.err,
              "mirage compare: --threshold 0: must be between 0 and 1 (a difference of 8-bit "
              "codes / 255)\n");
    auto word = run_tool("compare " + kDesert + out + " --counts 8,many");
    EXPECT_EQ(word.exit_code, 2);
    EXPECT_NE(word.err.find("--counts"), std::string::npos) << word.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CompareCli, ABadSceneIsReportedWithItsPlace) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const auto dir = test_dir("compare_cli", "bad_scene");
    const auto scene = dir / "ovus.pov";
    std::ofstream(scene) << "#version 3.7;\n#declare Mirage_Preset = \"paper\";\n"
                            "camera { location <0, 1, -3> look_at 0 }\n"
                            "  ovus { 1, 0.6 pigment { rgb 1 } }\n";
    auto r = run_tool("compare " + quoted(scene) + " -o " + quoted(dir / "out") + " -q");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "mirage compare: " + scene.string() +
                         ":4:3: unsupported object 'ovus'\n"
                         "  ovus { 1, 0.6 pigment { rgb 1 } }\n"
                         "  ^\n");
    EXPECT_FALSE(fs::exists(dir / "out" / "reference.png"));
}

}  // namespace
}  // namespace mirage
