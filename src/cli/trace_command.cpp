// `mirage trace SCENE.pov -o OUT.png`: the scene rendered by the built-in tracer along the
// curved light paths of its atmosphere (the continuous model).
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "trace_scene/trace_scene.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

struct TraceCliOptions {
    TraceOptions trace;
    double tolerance = 0.0;
    double clock = 0.0;
    std::vector<std::string> declares;
    bool no_atmosphere = false;
    bool quiet = false;
};

}  // namespace

void setup_trace_command(CLI::App& app) {
    auto o = std::make_shared<TraceCliOptions>();
    auto* sub = app.add_subcommand(
        "trace", "Render a scene with the built-in tracer along the atmosphere's curved rays");
    sub->add_option("scene", o->trace.scene, "the .pov scene")->required();
    sub->add_option("-o,--output", o->trace.output,
                    "the image: .png (as POV-Ray writes it) or .exr (linear)")
        ->required()
        ->check(non_empty_name());
    sub->add_option("-W,--width", o->trace.width, "image width, pixels")->capture_default_str();
    sub->add_option("-H,--height", o->trace.height, "image height, pixels")->capture_default_str();
    auto* tol = sub->add_option(
        "--tolerance", o->tolerance,
        "largest path error, pixels seen from the eye (default: Mirage_Tolerance, else 0.5)");
    sub->add_option("--threads", o->trace.threads, "worker threads (0: all cores)")
        ->capture_default_str();
    sub->add_flag("--scanline-paths", o->trace.scanline_paths,
                  "one path per image row rotated about the vertical, as Khote & Howard "
                  "(level camera only)");
    sub->add_flag("--no-atmosphere", o->no_atmosphere,
                  "straight rays, whatever the scene declares");
    sub->add_flag("--reference-sampling", o->trace.reference_sampling,
                  "sample every ray's path to the tolerance all along (the reference for the "
                  "default, which samples finely only near surfaces)");
    sub->add_option("-L,--library-path", o->trace.library_paths,
                    "extra include directory (searched first)");
    auto* clock = sub->add_option("--clock", o->clock,
                                  "render the still at this clock (POV-Ray's +K), one frame of "
                                  "an animation");
    sub->add_option("--declare", o->declares,
                    "declare NAME as the number VALUE before the scene is parsed (POV-Ray's "
                    "Declare=NAME=VALUE)")
        ->check(declare_text())
        ->allow_extra_args(false);  // one NAME=VALUE each time: the scene may follow
    sub->add_flag("-q,--quiet", o->quiet, "print nothing but errors");
    sub->footer(povray_switches_note(true));
    sub->callback([o, tol, clock] {
        TraceOptions t = o->trace;
        if (*tol) t.tolerance_px = o->tolerance;
        if (*clock) t.clock = o->clock;
        t.declares = declared_numbers(o->declares);
        t.atmosphere = !o->no_atmosphere;
        t.progress = !o->quiet;
        auto report = trace_scene(t);
        if (!report) {
            std::cerr << "mirage trace: " << escape_terminal(report.message()) << "\n";
            throw CommandFailed{1};
        }
        if (!o->quiet) std::cout << trace_summary(*report);
    });
}

}  // namespace mirage
