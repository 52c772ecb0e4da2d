// Test helper: renders a scene file with the POV-Ray on PATH, as the parity tests need it
// (no display, no antialiasing, 8-bit PNG).
#pragma once

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "image/image.h"
#include "image/image_io.h"
#include "util/result.h"

namespace mirage::testing {

/// Whether `povray` runs from PATH.
inline bool povray_available() {
    static const bool available = std::system("povray --version >/dev/null 2>&1") == 0;
    return available;
}

/// Writes `pov_text` to dir/name.pov and renders dir/name.png with `povray -D -A`.  POV-Ray
/// runs in `dir` (its I/O restrictions allow writing only there and under /tmp).
inline Result<Image> render_with_povray(const std::string& pov_text,
                                        const std::filesystem::path& dir, const std::string& name,
                                        int width, int height) {
    std::filesystem::create_directories(dir);
    const std::filesystem::path pov = dir / (name + ".pov");
    {
        std::ofstream out(pov);
        out << pov_text;
        if (!out) return make_error("cannot write " + pov.string());
    }
    std::ostringstream command;
    command << "cd '" << dir.string() << "' && povray -D -A +FN8 +W" << width << " +H" << height
            << " +I" << name << ".pov +O" << name << ".png > " << name << ".log 2>&1";
    if (std::system(command.str().c_str()) != 0) {
        std::ifstream log(dir / (name + ".log"));
        std::ostringstream text;
        text << log.rdbuf();
        return make_error("povray failed on " + pov.string() + ":\n" + text.str());
    }
    return read_image((dir / (name + ".png")).string());
}

/// What `povray -D ARGS` run in `dir` did: whether it succeeded, and its log (console output)
/// with POV-Ray's line wrapping undone (every run of whitespace one space), so that a
/// message can be found whole.
struct PovRayRun {
    bool ok = false;
    std::string log;
};

inline PovRayRun run_povray(const std::filesystem::path& dir, const std::string& args,
                            const std::string& log_name = "povray.log") {
    const auto quoted = [](const std::filesystem::path& p) { return "'" + p.string() + "'"; };
    const std::filesystem::path log = dir / log_name;
    PovRayRun r;
    r.ok =
        std::system(("cd " + quoted(dir) + " && povray -D " + args + " > " + quoted(log) + " 2>&1")
                        .c_str()) == 0;
    std::ifstream in(log);
    std::ostringstream text;
    text << in.rdbuf();
    for (char c : text.str()) {
        const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
        if (space && (r.log.empty() || r.log.back() == ' ')) continue;
        r.log += space ? ' ' : c;
    }
    return r;
}

/// A fresh directory for a test's files under the build tree.
inline std::filesystem::path test_dir(const std::string& group, const std::string& name) {
    const auto dir = std::filesystem::path(MIRAGE_BINARY_DIR) / "test_output" / group / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace mirage::testing
