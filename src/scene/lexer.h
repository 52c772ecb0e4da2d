// The lexer of POV-Ray's scene language: turns a file's text into raw tokens (identifiers,
// numbers, strings, punctuation), each with its line and column.  Directives, macros and
// keywords are the parser's business; the lexer only knows the characters.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mirage {

enum class TokenKind {
    Identifier,  ///< a name: keyword or identifier, told apart by the parser
    Number,      ///< a float literal; `number` holds its value
    String,      ///< a string literal; `text` holds it with escapes still unprocessed
    Punct,  ///< punctuation, `text` is one of { } ( ) [ ] < > <= >= = != , ; . + - * / ! ? : & | #
            ///< and the rare @ ` \ $ ^ % ' ~
    EndOfFile,
};

/// One token as written, with its 1-based line and column (columns count bytes).
struct RawToken {
    TokenKind kind = TokenKind::EndOfFile;
    std::string text;
    double number = 0.0;
    int line = 0;
    int column = 0;
};

/// A source file and its tokens; the last token is always EndOfFile.
struct SourceFile {
    std::string path;  // as shown in messages
    std::string text;
    std::vector<std::size_t> line_starts;  // byte offset of each line's first character
    std::vector<RawToken> tokens;

    /// The text of a 1-based line, without its line break ("" when out of range).
    std::string_view line_text(int line) const;
};

/// A lexical error: what went wrong and where it started.
struct LexError {
    std::string message;
    int line = 0;
    int column = 0;
};

/// Splits `file.text` into `file.tokens` (and fills `line_starts`) following POV-Ray 3.7's
/// tokenizer: `//` and nested `/* */` comments, string literals that may span lines, numbers
/// such as `1`, `1.5`, `.5`, `1e-3`, `2.` and the punctuation above.  Returns the first error.
std::optional<LexError> lex_source(SourceFile& file);

/// Processes the escapes of a string literal as POV-Ray does for strings that are not file
/// names: \a \b \f \n \r \t \v \\ \' \" and \uXXXX.  On a bad escape returns the offset of its
/// backslash in `error_offset` and std::nullopt.
std::optional<std::string> unescape_string(std::string_view literal, std::size_t* error_offset);

/// Appends a character of the Basic Multilingual Plane (`code` <= 0xFFFF: what \uXXXX and
/// chr() can give) to `out` as UTF-8.
void append_utf8(std::string& out, unsigned code);

}  // namespace mirage
