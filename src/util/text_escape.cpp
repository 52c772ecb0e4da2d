#include "util/text_escape.h"

#include <cstdio>

namespace mirage {

namespace {

/// The length of the UTF-8 sequence that starts at `i` (0 when none does: a stray byte, an
/// overlong form, a surrogate or a code point past U+10FFFF), and its code point.
std::size_t utf8_sequence(std::string_view s, std::size_t i, unsigned& code) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned c = b(i);
    std::size_t n;
    if (c >= 0xC2 && c <= 0xDF) {
        n = 2, code = c & 0x1F;
    } else if (c >= 0xE0 && c <= 0xEF) {
        n = 3, code = c & 0x0F;
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4, code = c & 0x07;
    } else {
        return 0;
    }
    if (i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((b(i + k) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (b(i + k) & 0x3F);
    }
    if ((n == 3 && (code < 0x800 || (code >= 0xD800 && code <= 0xDFFF))) ||
        (n == 4 && (code < 0x10000 || code > 0x10FFFF)))
        return 0;
    return n;
}

std::string hex_byte(unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", c);
    return buf;
}

std::string escape(std::string_view text, bool keep_newlines) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
            ++i;
        } else if (c == '\n' && keep_newlines) {
            out += '\n';
            ++i;
        } else if (c < 0x80) {
            switch (c) {
                case '\n':
                    out += "\\n";
                    break;
                case '\r':
                    out += "\\r";
                    break;
                case '\t':
                    out += "\\t";
                    break;
                case '\0':
                    out += "\\0";
                    break;
                default:
                    out += hex_byte(c);
            }
            ++i;
        } else {
            unsigned code = 0;
            const std::size_t n = utf8_sequence(text, i, code);
            if (n == 0) {
                out += hex_byte(c);
                ++i;
            } else if (code <= 0x9F) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", code);
                out += buf;
                i += n;
            } else {
                out.append(text.substr(i, n));
                i += n;
            }
        }
    }
    return out;
}

}  // namespace

std::string escape_control(std::string_view text) { return escape(text, false); }

std::string escape_terminal(std::string_view text) { return escape(text, true); }

}  // namespace mirage
