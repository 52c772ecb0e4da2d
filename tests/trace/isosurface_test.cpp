// Isosurfaces: hits, normals and inside tests against closed forms, the parser's errors and
// warnings, and POV-Ray's image.
#include "shapes/isosurface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "parsed_scene.h"
#include "scene/parser.h"
#include "shapes_parity_test.h"
#include "patterns/noise.h"
#include "trace/scene_accel.h"

namespace mirage {
namespace {

using testing::Parsed;

// The scenes include POV-Ray's include files (fonts, functions.inc).
Parsed build(const std::string& text) {
    return testing::build(text, testing::with_povray_includes());
}

std::string parse_error(const std::string& text) {
    auto s = parse_scene_text(text, "scene.pov", testing::with_povray_includes());
    return s.ok() ? std::string("(no error)") : s.message();
}

TEST(Isosurface, TheRootLiesWithinAccuracyBeyondTheSurface) {
    // |p| - 1 has slope 1 along the ray: the bisection stops at the first end of an interval
    // shorter than `accuracy` where the function is below the threshold.
    const Parsed p = build(
        "isosurface { function { sqrt(x*x + y*y + z*z) - 1 } contained_by { box { -2, 2 } } "
        "accuracy 0.0001 }");
    const glm::dvec3 o(0.3, 0.2, -5);
    const auto h = testing::sorted_hits(p, o, glm::dvec3(0, 0, 1));
    ASSERT_EQ(h.size(), 1u);  // max_trace 1: the first root only
    const double exact = 5.0 - std::sqrt(1.0 - 0.09 - 0.04);
    EXPECT_GE(h[0].t, exact);
    EXPECT_LT(h[0].t, exact + 1e-4);
    EXPECT_EQ(h[0].part, 0);
    const glm::dvec3 at = o + h[0].t * glm::dvec3(0, 0, 1);
    const glm::dvec3 n = shape_normal(p.accel.shape(0), at, h[0]);
    EXPECT_NEAR(glm::dot(n, glm::normalize(at)), 1.0, 1e-4);
    EXPECT_TRUE(inside_shape(p.accel.shape(0), glm::dvec3(0.5, 0, 0)));
    EXPECT_FALSE(inside_shape(p.accel.shape(0), glm::dvec3(1.5, 0, 0)));
}

TEST(Isosurface, AllIntersectionsFindsTheWayOutInTheTransformedSphere) {
    const Parsed p = build(
        "#include \"functions.inc\"\n"
        "isosurface { function { f_sphere(x, y, z, 1) } contained_by { sphere { 0, 3 } } "
        "all_intersections scale 2 translate <0, 0, 1> }");
    const auto h = testing::sorted_hits(p, glm::dvec3(0, 0, -5), glm::dvec3(0, 0, 1));
    ASSERT_EQ(h.size(), 2u);
    // In its own space the sphere has radius 1 and the search `accuracy` 0.001 along a ray
    // whose depths are world depths (twice the local ones).
    EXPECT_GE(h[0].t, 4.0);
    EXPECT_LT(h[0].t, 4.001);
    EXPECT_GE(h[1].t, 8.0);
    EXPECT_LT(h[1].t, 8.001);
    // A ray missing the surface but crossing the container finds nothing.
    EXPECT_TRUE(testing::sorted_hits(p, glm::dvec3(2.5, 0, -5), glm::dvec3(0, 0, 1)).empty());
    EXPECT_FALSE(inside_shape(p.accel.shape(0), glm::dvec3(0, 0, 3.2)));
    EXPECT_TRUE(inside_shape(p.accel.shape(0), glm::dvec3(0, 0, 2.8)));
}

TEST(Isosurface, AClosedContainerShowsWhereItCutsTheInside) {
    const std::string body = "function { y - 0.5 } contained_by { box { -1, 1 } }";
    const Parsed closed = build("isosurface { " + body + " }");
    const Parsed open = build("isosurface { " + body + " open }");
    // From the side below y = 0.5 the ray enters the box inside the function: the box's
    // side is the surface, with its own normal.
    auto h = testing::sorted_hits(closed, glm::dvec3(-5, 0, 0), glm::dvec3(1, 0, 0));
    ASSERT_EQ(h.size(), 1u);
    EXPECT_DOUBLE_EQ(h[0].t, 4.0);
    EXPECT_EQ(h[0].part, 1);  // POV-Ray's SIDE_X_0
    const glm::dvec3 n = shape_normal(closed.accel.shape(0), glm::dvec3(-1, 0, 0), h[0]);
    EXPECT_EQ(n, glm::dvec3(-1, 0, 0));
    EXPECT_TRUE(testing::sorted_hits(open, glm::dvec3(-5, 0, 0), glm::dvec3(1, 0, 0)).empty());
    // From above both find the plane y = 0.5, with the gradient's normal.
    for (const Parsed* p : {&closed, &open}) {
        h = testing::sorted_hits(*p, glm::dvec3(0.2, 5, 0.1), glm::dvec3(0, -1, 0));
        ASSERT_EQ(h.size(), 1u);
        EXPECT_GT(h[0].t, 4.5);
        EXPECT_LE(h[0].t, 4.501);
        const glm::dvec3 m = shape_normal(p->accel.shape(0), glm::dvec3(0.2, 0.5, 0.1), h[0]);
        EXPECT_NEAR(m.y, 1.0, 1e-9);
    }
}

TEST(Isosurface, NoiseIsPovRaysNoiseWithTheScenesGenerator) {
    // The surface y = noise(x, 0, z): inside below it, outside above, with the generator
    // global_settings gives even after the isosurface.
    const Parsed p = build(
        "#include \"functions.inc\"\n"
        "isosurface { function { y - f_noise3d(x, 0, z) } contained_by { box { -2, 2 } } }\n"
        "global_settings { noise_generator 3 }");
    for (const glm::dvec3 q : {glm::dvec3(0.3, 0, 0.7), glm::dvec3(-1.2, 0, 0.25)}) {
        const double y = noise(q, 3);
        EXPECT_NE(y, noise(q, 2));
        EXPECT_TRUE(inside_shape(p.accel.shape(0), q + glm::dvec3(0, y - 1e-6, 0)));
        EXPECT_FALSE(inside_shape(p.accel.shape(0), q + glm::dvec3(0, y + 1e-6, 0)));
    }
}

TEST(Isosurface, APigmentFunctionGivesTheComponentAsked) {
    // gradient x from black to <1, 0.5, 0> at x = 0.5: red 0.5, gray 0.297 * 0.5 + 0.589 * 0.25.
    const std::string f =
        "#declare F = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] "
        "} } }\n";
    const glm::dvec3 q(0.5, 0, 0.2);
    const Parsed red = build(f +
                             "isosurface { function { y - F(x, y, z).red } "
                             "contained_by { box { <0, -1, -1>, <0.9, 2, 1> } } }");
    EXPECT_TRUE(inside_shape(red.accel.shape(0), q + glm::dvec3(0, 0.5 - 1e-6, 0)));
    EXPECT_FALSE(inside_shape(red.accel.shape(0), q + glm::dvec3(0, 0.5 + 1e-6, 0)));
    const Parsed gray = build(f +
                              "isosurface { function { y - F(x, y, z).gray } "
                              "contained_by { box { <0, -1, -1>, <0.9, 2, 1> } } }");
    const double g = 0.297 * 0.5 + 0.589 * 0.25;
    EXPECT_TRUE(inside_shape(gray.accel.shape(0), q + glm::dvec3(0, g - 1e-6, 0)));
    EXPECT_FALSE(inside_shape(gray.accel.shape(0), q + glm::dvec3(0, g + 1e-6, 0)));
    EXPECT_EQ(parse_error(f + "isosurface { function { y - F(x, y, z) } }"),
              "scene.pov:2:40: expected '.' after the pigment function 'F' (a colour: .red, "
              ".green, .blue, .filter, .transmit or .gray), got '}'\n"
              "isosurface { function { y - F(x, y, z) } }\n"
              "                                       ^");
    EXPECT_EQ(parse_error(f + "isosurface { function { y - F(x, y, z).w } }"),
              "scene.pov:2:40: expected red, green, blue, filter, transmit or gray after '.', got "
              "undefined identifier 'w'\n"
              "isosurface { function { y - F(x, y, z).w } }\n"
              "                                       ^");
}

TEST(Isosurface, APigmentFunctionsMemberTIsItsFilter) {
    // POV-Ray's compile_member: .t is the fourth component, the filter (0.4 at x = 0.5 here;
    // the transmit is 0).
    const std::string f =
        "#declare F = function { pigment { gradient x color_map { [0 rgbft 0] "
        "[1 rgbft <1, 0.5, 0, 0.8, 0>] } } }\n";
    const glm::dvec3 q(0.5, 0, 0.2);
    for (const char* member : {"t", "filter"}) {
        const Parsed p = build(f + "isosurface { function { y - F(x, y, z)." + member +
                               " } contained_by { box { <0, -1, -1>, <0.9, 2, 1> } } }");
        EXPECT_TRUE(inside_shape(p.accel.shape(0), q + glm::dvec3(0, 0.4 - 1e-6, 0))) << member;
        EXPECT_FALSE(inside_shape(p.accel.shape(0), q + glm::dvec3(0, 0.4 + 1e-6, 0))) << member;
    }
}

TEST(Isosurface, BadInputIsReportedWhereItIs) {
    EXPECT_EQ(parse_error("isosurface {\n  sphere { 0, 1 } }"),
              "scene.pov:2:3: expected 'function' to begin the isosurface, got 'sphere'\n"
              "  sphere { 0, 1 } }\n"
              "  ^");
    EXPECT_EQ(parse_error("#include \"functions.inc\"\n"
                          "isosurface { function { f_dupin_cyclid(x, y, z, 1, 0, 0, 0, 0, 0) } }"),
              "scene.pov:2:14: unsupported isosurface function (it needs f_dupin_cyclid "
              "(internal 16), which mirage does not evaluate)\n"
              "isosurface { function { f_dupin_cyclid(x, y, z, 1, 0, 0, 0, 0, 0) } }\n"
              "             ^");
    EXPECT_EQ(parse_error("isosurface { function { x } threshold }"),
              "scene.pov:1:39: expected a numeric expression, got '}'\n"
              "isosurface { function { x } threshold }\n"
              "                                      ^");
    // f_noise3d is evaluated in traced shapes only, not while parsing.
    EXPECT_EQ(parse_error("#include \"functions.inc\"\n#declare A = f_noise3d(1, 2, 3);\n"
                          "sphere { 0, A }"),
              "scene.pov:3:13: unsupported function 'f_noise3d' (it needs f_noise3d (internal 76), "
              "which mirage evaluates only in shapes it traces) (in the value 'A' declared at "
              "scene.pov:2:10; the reason at scene.pov:2:14)\n"
              "sphere { 0, A }\n"
              "            ^");
}

TEST(Isosurface, ValuesPovRayReplacesAreReplacedWithAWarning) {
    auto s =
        parse_scene_text("isosurface { function { x } accuracy 0 max_gradient -1 max_trace 12 }",
                         "scene.pov", ParseOptions{});
    ASSERT_TRUE(s.ok()) << s.message();
    const auto& iso = std::get<Isosurface>(s->primitives[0].shape);
    EXPECT_EQ(iso.accuracy, 0.001);
    EXPECT_EQ(iso.max_gradient, 1.1);
    EXPECT_EQ(iso.max_trace, 10);
    ASSERT_EQ(s->messages.size(), 3u);
}

TEST(Isosurface, LenientModeLeavesOutAnIsosurfaceItCannotEvaluate) {
    ParseOptions lenient = testing::with_povray_includes();
    lenient.strict = false;
    auto s = parse_scene_text(
        "#include \"functions.inc\"\n"
        "isosurface { function { f_heart(x, y, z, 1) } translate x }\n"
        "sphere { 0, 1 }",
        "scene.pov", lenient);
    ASSERT_TRUE(s.ok()) << s.message();
    ASSERT_EQ(s->primitives.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<Sphere>(s->primitives[0].shape));
    ASSERT_EQ(s->unknown_objects.size(), 1u);
    EXPECT_EQ(s->unknown_objects[0].loc.line, 2);
}

TEST(IsosurfaceParity, BoxAndSphereContainersUserAndInternalFunctions) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const double psnr = testing::parity_psnr("isosurface_parity", "isosurfaces", R"(#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
isosurface { function { sqrt(x*x + z*z) - 0.6 + 0.15*sin(6*y) } contained_by { box { <-1,0,-1>, <1,1.5,1> } } max_gradient 2 pigment { rgb <1,0.3,0.2> } translate <-2.2,0,0.5> }
isosurface { function { f_torus(x, y, z, 0.8, 0.25) } contained_by { sphere { 0, 1.1 } } pigment { rgb <0.2,1,0.3> } rotate x*60 scale <1,0.8,1> translate <2,1,0.5> }
isosurface { function { f_rounded_box(x, y, z, 0.1, 0.5, 0.4, 0.6) } contained_by { box { -1, 1 } } pigment { rgb <0.3,0.5,1> } rotate y*30 translate <0,0.4,-1.8> }
isosurface { function { y - 0.3*sin(3*x)*cos(3*z) } open contained_by { box { <-1.5,-0.5,-1>, <1.5,0.5,1> } } max_gradient 2 pigment { rgb <1,1,0> } translate <0,1.8,2.5> }
isosurface { function { y + f_noise3d(2*x, 0, 2*z) - 0.5 } contained_by { box { <-0.6,-0.3,-0.6>, <0.6,0.8,0.6> } } max_gradient 2.5 pigment { rgb <1,0.5,1> } translate <2,0.3,-1.8> }
)",
                                             160, 120);
    EXPECT_GE(psnr, 40.0);
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

// accuracy 1e-300 with max_gradient 1e300 drops no interval: the search halved the ray's
// interval down to the accuracy everywhere (over 30 s at 16x12).  A ray's search stops at
// kMaxRootSearchSteps halvings (a miss there); this one needs 2^21 without the bound.
TEST(Isosurface, ARaysRootSearchIsBounded) {
    for (const char* accuracy : {"1e-6", "1e-300"}) {
        const testing::Parsed p = testing::build(
            std::string("isosurface { function { 1 } contained_by { box { -1, 1 } } accuracy ") +
                accuracy + " max_gradient 1e300 }",
            testing::with_povray_includes());
        const long before = root_search_steps_on_this_thread();
        const auto h = testing::sorted_hits(p, glm::dvec3(0.1, 0.2, -5), glm::dvec3(0, 0, 1));
        EXPECT_TRUE(h.empty());
        EXPECT_LE(root_search_steps_on_this_thread() - before, kMaxRootSearchSteps) << accuracy;
        EXPECT_GE(root_search_steps_on_this_thread() - before, kMaxRootSearchSteps / 2) << accuracy;
    }
}

}  // namespace
}  // namespace mirage
