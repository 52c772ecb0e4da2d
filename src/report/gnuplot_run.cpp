#include "report/gnuplot_run.h"

#include <filesystem>

#include "util/atomic_file.h"
#include "util/process.h"

namespace mirage {

std::string gnuplot_quoted(const std::string& s) {
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '\n') {
            out += "\\n";
        } else if (ch == '\r') {
            out += "\\r";
        } else if (ch == '\t') {
            out += "\\t";
        } else {
            if (ch == '"' || ch == '\\') out += '\\';
            out += ch;
        }
    }
    return out + "\"";
}

Status run_gnuplot(const std::string& gnuplot, const std::string& script, const std::string& anchor,
                   const std::vector<std::string>& expected, const std::string& what) {
    namespace fs = std::filesystem;
    if (!find_program(gnuplot))
        return make_error(gnuplot + " not found on PATH: " + what + " is drawn by gnuplot");
    const std::string script_path = temporary_name_for(anchor) + ".gp";
    const std::string log = temporary_name_for(anchor) + ".log";
    if (auto s = write_file_atomic(script_path, script); !s) return s.error();
    auto run = run_process({gnuplot, fs::absolute(script_path).string()}, "", log);
    std::error_code ec;
    fs::remove(script_path, ec);
    std::string log_text;
    if (auto l = read_file(log)) log_text = *l;
    fs::remove(log, ec);
    if (!run) return run.error();
    bool written = true;
    for (const std::string& f : expected) written = written && fs::exists(f, ec);
    if (run->exit_code != 0 || !written)
        return make_error("gnuplot failed (exit " + std::to_string(run->exit_code) +
                          "): " + log_text);
    return Ok{};
}

}  // namespace mirage
