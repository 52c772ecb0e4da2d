// Where a mirage scene's #include files are looked for: the paths every command that reads
// a scene uses, after the user's own -L directories.
#pragma once

#include <string>
#include <vector>

namespace mirage {

/// The scene file's directory, the project's pov_includes (mirage.inc; the build names it
/// with MIRAGE_POV_INCLUDES) and POV-Ray 3.7's standard include directory, in that order.
std::vector<std::string> default_library_paths(const std::string& scene);

}  // namespace mirage
