// `mirage compile SCENE.pov`: the scene with a banded refraction medium for POV-Ray.
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "compare/colour_render.h"
#include "compare/povray_render.h"
#include "compile/compile.h"
#include "util/format.h"
#include "util/text_escape.h"

namespace mirage {

namespace fs = std::filesystem;

namespace {

struct CompileCliOptions {
    CompileOptions compile;
    std::string layout = "auto";  // --layout, read into compile.layout
    double tolerance = 0.0;
    double clock = 0.0;
    std::vector<std::string> declares;
    std::string layers;
    int count = 0;
    bool json = false;
    bool quiet = false;
    std::string camera = "corrected";
    bool render = false;
    bool strict = false;
    int check_samples = 0;
    std::vector<double> wavelengths;  // --wavelengths
    bool colour = false;              // --colour
};

// Colour: a design per wavelength, each rendered with --render and the channels combined.
void compile_in_colour(const CompileCliOptions& o, const CompileOptions& c,
                       const ChannelWavelengths& nm) {
    auto report = compile_colour(c, nm, o.render);
    if (!report) {
        std::cerr << "mirage compile: " << escape_terminal(report.message()) << "\n";
        throw CommandFailed{1};
    }
    bool within = true;
    if (o.json) std::cout << "[\n";
    for (std::size_t k = 0; k < report->channels.size(); ++k) {
        const CompileReport& r = report->channels[k].report;
        within = within && r.within_tolerance;
        if (o.json) {
            std::cout << (k ? ",\n" : "") << report_json(r);
        } else if (!o.quiet) {
            std::cout << report_text(r);
        }
    }
    if (o.json) std::cout << "]\n";
    if (!o.quiet && !o.json) std::cout << colour_compile_summary(*report);
    if (o.strict && !within) throw CommandFailed{3};
}

}  // namespace

void setup_compile_command(CLI::App& app) {
    auto o = std::make_shared<CompileCliOptions>();
    auto* sub = app.add_subcommand(
        "compile",
        "Fit horizontal refractive layers to a scene's camera rays and write them for POV-Ray");
    sub->add_option("scene", o->compile.scene, "the .pov template")->required();
    sub->add_option("-W,--width", o->compile.width, "image width, pixels")->capture_default_str();
    sub->add_option("-H,--height", o->compile.height, "image height, pixels")
        ->capture_default_str();
    sub->add_option("-o,--output", o->compile.out_dir,
                    "directory for mirage_layers.inc, SCENE.ini, layers.csv, report.json "
                    "(default build/render/SCENE)")
        ->check(non_empty_name());
    sub->add_option("--image", o->compile.image,
                    "the image the .ini renders (default SCENE.png in the output directory)")
        ->check(non_empty_name());
    auto* tol = sub->add_option("--tolerance", o->tolerance,
                                "largest path error, pixels (default: Mirage_Tolerance, else 0.5)");
    auto* layers = sub->add_option("--layers", o->layers,
                                   "adaptive (default), uniform (Berger's equal layers) or "
                                   "index-steps (equal steps of the index: real air's design)")
                       ->check(CLI::IsMember({"adaptive", "uniform", "index-steps"}));
    auto* count =
        sub->add_option("--count", o->count, "number of uniform layers, or of index steps");
    sub->add_option("-L,--library-path", o->compile.library_paths,
                    "extra include directory (searched first)");
    sub->add_flag("--antialias", o->compile.antialias, "antialias the render (+A0.3)");
    sub->add_option("--fit-columns", o->compile.fit_columns,
                    "image columns to fit the layers to, spread from the centre to the edge")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    sub->add_option("--layout", o->layout,
                    "nested (planes), gaps (slabs with gaps: double-precision refraction for "
                    "real air) or auto")
        ->check(CLI::IsMember({"auto", "nested", "gaps"}))
        ->capture_default_str();
    sub->add_option("--error-map", o->compile.error_map,
                    "also write every pixel centre's path error, pixels, as a float image (.exr)")
        ->check(non_empty_name());
    sub->add_option("--camera", o->camera,
                    "corrected (every pixel's ray aimed through the layers to where its exact "
                    "ray ends: a mesh camera) or perspective (the scene's own camera)")
        ->check(CLI::IsMember({"corrected", "perspective"}))
        ->capture_default_str();
    sub->add_flag("--render", o->render,
                  "then render it with POV-Ray (beside the .ini), the corrected camera's extra "
                  "top row dropped");
    sub->add_flag("--strict", o->strict, "exit 3 when the pixels miss the tolerance");
    auto* samples =
        sub->add_option("--check-samples", o->check_samples,
                        "check a grid of N x N rays in every pixel (default: 1, the rays POV-Ray "
                        "shoots, with the corrected camera and no antialiasing; else 3)")
            ->check(CLI::Range(1, 5));
    auto* clock = sub->add_option("--clock", o->clock,
                                  "compile the still at this clock (POV-Ray's +K; the .ini "
                                  "renders it with Clock=), one frame of an animation");
    add_declare_option(*sub, o->declares, "; the .ini declares it too");
    auto* wavelengths =
        sub->add_option("--wavelengths", o->wavelengths,
                        "colour: one design per wavelength for the red, green and blue channels, "
                        "nm (e.g. 610,550,465; replaces Mirage_Wavelengths; real air only), in "
                        "OUT/SCENE-<nm>nm/; with --render the channels combined in the image")
            ->delimiter(',')
            ->type_name("R,G,B");
    sub->add_flag("--colour,--color", o->colour,
                  "colour at the default wavelengths 610,550,465 nm (the sRGB primaries')")
        ->excludes(wavelengths);
    sub->add_flag("--json", o->json, "print the report as JSON");
    sub->add_flag("-q,--quiet", o->quiet, "print nothing but errors");
    sub->footer(povray_switches_note(false));
    sub->callback([o, tol, layers, count, samples, clock] {
        CompileOptions c = o->compile;
        if (*tol) c.tolerance_px = o->tolerance;
        if (*clock) c.clock = o->clock;
        c.declares = declared_numbers(o->declares);
        if (*layers)
            c.layers = o->layers == "uniform"       ? LayerMode::Uniform
                       : o->layers == "index-steps" ? LayerMode::IndexSteps
                                                    : LayerMode::Adaptive;
        if (*count) c.layer_count = o->count;
        c.camera = o->camera == "perspective" ? CameraModel::Perspective : CameraModel::Corrected;
        if (o->layout != "auto")
            c.layout = o->layout == "gaps" ? LayerLayout::Gaps : LayerLayout::Nested;
        // The corrected camera without antialiasing shoots the pixel centres only: those are
        // the rays to check.  Antialiased it shoots samples of a 3 x 3 grid.
        c.samples_per_side = *samples ? o->check_samples
                             : (c.camera == CameraModel::Corrected && !c.antialias) ? 1
                                                                                    : 3;
        std::vector<double> asked = o->wavelengths;
        if (o->colour)
            asked.assign(kDefaultChannelWavelengthsNm.begin(), kDefaultChannelWavelengthsNm.end());
        std::string option = o->colour ? "--colour" : "--wavelengths ";
        for (std::size_t k = 0; k < o->wavelengths.size(); ++k)
            option += (k ? "," : "") + shortest(o->wavelengths[k]);
        auto colour = compile_colour_wavelengths(c, asked, option);
        if (!colour) {
            std::cerr << "mirage compile: " << escape_terminal(colour.message()) << "\n";
            throw CommandFailed{1};
        }
        if (*colour) return compile_in_colour(*o, c, **colour);
        auto report = compile_scene(c);
        if (!report) {
            std::cerr << "mirage compile: " << escape_terminal(report.message()) << "\n";
            throw CommandFailed{1};
        }
        if (o->json) {
            std::cout << report_json(*report);
        } else if (!o->quiet) {
            std::cout << report_text(*report);
        }
        if (o->render) {
            const std::string dir = fs::path(report->ini_path).parent_path().string();
            PovrayRenderSettings rs;
            rs.ini = report->ini_path;
            rs.work_dir = dir;
            rs.log = (fs::path(dir) / "povray.log").string();
            if (report->camera == "corrected") rs.crop_top_row = report->image_path;
            auto r = render_povray(rs);
            if (!r) {
                std::cerr << "mirage compile: " << r.message() << "\n";
                throw CommandFailed{1};
            }
            if (r->exit_code != 0) {
                std::cerr << "mirage compile: POV-Ray failed (exit " << r->exit_code << ") on "
                          << report->ini_path << ":\n"
                          << log_tail(rs.log, 20);
                throw CommandFailed{1};
            }
            if (!o->quiet && !o->json)
                std::cout << "  rendered    " << report->image_path << " (POV-Ray "
                          << sig(r->seconds, 3) << " s"
                          << (r->log.cpu_seconds
                                  ? ", " + sig(*r->log.cpu_seconds, 3) + " CPU-seconds"
                                  : std::string())
                          << (r->log.max_level ? ", max level " + std::to_string(*r->log.max_level)
                                               : std::string())
                          << ")\n"
                          << "              " << rs.log << " (POV-Ray's log)\n";
        }
        if (o->strict && !report->within_tolerance) throw CommandFailed{3};
    });
}

}  // namespace mirage
