#include "scene/object_tree.h"

#include <gtest/gtest.h>

#include "scene/transform.h"

namespace mirage {
namespace {

ObjectNode sphere(std::optional<Texture> texture = std::nullopt) {
    ObjectNode n;
    n.kind = ObjectNode::Kind::Shape;
    n.shape = Sphere{};
    n.texture = std::move(texture);
    return n;
}

Texture solid(double r) {
    Texture t;
    t.pigment.colour.rgb = glm::dvec3(r, 0, 0);
    return t;
}

TEST(ObjectTree, TransformMovesTheTexturesTheObjectAlreadyHas) {
    ObjectNode textured = sphere(solid(1));
    transform_object(textured, make_translation(glm::dvec3(1, 0, 0)));
    EXPECT_EQ(transform_point(textured.texture->pigment.transform, glm::dvec3(0)),
              glm::dvec3(1, 0, 0));
    EXPECT_EQ(transform_point(textured.transform, glm::dvec3(0)), glm::dvec3(1, 0, 0));
}

TEST(ObjectTree, FlattenInheritsFromTheNearestTexturedUnion) {
    ObjectNode inner;
    inner.kind = ObjectNode::Kind::Union;
    inner.children = {sphere(), sphere(solid(0.25))};
    ObjectNode outer;
    outer.kind = ObjectNode::Kind::Union;
    outer.children = {inner, sphere()};
    outer.texture = solid(0.5);
    outer.no_shadow = true;
    ObjectNode light;
    light.kind = ObjectNode::Kind::Light;
    light.light.location = glm::dvec3(1, 2, 3);
    outer.children.push_back(light);

    std::vector<Primitive> primitives;
    std::vector<PointLight> lights;
    flatten_object(outer, solid(0.0), primitives, lights);
    ASSERT_EQ(primitives.size(), 3u);
    EXPECT_EQ(primitives[0].texture.pigment.colour.rgb.x, 0.5);
    EXPECT_EQ(primitives[1].texture.pigment.colour.rgb.x, 0.25);
    EXPECT_EQ(primitives[2].texture.pigment.colour.rgb.x, 0.5);
    for (const Primitive& p : primitives) EXPECT_TRUE(p.no_shadow);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_EQ(lights[0].location, glm::dvec3(1, 2, 3));

    primitives.clear();
    flatten_object(sphere(), solid(0.75), primitives, lights);
    EXPECT_EQ(primitives[0].texture.pigment.colour.rgb.x, 0.75);  // the default texture
}

TEST(ObjectTree, OpacityAndDefaultGradientMap) {
    Texture t = solid(1);
    EXPECT_TRUE(texture_is_opaque(t));
    t.pigment.kind = PigmentKind::Checker;
    t.pigment.checker[1].transmit = 0.5;
    EXPECT_FALSE(texture_is_opaque(t));
    Pigment g;
    g.kind = PigmentKind::Gradient;
    finish_pigment(g);
    ASSERT_EQ(g.colour_map.size(), 2u);
    EXPECT_EQ(g.colour_map[1].colour.rgb, glm::dvec3(1));
}

}  // namespace
}  // namespace mirage
