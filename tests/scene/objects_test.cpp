// Objects: shapes, transforms, unions flattened with POV-Ray's texture rules, light sources.
#include <gtest/gtest.h>

#include "parse_helpers.h"
#include "scene/transform.h"

namespace mirage {
namespace {

using testing::expect_vec;
using testing::parse_error;
using testing::parse_ok;

glm::dvec3 world(const Primitive& p, const glm::dvec3& local) {
    return transform_point(p.transform, local);
}
glm::dvec3 pattern_point(const Pigment& p, const glm::dvec3& world_point) {
    return inverse_transform_point(p.transform, world_point);
}

TEST(Objects, Shapes) {
    Scene s = parse_ok(R"(
        sphere { <1, 2>, 0.5 }
        plane { <0, 2, 0>, 3 }
        box { <1, -1, 2>, <-1, 1, -2> }
        cylinder { 0, 2 * y, 0.25 open }
        disc { <0, 1, 0>, <0, 0, 3>, 2, 0.5 }
    )");
    ASSERT_EQ(s.primitives.size(), 5u);
    const auto& sphere = std::get<Sphere>(s.primitives[0].shape);
    expect_vec(sphere.center, glm::dvec3(1, 2, 0));  // a 2-vector is padded with 0
    EXPECT_EQ(sphere.radius, 0.5);
    const auto& plane = std::get<Plane>(s.primitives[1].shape);
    expect_vec(plane.normal, glm::dvec3(0, 1, 0));  // normalised; the distance is as given
    EXPECT_EQ(plane.distance, 3.0);
    const auto& box = std::get<Box>(s.primitives[2].shape);
    expect_vec(box.corner1, glm::dvec3(-1, -1, -2));  // sorted, as POV-Ray does
    expect_vec(box.corner2, glm::dvec3(1, 1, 2));
    const auto& cyl = std::get<Cylinder>(s.primitives[3].shape);
    expect_vec(cyl.cap, glm::dvec3(0, 2, 0));
    EXPECT_EQ(cyl.radius, 0.25);
    EXPECT_TRUE(cyl.open);
    const auto& disc = std::get<Disc>(s.primitives[4].shape);
    expect_vec(disc.normal, glm::dvec3(0, 0, 1));
    EXPECT_EQ(disc.radius, 2.0);
    EXPECT_EQ(disc.hole_radius, 0.5);
    EXPECT_EQ(s.primitives[3].loc.line, 5);
    EXPECT_EQ(s.primitives[3].loc.column, 9);
}

TEST(Objects, TransformsComposeInOrder) {
    Scene s = parse_ok(R"(
        sphere { 0, 1 scale 2 translate <1, 0, 0> }
        sphere { 0, 1 translate <1, 0, 0> scale 2 }
        sphere { 0, 1 rotate 90 * y translate <0, 0, 5> }
        sphere { 0, 1 matrix <1, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0> }
        #declare T = transform { translate 3 * x scale 2 }
        sphere { 0, 1 transform T }
        sphere { 0, 1 transform { T inverse } }
    )");
    ASSERT_EQ(s.primitives.size(), 6u);
    expect_vec(world(s.primitives[0], glm::dvec3(1, 0, 0)), glm::dvec3(3, 0, 0));
    expect_vec(world(s.primitives[1], glm::dvec3(1, 0, 0)), glm::dvec3(4, 0, 0));
    expect_vec(world(s.primitives[2], glm::dvec3(1, 0, 0)), glm::dvec3(0, 0, 4));
    expect_vec(world(s.primitives[3], glm::dvec3(0, 1, 0)), glm::dvec3(1, 1, 0));
    expect_vec(world(s.primitives[4], glm::dvec3(1, 0, 0)), glm::dvec3(8, 0, 0));
    expect_vec(world(s.primitives[5], glm::dvec3(8, 0, 0)), glm::dvec3(1, 0, 0));
}

TEST(Objects, ScaleByZeroBecomesOne) {
    Scene s = parse_ok("sphere { 0, 1 scale <2, 0, 1> }");
    ASSERT_EQ(s.primitives.size(), 1u);
    expect_vec(world(s.primitives[0], glm::dvec3(1, 1, 1)), glm::dvec3(2, 1, 1));
    ASSERT_EQ(s.messages.size(), 1u);
    EXPECT_EQ(s.messages[0], "scene.pov:1:21: warning: scale by 0 in y, changed to 1");
}

TEST(Objects, TransformsAfterATextureMoveItTransformsBeforeDoNot) {
    Scene s = parse_ok(R"(
        sphere { 0, 1 texture { pigment { checker } } translate <1, 0, 0> }
        sphere { 0, 1 translate <1, 0, 0> texture { pigment { checker } } }
        sphere { 0, 1 pigment { checker } scale 2 }
        sphere { 0, 1 scale 2 pigment { checker scale 3 } }
    )");
    ASSERT_EQ(s.primitives.size(), 4u);
    expect_vec(pattern_point(s.primitives[0].texture.pigment, glm::dvec3(1, 0, 0)),
               glm::dvec3(0, 0, 0));
    expect_vec(pattern_point(s.primitives[1].texture.pigment, glm::dvec3(1, 0, 0)),
               glm::dvec3(1, 0, 0));
    expect_vec(pattern_point(s.primitives[2].texture.pigment, glm::dvec3(2, 0, 0)),
               glm::dvec3(1, 0, 0));
    expect_vec(pattern_point(s.primitives[3].texture.pigment, glm::dvec3(3, 0, 0)),
               glm::dvec3(1, 0, 0));
}

TEST(Objects, UnionChildrenWithoutTextureInheritTheUnions) {
    Scene s = parse_ok(R"(
        union {
            sphere { 0, 1 scale 3 }
            sphere { 0, 1 pigment { rgb <1, 0, 0> } }
            union { sphere { 0, 1 } }
            pigment { checker rgb 1, rgb 0 }
            translate <0, 2, 0>
        }
    )");
    ASSERT_EQ(s.primitives.size(), 3u);
    const Pigment& inherited = s.primitives[0].texture.pigment;
    EXPECT_EQ(inherited.kind, PigmentKind::Checker);
    // The union's texture moved with the union, not with the child's own scale.
    expect_vec(pattern_point(inherited, glm::dvec3(0, 2, 0)), glm::dvec3(0, 0, 0));
    expect_vec(world(s.primitives[0], glm::dvec3(1, 0, 0)), glm::dvec3(3, 2, 0));
    const Pigment& own = s.primitives[1].texture.pigment;
    EXPECT_EQ(own.kind, PigmentKind::Solid);
    expect_vec(own.colour.rgb, glm::dvec3(1, 0, 0));
    // Through a nested union too.
    EXPECT_EQ(s.primitives[2].texture.pigment.kind, PigmentKind::Checker);
}

TEST(Objects, UntexturedObjectsGetPovRaysDefaultTexture) {
    Scene s = parse_ok("sphere { 0, 1 }");
    ASSERT_EQ(s.primitives.size(), 1u);
    const Texture& t = s.primitives[0].texture;
    EXPECT_EQ(t.pigment.kind, PigmentKind::Solid);
    expect_vec(t.pigment.colour.rgb, glm::dvec3(0, 0, 0));  // black
    expect_vec(t.finish.ambient, glm::dvec3(0.1));
    EXPECT_EQ(t.finish.diffuse, 0.6);
}

TEST(Objects, NoShadowAndInverse) {
    Scene s = parse_ok(R"(
        union { sphere { 0, 1 } sphere { 0, 2 inverse } no_shadow }
        sphere { 0, 3 inverse inverse }
    )");
    ASSERT_EQ(s.primitives.size(), 3u);
    EXPECT_TRUE(s.primitives[0].no_shadow);
    EXPECT_TRUE(s.primitives[1].no_shadow);
    EXPECT_TRUE(s.primitives[1].inverse);
    EXPECT_FALSE(s.primitives[0].inverse);
    EXPECT_FALSE(s.primitives[2].inverse);  // inverse toggles, as in POV-Ray
    EXPECT_FALSE(s.primitives[2].no_shadow);
}

TEST(Objects, DeclaredObjectsAreCopies) {
    Scene s = parse_ok(R"(
        #declare Ball = sphere { 0, 1 pigment { rgb 1 } translate y }
        object { Ball scale 2 }
        Ball
        sphere { Ball translate x }
        #declare Pair = union { object { Ball } object { Ball translate x } }
        object { Pair rotate 90 * y }
    )");
    ASSERT_EQ(s.primitives.size(), 5u);
    expect_vec(world(s.primitives[0], glm::dvec3(0, 0, 0)), glm::dvec3(0, 2, 0));
    expect_vec(world(s.primitives[1], glm::dvec3(0, 0, 0)), glm::dvec3(0, 1, 0));
    expect_vec(world(s.primitives[2], glm::dvec3(0, 0, 0)), glm::dvec3(1, 1, 0));
    expect_vec(world(s.primitives[4], glm::dvec3(0, 0, 0)), glm::dvec3(0, 1, -1));
}

TEST(Objects, LightSources) {
    Scene s = parse_ok(R"(
        light_source { <1, 2, 3>, 1 }
        light_source { <0, 0, 0>, rgb <1, 0.5, 0.25> shadowless translate <0, 10, 0> }
        union {
            sphere { 0, 1 }
            light_source { <1, 0, 0>, color rgb 2 }
            rotate 90 * y
        }
    )");
    ASSERT_EQ(s.lights.size(), 3u);
    expect_vec(s.lights[0].location, glm::dvec3(1, 2, 3));
    expect_vec(s.lights[0].colour, glm::dvec3(1, 1, 1));  // a float is grey
    EXPECT_FALSE(s.lights[0].shadowless);
    expect_vec(s.lights[1].location, glm::dvec3(0, 10, 0));
    expect_vec(s.lights[1].colour, glm::dvec3(1, 0.5, 0.25));
    EXPECT_TRUE(s.lights[1].shadowless);
    expect_vec(s.lights[2].location, glm::dvec3(0, 0, -1));
    expect_vec(s.lights[2].colour, glm::dvec3(2));
    EXPECT_EQ(s.lights[0].loc.line, 2);
    EXPECT_EQ(s.primitives.size(), 1u);
}

TEST(Objects, CameraStatement) {
    Scene none = parse_ok("sphere { 0, 1 }");
    EXPECT_FALSE(none.has_camera);
    expect_vec(none.camera.right, glm::dvec3(1.33, 0, 0));
    Scene s = parse_ok(R"(
        #declare Cam = camera { location <0, 0, -5> look_at 0 angle 90 }
        camera { Cam translate <0, 1, 0> }
    )");
    EXPECT_TRUE(s.has_camera);
    expect_vec(s.camera.location, glm::dvec3(0, 1, -5));
    expect_vec(s.camera.direction, glm::dvec3(0, 0, 0.665));
    expect_vec(s.camera.right, glm::dvec3(1.33, 0, 0));
    expect_vec(s.camera.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(s.camera.loc.line, 3);
    EXPECT_NE(parse_error("camera { location 0 look_at 0 }")
                  .find("the camera location and look_at point must be different"),
              std::string::npos);
}

TEST(Objects, UnionOfAnIdentifierWithModifiersIsACopy) {
    Scene s = parse_ok("#declare B = sphere { 0, 1 }\nunion { B translate x }");
    ASSERT_EQ(s.primitives.size(), 1u);
    expect_vec(world(s.primitives[0], glm::dvec3(0, 0, 0)), glm::dvec3(1, 0, 0));
}

}  // namespace
}  // namespace mirage
