#include "atmosphere/quadratic_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "air_fixtures.h"
#include "atmosphere/exact_path.h"

namespace mirage {
namespace {

using testing::exponential_spec;
using testing::fit_or_die;

struct RandomRay {
    double y0, elev;
};

std::vector<RandomRay> random_rays(std::mt19937_64& rng, int count, double y_lo, double y_hi,
                                   double elev_lo, double elev_hi) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<RandomRay> rays;
    for (int k = 0; k < count; ++k) {
        const double y0 = y_lo * std::pow(y_hi / y_lo, unit(rng));
        const double mag = elev_lo * std::pow(elev_hi / elev_lo, unit(rng));
        rays.push_back({y0, unit(rng) < 0.6 ? -mag : mag});
    }
    return rays;
}

// The exponential presets fitted to |dn| <= eps and traced by the general engine, against
// their closed forms: the same fate and turning points on every ray, and heights that differ
// by no more than the fit allows.  Two profiles whose index differs by at most eps give rays
// from one start whose directions at equal heights differ by at most sqrt(4 eps) (n cos(e) =
// beta, for beta and n each off by eps), so their heights part by at most d sqrt(4 eps).
TEST(QuadraticPath, MatchesTheExponentialClosedFormsOnTheirFittedProfiles) {
    const double eps = 1e-13;
    std::mt19937_64 rng(7);
    for (const char* preset : {"paper", "hot-road", "paper-superior", "cold-sea"}) {
        auto q = fit_or_die(exponential_spec(preset), eps);
        ASSERT_TRUE(q);
        const Atmosphere general = Atmosphere::quadratic(q);
        const Atmosphere closed = Atmosphere::exponential(*preset_profile(preset));
        int turning = 0, grounded = 0;
        for (const auto& r : random_rays(rng, 400, 0.05, 6.0, 1e-6, 0.5)) {
            auto a = ExactPath::make(general, r.y0, M_PI / 2 - r.elev);
            auto e = ExactPath::make(closed, r.y0, M_PI / 2 - r.elev);
            ASSERT_TRUE(a.ok() && e.ok());
            const std::string what = std::string(preset) + " y0=" + std::to_string(r.y0) +
                                     " elev=" + std::to_string(r.elev) + " " + e->class_name();
            ASSERT_EQ(a->fate(), e->fate()) << what;
            ASSERT_EQ(a->turning_point_count(), e->turning_point_count()) << what;
            ASSERT_EQ(a->hits_ground(), e->hits_ground()) << what;
            turning += e->turning_point_count();
            grounded += e->hits_ground();
            if (e->turning_point_count() == 1) {
                // n^2 off by 2 eps n (and beta^2 by as much) moves the level point by
                // 4 eps / |(n^2)'| there.
                const double yt = e->turning_point(0).y;
                EXPECT_NEAR(a->turning_point(0).y, yt, 1e-12 + 4.5 * eps / std::fabs(q->slope(yt)))
                    << what;
            }
            for (double d : {0.3, 1.0, 4.0, 15.0, 60.0, 250.0}) {
                if (e->hits_ground() && d > e->dz_ground()) continue;
                EXPECT_NEAR(a->height_at(d), e->height_at(d), 1e-9 + d * std::sqrt(4.0 * eps))
                    << what << " d=" << d;
            }
        }
        EXPECT_GT(turning, 20) << preset;
        EXPECT_GT(grounded, 10) << preset;
    }
}

// Every point of a path solves the ray equation of its own model: slope^2 beta^2 = n^2 - beta^2
// at the path's height, with n^2 - beta^2 carried as (n^2 - n0^2) - level.  A wrong closed form,
// a wrong crossing time or a wrong piece breaks this at once.
TEST(QuadraticPath, SolvesTheRayEquationOfItsModelAlongTheWholePath) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<std::pair<const char*, AirSpec>> cases = {
        {"road", testing::hot_road_spec()},
        {"duct", testing::road_duct_spec()},
        {"young", testing::young_spec(0.85)},
        {"paper", exponential_spec("paper")}};
    for (const auto& [name, spec] : cases) {
        auto q = fit_or_die(spec, 1e-11);
        ASSERT_TRUE(q);
        const Atmosphere atm = Atmosphere::quadratic(q);
        const double scale = spec.earth_radius_m > 0.0 ? 60.0 : 2.0;
        int checked = 0;
        for (const auto& r : random_rays(rng, 150, 0.05 * scale, 3.0 * scale, 1e-6, 0.05)) {
            auto path = ExactPath::make(atm, r.y0, M_PI / 2 - r.elev);
            ASSERT_TRUE(path.ok()) << path.message();
            const double beta2 = path->beta() * path->beta();
            const double level =
                q->excess(r.y0) - q->n_sq(r.y0) * std::pow(std::cos(path->i_rad()), 2);
            const double reach = std::min(path->dz_ground(), 20000.0 * scale / 2.0);
            for (int k = 0; k < 40; ++k) {
                const double d = reach * unit(rng);
                const double y = path->height_at(d), s = path->slope_at(d);
                ASSERT_TRUE(std::isfinite(y) && std::isfinite(s)) << name << " d=" << d;
                ASSERT_GE(y, -1e-9) << name;
                const double Q = q->excess(y) - level;
                // Q is known to about eps |n^2 - n0^2| (cancellation in the level).
                const double tol = 64.0 * 2.2e-16 * (std::fabs(q->excess(y)) + std::fabs(level)) +
                                   1e-9 * std::fabs(Q);
                EXPECT_NEAR(s * s * beta2, Q, tol)
                    << name << " y0=" << r.y0 << " elev=" << r.elev << " d=" << d << " y=" << y;
                ++checked;
            }
        }
        EXPECT_EQ(checked, 6000) << name;
    }
}

