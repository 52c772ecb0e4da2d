// `mirage compare SCENE.pov`: error against run time for the band models POV-Ray renders and
// for the tracer's polylines, against a finely traced reference.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "compare/compare.h"
#include "compare/compare_report.h"
#include "util/format.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

struct CompareCliOptions {
    CompareOptions compare;
    bool quiet = false;
};

/// The figures of the summary's first section, for the terminal.
void print_headlines(const CompareResult& r) {
    const Headlines h = compute_headlines(r.rows);
    if (h.adaptive_vs_uniform) {
        const EqualError& e = *h.adaptive_vs_uniform;
        std::cout << "at RMSE " << sig(e.error, 3) << ": uniform layers " << sig(e.a.seconds, 3)
                  << " s, adaptive layers " << sig(e.b.seconds, 3) << " s (x" << sig(e.speedup(), 3)
                  << ")\n";
    }
    if (h.corrected_vs_uniform) {
        const EqualError& e = *h.corrected_vs_uniform;
        std::cout << "at RMSE " << sig(e.error, 3) << ": uniform layers " << sig(e.a.seconds, 3)
                  << " s, the corrected camera " << sig(e.b.seconds, 3) << " s (x"
                  << sig(e.speedup(), 3) << ")\n";
    }
    if (h.tracer_vs_steps) {
        const EqualError& e = *h.tracer_vs_steps;
        std::cout << "at RMSE " << sig(e.error, 3) << ": POV-Ray with index steps "
                  << sig(e.a.seconds, 3) << " s, the tracer " << sig(e.b.seconds, 3) << " s (x"
                  << sig(e.speedup(), 3) << ")\n";
    }
    if (h.tracer_vs_adaptive) {
        const EqualError& e = *h.tracer_vs_adaptive;
        std::cout << "at RMSE " << sig(e.error, 3) << ": POV-Ray with adaptive layers "
                  << sig(e.a.seconds, 3) << " s, the tracer " << sig(e.b.seconds, 3) << " s (x"
                  << sig(e.speedup(), 3) << ")\n";
    }
    std::cout << "wrote " << r.summary_path << "\n      " << r.csv_path << "\n      "
              << (r.plotted ? r.plot_png + ", .svg" : r.plot_script + " (not plotted)")
              << "\n      " << r.sheet_path << "\n";
}

}  // namespace

void setup_compare_command(CLI::App& app) {
    auto o = std::make_shared<CompareCliOptions>();
    CompareOptions& c = o->compare;
    auto* sub = app.add_subcommand(
        "compare",
        "Error against run time: uniform and adaptive layers (for real air, index steps) "
        "and the corrected camera rendered by POV-Ray, and the tracer's polylines, each "
        "against a finely traced reference");
    sub->add_option("scene", c.scene, "the .pov scene")->required();
    sub->add_option("-W,--width", c.width, "image width, pixels")->capture_default_str();
    sub->add_option("-H,--height", c.height, "image height, pixels")->capture_default_str();
    sub->add_option("-o,--output", c.out_dir,
                    "directory for the results (default build/compare/SCENE)")
        ->check(non_empty_name());
    sub->add_option("--reference-tolerance", c.reference_tolerance_px,
                    "path tolerance of the reference, pixels (finer than every setting)")
        ->capture_default_str();
    sub->add_option("--counts", c.counts,
                    "uniform layer counts, comma-separated (default 8,16,32,... doubling until "
                    "POV-Ray's trace-level budget is exceeded)")
        ->delimiter(',')
        ->allow_extra_args(false);
    sub->add_option("--steps", c.steps,
                    "index steps of real air's layers, comma-separated (default 8,16,... 256 "
                    "doubling while within POV-Ray's trace-level budget)")
        ->delimiter(',')
        ->allow_extra_args(false);
    sub->add_option("--tolerances", c.tolerances,
                    "adaptive layers' tolerances, pixels, comma-separated")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->capture_default_str();
    sub->add_option("--corrected-counts", c.corrected_counts,
                    "layer counts of the corrected camera, comma-separated (empty: none)")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->capture_default_str();
    sub->add_option("--trace-tolerances", c.trace_tolerances,
                    "the tracer's tolerances, pixels, comma-separated")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->capture_default_str();
    sub->add_flag("--scanline-paths", c.scanline,
                  "also the tracer with one path per image row (Khote & Howard) as the model "
                  "'scanline'");
    sub->add_option("--threshold", c.threshold,
                    "difference of 8-bit codes / 255 over which a pixel counts as wrong")
        ->capture_default_str();
    sub->add_option("--threads", c.threads, "threads of the tracer and of POV-Ray (0: all cores)")
        ->capture_default_str();
    sub->add_option("-L,--library-path", c.library_paths,
                    "extra include directory (searched first)");
    sub->add_flag("-q,--quiet", o->quiet, "print nothing but errors");
    sub->callback([o] {
        CompareOptions options = o->compare;
        if (!o->quiet)
            options.progress = [](const std::string& line) { std::cerr << line << "\n"; };
        auto result = run_comparison(options);
        if (!result) {
            std::cerr << "mirage compare: " << escape_terminal(result.message()) << "\n";
            throw CommandFailed{1};
        }
        if (!o->quiet) print_headlines(*result);
    });
}

}  // namespace mirage
