// Textures, pigments, finishes, colour maps, and the scene-wide items (background,
// sky_sphere, global_settings).
#include <gtest/gtest.h>

#include <cmath>

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

TEST(Textures, LayersGoOnTopInOrder) {
    // POV-Ray's Link_Textures: each new texture is laid over the ones before it.
    Texture t = only_texture(parse_ok(
        "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } } "
        "texture { pigment { rgbf <0, 0, 1, 0.25> } } }"));
    expect_vec(t.pigment.colour.rgb, glm::dvec3(0, 0, 1));
    ASSERT_EQ(t.layers_below.size(), 2u);
    expect_vec(t.layers_below[0].pigment.colour.rgb, glm::dvec3(1, 0, 0));
    EXPECT_EQ(t.layers_below[0].pigment.colour.transmit, 0.5);
    expect_vec(t.layers_below[1].pigment.colour.rgb, glm::dvec3(1));
    // A declared layered texture keeps its layers, and goes on top of the object's.
    Texture d = only_texture(parse_ok(R"(
        #declare Two = texture { pigment { rgb 0.5 } } texture { pigment { rgbt <0, 1, 0, 0.7> } }
        sphere { 0, 1 texture { pigment { rgb 1 } } texture { Two } }
    )"));
    expect_vec(d.pigment.colour.rgb, glm::dvec3(0, 1, 0));
    ASSERT_EQ(d.layers_below.size(), 2u);
    expect_vec(d.layers_below[0].pigment.colour.rgb, glm::dvec3(0.5));
    expect_vec(d.layers_below[1].pigment.colour.rgb, glm::dvec3(1));
    EXPECT_NE(parse_error("sphere { 0, 1 texture { checker texture { } texture { } } "
                          "texture { pigment { rgb 1 } } }")
                  .find("cannot layer over a patterned texture"),
              std::string::npos);
}

TEST(Patterns, TypesWavesAndModifiers) {
    Texture t = only_texture(parse_ok(R"(
        sphere { 0, 1 pigment {
            wood frequency 2 phase 0.25 sine_wave turbulence <0.1, 0.2, 0.3> octaves 3
            omega 0.7 lambda 2.5 noise_generator 3 scale 2
        } }
    )"));
    const Pigment& p = t.pigment;
    EXPECT_EQ(p.kind, PatternKind::Wood);
    EXPECT_EQ(p.wave, WaveType::Sine);
    EXPECT_EQ(p.frequency, 2.0);
    EXPECT_EQ(p.phase, 0.25);
    EXPECT_EQ(p.noise_generator, 3);
    ASSERT_TRUE(p.turbulence.has_value());
    expect_vec(p.turbulence->amount, glm::dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(p.turbulence->octaves, 3);
    EXPECT_EQ(p.turbulence->omega, 0.7);
    EXPECT_EQ(p.turbulence->lambda, 2.5);
    // wood and marble default to a triangle wave, spirals too; the others to a ramp.
    EXPECT_EQ(only_texture(parse_ok("sphere { 0, 1 pigment { marble } }")).pigment.wave,
              WaveType::Triangle);
    EXPECT_EQ(only_texture(parse_ok("sphere { 0, 1 pigment { spiral2 5 } }")).pigment.arms, 5);
    EXPECT_EQ(only_texture(parse_ok("sphere { 0, 1 pigment { bozo } }")).pigment.wave,
              WaveType::Ramp);
    // poly_wave takes an optional exponent.
    EXPECT_EQ(
        only_texture(parse_ok("sphere { 0, 1 pigment { bozo poly_wave 3 } }")).pigment.exponent,
        3.0);
}

TEST(Patterns, ListPatternsTakeColoursAndDefaults) {
    // hexagon with one colour: the others from POV-Ray's default list (blue, green, red).
    Texture h = only_texture(parse_ok("sphere { 0, 1 pigment { hexagon rgb <1, 1, 0> } }"));
    ASSERT_EQ(h.pigment.colour_map.size(), 3u);
    expect_vec(h.pigment.colour_map[0].colour.rgb, glm::dvec3(1, 1, 0));
    expect_vec(h.pigment.colour_map[1].colour.rgb, glm::dvec3(0, 1, 0));
    expect_vec(h.pigment.colour_map[2].colour.rgb, glm::dvec3(1, 0, 0));
    EXPECT_EQ(h.pigment.colour_map[2].position, 2.0);
    EXPECT_EQ(h.pigment.frequency, 0.0);  // list patterns have no wave
    // brick: its colours, size and mortar (POV-Ray keeps mortar - 2 EPSILON).
    Texture b =
        only_texture(parse_ok("sphere { 0, 1 pigment { brick rgb 0.5, rgb <1, 0, 0> brick_size <2, "
                              "1, 1> mortar 0.1 } }"));
    EXPECT_EQ(b.pigment.kind, PatternKind::Brick);
    expect_vec(b.pigment.brick_size, glm::dvec3(2, 1, 1));
    EXPECT_DOUBLE_EQ(b.pigment.mortar, 0.1 - 2e-10);
    // checker of pigments is a pigment map with entries at 0 and 1.
    Texture c = only_texture(
        parse_ok("sphere { 0, 1 pigment { checker pigment { rgb 1 } pigment { bozo } } }"));
    ASSERT_EQ(c.pigment.pigment_map.size(), 2u);
    EXPECT_EQ(c.pigment.pigment_map[1].position, 1.0);
    EXPECT_EQ(c.pigment.pigment_map[1].pigment->kind, PatternKind::Bozo);
    EXPECT_NE(parse_error("sphere { 0, 1 pigment { checker color_map { [0 rgb 1] } } }")
                  .find("cannot use color_map with this pattern type"),
              std::string::npos);
}

TEST(Patterns, WarpsGoFirstInTheChain) {
    // POV-Ray inserts each warp at the head of the chain, before the transforms given so
    // far; classic turbulence stays last.
    Texture t = only_texture(parse_ok(R"(
        sphere { 0, 1 pigment { bozo scale 2 warp { repeat x * 3 flip y } rotate y * 90
                                turbulence 0.5 warp { turbulence 0.2 octaves 2 } } }
    )"));
    const Pigment& p = t.pigment;
    EXPECT_EQ(p.transform.matrix, glm::dmat4(1.0));
    ASSERT_EQ(p.warps.size(), 4u);
    EXPECT_EQ(p.warps[0].kind, Warp::Kind::Turbulence);
    EXPECT_EQ(p.warps[0].turbulence.octaves, 2);
    EXPECT_EQ(p.warps[1].kind, Warp::Kind::Transform);  // rotate
    expect_vec(transform_point(p.warps[1].transform, glm::dvec3(1, 0, 0)), glm::dvec3(0, 0, -1));
    EXPECT_EQ(p.warps[2].kind, Warp::Kind::Repeat);
    EXPECT_EQ(p.warps[2].axis, 0);
    EXPECT_EQ(p.warps[2].width, 3.0);
    expect_vec(p.warps[2].flip, glm::dvec3(1, -1, 1));
    EXPECT_EQ(p.warps[3].kind, Warp::Kind::Transform);  // scale
    ASSERT_TRUE(p.turbulence.has_value());
    expect_vec(p.turbulence->amount, glm::dvec3(0.5));
    EXPECT_NE(parse_error("sphere { 0, 1 pigment { bozo warp { repeat <1, 1, 0> } } }")
                  .find("repeat goes along one axis only"),
              std::string::npos);
}

TEST(Normals, PatternsBumpSizeAndMaps) {
    Texture t = only_texture(parse_ok(R"(
        #declare N = normal { granite 0.3 scale 2 }
        sphere { 0, 1 normal { bumps, 0.7 accuracy 0.01 } }
    )"));
    ASSERT_TRUE(t.normal.has_value());
    EXPECT_EQ(t.normal->kind, PatternKind::Bumps);
    EXPECT_EQ(t.normal->amount, 0.7);
    EXPECT_EQ(t.normal->delta, 0.01);
    Texture d = only_texture(parse_ok(R"(
        #declare N = normal { granite 0.3 scale 2 }
        sphere { 0, 1 texture { normal { N 0.5 } } }
    )"));
    ASSERT_TRUE(d.normal.has_value());
    EXPECT_EQ(d.normal->kind, PatternKind::Granite);
    EXPECT_EQ(d.normal->amount, 0.5);  // the identifier's normal with a new bump size
    expect_vec(inverse_transform_point(d.normal->transform, glm::dvec3(2, 0, 0)),
               glm::dvec3(1, 0, 0));
    Texture m = only_texture(parse_ok(R"(
        sphere { 0, 1 normal { gradient x normal_map { [0 bumps 0.2] [1 dents 0.4] }
                               slope_map { [0 <0, 1>] [1, <1, 0>] } } }
    )"));
    ASSERT_EQ(m.normal->normal_map.size(), 2u);
    EXPECT_EQ(m.normal->normal_map[1].normal->kind, PatternKind::Dents);
    EXPECT_EQ(m.normal->normal_map[1].normal->amount, 0.4);
    ASSERT_EQ(m.normal->slope_map.size(), 2u);
    EXPECT_EQ(m.normal->slope_map[1].point_slope, glm::dvec2(1, 0));
}

TEST(Textures, PatternedTexturesAndTiles) {
    Texture t = only_texture(parse_ok(R"(
        sphere { 0, 1 texture { gradient y texture_map {
            [0 pigment { rgb 1 }] [1 pigment { rgb 0 } finish { phong 1 }] } scale 3 } }
    )"));
    EXPECT_EQ(t.pattern.kind, PatternKind::Gradient);
    ASSERT_EQ(t.map.size(), 2u);
    EXPECT_EQ(t.map[1].texture->finish.phong, 1.0);
    expect_vec(inverse_transform_point(t.pattern.transform, glm::dvec3(0, 3, 0)),
               glm::dvec3(0, 1, 0));
    Texture tiles =
        only_texture(parse_ok("sphere { 0, 1 texture { tiles { texture { pigment { rgb 1 } } tile2 "
                              "texture { pigment { rgb 0 } } } } }"));
    EXPECT_EQ(tiles.pattern.kind, PatternKind::Checker);
    ASSERT_EQ(tiles.map.size(), 2u);
    expect_vec(tiles.map[1].texture->pigment.colour.rgb, glm::dvec3(1));  // the first tile at 1
    EXPECT_NE(parse_error("sphere { 0, 1 texture { gradient y } }")
                  .find("a patterned texture needs a texture_map"),
              std::string::npos);
}

TEST(Finishes, ReflectionBlockAndTheOldInteriorItems) {
    Texture t = only_texture(parse_ok(R"(
        sphere { 0, 1 finish {
            reflection { 0.1, 0.8 fresnel falloff 2 exponent 0.5 metallic 0.3 }
            metallic irid { 0.3 thickness 0.2 turbulence 0.1 } crand 0.05 conserve_energy
            diffuse 0.5, 0.2 ior 1.5 caustics 0.4 refraction 1
        } }
    )"));
    const Finish& f = t.finish;
    expect_vec(f.reflection, glm::dvec3(0.8));
    ASSERT_TRUE(f.reflection_min.has_value());
    expect_vec(*f.reflection_min, glm::dvec3(0.1));
    EXPECT_TRUE(f.reflection_fresnel);
    EXPECT_EQ(f.reflection_falloff, 2.0);
    EXPECT_EQ(f.reflection_exponent, 2.0);  // POV-Ray stores 1 / exponent
    EXPECT_EQ(f.reflection_metallic, 0.3);
    EXPECT_EQ(f.metallic, 1.0);
    EXPECT_EQ(f.irid, 0.3);
    EXPECT_EQ(f.irid_thickness, 0.2);
    EXPECT_EQ(f.irid_turbulence, 0.1);
    EXPECT_EQ(f.crand, 0.05);
    EXPECT_TRUE(f.conserve_energy);
    EXPECT_EQ(f.diffuse_back, 0.2);
    EXPECT_EQ(f.ior, 1.5);
    // fresnel without a second colour reflects from 0 at normal incidence.
    Texture z = only_texture(parse_ok("sphere { 0, 1 finish { reflection { 0.9 fresnel } } }"));
    expect_vec(*z.finish.reflection_min, glm::dvec3(0));
    expect_vec(z.finish.reflection, glm::dvec3(0.9));
}

TEST(Interiors, MaterialsAndUnionsShareOne) {
    Scene s = parse_ok(R"(
        #declare I = interior { ior 1.33 fade_distance 2 fade_power 1001 fade_color rgb <0, 0, 1> }
        #declare M = material { texture { pigment { rgbf <1, 1, 1, 0.9> } } interior { I caustics 1 } }
        sphere { 0, 1 material { M } }
        union { sphere { 0, 1 } sphere { x, 1 } interior { ior 2 } }
        sphere { 0, 1 hollow }
    )");
    ASSERT_EQ(s.primitives.size(), 4u);
    const Interior& glass = *s.primitives[0].interior;
    EXPECT_EQ(glass.ior, 1.33);
    EXPECT_EQ(glass.fade_power, 1001.0);
    expect_vec(glass.fade_colour, glm::dvec3(0, 0, 1));
    EXPECT_EQ(glass.caustics, 45.0);  // POV-Ray scales caustics by 45
    EXPECT_EQ(s.primitives[0].texture.pigment.colour.filter, 0.9);
    // The union's children are one medium: the same interior.
    EXPECT_EQ(s.primitives[1].interior, s.primitives[2].interior);
    EXPECT_EQ(s.primitives[1].interior->ior, 2.0);
    EXPECT_TRUE(s.primitives[3].interior->hollow);
    EXPECT_NE(s.primitives[3].interior, s.primitives[0].interior);
}

TEST(Interiors, InteriorTexturesOnObjectsMaterialsAndUnions) {
    Scene s = parse_ok(R"(
        #declare M = material { texture { pigment { rgb 1 } }
                                interior_texture { pigment { rgb <1, 0, 0> } } }
        sphere { 0, 1 material { M } }
        cylinder { 0, y, 1 open pigment { rgb 0.5 } interior_texture { pigment { rgb <0, 0, 1> } } }
        union { sphere { 0, 1 } sphere { x, 1 interior_texture { pigment { rgb <0, 1, 0> } } }
                interior_texture { pigment { rgb 0.25 } } }
        sphere { 0, 1 }
    )");
    ASSERT_EQ(s.primitives.size(), 5u);
    ASSERT_TRUE(s.primitives[0].interior_texture);
    expect_vec(s.primitives[0].interior_texture->pigment.colour.rgb, glm::dvec3(1, 0, 0));
    expect_vec(s.primitives[0].texture.pigment.colour.rgb, glm::dvec3(1, 1, 1));
    ASSERT_TRUE(s.primitives[1].interior_texture);
    expect_vec(s.primitives[1].interior_texture->pigment.colour.rgb, glm::dvec3(0, 0, 1));
    // A union's interior_texture goes to the children without one of their own.
    ASSERT_TRUE(s.primitives[2].interior_texture);
    expect_vec(s.primitives[2].interior_texture->pigment.colour.rgb, glm::dvec3(0.25));
    ASSERT_TRUE(s.primitives[3].interior_texture);
    expect_vec(s.primitives[3].interior_texture->pigment.colour.rgb, glm::dvec3(0, 1, 0));
    EXPECT_FALSE(s.primitives[4].interior_texture);
}

TEST(Lights, SpotsCylindersAreasAndFade) {
    Scene s = parse_ok(R"(
        light_source { <0, 10, 0>, 1 spotlight point_at <0, 0, 0> radius 20 falloff 30
                       tightness 5 fade_distance 4 fade_power 2 }
        light_source { <0, 10, 0>, 1 cylinder radius 1 falloff 2 point_at 0 }
        light_source { <0, 10, 0>, 1 area_light x, z, 3, 5 adaptive 1 circular orient
                       translate x }
    )");
    ASSERT_EQ(s.lights.size(), 3u);
    const PointLight& spot = s.lights[0];
    EXPECT_EQ(spot.kind, PointLight::Kind::Spot);
    EXPECT_DOUBLE_EQ(spot.radius, std::cos(20 * M_PI / 180));  // POV-Ray keeps the cosines
    EXPECT_DOUBLE_EQ(spot.falloff, std::cos(30 * M_PI / 180));
    EXPECT_EQ(spot.tightness, 5.0);
    EXPECT_EQ(spot.fade_power, 2.0);
    const PointLight& cyl = s.lights[1];
    EXPECT_EQ(cyl.kind, PointLight::Kind::Cylinder);
    EXPECT_TRUE(cyl.parallel);
    EXPECT_EQ(cyl.radius, 1.0);
    const PointLight& area = s.lights[2];
    EXPECT_TRUE(area.area_light);
    EXPECT_EQ(area.size1, 3);
    EXPECT_EQ(area.size2, 5);
    EXPECT_EQ(area.adaptive, 1);
    EXPECT_TRUE(area.circular);
    expect_vec(area.location, glm::dvec3(1, 10, 0));
    expect_vec(area.axis1, glm::dvec3(1, 0, 0));  // directions do not move
    EXPECT_NE(parse_error("light_source { 0, 1 radius 3 }").find("standard light source"),
              std::string::npos);
}

TEST(SceneItems, FogsAndGlobalSettings) {
    ParseOptions lenient;  // #version 3.1 is outside the language the parser follows
    lenient.strict = false;
    Scene s = parse_ok(R"(
        #version 3.1;
        global_settings { number_of_waves 4 irid_wavelength rgb <0.2, 0.3, 0.4> adc_bailout 0.01 }
        fog { distance 20 color rgbt <0.5, 0.5, 0.5, 0.2> }
        fog { fog_type 2 distance 5 fog_alt 1 fog_offset 0.5 up <0, 2, 0> turbulence 0.3 rgb 1 }
    )",
                       lenient);
    ASSERT_EQ(s.fogs.size(), 2u);
    EXPECT_EQ(s.fogs[0].distance, 20.0);
    EXPECT_EQ(s.fogs[0].colour.transmit, 0.2);
    EXPECT_EQ(s.fogs[1].type, 2);
    expect_vec(s.fogs[1].up, glm::dvec3(0, 1, 0));  // normalised
    ASSERT_TRUE(s.fogs[1].turbulence.has_value());
    EXPECT_EQ(s.global.number_of_waves, 4);
    EXPECT_EQ(s.global.adc_bailout, 0.01);
    // Before #version 3.5 the default noise is generator 1.
    EXPECT_EQ(s.global.noise_generator, 1);
    EXPECT_EQ(parse_ok("sphere { 0, 1 }").global.noise_generator, 2);
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
