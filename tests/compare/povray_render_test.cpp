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

// A real render: the whole process's processor time holds the trace's own CPU-seconds that
// POV-Ray reports, and is measured apart from the wall clock.
TEST(PovrayRender, MeasuresTheWholeProcesssProcessorTime) {
    const auto dir = mirage::testing::test_temp_path("mirage_povray_cpu");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "s.pov") << "#version 3.7;\ncamera { location <0, 0, -4> look_at 0 }\n"
                                    "light_source { <5, 5, -5>, rgb 1 }\n"
                                    "sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } "
                                    "finish { reflection 0.3 } }\n";
    std::ofstream(dir / "s.ini") << "Input_File_Name=s.pov\nWidth=320\nHeight=240\n"
                                    "Antialias=on\nAntialias_Threshold=0\nOutput_File_Type=N\n";
    PovrayRenderSettings s;
    s.ini = "s.ini";
    s.work_dir = dir.string();
    s.output = (dir / "s.png").string();
    s.log = (dir / "s.log").string();
    auto r = render_povray(s);
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_EQ(r->exit_code, 0) << log_tail(s.log, 10);
    ASSERT_TRUE(r->log.cpu_seconds);
    EXPECT_GT(*r->log.cpu_seconds, 0.0);
    EXPECT_GE(r->process_cpu_seconds, *r->log.cpu_seconds - 0.01);
    EXPECT_GT(r->seconds, 0.0);
}

TEST(LogTail, KeepsTheLastLines) {
    const auto path = mirage::testing::test_temp_path("mirage_log_tail.txt");
    std::ofstream(path) << "one\ntwo\nthree\n";
    EXPECT_EQ(log_tail(path.string(), 2), "two\nthree\n");
    EXPECT_EQ(log_tail(path.string(), 9), "one\ntwo\nthree\n");
}

}  // namespace
}  // namespace mirage
