// `mirage refraction`: how far the whole atmosphere lifts a star or the sun, at each apparent
// elevation and wavelength, beside the published tables (report/refraction_table.h).
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "report/refraction_table.h"
#include "util/json_text.h"
#include "util/output_set.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

struct RefractionCliOptions {
    RefractionTableOptions table;
    std::string plot;
    bool json = false;
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "mirage refraction: " << escape_terminal(message) << "\n";
    throw CommandFailed{1};
}

}  // namespace

void setup_refraction_command(CLI::App& app) {
    auto o = std::make_shared<RefractionCliOptions>();
    auto* sub = app.add_subcommand(
        "refraction",
        "Astronomical refraction: how far the standard atmosphere lifts a star or the sun at "
        "each apparent elevation and wavelength, beside the published tables");
    sub->add_option("--temperature", o->table.temperature_c, "at the ground, degC")
        ->capture_default_str();
    sub->add_option("--pressure", o->table.pressure_hpa, "at the ground, hPa")
        ->capture_default_str();
    sub->add_option("--wavelength", o->table.wavelengths_nm,
                    "vacuum wavelengths, nm (Ciddor's index; several: the colours' separation)")
        ->delimiter(',')
        ->capture_default_str();
    sub->add_option("--elevations", o->table.elevations_deg, "apparent elevations, degrees")
        ->delimiter(',')
        ->capture_default_str();
    sub->add_option("--observer-height", o->table.observer_height_m,
                    "the observer's height above the ground, m")
        ->capture_default_str();
    sub->add_option("--plot", o->plot, "a PNG of the refraction from the horizon up (gnuplot)")
        ->check(non_empty_name());
    sub->add_flag("--json", o->json, "print the table as JSON");
    sub->callback([o] {
        auto t = refraction_table(o->table);
        if (!t) fail(t.message());
        if (!o->plot.empty()) {
            OutputSet outputs;
            if (auto s = draw_refraction_plot(*t, outputs, o->plot); !s) fail(s.message());
            if (auto s = outputs.commit(); !s) fail(s.message());
        }
        if (o->json) {
            nlohmann::json j = refraction_json(*t);
            if (!o->plot.empty()) j["plot"] = o->plot;
            std::cout << json_text(j) << "\n";
            return;
        }
        std::cout << refraction_text(*t);
        if (!o->plot.empty()) std::cout << "wrote " << o->plot << "\n";
    });
}

}  // namespace mirage
