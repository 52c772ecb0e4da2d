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

TEST(ObjectTree, CsgChildrenShareItsInteriorAndInteriorTexture) {
    // difference { sphere sphere { interior { ior 1.1 } } interior { ior 1.5 }
    //              interior_texture { ... } } clipped_by { sphere }
    auto own = std::make_shared<Interior>();
    own->ior = 1.1;
    auto glass = std::make_shared<Interior>();
    glass->ior = 1.5;
    ObjectNode second = sphere();
    second.interior = own;
    ObjectNode csg;
    csg.kind = ObjectNode::Kind::Csg;
    csg.csg = CsgKind::Intersection;
    csg.children = {sphere(), second};
    csg.interior = glass;
    csg.interior_texture = solid(0.5);
    csg.clip = {sphere()};

    Scene scene;
    flatten_object(csg, solid(0.0), scene);
    ASSERT_EQ(scene.compounds.size(), 1u);
    ASSERT_EQ(scene.primitives.size(), 3u);
    EXPECT_EQ(scene.primitives[0].interior, glass);  // shared: one medium
    EXPECT_EQ(scene.primitives[1].interior, own);
    for (int i = 0; i < 2; ++i) {
        ASSERT_TRUE(scene.primitives[i].interior_texture);
        EXPECT_EQ(scene.primitives[i].interior_texture->pigment.colour.rgb.x, 0.5);
        EXPECT_EQ(scene.primitives[i].compound, 0);
    }
    // The clipping object is never seen: an interior of its own, no interior_texture.
    ASSERT_TRUE(scene.primitives[2].interior);
    EXPECT_NE(scene.primitives[2].interior, glass);
    EXPECT_FALSE(scene.primitives[2].interior_texture);

    // A CSG without an interior still gives its children one they share.
    csg.interior = nullptr;
    Scene plain;
    flatten_object(csg, solid(0.0), plain);
    ASSERT_TRUE(plain.primitives[0].interior);
    EXPECT_EQ(plain.primitives[0].interior->ior, 0.0);
    EXPECT_EQ(plain.primitives[1].interior, own);
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
