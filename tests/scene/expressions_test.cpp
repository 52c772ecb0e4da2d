// Expressions against hand-computed values and against what POV-Ray 3.7.0.10 prints (those
// values were obtained with #debug and str()/vstr() in POV-Ray itself, as the comments say).
#include <gtest/gtest.h>

#include <cmath>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::eval;
using testing::eval_string;
using testing::expect_vec;
using testing::parse_error;
using testing::parse_ok;
using testing::vector_symbol;

constexpr double kPi = 3.14159265358979323846;

TEST(Expressions, Precedence) {
    EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
    EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
    EXPECT_EQ(eval("10 - 4 - 3"), 3.0);
    EXPECT_EQ(eval("12 / 3 / 2"), 2.0);
    EXPECT_EQ(eval("-2 * 3 + 1"), -5.0);
    EXPECT_EQ(eval("- -1"), 1.0);
    EXPECT_EQ(eval("+4"), 4.0);
    // POV-Ray 3.7.0.10 prints -2.000 for str(-2.5 * 2 + 4 / 2 - -1, 0, 3).
    EXPECT_EQ(eval("-2.5 * 2 + 4 / 2 - -1"), -2.0);
}

TEST(Expressions, ComparisonsLogicAndTernary) {
    EXPECT_EQ(eval("(2 < 3) + (3 <= 3) + (4 = 4) + (4 != 4) + (5 >= 6) + (6 > 5)"), 4.0);
    EXPECT_EQ(eval("((1 & 0) | 1)"), 1.0);
    EXPECT_EQ(eval("(1 & 2)"), 1.0);
    EXPECT_EQ(eval("!0 + !3"), 1.0);
    EXPECT_EQ(eval("(1 < 2 ? 10 : 20)"), 10.0);
    EXPECT_EQ(eval("(0 ? 1 : 0 ? 2 : 3)"), 3.0);
    // Equality has POV-Ray's tolerance of 1e-10.
    EXPECT_EQ(eval("(1 = 1 + 1e-11)"), 1.0);
    EXPECT_EQ(eval("(1 = 1 + 1e-9)"), 0.0);
}

TEST(Expressions, Constants) {
    EXPECT_DOUBLE_EQ(eval("pi"), kPi);
    EXPECT_EQ(eval("true + yes + on"), 3.0);
    EXPECT_EQ(eval("false + no + off"), 0.0);
    EXPECT_EQ(eval("clock"), 0.0);
    EXPECT_DOUBLE_EQ(eval("version"), 3.7);
    ParseOptions o;
    o.image_width = 640;
    o.image_height = 480;
    Scene s = parse_ok("#declare A = image_width / image_height;", o);
    EXPECT_DOUBLE_EQ(testing::float_symbol(s, "A"), 640.0 / 480.0);
    // tau is not part of POV-Ray 3.7.
    EXPECT_NE(parse_error("#declare A = tau;").find("undefined identifier 'tau'"),
              std::string::npos);
}

TEST(Expressions, FloatFunctions) {
    EXPECT_DOUBLE_EQ(eval("sin(pi / 2) + cos(0) + tan(0)"), 2.0);
    EXPECT_DOUBLE_EQ(eval("asin(1)"), kPi / 2);
    EXPECT_DOUBLE_EQ(eval("acos(-1)"), kPi);
    EXPECT_DOUBLE_EQ(eval("atan(1)"), kPi / 4);
    EXPECT_DOUBLE_EQ(eval("atan2(1, -1)"), 3 * kPi / 4);
    EXPECT_DOUBLE_EQ(eval("sqrt(16) + pow(2, 10) + exp(0)"), 1029.0);
    EXPECT_DOUBLE_EQ(eval("log(1000)"), 3.0);
    EXPECT_DOUBLE_EQ(eval("ln(exp(2))"), 2.0);
    EXPECT_EQ(eval("abs(-3) + min(3, 1, 2) + max(3, 1, 2)"), 7.0);
    EXPECT_EQ(eval("floor(-1.5) + ceil(1.2)"), 0.0);
    EXPECT_DOUBLE_EQ(eval("degrees(pi) + radians(180)"), 180.0 + kPi);
    EXPECT_EQ(eval("sqr(3)"), 9.0);
    EXPECT_EQ(eval("select(-1, 1, 2, 3) + select(0, 1, 2, 3) * 10 + select(5, 1, 2) * 100"), 221.0);
    EXPECT_EQ(eval("bitwise_and(12, 10) + bitwise_or(12, 10) * 100"), 1408.0);
    // POV-Ray 3.7.0.10 prints -1.0 -3.0 -2.0 for mod(-7,3), div(-7,2), int(-2.5).
    EXPECT_EQ(eval("mod(-7, 3)"), -1.0);
    EXPECT_EQ(eval("div(-7, 2)"), -3.0);
    EXPECT_EQ(eval("int(-2.5)"), -2.0);
}

