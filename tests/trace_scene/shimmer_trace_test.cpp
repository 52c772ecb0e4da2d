// `mirage trace` of a scene with turbulent air: the still shimmers (differs from the calm one),
// is the same bytes for the same seed and clock at any thread count, follows the clock as the
// wind says, and C_n^2 = 0 is the calm scene byte for byte.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

class ShimmerTrace : public ::testing::Test {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_shimmer_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }

    // A long lens (2 degrees) on a fine checker 50 m away over a hot road's mirage: the shifts
    // of a few hundredths of a pixel move many pixel centres across a square's edge.
    std::string scene(const std::string& name, const std::string& settings) {
        const fs::path p = dir_ / (name + ".pov");
        std::ofstream(p) << "#declare Mirage_Preset = \"hot-road\";\n"
                         << settings << "\n#include \"mirage.inc\"\n"
                         << "camera { location <0, 1.2, 0> look_at <0, 1.2, 50> angle 2 }\n"
                            "light_source { <10, 30, -10> rgb 1 }\n"
                            "plane { y, 0 pigment { rgb 0.3 } }\n"
                            "box { <-5, 0, 50>, <5, 3, 50.1> pigment { checker rgb 0 rgb 1 "
                            "scale 0.02 } finish { ambient 1 diffuse 0 } }\n";
        return p.string();
    }
    Image trace(const std::string& path, int threads = 0, std::optional<double> clock = {},
                bool scanline = false) {
        TraceOptions o;
        o.scanline_paths = scanline;
        o.scene = path;
        o.width = 64;
        o.height = 48;
        o.progress = false;
        o.threads = threads;
        o.clock = clock;
        auto r = trace_scene(o);
        EXPECT_TRUE(r.ok()) << r.message();
        return r.ok() ? r->render.image : Image{};
    }
};

int differing(const Image& a, const Image& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    int n = 0;
    for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i)
        n += a.pixels[i] != b.pixels[i];
    return n;
}

TEST_F(ShimmerTrace, TheStillShimmersAndIsReproducible) {
    const std::string air =
        "#declare Mirage_Turbulence_Cn2 = 1e-12;\n#declare Mirage_Turbulence_Seed = 7;\n"
        "#declare Mirage_Wind = <2, 0, 0>;";
    const Image calm = trace(scene("calm", ""));
    const Image one = trace(scene("air", air), 1);
    const Image two = trace(scene("air", air), 2);
    EXPECT_GT(differing(calm, one), 50) << "the turbulence moves no pixel";
    EXPECT_EQ(differing(one, two), 0) << "1 and 2 threads differ";
    // C_n^2 = 0 is the calm scene, byte for byte, whatever goes with it.
    EXPECT_EQ(differing(calm, trace(scene("zero",
                                          "#declare Mirage_Turbulence_Cn2 = 0;\n"
                                          "#declare Mirage_Wind = <2, 0, 0>;"))),
              0);
    // Another seed, other air.
    const Image other = trace(scene("other",
                                    "#declare Mirage_Turbulence_Cn2 = 1e-12;\n"
                                    "#declare Mirage_Turbulence_Seed = 8;\n"
                                    "#declare Mirage_Wind = <2, 0, 0>;"));
    EXPECT_GT(differing(one, other), 50);
}

// Per-scanline paths (one path per row, Khote & Howard) are walked through the air too, with or
// without an atmosphere that bends them.
TEST_F(ShimmerTrace, ScanlinePathsShimmerToo) {
    const std::string air = "#declare Mirage_Turbulence_Cn2 = 1e-12;";
    const Image calm = trace(scene("calm", ""), 0, {}, true);
    const Image one = trace(scene("air", air), 1, {}, true);
    EXPECT_GT(differing(calm, one), 50);
    EXPECT_EQ(differing(one, trace(scene("air", air), 2, {}, true)), 0);
    const fs::path straight = dir_ / "straight.pov";
    std::ofstream(straight) << air
                            << "\ncamera { location <0, 1.2, 0> look_at <0, 1.2, 50> angle 2 }\n"
                            << "box { <-5, 0, 50>, <5, 3, 50.1> pigment { checker rgb 0 rgb 1 "
                               "scale 0.02 } finish { ambient 1 diffuse 0 } }\n";
    const fs::path still = dir_ / "still.pov";
    std::ofstream(still) << "camera { location <0, 1.2, 0> look_at <0, 1.2, 50> angle 2 }\n"
                         << "box { <-5, 0, 50>, <5, 3, 50.1> pigment { checker rgb 0 rgb 1 "
                            "scale 0.02 } finish { ambient 1 diffuse 0 } }\n";
    EXPECT_GT(differing(trace(still.string(), 0, {}, true), trace(straight.string(), 0, {}, true)),
              50);
}

// The air reaches the farthest bounded object; a scene without one must say how far.
TEST_F(ShimmerTrace, AirWithoutAReachIsRefused) {
    const fs::path p = dir_ / "open.pov";
    std::ofstream(p) << "#declare Mirage_Turbulence_Cn2 = 1e-12;\n"
                        "camera { location <0, 1.2, 0> look_at <0, 1.2, 50> }\n"
                        "plane { y, 0 pigment { rgb 1 } }\n";
    TraceOptions o;
    o.scene = p.string();
    o.progress = false;
    auto r = trace_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), p.string() +
                               ": Mirage_Turbulence_Cn2: the scene has no bounded object to say "
                               "how far the turbulent air reaches: declare Mirage_Extent");
    std::ofstream(p, std::ios::app) << "#declare Mirage_Extent = 100;\n";
    EXPECT_TRUE(trace_scene(o).ok());
}

TEST_F(ShimmerTrace, TheClockMovesTheAirWithTheWind) {
    const std::string windy = scene("windy",
                                    "#declare Mirage_Turbulence_Cn2 = 1e-12;\n"
                                    "#declare Mirage_Wind = <2, 0, 0>;");
    const std::string still = scene("still", "#declare Mirage_Turbulence_Cn2 = 1e-12;");
    const Image at0 = trace(windy, 0, 0.0);
    EXPECT_EQ(differing(at0, trace(windy)), 0) << "no clock is clock 0";
    EXPECT_EQ(differing(at0, trace(windy, 0, 0.0)), 0);
    const Image later = trace(windy, 0, 0.5);
    EXPECT_GT(differing(at0, later), 50) << "the wind moved nothing in half a second";
    // Without wind the air stands still: the clock changes nothing.
    EXPECT_EQ(differing(trace(still, 0, 0.0), trace(still, 0, 0.5)), 0);
}

}  // namespace
}  // namespace mirage
