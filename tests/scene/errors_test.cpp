// The exact text of the parser's error messages: place, message, context, source line, caret.
#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::data_dir;
using testing::parse_error;

TEST(Errors, UnknownKeyword) {
    EXPECT_EQ(parse_error("#version 3.7;\nunion {\n    spere { <0, 1, 0>, 1 }\n}\n"),
              "scene.pov:3:5: unknown keyword 'spere'\n"
              "    spere { <0, 1, 0>, 1 }\n"
              "    ^");
    EXPECT_EQ(parse_error("spere { 0, 1 }"),
              "scene.pov:1:1: unknown keyword 'spere'\n"
              "spere { 0, 1 }\n"
              "^");
}

TEST(Errors, UnterminatedComment) {
    EXPECT_EQ(parse_error("sphere { 0, 1 }\n  /* never /* nested */ closed\n"),
              "scene.pov:2:3: unterminated comment: no '*/' before the end of the file\n"
              "  /* never /* nested */ closed\n"
              "  ^");
}

TEST(Errors, UnterminatedString) {
    EXPECT_EQ(parse_error("#debug \"hello\n"),
              "scene.pov:1:8: unterminated string: no closing '\"' before the end of the file\n"
              "#debug \"hello\n"
              "       ^");
}

TEST(Errors, MissingBrace) {
    EXPECT_EQ(parse_error("sphere { <0, 1, 0>, 1\n  pigment { rgb 1 }\nbox { 0, 1 }\n"),
              "scene.pov:3:1: expected '}' to close 'sphere' opened at 1:1, got 'box'\n"
              "box { 0, 1 }\n"
              "^");
    EXPECT_EQ(parse_error("sphere { 0, 1"),
              "scene.pov:1:14: expected '}' to close 'sphere' opened at 1:1, got end of file\n"
              "sphere { 0, 1\n"
              "             ^");
    EXPECT_EQ(parse_error("sphere { 0, 1 pigment { rgb 1 }"),
              "scene.pov:1:32: expected '}' to close 'sphere' opened at 1:1, got end of file\n"
              "sphere { 0, 1 pigment { rgb 1 }\n"
              "                               ^");
}

TEST(Errors, WrongType) {
    EXPECT_EQ(parse_error("sphere { <0, 1, 0>, <1, 2, 3> }"),
              "scene.pov:1:21: expected a float, got a vector\n"
              "sphere { <0, 1, 0>, <1, 2, 3> }\n"
              "                    ^");
    EXPECT_EQ(parse_error("#declare C = rgb 1;\nsphere { C, 1 }"),
              "scene.pov:2:10: expected a vector, got a colour\n"
              "sphere { C, 1 }\n"
              "         ^");
    EXPECT_EQ(parse_error("#declare S = \"s\";\nsphere { 0, S }"),
              "scene.pov:2:13: expected a numeric expression, got string identifier 'S'\n"
              "sphere { 0, S }\n"
              "            ^");
}

TEST(Errors, UndefinedIdentifier) {
    EXPECT_EQ(parse_error("sphere { 0, Radius }"),
              "scene.pov:1:13: undefined identifier 'Radius'\n"
              "sphere { 0, Radius }\n"
              "            ^");
}

TEST(Errors, IncludeNotFoundListsSearchedDirectories) {
    ParseOptions o;
    o.library_paths = {"/no/such/dir", "/another"};
    EXPECT_EQ(parse_error("#include \"nothere.inc\"", o),
              "scene.pov:1:10: cannot find include file 'nothere.inc' (searched: ., "
              "/no/such/dir, /another)\n"
              "#include \"nothere.inc\"\n"
              "         ^");
}

TEST(Errors, ErrorsInIncludedFilesShowTheIncludeChain) {
    ParseOptions o;
    o.library_paths = {data_dir()};
    std::string inc = data_dir() + "/bad_include.inc";
    EXPECT_EQ(parse_error("// main\n#include \"include_bad_include.inc\"\n", o),
              inc + ":3:1: unknown keyword 'spere'\n" + "  included from " + data_dir() +
                  "/include_bad_include.inc:2:1\n" + "  included from scene.pov:2:1\n" +
                  "spere { <0, 2, 0>, 1 }\n" + "^");
}

TEST(Errors, ErrorInAMacroBodyNamesTheCall) {
    EXPECT_EQ(parse_error("#macro Ball(R)\n  sphere { 0, R, 1 }\n#end\nBall(<1, 2, 3>)\n"),
              "scene.pov:2:15: expected a float, got a vector\n"
              "  in macro 'Ball' called from scene.pov:4:1\n"
              "  sphere { 0, R, 1 }\n"
              "              ^");
}

TEST(Errors, ErrorDirective) {
    EXPECT_EQ(
        parse_error("#declare A = 1;\n#if (A > 0)\n  #error concat(\"A is \", str(A, 0, 0))\n#end"),
        "scene.pov:3:3: #error: A is 1\n"
        "  #error concat(\"A is \", str(A, 0, 0))\n"
        "  ^");
}

