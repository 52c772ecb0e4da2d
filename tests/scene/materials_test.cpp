// Textures, pigments, finishes, colour maps, and the scene-wide items (background,
// sky_sphere, global_settings).
#include <gtest/gtest.h>

#include "parse_helpers.h"
#include "scene/transform.h"

namespace mirage {
namespace {

using testing::expect_vec;
using testing::parse_error;
using testing::parse_ok;

const Texture& only_texture(const Scene& s) {
    EXPECT_EQ(s.primitives.size(), 1u);
    static Texture none;
    return s.primitives.empty() ? none : s.primitives[0].texture;
}

TEST(Pigments, SolidColours) {
    Texture t = only_texture(parse_ok("sphere { 0, 1 pigment { color rgbf <1, 0.5, 0, 0.3> } }"));
    EXPECT_EQ(t.pigment.kind, PigmentKind::Solid);
    expect_vec(t.pigment.colour.rgb, glm::dvec3(1, 0.5, 0));
    EXPECT_DOUBLE_EQ(t.pigment.colour.filter, 0.3);
    // POV-Ray's quirk: a float colour sets filter and transmit too.
    Texture g = only_texture(parse_ok("sphere { 0, 1 pigment { color 0.5 } }"));
    EXPECT_EQ(g.pigment.colour.transmit, 0.5);
}

TEST(Pigments, CheckerWithPovRaysDefaultColours) {
    Texture two =
        only_texture(parse_ok("sphere { 0, 1 pigment { checker rgb 1, rgb <1, 0, 0> } }"));
    EXPECT_EQ(two.pigment.kind, PigmentKind::Checker);
    expect_vec(two.pigment.checker[0].rgb, glm::dvec3(1, 1, 1));
    expect_vec(two.pigment.checker[1].rgb, glm::dvec3(1, 0, 0));
    Texture none = only_texture(parse_ok("sphere { 0, 1 pigment { checker } }"));
    expect_vec(none.pigment.checker[0].rgb, glm::dvec3(0, 0, 1));  // blue
    expect_vec(none.pigment.checker[1].rgb, glm::dvec3(0, 1, 0));  // green
    Texture one = only_texture(parse_ok("sphere { 0, 1 pigment { checker color rgb 0.2 } }"));
    expect_vec(one.pigment.checker[0].rgb, glm::dvec3(0.2));
    expect_vec(one.pigment.checker[1].rgb, glm::dvec3(0, 1, 0));
}

TEST(Pigments, GradientWithColourMap) {
    Texture t = only_texture(parse_ok(R"(
        sphere { 0, 1 pigment {
            gradient <0, 2, 0>
            color_map { [0 color rgb 0] [0.5, 0.75 color rgb 1 color rgb <1, 0, 0>] [1 rgb 1] }
            scale 3
        } }
    )"));
    const Pigment& p = t.pigment;
    EXPECT_EQ(p.kind, PigmentKind::Gradient);
    expect_vec(p.gradient_axis, glm::dvec3(0, 1, 0));  // normalised, as POV-Ray does
    ASSERT_EQ(p.colour_map.size(), 4u);
    EXPECT_EQ(p.colour_map[1].position, 0.5);
    EXPECT_EQ(p.colour_map[2].position, 0.75);
    expect_vec(p.colour_map[2].colour.rgb, glm::dvec3(1, 0, 0));
    expect_vec(inverse_transform_point(p.transform, glm::dvec3(0, 3, 0)), glm::dvec3(0, 1, 0));
}

TEST(Pigments, GradientWithoutMapGetsTheDefaultBlackToWhite) {
    Texture t = only_texture(parse_ok("sphere { 0, 1 pigment { gradient x } }"));
    ASSERT_EQ(t.pigment.colour_map.size(), 2u);
    EXPECT_EQ(t.pigment.colour_map[0].position, 0.0);
    expect_vec(t.pigment.colour_map[0].colour.rgb, glm::dvec3(0));
    EXPECT_EQ(t.pigment.colour_map[1].position, 1.0);
    expect_vec(t.pigment.colour_map[1].colour.rgb, glm::dvec3(1));
}

TEST(Pigments, IdentifiersAndDeclaredMaps) {
    Scene s = parse_ok(R"(
        #declare M = color_map { [0 rgb 1] [1 rgb 0] }
        #declare P = pigment { gradient y color_map { M } }
        sphere { 0, 1 pigment { P scale 2 } }
        sphere { 0, 1 pigment { P } }
    )");
    ASSERT_EQ(s.primitives.size(), 2u);
    const Pigment& scaled = s.primitives[0].texture.pigment;
    EXPECT_EQ(scaled.kind, PigmentKind::Gradient);
    ASSERT_EQ(scaled.colour_map.size(), 2u);
    expect_vec(scaled.colour_map[0].colour.rgb, glm::dvec3(1));
    expect_vec(inverse_transform_point(scaled.transform, glm::dvec3(0, 2, 0)), glm::dvec3(0, 1, 0));
    expect_vec(
        inverse_transform_point(s.primitives[1].texture.pigment.transform, glm::dvec3(0, 2, 0)),
        glm::dvec3(0, 2, 0));
}

TEST(Pigments, ColourMapOnAPlainColourIsAnError) {
    EXPECT_NE(parse_error("sphere { 0, 1 pigment { rgb 1 color_map { [0 rgb 0] } } }")
                  .find("color_map needs a pattern such as gradient"),
              std::string::npos);
}

TEST(Finishes, ItemsAndDefaults) {
    Texture t = only_texture(parse_ok(R"(
        sphere { 0, 1 finish {
            ambient 0.2 emission rgb <0, 0, 1> diffuse 0.7 brilliance 2
            specular 0.3 roughness 0.01 phong 0.5 phong_size 80 reflection 0.25
        } }
    )"));
    const Finish& f = t.finish;
    expect_vec(f.ambient, glm::dvec3(0.2));
    expect_vec(f.emission, glm::dvec3(0, 0, 1));
    EXPECT_EQ(f.diffuse, 0.7);
    EXPECT_EQ(f.brilliance, 2.0);
    EXPECT_EQ(f.specular, 0.3);
    EXPECT_EQ(f.roughness, 0.01);
    EXPECT_EQ(f.phong, 0.5);
    EXPECT_EQ(f.phong_size, 80.0);
    expect_vec(f.reflection, glm::dvec3(0.25));
    Texture c = only_texture(parse_ok(
        "sphere { 0, 1 finish { ambient rgb <0.1, 0.2, 0.3> reflection { rgb <1, 0.5, 0> } } }"));
    expect_vec(c.finish.ambient, glm::dvec3(0.1, 0.2, 0.3));
    expect_vec(c.finish.reflection, glm::dvec3(1, 0.5, 0));
}

TEST(Finishes, AlbedoRescalesAsPovRayDoes) {
    Texture t = only_texture(parse_ok(
        "sphere { 0, 1 finish { diffuse albedo 0.8 brilliance 3 phong albedo 1 phong_size 9 } }"));
    EXPECT_DOUBLE_EQ(t.finish.diffuse, 0.8 * (3.0 + 1.0) / 2.0);
    EXPECT_DOUBLE_EQ(t.finish.phong, 1.0 * (9.0 + 1.0) / 2.0);
}

TEST(Finishes, DeclaredFinishesAreModifiedCopies) {
    Scene s = parse_ok(R"(
        #declare F = finish { phong 1 }
        sphere { 0, 1 finish { F ambient 0 } }
        sphere { 0, 1 finish { F } }
    )");
    ASSERT_EQ(s.primitives.size(), 2u);
    EXPECT_EQ(s.primitives[0].texture.finish.phong, 1.0);
    expect_vec(s.primitives[0].texture.finish.ambient, glm::dvec3(0));
    expect_vec(s.primitives[1].texture.finish.ambient, glm::dvec3(0.1));
}

TEST(Textures, IdentifiersPigmentAndFinishInside) {
    Scene s = parse_ok(R"(
        #declare P = pigment { rgb <0, 1, 0> }
        #declare F = finish { diffuse 0.9 }
        #declare T = texture { P F translate x }
        sphere { 0, 1 texture { T } }
        sphere { 0, 1 texture { pigment { P } finish { F } } }
    )");
    ASSERT_EQ(s.primitives.size(), 2u);
    expect_vec(s.primitives[0].texture.pigment.colour.rgb, glm::dvec3(0, 1, 0));
    EXPECT_EQ(s.primitives[0].texture.finish.diffuse, 0.9);
    expect_vec(transform_point(s.primitives[0].texture.pigment.transform, glm::dvec3(0)),
               glm::dvec3(1, 0, 0));
    EXPECT_EQ(s.primitives[1].texture.finish.diffuse, 0.9);
}

TEST(Textures, PigmentAfterATextureChangesThatTexture) {
    Texture t =
        only_texture(parse_ok("sphere { 0, 1 texture { pigment { checker } finish { phong 1 } } "
                              "pigment { rgb 1 } }"));
    EXPECT_EQ(t.pigment.kind, PigmentKind::Solid);
    EXPECT_EQ(t.finish.phong, 1.0);
}

TEST(Textures, AnOpaqueLayerReplacesATransparentOneIsRefused) {
    Texture t = only_texture(parse_ok(
        "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgb <1, 0, 0> } } }"));
    expect_vec(t.pigment.colour.rgb, glm::dvec3(1, 0, 0));
    EXPECT_NE(parse_error("sphere { 0, 1 texture { pigment { rgb 1 } } "
                          "texture { pigment { rgbt <1, 0, 0, 0.5> } } }")
                  .find("unsupported texture layered over another with filter or transmit"),
              std::string::npos);
}

TEST(SceneItems, BackgroundSkySphereGlobalSettings) {
    Scene s = parse_ok(R"(
        global_settings { assumed_gamma 2.2 max_trace_level 300 ambient_light rgb <0.5, 0.5, 1> }
        background { rgbt <0.1, 0.2, 0.3, 0.4> }
        sky_sphere {
            pigment { gradient y color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } }
            pigment { rgbt 1 }
            emission 0.5
            rotate 90 * x
        }
    )");
    EXPECT_EQ(s.global.assumed_gamma, 2.2);
    EXPECT_EQ(s.global.max_trace_level, 256);  // POV-Ray's limit
    expect_vec(s.global.ambient_light, glm::dvec3(0.5, 0.5, 1));
    expect_vec(s.background.rgb, glm::dvec3(0.1, 0.2, 0.3));
    EXPECT_DOUBLE_EQ(s.background.transmit, 0.4);
    ASSERT_TRUE(s.sky_sphere.has_value());
    ASSERT_EQ(s.sky_sphere->pigments.size(), 2u);
    EXPECT_EQ(s.sky_sphere->pigments[0].kind, PigmentKind::Gradient);
    EXPECT_EQ(s.sky_sphere->pigments[1].colour.transmit, 1.0);
    expect_vec(s.sky_sphere->emission, glm::dvec3(0.5));
    expect_vec(transform_point(s.sky_sphere->transform, glm::dvec3(0, 1, 0)), glm::dvec3(0, 0, 1));
    // The pigments keep their own transforms.
    expect_vec(transform_point(s.sky_sphere->pigments[0].transform, glm::dvec3(0, 1, 0)),
               glm::dvec3(0, 1, 0));
}

TEST(SceneItems, DeclaredSkySphereAndOldDefault) {
    Scene s = parse_ok(R"(
        #declare Sky = sky_sphere { pigment { rgb <0, 0, 1> } }
        sky_sphere { Sky rotate 90 * y }
        default { finish { ambient 0 } }
        sphere { 0, 1 }
    )");
    ASSERT_TRUE(s.sky_sphere.has_value());
    ASSERT_EQ(s.sky_sphere->pigments.size(), 1u);
    expect_vec(s.sky_sphere->pigments[0].colour.rgb, glm::dvec3(0, 0, 1));
    expect_vec(transform_point(s.sky_sphere->transform, glm::dvec3(1, 0, 0)), glm::dvec3(0, 0, -1));
    expect_vec(s.primitives.at(0).texture.finish.ambient, glm::dvec3(0));
}

TEST(SceneItems, SrgbColoursNeedAssumedGamma) {
    EXPECT_NE(parse_error("background { srgb 0.5 }").find("needs assumed_gamma"),
              std::string::npos);
    Scene s = parse_ok("global_settings { assumed_gamma 1.0 } background { srgb <1, 0.5, 0> }");
    // The sRGB transfer function: 0.5 decodes to ((0.5 + 0.055) / 1.055)^2.4.
    EXPECT_NEAR(s.background.rgb.y, 0.21404114048223255, 1e-15);
    EXPECT_EQ(s.background.rgb.x, 1.0);
}

}  // namespace
}  // namespace mirage
