#include "util/process.h"

#include <gtest/gtest.h>

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
    EXPECT_GE(r->seconds, 0.0);
    auto text = read_file(log);
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(*text, fs::canonical(dir).string() + "\noops\n");
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