TEST(Errors, DivisionByZero) {
    EXPECT_EQ(parse_error("#declare A = 1 / (2 - 2);"),
              "scene.pov:1:16: division by zero\n"
              "#declare A = 1 / (2 - 2);\n"
              "               ^");
    EXPECT_NE(parse_error("#declare A = <1, 2, 3> / <1, 0, 1>;").find("division by zero"),
              std::string::npos);
    EXPECT_NE(parse_error("#declare A = mod(1, 0);").find("division by zero"), std::string::npos);
}

TEST(Errors, WrongMacroArgumentCount) {
    EXPECT_EQ(parse_error("#macro M(A, B) (A + B) #end\n#declare X = M(1);"),
              "scene.pov:2:14: macro 'M' expects 2 arguments, got 1 (declared at 1:8)\n"
              "#declare X = M(1);\n"
              "             ^");
    EXPECT_EQ(parse_error("#macro M(A) (A) #end\n#declare X = M(1, 2, 3);"),
              "scene.pov:2:14: macro 'M' expects 1 argument, got 3 (declared at 1:8)\n"
              "#declare X = M(1, 2, 3);\n"
              "             ^");
}

TEST(Errors, MissingSemicolonAfterAFloatDeclaration) {
    EXPECT_EQ(parse_error("#declare A = 1\nsphere { 0, A }"),
              "scene.pov:2:1: expected ';' after the value of 'A', got 'sphere'\n"
              "sphere { 0, A }\n"
              "^");
}

TEST(Errors, UnbalancedDirectives) {
    EXPECT_EQ(parse_error("#if (1)\n  sphere { 0, 1 }\n"),
              "scene.pov:3:1: expected '#end' to close '#if' opened at 1:1, got end of file");
    EXPECT_EQ(parse_error("sphere { 0, 1 }\n#end\n"),
              "scene.pov:2:1: #end without #if, #ifdef, #ifndef, #while, #for, #switch or #macro\n"
              "#end\n"
              "^");
    EXPECT_EQ(parse_error("#while (1)\n#declare A = 1;\n"),
              "scene.pov:3:1: expected '#end' to close '#while' opened at 1:1, got end of file");
}

TEST(Errors, UnsupportedInStrictMode) {
    EXPECT_EQ(parse_error("julia_fractal { <1, 0, 0, 0> }"),
              "scene.pov:1:1: unsupported object 'julia_fractal'\n"
              "julia_fractal { <1, 0, 0, 0> }\n"
              "^");
    EXPECT_EQ(parse_error("sphere { 0, 1 photons { target } }"),
              "scene.pov:1:15: unsupported modifier 'photons' in 'sphere'\n"
              "sphere { 0, 1 photons { target } }\n"
              "              ^");
    EXPECT_EQ(parse_error("light_source { 0, 1 looks_like { sphere { 0, 1 } } }"),
              "scene.pov:1:21: unsupported light source modifier 'looks_like' (only point "
              "lights)\n"
              "light_source { 0, 1 looks_like { sphere { 0, 1 } } }\n"
              "                    ^");
    EXPECT_EQ(parse_error("sphere { 0, 1 pigment { julia <0.3, 0.5>, 30 } }"),
              "scene.pov:1:25: unsupported pattern 'julia'\n"
              "sphere { 0, 1 pigment { julia <0.3, 0.5>, 30 } }\n"
              "                        ^");
    EXPECT_EQ(parse_error("global_settings { radiosity { } }"),
              "scene.pov:1:19: unsupported global setting 'radiosity'\n"
              "global_settings { radiosity { } }\n"
              "                  ^");
}

TEST(Errors, ReservedWordsCannotBeDeclared) {
    EXPECT_EQ(parse_error("#declare sphere = 1;"),
              "scene.pov:1:10: cannot #declare 'sphere': it is a reserved word\n"
              "#declare sphere = 1;\n"
              "         ^");
}

TEST(Errors, AnArrayElementOfTheWrongKind) {
    EXPECT_EQ(parse_error("#declare A = array[2] { sphere { 0, 1 }, 5 }\nobject { A[1] }"),
              "scene.pov:2:10: expected an object, got float\n"
              "object { A[1] }\n"
              "         ^");
}

TEST(Errors, AMacroNameRedeclaredBeforeItsCallRuns) {
    // The look for ';' after the string defers the call; by then M is a string.
    EXPECT_NE(parse_error("#macro M() 1 #end\n#declare M = \"s\" M sphere { 0, 1 }")
                  .find("expected an object, camera, light_source or directive, got string "
                        "identifier 'M'"),
              std::string::npos);
}

TEST(Errors, MissingFileIsReportedWithItsPath) {
    auto r = parse_scene_file(data_dir() + "/no_such_scene.pov", ParseOptions{});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(),
              data_dir() + "/no_such_scene.pov: cannot be opened: No such file or directory");
}

}  // namespace
}  // namespace mirage
