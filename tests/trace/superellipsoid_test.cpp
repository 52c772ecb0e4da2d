// Superellipsoids: the sphere and the box they become, inside tests, and POV-Ray's image.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/parser.h"
#include "shapes_parity_test.h"
#include "trace/scene_accel.h"

namespace mirage {
namespace {

SceneAccel accel_of(const std::string& text) {
    auto scene = parse_scene_text(text, "scene.pov", ParseOptions{});
    EXPECT_TRUE(scene.ok()) << scene.message();
    auto accel = SceneAccel::build(*scene);
    EXPECT_TRUE(accel.ok()) << accel.message();
    return std::move(*accel);
}

TEST(Superellipsoid, ExponentsOfOneMakeTheUnitSphere) {
    const SceneAccel a = accel_of("superellipsoid { <1, 1> pigment { rgb 1 } }\n");
    auto h = a.closest_hit({0, 0, -5}, {0, 0, 1}, 1e-4, 1e6);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-9);
    EXPECT_NEAR(h->normal.z, -1.0, 1e-9);
    const glm::dvec3 d = glm::normalize(glm::dvec3(1, 1, 1));
    h = a.closest_hit(-5.0 * d, d, 1e-4, 1e6);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-9);
    EXPECT_TRUE(inside_shape(a.shape(0), {0.5, 0.5, 0.5}));
    EXPECT_FALSE(inside_shape(a.shape(0), {0.6, 0.6, 0.6}));
}

TEST(Superellipsoid, SmallExponentsApproachTheCube) {
    const SceneAccel a = accel_of("superellipsoid { <0.05, 0.05> pigment { rgb 1 } }\n");
    const glm::dvec3 d = glm::normalize(glm::dvec3(1, 1, 1));
    auto h = a.closest_hit(-5.0 * d, d, 1e-4, 1e6);
    ASSERT_TRUE(h);
    // The corner of the unit cube is sqrt(3) from the centre; the 0.05 exponents round it by
    // 2^-0.05 per axis pair.
    EXPECT_NEAR(h->t, 5.0 - std::sqrt(3.0), 0.15);
    EXPECT_LT(h->t, 5.0 - 1.0);  // well outside the sphere
    EXPECT_TRUE(inside_shape(a.shape(0), {0.9, 0.9, 0.9}));
}

TEST(SuperellipsoidParity, RoundedBoxesCylindersAndStars) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const double psnr = testing::parity_psnr("superellipsoid_parity", "superellipsoids",
                                             R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
superellipsoid { <0.25, 0.25> pigment { rgb <1,0.3,0.2> } scale 0.7 translate <-2.2,0.7,0> }
superellipsoid { <1, 0.2> pigment { rgb <0.2,1,0.3> } scale 0.7 translate <0,0.7,0> }
superellipsoid { <2.5, 2.5> pigment { rgb <0.3,0.5,1> } scale 0.7 rotate y*30 translate <2.2,0.7,0> }
difference { box { <-0.6,0,-0.6>, <0.6,0.8,0.6> } superellipsoid { <0.5, 0.5> scale 0.5 translate y*0.8 } pigment { rgb 0.9 } translate <1.2,0,-2.2> }
)",
                                             160, 120);
    EXPECT_GE(psnr, 40.0);
}

}  // namespace
}  // namespace mirage
