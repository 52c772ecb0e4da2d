// Diagnostic formatting, shared by the lexer and parser errors.
#include "scene/diagnostics.h"

#include <algorithm>

#include "scene/scene.h"

namespace mirage {

namespace {

constexpr std::size_t kEchoBytes = 120;     // a longer source line is cut around the column
constexpr std::size_t kMessageBytes = 400;  // a longer message is cut in its middle
constexpr std::size_t kContextEnds = 8;     // a longer chain of frames shows its 8 ends

bool continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// The length of the UTF-8 sequence that starts `text` (1 to 4), or 0 when it is none.
std::size_t utf8_length(std::string_view text) {
    const auto c = static_cast<unsigned char>(text[0]);
    const std::size_t n = c < 0x80           ? 1
                          : (c >> 5) == 0x6  ? 2
                          : (c >> 4) == 0xE  ? 3
                          : (c >> 3) == 0x1E ? 4
                                             : 0;
    if (n == 0 || n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k)
        if (!continuation(static_cast<unsigned char>(text[k]))) return 0;
    return n;
}

}  // namespace

std::string format_diagnostic(std::string_view path, int line, int column, std::string_view message,
                              const std::vector<std::string>& context,
                              std::string_view source_line) {
    std::string out;
    out += to_string(FileLoc{std::string(path), line, column}) + ": ";
    // A message quotes the scene's words; a word of 200 KB (or an #error of as many) is
    // quoted by its ends.
    if (message.size() > kMessageBytes) {
        std::size_t head = kMessageBytes / 2, tail = message.size() - kMessageBytes / 2;
        while (head > 0 && continuation(static_cast<unsigned char>(message[head]))) --head;
        while (tail < message.size() && continuation(static_cast<unsigned char>(message[tail])))
            ++tail;
        out += message.substr(0, head);
        out += " ... ";
        out += message.substr(tail);
    } else {
        out += message;
    }
    // The chain of macro calls and includes by its ends: an endless recursion stops a
    // thousand frames deep, and the frames that matter are the innermost and the outermost.
    const std::size_t n = context.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (n > 2 * kContextEnds && i == kContextEnds) {
            out += "\n  ... " + std::to_string(n - 2 * kContextEnds) + " more";
            i = n - kContextEnds - 1;
            continue;
        }
        out += '\n';
        out += context[i];
    }
    if (source_line.empty()) return out;
    // The line as shown: around the column when it is long, with "..." where it is cut, and a
    // '?' for every byte that is not text (a control character, broken UTF-8), so that a
    // binary file echoes as one short line.
    const std::size_t want = column > 1 ? static_cast<std::size_t>(column - 1) : 0;
    const std::size_t at = std::min(want, source_line.size());
    std::size_t begin = 0, end = source_line.size();
    if (end > kEchoBytes) {
        begin = at > kEchoBytes / 2 ? at - kEchoBytes / 2 : 0;
        end = std::min(source_line.size(), begin + kEchoBytes);
        while (begin < at && continuation(static_cast<unsigned char>(source_line[begin]))) ++begin;
        while (end < source_line.size() &&
               continuation(static_cast<unsigned char>(source_line[end])))
            ++end;
    }
    std::string shown = begin > 0 ? "..." : "";
    std::string caret = begin > 0 ? "   " : "";
    for (std::size_t i = begin; i < end;) {
        const char c = source_line[i];
        std::size_t n = utf8_length(source_line.substr(i, end - i));
        const bool text = n > 1 || (n == 1 && (c == '\t' || (c >= 0x20 && c != 0x7F)));
        if (text) {
            shown.append(source_line.substr(i, n));
        } else {
            shown += '?';
            n = 1;
        }
        // Keep tabs so that the caret lines up with the source line in any terminal.
        if (i < at) caret += c == '\t' ? '\t' : ' ';
        i += n;
    }
    if (end < source_line.size()) shown += "...";
    if (end == source_line.size())
        for (std::size_t i = end; i < want; ++i) caret += ' ';  // a column past the line's end
    out += '\n';
    out += shown;
    out += '\n';
    out += caret;
    out += '^';
    return out;
}

}  // namespace mirage