// Across every knot of a sweep the path and its slope are continuous.
TEST(QuadraticPath, IsContinuousWithAContinuousSlopeAcrossEveryPiece) {
    auto q = fit_or_die(testing::hot_road_spec(), 1e-11);
    ASSERT_TRUE(q);
    for (double elev : {-0.004, -0.0015, 0.002}) {
        auto path = QuadraticPath::make(*q, 1.5, M_PI / 2 - elev);
        ASSERT_TRUE(path.ok());
        const Sweep& s = path->sweep();
        ASSERT_GT(s.segments.size(), 10u);
        for (size_t k = 1; k < s.segments.size(); ++k) {
            const double t = s.segments[k].t0;
            const double h = 1e-7 * (1.0 + t);
            const double below = sweep_height(s, t - h), above = sweep_height(s, t + h);
            const double slope = sweep_slope(s, t);
            const double curv = path->curvature_bound(below, above);
            EXPECT_NEAR(above - below, 2.0 * h * slope, 1e-14 + curv * h * h) << "knot " << k;
            EXPECT_NEAR(sweep_slope(s, t - h), sweep_slope(s, t + h), 1e-14 + 2.0 * h * curv)
                << "knot " << k;
            EXPECT_NEAR(s.segments[k - 1].y1, sweep_height(s, t), 1e-12) << "knot " << k;
        }
    }
}

