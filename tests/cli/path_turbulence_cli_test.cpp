// `mirage path --svg ... --turbulence-cn2`: the fan's rays through realizations of turbulent air,
// drawn dashed over the exact paths.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "run_tool.h"
#include "test_temp.h"

namespace mirage {
namespace {

using testing::quoted;
using testing::read_bytes;
using testing::run_tool;
using testing::test_temp_path;

// The points of the dashed polylines, in order.
std::vector<std::string> dashed(const std::string& svg) {
    std::vector<std::string> out;
    const std::string mark = "stroke-dasharray=\"3,2\" points=\"";
    for (auto at = svg.find(mark); at != std::string::npos; at = svg.find(mark, at + 1)) {
        const auto begin = at + mark.size();
        out.push_back(svg.substr(begin, svg.find('"', begin) - begin));
    }
    return out;
}

TEST(PathTurbulenceCli, DrawsEachRealizationOfEachRay) {
    const auto dir = test_temp_path("path_turbulence");
    std::filesystem::create_directories(dir);
    const std::string fan =
        "path --preset hot-road --eye-height 1.5 --elevation-deg -0.3 "
        "--fan-count 5 --svg ";
    auto calm = run_tool(fan + quoted(dir / "calm.svg"));
    ASSERT_EQ(calm.exit_code, 0) << calm.err;
    EXPECT_TRUE(dashed(read_bytes(dir / "calm.svg")).empty());
    auto r = run_tool(fan + quoted(dir / "air.svg") +
                      " --turbulence-cn2 1e-10 --turbulence-aperture 0.05 --realizations 3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string svg = read_bytes(dir / "air.svg");
    const std::vector<std::string> rays = dashed(svg);
    ASSERT_EQ(rays.size(), 15u);  // 3 realizations x 5 rays
    // Every realization moves every ray its own way.
    EXPECT_EQ(std::set<std::string>(rays.begin(), rays.end()).size(), 15u);
    EXPECT_NE(svg.find("dashed: through turbulent air, C_n^2 1e-10 m^-2/3, 3 realizations"),
              std::string::npos);
    // The same seed draws the same air; another seed, other air.
    auto again = run_tool(fan + quoted(dir / "again.svg") +
                          " --turbulence-cn2 1e-10 --turbulence-aperture 0.05 --realizations 3");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(dashed(read_bytes(dir / "again.svg")), rays);
    auto other = run_tool(fan + quoted(dir / "other.svg") +
                          " --turbulence-cn2 1e-10 --turbulence-aperture 0.05 --realizations 3 "
                          "--turbulence-seed 9");
    ASSERT_EQ(other.exit_code, 0) << other.err;
    EXPECT_NE(dashed(read_bytes(dir / "other.svg")), rays);
    std::filesystem::remove_all(dir);
}

TEST(PathTurbulenceCli, BadValuesAreNamed) {
    const auto dir = test_temp_path("path_turbulence_bad");
    std::filesystem::create_directories(dir);
    const std::string fan = "path --preset hot-road --eye-height 1.5 --elevation-deg -0.3 --svg " +
                            quoted(dir / "f.svg");
    auto r = run_tool(
        "path --preset hot-road --eye-height 1.5 --elevation-deg -0.3 "
        "--turbulence-cn2 1e-12");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(
        r.err.find("--turbulence-cn2 draws perturbed rays on the ray diagram: give --svg FILE"),
        std::string::npos)
        << r.err;
    r = run_tool(fan + " --turbulence-cn2 -1e-12");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("--turbulence-cn2 and its options: C_n^2 -1e-12 m^-2/3 must be from 0 "
                         "to 1e-08 m^-2/3"),
              std::string::npos)
        << r.err;
    r = run_tool(fan + " --turbulence-cn2 1e-12 --turbulence-seed 1.5");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("--turbulence-seed 1.5: must be a whole number from 0 to 4294967295"),
              std::string::npos)
        << r.err;
    r = run_tool(fan + " --turbulence-cn2 1e-12 --turbulence-aperture 30");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("--turbulence-aperture: aperture 30 m must be from 0 to 10 m"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "f.svg"));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mirage
