// Text from outside (file names, scene strings) made safe for where it is printed: a
// terminal, a comment line of a generated file.
#pragma once

#include <string>
#include <string_view>

namespace mirage {

/// `text` with every byte that could act on a terminal or break a line written as an escape:
/// control bytes as \n, \r, \t, \0 or \xNN (ESC as \x1b), DEL and bytes that are not part of
/// UTF-8 as \xNN, the C1 controls U+0080 to U+009F as \u0080...; a backslash stays as it is.
/// Printable ASCII and the rest of UTF-8 are kept.
std::string escape_control(std::string_view text);

/// The same with line ends kept: for a message of several lines printed on a terminal.
std::string escape_terminal(std::string_view text);

}  // namespace mirage
