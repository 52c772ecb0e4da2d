// Every input that ever made the fuzz target crash, hang or abort (tests/fuzz/crashes/),
// replayed through the same target with the normal build: each must now be refused with a
// message naming its place, or accepted, and return.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "scene_fuzz_input.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> crash_inputs() {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(fs::path(MIRAGE_SOURCE_DIR) / "tests/fuzz/crashes"))
        if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(FuzzReplay, EveryInputThatEverCrashedNowReturns) {
    const auto files = crash_inputs();
    ASSERT_GE(files.size(), 10u);  // the reproducers at least
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.filename().string());
        std::ifstream in(f, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        fuzz::check_scene_input(text.str());  // aborts the test binary on a broken property
    }
}

}  // namespace
}  // namespace mirage
