// Opaque values: declarations the parser cannot evaluate cost nothing until they are used
// (scene/value.h, scene/parse_opaque.cpp).
#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::parse_error;
using testing::parse_ok;

ParseOptions lenient() {
    ParseOptions o;
    o.strict = false;
    return o;
}

// A pigment pattern and an object kind mirage does not evaluate.
constexpr const char* kOpaqueDeclarations = R"(
#declare P_Fractal = pigment { julia <0.353, 0.288>, 30 color_map { [0 rgb 0] [1 rgb 1] } }
#declare T_Fractal = texture { pigment { P_Fractal } finish { ambient 0.2 } }
#declare O_Julia = julia_fractal { <-0.1, 0.6, 0, 0> quaternion sqr max_iteration 8 }
#declare Copy = T_Fractal;
)";

TEST(Opaque, UnusedDeclarationsOfUnsupportedThingsParseStrictly) {
    Scene s = parse_ok(std::string(kOpaqueDeclarations) + "sphere { 0, 1 }\n");
    EXPECT_EQ(s.primitives.size(), 1u);
    EXPECT_TRUE(s.skipped.empty());
}

TEST(Opaque, AUseIsAnErrorAtTheUseNamingTheReasonAndTheDeclaration) {
    const std::string e =
        parse_error(std::string(kOpaqueDeclarations) + "sphere { 0, 1 texture { T_Fractal } }\n");
    // The use's place first, then the reason and where it lies.
    EXPECT_EQ(e.rfind("scene.pov:6:", 0), 0u) << e;
    EXPECT_NE(e.find("T_Fractal"), std::string::npos) << e;
    EXPECT_NE(e.find("P_Fractal"), std::string::npos) << e;
    EXPECT_NE(e.find("unsupported pattern 'julia'"), std::string::npos) << e;
    EXPECT_NE(e.find("declared at scene.pov:3:10"), std::string::npos) << e;
}

TEST(Opaque, ACopyStaysOpaqueAndItsUseFails) {
    const std::string e =
        parse_error(std::string(kOpaqueDeclarations) + "sphere { 0, 1 texture { Copy } }\n");
    EXPECT_EQ(e.rfind("scene.pov:6:", 0), 0u) << e;
    EXPECT_NE(e.find("'julia'"), std::string::npos) << e;
}

TEST(Opaque, AnOpaqueObjectFailsWhereItIsUsed) {
    const std::string e =
        parse_error(std::string(kOpaqueDeclarations) + "object { O_Julia translate x }\n");
    EXPECT_EQ(e.rfind("scene.pov:6:10:", 0), 0u) << e;
    EXPECT_NE(e.find("unsupported object 'julia_fractal'"), std::string::npos) << e;
}

TEST(Opaque, LenientUseOfAnUnreadTextureTakesTheDefaultAndRecordsIt) {
    Scene s = parse_ok(R"(
#declare T = texture { pigment { rgb 1 } not_a_keyword 3 finish { ambient 1 } }
sphere { 0, 1 texture { T } }
sphere { x, 1 }
)",
                       lenient());
    ASSERT_EQ(s.primitives.size(), 2u);
    EXPECT_EQ(s.primitives[0].texture.finish.ambient, s.primitives[1].texture.finish.ambient);
    bool recorded = false;
    for (const auto& k : s.skipped) recorded |= k.what.find("'T'") != std::string::npos;
    EXPECT_TRUE(recorded);
}

TEST(Opaque, LenientReadsWhatItCanOfADeclarationWithSomethingUnsupported) {
    // The pattern is left out, the finish kept: the compiler needs no more.
    Scene s = parse_ok(std::string(kOpaqueDeclarations) + "sphere { 0, 1 texture { T_Fractal } }\n",
                       lenient());
    ASSERT_EQ(s.primitives.size(), 1u);
    EXPECT_EQ(s.primitives[0].texture.finish.ambient, glm::dvec3(0.2));
}

TEST(Opaque, LenientStopsAtTheEndOfTheFileWithAConditionalLeftOpen) {
    // A statement cut short at the end of the file inside an open '#if': nothing is left to
    // skip to, so the parse ends with the unclosed conditional's message (it used to meet the
    // same failure again and again, recording a skipped statement each time, without end).
    for (const char* text : {"#if (1) #declare S = (1 #decla\n",
                             "#declare S = \"a\"\n#if (strlen(S) = 1) #declare S = (\"a\"\n"
                             "#if (strlen(S) = 1) #decla: unsupported\n"}) {
        SCOPED_TRACE(text);
        const std::string e = parse_error(text, lenient());
        EXPECT_NE(e.find("expected '#end' to close '#if' opened at"), std::string::npos) << e;
        EXPECT_NE(e.find("got end of file"), std::string::npos) << e;
    }
}

TEST(Opaque, LenientKeepsADeclarationItCannotReadAndGoesOn) {
    // An unknown function in an expression, an unknown keyword inside braces: both
    // declarations are opaque, the rest of the file is read.
    Scene s = parse_ok(R"(
#declare A = 2 * no_such_function(3, 4);
#declare T = texture { pigment { rgb 1 } not_a_keyword 3 finish { ambient 1 } }
#declare B = 5;
sphere { 0, B }
)",
                       lenient());
    ASSERT_EQ(s.primitives.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.primitives[0].shape).radius, 5.0);
    EXPECT_EQ(testing::float_symbol(s, "B"), 5.0);
}

TEST(Opaque, LenientObjectThatUsesAnUnreadNumberBecomesAnUnknownObject) {
    // Its extent needs the number: it is recorded, with the reason, as an object the
    // compiler cannot bound; the next object is read as usual.
    Scene s = parse_ok(R"(
#declare A = 2 * no_such_function(3, 4);
sphere { 0, A }
sphere { x, 1 }
)",
                       lenient());
    ASSERT_EQ(s.primitives.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.primitives[0].shape).center, glm::dvec3(1, 0, 0));
    ASSERT_EQ(s.unknown_objects.size(), 1u);
    EXPECT_EQ(s.unknown_objects[0].loc.line, 3);
    EXPECT_NE(s.unknown_objects[0].what.find("no_such_function"), std::string::npos)
        << s.unknown_objects[0].what;
}

TEST(Opaque, StrictUseOfAnUnreadNumberIsAnErrorAtItsUse) {
    // Strict mode keeps only what is unsupported: an unknown function is an error at once.
    const std::string e = parse_error("#declare A = 2 * no_such_function(3, 4);\n");
    EXPECT_EQ(e.rfind("scene.pov:1:18:", 0), 0u) << e;
}

TEST(Opaque, AnExpressionOfAnOpaqueValueIsOpaqueToo) {
    ParseOptions o = lenient();
    Scene s = parse_ok(R"(
#declare A = no_such_function(3);
#declare B = A * 2;
#declare C = 1;
)",
                       o);
    EXPECT_EQ(testing::float_symbol(s, "C"), 1.0);
    EXPECT_EQ(s.symbols.count("B"), 0u);  // not a number: not exported
}

TEST(Opaque, StrictStillRefusesWhatIsWrongOutsideDeclarations) {
    const std::string e =
        parse_error("sphere { 0, 1 texture { pigment { julia <0.353, 0.288>, 30 } } }\n");
    EXPECT_NE(e.find("unsupported pattern 'julia'"), std::string::npos) << e;
    // A typo in a declaration is still an error where it is.
    const std::string typo = parse_error("#declare T = texture { pigmnet { rgb 1 } }\n");
    EXPECT_EQ(typo.rfind("scene.pov:1:24:", 0), 0u) << typo;
}

}  // namespace
}  // namespace mirage
