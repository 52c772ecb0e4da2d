#include "atmosphere/path_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "air_fixtures.h"
#include "rectangles.h"

namespace mirage {
namespace {

struct Family {
    const char* name;
    Atmosphere atmosphere;
    double y0_lo, y0_hi;  // start heights, m (log-uniform)
    double elev_lo;       // smallest |elevation|, rad (log-uniform up to elev_hi)
    double elev_hi;
    double reach;  // largest max_dz, m
};

std::vector<Family> families() {
    using namespace testing;
    std::vector<Family> f;
    // The exponential presets through the interface (closed forms underneath).
    f.push_back({"paper closed form", Atmosphere::exponential(*preset_profile("paper")), 0.05, 5.0,
                 1e-9, 0.5, 200});
    f.push_back({"cold-sea closed form", Atmosphere::exponential(*preset_profile("cold-sea")), 0.1,
                 20.0, 1e-8, 0.5, 2000});
    // The general engine.
    f.push_back({"paper fitted",
                 Atmosphere::quadratic(fit_or_die(exponential_spec("paper"), 1e-10)), 0.05, 5.0,
                 1e-8, 0.5, 200});
    f.push_back({"hot road temperatures", Atmosphere::quadratic(fit_or_die(hot_road_spec(), 1e-10)),
                 0.05, 3.0, 1e-7, 0.1, 1000});
    f.push_back({"road duct", Atmosphere::quadratic(fit_or_die(road_duct_spec(), 1e-10)), 0.05, 4.0,
                 1e-7, 0.05, 3000});
    f.push_back({"young smooth, curved", Atmosphere::quadratic(fit_or_die(young_spec(0.85), 1e-10)),
                 5.0, 120.0, 1e-6, 0.02, 60000});
    return f;
}

// The sampler's stated bound, checked densely: |polyline - exact| <= allowance at every dz (4000
// even probes, and the middle and quarter of every chord), and with an angular tolerance only,
// the angle seen from the start stays within it.
void check_bound(const ExactPath& path, const SampleSettings& st, const SampledPath& poly,
                 const std::string& what) {
    ASSERT_GE(poly.points.size(), 1u) << what;
    EXPECT_EQ(poly.points.front().x, 0.0) << what;
    EXPECT_EQ(poly.points.front().y, path.y0()) << what;
    for (size_t k = 1; k < poly.points.size(); ++k)
        ASSERT_GE(poly.points[k].x, poly.points[k - 1].x) << what << " point " << k;
    const double last = poly.points.back().x;
    double reach = last;
    if (poly.end == PathEnd::Straight) reach = std::max(20.0 * last, last + 1e4);
    if (poly.end == PathEnd::Ground) {
        EXPECT_EQ(poly.points.back().y, 0.0) << what;
    }
    std::vector<double> probes;
    for (int j = 0; j <= 4000; ++j) probes.push_back(reach * j / 4000);
    for (size_t k = 1; k < poly.points.size(); ++k) {
        probes.push_back(0.5 * (poly.points[k - 1].x + poly.points[k].x));
        probes.push_back(0.75 * poly.points[k - 1].x + 0.25 * poly.points[k].x);
    }
    for (double dz : probes) {
        if (path.hits_ground() && dz > path.dz_ground()) continue;
        const double y = path.height_at(dz);
        const double got = polyline_height(poly, dz);
        const double allow = allowed_error(path, st, dz, y);
        const double slack = 1e-12 * (1.0 + std::fabs(y));
        ASSERT_LE(std::fabs(got - y), allow + slack)
            << what << " at dz = " << dz << ": polyline " << got << ", exact " << y
            << ", allowance " << allow << " (" << poly.points.size() << " points)";
        if (st.tolerance_m == 0.0 && st.start_distance == 0.0 && dz > 0.0) {
            const double a_exact = std::atan2(y - path.y0(), dz);
            const double a_poly = std::atan2(got - path.y0(), dz);
            ASSERT_LE(std::fabs(a_exact - a_poly), st.tolerance_rad * (1.0 + 1e-9) + 1e-15)
                << what << " angle at dz = " << dz;
        }
    }
}

TEST(PathSampler, ToleranceBoundsTheErrorOverManyRandomRaysOfEveryProfile) {
    std::mt19937_64 rng(20260601);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int rays = 0, trapped = 0, turned = 0, three_turns = 0;
    for (const auto& fam : families()) {
        for (int trial = 0; trial < 120; ++trial) {
            const double y0 = fam.y0_lo * std::pow(fam.y0_hi / fam.y0_lo, unit(rng));
            const double mag = fam.elev_lo * std::pow(fam.elev_hi / fam.elev_lo, unit(rng));
            const double elev = unit(rng) < 0.6 ? -mag : mag;
            auto path = ExactPath::make(fam.atmosphere, y0, M_PI / 2 - elev);
            ASSERT_TRUE(path.ok()) << path.message();
            SampleSettings st;
            const int mode = trial % 3;
            st.tolerance_rad = std::pow(10.0, -2.0 - 3.0 * unit(rng));
            if (mode == 1) st.tolerance_m = 1e-4;
            if (mode == 2) st.start_distance = 10.0 * unit(rng);
            st.max_dz = fam.reach * (0.05 + unit(rng));
            const auto poly = sample_exact_path(*path, st);
            char what[300];
            std::snprintf(what, sizeof what,
                          "%s y0=%.17g elev=%.17g tol_rad=%.17g tol_m=%g start=%.17g max_dz=%.17g "
                          "class=%s",
                          fam.name, y0, elev, st.tolerance_rad, st.tolerance_m, st.start_distance,
                          st.max_dz, path->class_name().c_str());
            check_bound(*path, st, poly, what);
            ++rays;
            if (path->turning_point_count() < 0) {
                ++trapped;
                // Trapped rays sampled past three or more turning points.
                if (path->turning_point(2).dz < poly.points.back().x) ++three_turns;
            }
            turned += poly.turns;
        }
    }
    EXPECT_EQ(rays, 720);
    EXPECT_GT(trapped, 20);
    EXPECT_GT(three_turns, 10);
    EXPECT_GT(turned, 150);
}

// Rays trapped in a duct are sampled through every turning point they pass: each turning
// point within the sampled distance is a sample, and the samples alternate between the two
// turning heights' sides.
TEST(PathSampler, DuctedRaysAreSampledThroughEveryTurningPoint) {
    auto q = testing::fit_or_die(testing::road_duct_spec(), 1e-11);
    ASSERT_TRUE(q);
    const Atmosphere atm = Atmosphere::quadratic(q);
    const auto ducts = find_ducts(*q);
    ASSERT_EQ(ducts.size(), 1u);
    // Near the peak of n^2 (above the hot ground, under the inversion) a nearly level ray
    // oscillates between two heights a few decimetres apart, with a half period near 1 km.
    auto path = ExactPath::make(atm, ducts[0].peak, M_PI / 2 - 5e-4);
    ASSERT_TRUE(path.ok());
    ASSERT_EQ(path->turning_point_count(), -1);
    SampleSettings st;
    st.tolerance_rad = 1e-5;
    st.max_dz = 4000.0;
    const auto poly = sample_exact_path(*path, st);
    int passed = 0;
    for (int k = 0; path->turning_point(k).dz < st.max_dz; ++k) {
        const TurningPoint t = path->turning_point(k);
        bool found = false;
        for (const auto& p : poly.points) found = found || std::fabs(p.x - t.dz) <= 1e-9 * t.dz;
        EXPECT_TRUE(found) << "turning point " << k << " at " << t.dz;
        ++passed;
    }
    EXPECT_GE(passed, 3);  // three or more turning points on the sampled path
    EXPECT_EQ(poly.end, PathEnd::Cut);
    check_bound(*path, st, poly, "duct");
}

// On the exponential profiles the general sampler keeps the closed-form sampler's economy: it
// needs about as many samples as sampler.h (within 25 %) for the same rays and tolerance.
TEST(PathSampler, NeedsAboutAsManySamplesAsTheClosedFormSampler) {
    const Profile p = *preset_profile("hot-road");
    const Atmosphere atm = Atmosphere::exponential(p);
    double ours = 0.0, theirs = 0.0;
    for (int j = 0; j < 60; ++j) {
        const double e = -0.0087 + 0.0174 * (j + 0.5) / 60;
        SampleSettings st;
        st.tolerance_rad = 18e-6;
        st.max_dz = 4000.0;
        auto ray = make_exact_ray(p, 1.5, M_PI / 2 - e);
        auto path = ExactPath::make(atm, 1.5, M_PI / 2 - e);
        theirs += sample_path(*ray, st).points.size();
        ours += sample_exact_path(*path, st).points.size();
    }
    EXPECT_LT(ours, 1.25 * theirs);
    EXPECT_GT(ours, 0.75 * theirs);
}

// The exact path, widened by the allowance, stays clear of every rectangle over [lo, hi].
bool stretch_is_clear(const ExactPath& path, const SampleSettings& st,
                      const testing::Rectangles& obstacles, double lo, double hi) {
    const int n = 400;
    for (int j = 0; j <= n; ++j) {
        const double dz = lo + (hi - lo) * j / n;
        if (path.hits_ground() && dz > path.dz_ground()) break;
        const double y = path.height_at(dz);
        const double a = allowed_error(path, st, dz, y);
        for (const auto& r : obstacles.rects()) {
            if (dz >= r.dz_lo && dz <= r.dz_hi && y + a >= r.y_lo && y - a <= r.y_hi) return false;
        }
    }
    return true;
}

// The general engine's near sampler among random rectangles, with the coarse spans the tracer
// fits: every segment not marked clear is one of the segments sampled without obstacles (so it
// keeps the tolerance), every clear stretch of the exact path, widened by the allowance, meets
// no rectangle, and where the path passes through a rectangle it is sampled to the tolerance.
// A path kept as its start alone (a rising path with nothing near it all the way, nor beyond
// the cut) ends in the direction the full sampling ends in, and truly meets nothing.
TEST(PathSamplerNear, CoarseOnlyWhereNothingLiesNearAndTheSameSegmentsElsewhere) {
    using testing::Rectangles;
    struct Case {
        const char* name;
        Atmosphere atmosphere;
        double y0_lo, y0_hi, elev_lo, elev_hi, reach;
    };
    using namespace testing;
    const std::vector<Case> cases = {
        {"hot road temperatures, spans",
         Atmosphere::quadratic(fit_or_die(hot_road_spec(), 1e-10, true)), 0.05, 3.0, 1e-5, 0.1,
         1000},
        {"road duct, spans", Atmosphere::quadratic(fit_or_die(road_duct_spec(), 1e-10, true)),
         0.05, 4.0, 1e-5, 0.05, 3000},
        {"young smooth, curved, spans",
         Atmosphere::quadratic(fit_or_die(young_spec(0.85), 1e-10, true)), 5.0, 120.0, 1e-5, 0.02,
         60000},
        {"paper fitted, spans",
         Atmosphere::quadratic(fit_or_die(exponential_spec("paper"), 1e-10, true)), 0.05, 5.0,
         1e-5, 0.2, 200},
    };
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int clear_segments = 0, fine_segments = 0, rays = 0, inside = 0, whole = 0, whole_cut = 0;
    int fewer = 0, short_of_reach = 0, inside_full = 0;
    for (const auto& c : cases) {
        for (int trial = 0; trial < 80; ++trial) {
            const double y0 = c.y0_lo * std::pow(c.y0_hi / c.y0_lo, unit(rng));
            const double mag = c.elev_lo * std::pow(c.elev_hi / c.elev_lo, unit(rng));
            const double elev = unit(rng) < 0.5 ? -mag : mag;
            auto path = ExactPath::make(c.atmosphere, y0, M_PI / 2 - elev);
            ASSERT_TRUE(path.ok()) << path.message();
            SampleSettings st;
            st.tolerance_rad = std::pow(10.0, -3.0 - 2.0 * unit(rng));
            if (trial % 2) st.start_distance = 5.0 * unit(rng);
            st.max_dz = c.reach * (0.05 + unit(rng));
            SampledPath full;
            sample_exact_path_near(*path, st, nullptr, full);
            // Rectangles about the path's own heights, somewhere along its sampled part, or
            // (every fourth ray) far above or below it.
            const double reach = std::max(full.points.back().x, 1.0);
            std::vector<Rectangles::Rect> rects;
            const int count = 1 + trial % 3;
            for (int k = 0; k < count; ++k) {
                const double dz = reach * unit(rng);
                const double w = reach * 0.05 * unit(rng) + 1e-3;
                const double y_path = path->height_at(dz);
                const double h = 0.1 * y0 * unit(rng) + 1e-3;
                double y = y_path + (unit(rng) - 0.5) * 0.5 * y0;
                if (trial % 4 == 3) y = unit(rng) < 0.5 ? -10.0 * y0 - 1.0 : 1e6;
                rects.push_back({dz, dz + w, y, y + h});
            }
            if (trial % 8 == 7 && full.end == PathEnd::Cut) {
                // Something beyond the cut, on the straight line the tracer goes on along.
                const double x = 1.5 * st.max_dz;
                const double y = full.points.back().y + full.end_slope * (x - st.max_dz);
                rects.push_back({x, x + 1.0, y - 1.0, y + 1.0});
            }
            const bool ground = trial % 5 == 0;
            const bool knows_reach = trial % 3 != 0;
            const Rectangles obstacles(rects, ground, knows_reach);
            SampledPath near;
            sample_exact_path_near(*path, st, &obstacles, near);
            char what[300];
            std::snprintf(what, sizeof what, "%s y0=%.17g elev=%.17g tol_rad=%.17g max_dz=%.17g "
                          "class=%s", c.name, y0, elev, st.tolerance_rad, st.max_dz,
                          path->class_name().c_str());
            ASSERT_EQ(near.points.front(), full.points.front()) << what;
            EXPECT_EQ(near.turns, full.turns) << what;
            EXPECT_EQ(near.end_slope, full.end_slope) << what;
            EXPECT_EQ(near.end_slope_dz, full.end_slope_dz) << what;
            if (near.end_clear) {
                EXPECT_NE(near.end, PathEnd::Ground) << what;
                // Nothing near the path from its last point on, nor (cut) beyond the cut.
                const double from = near.points.back().x;
                const double to = near.end == PathEnd::Cut ? st.max_dz : 4.0 * reach;
                EXPECT_TRUE(stretch_is_clear(*path, st, obstacles, from, to)) << what;
                if (near.end == PathEnd::Cut) {
                    for (const auto& r : rects) EXPECT_LT(r.dz_hi, st.max_dz) << what;
                }
                if (near.points.size() == 1) {
                    ++whole;
                    if (near.end == PathEnd::Cut) ++whole_cut;
                }
            } else {
                EXPECT_EQ(near.end, full.end) << what;
                EXPECT_EQ(near.points.back(), full.points.back()) << what;
            }
            ASSERT_EQ(near.clear_length.size() + 1, near.points.size()) << what;
            for (std::size_t k = 1; k < near.points.size(); ++k) {
                const glm::dvec2 a = near.points[k - 1], b = near.points[k];
                if (near.clear_length[k - 1] > 0.0) {
                    ++clear_segments;
                    EXPECT_TRUE(stretch_is_clear(*path, st, obstacles, a.x, b.x))
                        << what << ": segment " << k << " from dz " << a.x << " to " << b.x;
                    continue;
                }
                ++fine_segments;
                const auto at = std::find(full.points.begin(), full.points.end(), a);
                if (at != full.points.end() && at + 1 != full.points.end() && *(at + 1) == b)
                    continue;
                // Stopped at the grid's node that covers the rectangles' reach, a path may end
                // on a node inside one of the full sampling's segments (which kept the
                // tolerance as a whole, and so over every node of the grid inside it): then
                // its chord keeps the tolerance too.
                ASSERT_TRUE(knows_reach) << what << ": segment " << k;
                ASSERT_EQ(k + 1, near.points.size() - (near.end == PathEnd::Cut ? 1 : 0))
                    << what << ": segment " << k << " is not the last sampled";
                const auto after =
                    std::upper_bound(full.points.begin(), full.points.end(), b.x,
                                     [](double x, const glm::dvec2& p) { return x <= p.x; });
                ASSERT_NE(after, full.points.end()) << what;
                ASSERT_NE(after, full.points.begin()) << what;
                EXPECT_LE((after - 1)->x, a.x) << what << ": segment " << k;
                ++inside_full;
                for (int j = 0; j <= 50; ++j) {
                    const double dz = a.x + (b.x - a.x) * j / 50;
                    const double y = path->height_at(dz);
                    const double chord = a.y + (b.y - a.y) * (dz - a.x) / (b.x - a.x);
                    EXPECT_LE(std::fabs(chord - y), allowed_error(*path, st, dz, y) * (1 + 1e-9))
                        << what << ": segment " << k << " at " << dz;
                }
            }
            // Where the path crosses a rectangle, a fine segment covers it.
            for (const auto& r : rects) {
                for (int j = 0; j <= 50; ++j) {
                    const double dz = r.dz_lo + (r.dz_hi - r.dz_lo) * j / 50;
                    if (path->hits_ground() && dz > path->dz_ground()) continue;
                    if (dz > near.points.back().x) continue;
                    const double y = path->height_at(dz);
                    if (y < r.y_lo || y > r.y_hi) continue;
                    std::size_t k = 1;
                    while (k + 1 < near.points.size() && near.points[k].x < dz) ++k;
                    ASSERT_GT(near.points.size(), 1u) << what;
                    EXPECT_EQ(near.clear_length[k - 1], 0.0) << what << " at dz " << dz;
                    ++inside;
                }
            }
            if (knows_reach && near.end != PathEnd::Ground) {
                // Sampled no farther than the grid's node that covers the reach (shorter than
                // twice the reach), but for the cut, reached by one clear stretch.
                const double r = obstacles.reach();
                for (std::size_t k = 1; k < near.points.size(); ++k) {
                    if (near.end == PathEnd::Cut && k + 1 == near.points.size() &&
                        near.points[k].x == st.max_dz && near.clear_length[k - 1] > 0.0)
                        continue;
                    EXPECT_LT(near.points[k].x, 2.0 * r) << what << ": point " << k;
                }
                if (near.points.back().x < full.points.back().x) ++short_of_reach;
            }
            if (near.points.size() < full.points.size()) ++fewer;
            ++rays;
        }
    }
    std::printf(
        "%d rays: %d clear segments, %d fine; fewer points for %d; %d points in boxes; "
        "%d kept as their start (%d of them cut); %d stopped at the reach, %d of them inside a "
        "full segment\n",
        rays, clear_segments, fine_segments, fewer, inside, whole, whole_cut, short_of_reach,
        inside_full);
    EXPECT_EQ(rays, 320);
    // The obstacles leave work out, and not everything; whole paths are found clear, among
    // them paths cut at the end of the reach.
    EXPECT_GT(clear_segments, 100);
    EXPECT_GT(fine_segments, 200);
    EXPECT_GT(inside, 100);
    EXPECT_GT(fewer, rays / 4);
    EXPECT_GT(whole, 20);
    EXPECT_GT(whole_cut, 5);
    EXPECT_GT(short_of_reach, 20);
}

}  // namespace
}  // namespace mirage
