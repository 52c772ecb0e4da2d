// User functions (scene/function.h, scene/parse_functions.cpp): POV-Ray's function syntax,
// its built-ins, functions.inc's internal functions and calls in float expressions.
#include <gtest/gtest.h>

#include <cmath>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::float_symbol;
using testing::parse_error;
using testing::parse_ok;

ParseOptions with_povray_includes() {
    ParseOptions o;
    o.library_paths = {testing::kPovRayIncludes};
    return o;
}

TEST(Functions, DefaultParametersAndPrecedence) {
    Scene s = parse_ok(R"(
#declare F = function { x * x + y * 2 - z / 4 }
#declare A = F(3, 1, 8);
#declare Neg = function { -x * -y + +z }
#declare B = Neg(2, 3, 1);
)");
    EXPECT_EQ(float_symbol(s, "A"), 9.0);
    EXPECT_EQ(float_symbol(s, "B"), 7.0);
}

TEST(Functions, ComparisonsAndLogicBindLooserThanArithmetic) {
    // | below &, below comparisons, below + -: 1 + 1 < 3 is (1 + 1) < 3.
    Scene s = parse_ok(R"(
#declare F = function(a, b) { a + 1 < b | a > 5 & b = 0 }
#declare T1 = F(1, 3);
#declare T2 = F(6, 0);
#declare T3 = F(2, 3);
#declare G = function(a) { (a <= 1) + (a >= 1) * 2 + (a != 1) * 4 }
#declare T4 = G(1);
#declare T5 = G(0);
)");
    EXPECT_EQ(float_symbol(s, "T1"), 1.0);
    EXPECT_EQ(float_symbol(s, "T2"), 1.0);
    EXPECT_EQ(float_symbol(s, "T3"), 0.0);
    EXPECT_EQ(float_symbol(s, "T4"), 3.0);
    EXPECT_EQ(float_symbol(s, "T5"), 5.0);
}

TEST(Functions, BuiltinsConstantsAndCalls) {
    Scene s = parse_ok(R"(
#declare R = 2;
#declare V = <1, 5, 7>;
#declare F = function(u, v) { sqrt(u * u + v * v) * R + V.y }
#declare G = function { F(x, y) + pow(2, z) + select(x - 4, 10, 20) + select(0, 1, 2, 3) }
#declare A = G(3, 4, 3);
#declare M = function { min(x, y, z) + max(x, y) + abs(-2) + mod(7, 3) + sqr(3) + div(7, 2) }
#declare B = M(4, 2, 3);
#declare H = function { atan2(1, 1) * 4 - pi + degrees(pi) + radians(180) - pi }
#declare C = H(0, 0, 0);
)");
    EXPECT_DOUBLE_EQ(float_symbol(s, "A"), 5 * 2 + 5 + 8 + 10 + 2);
    EXPECT_DOUBLE_EQ(float_symbol(s, "B"), 2 + 4 + 2 + 1 + 9 + 3);
    EXPECT_NEAR(float_symbol(s, "C"), 180.0, 1e-12);
}

TEST(Functions, SumAndProd) {
    Scene s = parse_ok(R"(
#declare S = function(n) { sum(i, 1, n, i * i) }
#declare P = function(n) { prod(k, 1, n, k) }
#declare A = S(4);
#declare B = P(5);
)");
    EXPECT_EQ(float_symbol(s, "A"), 30.0);
    EXPECT_EQ(float_symbol(s, "B"), 120.0);
}

TEST(Functions, InternalFunctionsOfFunctionsInc) {
    Scene s = parse_ok(R"(
#include "functions.inc"
#declare A = f_sphere(3, 4, 0, 2);
#declare B = f_torus(3, 0, 0, 2, 0.5);
#declare C = f_rounded_box(2, 0, 0, 0.1, 1, 1, 1);
#declare F = function { f_sphere(x, y, z, 1) - 0.5 }
#declare D = F(0, 0, 0);
)",
                       with_povray_includes());
    EXPECT_DOUBLE_EQ(float_symbol(s, "A"), 3.0);
    EXPECT_DOUBLE_EQ(float_symbol(s, "B"), 0.5);
    EXPECT_NEAR(float_symbol(s, "C"), 1.0, 1e-5);
    EXPECT_DOUBLE_EQ(float_symbol(s, "D"), -1.5);
}

TEST(Functions, AnInternalFunctionMirageDoesNotEvaluateIsRefusedWhereItIsNeeded) {
    // Declaring it (functions.inc declares them all) is fine, and so is a declaration
    // computed from a call (kept opaque); a value the scene needs is the error.
    const std::string prelude = R"(#include "functions.inc"
#declare F = function { f_noise3d(x, y, z) * 2 }
#declare A = F(1, 2, 3);
)";
    parse_ok(prelude, with_povray_includes());
    const std::string e = parse_error(prelude + "sphere { 0, A }\n", with_povray_includes());
    EXPECT_NE(e.find("scene.pov:4:13:"), std::string::npos) << e;
    EXPECT_NE(e.find("unsupported function 'F' (it needs f_noise3d (internal 76)"),
              std::string::npos)
        << e;
    const std::string direct =
        parse_error(prelude + "sphere { 0, F(0, 0, 0) }\n", with_povray_includes());
    EXPECT_NE(direct.find("scene.pov:4:13: unsupported function 'F' (it needs f_noise3d"),
              std::string::npos)
        << direct;
}

TEST(Functions, WrongArgumentCountsAndUnknownNames) {
    EXPECT_NE(parse_error("#declare F = function(a) { a }\n#declare A = F(1, 2);\n")
                  .find("scene.pov:2:14: the function 'F' takes 1 arguments, got 2"),
              std::string::npos);
    EXPECT_NE(parse_error("#declare F = function { x + q }\n")
                  .find("scene.pov:1:29: 'q' is neither a parameter"),
              std::string::npos);
    EXPECT_NE(parse_error("#declare F = function { !x }\n").find("'!' is not an operator"),
              std::string::npos);
}

TEST(Functions, APigmentFunctionIsOpaqueUntilUsed) {
    // Evaluated only in traced shapes: a call while parsing makes the declaration calling it
    // opaque; its use where a value is needed is the error, naming the pigment function.
    parse_ok("#declare P = function { pigment { rgb 1 } }\n#declare A = P(1, 2, 3);\n");
    const std::string e = parse_error(
        "#declare P = function { pigment { rgb 1 } }\n#declare A = P(1, 2, 3);\n"
        "sphere { 0, A }\n");
    EXPECT_NE(e.find("scene.pov:3:13:"), std::string::npos) << e;
    EXPECT_NE(e.find("unsupported function 'P' (it needs a pigment function"), std::string::npos)
        << e;
    const std::string direct =
        parse_error("#declare P = function { pigment { rgb 1 } }\nsphere { 0, P(1, 2, 3) }\n");
    EXPECT_NE(direct.find("scene.pov:2:13:"), std::string::npos) << direct;
}

}  // namespace
}  // namespace mirage
