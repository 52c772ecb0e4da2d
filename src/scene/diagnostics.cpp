// Diagnostic formatting, shared by the lexer and parser errors.
#include "scene/diagnostics.h"

#include "scene/scene.h"

namespace mirage {

std::string format_diagnostic(std::string_view path, int line, int column, std::string_view message,
                              const std::vector<std::string>& context,
                              std::string_view source_line) {
    std::string out;
    out += to_string(FileLoc{std::string(path), line, column}) + ": ";
    out += message;
    for (const std::string& c : context) {
        out += '\n';
        out += c;
    }
    if (!source_line.empty()) {
        out += '\n';
        out += source_line;
        out += '\n';
        // Keep tabs so that the caret lines up with the source line in any terminal.
        for (int i = 0; i + 1 < column; ++i) {
            bool tab = static_cast<std::size_t>(i) < source_line.size() && source_line[i] == '\t';
            out += tab ? '\t' : ' ';
        }
        out += '^';
    }
    return out;
}

}  // namespace mirage
