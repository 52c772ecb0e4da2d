// The subcommands of the mirage tool, each set up by its own file.
#pragma once

#include <CLI/CLI.hpp>

namespace mirage {

void setup_path_command(CLI::App& app);
void setup_compile_command(CLI::App& app);
void setup_trace_command(CLI::App& app);
void setup_compare_command(CLI::App& app);
void setup_animate_command(CLI::App& app);
void setup_study_command(CLI::App& app);
void setup_frame_command(CLI::App& app);

/// For options that name a file or a folder: an empty value (`-o ''`) is refused as the
/// option is read, instead of standing for "not given".
inline CLI::Validator non_empty_name() {
    return CLI::Validator(
        [](std::string& value) {
            return value.empty() ? std::string("an empty name: give a file or folder name")
                                 : std::string();
        },
        "NAME");
}

/// Thrown by a subcommand's callback to end the program with `code` after it has printed its
/// own message.
struct CommandFailed {
    int code = 1;
};

}  // namespace mirage
