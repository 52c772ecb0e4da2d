// POV-Ray 3.7's tokenizer (source/backend/parser/tokenize.cpp), character level only.
#include "scene/lexer.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace mirage {
namespace {

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Lexer {
  public:
    explicit Lexer(SourceFile& file) : file_(file), text_(file.text) {}

    std::optional<LexError> run() {
        compute_line_starts();
        // A UTF-8 byte order mark is not part of the scene.
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") advance(3);
        while (true) {
            if (auto error = skip_space_and_comments()) return error;
            if (at_end()) break;
            if (auto error = lex_token()) return error;
        }
        RawToken eof;
        eof.kind = TokenKind::EndOfFile;
        // The end of file sits just after the last character, for carets.
        eof.line = line_;
        eof.column = column_;
        file_.tokens.push_back(eof);
        return std::nullopt;
    }

  private:
    void compute_line_starts() {
        file_.line_starts.clear();
        file_.line_starts.push_back(0);
        for (std::size_t i = 0; i < text_.size(); ++i) {
            if (text_[i] == '\n') file_.line_starts.push_back(i + 1);
        }
    }

    bool at_end() const { return pos_ >= text_.size(); }
    char peek(std::size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }
    void advance(std::size_t n = 1) {
        for (std::size_t i = 0; i < n && pos_ < text_.size(); ++i) {
            if (text_[pos_] == '\n') {
                ++line_;
                column_ = 1;
            } else {
                ++column_;
            }
            ++pos_;
        }
    }

    LexError error_at(int line, int column, std::string message) const {
        return LexError{std::move(message), line, column};
    }

    std::optional<LexError> skip_space_and_comments() {
        while (!at_end()) {
            char c = peek();
            // POV-Ray ignores Ctrl-Z and NUL as well as white space.
            if (std::isspace(static_cast<unsigned char>(c)) || c == '\x1a' || c == '\0') {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (!at_end() && peek() != '\n') advance();
            } else if (c == '/' && peek(1) == '*') {
                if (auto error = skip_block_comment()) return error;
            } else {
                break;
            }
        }
        return std::nullopt;
    }

    // Block comments nest, as in POV-Ray.
    std::optional<LexError> skip_block_comment() {
        struct Open {
            int line, column;
        };
        std::vector<Open> open;
        open.push_back({line_, column_});
        advance(2);
        while (!open.empty()) {
            if (at_end()) {
                return error_at(open.front().line, open.front().column,
                                "unterminated comment: no '*/' before the end of the file");
            }
            if (peek() == '*' && peek(1) == '/') {
                advance(2);
                open.pop_back();
            } else if (peek() == '/' && peek(1) == '*') {
                open.push_back({line_, column_});
                advance(2);
            } else {
                advance();
            }
        }
        return std::nullopt;
    }

    void push(TokenKind kind, std::string text, int line, int column, double number = 0.0) {
        RawToken token;
        token.kind = kind;
        token.text = std::move(text);
        token.number = number;
        token.line = line;
        token.column = column;
        file_.tokens.push_back(std::move(token));
    }

    std::optional<LexError> lex_token() {
        const int line = line_, column = column_;
        const char c = peek();
        if (is_ident_start(c)) {
            std::size_t start = pos_;
            while (!at_end() && is_ident_char(peek())) advance();
            push(TokenKind::Identifier, std::string(text_.substr(start, pos_ - start)), line,
                 column);
            return std::nullopt;
        }
        if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return lex_number();
        if (c == '"') return lex_string();
        // Two-character operators first.
        if ((c == '<' || c == '>' || c == '!') && peek(1) == '=') {
            push(TokenKind::Punct, std::string{c, '='}, line, column);
            advance(2);
            return std::nullopt;
        }
        static constexpr std::string_view kSingle = "{}()[]<>=,;.+-*/!?:&|#@`\\$^%'~";
        if (kSingle.find(c) != std::string_view::npos) {
            push(TokenKind::Punct, std::string(1, c), line, column);
            advance();
            return std::nullopt;
        }
        char code[8];
        std::snprintf(code, sizeof code, "%02x", static_cast<unsigned char>(c));
        return error_at(line, column, std::string("illegal character (byte 0x") + code + ")");
    }

    // Digits, an optional fraction and an optional exponent; a second '.' is an error, as in
    // POV-Ray's Read_Float.
    std::optional<LexError> lex_number() {
        const int line = line_, column = column_;
        std::size_t start = pos_;
        while (is_digit(peek())) advance();
        bool had_point = false;
        if (peek() == '.') {
            had_point = true;
            advance();
            while (is_digit(peek())) advance();
        }
        bool had_exponent = false;
        if (peek() == 'e' || peek() == 'E') {
            // Only an exponent when digits follow (with an optional sign).
            std::size_t digits_at = (peek(1) == '+' || peek(1) == '-') ? 2 : 1;
            if (is_digit(peek(digits_at))) {
                had_exponent = true;
                advance(digits_at);
                while (is_digit(peek())) advance();
            }
        }
        if (peek() == '.' && (had_point || had_exponent)) {
            return error_at(line_, column_, "unexpected second '.' in a number");
        }
        std::string text(text_.substr(start, pos_ - start));
        double value = std::strtod(text.c_str(), nullptr);
        push(TokenKind::Number, text, line, column, value);
        return std::nullopt;
    }

    // POV-Ray keeps escapes in the literal (they are processed where the string is used,
    // except in file names) but for \" which ends up as a plain quote.
    std::optional<LexError> lex_string() {
        const int line = line_, column = column_;
        advance();  // opening quote
        std::string value;
        while (true) {
            if (at_end()) {
                return error_at(line, column,
                                "unterminated string: no closing '\"' before the end of the file");
            }
            char c = peek();
            if (c == '"') {
                advance();
                break;
            }
            if (c == '\\') {
                char next = peek(1);
                if (next == '\n' || next == '\r') {
                    return error_at(line_, column_,
                                    "unterminated string: '\\' at the end of a line");
                }
                if (pos_ + 1 >= text_.size()) {
                    return error_at(
                        line, column,
                        "unterminated string: no closing '\"' before the end of the file");
                }
                if (next == '"') {
                    value += '"';
                } else {
                    value += '\\';
                    value += next;
                }
                advance(2);
                continue;
            }
            value += c;
            advance();
        }
        push(TokenKind::String, std::move(value), line, column);
        return std::nullopt;
    }

    SourceFile& file_;
    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

}  // namespace

void append_utf8(std::string& out, unsigned code) {
    if (code < 0x80) {
        out += static_cast<char>(code);
    } else if (code < 0x800) {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
        out += static_cast<char>(0xE0 | ((code >> 12) & 0x0F));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    }
}

std::string_view SourceFile::line_text(int line) const {
    if (line < 1 || static_cast<std::size_t>(line) > line_starts.size()) return {};
    std::size_t begin = line_starts[line - 1];
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    if (end > begin && text[end - 1] == '\r') --end;
    return std::string_view(text).substr(begin, end - begin);
}

std::optional<LexError> lex_source(SourceFile& file) {
    file.tokens.clear();
    return Lexer(file).run();
}

std::optional<std::string> unescape_string(std::string_view literal, std::size_t* error_offset) {
    std::string out;
    for (std::size_t i = 0; i < literal.size(); ++i) {
        char c = literal[i];
        if (c != '\\') {
            out += c;
            continue;
        }
        if (i + 1 >= literal.size()) {
            out += '\\';
            break;
        }
        char e = literal[++i];
        switch (e) {
            case 'a':
                out += '\a';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'v':
                out += '\v';
                break;
            case '\'':
                out += '\'';
                break;
            case '\\':
                out += '\\';
                break;
            case '"':
                out += '"';
                break;
            case 'u': {
                unsigned code = 0;
                bool ok = i + 4 < literal.size();  // four hex digits follow the 'u'
                for (int k = 1; ok && k <= 4; ++k) {
                    char h = literal[i + k];
                    if (!std::isxdigit(static_cast<unsigned char>(h))) {
                        ok = false;
                        break;
                    }
                    code = code * 16 + static_cast<unsigned>(std::isdigit(h)
                                                                 ? h - '0'
                                                                 : (std::tolower(h) - 'a' + 10));
                }
                if (!ok) {
                    if (error_offset) *error_offset = i - 1;
                    return std::nullopt;
                }
                append_utf8(out, code);
                i += 4;
                break;
            }
            default:
                if (error_offset) *error_offset = i - 1;
                return std::nullopt;
        }
    }
    return out;
}

}  // namespace mirage
