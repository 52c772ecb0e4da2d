#include "atmosphere/sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mirage {
namespace {

struct Family {
    const char* name;
    Profile profile;
    double y0_lo, y0_hi;  // start heights, m (log-uniform)
    double elev_lo;       // smallest |elevation|, rad (log-uniform up to 0.5)
};

std::vector<Family> families() {
    return {
        {"paper", *preset_profile("paper"), 0.05, 5.0, 1e-9},
        {"hot-road", *preset_profile("hot-road"), 0.05, 3.0, 1e-8},
        {"paper-superior", *preset_profile("paper-superior"), 0.05, 5.0, 1e-9},
        {"cold-sea", *preset_profile("cold-sea"), 0.1, 20.0, 1e-8},
        {"stiff", Profile{ProfileKind::Inferior, 1.00026383734375, 5.93e-3, 1000.0}, 0.5, 2.0,
         1e-6},
        {"tiny-eta1", Profile{ProfileKind::Inferior, 1.0003, 1e-6, 2.303}, 0.5, 2.0, 1e-8},
    };
}

// Checks the sampler's stated bound densely: |polyline - exact| <= allowance at every dz,
// and, with an angular tolerance only, the angle seen from the start stays within it.
void check_bound(const ExactRay& ray, const SampleSettings& st, const SampledPath& path,
                 const std::string& what) {
    ASSERT_GE(path.points.size(), 1u) << what;
    EXPECT_EQ(path.points.front().x, 0.0) << what;
    EXPECT_EQ(path.points.front().y, ray.y0) << what;
    for (size_t k = 1; k < path.points.size(); ++k)
        ASSERT_GE(path.points[k].x, path.points[k - 1].x) << what << " point " << k;
    const double last = path.points.back().x;
    // Where to look: the sampled part, and far along the straight end.
    double reach = last;
    if (path.end == PathEnd::Straight)
        reach = std::max(20.0 * last, last + std::min(40.0 / ray.c, 1e5));
    if (path.end == PathEnd::Ground) {
        EXPECT_EQ(path.points.back().y, 0.0) << what;
    }
    std::vector<double> probes;
    const int n = 4000;
    for (int j = 0; j <= n; ++j) probes.push_back(reach * j / n);
    for (size_t k = 1; k < path.points.size(); ++k) {  // mid-chords, where errors peak
        probes.push_back(0.5 * (path.points[k - 1].x + path.points[k].x));
        probes.push_back(0.75 * path.points[k - 1].x + 0.25 * path.points[k].x);
    }
    double worst = 0.0;
    for (double dz : probes) {
        if (ray.hits_ground && dz > ray.dz_ground) continue;
        const double y = height_at(ray, dz);
        const double got = polyline_height(path, dz);
        const double allow = allowed_error(ray, st, dz, y);
        const double slack = 1e-12 * (1.0 + std::fabs(y));
        worst = std::max(worst, std::fabs(got - y) / allow);
        ASSERT_LE(std::fabs(got - y), allow + slack)
            << what << " at dz = " << dz << ": polyline " << got << ", exact " << y
            << ", allowance " << allow << " (" << path.points.size() << " points)";
        if (st.tolerance_m == 0.0 && st.start_distance == 0.0 && dz > 0.0) {
            const double a_exact = std::atan2(y - ray.y0, dz);
            const double a_poly = std::atan2(got - ray.y0, dz);
            ASSERT_LE(std::fabs(a_exact - a_poly), st.tolerance_rad * (1.0 + 1e-9) + 1e-15)
                << what << " angle at dz = " << dz;
        }
    }
    (void)worst;
}

TEST(Sampler, ToleranceBoundsTheErrorOverManyRandomRays) {
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int rays = 0;
    for (const auto& fam : families()) {
        for (int trial = 0; trial < 150; ++trial) {
            const double y0 = fam.y0_lo * std::pow(fam.y0_hi / fam.y0_lo, unit(rng));
            const double mag = fam.elev_lo * std::pow(0.5 / fam.elev_lo, unit(rng));
            const double elev = unit(rng) < 0.6 ? -mag : mag;
            auto ray = make_exact_ray(fam.profile, y0, M_PI / 2 - elev);
            ASSERT_TRUE(ray.ok()) << ray.message();
            SampleSettings st;
            const int mode = trial % 3;
            st.tolerance_rad = std::pow(10.0, -2.0 - 3.0 * unit(rng));
            if (mode == 1) st.tolerance_m = 1e-4;
            if (mode == 2) st.start_distance = 10.0 * unit(rng);
            if (trial % 4 == 0) st.max_dz = 200.0 * unit(rng) + 1e-3;
            const auto path = sample_path(*ray, st);
            char what[300];
            std::snprintf(what, sizeof what,
                          "%s y0=%.17g elev=%.17g tol_rad=%.17g tol_m=%g start=%.17g max_dz=%.17g "
                          "class=%s",
                          fam.name, y0, elev, st.tolerance_rad, st.tolerance_m, st.start_distance,
                          st.max_dz, std::string(ray_class_name(ray->ray_class)).c_str());
            check_bound(*ray, st, path, what);
            ++rays;
        }
    }
    EXPECT_EQ(rays, 900);
}

TEST(Sampler, TurningRayIsMirroredAboutItsVertex) {
    auto ray = make_exact_ray(*preset_profile("paper"), 1.5, M_PI / 2 + 0.2);
    ASSERT_TRUE(ray.ok());
    ASSERT_EQ(ray->ray_class, RayClass::InfTurn);
    SampleSettings st;
    st.tolerance_rad = 1e-4;
    const auto path = sample_path(*ray, st);
    ASSERT_TRUE(path.turns);
    // Every sample before the vertex has its mirror image after it, at the same height.
    int mirrored = 0;
    for (const auto& p : path.points) {
        if (p.x <= 0.0 || p.x >= ray->dz_turn) continue;
        const double mirror = 2.0 * ray->dz_turn - p.x;
        for (const auto& q : path.points) {
            if (std::fabs(q.x - mirror) < 1e-12 * mirror) {
                EXPECT_EQ(q.y, p.y);
                ++mirrored;
            }
        }
    }
    EXPECT_GT(mirrored, 5);
    EXPECT_EQ(path.end, PathEnd::Straight);
    EXPECT_NEAR(path.end_slope, asymptotic_slope(*ray), 1e-15);
}

TEST(Sampler, SampleCountGrowsAsTheInverseSquareRootOfTheTolerance) {
    // Adaptive sampling on y'' needs O(tol^-1/2) points; uniform steps would need far more
    // and a sampler ignoring curvature would not grow at all.
    auto ray = make_exact_ray(*preset_profile("paper"), 1.5, M_PI / 2 + 0.1);
    ASSERT_TRUE(ray.ok());
    SampleSettings coarse, fine;
    coarse.tolerance_m = 1e-4;
    fine.tolerance_m = 1e-6;
    coarse.max_dz = fine.max_dz = 60.0;
    const double n_coarse = sample_path(*ray, coarse).points.size();
    const double n_fine = sample_path(*ray, fine).points.size();
    EXPECT_GT(n_fine / n_coarse, 6.0);
    EXPECT_LT(n_fine / n_coarse, 14.0);
}

TEST(Sampler, StraightAtmosphereGivesOneSegment) {
    Profile none{ProfileKind::None, 1.0, 0.0, 1.0};
    auto ray = make_exact_ray(none, 1.5, M_PI / 2 + 0.1);
    ASSERT_TRUE(ray.ok());
    SampleSettings st;
    st.tolerance_rad = 1e-3;
    const auto path = sample_path(*ray, st);
    ASSERT_EQ(path.points.size(), 2u);
    EXPECT_EQ(path.end, PathEnd::Ground);
    EXPECT_NEAR(path.points[1].x, 1.5 / std::tan(0.1), 1e-12);
}

}  // namespace
}  // namespace mirage
