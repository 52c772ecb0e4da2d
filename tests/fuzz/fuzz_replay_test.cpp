// Every input that ever made a fuzz target crash, hang or abort (tests/fuzz/crashes/ for the
// scene target, its csv/, sounding/ and truetype/ for the others), replayed through the same
// target with the normal build: each must now be refused with a message naming its place, or
// accepted, and return.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "scene_fuzz_input.h"
#include "table_fuzz_input.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> crash_inputs(const std::string& sub = "") {
    std::vector<fs::path> files;
    for (const auto& e :
         fs::directory_iterator(fs::path(MIRAGE_SOURCE_DIR) / "tests/fuzz/crashes" / sub))
        if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string read_all(const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(FuzzReplay, EveryInputThatEverCrashedNowReturns) {
    const auto files = crash_inputs();
    ASSERT_GE(files.size(), 10u);  // the reproducers at least
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.filename().string());
        fuzz::check_scene_input(read_all(f));  // aborts the test binary on a broken property
    }
}

TEST(FuzzReplay, EveryTableSoundingAndFontInputThatEverCrashedNowReturns) {
    const std::pair<const char*, void (*)(std::string_view)> targets[] = {
        {"csv", fuzz::check_csv_input},
        {"sounding", fuzz::check_sounding_input},
        {"truetype", fuzz::check_truetype_input}};
    for (const auto& [sub, check] : targets) {
        const auto files = crash_inputs(sub);
        EXPECT_GE(files.size(), 1u) << sub;
        for (const fs::path& f : files) {
            SCOPED_TRACE(f.string());
            check(read_all(f));
        }
    }
}

}  // namespace
}  // namespace mirage
