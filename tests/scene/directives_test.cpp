// Directives: conditionals, loops, macros, scopes, includes, messages.
#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::float_symbol;
using testing::parse_error;
using testing::parse_ok;
using testing::string_symbol;

TEST(Directives, IfElseifElse) {
    Scene s = parse_ok(R"(
        #declare A = 2;
        #if (A = 1) #declare R1 = 1; #elseif (A = 2) #declare R1 = 2; #else #declare R1 = 3; #end
        #if (A > 5) #declare R2 = 1; #else #declare R2 = 2; #end
        #if (A < 5) #declare R3 = 1; #elseif (A = 2) #declare R3 = 2; #end
        #if (0) #if (1) #declare Bad = 1; #else #declare Bad = 2; #end #end
        #ifdef (A) #declare R4 = 1; #else #declare R4 = 0; #end
        #ifndef (B) #declare R5 = 1; #end
        #ifdef (sphere) #declare Bad = 3; #end
    )");
    EXPECT_EQ(float_symbol(s, "R1"), 2.0);
    EXPECT_EQ(float_symbol(s, "R2"), 2.0);
    EXPECT_EQ(float_symbol(s, "R3"), 1.0);
    EXPECT_EQ(float_symbol(s, "R4"), 1.0);
    EXPECT_EQ(float_symbol(s, "R5"), 1.0);
    EXPECT_EQ(s.symbols.count("Bad"), 0u);
}

TEST(Directives, SwitchFallsThroughUntilBreak) {
    // As in POV-Ray: a true #case runs on into the following ones until #break.
    Scene s = parse_ok(R"(
        #declare Trace = "";
        #switch (2)
          #case (1) #declare Trace = concat(Trace, "1");
          #case (2) #declare Trace = concat(Trace, "2");
          #case (3) #declare Trace = concat(Trace, "3"); #break
          #case (4) #declare Trace = concat(Trace, "4");
          #else #declare Trace = concat(Trace, "e");
        #end
        #declare T2 = "";
        #switch (7)
          #range (1, 4) #declare T2 = "low"; #break
          #range (5, 9) #declare T2 = "mid"; #break
          #else #declare T2 = "other";
        #end
        #declare T3 = "";
        #switch (42) #case (1) #declare T3 = "one"; #break #else #declare T3 = "else"; #end
    )");
    EXPECT_EQ(string_symbol(s, "Trace"), "23");
    EXPECT_EQ(string_symbol(s, "T2"), "mid");
    EXPECT_EQ(string_symbol(s, "T3"), "else");
}

TEST(Directives, WhileAndFor) {
    Scene s = parse_ok(R"(
        #declare I = 0; #declare Sum = 0;
        #while (I < 10) #declare Sum = Sum + I; #declare I = I + 1; #end
        #declare ForSum = 0;
        #for (J, 1, 10, 3) #declare ForSum = ForSum + J; #end
        #declare Down = "";
        #for (K, 3, 1, -1) #declare Down = concat(Down, str(K, 0, 0)); #end
        #declare None = 0;
        #for (K, 1, 0) #declare None = 1; #end
        #declare Nested = 0;
        #for (A, 1, 3) #for (B, 1, 4) #declare Nested = Nested + 1; #end #end
        #declare N = 0;
        #while (1) #declare N = N + 1; #if (N >= 7) #break #end #end
    )");
    EXPECT_EQ(float_symbol(s, "Sum"), 45.0);
    EXPECT_EQ(float_symbol(s, "ForSum"), 22.0);  // 1 + 4 + 7 + 10
    EXPECT_EQ(string_symbol(s, "Down"), "321");
    EXPECT_EQ(float_symbol(s, "None"), 0.0);
    EXPECT_EQ(float_symbol(s, "Nested"), 12.0);
    EXPECT_EQ(float_symbol(s, "N"), 7.0);
}

TEST(Directives, MacrosWithLocalsAndRecursion) {
    Scene s = parse_ok(R"(
        #macro Square(X) #local R = X * X; R #end
        #declare A = Square(3) + 1;
        #ifdef (R) #declare Leaked = 1; #end
        #macro Fact(N) (#if (N <= 1) 1 #else N * Fact(N - 1) #end) #end
        #declare F = Fact(6);
        #macro SetGlobal(V) #declare G = V * 2; #end
        SetGlobal(21)
        #macro NoArgs() 7 #end
        #declare Seven = NoArgs();
    )");
    EXPECT_EQ(float_symbol(s, "A"), 10.0);
    EXPECT_EQ(s.symbols.count("Leaked"), 0u);
    EXPECT_EQ(float_symbol(s, "F"), 720.0);
    EXPECT_EQ(float_symbol(s, "G"), 42.0);
    EXPECT_EQ(float_symbol(s, "Seven"), 7.0);
}

