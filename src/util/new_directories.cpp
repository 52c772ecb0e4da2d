#include "util/new_directories.h"

#include <filesystem>

namespace mirage {

namespace fs = std::filesystem;

NewDirectories::~NewDirectories() {
    std::error_code ec;
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) fs::remove(*it, ec);  // if empty
}

Status NewDirectories::make(const std::string& dir) {
    std::error_code ec;
    std::vector<fs::path> missing;
    for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !p.empty(); p = p.parent_path()) {
        if (fs::exists(fs::symlink_status(p, ec))) break;
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        if (it->filename().empty()) continue;  // "dir/" ends in an empty name
        if (fs::create_directory(*it, ec)) made_.push_back(it->string());
        if (ec) return make_error(dir + ": cannot create: " + ec.message());
    }
    if (!fs::is_directory(dir, ec)) return make_error(dir + ": cannot create: not a directory");
    return Ok{};
}

}  // namespace mirage