// A ray trapped in a duct turns for ever: its turning heights alternate, its path is
// symmetric about every turning point and repeats with twice the half period.
TEST(QuadraticPath, DuctedRaysArePeriodicAndSymmetricAboutEveryTurningPoint) {
    auto q = fit_or_die(testing::road_duct_spec(), 1e-11);
    ASSERT_TRUE(q);
    const auto ducts = find_ducts(*q);
    ASSERT_EQ(ducts.size(), 1u);
    // On flat ground a profile whose index falls all the way up traps every ray with beta above
    // its top index between the hot ground and the sky: the duct reaches the top.
    EXPECT_NEAR(ducts[0].top, q->top(), 1e-7);
    for (double y0 : {ducts[0].peak, 0.5 * (ducts[0].bottom + ducts[0].top)})
        for (double elev : {0.0, 4e-4, -7e-4}) {
            auto path = QuadraticPath::make(*q, y0, M_PI / 2 - elev);
            ASSERT_TRUE(path.ok());
            ASSERT_EQ(path->fate(), PathFate::Ducted);
            ASSERT_EQ(path->turning_point_count(), -1);
            EXPECT_FALSE(path->hits_ground());
            const TurningPoint t0 = path->turning_point(0), t1 = path->turning_point(1);
            const double half = t1.dz - t0.dz;
            ASSERT_GT(half, 0.0);
            EXPECT_NE(t0.lowest, t1.lowest);
            for (int k = 0; k < 8; ++k) {
                const TurningPoint tk = path->turning_point(k);
                EXPECT_NEAR(tk.dz, t0.dz + k * half, 1e-9 * tk.dz);
                EXPECT_DOUBLE_EQ(tk.y, k % 2 == 0 ? t0.y : t1.y);
                EXPECT_NEAR(path->height_at(tk.dz), tk.y, 1e-9);
                EXPECT_NEAR(path->slope_at(tk.dz), 0.0, 1e-9);
                EXPECT_GE(tk.y, ducts[0].bottom - 1e-9);
                EXPECT_LE(tk.y, ducts[0].top + 1e-9);
                for (double u : {0.1, 0.37, 0.8}) {
                    const double du = u * half;
                    if (tk.dz - du < 0.0) continue;
                    EXPECT_NEAR(path->height_at(tk.dz - du), path->height_at(tk.dz + du), 1e-9)
                        << "turning point " << k << " u=" << u;
                }
            }
            for (double d : {3.0, 17.0, 41.0}) {
                EXPECT_NEAR(path->height_at(d + 2.0 * half), path->height_at(d), 1e-9);
                EXPECT_NEAR(path->height_at(d + 20.0 * half), path->height_at(d), 1e-8);
            }
            EXPECT_EQ(path->first_turning_point_after(t0.dz + 2.5 * half), 3);
        }
}

// turning_point_before answers whether the k-th turning point lies before a distance without
// computing the path further than that needs: the same answers and turning points as
// turning_point(k) on a fresh copy of the path, and the same heights afterwards.
TEST(QuadraticPath, TurningPointBeforeAgreesWithTheTurningPoints) {
    auto q = fit_or_die(testing::road_duct_spec(), 1e-11);
    ASSERT_TRUE(q);
    const auto ducts = find_ducts(*q);
    ASSERT_EQ(ducts.size(), 1u);
    int before = 0, beyond = 0;
    for (double y0 : {ducts[0].peak, 0.5 * (ducts[0].bottom + ducts[0].top), 0.3, 2.0})
        for (double elev : {0.0, 4e-4, -7e-4, 0.01, -0.02}) {
            auto made = QuadraticPath::make(*q, y0, M_PI / 2 - elev);
            ASSERT_TRUE(made.ok());
            const int count = made->turning_point_count();
            for (int k = 0; k < 4; ++k) {
                const bool exists = count < 0 || k < count;
                const double dz_k = exists ? QuadraticPath(*made).turning_point(k).dz : 0.0;
                for (double f : {0.5, 0.999, 1.001, 3.0}) {
                    const double dz = exists ? f * dz_k : f * 100.0;
                    const QuadraticPath lazy = *made;
                    TurningPoint tp;
                    const bool got = lazy.turning_point_before(k, dz, tp);
                    EXPECT_EQ(got, exists && dz_k < dz) << y0 << " " << elev << " k=" << k;
                    if (got) {
                        const TurningPoint ref = QuadraticPath(*made).turning_point(k);
                        EXPECT_EQ(tp.dz, ref.dz);
                        EXPECT_EQ(tp.y, ref.y);
                        EXPECT_EQ(tp.lowest, ref.lowest);
                        ++before;
                    } else {
                        ++beyond;
                    }
                    const QuadraticPath full = *made;
                    full.sweep();  // the whole run computed
                    for (double d : {0.25 * dz, dz, 2.0 * dz}) {
                        EXPECT_EQ(lazy.height_at(d), full.height_at(d));
                        EXPECT_EQ(lazy.slope_at(d), full.slope_at(d));
                    }
                }
            }
        }
    EXPECT_GT(before, 20);
    EXPECT_GT(beyond, 20);
}

