#include "util/input_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace mirage {

std::string bytes_text(std::size_t n) {
    std::string s = std::to_string(n) + " bytes";
    if (n >= (std::size_t{1} << 20) && n % (std::size_t{1} << 20) == 0)
        s += " (" + std::to_string(n >> 20) + " MiB)";
    return s;
}

bool read_at_most(std::istream& in, std::size_t max_bytes, std::string& text) {
    char piece[1 << 16];
    while (in) {
        in.read(piece, sizeof piece);
        text.append(piece, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_bytes) return false;
    }
    return true;
}

Result<std::string> read_input_file(const std::string& path, const InputKind& kind) {
    namespace fs = std::filesystem;
    auto refuse = [&](const std::string& why) { return make_error(path + ": " + why); };
    std::error_code ec;
    // The file's kind before it is opened: opening a FIFO would wait for a writer.
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        return refuse(std::string("cannot be opened: ") +
                      (ec ? ec.message() : std::string(std::strerror(ENOENT))));
    if (fs::is_directory(status)) return refuse("is a directory, not " + kind.what);
    if (!fs::is_regular_file(status))
        return refuse("is not a regular file (a device, a pipe or a socket?): " + kind.many +
                      " are read from files");
    auto too_large = [&](std::size_t bytes) {
        return refuse("is " + bytes_text(bytes) + ", more than the " + bytes_text(kind.max_bytes) +
                      " mirage reads for " + kind.what);
    };
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) return refuse("cannot be read: " + ec.message());
    if (size > kind.max_bytes) return too_large(static_cast<std::size_t>(size));
    std::ifstream in(path, std::ios::binary);
    if (!in) return refuse(std::string("cannot be opened: ") + std::strerror(errno));
    std::string text;
    text.reserve(static_cast<std::size_t>(size));
    if (!read_at_most(in, kind.max_bytes, text)) return too_large(text.size());
    if (in.bad()) return refuse(std::string("cannot be read: ") + std::strerror(errno));
    return text;
}

std::string quote_cut(const std::string& text, std::size_t max_bytes) {
    auto printable = [](std::string_view s) {
        std::string out(s);
        for (char& c : out) {
            const auto u = static_cast<unsigned char>(c);
            if (u < 0x20 || u >= 0x7f) c = '?';
        }
        return out;
    };
    if (text.size() <= max_bytes) return printable(text);
    const std::size_t half = max_bytes / 2;
    const std::string_view all(text);
    return printable(all.substr(0, half)) + "..." + printable(all.substr(all.size() - half)) +
           " (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace mirage
