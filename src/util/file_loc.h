// A place in a source file, and the "file:line:column" every message names it by.
#pragma once

#include <string>

namespace mirage {

/// A place in a source file, 1-based line and column (columns count bytes).
struct FileLoc {
    std::string file;
    int line = 0;
    int column = 0;
};

/// "file:line:column" as messages name a place ("file" alone when the line is not known).
inline std::string to_string(const FileLoc& loc) {
    if (loc.line <= 0) return loc.file;
    return loc.file + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column);
}

/// "file:line:column: ", the prefix of a message about `loc`, or "" when it has no file.
inline std::string place_prefix(const FileLoc& loc) {
    return loc.file.empty() ? std::string() : to_string(loc) + ": ";
}

/// The prefix of a message about something at `loc` that may have no place of its own (the
/// camera of a scene that declares none): `loc`, else `file`.
inline std::string place_prefix(const FileLoc& loc, const std::string& file) {
    return (loc.file.empty() ? file : to_string(loc)) + ": ";
}

}  // namespace mirage