// The run is computed piece after piece from knot to knot (QuadraticPath::cross_pieces) and
// by the general step where something else happens (the origin's piece, a turning point, the
// piece holding the start, the top).  Every segment must take up where the one before ended,
// in the next piece, and reach its far knot at its own crossing time; the start must lie on
// the run at the first turning point's distance; and the run must be the same however it was
// computed: in one go, or in small steps by height queries (each stopping the piece loop at a
// distance).  A loop that ran into the end piece, past the start's piece or the top, or that
// carried the slope or n^2 - beta^2 wrongly from piece to piece fails here.
TEST(QuadraticPath, EverySegmentTakesUpWhereTheLastEndedAndReachesItsKnot) {
    std::mt19937_64 rng(23);
    int segments = 0, turning = 0, grounded = 0, ducted = 0;
    for (const auto& spec : {testing::hot_road_spec(), testing::road_duct_spec()}) {
        auto q = fit_or_die(spec, 1e-11);
        ASSERT_TRUE(q);
        for (const auto& r : random_rays(rng, 150, 0.02, 8.0, 1e-6, 0.05)) {
            auto made = QuadraticPath::make(*q, r.y0, M_PI / 2 - r.elev);
            ASSERT_TRUE(made.ok());
            const std::string what =
                "y0=" + std::to_string(r.y0) + " elev=" + std::to_string(r.elev);
            const QuadraticPath full = *made;
            const Sweep& s = full.sweep();
            for (size_t k = 0; k < s.segments.size(); ++k) {
                const QuadraticSegment& g = s.segments[k];
                if (k > 0) {
                    const QuadraticSegment& prev = s.segments[k - 1];
                    ASSERT_EQ(g.t0, prev.t1) << what << " segment " << k;
                    ASSERT_EQ(g.piece, prev.piece + s.dir) << what << " segment " << k;
                    // Entered at the knot the last one reached (a segment ending on a turning
                    // point is anchored there instead).
                    const bool vertex_end = k + 1 == s.segments.size() && s.end == SweepEnd::Vertex;
                    if (!vertex_end) ASSERT_EQ(g.ya, prev.y1) << what << " segment " << k;
                }
                ASSERT_GE(g.t1, g.t0) << what;
                EXPECT_NEAR(sweep_height(s, g.t1), g.y1, 1e-9 * (1.0 + std::fabs(g.y1)))
                    << what << " segment " << k;
                ++segments;
            }
            if (full.turning_point_count() != 0) {
                // The start lies on the run at the first turning point's distance.
                const double t1 = full.first_turn_dz();
                EXPECT_NEAR(sweep_height(s, t1), r.y0, 1e-9 * (1.0 + r.y0)) << what;
                ++turning;
            }
            grounded += full.hits_ground();
            ducted += full.fate() == PathFate::Ducted;
            // In small steps: the same segments, bit for bit.
            const QuadraticPath stepped = *made;
            const double reach = std::min(std::isfinite(full.dz_ground()) ? full.dz_ground() : 1e4,
                                          full.turning_point_count() != 0
                                              ? full.first_turn_dz() + s.length
                                              : s.length + 1.0);
            // (Short of the ground hit itself, where a path computed just up to it and one
            // computed beyond evaluate the last segment and its end: 0 against -4e-17.)
            for (int i = 1; i < 64; ++i) {
                const double d = reach * i / 64.0;
                ASSERT_EQ(stepped.height_at(d), full.height_at(d)) << what << " d=" << d;
                ASSERT_EQ(stepped.slope_at(d), full.slope_at(d)) << what << " d=" << d;
            }
            EXPECT_EQ(stepped.dz_ground(), full.dz_ground()) << what;
            const Sweep& t = stepped.sweep();
            ASSERT_EQ(t.segments.size(), s.segments.size()) << what;
            for (size_t k = 0; k < s.segments.size(); ++k) {
                EXPECT_EQ(t.segments[k].t1, s.segments[k].t1) << what;
                EXPECT_EQ(t.segments[k].sa, s.segments[k].sa) << what;
            }
        }
    }
    EXPECT_GT(segments, 2000);
    EXPECT_GT(turning, 30);
    EXPECT_GT(grounded, 30);
    EXPECT_GT(ducted, 10);
}

