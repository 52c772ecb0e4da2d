#include "util/output_set.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "util/check.h"
#include "util/output_path.h"

namespace mirage {

namespace fs = std::filesystem;

namespace {

/// A name beside `target` for a file of this process: ".stem.<tag><pid>-<n>.ext".
std::string sibling_name(const std::string& target, const char* tag) {
    static int counter = 0;
    const fs::path p(target);
    std::string name = ".";
    name += p.stem().string();
    name += tag;
    name += std::to_string(::getpid());
    name += "-";
    name += std::to_string(counter++);
    name += p.extension().string();
    return (p.parent_path() / name).string();
}

bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec;
}

std::string normal(const std::string& path) {
    std::error_code ec;
    const fs::path abs = fs::absolute(path, ec);
    return (ec ? fs::path(path) : abs).lexically_normal().string();
}

}  // namespace

OutputSet::OutputSet(std::vector<std::string> inputs) : inputs_(std::move(inputs)) {}

OutputSet::~OutputSet() {
    for (const Staged& s : staged_) std::remove(s.temporary.c_str());
    if (!staging_folder_.empty()) {
        std::error_code ec;
        fs::remove_all(staging_folder_, ec);
    }
}

void OutputSet::protect(const std::vector<std::string>& inputs) {
    inputs_.insert(inputs_.end(), inputs.begin(), inputs.end());
}

Status OutputSet::check(const std::string& path) const {
    if (auto out = resolve_output_path(path); !out) return out.error();
    for (const std::string& input : inputs_) {
        if (same_file(input, path) || normal(input) == normal(path)) {
            return make_error(path + ": the output would overwrite " +
                              (input == path ? std::string("an input") : "the input " + input) +
                              " of this command (the scene or a file it includes)");
        }
    }
    for (const Staged& s : staged_) {
        if (same_file(s.out.name, path) || normal(s.out.name) == normal(path))
            return make_error(path + ": named for two outputs of this command");
    }
    return Ok{};
}

Result<std::string> OutputSet::stage(const std::string& path) {
    if (auto s = check(path); !s) return s.error();
    auto out = resolve_output_path(path);
    if (!out) return out.error();
    staged_.push_back({*out, temporary_for(*out)});
    return staged_.back().temporary;
}

Status OutputSet::adopt(const std::string& temporary, const std::string& target) {
    auto out = resolve_output_path(target);
    if (auto s = out ? check(target) : Status(out.error()); !s) {
        std::remove(temporary.c_str());
        return s;
    }
    staged_.push_back({*out, temporary});
    return Ok{};
}

Result<std::string> OutputSet::make_staging_folder(const std::string& out_dir) {
    const fs::path folder = fs::path(out_dir) / (".staging-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::remove_all(folder, ec);
    fs::create_directories(folder, ec);
    if (ec) return make_error(folder.string() + ": cannot create: " + ec.message());
    staging_folder_ = folder.string();
    staging_out_dir_ = out_dir;
    return staging_folder_;
}

Status OutputSet::commit_staging_folder() {
    MIRAGE_CHECK(!staging_folder_.empty());
    const fs::path folder(staging_folder_);
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(folder, ec)) {
        if (!e.is_regular_file()) continue;
        const fs::path target = fs::path(staging_out_dir_) / fs::relative(e.path(), folder);
        if (auto s = adopt(e.path().string(), target.string()); !s) return s;
    }
    if (ec) return make_error(staging_folder_ + ": cannot list: " + ec.message());
    return commit();
}

Status OutputSet::write_text(const std::string& path, std::string_view content) {
    auto tmp = stage(path);
    if (!tmp) return tmp.error();
    std::ofstream out(*tmp, std::ios::binary | std::ios::trunc);
    if (!out) return make_error(path + ": cannot write: " + std::strerror(errno));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) return make_error(path + ": write failed: " + std::strerror(errno));
    return Ok{};
}

Status OutputSet::commit() {
    struct Done {
        std::string backup;  // the target's old content, kept under another name; "" if none
        bool existed = false;
    };
    // Streams first: what went into a device or a pipe cannot be taken back, so it goes
    // before any file is replaced, and a failed stream leaves every file as it was.
    for (const Staged& s : staged_) {
        if (!s.out.stream) continue;
        if (auto c = copy_to_stream(s.temporary, s.out); !c) return c;
    }
    std::vector<const Staged*> files;
    for (const Staged& s : staged_)
        if (!s.out.stream) files.push_back(&s);
    std::vector<Done> done;
    for (const Staged* f : files) {
        const Staged& s = *f;
        const std::string& target = s.out.target;
        Done d;
        std::error_code ec;
        d.existed = fs::exists(fs::symlink_status(target, ec));
        if (d.existed) {
            // A second name for the old file, so that it can come back if a later rename fails.
            d.backup = sibling_name(target, ".old");
            if (::link(target.c_str(), d.backup.c_str()) != 0) d.backup.clear();
        }
        if (std::rename(s.temporary.c_str(), target.c_str()) != 0) {
            const std::string reason = std::strerror(errno);
            if (!d.backup.empty()) std::remove(d.backup.c_str());
            bool restored = true;
            for (std::size_t k = done.size(); k-- > 0;) {
                const std::string& old = files[k]->out.target;
                if (!done[k].backup.empty()) {
                    restored = std::rename(done[k].backup.c_str(), old.c_str()) == 0 && restored;
                } else if (!done[k].existed) {
                    std::remove(old.c_str());
                } else {
                    restored = false;  // no second name could be made for it
                }
            }
            return make_error(s.out.name + ": cannot write: " + reason +
                              (restored ? " (no output of this command was changed)" : ""));
        }
        done.push_back(d);
    }
    for (const Done& d : done)
        if (!d.backup.empty()) std::remove(d.backup.c_str());
    staged_.clear();
    return Ok{};
}

std::vector<std::string> OutputSet::targets() const {
    std::vector<std::string> t;
    for (const Staged& s : staged_) t.push_back(s.out.name);
    return t;
}

}  // namespace mirage
