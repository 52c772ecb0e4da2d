// Parts of file names.
#pragma once

#include <string>

namespace mirage {

/// The extension of `path`'s last component with its dot, in lower case (".png"), or "".
std::string lower_extension(const std::string& path);

}  // namespace mirage
