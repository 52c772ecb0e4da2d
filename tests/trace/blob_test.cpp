// Blobs: the density field against its closed form, hits and normals of one-component blobs
// against spheres, the parser's defaults and refusals, and POV-Ray's image.
#include "shapes/blob.h"

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

const Blob& blob_of(const Parsed& p) { return std::get<Blob>(p.scene.primitives.at(0).shape); }

TEST(Blob, TheFieldIsStrengthTimesOneMinusRSquaredOverRadiusSquaredSquared) {
    const Parsed p = build(
        "blob { threshold 0.5 sphere { <1,0,0>, 2, 3 } cylinder { <0,5,0>, <4,5,0>, 1, "
        "strength -0.5 } pigment { rgb 1 } }\n");
    const Blob& b = blob_of(p);
    ASSERT_EQ(b.components.size(), 2u);
    EXPECT_DOUBLE_EQ(b.threshold, 0.5);
    const auto f = [](double s, double r2, double R2) {
        return r2 < R2 ? s * (1.0 - r2 / R2) * (1.0 - r2 / R2) : 0.0;
    };
    // The sphere's centre, a point 1.5 from it, and one outside its radius.
    EXPECT_NEAR(blob_field(b, {1, 0, 0}), 3.0, 1e-12);
    EXPECT_NEAR(blob_field(b, {1, 1.5, 0}), f(3.0, 2.25, 4.0), 1e-12);
    EXPECT_NEAR(blob_field(b, {3.5, 0, 0}), 0.0, 1e-15);
    // The cylinder: 0.6 off its axis over its body; 0.6 beyond its end, in the end's
    // hemisphere (the same radial law from the end point); nothing 1.1 beyond.
    EXPECT_NEAR(blob_field(b, {2, 5.6, 0}), f(-0.5, 0.36, 1.0), 1e-12);
    EXPECT_NEAR(blob_field(b, {4.6, 5, 0}), f(-0.5, 0.36, 1.0), 1e-12);
    EXPECT_NEAR(blob_field(b, {-0.3, 5.4, 0}), f(-0.5, 0.25, 1.0), 1e-12);
    EXPECT_NEAR(blob_field(b, {5.1, 5, 0}), 0.0, 1e-15);
    const auto per = blob_component_fields(b, {1, 1.5, 0});
    ASSERT_EQ(per.size(), 2u);
    EXPECT_NEAR(per[0], f(3.0, 2.25, 4.0), 1e-12);
    EXPECT_EQ(per[1], 0.0);
}

TEST(Blob, OneSphereComponentIsASphereOfTheRadiusWhereTheFieldMeetsTheThreshold) {
    // strength 1, radius 2, threshold 0.25: (1 - r^2/4)^2 = 0.25 at r^2 = 2.
    const Parsed p =
        build("blob { threshold 0.25 sphere { <0,0,0>, 2, 1 } pigment { rgb 1 } translate y }\n");
    const double r = std::sqrt(2.0);
    auto t = testing::hit_depths(p, {-5, 1, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5.0 - r, 1e-9);
    EXPECT_NEAR(t[1], 5.0 + r, 1e-9);
    auto h = p.accel.closest_hit({-5, 1.5, 0}, {1, 0, 0}, 1e-4, 1e6);
    ASSERT_TRUE(h);
    const glm::dvec3 at = glm::dvec3(-5, 1.5, 0) + h->t * glm::dvec3(1, 0, 0);
    const glm::dvec3 expected = glm::normalize(at - glm::dvec3(0, 1, 0));
    EXPECT_NEAR(h->normal.x, expected.x, 1e-9);
    EXPECT_NEAR(h->normal.y, expected.y, 1e-9);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {1.4, 1, 0}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {1.42, 1, 0}));
    // The bounds: the component's sphere, moved.
    const Aabb box = shape_bounds(p.accel.shape(0));
    EXPECT_NEAR(box.lo.y, -1.0, 1e-9);
    EXPECT_NEAR(box.hi.y, 3.0, 1e-9);
    EXPECT_NEAR(box.hi.x, 2.0, 1e-9);
}

