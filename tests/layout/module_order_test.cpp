// The modules of src/ stand in one order (README.md's Layout states it): a module includes
// only from itself and the modules before it, never from one above.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace mirage {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kOrder = {
    "util",   "atmosphere", "scene",  "load",    "image",       "layers",  "pov",
    "report", "patterns",   "shapes", "trace",   "shading",     "render",  "compile",
    "trace_scene", "compare", "animate", "frame", "paths", "cli"};

int rank(const std::string& module) {
    auto it = std::find(kOrder.begin(), kOrder.end(), module);
    return it == kOrder.end() ? -1 : static_cast<int>(it - kOrder.begin());
}

TEST(ModuleOrder, NoIncludeArrowPointsUp) {
    const fs::path src = fs::path(MIRAGE_SOURCE_DIR) / "src";
    const std::regex include(R"re(^\s*#\s*include\s+"([a-z_]+)/[^"]+")re");
    int files = 0;
    std::vector<std::string> upward;
    for (const auto& e : fs::recursive_directory_iterator(src)) {
        if (!e.is_regular_file()) continue;
        const std::string module = fs::relative(e.path(), src).begin()->string();
        ASSERT_GE(rank(module), 0) << "a module not in the order: " << module;
        ++files;
        std::ifstream in(e.path());
        std::string line;
        std::smatch m;
        while (std::getline(in, line)) {
            if (!std::regex_search(line, m, include)) continue;
            const std::string target = m[1];
            ASSERT_GE(rank(target), 0) << e.path() << ": " << line;
            if (rank(target) > rank(module))
                upward.push_back(fs::relative(e.path(), src).string() + " -> " + target);
        }
    }
    EXPECT_GT(files, 100);
    EXPECT_TRUE(upward.empty()) << "includes from a higher module: "
                                << ::testing::PrintToString(upward);
}

}  // namespace
}  // namespace mirage