TEST(Expressions, RandomStreamsMatchPovRay) {
    // POV-Ray 3.7.0.10: #declare S = seed(42); str(rand(S), 0, 10) twice printed
    // 0.7235829112 and 0.3299792596.
    auto s = parse_ok("#declare S = seed(42); #declare A = rand(S); #declare B = rand(S);");
    EXPECT_NEAR(testing::float_symbol(s, "A"), 0.7235829112, 1e-10);
    EXPECT_NEAR(testing::float_symbol(s, "B"), 0.3299792596, 1e-10);
}

TEST(Expressions, VectorsAndPromotion) {
    Scene s = parse_ok(R"(
        #declare A = <1, 2, 3> + 1;
        #declare B = 2 * <1, 2, 3>;
        #declare C = <1, 2, 3> * <2, 0.5, -1> - <1, 1, 1> / 2;
        #declare D = -<1, -2, 3>;
        #declare E = <1, 2> + <1, 2, 3>;
        #declare F = (<1, 2, 3> = 1);
        #declare G = x + 2 * y - z;
        #declare H = <1 2 3>;
    )");
    expect_vec(vector_symbol(s, "A"), glm::dvec3(2, 3, 4));
    expect_vec(vector_symbol(s, "B"), glm::dvec3(2, 4, 6));
    expect_vec(vector_symbol(s, "C"), glm::dvec3(1.5, 0.5, -3.5));
    expect_vec(vector_symbol(s, "D"), glm::dvec3(-1, 2, -3));
    // POV-Ray 3.7.0.10: vstr(3, <1,2> + <1,2,3>, ...) printed 2.0,4.0,3.0 and
    // vstr(3, (<1,2,3> = 1), ...) printed 1.0,0.0,0.0.
    expect_vec(vector_symbol(s, "E"), glm::dvec3(2, 4, 3));
    expect_vec(vector_symbol(s, "F"), glm::dvec3(1, 0, 0));
    expect_vec(vector_symbol(s, "G"), glm::dvec3(1, 2, -1));
    // Commas are optional in POV-Ray vectors.
    expect_vec(vector_symbol(s, "H"), glm::dvec3(1, 2, 3));
    // A 2-vector: POV-Ray 3.7.0.10 prints 2.0,3.0,0.0 for vstr(3, 1 + <1,2>, ...).
    EXPECT_EQ(eval_string("vstr(3, 1 + <1, 2>, \",\", 0, 1)"), "2.0,3.0,0.0");
}

TEST(Expressions, DotAccess) {
    EXPECT_EQ(eval("<4, 5, 6>.y"), 5.0);
    Scene s = parse_ok(R"(
        #declare V = <1, 2, 3>;
        #declare V4 = <1, 2, 3, 4>;
        #declare C = color red 1 green 0.5 filter 0.2;
        #declare A = V.x + V.y * 10 + V.z * 100;
        #declare T = V4.t;
        #declare R = C.red + C.green * 10 + C.filter * 100 + C.transmit * 1000;
        #declare G = C.gray;
        #declare U = <7, 8>.v;
    )");
    EXPECT_EQ(testing::float_symbol(s, "A"), 321.0);
    EXPECT_EQ(testing::float_symbol(s, "T"), 4.0);
    EXPECT_DOUBLE_EQ(testing::float_symbol(s, "R"), 26.0);
    // POV-Ray 3.7.0.10 prints 0.5915 for str(C.gray, 0, 4): 0.297 r + 0.589 g + 0.114 b.
    EXPECT_DOUBLE_EQ(testing::float_symbol(s, "G"), 0.5915);
    EXPECT_EQ(testing::float_symbol(s, "U"), 8.0);
}

TEST(Expressions, Colours) {
    // POV-Ray 3.7.0.10 printed these with vstr(5, C, ",", 0, 2) (but C5 and C6).
    Scene s = parse_ok(R"(
        #declare C1 = color <1, 0, 0>;
        #declare C2 = rgbt 0.5;
        #declare C3 = rgb <1, 0.5, 0.25> * 2;
        #declare C4 = color 0.5;
        #declare C5 = rgbf <0.1, 0.2, 0.3, 0.4> transmit 0.5;
        #declare C6 = color rgb 1 blue 0;
        #declare S1 = vstr(5, C1, ",", 0, 2);
        #declare S2 = vstr(5, C2, ",", 0, 2);
        #declare S3 = vstr(5, C3, ",", 0, 2);
        #declare S4 = vstr(5, C4, ",", 0, 2);
        #declare S5 = vstr(5, C5, ",", 0, 2);
        #declare S6 = vstr(5, C6, ",", 0, 2);
    )");
    EXPECT_EQ(testing::string_symbol(s, "S1"), "1.00,0.00,0.00,0.00,0.00");
    EXPECT_EQ(testing::string_symbol(s, "S2"), "0.50,0.50,0.50,0.00,0.50");
    EXPECT_EQ(testing::string_symbol(s, "S3"), "2.00,1.00,0.50,0.00,0.00");
    EXPECT_EQ(testing::string_symbol(s, "S4"), "0.50,0.50,0.50,0.50,0.50");
    EXPECT_EQ(testing::string_symbol(s, "S5"), "0.10,0.20,0.30,0.40,0.50");
    EXPECT_EQ(testing::string_symbol(s, "S6"), "1.00,1.00,0.00,0.00,0.00");
}

