// mirage: command-line front end.  Each subcommand lives in its own file under src/cli/.
#include <poll.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "util/hex_args.h"

int main(int argc, char** argv) {
    // Into a file or a pipe the output goes in one piece at the end, so that a write that
    // fails (a full disk) is seen below with its reason.
    static char out_buffer[1 << 20];
    // A reader that stops early (`mirage path --batch rays.csv | head`) closes the pipe: the
    // write fails with EPIPE, seen below, instead of a signal ending the program.  Programs
    // started from here get the default back (util/process.cpp).
    std::signal(SIGPIPE, SIG_IGN);
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
    mirage::setup_frame_command(app);
    mirage::setup_refraction_command(app);
    // `mirage --args-hex HEX MORE...`: HEX stands for the arguments it holds
    // (util/hex_args.h), as the frame tasks of `mirage animate --hosts` are started, so that no
    // byte of a file name passes through GNU parallel or a remote shell.
    std::vector<std::string> words(argv, argv + argc);
    if (argc >= 3 && std::string(argv[1]) == "--args-hex") {
        const auto args = mirage::args_from_hex(argv[2]);
        if (!args) {
            std::cerr << "mirage: --args-hex: not a list of arguments in hex\n";
            return 2;
        }
        words = {argv[0]};
        words.insert(words.end(), args->begin(), args->end());
        for (int k = 3; k < argc; ++k) words.push_back(argv[k]);
    }
    // POV-Ray's spellings translated, unknown subcommands and options answered plainly.
    try {
        words = mirage::prepare_command_line(app, std::move(words));
    } catch (const mirage::CommandFailed& failed) {
        return failed.code;
    }
    std::vector<char*> word_ptrs;
    for (auto& w : words) word_ptrs.push_back(w.data());
    word_ptrs.push_back(nullptr);
    argc = static_cast<int>(words.size());
    argv = word_ptrs.data();
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
        // The reader has all it wanted: a quiet end, as for a pipe that is read to its end.
        // (A write that failed earlier left errno behind; a pipe whose reader is gone polls
        // as an error.)
        pollfd out{STDOUT_FILENO, 0, 0};
        if (errno == EPIPE || (errno == 0 && ::poll(&out, 1, 0) == 1 && (out.revents & POLLERR)))
            return 0;
        std::cerr << "mirage: cannot write the standard output"
                  << (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string())
                  << "\n";
        return 1;
    }
    return 0;
}
