// The tracer's rays through turbulent air (CurvedSettings::turbulence): where camera rays meet
// a wall, against the angle-of-arrival statistics of a spherical wave, and frame to frame as the
// wind moves the air.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "atmosphere/phase_screens.h"
#include "parsed_scene.h"
#include "trace/curved_propagator.h"
#include "atmosphere/turbulence_theory.h"

namespace mirage {
namespace {

using testing::integrate_kappa;
using testing::TiltCorrelations;
using testing::tilt_variance_ap;
using testing::tilt_variance_integral;
using testing::uniform;

constexpr double kPi = std::numbers::pi;

constexpr double kWall = 20.0;  // m: the wall across the line of sight
const glm::dvec3 kEye(0.0, 1.0, 0.0);

// A camera at the eye looking along +z at a wall kWall away.
struct WallScene {
    testing::Parsed parsed = testing::build(
        "camera { location <0, 1, 0> look_at <0, 1, 10> }\n"
        "plane { z, 20 pigment { rgb 1 } }\n");
    CurvedSettings curved(const TurbulenceSettings& t, double unit_m = 1.0) const {
        ScreenLayout l;
        l.origin = kEye;  // metres, whatever the scene's unit
        l.axis = glm::dvec3(0.0, 0.0, 1.0);
        l.reach_m = kWall;
        l.count = 16;
        auto screens = PhaseScreens::make(t, l);
        EXPECT_TRUE(screens.ok()) << screens.message();
        CurvedSettings s;
        s.turbulence = std::make_shared<const PhaseScreens>(std::move(*screens));
        s.unit_m = unit_m;
        return s;
    }
};

// Where a camera ray along d is seen to move: its hit on the wall minus the straight ray's,
// divided by the distance, per image axis (x right, y up).
glm::dvec2 image_shift(const CurvedPropagator& p, const SceneAccel& accel, const glm::dvec3& d) {
    RayStart start;
    start.origin = kEye;
    start.direction = d;
    const PathHit hit = p.propagate(accel, start);
    EXPECT_TRUE(hit.hit);
    const double range = (kWall - kEye.z) / d.z;
    const glm::dvec3 moved = hit.surface.point - (kEye + range * d);
    return glm::dvec2(moved.x, moved.y) / range;
}

glm::dvec3 random_view(std::mt19937_64& rng) {
    const double half = 3.0 * kPi / 180.0;  // within 3 degrees of the axis
    return glm::normalize(glm::dvec3(std::tan(half * (2.0 * uniform(rng) - 1.0)),
                                     std::tan(half * (2.0 * uniform(rng) - 1.0)), 1.0));
}

// The image-space shift of a point at distance L, per axis: the angle of arrival of a spherical
// wave at a point receiver, 2 pi^2 int_0^L (1 - s/L)^2 ds int kappa^3 Phi_n dkappa, one third of
// the plane wave's (A&P 2005, ch. 6: a turn at s moves the ray's end by (L - s) times it).
// 200 realizations x 16 rays within 3 degrees of the axis, both axes: 6400 shifts; l0 = 1 cm,
// L0 = 100 m, C_n^2 = 1e-12.  Tolerance 20 %.  Without the screens' turns carried to the wall
// (the plane wave's weights) the variance is 3 times as large; without any, 0.
TEST(ShimmerRays, ImageShiftsHaveTheSphericalWavesVariance) {
    const WallScene setup;
    TurbulenceSettings t;
    t.cn2 = 1e-12;
    t.inner_scale_m = 0.01;
    t.outer_scale_m = 100.0;
    std::mt19937_64 rng(3);
    double sum = 0.0;
    int n = 0;
    for (int r = 0; r < 200; ++r) {
        t.seed = 100 + r;
        const CurvedPropagator p(setup.curved(t));
        for (int i = 0; i < 16; ++i) {
            const glm::dvec2 a = image_shift(p, setup.parsed.accel, random_view(rng));
            sum += a.x * a.x + a.y * a.y;
            n += 2;
        }
    }
    const double variance = sum / n;
    const double length = kWall - kEye.z;
    const double plane = tilt_variance_integral(t, length);
    std::printf("  <alpha^2> = %.4g rad^2, spherical wave %.4g (ratio %.3f), plane wave %.4g\n",
                variance, plane / 3.0, variance / (plane / 3.0), plane);
    EXPECT_NEAR(variance / (plane / 3.0), 1.0, 0.20);
}

// The same rays a frame later: the wind (across the line of sight) has moved the air by rho at
// every screen, so a ray's shift is correlated with its shift before as two parallel paths rho
// apart are, B(rho) / B(0) (turbulence_test.cpp), whatever the weights along the path.
// 200 realizations x 16 rays; tolerance 0.08.  The scene in centimetres (Mirage_Unit 0.01) gives
// the same shifts: the screens are in metres.
TEST(ShimmerRays, SuccessiveFramesAreCorrelatedAsTheWindSays) {
    const WallScene setup;
    TurbulenceSettings t;
    t.cn2 = 1e-12;
    t.inner_scale_m = 0.01;
    t.outer_scale_m = 100.0;
    t.wind = glm::dvec3(0.0, 4.0, 0.0);  // rising air: the vertical shift decorrelates
    TiltCorrelations corr({0.002, 0.005, 0.01, 0.02});
    const std::vector<double>& rhos = corr.rhos();
    std::mt19937_64 rng(4);
    for (int r = 0; r < 200; ++r) {
        t.seed = 500 + r;
        CurvedSettings s = setup.curved(t);
        const CurvedPropagator now(s);
        std::vector<CurvedPropagator> later;
        for (double rho : rhos) {
            s.turbulence_time_s = rho / t.wind.y;
            later.emplace_back(s);
        }
        for (int i = 0; i < 16; ++i) {
            const glm::dvec3 d = random_view(rng);
            const double a = image_shift(now, setup.parsed.accel, d).x;
            for (std::size_t j = 0; j < rhos.size(); ++j) {
                const double b = image_shift(later[j], setup.parsed.accel, d).x;
                corr.add(j, a, b);
            }
        }
    }
    corr.expect_near(t, 0.08, "shift correlation");
}

// The same air in a scene drawn in centimetres: the same shifts (the screens are in metres).
TEST(ShimmerRays, SceneUnitsAreConvertedToMetres) {
    TurbulenceSettings t;
    t.cn2 = 1e-12;
    const WallScene metres;
    const CurvedPropagator p(metres.curved(t));
    const testing::Parsed cm = testing::build(
        "camera { location <0, 100, 0> look_at <0, 100, 1000> }\n"
        "plane { z, 2000 pigment { rgb 1 } }\n");
    const CurvedPropagator q(metres.curved(t, 0.01));  // the same screens, in metres
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.01, 0.02, 1.0));
    RayStart a;
    a.origin = kEye;
    a.direction = d;
    RayStart b = a;
    b.origin = kEye * 100.0;
    const PathHit ha = p.propagate(metres.parsed.accel, a);
    const PathHit hb = q.propagate(cm.accel, b);
    ASSERT_TRUE(ha.hit && hb.hit);
    EXPECT_LT(glm::length(hb.surface.point * 0.01 - ha.surface.point), 1e-9);
    const double range = (kWall - kEye.z) / d.z;
    EXPECT_GT(glm::length(ha.surface.point - (kEye + range * d)), 1e-7);
}

}  // namespace
}  // namespace mirage
