// The vanishing of the inferior mirage: the distances from the exact paths against the closed
// form of the turned ray and against rays shot from the eye one by one.
#include "atmosphere/vanishing.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(Vanishing, BadValuesAreNamed) {
    const Profile p = paper();
    EXPECT_EQ(mirror_reach(p, 0.0, 2.0).message(), "eye height 0: must be above the ground (> 0)");
    EXPECT_EQ(mirror_reach(p, 1.5, -1.0).message(),
              "object height -1: must be above the ground (> 0)");
    EXPECT_FALSE(mirror_reach(*preset_profile("cold-sea"), 1.5, 2.0).ok());
    EXPECT_FALSE(sphere_vanishing_distance(p, 1.5, 0.5, 1.0).ok());
}

}  // namespace
}  // namespace mirage
