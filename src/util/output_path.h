// Where an output named by the user goes.  A regular file, or a name not taken, is replaced
// by renaming a finished temporary file onto it; a character device or a FIFO (or a link to
// one) and "-" (the standard output) are written in place as a stream, never renamed onto,
// so that `--svg /dev/null` or a pipe stays what it was.  A directory, a block device (a disk)
// and a socket are refused by name.
#pragma once

#include <string>
#include <string_view>

#include "util/result.h"

namespace mirage {

struct OutputPath {
    std::string name;    // as given, for messages
    std::string target;  // the file to rename onto (a link followed), or the stream to write
    bool stream = false;
};

/// Resolves `path` as above; an error names it and says why it cannot be written.
Result<OutputPath> resolve_output_path(const std::string& path);

/// A temporary name for content bound for `out`: beside its target (same directory, same
/// extension, so that the rename stays on one file system and the extension still tells the
/// format), or for a stream in the temporary directory.  `tag` tells uses apart.
std::string temporary_for(const OutputPath& out, const char* tag = ".tmp");

/// Writes `content` to the stream `out` (opened without creating or truncating anything).
Status write_stream(const OutputPath& out, std::string_view content);

/// Copies the file `from` into the stream `out`, then removes `from` (also on failure).
Status copy_to_stream(const std::string& from, const OutputPath& out);

}  // namespace mirage
