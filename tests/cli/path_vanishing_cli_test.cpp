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
