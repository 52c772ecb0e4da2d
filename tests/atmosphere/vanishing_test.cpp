// The vanishing of the inferior mirage: the distances from the exact paths against the closed
// form of the turned ray and against rays shot from the eye one by one.
#include "atmosphere/vanishing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>

#include "air_fixtures.h"
#include "atmosphere/exact_ray.h"

namespace mirage {
namespace {

constexpr double kPi = 3.14159265358979323846;

Profile paper() { return *preset_profile("paper"); }

// X(y_t -> y) for the inferior profile, integrated by hand: dz/dy = beta / sqrt(eta^2 - beta^2)
// with eta^2 - beta^2 = eta1^2 (exp(-alpha y_t) - exp(-alpha y)).
double closed_form_rise(const Profile& p, double y_t, double y) {
    const double beta = eta(p, y_t);
    return 2.0 * beta / (p.alpha * p.eta1) * std::exp(0.5 * p.alpha * y_t) *
           std::atanh(std::sqrt(-std::expm1(-p.alpha * (y - y_t))));
}

// The horizontal distance at which the eye ray of elevation e, after its turn, is at height h
// (bisection on the exact height; +inf when it never gets there).
double eye_ray_reach(const Profile& p, double y0, double e, double h) {
    auto ray = make_exact_ray(p, y0, 0.5 * kPi - e);
    if (!ray || ray->ray_class != RayClass::InfTurn || ray->y_turn > h + 1e-9) return INFINITY;
    if (ray->y_turn > h - 1e-9) return ray->dz_turn;  // it touches h at its turn
    double lo = ray->dz_turn, hi = lo + 1.0;
    while (height_at(*ray, hi) < h) {
        hi = lo + 2.0 * (hi - lo);
        if (hi > 1e6) return INFINITY;
    }
    for (int i = 0; i < 200; ++i) {
        const double m = 0.5 * (lo + hi);
        (height_at(*ray, m) < h ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

TEST(Vanishing, RiseFromTheTurningPointIsTheClosedForm) {
    const Profile p = paper();
    for (double y_t : {0.0, 0.01, 0.4, 1.2})
        for (double y : {y_t + 1e-3, y_t + 0.5, 2.0, 6.0}) {
            if (y <= y_t) continue;
            EXPECT_NEAR(turn_to_height_distance(p, y_t, y), closed_form_rise(p, y_t, y),
                        1e-9 * closed_form_rise(p, y_t, y))
                << "y_t " << y_t << " y " << y;
        }
    const Profile road = *preset_profile("hot-road");
    EXPECT_NEAR(turn_to_height_distance(road, 0.05, 1.2), closed_form_rise(road, 0.05, 1.2),
                1e-6 * closed_form_rise(road, 0.05, 1.2));
}

TEST(Vanishing, NearestDistanceIsTheMinimumOverEyeRays) {
    const Profile p = paper();
    const double y0 = 1.5;
    for (double h : {0.7, 2.0, 4.5}) {
        auto reach = mirror_reach(p, y0, h);
        ASSERT_TRUE(reach.ok()) << reach.message();
        // Brute force: 20000 eye rays between the one grazing the ground and the level one.
        const double e_ground = -std::acos(eta(p, 0.0) / eta(p, y0));
        double best = INFINITY, worst = 0.0;
        for (int k = 1; k < 20000; ++k) {
            const double d = eye_ray_reach(p, y0, e_ground * (1.0 - k / 20000.0), h);
            if (!std::isfinite(d)) continue;
            best = std::min(best, d);
            worst = std::max(worst, d);
        }
        EXPECT_NEAR(reach->nearest, best, 2e-3 * best) << "h " << h;
        EXPECT_LE(reach->nearest, best + 1e-9) << "no eye ray gets closer than the minimum";
        EXPECT_NEAR(reach->farthest, worst, 2e-3 * worst) << "h " << h;
        // The ray named as the nearest one reaches the point from there.
        EXPECT_NEAR(eye_ray_reach(p, y0, reach->nearest_elevation_rad, h), reach->nearest,
                    1e-6 * reach->nearest + (reach->grazing ? 1e-3 : 0.0));
    }
}

TEST(Vanishing, SphereMirrorVanishesAtItsDistance) {
    const Profile p = paper();
    const double y0 = 1.5, c = 4.5, r = 1.0;
    auto dv = sphere_vanishing_distance(p, y0, c, r);
    ASSERT_TRUE(dv.ok()) << dv.message();
    EXPECT_GT(*dv, 5.0);
    EXPECT_LT(*dv, 30.0);
    const auto before = mirrored_image_of_sphere(p, y0, *dv * 1.005, c, r);
    const auto after = mirrored_image_of_sphere(p, y0, *dv * 0.995, c, r);
    EXPECT_TRUE(before.visible);
    EXPECT_GT(before.angular_size_rad, 0.0);
    EXPECT_FALSE(after.visible);
    EXPECT_EQ(after.angular_size_rad, 0.0);
    // Farther away it is larger; its rays all point down.
    const auto far = mirrored_image_of_sphere(p, y0, 25.0, c, r);
    EXPECT_GT(far.angular_size_rad, before.angular_size_rad);
    EXPECT_LT(far.elevation_high_rad, 0.0);
}

// The eye ray of elevation e in any atmosphere: the distance at which it is at height h after
// its first turning point, a lowest one (bisection on the exact height over the rising run up
// to the next turning point; +inf when it never gets there).  Only height_at and the turning
// points: independent of distance_to_height and of the turning-height parameterization.
double general_eye_ray_reach(const Atmosphere& atm, double y0, double e, double h) {
    auto ray = ExactPath::make(atm, y0, 0.5 * kPi - e);
    if (!ray || ray->turning_point_count() == 0) return INFINITY;
    const TurningPoint turn = ray->turning_point(0);
    if (!turn.lowest || turn.y > h) return INFINITY;
    double hi;
    if (ray->turning_point_count() < 0 || ray->turning_point_count() > 1) {
        const TurningPoint apex = ray->turning_point(1);
        if (apex.y < h) return INFINITY;
        hi = apex.dz;
    } else {
        hi = turn.dz + 1.0;
        while (ray->height_at(hi) < h) {
            hi = turn.dz + 2.0 * (hi - turn.dz);
            if (hi > 1e7) return INFINITY;
        }
    }
    double lo = turn.dz;
    for (int i = 0; i < 200; ++i) {
        const double m = 0.5 * (lo + hi);
        (ray->height_at(m) < h ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

// Real air through the general engine: a hot ground under an inversion, n peaking near 1 m
// (tests/atmosphere/air_fixtures.h).  From eyes below and above the peak, at points below it,
// in the inversion where n falls with height, and above it, the nearest and farthest eye
// distances equal the extremes over 20000 eye rays shot one by one (each refined between its
// neighbours).  Turning heights whose level ray does not rise to the eye or the point (in the
// inversion, or below air of a lower index) are left out: no eye ray turns there.
TEST(Vanishing, AnyProfileNearestAndFarthestAreTheExtremesOverEyeRays) {
    auto q = testing::fit_or_die(testing::road_duct_spec(), 1e-11);
    ASSERT_TRUE(q);
    const Atmosphere atm = Atmosphere::quadratic(q);
    struct Case {
        double y0, h;
    };
    int cases = 0;
    for (const Case c : {Case{0.6, 0.3}, Case{0.6, 2.0}, Case{3.0, 0.5}, Case{3.0, 2.0},
                         Case{3.0, 4.0}}) {
        const std::string what = "eye " + std::to_string(c.y0) + " point " + std::to_string(c.h);
        auto reach = mirror_reach(atm, c.y0, c.h);
        const double e_ground = -std::acos(std::min(1.0, atm.n(0.0) / atm.n(c.y0)));
        // 20000 eye rays, then each extreme refined between the rays beside it (the extremes
        // may lie where the rays stop reaching the point, at a boundary of the set).
        auto reach_at = [&](double e) { return general_eye_ray_reach(atm, c.y0, e, c.h); };
        constexpr int kRays = 20000;
        auto e_of = [&](int k) { return e_ground * (1.0 - double(k) / kRays); };
        int k_best = -1, k_worst = -1;
        double best = INFINITY, worst = 0.0;
        for (int k = 1; k < kRays; ++k) {
            const double d = reach_at(e_of(k));
            if (!std::isfinite(d)) continue;
            if (d < best) best = d, k_best = k;
            if (d > worst) worst = d, k_worst = k;
        }
        auto refine = [&](int k, double sign, double& value) {
            double a = e_of(k - 1), b = e_of(k + 1);
            for (int i = 0; i < 80; ++i) {
                const double m1 = a + (b - a) / 3.0, m2 = b - (b - a) / 3.0;
                auto score = [&](double e) {
                    const double d = reach_at(e);
                    return std::isfinite(d) ? sign * d : INFINITY;
                };
                const double f1 = score(m1), f2 = score(m2);
                if (std::isfinite(f1) && f1 < sign * value) value = sign * f1;
                if (std::isfinite(f2) && f2 < sign * value) value = sign * f2;
                (f1 < f2 ? b : a) = f1 < f2 ? m2 : m1;
            }
        };
        if (!std::isfinite(best)) {
            EXPECT_FALSE(reach.ok()) << what << ": no eye ray reaches it after a turn";
            continue;
        }
        refine(k_best, 1.0, best);
        refine(k_worst, -1.0, worst);
        ASSERT_TRUE(reach.ok()) << what << ": " << reach.message();
        EXPECT_NEAR(reach->nearest, best, 2e-4 * best) << what;
        EXPECT_LE(reach->nearest, best * (1.0 + 1e-9)) << what << ": no eye ray gets closer";
        EXPECT_NEAR(reach->farthest, worst, 2e-4 * worst) << what;
        // The farthest lies where the rays stop reaching the point (their apex at it), where the
        // distance changes as the square root of the invariant's change: 1e-16 of n is
        // millimetres there, so the two computations agree to 1e-6 of it, not to rounding.
        EXPECT_GE(reach->farthest, worst * (1.0 - 1e-6))
            << what << ": no eye ray gets farther: " << std::setprecision(17) << reach->farthest
            << " " << worst;
        ++cases;
    }
    EXPECT_GE(cases, 4);
}

// The exponential hot road fitted by the general engine gives the closed forms' distances, for
// points and for a marked sphere, within what the fit (|dn| <= 1e-12) moves them.
TEST(Vanishing, TheGeneralEngineGivesTheClosedFormsDistances) {
    const Profile road = *preset_profile("hot-road");
    auto q = testing::fit_or_die(testing::exponential_spec("hot-road"), 1e-12);
    ASSERT_TRUE(q);
    const Atmosphere general = Atmosphere::quadratic(q);
    for (double h : {0.2, 1.0, 2.5}) {
        auto exact = mirror_reach(road, 1.5, h);
        auto fitted = mirror_reach(general, 1.5, h);
        ASSERT_TRUE(exact.ok() && fitted.ok());
        EXPECT_NEAR(fitted->nearest, exact->nearest, 1e-4 * exact->nearest) << "h " << h;
        EXPECT_NEAR(fitted->farthest, exact->farthest, 1e-4 * exact->farthest) << "h " << h;
        EXPECT_NEAR(fitted->nearest_elevation_rad, exact->nearest_elevation_rad,
                    1e-4 * std::fabs(exact->nearest_elevation_rad));
    }
    auto exact = sphere_vanishing_distance(road, 1.5, 2.5, 0.5);
    auto fitted = sphere_vanishing_distance(general, 1.5, 2.5, 0.5);
    ASSERT_TRUE(exact.ok() && fitted.ok());
    EXPECT_NEAR(*fitted, *exact, 1e-4 * *exact);
    const auto a = mirrored_image_of_sphere(road, 1.5, 1.2 * *exact, 2.5, 0.5);
    const auto b = mirrored_image_of_sphere(general, 1.5, 1.2 * *exact, 2.5, 0.5);
    ASSERT_TRUE(a.visible && b.visible);
    EXPECT_NEAR(b.angular_size_rad, a.angular_size_rad, 1e-3 * a.angular_size_rad);
    EXPECT_FALSE(mirrored_image_of_sphere(general, 1.5, 0.98 * *exact, 2.5, 0.5).visible);
}

TEST(Vanishing, BadValuesAreNamed) {
    const Profile p = paper();
    EXPECT_EQ(mirror_reach(p, 0.0, 2.0).message(), "eye height 0: must be above the ground (> 0)");
    EXPECT_EQ(mirror_reach(p, 1.5, -1.0).message(),
              "object height -1: must be above the ground (> 0)");
    EXPECT_FALSE(mirror_reach(*preset_profile("cold-sea"), 1.5, 2.0).ok());
    EXPECT_FALSE(sphere_vanishing_distance(p, 1.5, 0.5, 1.0).ok());
    // Air whose index falls with height everywhere (a cold sea under warm air): no ray turns
    // below, and the message says why.
    AirSpec cold;
    cold.column.ground_temperature_k = 280.0;
    cold.column.layers.push_back({-10.0, 5.0});
    cold.top_m = 100.0;
    auto q = testing::fit_or_die(cold, 1e-11);
    ASSERT_TRUE(q);
    EXPECT_EQ(mirror_reach(Atmosphere::quadratic(q), 1.5, 2.0).message(),
              "no ray from the eye at 1.5 turns below 1.5 and rises again to 2: the air has no "
              "inferior mirage of that point (the index must grow with height between the "
              "turning point and both)");
}

}  // namespace
}  // namespace mirage
