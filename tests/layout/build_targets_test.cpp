// Every program the Makefile and the tools run from the build directory is a target the build
// defines: a target dropped from CMakeLists.txt breaks `make bench` or a tool on a fresh clone,
// where an old build directory would still hide it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(BuildTargets, EveryProgramTheMakefileAndToolsRunIsBuilt) {
    const fs::path top = MIRAGE_SOURCE_DIR;
    std::set<std::string> defined;
    const std::string cmake = read_text(top / "CMakeLists.txt");
    const std::regex target(R"(add_executable\((mirage[A-Za-z0-9_]*))");
    for (auto it = std::sregex_iterator(cmake.begin(), cmake.end(), target);
         it != std::sregex_iterator(); ++it)
        defined.insert((*it)[1]);
    ASSERT_TRUE(defined.count("mirage")) << "CMakeLists.txt not read";
    // $(BUILD)/NAME in the Makefile, $build/NAME, build/NAME or $..._build/NAME in the tools.
    const std::regex used(R"((?:\$\(BUILD\)|\$build|\bbuild|_build)/(mirage[A-Za-z0-9_]*))");
    std::vector<fs::path> files = {top / "Makefile"};
    for (const auto& e : fs::directory_iterator(top / "tools"))
        if (e.path().extension() == ".sh") files.push_back(e.path());
    int uses = 0;
    for (const fs::path& f : files) {
        const std::string text = read_text(f);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), used);
             it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[1];
            if (name.find("_fuzzer") != std::string::npos) continue;  // clang only (make fuzz)
            ++uses;
            EXPECT_TRUE(defined.count(name))
                << f.filename().string() << " runs " << name << ", which CMakeLists.txt does not build";
        }
    }
    EXPECT_GE(uses, 3);
}

}  // namespace
}  // namespace mirage
