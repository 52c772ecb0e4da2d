#include "util/output_path.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace mirage {

namespace fs = std::filesystem;

namespace {

/// What a name that exists is: nullptr for a regular file (or a link to one), else what it is.
const char* kind_of(mode_t mode) {
    if (S_ISREG(mode)) return nullptr;
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISFIFO(mode)) return "a FIFO";
    return "not a regular file";
}

Status write_all(int fd, std::string_view data, const std::string& name) {
    while (!data.empty()) {
        const ssize_t n = ::write(fd, data.data(), data.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            return make_error(name + ": cannot write: " + std::strerror(errno));
        }
        data.remove_prefix(static_cast<std::size_t>(n));
    }
    return Ok{};
}

}  // namespace

Result<OutputPath> resolve_output_path(const std::string& path) {
    OutputPath out{path, path, false};
    if (path.empty()) return make_error("an output named '': give a file name");
    if (path == "-") {
        out.stream = true;
        return out;
    }
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return out;  // a new name
    if (S_ISLNK(st.st_mode)) {
        // Written where the link leads: a link to a device stays a link to that device, a link
        // to a file gets new content in that file, a link to no file makes it (as a shell's
        // '>' would).
        fs::path p = path;
        for (int hops = 0; S_ISLNK(st.st_mode); ++hops) {
            std::error_code ec;
            const fs::path to = fs::read_symlink(p, ec);
            if (ec) return make_error(path + ": cannot follow the link: " + ec.message());
            if (hops == 40) return make_error(path + ": more than 40 links in a row");
            p = (to.is_absolute() ? to : p.parent_path() / to).lexically_normal();
            if (::lstat(p.c_str(), &st) != 0) {
                out.target = p.string();
                return out;
            }
        }
        out.target = p.string();
    }
    const char* kind = kind_of(st.st_mode);
    if (!kind) return out;
    if (S_ISDIR(st.st_mode)) return make_error(path + ": is a directory; an output must be a file");
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
        out.stream = true;
        return out;
    }
    return make_error(path + ": is " + kind +
                      "; an output must be a file, a character device or a FIFO");
}

std::string temporary_for(const OutputPath& out, const char* tag) {
    static int counter = 0;
    const fs::path p(out.target);
    std::string name = ".";
    name += out.stream ? "mirage-stream" : p.stem().string();
    name += tag;
    name += std::to_string(::getpid());
    name += "-";
    name += std::to_string(counter++);
    name += p.extension().string();
    if (out.stream) {
        std::error_code ec;
        fs::path dir = fs::temp_directory_path(ec);
        if (ec) dir = "/tmp";
        return (dir / name).string();
    }
    return (p.parent_path() / name).string();
}

Status write_stream(const OutputPath& out, std::string_view content) {
    if (out.target == "-") {
        if (std::fwrite(content.data(), 1, content.size(), stdout) != content.size() ||
            std::fflush(stdout) != 0)
            return make_error(std::string("the standard output: cannot write: ") +
                              std::strerror(errno));
        return Ok{};
    }
    const int fd = ::open(out.target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return make_error(out.name + ": cannot open: " + std::strerror(errno));
    Status s = write_all(fd, content, out.name);
    if (::close(fd) != 0 && s) s = make_error(out.name + ": cannot write: " + std::strerror(errno));
    return s;
}

Status copy_to_stream(const std::string& from, const OutputPath& out) {
    std::string content;
    {
        std::ifstream in(from, std::ios::binary);
        if (!in) {
            const std::string reason = std::strerror(errno);
            std::remove(from.c_str());
            return make_error(from + ": cannot read: " + reason);
        }
        std::ostringstream buffer;
        buffer << in.rdbuf();
        content = buffer.str();
    }
    std::remove(from.c_str());
    return write_stream(out, content);
}

}  // namespace mirage
