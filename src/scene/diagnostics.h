// Error messages in the form users know from compilers:
//   scene.pov:12:7: unknown keyword 'spere'
//     included from main.pov:3:1
//   spere { <0, 1, 0>, 1 }
//   ^
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mirage {

/// Formats a message about `path`:`line`:`column`: the first line names the place and says what
/// is wrong, then one line per entry of `context` (e.g. "  included from scene.pov:3:1"), then
/// the source line and a caret under the column.  `source_line` may be empty (no caret then).
std::string format_diagnostic(std::string_view path, int line, int column, std::string_view message,
                              const std::vector<std::string>& context,
                              std::string_view source_line);

}  // namespace mirage
