// Reading an input file whole (a CSV table, a sounding, a font): only a regular file, and
// only up to a size, so that a device (/dev/zero), a pipe that never ends or a huge file
// gives a message instead of memory without end or a wait without end.
#pragma once

#include <cstddef>
#include <istream>
#include <string>

#include "util/result.h"

namespace mirage {

/// What an input file is, for messages: "a CSV table" ("PATH: is a directory, not a CSV
/// table").
struct InputKind {
    std::string what;  // "a CSV table", "a sounding", "a font"
    std::string many;  // "CSV tables", "soundings", "fonts" ("... are read from files")
    std::size_t max_bytes = std::size_t{64} << 20;
};

/// The bytes of the file at `path`, or an error naming it: missing ("cannot be opened: No such
/// file or directory"), a directory, not a regular file (a device, a pipe or a socket: never
/// opened, so a FIFO does not block), larger than kind.max_bytes (checked before reading and
/// while reading, so a file that grows meanwhile is cut at the limit) or unreadable.
Result<std::string> read_input_file(const std::string& path, const InputKind& kind);

/// Reads `in` to its end into `text`, in pieces, so that a file that grows meanwhile is still
/// cut at the limit: false as soon as `text` holds more than `max_bytes` bytes.
bool read_at_most(std::istream& in, std::size_t max_bytes, std::string& text);

/// "1.5 MiB", "12 KiB", "300 bytes": a size for messages.
std::string bytes_text(std::size_t bytes);

/// `text` for quoting in a message: at most `max_bytes` bytes, its ends kept around "..."
/// when it is longer, control bytes and bytes that are not ASCII as '?'.
std::string quote_cut(const std::string& text, std::size_t max_bytes = 60);

}  // namespace mirage
