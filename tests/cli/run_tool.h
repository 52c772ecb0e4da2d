// Runs the built mirage tool for command-line tests and captures its output and exit code.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mirage::testing {

struct ToolRun {
    int exit_code = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

/// The bytes of a file (empty when it cannot be read).
inline std::string read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Writes `text` to a file as it is.
inline void write_bytes(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

/// A path quoted for the shell command line of run_tool, whatever bytes it holds (a single
/// quote in it too).
inline std::string quoted(const std::filesystem::path& p) {
    std::string q = "'";
    for (char c : p.string()) {
        if (c == '\'') {
            q += "'\\''";
        } else {
            q += c;
        }
    }
    q += '\'';
    return q;
}

/// Runs `build/mirage <args>` through the shell (args are quoted by the caller).
inline ToolRun run_tool(const std::string& args, const std::string& stdin_text = "") {
    static int counter = 0;
    const std::string base = std::string(::testing::TempDir()) + "mirage_run_" +
                             std::to_string(::getpid()) + "_" + std::to_string(counter++);
    const std::string err_path = base + ".err";
    std::string cmd = std::string(MIRAGE_BINARY_DIR) + "/mirage " + args + " 2>" + err_path;
    if (!stdin_text.empty()) {
        const std::string in_path = base + ".in";
        FILE* f = std::fopen(in_path.c_str(), "w");
        std::fputs(stdin_text.c_str(), f);
        std::fclose(f);
        cmd += " <" + in_path;
    }
    ToolRun r;
    FILE* p = popen(cmd.c_str(), "r");
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
    const int status = pclose(p);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    FILE* e = std::fopen(err_path.c_str(), "r");
    if (e) {
        while ((n = std::fread(buf.data(), 1, buf.size(), e)) > 0) r.err.append(buf.data(), n);
        std::fclose(e);
    }
    return r;
}

}  // namespace mirage::testing
