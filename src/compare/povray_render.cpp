#include "compare/povray_render.h"

#include "pov/emit_camera.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <vector>

#include "pov/povray_path.h"
#include "util/atomic_file.h"
#include "util/process.h"
#include "util/text_escape.h"

namespace mirage {

PovrayLog parse_povray_log(std::string_view text) {
    PovrayLog log;
    const std::string s(text);
    std::smatch m;
    if (std::regex_search(s, m, std::regex(R"(Ray Tracer Version ([^\s(]+))"))) log.version = m[1];
    // The render's figures follow "Trace Time"; parse and bounding times have their own
    // "using N thread(s)" lines before it.
    const std::regex trace_re(
        R"(Trace Time:[^(\n]*\(([0-9.]+) seconds\)\s*\n\s*using ([0-9]+) thread\(s\) with ([0-9.]+) CPU-seconds)");
    if (std::regex_search(s, m, trace_re)) {
        log.trace_seconds = std::strtod(m[1].str().c_str(), nullptr);
        log.threads = std::atoi(m[2].str().c_str());
        log.cpu_seconds = std::strtod(m[3].str().c_str(), nullptr);
    } else if (std::regex_search(s, m, std::regex(R"(Trace Time:[^(\n]*\(([0-9.]+) seconds\))"))) {
        log.trace_seconds = std::strtod(m[1].str().c_str(), nullptr);
    }
    if (std::regex_search(s, m, std::regex(R"(Max Level:\s*([0-9]+)/)")))
        log.max_level = std::atoi(m[1].str().c_str());
    return log;
}

Result<PovrayRender> render_povray(const PovrayRenderSettings& st) {
    std::vector<std::string> argv = {st.povray, "-D"};
    if (st.threads > 0) argv.push_back("+WT" + std::to_string(st.threads));
    // POV-Ray splits an option at spaces unless its value is quoted (pov/povray_path.h).
    argv.push_back(povray_quoted(st.ini));
    if (!st.output.empty()) argv.push_back("+O" + povray_quoted(st.output));
    std::error_code ec;
    std::filesystem::remove(st.log, ec);
    auto run = run_process(argv, st.work_dir, st.log);
    if (!run) return run.error();
    PovrayRender r;
    r.exit_code = run->exit_code;
    r.seconds = run->seconds;
    r.process_cpu_seconds = run->cpu_seconds;
    if (auto text = read_file(st.log)) r.log = parse_povray_log(*text);
    if (r.exit_code == 0 && !st.crop_top_row.empty())
        if (auto s = crop_mesh_camera_render(st.crop_top_row); !s) return s.error();
    return r;
}

std::string log_tail(const std::string& path, int lines) {
    auto text = read_file(path);
    if (!text) return "";
    // POV-Ray's progress is one long line of carriage returns: keep what follows the last.
    std::vector<std::string> all;
    std::istringstream in(*text);
    std::string line;
    while (std::getline(in, line)) {
        const auto cr = line.find_last_of('\r');
        if (cr != std::string::npos) line = line.substr(cr + 1);
        all.push_back(line);
    }
    std::string out;
    const size_t first = all.size() > static_cast<size_t>(lines) ? all.size() - lines : 0;
    for (size_t i = first; i < all.size(); ++i) out += all[i] + "\n";
    return out;
}

std::string povray_failure_cause(const std::string& log_path) {
    auto text = read_file(log_path);
    if (!text) return "no log (" + log_path + ")";
    std::string line, last;
    std::istringstream in(*text);
    // POV-Ray's progress is one long line of carriage returns: split there too.
    while (std::getline(in, line)) {
        std::istringstream parts(line);
        std::string part;
        while (std::getline(parts, part, '\r')) {
            if (part.find_first_not_of(" \t") == std::string::npos) continue;
            if (part.find("Error") != std::string::npos ||
                part.find("Failed to") != std::string::npos ||
                part.find("Problem with") != std::string::npos)
                return escape_control(part.substr(part.find_first_not_of(" \t")));
            last = part;
        }
    }
    return last.empty() ? "an empty log (" + log_path + ")" : escape_control(last);
}

}  // namespace mirage
