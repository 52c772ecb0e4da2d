// Prisms, lathes and surfaces of revolution: hits, normals and inside tests against closed
// forms, and POV-Ray's image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "parsed_scene.h"
#include "scene/parser.h"
#include "shapes_parity_test.h"
#include "trace/scene_accel.h"

namespace mirage {
namespace {

using testing::build;
using testing::Parsed;

TEST(Prism, ALinearSquarePrismIsABox) {
    const Parsed p =
        build("prism { 0, 2, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> pigment { rgb 1 } }\n");
    auto t = testing::hit_depths(p, {-5, 1, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.0, 1e-12);
    EXPECT_NEAR(t[1], 6.0, 1e-12);
    t = testing::hit_depths(p, {0.5, 5, 0.5}, {0, -1, 0});  // through the caps
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 3.0, 1e-12);
    EXPECT_NEAR(t[1], 5.0, 1e-12);
    auto h = p.accel.closest_hit({-5, 1, 0.3}, {1, 0, 0}, 1e-4, 1e6);
    ASSERT_TRUE(h);
    EXPECT_NEAR(std::abs(h->normal.x), 1.0, 1e-12);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {0.9, 1.9, -0.9}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {1.1, 1.0, 0.0}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {0.0, 2.1, 0.0}));
}

TEST(Prism, AnOpenPrismHasNoCapsAndAConicOneNarrowsToTheOrigin) {
    const Parsed open = build(
        "prism { 0, 2, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> open pigment { rgb 1 } }\n");
    EXPECT_TRUE(testing::hit_depths(open, {0.5, 5, 0.5}, {0, -1, 0}).empty());
    // A conic sweep from y = 0 to 1: at height h the square is h wide on each side.
    const Parsed conic = build(
        "prism { conic_sweep 0, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> pigment { rgb 1 } "
        "}\n");
    auto t = testing::hit_depths(conic, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.5, 1e-12);
    EXPECT_NEAR(t[1], 5.5, 1e-12);
}

TEST(Lathe, ALinearLatheIsACone) {
    // r(y) = 1 - y / 2 from y = 0 to 2, closed by the axis at both ends.  A ray off the axis by
    // 0.3 at y = 1 (r = 0.5) meets the cone at x = -0.4 and 0.4.
    const Parsed p =
        build("lathe { linear_spline 4, <0,0>, <1,0>, <0,2>, <0,0> pigment { rgb 1 } }\n");
    auto t = testing::hit_depths(p, {-5, 1, 0.3}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.6, 1e-9);
    EXPECT_NEAR(t[1], 5.4, 1e-9);
    auto h = p.accel.closest_hit({-5, 1, 0.3}, {1, 0, 0}, 1e-4, 1e6);
    ASSERT_TRUE(h);
    // Outward: along the radius (-0.4, 0, 0.3) / 0.5, tilted up by the slope 1/2.
    const glm::dvec3 expect = glm::normalize(glm::dvec3(-0.8, 0.5, 0.6));
    EXPECT_NEAR(std::abs(glm::dot(h->normal, expect)), 1.0, 1e-9);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {0.0, 1.0, 0.4}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {0.0, 1.0, 0.6}));
}

TEST(Sor, ACylindricalProfileIsACylinder) {
    // r = 0.5 from y = 0 to 1 (control points below and above set the slopes to zero).
    const Parsed p = build("sor { 4, <0.5,-1>, <0.5,0>, <0.5,1>, <0.5,2> pigment { rgb 1 } }\n");
    auto t = testing::hit_depths(p, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.5, 1e-9);
    EXPECT_NEAR(t[1], 5.5, 1e-9);
    t = testing::hit_depths(p, {0.2, 5, 0}, {0, -1, 0});  // the caps
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.0, 1e-9);
    EXPECT_NEAR(t[1], 5.0, 1e-9);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {0.4, 0.5, 0.0}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {0.6, 0.5, 0.0}));
}

TEST(Sor, DecreasingHeightsAreRefusedWithTheirPlace) {
    auto s =
        parse_scene_text("sor { 4, <1,0>, <1,1>, <1,0.5>, <1,2> }", "scene.pov", ParseOptions{});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message().rfind("scene.pov:1:24: incorrect point in surface of revolution", 0), 0u)
        << s.message();
}

TEST(SweepParity, PrismsLathesAndSors) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const double psnr = testing::parity_psnr("sweep_parity", "sweeps", R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
prism { linear_sweep quadratic_spline 0, 0.8, 6, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1> pigment { rgb <0.2,1,0.3> } translate <-2.5,0,1> }
prism { cubic_spline 0, 1.2, 7, <1,0>, <0,1>, <-1,0>, <0,-0.5>, <1,0>, <0,1>, <-1,0> pigment { rgb <0.3,0.5,1> } translate <2.5,0,1> }
prism { conic_sweep linear_spline 0, 1, 5, <1,1>, <-1,1>, <-1,-1>, <1,-1>, <1,1> rotate x*180 translate <0,1,1.5> pigment { rgb <1,1,0> } }
prism { bezier_spline 0, 0.5, 8, <0,0>, <1,0>, <1,1>, <0,1>, <0,1>, <-1,1>, <-1,0>, <0,0> pigment { rgb <1,0,1> } translate <-2,0,-2.5> }
lathe { quadratic_spline 6, <0,0>, <0.8,0.1>, <0.4,0.7>, <0.6,1.2>, <0.2,1.5>, <0,1.6> pigment { rgb <1,0.3,0.2> } translate <-0.8,0,0> }
lathe { bezier_spline 8, <0,0>, <1,0>, <1,0.5>, <0.5,0.7>, <0.5,0.7>, <0.2,0.9>, <0.4,1.3>, <0,1.4> pigment { rgb <1,0.8,0> } translate <0.8,0,0> }
sor { 6, <0,-0.5>, <0.6,0>, <0.3,0.4>, <0.5,0.9>, <0.2,1.2>, <0.3,1.5> pigment { rgb <0,1,1> } translate <1.8,0,-2> }
difference { box { <-0.6,0,-0.6>, <0.6,0.8,0.6> } sor { 4, <0,-0.1>, <0.3,0>, <0.3,1>, <0.3,1.2> } pigment { rgb 0.9 } translate <0,0,-2.5> }
)",
                                             160, 120);
    EXPECT_GE(psnr, 40.0);
}

}  // namespace
}  // namespace mirage
