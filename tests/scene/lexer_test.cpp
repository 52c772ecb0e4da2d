#include "scene/lexer.h"

#include <gtest/gtest.h>

#include "scene/keywords.h"

namespace mirage {
namespace {

SourceFile lex_ok(const std::string& text) {
    SourceFile file;
    file.path = "t.pov";
    file.text = text;
    auto error = lex_source(file);
    EXPECT_FALSE(error.has_value()) << (error ? error->message : "");
    return file;
}

LexError lex_error(const std::string& text) {
    SourceFile file;
    file.path = "t.pov";
    file.text = text;
    auto error = lex_source(file);
    EXPECT_TRUE(error.has_value());
    return error.value_or(LexError{});
}

TEST(Lexer, TokensCarryLineAndColumn) {
    SourceFile f = lex_ok("sphere {\n  <0, 1.5, -2>, .5\n}");
    ASSERT_EQ(f.tokens.size(), 14u);  // 13 tokens and the end of file
    EXPECT_EQ(f.tokens[0].kind, TokenKind::Identifier);
    EXPECT_EQ(f.tokens[0].text, "sphere");
    EXPECT_EQ(f.tokens[0].line, 1);
    EXPECT_EQ(f.tokens[0].column, 1);
    EXPECT_EQ(f.tokens[2].text, "<");
    EXPECT_EQ(f.tokens[2].line, 2);
    EXPECT_EQ(f.tokens[2].column, 3);
    EXPECT_EQ(f.tokens[5].kind, TokenKind::Number);
    EXPECT_EQ(f.tokens[5].number, 1.5);
    EXPECT_EQ(f.tokens[5].column, 7);
    EXPECT_EQ(f.tokens[7].text, "-");  // the sign is an operator, as in POV-Ray
    EXPECT_EQ(f.tokens[8].number, 2.0);
    EXPECT_EQ(f.tokens[11].number, 0.5);
    EXPECT_EQ(f.tokens[12].text, "}");
    EXPECT_EQ(f.tokens[12].line, 3);
    EXPECT_EQ(f.tokens.back().kind, TokenKind::EndOfFile);
}

TEST(Lexer, NumbersInPovRayForms) {
    SourceFile f = lex_ok("1e-3 2.5E+2 .25 7. 3e 12");
    ASSERT_GE(f.tokens.size(), 6u);
    EXPECT_DOUBLE_EQ(f.tokens[0].number, 1e-3);
    EXPECT_DOUBLE_EQ(f.tokens[1].number, 250.0);
    EXPECT_DOUBLE_EQ(f.tokens[2].number, 0.25);
    EXPECT_DOUBLE_EQ(f.tokens[3].number, 7.0);
    // "3e" without exponent digits is the number 3 and the identifier e.
    EXPECT_DOUBLE_EQ(f.tokens[4].number, 3.0);
    EXPECT_EQ(f.tokens[5].text, "e");
    EXPECT_DOUBLE_EQ(f.tokens[6].number, 12.0);
}

TEST(Lexer, PeriodAfterAnIdentifierIsPunctuation) {
    SourceFile f = lex_ok("V.x 2.x");
    ASSERT_EQ(f.tokens.size(), 6u);
    EXPECT_EQ(f.tokens[1].text, ".");
    EXPECT_EQ(f.tokens[2].text, "x");
    EXPECT_DOUBLE_EQ(f.tokens[3].number, 2.0);  // "2." is a number, then x
    EXPECT_EQ(f.tokens[4].text, "x");
}

TEST(Lexer, TwoCharacterOperators) {
    SourceFile f = lex_ok("a<=b>=c!=d<e>f=g!h");
    std::vector<std::string> texts;
    for (const RawToken& t : f.tokens) texts.push_back(t.text);
    std::vector<std::string> expected{"a", "<=", "b", ">=", "c", "!=", "d", "<",
                                      "e", ">",  "f", "=",  "g", "!",  "h", ""};
    EXPECT_EQ(texts, expected);
}

TEST(Lexer, CommentsNestAndLineCommentsEndAtNewline) {
    SourceFile f = lex_ok("a /* x /* nested */ still comment */ b // tail\nc");
    ASSERT_EQ(f.tokens.size(), 4u);
    EXPECT_EQ(f.tokens[0].text, "a");
    EXPECT_EQ(f.tokens[1].text, "b");
    EXPECT_EQ(f.tokens[2].text, "c");
    EXPECT_EQ(f.tokens[2].line, 2);
}

TEST(Lexer, StringsKeepEscapesForLaterButUnquote) {
    SourceFile f = lex_ok(R"("a\"b\n" "C:\dir")");
    ASSERT_EQ(f.tokens.size(), 3u);
    EXPECT_EQ(f.tokens[0].kind, TokenKind::String);
    EXPECT_EQ(f.tokens[0].text, "a\"b\\n");
    EXPECT_EQ(f.tokens[1].text, "C:\\dir");  // file names keep their backslashes
    std::size_t bad = 0;
    EXPECT_EQ(unescape_string(f.tokens[0].text, &bad), std::optional<std::string>("a\"b\n"));
    EXPECT_EQ(unescape_string("tab\\there \\u0041", &bad),
              std::optional<std::string>("tab\there A"));
    EXPECT_EQ(unescape_string("C:\\dir", &bad), std::nullopt);
    EXPECT_EQ(bad, 2u);
}

TEST(Lexer, StringsMaySpanLines) {
    SourceFile f = lex_ok("\"one\ntwo\" x");
    EXPECT_EQ(f.tokens[0].text, "one\ntwo");
    EXPECT_EQ(f.tokens[1].line, 2);
}

TEST(Lexer, UnterminatedCommentPointsAtItsStart) {
    LexError e = lex_error("a\n  /* one /* two */ \n b");
    EXPECT_EQ(e.message, "unterminated comment: no '*/' before the end of the file");
    EXPECT_EQ(e.line, 2);
    EXPECT_EQ(e.column, 3);
}

TEST(Lexer, UnterminatedStringPointsAtItsStart) {
    LexError e = lex_error("#debug \"hello\n");
    EXPECT_EQ(e.message, "unterminated string: no closing '\"' before the end of the file");
    EXPECT_EQ(e.line, 1);
    EXPECT_EQ(e.column, 8);
}

TEST(Lexer, IllegalCharacterAndDoublePeriod) {
    LexError e = lex_error("a\n b \x01");
    EXPECT_EQ(e.message, "illegal character (byte 0x01)");
    EXPECT_EQ(e.line, 2);
    EXPECT_EQ(e.column, 4);
    LexError d = lex_error("1.2.3");
    EXPECT_EQ(d.message, "unexpected second '.' in a number");
}

TEST(Lexer, LineTextStripsLineBreaks) {
    SourceFile f = lex_ok("first\r\nsecond\nthird");
    EXPECT_EQ(f.line_text(1), "first");
    EXPECT_EQ(f.line_text(2), "second");
    EXPECT_EQ(f.line_text(3), "third");
    EXPECT_EQ(f.line_text(4), "");
}

TEST(Keywords, ReservedWordsOfPovRay37) {
    for (const char* w : {"sphere", "rgb", "x", "t", "pi", "global_settings", "light_source",
                          "aa_level", "yes", "vturbulence", "colour_map", "sky_sphere"}) {
        EXPECT_TRUE(is_reserved_word(w)) << w;
    }
    // image_width is an identifier POV-Ray declares, tau came with 3.8.
    for (const char* w : {"image_width", "tau", "Sphere", "spere", "White", ""}) {
        EXPECT_FALSE(is_reserved_word(w)) << w;
    }
}

}  // namespace
}  // namespace mirage
