// A list of command-line arguments as one word of hex digits, for a command line that passes
// through programs that would read it (GNU parallel's replacement strings, a remote shell):
// no byte of a file name can act there.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mirage {

/// Each argument's bytes in lower-case hex, each argument ended by "00".
std::string args_to_hex(const std::vector<std::string>& args);

/// The arguments back; nothing when `hex` is not such a word.
std::optional<std::vector<std::string>> args_from_hex(const std::string& hex);

}  // namespace mirage
