#include "util/process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <filesystem>

#include "test_temp.h"
#include "util/atomic_file.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

TEST(FindProgram, FindsOnPathAndByPath) {
    auto sh = find_program("sh");
    ASSERT_TRUE(sh);
    EXPECT_EQ(fs::path(*sh).filename(), "sh");
    EXPECT_EQ(find_program(*sh), sh);
    EXPECT_FALSE(find_program("mirage-no-such-program"));
    EXPECT_FALSE(find_program("/nonexistent/sh"));
    EXPECT_FALSE(find_program(""));
}

TEST(RunProcess, RunsInTheDirectoryWithOutputInTheLog) {
    const fs::path dir = mirage::testing::test_temp_path("mirage_process_run");
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string log = (dir / "out.log").string();
    auto r = run_process({"sh", "-c", "pwd; echo oops >&2; exit 3"}, dir.string(), log);
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->exit_code, 3);
    auto text = read_file(log);
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(*text, fs::canonical(dir).string() + "\noops\n");
}

TEST(RunProcess, TimesTheProgramFromStartToExit) {
    // A program that sleeps a known while ran at least that while, and run_process's time of
    // it lies within the test's own time of the call (steady clock, as run_process's).
    const double sleep_seconds = 0.3;
    const auto before = std::chrono::steady_clock::now();
    auto r = run_process({"sh", "-c", "sleep 0.3"}, "", "");
    const auto after = std::chrono::steady_clock::now();
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_EQ(r->exit_code, 0);
    EXPECT_GE(r->seconds, sleep_seconds);
    EXPECT_LE(r->seconds, std::chrono::duration<double>(after - before).count());
}

// The processor time is the program's own: a sleeping program takes almost none of it, a
// counting one takes some, and no more than its wall-clock time on every core.
TEST(RunProcess, MeasuresTheProgramsProcessorTime) {
    auto idle = run_process({"sh", "-c", "sleep 0.3"}, "", "");
    ASSERT_TRUE(idle.ok()) << idle.message();
    EXPECT_LT(idle->cpu_seconds, 0.05);
    EXPECT_GE(idle->seconds, 0.3);
    auto busy = run_process(
        {"sh", "-c", "i=0; while [ $i -lt 200000 ]; do i=$((i + 1)); done"}, "", "");
    ASSERT_TRUE(busy.ok()) << busy.message();
    ASSERT_EQ(busy->exit_code, 0);
    EXPECT_GT(busy->cpu_seconds, 0.05);
    EXPECT_LE(busy->cpu_seconds,
              busy->seconds * std::max(1u, std::thread::hardware_concurrency()) + 0.01);
}

TEST(RunProcess, ProgramsThatCannotStartAreErrors) {
    auto missing = run_process({"mirage-no-such-program"}, "", "");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.message(), "mirage-no-such-program: not found on PATH");
    auto no_dir = run_process({"sh", "-c", "true"}, "/nonexistent/mirage", "");
    ASSERT_FALSE(no_dir.ok());
    EXPECT_EQ(no_dir.message(),
              "/nonexistent/mirage: cannot run sh there: No such file or directory");
}

}  // namespace
}  // namespace mirage
