// mirage path --object-height/--object-distance: where a point's mirrored image vanishes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "atmosphere/vanishing.h"
#include "run_tool.h"

namespace mirage {
namespace {

using testing::run_tool;

TEST(PathVanishingCli, PrintsTheNearestEyeDistanceAndWhetherAPointIsMirrored) {
    auto reach = mirror_reach(*preset_profile("paper"), 1.5, 3.5);
    ASSERT_TRUE(reach.ok());
    const double d = reach->nearest;
    for (const double at : {d * 0.99, d * 1.01}) {
        const auto r = run_tool(
            "path --preset paper --eye-height 1.5 --object-height 3.5 "
            "--object-distance " +
            std::to_string(at) + " --json");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_DOUBLE_EQ(j["nearest_eye_distance"].get<double>(), d);
        EXPECT_DOUBLE_EQ(j["farthest_eye_distance"].get<double>(), reach->farthest);
        EXPECT_EQ(j["mirrored"].get<bool>(), at > d) << "at " << at << " m";
    }
    const auto text = run_tool(
        "path --preset paper --eye-height 1.5 --object-height 3.5 "
        "--object-distance 12");
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("vanishing   nearest eye distance with a mirrored image 13.52"),
              std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("at 12 m    no mirrored image"), std::string::npos) << text.out;
}

// Real air: the hot road's sounding on the curved Earth, heights above the sphere.  A point is
// mirrored just beyond the nearest distance and not just before it, the curved Earth's
// distances differ from flat ground's by less than a percent (not at all would mean the
// radius was lost), and the closed forms' preset traced through the general engine
// (--general) gives the closed forms' figure.
TEST(PathVanishingCli, RealAirGivesTheGeneralEnginesDistancesAboveTheSphere) {
    const std::string source = MIRAGE_SOURCE_DIR;
    const std::string air = "path --sounding " + source +
                            "/scenes/hot_road.csv --earth-radius 6371000 --eye-height 1.2 "
                            "--object-height 1.9 --json";
    const auto r = run_tool(air);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double d = j["nearest_eye_distance"].get<double>();
    EXPECT_GT(d, 300.0);
    EXPECT_LT(d, 800.0);
    EXPECT_LT(d, j["farthest_eye_distance"].get<double>());
    EXPECT_TRUE(j.contains("air")) << "the air is described, not an exponential profile";
    for (const double at : {d * 0.99, d * 1.01}) {
        const auto near = run_tool(air + " --object-distance " + std::to_string(at));
        ASSERT_EQ(near.exit_code, 0) << near.err;
        EXPECT_EQ(nlohmann::json::parse(near.out)["mirrored"].get<bool>(), at > d) << at;
    }
    // Flat ground differs from the curved Earth by the sphere's fall, d^2 / 2R = 2 cm at 500 m:
    // the distances move, by less than a percent.
    const auto flat = run_tool("path --sounding " + source +
                               "/scenes/hot_road.csv --earth-radius 0 --eye-height 1.2 "
                               "--object-height 1.9 --json");
    ASSERT_EQ(flat.exit_code, 0) << flat.err;
    const double d_flat = nlohmann::json::parse(flat.out)["nearest_eye_distance"].get<double>();
    EXPECT_NE(d_flat, d);
    EXPECT_NEAR(d_flat, d, 0.01 * d);
    auto exact = mirror_reach(*preset_profile("hot-road"), 1.5, 2.5);
    ASSERT_TRUE(exact.ok());
    const auto general =
        run_tool("path --preset hot-road --general --eye-height 1.5 --object-height 2.5 --json");
    ASSERT_EQ(general.exit_code, 0) << general.err;
    EXPECT_NEAR(nlohmann::json::parse(general.out)["nearest_eye_distance"].get<double>(),
                exact->nearest, 1e-3 * exact->nearest);
}

TEST(PathVanishingCli, BadValuesAreNamed) {
    auto r = run_tool("path --preset paper --eye-height 1.5 --object-distance 14");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --object-distance needs the point's height: --object-height M\n");
    r = run_tool("path --preset paper --eye-height 1.5 --object-height 3 --object-distance -2");
    EXPECT_EQ(r.err, "mirage path: --object-distance -2: must be a distance > 0 m\n");
    r = run_tool("path --preset paper --eye-height 1.5 --object-height 0");
    EXPECT_EQ(r.err, "mirage path: object height 0: must be above the ground (> 0)\n");
    r = run_tool("path --preset cold-sea --eye-height 1.5 --object-height 3");
    EXPECT_EQ(r.err,
              "mirage path: the mirrored image that vanishes is the inferior mirage's: the "
              "profile is superior\n");
}

}  // namespace
}  // namespace mirage
