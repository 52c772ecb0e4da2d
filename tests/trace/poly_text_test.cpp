// poly, cubic and quartic, and TrueType text: hits and inside tests against closed forms, and
// POV-Ray's images.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "parsed_scene.h"
#include "scene/parser.h"
#include "shapes_parity_test.h"
#include "trace/scene_accel.h"

namespace mirage {
namespace {

using testing::Parsed;

// The scenes include POV-Ray's include files (fonts, functions.inc).
Parsed build(const std::string& text) {
    return testing::build(text, testing::with_povray_includes());
}

TEST(Poly, AQuadraticPolyIsTheSphereItDescribes) {
    // x^2 + y^2 + z^2 - 0.25 = 0: poly { 2, ... } terms x2 xy xz x y2 yz y z2 z 1.
    const Parsed p = build("poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -0.25> pigment { rgb 1 } }\n");
    const auto t = testing::hit_depths(p, {0, 0, -3}, {0, 0, 1});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.5, 1e-12);
    EXPECT_NEAR(t[1], 3.5, 1e-12);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {0.1, 0.1, 0.1}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {0.6, 0.0, 0.0}));
    EXPECT_EQ(p.accel.unbounded().size(), 1u);  // POV-Ray does not bound polynomials
}

TEST(Poly, AQuarticTorusHasTheTorusRoots) {
    // (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) with R = 1, r = 0.3.
    const Parsed p = build(
        "quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.18, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, "
        "0, 1.82, 0, 0, 0, 0, 1, 0, -2.18, 0, 0.8281> sturm pigment { rgb 1 } }\n");
    const auto t = testing::hit_depths(p, {-3, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 4u);
    EXPECT_NEAR(t[0], 3.0 - 1.3, 1e-7);
    EXPECT_NEAR(t[1], 3.0 - 0.7, 1e-7);
    EXPECT_NEAR(t[2], 3.0 + 0.7, 1e-7);
    EXPECT_NEAR(t[3], 3.0 + 1.3, 1e-7);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {1.0, 0.1, 0.0}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {0.0, 0.0, 0.0}));
}

TEST(Poly, TheWrongNumberOfCoefficientsIsRefused) {
    auto s = parse_scene_text("cubic { <1, 2, 3> }", "scene.pov", ParseOptions{});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(
        s.message().rfind("scene.pov:1:9: 'cubic' of order 3 needs 20 coefficients, got 3", 0), 0u)
        << s.message();
}

TEST(Text, TheFrontFaceOfALetterIsWhereTheFontPutsIt) {
    // "l" of Times: a vertical stem around x = 0.05..0.12 em, from y = 0 to about 0.68 em.
    const Parsed p = build("text { ttf \"timrom.ttf\" \"l\" 0.5, 0 pigment { rgb 1 } }\n");
    const Aabb b = p.accel.finite_bounds();
    ASSERT_FALSE(b.empty());
    EXPECT_NEAR(b.lo.z, 0.0, 1e-3);
    EXPECT_NEAR(b.hi.z, 0.5, 1e-3);
    EXPECT_GT(b.hi.y, 0.6);
    const double x = 0.5 * (b.lo.x + b.hi.x);
    auto h = p.accel.closest_hit({x, 0.3, -2}, {0, 0, 1}, 1e-4, 1e6);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2.0, 1e-4);  // the front face, z = 0 (turned by POV-Ray's 0.001 degrees)
    EXPECT_LT(h->normal.z, -0.999);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), {x, 0.3, 0.25}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {x, 0.3, 0.6}));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), {x + 0.3, 0.3, 0.25}));
}

TEST(Text, AMissingFontIsRefusedWithItsPlace) {
    auto s = parse_scene_text("text { ttf \"no_such_font.ttf\" \"x\" 1, 0 }", "scene.pov",
                              ParseOptions{});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message().rfind("scene.pov:1:12: cannot find the font file 'no_such_font.ttf'", 0),
              0u)
        << s.message();
}

TEST(PolyTextParity, FontsKerningCsgAndQuartics) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const double psnr = testing::parity_psnr("poly_text_parity", "text", R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
text { ttf "timrom.ttf" "AVWay, 3.7!" 0.3, 0 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.5 } translate <-2.6, 1.6, 0> }
text { ttf "cyrvetic" "Mirage gq" 0.5, <0.05, 0.1, 0> pigment { rgb <0.2, 1, 0.3> } rotate y*30 translate <-2.2, 0.2, -1> }
text { ttf "crystal.ttf" "Ok" 1, 0 pigment { rgb <0.3, 0.3, 1> } scale 0.8 rotate <0, -40, 0> translate <1.5, 0.2, -2> }
difference { box { <-0.5, 0, 0>, <0.5, 0.6, 0.2> } text { ttf "povlogo.ttf" "P" 0.4, 0 scale 0.5 translate <-0.2, 0.05, -0.1> } pigment { rgb <1, 1, 0> } translate <0.5, 0, -3> }
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.18, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 2, 0, 1.82, 0, 0, 0, 0, 1, 0, -2.18, 0, 0.8281>
  sturm pigment { rgb <1, 0.6, 0.2> } scale 0.5 translate <2.2, 0.3, 0> }
)",
                                             160, 120);
    EXPECT_GE(psnr, 40.0);
}

}  // namespace
}  // namespace mirage
