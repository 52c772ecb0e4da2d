// Writing outputs so that a failure leaves every existing file as it was: the content goes
// to a temporary name in the same directory and is renamed over the target at the end; a
// device or a FIFO is written in place instead (util/output_path.h).
#pragma once

#include <string>
#include <string_view>

#include "util/result.h"

namespace mirage {

/// Writes `content` to `path` atomically (temporary file + rename).  The message of an error
/// names the path and the reason.
Status write_file_atomic(const std::string& path, std::string_view content);

/// A temporary name beside `path` for a file to be renamed into place later.
std::string temporary_name_for(const std::string& path);

/// Renames `from` to `to` (replacing it; a device or a FIFO gets `from`'s content written into
/// it instead); on failure removes `from`.
Status commit_file(const std::string& from, const std::string& to);

/// Reads a whole file.
Result<std::string> read_file(const std::string& path);

}  // namespace mirage
