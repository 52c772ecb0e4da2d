// mirage: command-line front end.  Each subcommand lives in its own file under src/cli/.
#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"mirage: atmospheric mirages for POV-Ray, physically right and checked"};
    app.set_version_flag("--version", "mirage 0.1");
    app.require_subcommand(1);
    CLI11_PARSE(app, argc, argv);
    return 0;
}