TEST(Directives, MacroArgumentsByReferenceAndByValue) {
    // A lone identifier is passed by reference (POV-Ray's Parse_RValue); an expression by value.
    Scene s = parse_ok(R"(
        #macro Inc(V) #declare V = V + 1; #end
        #declare K = 10;
        Inc(K)
        #declare L = 10;
        Inc(L + 0)
    )");
    EXPECT_EQ(float_symbol(s, "K"), 11.0);
    EXPECT_EQ(float_symbol(s, "L"), 10.0);
}

TEST(Directives, MacroLocalShadowsGlobal) {
    Scene s = parse_ok(R"(
        #declare X = 1;
        #macro M() #local X = 50; #declare Seen = X; #end
        M()
    )");
    EXPECT_EQ(float_symbol(s, "X"), 1.0);
    EXPECT_EQ(float_symbol(s, "Seen"), 50.0);
}

TEST(Directives, ALocalFromAMacroWhoseBodyEndsInASemicolonBelongsToTheCaller) {
    // F's ';' ends G's #local while F's table is still open: V is G's all the same, as in
    // POV-Ray (tracevines.pov's FindTmp).
    Scene s = parse_ok(R"(
        #macro F(P) #local Q = P * 2; Q; #end
        #macro G(P) #local V = F(P) #declare Seen = V + 1; #end
        G(3)
    )");
    EXPECT_EQ(float_symbol(s, "Seen"), 7.0);
    EXPECT_EQ(s.symbols.count("V"), 0u);  // G's local, gone with G
}

TEST(Directives, MacrosProduceObjects) {
    Scene s = parse_ok(R"(
        #macro Ball(R) sphere { 0, R } #end
        object { Ball(2) translate x }
        union { Ball(1) Ball(0.5) translate y }
    )");
    ASSERT_EQ(s.primitives.size(), 3u);
    EXPECT_EQ(std::get<Sphere>(s.primitives[0].shape).radius, 2.0);
    EXPECT_EQ(s.primitives[0].transform.matrix[3][0], 1.0);
    EXPECT_EQ(s.primitives[2].transform.matrix[3][1], 1.0);
}

TEST(Directives, BreakInsideAMacroReturnsFromIt) {
    Scene s = parse_ok(R"(
        #macro M() #declare A = 1; #if (1) #break #end #declare A = 2; #end
        M()
    )");
    EXPECT_EQ(float_symbol(s, "A"), 1.0);
}

TEST(Directives, UndefAndRedeclare) {
    Scene s = parse_ok(R"(
        #declare A = 1;
        #undef A
        #ifdef (A) #declare WasDefined = 1; #else #declare WasDefined = 0; #end
        #declare B = 1;
        #declare B = "now a string";
    )");
    EXPECT_EQ(s.symbols.count("A"), 0u);
    EXPECT_EQ(float_symbol(s, "WasDefined"), 0.0);
    EXPECT_EQ(string_symbol(s, "B"), "now a string");
}

TEST(Directives, IncludeViaLibraryPathWithItsOwnLocalScope) {
    ParseOptions o;
    o.library_paths = {"/no/such/dir", testing::data_dir() + "/lib"};
    Scene s = parse_ok(R"(
        #declare Outer = 1;
        #declare Shadow = 7;
        #include "scoping.inc"
        #ifdef (Hidden) #declare Leaked = 1; #end
        #declare Scaled = Scale_By(3, 4);
    )",
                       o);
    EXPECT_EQ(float_symbol(s, "Visible"), 10.0);
    EXPECT_EQ(float_symbol(s, "Outer"), 2.0);
    EXPECT_EQ(float_symbol(s, "Shadow"), 7.0);
    EXPECT_EQ(float_symbol(s, "FromInclude"), 100.0);
    EXPECT_EQ(s.symbols.count("Leaked"), 0u);
    EXPECT_EQ(float_symbol(s, "Scaled"), 12.0);
    // Symbols keep where they were declared.
    EXPECT_EQ(s.symbols.at("Visible").loc.file, testing::data_dir() + "/lib/scoping.inc");
    EXPECT_EQ(s.symbols.at("Visible").loc.line, 3);
}

TEST(Directives, IncludeLooksInTheIncludingFilesDirectoryFirst) {
    // main.pov in data/ includes lib/scoping.inc by a relative path.
    auto r = parse_scene_file(testing::data_dir() + "/includes_relative.pov", ParseOptions{});
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(float_symbol(*r, "Visible"), 10.0);
}

TEST(Directives, DeclaresFromOptionsAreDefinedBeforeParsing) {
    ParseOptions o;
    o.declares = {{"Mirage_Height", 2.5}};
    Scene s = parse_ok(R"(
        #ifndef (Mirage_Height) #declare Mirage_Height = 1; #end
        #ifndef (Mirage_Width) #declare Mirage_Width = 3; #end
        #declare Doubled = Mirage_Height * 2;
    )",
                       o);
    EXPECT_EQ(float_symbol(s, "Mirage_Height"), 2.5);
    EXPECT_EQ(float_symbol(s, "Mirage_Width"), 3.0);
    EXPECT_EQ(float_symbol(s, "Doubled"), 5.0);
    EXPECT_EQ(s.symbols.at("Mirage_Height").loc.file, "<command line>");
    EXPECT_EQ(s.symbols.count("image_width"), 0u);  // implicit, not a declaration
}

