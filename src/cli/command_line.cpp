// The words of the command line made ready for CLI11: POV-Ray's spellings translated
// (util/povray_switches.h), and the mistakes CLI11 answers poorly answered plainly: an unknown
// subcommand or none, a misspelt long option, -w/-h given for the image size.
#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "cli/commands.h"
#include "util/edit_distance.h"
#include "util/povray_switches.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

std::vector<CLI::App*> subcommands(CLI::App& app) {
    return app.get_subcommands([](CLI::App*) { return true; });
}

std::string subcommand_list(CLI::App& app) {
    std::string s;
    for (CLI::App* sub : subcommands(app))
        s += "  " + sub->get_name() +
             std::string(10 - std::min<std::size_t>(9, sub->get_name().size()), ' ') +
             sub->get_description() + "\n";
    return s;
}

// For `mirage` alone and an unknown subcommand: what there is, and how to render a scene.
void print_overview(CLI::App& app) {
    std::cerr << "The subcommands:\n"
              << subcommand_list(app)
              << "To render a scene with its mirage: mirage compile SCENE.pov --render (POV-Ray "
                 "through the compiled layers)\nor mirage trace SCENE.pov -o OUT.png (the "
                 "built-in tracer along the curved rays).  mirage SUBCOMMAND --help lists its "
                 "options.\n";
}

// The option names of `sub` ("-o", "--output", ...), and those that take a value.
struct OptionNames {
    std::vector<std::string> all, long_names, taking_value;
};

OptionNames option_names(CLI::App& sub) {
    OptionNames n;
    for (const CLI::Option* opt : sub.get_options()) {
        std::vector<std::string> names;
        for (const auto& s : opt->get_snames()) names.push_back("-" + s);
        for (const auto& l : opt->get_lnames()) {
            names.push_back("--" + l);
            n.long_names.push_back("--" + l);
        }
        for (const auto& name : names) {
            n.all.push_back(name);
            if (opt->get_items_expected_min() > 0) n.taking_value.push_back(name);
        }
    }
    return n;
}

bool is_number(const std::string& s) {
    if (s.empty()) return false;
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
}

[[noreturn]] void refuse(const std::string& command, const std::string& message) {
    std::cerr << command << ": " << escape_terminal(message) << "\n";
    throw CommandFailed{2};
}

}  // namespace

std::vector<std::string> prepare_command_line(CLI::App& app, std::vector<std::string> words) {
    if (words.size() <= 1) {
        std::cerr << "mirage: give a subcommand: mirage SUBCOMMAND ... (mirage --help)\n";
        print_overview(app);
        throw CommandFailed{2};
    }
    // The subcommand: the first word that is no option (mirage's own are --help, --version).
    std::size_t at = 1;
    while (at < words.size() && !words[at].empty() && words[at][0] == '-') ++at;
    if (at == words.size()) return words;
    const std::string name = words[at];
    std::vector<std::string> names;
    for (CLI::App* s : subcommands(app)) names.push_back(s->get_name());
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        const std::string near = closest_name(name, names, 3);
        std::cerr << "mirage: no subcommand '" << escape_terminal(name) << "'"
                  << (near.empty() ? std::string() : " (did you mean " + near + "?)") << "\n";
        print_overview(app);
        throw CommandFailed{2};
    }
    CLI::App& sub = *app.get_subcommand(name);
    const std::string command = "mirage " + name;
    OptionNames options = option_names(sub);
    std::vector<std::string> rest(words.begin() + static_cast<std::ptrdiff_t>(at) + 1, words.end());
    if (name == "trace" || name == "compile") {
        auto translated = translate_povray_switches(
            rest, name == "trace" ? SwitchTarget::Trace : SwitchTarget::Compile,
            options.taking_value);
        if (!translated) refuse(command, translated.message());
        rest = std::move(*translated);
    }
    const bool has_size =
        std::find(options.all.begin(), options.all.end(), "--height") != options.all.end();
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const std::string& w = rest[i];
        if (w == "--") break;
        if (std::find(options.taking_value.begin(), options.taking_value.end(), w) !=
            options.taking_value.end()) {
            ++i;  // its value
            continue;
        }
        // -h is the help, as in every command; before a number it was meant for the size.
        const std::string next = i + 1 < rest.size() ? rest[i + 1] : std::string();
        if (has_size &&
            (w == "-w" || (w.rfind("-w", 0) == 0 && is_number(w.substr(2))) ||
             (w == "-h" && is_number(next)) || (w.rfind("-h", 0) == 0 && is_number(w.substr(2)))))
            refuse(command, w + (w.size() == 2 && is_number(next) ? " " + next : "") +
                                ": the image size is -W and -H (--width, --height), as "
                                "POV-Ray's +W and +H; -h is the help");
        if (w.size() > 2 && w.rfind("--", 0) == 0) {
            const std::string option = w.substr(0, w.find('='));
            if (std::find(options.long_names.begin(), options.long_names.end(), option) !=
                options.long_names.end())
                continue;
            const std::string near = closest_name(option, options.long_names, 4);
            refuse(command, "unknown option " + option +
                                (near.empty() ? " (" + command + " --help lists its options)"
                                              : " (did you mean " + near + "?)"));
        }
    }
    words.resize(at + 1);
    words.insert(words.end(), rest.begin(), rest.end());
    return words;
}

}  // namespace mirage