// distance_to_height: on random rays of a hot road, a duct under an inversion and the same
// with coarse spans, every height the ray passes before its first turning point (or its end)
// is reached at the distance given (the height there within 1e-9 m, and no sooner: the height
// a hair before is short of it), and heights it never moves towards, or lies beyond the turn,
// are +inf.  A closed form with the wrong anchor, slope or sign fails the first check.
TEST(QuadraticPath, DistanceToHeightIsWhereThePathFirstReachesIt) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0, before_turn = 0, spans_used = 0, unreachable = 0;
    for (bool spans : {false, true}) {
        for (const auto& spec : {testing::hot_road_spec(), testing::road_duct_spec()}) {
            auto q = fit_or_die(spec, 1e-11, spans);
            ASSERT_TRUE(q);
            for (const auto& r : random_rays(rng, 120, 0.02, 8.0, 1e-6, 0.3)) {
                auto made = QuadraticPath::make(*q, r.y0, M_PI / 2 - r.elev);
                ASSERT_TRUE(made.ok());
                const QuadraticPath path = *made;
                const std::string what =
                    "y0=" + std::to_string(r.y0) + " elev=" + std::to_string(r.elev);
                // Where the monotone stretch from the start ends.
                double end_y;
                const bool turns = path.turning_point_count() != 0;
                if (turns) {
                    end_y = path.turning_point(0).y;
                    ++before_turn;
                } else if (path.hits_ground()) {
                    end_y = 0.0;
                } else {
                    end_y = path.height_at(1e4);
                }
                for (int k = 0; k < 6; ++k) {
                    const double y = r.y0 + (end_y - r.y0) * unit(rng);
                    if (y < 0.0) continue;
                    const double d = path.distance_to_height(y);
                    ASSERT_TRUE(std::isfinite(d)) << what << " y " << y;
                    ASSERT_NEAR(path.height_at(d), y, 1e-9 * (1.0 + y)) << what << " y " << y;
                    const double before = path.height_at(d * (1.0 - 1e-6));
                    ASSERT_LT((end_y > r.y0 ? 1 : -1) * (before - y), 0.0) << what << " y " << y;
                    ++checked;
                }
                // Behind the start, and past the turning point: never.
                const double away = r.y0 - 0.1 * (end_y - r.y0) - 1e-3 * (end_y > r.y0 ? 1 : -1);
                if (away > 0.0 && std::fabs(end_y - r.y0) > 0.0) {
                    EXPECT_EQ(path.distance_to_height(away), INFINITY) << what;
                    ++unreachable;
                }
                if (turns) {
                    const double past = end_y + 0.05 * (end_y - r.y0);
                    if (past > 0.0) EXPECT_EQ(path.distance_to_height(past), INFINITY) << what;
                }
                spans_used += path.spans_crossed() > 0;
            }
        }
    }
    EXPECT_GT(checked, 2000);
    EXPECT_GT(before_turn, 100);
    EXPECT_GT(spans_used, 20);
    EXPECT_GT(unreachable, 200);
}

