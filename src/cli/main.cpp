// mirage: command-line front end.  Each subcommand lives in its own file under src/cli/.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "cli/commands.h"

int main(int argc, char** argv) {
    // Into a file or a pipe the output goes in one piece at the end, so that a write that
    // fails (a full disk) is seen below with its reason.
    static char out_buffer[1 << 20];
    if (!::isatty(STDOUT_FILENO)) std::setvbuf(stdout, out_buffer, _IOFBF, sizeof out_buffer);
    CLI::App app{"mirage: atmospheric mirages for POV-Ray, physically right and checked"};
    app.set_version_flag("--version", "mirage 0.1");
    app.require_subcommand(1);
    mirage::setup_path_command(app);
    mirage::setup_compile_command(app);
    mirage::setup_trace_command(app);
    mirage::setup_compare_command(app);
    mirage::setup_animate_command(app);
    mirage::setup_study_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // CLI11 prints the message (it names the flag); usage errors exit with 2.
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    } catch (const mirage::CommandFailed& failed) {
        return failed.code;
    }
    // What was printed must have reached its place: a full disk or a closed pipe is an error
    // too (the last of the output may sit in the buffers until here).
    errno = 0;
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::cerr << "mirage: cannot write the standard output"
                  << (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string())
                  << "\n";
        return 1;
    }
    return 0;
}
