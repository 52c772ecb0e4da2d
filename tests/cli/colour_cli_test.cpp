// Colour from the command line: `mirage trace --wavelengths/--colour/--monochrome` and
// `mirage compile --wavelengths/--colour`, their messages and outputs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../trace/povray_runner.h"
#include "image/image_io.h"
#include "run_tool.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::test_dir;

std::string scene(const std::string& name) {
    return quoted(fs::path(MIRAGE_SOURCE_DIR) / "scenes" / (name + ".pov"));
}

TEST(ColourCli, TraceInColourAndMonochrome) {
    const auto dir = test_dir("colour_cli", "trace");
    auto r = run_tool("trace " + scene("sunset") + " -W 64 -H 48 -o " + quoted(dir / "c.png"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("colour: red 610 nm, green 550 nm, blue 465 nm"), std::string::npos)
        << r.out;
    // 3 x 3072 camera rays (the sea's reflected rays come on top).
    EXPECT_NE(r.out.find("64x48: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" rays (9216 camera, "), std::string::npos) << r.out;
    auto m = run_tool("trace " + scene("sunset") + " -W 64 -H 48 --monochrome -o " +
                      quoted(dir / "m.png"));
    ASSERT_EQ(m.exit_code, 0) << m.err;
    EXPECT_EQ(m.out.find("colour:"), std::string::npos) << m.out;
    EXPECT_NE(m.out.find(" rays (3072 camera, "), std::string::npos) << m.out;
    auto fm = run_tool("trace " + scene("fata_morgana") + " -W 48 -H 16 --colour -q -o " +
                       quoted(dir / "fm.png"));
    EXPECT_EQ(fm.exit_code, 0) << fm.err;
    EXPECT_TRUE(read_image((dir / "fm.png").string()).ok());
}

TEST(ColourCli, BadWavelengthsAreNamed) {
    const auto dir = test_dir("colour_cli", "bad");
    auto few = run_tool("trace " + scene("fata_morgana") + " --wavelengths 610,550 -o " +
                        quoted(dir / "x.png"));
    EXPECT_EQ(few.exit_code, 1);
    EXPECT_EQ(few.err,
              "mirage trace: --wavelengths 610,550: give three wavelengths, the red, green and "
              "blue channels' (nm), e.g. 610,550,465\n");
    auto road = run_tool("compile " + scene("road") + " --wavelengths 610,550,465 -o " +
                         quoted(dir / "road"));
    EXPECT_EQ(road.exit_code, 1);
    EXPECT_NE(road.err.find("road.pov: the wavelength 610 nm: an exponential profile"),
              std::string::npos)
        << road.err;
    EXPECT_FALSE(fs::exists(dir / "road" / "road-610nm" / "road.ini"));
    auto far = run_tool("compile " + scene("fata_morgana") + " --wavelengths 610,550,2000 -o " +
                        quoted(dir / "fm"));
    EXPECT_EQ(far.exit_code, 1);
    EXPECT_EQ(far.err,
              "mirage compile: --wavelengths 610,550,2000: the blue channel's wavelength 2000 nm "
              "must be from 300 to 1690 nm (Ciddor's range)\n");
    auto both =
        run_tool("trace " + scene("sunset") + " --colour --monochrome -o " + quoted(dir / "x.png"));
    EXPECT_NE(both.exit_code, 0);
    EXPECT_NE(both.err.find("--colour excludes --monochrome"), std::string::npos) << both.err;
}

TEST(ColourCli, CompileWritesADesignPerWavelength) {
    const auto dir = test_dir("colour_cli", "compile");
    const fs::path scenes = fs::path(MIRAGE_SOURCE_DIR) / "scenes";
    // hot_road.pov takes Gladstone-Dale's index: refused by name.
    auto gd = run_tool("compile " + quoted(scenes / "hot_road.pov") + " -W 48 -H 36 --colour -o " +
                       quoted(dir / "gd"));
    EXPECT_EQ(gd.exit_code, 1);
    EXPECT_NE(gd.err.find("Gladstone-Dale's index has no wavelength"), std::string::npos) << gd.err;
    // The same road through Ciddor's index on flat ground: a design per wavelength.
    fs::copy_file(scenes / "hot_road.csv", dir / "hot_road.csv",
                  fs::copy_options::overwrite_existing);
    {
        std::ifstream in(scenes / "hot_road.pov");
        std::ofstream out(dir / "road.pov");
        for (std::string line; std::getline(in, line);) {
            out << line << "\n";
            if (line.rfind("#declare Mirage_Sounding", 0) == 0)
                out << "#declare Mirage_Earth_Radius = 0;\n#declare Mirage_Index = \"ciddor\";\n";
        }
    }
    auto r = run_tool("compile " + quoted(dir / "road.pov") + " -W 48 -H 36 --colour -o " +
                      quoted(dir / "out"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* nm : {"610", "550", "465"}) {
        EXPECT_TRUE(fs::exists(dir / "out" / ("road-" + std::string(nm) + "nm") / "road.ini"))
            << nm;
        EXPECT_NE(r.out.find(" " + std::string(nm) + " nm: "), std::string::npos) << r.out;
    }
    EXPECT_FALSE(fs::exists(dir / "out" / "road.png"));  // rendered with --render only
}

}  // namespace
}  // namespace mirage
