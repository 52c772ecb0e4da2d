// File names as POV-Ray 3.7 takes them, in an .ini value and on its command line.  Its
// command line splits an option at spaces unless the value is in double quotes; an .ini value
// ends at a line end, a quoted one at the next '"'; a '\' in a file name is read as a string
// escape ("Illegal escape sequence"), and a byte outside ASCII is lost on the way to the file
// system ("Cannot open input file").
#pragma once

#include <string>

#include "util/result.h"

namespace mirage {

/// Why POV-Ray cannot take `path` as a file name, or "" when it can.
std::string povray_path_problem(const std::string& path);

/// Refuses `path` when POV-Ray cannot take it: "<path>: <what> holds <why>...".  `what` names
/// it for the user ("the scene", "--image", "the output folder (-o)").
Status check_povray_path(const std::string& path, const std::string& what);

/// `path` in double quotes: one value of an .ini or of a command-line option, spaces and ';'
/// included (check_povray_path first: a '"' cannot be inside).
std::string povray_quoted(const std::string& path);

}  // namespace mirage
