// `mirage compile SCENE.pov`: the scene with a banded refraction medium for POV-Ray.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "compile/compile.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

struct CompileCliOptions {
    CompileOptions compile;
    double tolerance = 0.0;
    std::string layers;
    int count = 0;
    bool json = false;
    bool quiet = false;
};

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
                    "the image the .ini renders (default next to the directory)")
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
    sub->add_option("--layout", o->compile.layout,
                    "nested (planes), gaps (slabs with gaps: double-precision refraction for "
                    "real air) or auto")
        ->check(CLI::IsMember({"auto", "nested", "gaps"}))
        ->capture_default_str();
    sub->add_option("--error-map", o->compile.error_map,
                    "also write every pixel centre's path error, pixels, as a float image (.exr)")
        ->check(non_empty_name());
    sub->add_flag("--json", o->json, "print the report as JSON");
    sub->add_flag("-q,--quiet", o->quiet, "print nothing but errors");
    sub->callback([o, tol, layers, count] {
        CompileOptions c = o->compile;
        if (*tol) c.tolerance_px = o->tolerance;
        if (*layers)
            c.layers = o->layers == "uniform"       ? LayerMode::Uniform
                       : o->layers == "index-steps" ? LayerMode::IndexSteps
                                                    : LayerMode::Adaptive;
        if (*count) c.layer_count = o->count;
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
    });
}

}  // namespace mirage
