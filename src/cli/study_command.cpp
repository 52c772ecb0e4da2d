// `mirage study SCENE.pov`: the band designs compared on the scene's continuum of camera rays.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "compare/design_study.h"
#include "util/format.h"
#include "util/text_escape.h"

namespace mirage {

void setup_study_command(CLI::App& app) {
    auto o = std::make_shared<StudyOptions>();
    auto* sub = app.add_subcommand(
        "study",
        "Compare band designs (equal layers, fitted planes, graded layers of "
        "revolution) on a scene's camera rays: error against crossings and POV-Ray time");
    sub->add_option("scene", o->scene, "the .pov template")->required();
    sub->add_option("-W,--width", o->width, "image width, pixels")->capture_default_str();
    sub->add_option("-H,--height", o->height, "image height, pixels")->capture_default_str();
    sub->add_option("-o,--output", o->out_dir,
                    "directory for the results (default build/study/SCENE)")
        ->check(non_empty_name());
    sub->add_option("--counts", o->uniform_counts, "equal-layer counts")->delimiter(',');
    sub->add_option("--graded-levels", o->graded_levels, "graded designs: levels per index range")
        ->delimiter(',');
    sub->add_option("--graded-steps", o->graded_steps,
                    "graded designs: levels a level ray gains from the grading")
        ->delimiter(',');
    sub->add_option("--rays-per-row", o->rays_per_row, "continuum rays per pixel row")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    sub->add_flag("!--no-render", o->render, "do not render the plane designs with POV-Ray");
    sub->add_option("-L,--library-path", o->library_paths, "extra include directory");
    sub->callback([o] {
        StudyOptions s = *o;
        if (s.width < 1 || s.height < 1 || s.width > 20000 || s.height > 20000) {
            std::cerr << "mirage study: image size " << s.width << "x" << s.height
                      << " must be 1 to 20000 pixels each way\n";
            throw CommandFailed{1};
        }
        s.progress = [](const std::string& line) { std::cerr << "study: " << line << "\n"; };
        auto r = run_design_study(s);
        if (!r) {
            std::cerr << "mirage study: " << escape_terminal(r.message()) << "\n";
            throw CommandFailed{1};
        }
        std::cout << "wrote " << r->csv_path << "\n      " << r->summary_path << "\n";
        if (r->plotted)
            std::cout << "      " << r->plot_elevation << "\n      " << r->plot_crossings << "\n";
        for (const auto& n : r->notes) std::cout << "note: " << n << "\n";
    });
}

}  // namespace mirage
