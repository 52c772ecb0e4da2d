#include "compare/povray_render.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_temp.h"

namespace mirage {
namespace {

// The end of POV-Ray 3.7.0.10's console output for a render (Debian 12).
const char* kLog = R"(Persistence of Vision(tm) Ray Tracer Version 3.7.0.10.unofficial (g++ @
 x86_64-pc-linux-gnu)
Parser Time
  Parse Time:       0 hours  0 minutes  0 seconds (0.002 seconds)
              using 1 thread(s) with 0.001 CPU-seconds total
  Bounding Time:    0 hours  0 minutes  0 seconds (0.001 seconds)
              using 1 thread(s) with 0.000 CPU-seconds total
Rays:            3460950   Saved:                 0   Max Level: 166/256
Render Time:
  Photon Time:      No photons
  Radiosity Time:   No radiosity
  Trace Time:       0 hours  0 minutes  3 seconds (3.601 seconds)
              using 2 thread(s) with 3.599 CPU-seconds total
POV-Ray finished
)";

TEST(PovrayLog, ReadsTheRendersFiguresNotTheParsers) {
    const PovrayLog log = parse_povray_log(kLog);
    EXPECT_EQ(log.version, "3.7.0.10.unofficial");
    ASSERT_TRUE(log.trace_seconds);
    EXPECT_DOUBLE_EQ(*log.trace_seconds, 3.601);
    ASSERT_TRUE(log.cpu_seconds);
    EXPECT_DOUBLE_EQ(*log.cpu_seconds, 3.599);
    EXPECT_EQ(log.threads, 2);
    ASSERT_TRUE(log.max_level);
    EXPECT_EQ(*log.max_level, 166);
}

TEST(PovrayLog, AFailedRenderHasNoFigures) {
    const PovrayLog log = parse_povray_log("Parse Error: No objects in scene.\n");
    EXPECT_FALSE(log.trace_seconds);
    EXPECT_FALSE(log.cpu_seconds);
    EXPECT_EQ(log.threads, 0);
    EXPECT_FALSE(log.max_level);
}

TEST(PovrayRender, AMissingProgramIsAnError) {
    PovrayRenderSettings s;
    s.povray = "mirage-no-such-povray";
    s.ini = "x.ini";
    s.log = mirage::testing::test_temp_path("mirage_povray_missing.log").string();
    auto r = render_povray(s);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), "mirage-no-such-povray: not found on PATH");
}

TEST(LogTail, KeepsTheLastLines) {
    const auto path = mirage::testing::test_temp_path("mirage_log_tail.txt");
    std::ofstream(path) << "one\ntwo\nthree\n";
    EXPECT_EQ(log_tail(path.string(), 2), "two\nthree\n");
    EXPECT_EQ(log_tail(path.string(), 9), "one\ntwo\nthree\n");
}

}  // namespace
}  // namespace mirage
