// `mirage trace SCENE.pov -o OUT.png`: the scene rendered by the built-in tracer along the
// curved light paths of its atmosphere (the continuous model).
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "load/atmosphere_settings.h"
#include "trace_scene/side_by_side.h"
#include "trace_scene/trace_scene.h"
#include "util/format.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

/// POV-Ray's antialiasing options (+A, +AM, +R, +J) and --side-by-side.
struct AntialiasCli {
    CLI::Option* antialias = nullptr;   // --antialias: given when antialiasing
    std::vector<CLI::Option*> with_it;  // options that need --antialias
    int method = 1;                     // +AM
    bool no_jitter = false;
    bool side_by_side = false;

    void add(CLI::App* sub, AntialiasSettings& aa) {
        const std::string fallback = shortest(aa.threshold);
        // Without a value --antialias takes +A's threshold (apply()); a value is checked here,
        // so that a scene taken for one is named.
        const CLI::Validator threshold(
            [fallback](std::string& v) {
                double d = 0.0;
                if (v.empty() || v == "true" ||
                    (CLI::detail::lexical_cast(v, d) && d >= 0.0 && d <= 1.0))
                    return std::string();
                return "'" + v +
                       "' is not a threshold in [0, 1] (before the scene, write --antialias=" +
                       fallback + ")";
            },
            "");
        const std::string help =
            "POV-Ray's +A: supersample where colours differ by THRESHOLD (default " + fallback +
            ")";
        antialias = sub->add_option("--antialias", aa.threshold, help)
                        ->type_name("[THRESHOLD]")
                        ->expected(0, 1)
                        ->check(threshold);
        with_it = {sub->add_option("--antialias-method", method,
                                   "POV-Ray's +AM: 1 non-recursive, 2 adaptive recursive")
                       ->check(CLI::IsMember({1, 2}))
                       ->capture_default_str(),
                   sub->add_option("--antialias-depth", aa.depth,
                                   "POV-Ray's +R: method 1's rays per side, method 2's levels + 1")
                       ->check(CLI::Range(1, 9))
                       ->capture_default_str(),
                   sub->add_option("--jitter", aa.jitter, "POV-Ray's +J: the sub-samples' jitter")
                       ->check(CLI::Range(0.0, 1.0))
                       ->capture_default_str()};
        sub->add_flag("--no-jitter", no_jitter, "POV-Ray's -J: sub-samples on their grid");
        sub->add_flag("--side-by-side,--before-after", side_by_side,
                      "one PNG: the scene without the atmosphere (left) and with it (right), "
                      "labelled");
    }

    /// Sets `t`'s antialiasing; with --side-by-side traces both halves and returns true.
    bool apply(TraceOptions& t, bool quiet) const {
        if (*antialias) {
            t.antialias.method =
                method == 2 ? AntialiasMethod::Recursive : AntialiasMethod::NonRecursive;
            const auto& given = antialias->results();
            if (given.empty() || given.front().empty() || given.front() == "true")
                t.antialias.threshold = AntialiasSettings{}.threshold;
        }
        if (no_jitter) t.antialias.jitter = 0.0;
        for (const CLI::Option* opt : with_it)
            if (!*antialias && *opt)
                std::cerr << "mirage trace: warning: " << opt->get_name()
                          << " has no effect without --antialias (as in POV-Ray)\n";
        if (!side_by_side) return false;
        if (!t.atmosphere) {
            std::cerr << "mirage trace: --side-by-side renders the scene without and with the "
                         "atmosphere; drop --no-atmosphere\n";
            throw CommandFailed{1};
        }
        auto both = trace_side_by_side(t);
        if (!both) {
            std::cerr << "mirage trace: " << escape_terminal(both.message()) << "\n";
            throw CommandFailed{1};
        }
        if (!quiet) std::cout << side_by_side_summary(*both);
        return true;
    }
};

struct TraceCliOptions {
    TraceOptions trace;
    double tolerance = 0.0;
    double clock = 0.0;
    std::vector<std::string> declares;
    bool no_atmosphere = false;
    bool quiet = false;
    bool colour = false;
    AntialiasCli antialias;
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
    add_declare_option(*sub, o->declares);
    auto* wavelengths =
        sub->add_option("--wavelengths", o->trace.wavelengths_nm,
                        "colour: trace the red, green and blue channels at these wavelengths, nm "
                        "(e.g. 610,550,465; replaces Mirage_Wavelengths; real air only)")
            ->delimiter(',')
            ->type_name("R,G,B");
    sub->add_flag("--colour,--color", o->colour,
                  "colour at the default wavelengths 610,550,465 nm (the sRGB primaries')")
        ->excludes(wavelengths);
    sub->add_flag("--monochrome", o->trace.monochrome,
                  "one wavelength for the three channels (the green one of the scene's "
                  "Mirage_Wavelengths)")
        ->excludes(wavelengths)
        ->excludes("--colour");
    sub->add_flag("-q,--quiet", o->quiet, "print nothing but errors");
    o->antialias.add(sub, o->trace.antialias);
    sub->footer(povray_switches_note(true));
    sub->callback([o, tol, clock] {
        TraceOptions t = o->trace;
        if (*tol) t.tolerance_px = o->tolerance;
        if (*clock) t.clock = o->clock;
        t.declares = declared_numbers(o->declares);
        t.atmosphere = !o->no_atmosphere;
        t.progress = !o->quiet;
        if (o->colour)
            t.wavelengths_nm.assign(kDefaultChannelWavelengthsNm.begin(),
                                    kDefaultChannelWavelengthsNm.end());
        if (o->antialias.apply(t, o->quiet)) return;
        auto report = trace_scene(t);
        if (!report) {
            std::cerr << "mirage trace: " << escape_terminal(report.message()) << "\n";
            throw CommandFailed{1};
        }
        if (!o->quiet) std::cout << trace_summary(*report);
    });
}

}  // namespace mirage
