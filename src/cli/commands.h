// The subcommands of the mirage tool, each set up by its own file.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "load/mirage_scene.h"

namespace mirage {

void setup_path_command(CLI::App& app);
void setup_compile_command(CLI::App& app);
void setup_trace_command(CLI::App& app);
void setup_compare_command(CLI::App& app);
void setup_animate_command(CLI::App& app);
void setup_study_command(CLI::App& app);
void setup_frame_command(CLI::App& app);
void setup_refraction_command(CLI::App& app);

/// The command line's words (argv) as CLI11 is to parse them: POV-Ray's switches of trace and
/// compile translated to their long options (util/povray_switches.h).  Refuses, with a
/// message and CommandFailed{2}: no subcommand or an unknown one (listing them), an unknown
/// long option (with the nearest name), -w or -h before a number (the size is -W and -H).
std::vector<std::string> prepare_command_line(CLI::App& app, std::vector<std::string> words);

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

/// For --declare NAME=VALUE: refused as the option is read unless NAME is an identifier and
/// VALUE a number (load/mirage_scene.h, parse_declare).
inline CLI::Validator declare_text() {
    return CLI::Validator(
        [](std::string& value) {
            auto d = parse_declare(value);
            return d ? std::string() : d.message();
        },
        "NAME=VALUE");
}

/// --declare NAME=VALUE, as often as wanted; `more` adds to the help's note on POV-Ray's
/// Declare= ("; the .ini declares it too").
inline CLI::Option* add_declare_option(CLI::App& sub, std::vector<std::string>& declares,
                                       const std::string& more = "") {
    return sub
        .add_option("--declare", declares,
                    "declare NAME as the number VALUE before the scene is parsed (POV-Ray's "
                    "Declare=NAME=VALUE" +
                        more + ")")
        ->check(declare_text())
        ->allow_extra_args(false);  // one NAME=VALUE each time: the scene may follow
}

/// The --declare options' names and numbers (checked by declare_text); a later one replaces
/// an earlier one of the same name, as POV-Ray's Declare= does.
inline std::map<std::string, double> declared_numbers(const std::vector<std::string>& texts) {
    std::map<std::string, double> out;
    for (const auto& t : texts)
        if (auto d = parse_declare(t)) out[d->first] = d->second;
    return out;
}

/// The help's note on POV-Ray's spellings (main.cpp translates them, util/povray_switches.h).
inline std::string povray_switches_note(bool trace) {
    return std::string(
               "POV-Ray's spellings are accepted too, the value attached as POV-Ray "
               "takes it: +W640 +H480 ") +
           (trace ? "+A0.3 +AM2 +R3 +Oout.png" : "+A +Oout.png (--image)") +
           " +K0.5 +Lpath Declare=NAME=VALUE.\n";
}

/// Thrown by a subcommand's callback to end the program with `code` after it has printed its
/// own message.
struct CommandFailed {
    int code = 1;
};

}  // namespace mirage
