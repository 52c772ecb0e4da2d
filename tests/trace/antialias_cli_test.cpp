// `mirage trace --antialias [THRESHOLD] --antialias-method N --antialias-depth N --jitter A
// --no-jitter` from the command line: POV-Ray's defaults, and bad values named.
#include <gtest/gtest.h>

#include <filesystem>

#include "../cli/run_tool.h"
#include "povray_runner.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::read_bytes;
using testing::run_tool;
using testing::test_dir;

const std::string kScene = std::string(MIRAGE_SOURCE_DIR) + "/scenes/road.pov";

testing::ToolRun trace(const std::string& options, const fs::path& out) {
    return run_tool("trace " + kScene + " -W 64 -H 48 --threads 2 " + options + " -o " +
                    quoted(out));
}

TEST(AntialiasCli, WithoutAValueTheThresholdIsPovRays) {
    const auto dir = test_dir("antialias_cli", "default");
    const auto bare = trace("--antialias", dir / "bare.png");
    ASSERT_EQ(bare.exit_code, 0) << bare.err;
    const auto given = trace("--antialias 0.3 --antialias-method 1 --antialias-depth 3 --jitter 1",
                             dir / "given.png");
    ASSERT_EQ(given.exit_code, 0) << given.err;
    const auto other = trace("--antialias=0.05", dir / "other.png");
    ASSERT_EQ(other.exit_code, 0) << other.err;
    const auto plain = trace("", dir / "plain.png");
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(read_bytes(dir / "bare.png"), read_bytes(dir / "given.png"));
    EXPECT_NE(read_bytes(dir / "bare.png"), read_bytes(dir / "other.png"));
    EXPECT_NE(read_bytes(dir / "bare.png"), read_bytes(dir / "plain.png"));
    EXPECT_NE(bare.out.find(" pixels supersampled ("), std::string::npos) << bare.out;
    EXPECT_EQ(plain.out.find("supersampled"), std::string::npos) << plain.out;
    // Method 2 and no jitter are other images again.
    const auto m2 = trace("--antialias --antialias-method 2 --no-jitter", dir / "m2.png");
    ASSERT_EQ(m2.exit_code, 0) << m2.err;
    EXPECT_NE(read_bytes(dir / "m2.png"), read_bytes(dir / "bare.png"));
}

TEST(AntialiasCli, BadValuesAreNamed) {
    const auto dir = test_dir("antialias_cli", "bad");
    const auto high = trace("--antialias=1.5", dir / "x.png");
    EXPECT_EQ(high.exit_code, 2);
    EXPECT_NE(high.err.find("--antialias: '1.5' is not a threshold in [0, 1]"), std::string::npos)
        << high.err;
    // A scene taken for the threshold is named, with the way to write it.
    const auto scene = run_tool("trace --antialias " + kScene + " -o " + quoted(dir / "x.png"));
    EXPECT_NE(scene.exit_code, 0);
    EXPECT_NE(scene.err.find("'" + kScene +
                             "' is not a threshold in [0, 1] (before the scene, "
                             "write --antialias=0.3)"),
              std::string::npos)
        << scene.err;
    const auto method = trace("--antialias --antialias-method 3", dir / "x.png");
    EXPECT_EQ(method.exit_code, 2);
    EXPECT_NE(method.err.find("--antialias-method: 3 not in {1,2}"), std::string::npos)
        << method.err;
    const auto depth = trace("--antialias --antialias-depth 10", dir / "x.png");
    EXPECT_EQ(depth.exit_code, 2);
    EXPECT_NE(depth.err.find("--antialias-depth"), std::string::npos) << depth.err;
    const auto jitter = trace("--antialias --jitter 2", dir / "x.png");
    EXPECT_EQ(jitter.exit_code, 2);
    EXPECT_NE(jitter.err.find("--jitter"), std::string::npos) << jitter.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(AntialiasCli, OptionsWithoutAntialiasAreWarnedOf) {
    const auto dir = test_dir("antialias_cli", "warned");
    const auto r = trace("--antialias-method 2 --antialias-depth 4 -q", dir / "x.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err,
              "mirage trace: warning: --antialias-method has no effect without --antialias (as in "
              "POV-Ray)\n"
              "mirage trace: warning: --antialias-depth has no effect without --antialias (as in "
              "POV-Ray)\n");
}

}  // namespace
}  // namespace mirage
