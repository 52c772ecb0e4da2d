#include "atmosphere/sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "rectangles.h"

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
    for (double dz : probes) {
        if (ray.hits_ground && dz > ray.dz_ground) continue;
        const double y = height_at(ray, dz);
        const double got = polyline_height(path, dz);
        const double allow = allowed_error(ray, st, dz, y);
        const double slack = 1e-12 * (1.0 + std::fabs(y));
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

using testing::Rectangles;

TEST(SamplerNear, WithoutObstaclesTheToleranceBoundsTheErrorEverywhere) {
    std::mt19937_64 rng(20261201);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int rays = 0;
    for (const auto& fam : families()) {
        for (int trial = 0; trial < 100; ++trial) {
            const double y0 = fam.y0_lo * std::pow(fam.y0_hi / fam.y0_lo, unit(rng));
            const double mag = fam.elev_lo * std::pow(0.5 / fam.elev_lo, unit(rng));
            const double elev = unit(rng) < 0.6 ? -mag : mag;
            auto ray = make_exact_ray(fam.profile, y0, M_PI / 2 - elev);
            ASSERT_TRUE(ray.ok()) << ray.message();
            SampleSettings st;
            st.tolerance_rad = std::pow(10.0, -2.0 - 3.0 * unit(rng));
            if (trial % 3 == 1) st.tolerance_m = 1e-4;
            if (trial % 3 == 2) st.start_distance = 10.0 * unit(rng);
            if (trial % 4 == 0) st.max_dz = 200.0 * unit(rng) + 1e-3;
            const auto path = sample_path_near(*ray, st, nullptr);
            EXPECT_TRUE(path.clear_length.empty());
            EXPECT_FALSE(path.end_clear);
            char what[300];
            std::snprintf(what, sizeof what,
                          "near %s y0=%.17g elev=%.17g tol_rad=%.17g tol_m=%g start=%.17g "
                          "max_dz=%.17g class=%s",
                          fam.name, y0, elev, st.tolerance_rad, st.tolerance_m, st.start_distance,
                          st.max_dz, std::string(ray_class_name(ray->ray_class)).c_str());
            check_bound(*ray, st, path, what);
            ++rays;
        }
    }
    EXPECT_EQ(rays, 600);
}

// The exact path, widened by the allowance, stays clear of every rectangle over [lo, hi].
bool stretch_is_clear(const ExactRay& ray, const SampleSettings& st, const Rectangles& obstacles,
                      double lo, double hi) {
    const int n = 200;
    for (int j = 0; j <= n; ++j) {
        const double dz = lo + (hi - lo) * j / n;
        const double y = height_at(ray, dz);
        const double a = allowed_error(ray, st, dz, y);
        for (const auto& r : obstacles.rects()) {
            if (dz >= r.dz_lo && dz <= r.dz_hi && y + a >= r.y_lo && y - a <= r.y_hi) return false;
        }
    }
    return true;
}

TEST(SamplerNear, CoarseOnlyWhereNothingLiesNearAndTheSameSegmentsElsewhere) {
    // Random rays among random rectangles: every segment not marked clear is one of the
    // segments sampled without obstacles (so it keeps the tolerance), every clear stretch of
    // the exact path, widened by the allowance, meets no rectangle, and where the path passes
    // through a rectangle it is sampled to the tolerance.
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int clear_segments = 0, fine_segments = 0, fewer = 0, rays = 0, inside = 0;
    for (const auto& fam : families()) {
        for (int trial = 0; trial < 60; ++trial) {
            const double y0 = fam.y0_lo * std::pow(fam.y0_hi / fam.y0_lo, unit(rng));
            const double mag = std::max(fam.elev_lo, 1e-4) * std::pow(0.2 / 1e-4, unit(rng));
            const double elev = unit(rng) < 0.6 ? -std::min(mag, 0.2) : std::min(mag, 0.2);
            auto ray = make_exact_ray(fam.profile, y0, M_PI / 2 - elev);
            ASSERT_TRUE(ray.ok()) << ray.message();
            SampleSettings st;
            st.tolerance_rad = std::pow(10.0, -3.0 - 2.0 * unit(rng));
            if (trial % 2) st.start_distance = 5.0 * unit(rng);
            const SampledPath full = sample_path_near(*ray, st, nullptr);
            // Rectangles about the path's own heights, somewhere along its sampled part.
            const double reach = std::max(full.points.back().x, 1.0);
            std::vector<Rectangles::Rect> rects;
            const int count = 1 + trial % 3;
            for (int k = 0; k < count; ++k) {
                const double dz = reach * unit(rng);
                const double w = reach * 0.05 * unit(rng) + 1e-3;
                const double y = height_at(*ray, dz) + (unit(rng) - 0.5) * 0.5 * y0;
                const double h = 0.1 * y0 * unit(rng) + 1e-3;
                rects.push_back({dz, dz + w, y, y + h});
            }
            const bool ground = trial % 5 == 0;
            const Rectangles obstacles(rects, ground);
            const SampledPath near = sample_path_near(*ray, st, &obstacles);
            char what[300];
            std::snprintf(what, sizeof what, "%s y0=%.17g elev=%.17g tol_rad=%.17g class=%s",
                          fam.name, y0, elev, st.tolerance_rad,
                          std::string(ray_class_name(ray->ray_class)).c_str());
            ASSERT_EQ(near.points.front(), full.points.front()) << what;
            EXPECT_EQ(near.end, full.end) << what;
            EXPECT_EQ(near.turns, full.turns) << what;
            if (!near.end_clear) {
                // The same last point (unless nothing is near the path at all).
                EXPECT_EQ(near.points.back(), full.points.back()) << what;
            } else {
                EXPECT_TRUE(stretch_is_clear(*ray, st, obstacles, 0.0, 4.0 * reach)) << what;
            }
            ASSERT_EQ(near.clear_length.size() + 1, near.points.size()) << what;
            for (std::size_t k = 1; k < near.points.size(); ++k) {
                const glm::dvec2 a = near.points[k - 1], b = near.points[k];
                if (near.clear_length[k - 1] > 0.0) {
                    ++clear_segments;
                    EXPECT_TRUE(stretch_is_clear(*ray, st, obstacles, a.x, b.x))
                        << what << ": segment " << k << " from dz " << a.x << " to " << b.x;
                    // Its length is the arc's, between the chord and the chord plus a bit.
                    const double chord = std::hypot(b.x - a.x, b.y - a.y);
                    EXPECT_GE(near.clear_length[k - 1], chord * (1.0 - 1e-12)) << what;
                    EXPECT_LE(near.clear_length[k - 1], chord * 1.01) << what;
                    continue;
                }
                ++fine_segments;
                // One of the full sampling's segments.
                const auto at = std::find(full.points.begin(), full.points.end(), a);
                ASSERT_NE(at, full.points.end()) << what << ": point " << k - 1;
                ASSERT_NE(at + 1, full.points.end()) << what;
                EXPECT_EQ(*(at + 1), b) << what << ": segment " << k;
            }
            // Where the path crosses a rectangle, a fine segment covers it.
            for (const auto& r : rects) {
                for (int j = 0; j <= 50; ++j) {
                    const double dz = r.dz_lo + (r.dz_hi - r.dz_lo) * j / 50;
                    if (ray->hits_ground && dz > ray->dz_ground) continue;
                    if (dz > near.points.back().x) continue;
                    const double y = height_at(*ray, dz);
                    if (y < r.y_lo || y > r.y_hi) continue;
                    std::size_t k = 1;
                    while (k + 1 < near.points.size() && near.points[k].x < dz) ++k;
                    EXPECT_EQ(near.clear_length[k - 1], 0.0) << what << " at dz " << dz;
                    ++inside;
                }
            }
            if (near.points.size() < full.points.size()) ++fewer;
            ++rays;
        }
    }
    std::printf("%d rays: %d clear segments, %d fine; fewer points for %d; %d points in boxes\n",
                rays, clear_segments, fine_segments, fewer, inside);
    EXPECT_EQ(rays, 360);
    // The obstacles do leave work out, and do not leave out everything.
    EXPECT_GT(clear_segments, 200);
    EXPECT_GT(fine_segments, 200);
    EXPECT_GT(inside, 200);
    EXPECT_GT(fewer, rays / 3);
}

TEST(SamplerNear, NothingNearAnEscapingPathLeavesItsStartAndStraightEnd) {
    auto ray = make_exact_ray(*preset_profile("paper"), 1.5, M_PI / 2 + 0.05);
    ASSERT_TRUE(ray.ok());
    ASSERT_EQ(ray->ray_class, RayClass::InfTurn);
    SampleSettings st;
    st.tolerance_rad = 1e-4;
    // Far below the path and far above it: nothing near.
    const Rectangles away({{0.0, 1e4, -10.0, -5.0}, {0.0, 1e4, 1e6, 2e6}});
    const int asked_before = away.asked();
    const SampledPath near = sample_path_near(*ray, st, &away);
    // Only the final direction counts: the start, then straight along the asymptote, untested.
    ASSERT_EQ(near.points.size(), 1u);
    EXPECT_TRUE(near.end_clear);
    EXPECT_EQ(near.end, PathEnd::Straight);
    EXPECT_TRUE(near.turns);  // the ray's turning point, though not among the points
    EXPECT_EQ(near.dz_turn, ray->dz_turn);
    EXPECT_EQ(near.end_slope, asymptotic_slope(*ray));
    EXPECT_EQ(away.asked() - asked_before, 1);  // the one question about the whole wedge
    // A rising ray the same, and its straight end from the start misses the boxes too.
    auto up = make_exact_ray(*preset_profile("paper"), 1.5, M_PI / 2 - 0.05);
    ASSERT_TRUE(up.ok());
    ASSERT_EQ(up->ray_class, RayClass::InfUp);
    const SampledPath sky = sample_path_near(*up, st, &away);
    ASSERT_EQ(sky.points.size(), 1u);
    EXPECT_TRUE(sky.end_clear);
    EXPECT_EQ(sky.end_slope, asymptotic_slope(*up));
    for (const auto& r : away.rects()) {
        // The line y0 + end_slope dz against each rectangle, over its stretch of dz.
        const double ya = up->y0 + sky.end_slope * r.dz_lo;
        const double yb = up->y0 + sky.end_slope * r.dz_hi;
        EXPECT_TRUE((ya < r.y_lo && yb < r.y_lo) || (ya > r.y_hi && yb > r.y_hi));
    }
    // A box on the way up after the turn brings the sampling back, and its stretch is fine.
    const double dz = 3.0 * ray->dz_turn;
    const double y = height_at(*ray, dz);
    const Rectangles post({{dz, dz + 0.1, y - 0.01, y + 0.01}});
    const SampledPath met = sample_path_near(*ray, st, &post);
    EXPECT_FALSE(met.end_clear);
    EXPECT_GT(met.points.size(), 3u);
    EXPECT_GT(post.asked(), 1);
    std::size_t k = 1;
    while (met.points[k].x < dz) ++k;
    EXPECT_EQ(met.clear_length[k - 1], 0.0);
}

TEST(RegionTest, MeetsExactlyTheRectanglesThatOverlapTheRegion) {
    // A strip between a lower line of slope 1 through (0, 0) and an upper one through (0, 1),
    // over dz in [0, 10].
    PathRegion r;
    r.dz_lo = 0.0;
    r.dz_hi = 10.0;
    r.lower = {PathLine{0.0, 0.0, 1.0}, PathLine{0.0, 0.0, 1.0}};
    r.upper = {PathLine{0.0, 1.0, 1.0}, PathLine{0.0, 1.0, 1.0}};
    r.lower_count = r.upper_count = 1;
    EXPECT_TRUE(region_meets_rectangle(r, 4.0, 5.0, 4.5, 4.6));       // inside
    EXPECT_FALSE(region_meets_rectangle(r, 4.0, 5.0, 6.5, 7.0));      // above
    EXPECT_FALSE(region_meets_rectangle(r, 4.0, 5.0, 2.0, 2.9));      // below
    EXPECT_TRUE(region_meets_rectangle(r, 4.0, 5.0, 5.9, 7.0));       // the upper corner
    EXPECT_FALSE(region_meets_rectangle(r, 11.0, 12.0, 11.0, 12.0));  // beyond dz_hi
    EXPECT_TRUE(region_meets_rectangle(r, -5.0, 20.0, 5.0,
                                       std::numeric_limits<double>::infinity()));  // to the sky
    // A second lower line (a tent) cuts the strip's middle: level at 3.
    r.lower[1] = PathLine{0.0, 3.0, 0.0};
    r.lower_count = 2;
    EXPECT_FALSE(region_meets_rectangle(r, 1.0, 1.5, 0.0, 2.0));
    EXPECT_TRUE(region_meets_rectangle(r, 1.0, 2.5, 0.0, 3.2));
}

}  // namespace
}  // namespace mirage
