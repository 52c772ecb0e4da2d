// The path command's fan diagram: how far it is drawn, and the fan's rays through turbulent air.
#include "paths/path_diagram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "atmosphere/exact_ray.h"

namespace mirage {
namespace {

constexpr double kPi = 3.14159265358979323846;

PathAir hot_road() {
    PathAirOptions a;
    a.preset = "hot-road";
    return *resolve_reference_air(a);
}

TEST(PathDiagram, TheFanIsDrawnFarEnoughForEveryTurnAndGroundHit) {
    const PathAir air = hot_road();
    // A fan of rays turning above the road and one of rays reaching it, from a low eye.
    for (const auto& [eye, elevation] : {std::pair{1.5, -0.5}, std::pair{0.2, -10.0}}) {
        PathOptions o;
        o.eye_height = eye;
        o.fan_count = 5;
        const RayDiagramSettings st = fan_diagram_settings(o, air, elevation);
        // The default fan about a downward ray: from twice its elevation to a quarter of it
        // above level.
        EXPECT_EQ(st.elev_from_deg, 2.0 * elevation);
        EXPECT_EQ(st.elev_to_deg, -0.25 * elevation);
        double reach = 10.0 * eye, ground = 0.0;
        for (int j = 0; j < 5; ++j) {
            const double e = (2.0 * elevation - 2.25 * elevation * j / 4) * kPi / 180;
            auto ray = make_exact_ray(*air.atmosphere.exponential_profile(), eye, kPi / 2 - e);
            ASSERT_TRUE(ray.ok());
            if (ray->turn_kind == TurnKind::Ahead) reach = std::max(reach, 1.6 * ray->dz_turn);
            if (ray->hits_ground) ground = std::max(ground, 1.1 * ray->dz_ground);
        }
        reach = std::max(reach, ground);
        EXPECT_GT(reach, 10.0 * eye);
        EXPECT_DOUBLE_EQ(st.max_distance, std::min(reach, 1e6)) << elevation;
        o.max_distance = 77.0;
        EXPECT_EQ(fan_diagram_settings(o, air, elevation).max_distance, 77.0);
    }
}

TEST(PathDiagram, PerturbedRaysStartAtTheEyeAndStopAtTheGround) {
    PathOptions o;
    o.eye_height = 1.5;
    o.fan_count = 3;
    o.realizations = 2;
    o.turbulence_cn2 = 1e-10;
    RayDiagramSettings st = fan_diagram_settings(o, hot_road(), -0.3);
    ASSERT_TRUE(add_perturbed_rays(o, st).ok());
    ASSERT_EQ(st.overlaid.size(), 6u);
    for (size_t k = 0; k < st.overlaid.size(); ++k) {
        const OverlaidRay& r = st.overlaid[k];
        EXPECT_EQ(r.fan_ray, int(k % 3));
        ASSERT_GE(r.points.size(), 2u);
        EXPECT_EQ(r.points.front().x, 0.0);
        EXPECT_DOUBLE_EQ(r.points.front().y, 1.5);
        for (const auto& p : r.points) EXPECT_GE(p.y, 0.0);
    }
    EXPECT_EQ(st.overlaid_label, "through turbulent air, C_n^2 1e-10 m^-2/3, 2 realizations");

    o.turbulence_seed = 1.5;
    EXPECT_EQ(add_perturbed_rays(o, st).message(),
              "--turbulence-seed 1.5: must be a whole number from 0 to 4294967295");
    o.turbulence_seed = 1.0;
    o.turbulence_cn2 = 0.0;
    EXPECT_EQ(add_perturbed_rays(o, st).message(),
              "--turbulence-cn2 0: nothing to draw (give more than 0)");
}

}  // namespace
}  // namespace mirage
