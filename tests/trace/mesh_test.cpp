// Triangles, meshes (mesh, mesh2) and polygons: hits, normals and inside tests against closed
// forms, and POV-Ray's image.
#include <gtest/gtest.h>

#include <cmath>

#include "parsed_scene.h"
#include "scene/parser.h"
#include "shapes_parity_test.h"
#include "trace/scene_accel.h"

namespace mirage {
namespace {

using testing::build;
using testing::Parsed;
using testing::shoot;

TEST(Mesh, ATriangleIsHitInsideItsEdgesOnly) {
    const Parsed p = build("triangle { <0, 0, 0>, <2, 0, 0>, <0, 2, 0> pigment { rgb 1 } }\n");
    auto h = shoot(p, {0.5, 0.5, -3}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.0, 1e-12);
    EXPECT_NEAR(std::abs(h->normal.z), 1.0, 1e-12);
    EXPECT_FALSE(shoot(p, {1.1, 1.1, -3}, {0, 0, 1}));  // beyond the hypotenuse
    EXPECT_FALSE(shoot(p, {-0.1, 0.5, -3}, {0, 0, 1}));
}

TEST(Mesh, SmoothTriangleNormalsInterpolateAsPovRay) {
    // Normals leaning in x at the first corner, straight at the others: at a vertex the
    // normal is that vertex's, between them a blend.
    const Parsed p = build(
        "smooth_triangle { <0, 0, 0>, <1, 0, -1>, <2, 0, 0>, <0, 0, -1>, <0, 2, 0>, <0, 0, -1> "
        "pigment { rgb 1 } }\n");
    auto at_corner = shoot(p, {1e-7, 1e-7, -3}, {0, 0, 1});
    ASSERT_TRUE(at_corner);
    EXPECT_NEAR(at_corner->normal.x, std::sqrt(0.5), 1e-5);
    auto far = shoot(p, {1.0, 0.99, -3}, {0, 0, 1});  // near the edge opposite the corner
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->normal.x, 0.0, 0.01);
    auto middle = shoot(p, {0.5, 0.5, -3}, {0, 0, 1});
    ASSERT_TRUE(middle);
    EXPECT_GT(middle->normal.x, 0.1);
    EXPECT_LT(middle->normal.x, std::sqrt(0.5));
}

TEST(Mesh, InsideVectorGivesATetrahedronAnInside) {
    const std::string tet =
        "vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <0,0,1> } "
        "face_indices { 4, <0,1,2>, <0,1,3>, <0,2,3>, <1,2,3> } ";
    const Parsed with = build("mesh2 { " + tet + " inside_vector <1, 1.1, 1.2> }\n");
    const Parsed without = build("mesh2 { " + tet + " }\n");
    EXPECT_TRUE(inside_shape(with.accel.shape(0), {0.1, 0.1, 0.1}));
    EXPECT_FALSE(inside_shape(with.accel.shape(0), {0.5, 0.5, 0.5}));
    EXPECT_FALSE(inside_shape(without.accel.shape(0), {0.1, 0.1, 0.1}));
    // Through the slanted face: x + y + z = 1.
    auto h = shoot(with, {0.2, 0.2, 5}, {0, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - 0.6, 1e-6);  // single precision, as POV-Ray
}

TEST(Mesh, TrianglesWithTexturesKeepThem) {
    const Parsed p = build(R"(
#declare T_Red = texture { pigment { rgb <1, 0, 0> } }
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> texture { T_Red } }
  triangle { <2, 0, 0>, <3, 0, 0>, <2, 1, 0> }
  pigment { rgb <0, 0, 1> }
}
)");
    auto red = shoot(p, {0.2, 0.2, -1}, {0, 0, 1});
    auto blue = shoot(p, {2.2, 0.2, -1}, {0, 0, 1});
    ASSERT_TRUE(red && blue);
    EXPECT_EQ(p.scene.primitives[red->primitive].texture.pigment.colour.rgb, glm::dvec3(1, 0, 0));
    EXPECT_EQ(p.scene.primitives[blue->primitive].texture.pigment.colour.rgb, glm::dvec3(0, 0, 1));
}

TEST(Mesh, BadFaceIndicesAreRefusedWithTheirPlace) {
    auto s =
        parse_scene_text("mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 3> } }",
                         "scene.pov", ParseOptions{});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message().rfind("scene.pov:1:57: face index 3 out of range 0 to 2", 0), 0u)
        << s.message();
}

TEST(Polygon, HoleAndOutlineByTheCrossingRule) {
    // A 2 x 2 square with a 1 x 1 hole, in the xy plane.
    const Parsed p = build(
        "polygon { 10, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>, <-0.5,-0.5>, <0.5,-0.5>, "
        "<0.5,0.5>, <-0.5,0.5>, <-0.5,-0.5> pigment { rgb 1 } }\n");
    auto h = shoot(p, {0.75, 0, -2}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2.0, 1e-12);
    EXPECT_FALSE(shoot(p, {0, 0, -2}, {0, 0, 1}));    // in the hole
    EXPECT_FALSE(shoot(p, {1.2, 0, -2}, {0, 0, 1}));  // outside
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {0.75, 0, 0}));
}

TEST(MeshParity, MeshMesh2TrianglesAndPolygon) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const double psnr = testing::parity_psnr("mesh_parity", "meshes", R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
#declare T_Green = texture { pigment { rgb <0, 1, 0> } }
mesh {
  triangle { <-3, 0, 0>, <-2, 2, 0>, <-1, 0, 0> }
  smooth_triangle { <-1, 0, 0>, <-1, 0, -1>, <0, 2, 0>, <0, 1, -1>, <1, 0, 0>, <1, 0, -1> texture { T_Green } }
  pigment { rgb <1, 0, 0> } finish { phong 0.8 }
}
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <0.5,0,1>, <0.5,1,0.4> }
  normal_vectors { 4, <0,-1,0>, <1,0,-1>, <-1,0,-1>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb <1,1,0> } } texture { pigment { rgb <0,1,1> } } }
  face_indices { 4, <0,1,3>, 0, <1,2,3>, 1, <2,0,3>, 0, <0,1,2> }
  inside_vector y
  pigment { rgb 1 }
  translate <1.5, 0, -1> scale 1.5
}
triangle { <2, 0, 2>, <3, 2, 2>, <4, 0, 2> pigment { rgb <1,0,1> } }
smooth_triangle { <-4, 0, 2>, <0,1,-1>, <-3, 2, 2>, <-1,0,-1>, <-2, 0, 2>, <1,0,-1> pigment { rgb <0,0,1> } finish { phong 1 } }
polygon { 10, <-1,0.2>, <1,0.2>, <1,2>, <-1,2>, <-1,0.2>, <-0.5,0.7>, <0.5,0.7>, <0.5,1.5>, <-0.5,1.5>, <-0.5,0.7> pigment { rgb <1,0.5,0> } rotate y*20 translate <0,0,3> }
difference {
  box { <-0.6,0,-2.6>, <0.2, 0.8, -1.8> }
  mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0.5,0,1>, <0.5,1,0.4> }
          face_indices { 4, <0,1,3>, <1,2,3>, <2,0,3>, <0,1,2> } inside_vector y
          translate <-0.7, 0.3, -2.7> }
  pigment { rgb <0.5,0.5,1> }
}
)",
                                             160, 120);
    EXPECT_GE(psnr, 40.0);
}

}  // namespace
}  // namespace mirage
