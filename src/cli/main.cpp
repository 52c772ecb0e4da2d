// mirage: command-line front end.  Each subcommand lives in its own file under src/cli/.
#include <CLI/CLI.hpp>

#include "cli/commands.h"

int main(int argc, char** argv) {
    CLI::App app{"mirage: atmospheric mirages for POV-Ray, physically right and checked"};
    app.set_version_flag("--version", "mirage 0.1");
    app.require_subcommand(1);
    mirage::setup_path_command(app);
    mirage::setup_compile_command(app);
    mirage::setup_trace_command(app);
    mirage::setup_compare_command(app);
    mirage::setup_animate_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // CLI11 prints the message (it names the flag); usage errors exit with 2.
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    } catch (const mirage::CommandFailed& failed) {
        return failed.code;
    }
    return 0;
}