TEST(Expressions, VectorFunctions) {
    Scene s = parse_ok(R"(
        #declare L = vlength(<3, 4, 0>);
        #declare D = vdot(<1, 2, 3>, <4, 5, 6>);
        #declare C = vcross(x, y);
        #declare N = vnormalize(<3, 0, 4>);
        #declare R = vrotate(<1, 2, 3>, <10, 20, 30>);
        #declare A = vaxis_rotate(<1, 2, 3>, <1, 1, 0>, 33);
    )");
    EXPECT_EQ(testing::float_symbol(s, "L"), 5.0);
    EXPECT_EQ(testing::float_symbol(s, "D"), 32.0);
    expect_vec(vector_symbol(s, "C"), glm::dvec3(0, 0, 1));
    expect_vec(vector_symbol(s, "N"), glm::dvec3(0.6, 0, 0.8));
    // POV-Ray 3.7.0.10 printed 1.067425379,2.289059483,2.760581414 and
    // 2.236018581,0.763981419,2.901129659.
    expect_vec(vector_symbol(s, "R"), glm::dvec3(1.067425379, 2.289059483, 2.760581414), 1e-9);
    expect_vec(vector_symbol(s, "A"), glm::dvec3(2.236018581, 0.763981419, 2.901129659), 1e-9);
}

TEST(Expressions, Strings) {
    EXPECT_EQ(eval_string("concat(\"a\", \"b\", str(3.14159, 0, 2))"), "ab3.14");
    EXPECT_EQ(eval_string("str(5, 5, 1)"), "  5.0");
    EXPECT_EQ(eval_string("str(5, -5, 1)"), "005.0");
    EXPECT_EQ(eval_string("str(2.5, 0, -1)"), "2.500000");
    // POV-Ray 3.7.0.10: concat(chr(65), substr("hello", 2, 3), strupr("ab")) is AellAB.
    EXPECT_EQ(eval_string("concat(chr(65), substr(\"hello\", 2, 3), strupr(\"ab\"))"), "AellAB");
    EXPECT_EQ(eval_string("strlwr(\"MiXeD\")"), "mixed");
    EXPECT_EQ(eval_string("\"tab\\there\""), "tab\there");
    EXPECT_EQ(eval_string("vstr(2, <1, 2>, \", \", 0, 0)"), "1, 2");
    EXPECT_EQ(eval("strlen(\"hello\")"), 5.0);
    EXPECT_EQ(eval("val(\"3.5e1\")"), 35.0);
    EXPECT_EQ(eval("asc(\"A\")"), 65.0);
    EXPECT_EQ(eval("strcmp(\"abc\", \"abd\")"), -1.0);
    EXPECT_EQ(eval("(\"abc\" < \"abd\") + (\"x\" = \"x\") * 10"), 11.0);
    Scene s = parse_ok("#declare S = \"text\" #declare T = S;");  // no ';' needed for strings
    EXPECT_EQ(testing::string_symbol(s, "T"), "text");
}

TEST(Expressions, DefinedAndArrays) {
    Scene s = parse_ok(R"(
        #declare A = 1;
        #declare D1 = defined(A);
        #declare D2 = defined(Nothing);
        #declare Arr = array[3] {1, 2, 3};
        #declare Arr[1] = 20;
        #declare Sum = Arr[0] + Arr[1] + Arr[2];
        #declare M = array[2][3] {{1, 2, 3}, {4, 5, 6}};
        #declare M12 = M[1][2];
        #declare Dims = dimensions(M) * 10 + dimension_size(M, 2);
        #declare Empty = array[2];
        #declare E0 = defined(Empty[0]);
        #declare Empty[1] = <1, 2, 3>;
        #declare E1 = defined(Empty[1]);
        #declare V = Empty[1] * 2;
    )");
    EXPECT_EQ(testing::float_symbol(s, "D1"), 1.0);
    EXPECT_EQ(testing::float_symbol(s, "D2"), 0.0);
    EXPECT_EQ(testing::float_symbol(s, "Sum"), 24.0);
    EXPECT_EQ(testing::float_symbol(s, "M12"), 6.0);
    EXPECT_EQ(testing::float_symbol(s, "Dims"), 23.0);
    EXPECT_EQ(testing::float_symbol(s, "E0"), 0.0);
    EXPECT_EQ(testing::float_symbol(s, "E1"), 1.0);
    expect_vec(vector_symbol(s, "V"), glm::dvec3(2, 4, 6));
}

}  // namespace
}  // namespace mirage