TEST(QuadraticPath, HomogeneousAirGivesStraightLines) {
    auto q = QuadraticProfile::make({0.0, 10.0}, {0.0}, {0.0}, 1.0003 * 1.0003, 0.0);
    ASSERT_TRUE(q.ok());
    auto up = QuadraticPath::make(*q, 2.0, M_PI / 2 - 0.1);
    ASSERT_TRUE(up.ok());
    EXPECT_EQ(up->fate(), PathFate::Straight);
    EXPECT_NEAR(up->height_at(50.0), 2.0 + 50.0 * std::tan(0.1), 1e-13);
    auto down = QuadraticPath::make(*q, 2.0, M_PI / 2 + 0.1);
    ASSERT_TRUE(down.ok());
    EXPECT_TRUE(down->hits_ground());
    EXPECT_NEAR(down->dz_ground(), 2.0 / std::tan(0.1), 1e-12);
}

// Above the profile's top the air is homogeneous: a ray from there goes straight down to the
// top, then bends.
TEST(QuadraticPath, StartsAboveTheTopGoStraightUntilTheyReachIt) {
    auto q = fit_or_die(testing::hot_road_spec(), 1e-11);
    ASSERT_TRUE(q);
    const double top = q->top();
    auto path = QuadraticPath::make(*q, top + 50.0, M_PI / 2 + 0.02);
    ASSERT_TRUE(path.ok());
    const double d_top = 50.0 / std::tan(0.02);
    EXPECT_NEAR(path->height_at(0.5 * d_top), top + 25.0, 1e-9);
    EXPECT_NEAR(path->height_at(d_top), top, 1e-9);
    auto up = QuadraticPath::make(*q, top + 50.0, M_PI / 2 - 0.02);
    ASSERT_TRUE(up.ok());
    EXPECT_EQ(up->fate(), PathFate::Escape);
    EXPECT_NEAR(up->height_at(1000.0), top + 50.0 + 1000.0 * std::tan(0.02), 1e-9);
}

TEST(QuadraticPath, RefusesStartsBelowTheGroundAndVerticalRays) {
    auto q = fit_or_die(testing::hot_road_spec(), 1e-10);
    ASSERT_TRUE(q);
    auto below = QuadraticPath::make(*q, -0.5, 1.5);
    ASSERT_FALSE(below.ok());
    EXPECT_EQ(below.message(), "start height y0 = -0.5 m must be finite and >= 0");
    auto vertical = QuadraticPath::make(*q, 1.0, 0.0);
    ASSERT_FALSE(vertical.ok());
    EXPECT_NE(vertical.message().find("strictly between 0 and pi"), std::string::npos);
}

