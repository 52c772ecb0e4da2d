#include "util/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "util/output_path.h"

namespace mirage {

std::string temporary_name_for(const std::string& path) {
    return path + ".tmp" + std::to_string(::getpid());
}

Status commit_file(const std::string& from, const std::string& to) {
    auto out = resolve_output_path(to);
    if (!out) {
        std::remove(from.c_str());
        return out.error();
    }
    if (out->stream) return copy_to_stream(from, *out);
    if (std::rename(from.c_str(), out->target.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(from.c_str());
        return make_error(to + ": cannot write: " + reason);
    }
    return Ok{};
}

Status write_file_atomic(const std::string& path, std::string_view content) {
    auto out = resolve_output_path(path);
    if (!out) return out.error();
    if (out->stream) return write_stream(*out, content);
    const std::string tmp = temporary_for(*out);
    {
        std::ofstream file(tmp, std::ios::binary | std::ios::trunc);
        if (!file) return make_error(path + ": cannot write: " + std::strerror(errno));
        file.write(content.data(), static_cast<std::streamsize>(content.size()));
        file.flush();
        if (!file) {
            const std::string reason = std::strerror(errno);
            std::remove(tmp.c_str());
            return make_error(path + ": cannot write: " + reason);
        }
    }
    return commit_file(tmp, path);
}

Result<std::string> read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(path + ": cannot open: " + std::strerror(errno));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

}  // namespace mirage
