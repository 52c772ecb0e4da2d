#include "util/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace mirage {

std::string temporary_name_for(const std::string& path) {
    return path + ".tmp" + std::to_string(::getpid());
}

Status commit_file(const std::string& from, const std::string& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(from.c_str());
        return make_error(to + ": cannot write: " + reason);
    }
    return Ok{};
}

Status write_file_atomic(const std::string& path, std::string_view content) {
    const std::string tmp = temporary_name_for(path);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) return make_error(path + ": cannot write: " + std::strerror(errno));
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            return make_error(path + ": write failed: " + std::strerror(errno));
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