// A tracer makes its paths from the ray's direction (make_direction: cos i and sin i, no angle):
// the same paths as from the angle, to the rounding of the cosine; a level direction, whose cos i
// is exactly 0, the path make(pi / 2) gives (with cos i = 6.1e-17 a start just inside the run,
// where exactly 0 would put the start on its own turning point and send a ray with a falling
// index upwards first: Young's duct from 54 m then meets a wall 40 km away 0.39 m too high);
// directions that are not unit vectors with a horizontal part are refused.
TEST(QuadraticPath, MadeFromADirectionIsTheRayMadeFromItsAngle) {
    for (const auto& spec :
         {testing::young_spec(0.85), testing::road_duct_spec(), testing::hot_road_spec()}) {
        auto q = fit_or_die(spec, 1e-11);
        ASSERT_TRUE(q);
        std::mt19937_64 rng(20261203);
        int compared = 0;
        for (const RandomRay& r : random_rays(rng, 60, 0.05, 80.0, 1e-6, 0.05)) {
            const double i = M_PI / 2 - r.elev;
            auto from_angle = QuadraticPath::make(*q, r.y0, i);
            auto from_direction = QuadraticPath::make_direction(*q, quadratic_start(*q, r.y0),
                                                                std::cos(i), std::sin(i));
            ASSERT_TRUE(from_angle.ok() && from_direction.ok());
            EXPECT_EQ(from_direction->fate(), from_angle->fate()) << r.y0 << " " << r.elev;
            EXPECT_EQ(from_direction->turning_point_count(), from_angle->turning_point_count());
            EXPECT_EQ(from_direction->beta(), from_angle->beta());
            EXPECT_NEAR(from_direction->i_rad(), i, 1e-15);
            for (const double dz : {10.0, 300.0, 5000.0}) {
                EXPECT_EQ(from_direction->height_at(dz), from_angle->height_at(dz))
                    << r.y0 << " " << r.elev << " " << dz;
            }
            ++compared;
        }
        EXPECT_EQ(compared, 60);

        // Level: from 54 m (in Young's inversion, where the index falls upwards), the start is
        // an apex, as make(pi / 2) has it.
        for (const double y0 : {54.0, 1.0, 0.3}) {
            auto level = QuadraticPath::make_direction(*q, quadratic_start(*q, y0), 0.0, 1.0);
            auto angle = QuadraticPath::make(*q, y0, M_PI / 2);
            ASSERT_TRUE(level.ok() && angle.ok());
            EXPECT_EQ(level->fate(), angle->fate()) << y0;
            ASSERT_EQ(level->turning_point_count(), angle->turning_point_count()) << y0;
            if (angle->turning_point_count() != 0) {
                EXPECT_EQ(level->turning_point(0).dz, angle->turning_point(0).dz) << y0;
                EXPECT_EQ(level->turning_point(0).y, angle->turning_point(0).y) << y0;
            }
            EXPECT_EQ(level->height_at(40000.0), angle->height_at(40000.0)) << y0;
        }
    }
    auto q = fit_or_die(testing::hot_road_spec(), 1e-10);
    const QuadraticStart start = quadratic_start(*q, 1.0);
    for (const auto& [c, s] : {std::pair{0.6, 0.6}, std::pair{1.0, 0.0}, std::pair{0.6, -0.8},
                               std::pair{std::nan(""), 1.0}}) {
        auto bad = QuadraticPath::make_direction(*q, start, c, s);
        ASSERT_FALSE(bad.ok()) << c << " " << s;
        EXPECT_NE(bad.message().find("must be a unit vector with a horizontal part"),
                  std::string::npos)
            << bad.message();
    }
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

// Starts exactly on knots (sounding rows, an inversion's corners), level or nearly so, in both
// directions: every path is finite everywhere, and a level ray on the sharp bottom of an
// inversion (a maximum of n*^2 with a corner, n*^2 falling on both sides) stays level there.
TEST(QuadraticPath, StartsOnKnotsGiveFinitePathsAndACornerMaximumHoldsALevelRay) {
    const std::vector<AirSpec> specs = {testing::young_spec(0.0), testing::road_duct_spec()};
    for (const auto& spec : specs) {
        auto q = testing::fit_or_die(spec, 1e-10);
        ASSERT_TRUE(q);
        const Atmosphere atm = Atmosphere::quadratic(q);
        for (int j = 0; j <= q->piece_count(); ++j) {
            for (double el : {0.0, 1e-12, -1e-12, 1e-6, -1e-6, 1e-3, -1e-3, 0.3, -0.3}) {
                auto path = ExactPath::make(atm, q->knot(j), M_PI / 2 - el);
                ASSERT_TRUE(path.ok()) << path.message();
                for (double d : {0.0, 0.5, 37.0, 1234.5, 60000.0}) {
                    if (path->hits_ground() && d > path->dz_ground()) continue;
                    ASSERT_TRUE(std::isfinite(path->height_at(d)))
                        << "knot " << j << " elev " << el << " d " << d;
                    ASSERT_TRUE(std::isfinite(path->slope_at(d)));
                }
            }
        }
    }
    auto q = testing::fit_or_die(testing::young_spec(0.0), 1e-10);
    const double corner = flattened_height(50.0, 6371000.0);
    int k = q->piece_at(corner);
    if (std::fabs(q->knot(k + 1) - corner) < std::fabs(q->knot(k) - corner)) ++k;
    auto level = QuadraticPath::make(*q, q->knot(k), M_PI / 2);
    ASSERT_TRUE(level.ok());
    EXPECT_EQ(level->fate(), PathFate::Level);
    EXPECT_EQ(level->height_at(5000.0), q->knot(k));
}

}  // namespace
}  // namespace mirage