TEST(Directives, TopLevelSymbolsExportFloatsVectorsAndStrings) {
    Scene s = parse_ok(R"(
        #declare Mirage_Profile = "paper";
        #declare Mirage_Eye = <0, 1.5, -3>;
        #local Mirage_Tol = 0.5;
        #declare Colour = rgb 1;
        #declare Obj = sphere { 0, 1 }
        #macro M() #declare FromMacro = 1; #local NotGlobal = 2; #end
        M()
    )");
    EXPECT_EQ(string_symbol(s, "Mirage_Profile"), "paper");
    testing::expect_vec(testing::vector_symbol(s, "Mirage_Eye"), glm::dvec3(0, 1.5, -3));
    EXPECT_EQ(float_symbol(s, "Mirage_Tol"), 0.5);
    EXPECT_EQ(float_symbol(s, "FromMacro"), 1.0);
    EXPECT_EQ(s.symbols.count("Colour"), 0u);
    EXPECT_EQ(s.symbols.count("Obj"), 0u);
    EXPECT_EQ(s.symbols.count("NotGlobal"), 0u);
    EXPECT_EQ(s.symbols.at("Mirage_Eye").loc.line, 3);
    EXPECT_EQ(s.symbols.at("Mirage_Eye").loc.column, 18);
}

TEST(Directives, DebugAndWarningAreRecordedWithTheirPlace) {
    Scene s = parse_ok(
        "#declare A = 3;\n#debug concat(\"A=\", str(A, 0, 0), \"\\n\")\n"
        "  #warning \"careful\"\n");
    ASSERT_EQ(s.messages.size(), 2u);
    EXPECT_EQ(s.messages[0], "scene.pov:2:1: debug: A=3\n");
    EXPECT_EQ(s.messages[1], "scene.pov:3:3: warning: careful");
}

TEST(Directives, DirectivesBetweenTokensAndInsideExpressions) {
    Scene s = parse_ok(R"(
        #declare Big = 1;
        sphere { 0,
          #if (Big) 2 #else 1 #end
        }
        #declare V = <1, #if (Big) 5 #else 6 #end, 3>;
        #declare W = (1 + #if (Big) 10 #else 20 #end);
    )");
    ASSERT_EQ(s.primitives.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.primitives[0].shape).radius, 2.0);
    testing::expect_vec(testing::vector_symbol(s, "V"), glm::dvec3(1, 5, 3));
    EXPECT_EQ(float_symbol(s, "W"), 11.0);
}

TEST(Directives, DeclarationAssignsBeforeTheNextDirectiveRuns) {
    // A string needs no ';': the look for one must not run the #if before S is declared.
    Scene s = parse_ok("#declare S = \"a\"\n#if (strlen(S) = 1) #declare Ok = 1; #end\n");
    EXPECT_EQ(float_symbol(s, "Ok"), 1.0);
}

TEST(Directives, ArraysAreDeclaredBeforeTheNextDirectiveRuns) {
    // Neither needs a ';': looking past the array or the copied name must not run the
    // #declare that follows before the array exists (found parsing POV-Ray's sample scenes).
    Scene s = parse_ok(R"(
        #declare TG = array[2]
        #declare TG[0] = 5;
        #declare Init = array[2] { 1, 2 }
        #declare Sum = Init[0] + Init[1];
        #declare Copy = Init
        #declare CopySum = Copy[0] + Copy[1];
    )");
    EXPECT_EQ(float_symbol(s, "Sum"), 3.0);
    EXPECT_EQ(float_symbol(s, "CopySum"), 3.0);
}

TEST(Directives, AStrayHashIsIgnoredAsInPovRay) {
    Scene s = parse_ok("sphere { 0, 1 # }");
    EXPECT_EQ(s.primitives.size(), 1u);
}

TEST(Directives, VersionSetsTheLanguageVersion) {
    Scene s = parse_ok("#version 3.6;\n#declare V = version;");
    EXPECT_DOUBLE_EQ(float_symbol(s, "V"), 3.6);
    EXPECT_NE(parse_error("#version 3.8;").find("this scene needs POV-Ray 3.8"), std::string::npos);
    EXPECT_NE(parse_error("#version 3.1;").find("unsupported language version 3.10"),
              std::string::npos);
}

TEST(Directives, DefaultChangesLaterObjectsOnly) {
    Scene s = parse_ok(R"(
        sphere { 0, 1 }
        #default { finish { ambient 0.3 } pigment { rgb <1, 0, 0> } }
        sphere { 0, 2 }
    )");
    ASSERT_EQ(s.primitives.size(), 2u);
    testing::expect_vec(s.primitives[0].texture.finish.ambient, glm::dvec3(0.1));
    testing::expect_vec(s.primitives[1].texture.finish.ambient, glm::dvec3(0.3));
    testing::expect_vec(s.primitives[1].texture.pigment.colour.rgb, glm::dvec3(1, 0, 0));
}

}  // namespace
}  // namespace mirage
