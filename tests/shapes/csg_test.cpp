// Compound objects (CSG, clipped_by, bounded_by) and the cone, torus and quadric: hits,
// normals and inside tests against closed forms, and POV-Ray's images.
#include <gtest/gtest.h>

#include <cmath>

#include "trace/parsed_scene.h"
#include "scene/parser.h"
#include "trace/shapes_parity_test.h"
#include "trace/scene_accel.h"

namespace mirage {
namespace {

using testing::build;
using testing::Parsed;
using testing::shoot;

glm::dvec3 colour_of(const Parsed& p, const SurfaceHit& h) {
    return p.scene.primitives[h.primitive].texture.pigment.colour.rgb;
}

TEST(Csg, DifferenceShowsTheSubtractedSurfaceInsideOutWithItsTexture) {
    const Parsed p = build(R"(
difference {
  box { -1, 1 pigment { rgb <1, 0, 0> } }
  sphere { <0, 0, -1>, 0.5 pigment { rgb <0, 1, 0> } }
}
)");
    ASSERT_EQ(p.scene.compounds.size(), 1u);
    // Through the hole: the sphere's far side at z = -0.5.
    auto h = shoot(p, {0, 0, -5}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, 1e-12);
    EXPECT_EQ(colour_of(p, *h), glm::dvec3(0, 1, 0));
    // The inverted sphere's normal points into the sphere, towards its centre (-z here).
    EXPECT_NEAR(h->normal.z, -1.0, 1e-12);
    // Beside the hole: the box's front face.
    h = shoot(p, {0.8, 0, -5}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-12);
    EXPECT_EQ(colour_of(p, *h), glm::dvec3(1, 0, 0));
    // The sphere's part outside the box is not there.
    EXPECT_FALSE(shoot(p, {0, 0.3, -5}, {0, 0.0, 1}).has_value() &&
                 shoot(p, {0, 0.3, -5}, {0, 0, 1})->t < 3.9);
}

TEST(Csg, IntersectionKeepsWhatIsInsideEveryChildAndIsBoundedByThem) {
    const Parsed p = build(R"(
intersection { sphere { 0, 1 } box { -0.75, 0.75 } pigment { rgb 1 } }
)");
    // Along the axis: the box's face (inside the sphere).
    auto h = shoot(p, {0, 0, -5}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.25, 1e-12);
    // Along a diagonal the sphere comes first: its surface is inside the box there (the box's
    // corner, 0.75 sqrt(3) from the centre, is cut off).
    const double s = 1.0 / std::sqrt(3.0);
    h = shoot(p, {-5 * s, -5 * s, -5 * s}, {1, 1, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-9);
    EXPECT_NEAR(h->normal.x, -s, 1e-9);
    const Aabb b = p.accel.finite_bounds();
    EXPECT_NEAR(b.hi.x, 0.75, 1e-6);
    EXPECT_NEAR(b.lo.y, -0.75, 1e-6);
}

TEST(Csg, MergeHasNoInnerSurfacesAndUnionHas) {
    const std::string spheres = "sphere { 0, 1 } sphere { <1, 0, 0>, 1 } pigment { rgb 1 }";
    const Parsed u = build("union { " + spheres + " clipped_by { box { -5, 5 } } }\n");
    const Parsed m = build("merge { " + spheres + " }\n");
    // From the centre of the first sphere towards the second: the union meets the second
    // sphere's near side inside the first, the merge only the far side of the second.
    auto hu = shoot(u, {0, 0, 0}, {1, 0, 0});
    auto hm = shoot(m, {0, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(hu && hm);
    EXPECT_NEAR(hu->t, 1.0, 1e-12);  // the first sphere's exit, x = 1 (the second's entry is 0)
    EXPECT_NEAR(hm->t, 2.0, 1e-12);
}

TEST(Csg, InverseOfAUnionIsTheIntersectionOfTheInverses) {
    // POV-Ray's Invert_CSG_Object: the inside of union { A B inverse } is outside both.
    const Parsed p = build(R"(
intersection {
  box { -3, 3 }
  union { sphere { <-1, 0, 0>, 0.5 } sphere { <1, 0, 0>, 0.5 } inverse }
  pigment { rgb 1 }
}
)");
    // From inside the box, between the spheres, towards one: its surface, seen from outside.
    auto h = shoot(p, {0, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 0.5, 1e-12);
    EXPECT_NEAR(h->normal.x, 1.0, 1e-12);  // inverted: into the sphere
}

TEST(Csg, ClippedByRemovesWhatLiesOutsideTheClip) {
    const Parsed p = build("sphere { 0, 1 clipped_by { plane { z, 0 } } pigment { rgb 1 } }\n");
    // The front half is kept (inside plane { z, 0 } is z < 0).
    auto h = shoot(p, {0, 0, -5}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-12);
    // From behind, the back cap is gone: the ray meets the front half from inside.
    h = shoot(p, {0, 0, 5}, {0, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 6.0, 1e-12);
}

TEST(Csg, BoundedByTestsOnlyRaysThatMeetTheBound) {
    // A bound smaller than the object: rays missing it miss the object, rays meeting it see
    // all of the object (POV-Ray's Ray_In_Bound, not a clip).
    const Parsed p = build(
        "sphere { 0, 1 bounded_by { box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> } } "
        "pigment { rgb 1 } }\n");
    EXPECT_FALSE(shoot(p, {0.8, 0, -5}, {0, 0, 1}).has_value());
    auto h = shoot(p, {0, 0, -5}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-12);  // the sphere, outside the bound
}

TEST(Cone, HitsNormalsAndInsideAgainstTheClosedForm) {
    // Base radius 1 at y = 0, tip-side radius 0.5 at y = 2: r(y) = 1 - y / 4.
    const Parsed p = build("cone { <0, 0, 0>, 1, <0, 2, 0>, 0.5 pigment { rgb 1 } }\n");
    auto h = shoot(p, {-5, 1, 0}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - 0.75, 1e-12);
    // The side's normal leans up: proportional to (-1, 1/4, 0) at (-0.75, 1, 0).
    const glm::dvec3 expect = glm::normalize(glm::dvec3(-1.0, 0.25, 0.0));
    EXPECT_NEAR(glm::length(h->normal - expect), 0.0, 1e-12);
    // The caps.
    h = shoot(p, {0.2, 5, 0}, {0, -1, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.0, 1e-12);
    EXPECT_NEAR(h->normal.y, 1.0, 1e-12);
    h = shoot(p, {0.9, -5, 0}, {0, 1, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0, 1e-12);
    EXPECT_NEAR(h->normal.y, -1.0, 1e-12);
    const PreparedShape& s = p.accel.shape(0);
    EXPECT_TRUE(inside_shape(s, {0.0, 1.0, 0.7}));
    EXPECT_FALSE(inside_shape(s, {0.0, 1.0, 0.8}));
    EXPECT_FALSE(inside_shape(s, {0.0, 2.1, 0.0}));
}

TEST(Torus, FourHitsAlongADiameterAndTheTubeNormal) {
    const Parsed p = build("torus { 2, 0.5 pigment { rgb 1 } }\n");
    const PreparedShape& s = p.accel.shape(0);
    std::vector<ShapeHit> hits;
    intersect_shape_all(s, {-5, 0, 0}, {1, 0, 0}, 1e-4, 100.0, hits);
    ASSERT_EQ(hits.size(), 4u);
    std::vector<double> t;
    for (const auto& h : hits) t.push_back(h.t);
    std::sort(t.begin(), t.end());
    EXPECT_NEAR(t[0], 2.5, 1e-9);
    EXPECT_NEAR(t[1], 3.5, 1e-9);
    EXPECT_NEAR(t[2], 6.5, 1e-9);
    EXPECT_NEAR(t[3], 7.5, 1e-9);
    // From above onto the tube at (2, 0.5, 0)... the top of the tube.
    auto h = shoot(p, {2, 5, 0}, {0, -1, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, 1e-9);
    EXPECT_NEAR(h->normal.y, 1.0, 1e-9);
    EXPECT_TRUE(inside_shape(s, {0.0, 0.2, 2.1}));
    EXPECT_FALSE(inside_shape(s, {0.0, 0.0, 0.0}));
}

TEST(Quadric, EllipsoidHitsNormalAndBounds) {
    // x^2 / 4 + y^2 + z^2 = 1, moved to y = 3.
    const Parsed p = build(
        "quadric { <0.25, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 translate y*3 pigment { rgb 1 } }\n");
    auto h = shoot(p, {-10, 3, 0}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 8.0, 1e-12);
    EXPECT_NEAR(h->normal.x, -1.0, 1e-12);
    const Aabb b = p.accel.finite_bounds();
    EXPECT_NEAR(b.lo.x, -2.0, 1e-6);
    EXPECT_NEAR(b.hi.y, 4.0, 1e-6);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {1.9, 3.0, 0.0}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {1.9, 3.5, 0.0}));
}

TEST(Quadric, AnInfiniteCylinderIsUnbounded) {
    const Parsed p = build("quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 pigment { rgb 1 } }\n");
    EXPECT_EQ(p.accel.unbounded().size(), 1u);
    auto h = shoot(p, {0, 1e5, -10}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 9.0, 1e-9);
}

TEST(CsgParity, DifferenceIntersectionMergeConeTorusQuadricClip) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const double psnr = testing::parity_psnr("csg_parity", "csg", R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
difference {
  box { <-1, 0, -1>, <1, 2, 1> pigment { rgb <0.9, 0.2, 0.1> } }
  sphere { <0, 2, 0>, 1.2 pigment { rgb <0.1, 0.8, 0.2> } }
  cylinder { <-2, 0.7, 0>, <2, 0.7, 0>, 0.4 pigment { rgb <0.1, 0.2, 0.9> } }
  translate <-2.2, 0, 0> rotate y*20
}
intersection {
  sphere { 0, 1 }
  box { -0.75, 0.75 }
  pigment { rgb <0.9, 0.8, 0.1> } finish { phong 0.8 }
  translate <0, 1, 1>
}
merge {
  cone { <0, 0, 0>, 0.8, <0, 1.5, 0>, 0.1 }
  torus { 0.8, 0.25 translate y*0.25 }
  pigment { rgb <0.3, 0.9, 0.9> }
  translate <2.2, 0, -0.5>
}
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -0.16 pigment { rgb 1 } translate <0, 0.4, -2> }
sphere { <-1, 0.5, -2.5>, 0.5 pigment { rgb <1, 0.5, 0> } clipped_by { plane { y, 0.6 } } }
union {
  sphere { <1.2, 0.3, -2.6>, 0.3 } sphere { <1.5, 0.3, -2.6>, 0.3 }
  bounded_by { box { <0.8, 0, -3>, <1.9, 0.6, -2.2> } }
  pigment { rgb <0.8, 0.3, 0.8> }
}
)",
                                             160, 120);
    EXPECT_GE(psnr, 40.0);
}

}  // namespace
}  // namespace mirage