TEST(Blob, ACylinderComponentIsACapsuleAndAScaledSphereAnEllipsoid) {
    // A cylinder of radius 1, strength 1, threshold 0.25: radius sqrt(0.5) around the axis
    // from <-1,0,0> to <1,0,0>, rounded at both ends.
    const Parsed cyl =
        build("blob { threshold 0.25 cylinder { <-1,0,0>, <1,0,0>, 1, 1 } pigment { rgb 1 } }\n");
    const double r = std::sqrt(0.5);
    auto t = testing::hit_depths(cyl, {0.3, 5, 0}, {0, -1, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5.0 - r, 1e-9);
    EXPECT_NEAR(t[1], 5.0 + r, 1e-9);
    t = testing::hit_depths(cyl, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.0 - r, 1e-9);
    EXPECT_NEAR(t[1], 6.0 + r, 1e-9);
    // sphere { 0, 1, 1 scale <2,1,1> } with threshold 0.25: an ellipsoid of semi-axes
    // 2 sqrt(0.5), sqrt(0.5), sqrt(0.5).
    const Parsed ell =
        build("blob { threshold 0.25 sphere { 0, 1, 1 scale <2,1,1> } pigment { rgb 1 } }\n");
    t = testing::hit_depths(ell, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5.0 - 2.0 * r, 1e-9);
    EXPECT_NEAR(t[1], 5.0 + 2.0 * r, 1e-9);
}

TEST(Blob, ANegativeComponentCutsAndTheOldSyntaxAndDefaultThresholdHold) {
    // Two spheres of strength 2 at +-0.5 with the default threshold 1, and a negative
    // component at the origin.  On the x axis the field of the positive pair at 0 is
    // 2 * 2 * (1 - 0.25)^2 = 2.25; the negative one, -2 there, leaves 0.25 < 1: a hole.
    const Parsed p = build(
        "blob { component 2, 1, <-0.5,0,0> component 2, 1, <0.5,0,0> sphere { 0, 0.5, -2 } "
        "pigment { rgb 1 } }\n");
    EXPECT_DOUBLE_EQ(blob_of(p).threshold, 1.0);
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {0, 0, 0}));
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {0.6, 0, 0}));
    // Along z through a positive centre only that sphere reaches: 2 (1 - z^2)^2 = 1.
    const auto t = testing::hit_depths(p, {0.5, 0, -5}, {0, 0, 1});
    const double z = std::sqrt(1.0 - 1.0 / std::sqrt(2.0));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5.0 - z, 1e-9);
    EXPECT_NEAR(t[1], 5.0 + z, 1e-9);
}

TEST(Blob, ARadiusIsSquaredSoItsSignDoesNotMatterAndZeroGivesNothing) {
    const Parsed neg = build(
        "blob { threshold 0.25 sphere { 0, -2, 1 } sphere { <5,0,0>, 0, 1 } "
        "pigment { rgb 1 } }\n");
    EXPECT_NEAR(blob_field(blob_of(neg), {1, 0, 0}), 0.5625, 1e-12);
    EXPECT_EQ(blob_field(blob_of(neg), {5, 0, 0.001}), 0.0);
    auto t = testing::hit_depths(neg, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5.0 - std::sqrt(2.0), 1e-9);
}

TEST(Blob, BadInputIsRefusedWithItsPlace) {
    auto empty =
        parse_scene_text("blob { threshold 1 pigment { rgb 1 } }", "scene.pov", ParseOptions{});
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.message().rfind("scene.pov:1:1: a blob needs at least one component", 0), 0u)
        << empty.message();
    auto degenerate = parse_scene_text("blob {\n  cylinder { <1,2,3>, <1,2,3>, 1, 1 }\n}",
                                       "scene.pov", ParseOptions{});
    ASSERT_FALSE(degenerate.ok());
    EXPECT_EQ(
        degenerate.message().rfind("scene.pov:2:14: degenerate cylindrical component in blob", 0),
        0u)
        << degenerate.message();
    auto missing = parse_scene_text("blob { sphere { <0,0,0>, 1 } }", "scene.pov", ParseOptions{});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.message().rfind("scene.pov:1:", 0), 0u) << missing.message();
}

TEST(BlobParity, SpheresCylindersNegativeStrengthTransformsAndSturm) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const double psnr = testing::parity_psnr("blob_parity", "blobs", R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
blob {
  threshold 0.6
  sphere { <-0.6, 1, 0>, 1, 1 }
  sphere { <0.6, 1, 0>, 1, 1 }
  sphere { <0, 1.3, -0.6>, 0.7, -1.5 }
  cylinder { <-1, 0.3, 0>, <1, 0.3, 0>, 0.5, strength 1.2 }
  sphere { 0, 1, 1 scale <0.3, 1, 0.3> rotate z*30 translate <0, 2, 0.4> }
  pigment { rgb <1, 0.3, 0.2> }
  finish { phong 0.8 }
  rotate y*20 translate <-1.3, 0, 0.5>
}
blob {
  threshold 0.4
  cylinder { <0, 0.2, 0>, <0, 1.6, 0>, 0.6, 1 }
  cylinder { <-0.8, 1, 0>, <0.8, 1, 0>, 0.4, 1 rotate y*45 }
  component -1, 0.5, <0, 1.6, -0.3>
  sturm
  pigment { rgb <0.3, 0.6, 1> }
  scale 1.2 translate <1.6, 0, 0>
}
)",
                                             160, 120);
    EXPECT_GE(psnr, 40.0);
}

}  // namespace
}  // namespace mirage
