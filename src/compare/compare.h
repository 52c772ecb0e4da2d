// `mirage compare`: error against run time for one scene, for the band models POV-Ray
// renders (Berger's equal layers, layers placed where the scene's rays turn, and for real air
// layers at equal steps of the index) and for the
// continuous model (the built-in tracer along polylines within a tolerance).  Every image is
// measured against a reference traced along per-ray paths at a much finer tolerance, after
// both are quantized to the 8-bit codes POV-Ray writes.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "util/result.h"
#include "util/scene_input.h"

namespace mirage {

enum class CompareModel {
    UniformBands,    // Berger, Trout & Levit's equal layers, rendered by POV-Ray
    AdaptiveBands,   // layers fitted to the scene's rays, rendered by POV-Ray
    IndexStepBands,  // real air's layers at equal steps of the index, rendered by POV-Ray
    CorrectedBands,  // the corrected camera: every pixel aimed through N layers (POV-Ray)
    Polyline,        // the tracer along every ray's own path
    Scanline,        // the tracer along one path per image row (Khote & Howard)
};

/// "uniform-bands", "adaptive-bands", "index-step-bands", "corrected-bands", "polyline",
/// "scanline": the `model`
/// column.
std::string model_name(CompareModel model);

/// POV-Ray's ceiling on max_trace_level: a design whose camera rays need more renders black
/// where they run out.
constexpr int kPovrayMaxTraceLevel = 256;

struct CompareOptions : SceneInput {
    std::string out_dir;                   // default build/compare/<scene name>
    double reference_tolerance_px = 0.02;  // the reference's path tolerance, pixels
    std::vector<int> counts;  // uniform layer counts; empty: 8, 16, 32, ... doubling until
                              // a count exceeds the trace-level budget (at most 4096)
    std::vector<double> tolerances = {4, 2, 1, 0.5, 0.25, 0.1};  // adaptive layers, px
    std::vector<int> steps;  // index steps (real air only); empty: 8, 16, ... 256 doubling
                             // while a design stays within the trace-level budget
    std::vector<int> corrected_counts = {6, 12, 24, 48};  // layers of the corrected camera
    std::vector<double> trace_tolerances = {4, 2, 1, 0.5, 0.25, 0.1};  // polylines, px
    bool scanline = false;          // also the per-scanline tracer at trace_tolerances
    double threshold = 0.05;        // a pixel is "over" when a channel differs by more (code / 255)
    int threads = 0;                // threads of the tracer and of POV-Ray; 0: all cores
    std::string povray = "povray";  // the POV-Ray program, looked up on PATH
    std::string gnuplot = "gnuplot";  // the plotting program; missing: no plot, a note
    std::function<void(const std::string&)> progress;  // one line per setting (may be empty)
};

/// One rendered setting of one model, measured against the reference.
struct CompareRow {
    CompareModel model = CompareModel::Polyline;
    double setting = 0.0;  // layer count (uniform), index steps, or tolerance in pixels
    int layers = -1;       // boundaries of a band design; -1 for the tracer
    double seconds = 0.0;  // wall clock: the POV-Ray process, or the tracer call (parse, trace,
                           // PNG)
    double render_seconds = 0.0;       // POV-Ray's own "Trace Time"; the tracer's render loop
    double cpu_seconds = 0.0;          // POV-Ray's render CPU-seconds; the process's CPU time over
                                       // the tracer call
    double process_cpu_seconds = 0.0;  // processor time of the whole POV-Ray process (parse
                                       // included, its idle waits not); the tracer call's
    int threads = 0;                   // render threads
    double compile_seconds = -1.0;     // mirage compile's time (bands); -1 for the tracer
    double rmse = 0.0, psnr_db = 0.0;  // against the reference, 8-bit codes / 255
    double share_over = 0.0;           // share of pixels with a channel over the threshold
    double max_error_px = 0.0;      // bands: the largest path error over the pixel centres as the
                                    // compile report measures it (+inf where a ray is cut off);
                                    // tracer: its tolerance, which bounds the paths' error by
                                    // construction (not measured)
    double p95_error_px = -1.0;     // bands: 95th percentile of the same; -1 for the tracer
    double p95_shift_rows = -1.0;   // bands: 95th percentile of the rows the picture moves
                                    // (compile's pixel check); -1 for the tracer
    int max_trace_level = -1;       // bands: as compile measures it; -1 for the tracer
    double segments_per_ray = 0.0;  // tracer: straight segments per propagated ray
    std::string image;              // the render, relative to the output directory
};

/// The machine the times were taken on.
struct MachineInfo {
    int cores = 0;     // as nproc counts them
    std::string cpu;   // "model name" of /proc/cpuinfo
    std::string load;  // /proc/loadavg's first three figures when the sweep started
};
MachineInfo read_machine_info();

struct CompareResult {
    std::string scene, name;  // the scene file and its name without extension
    int width = 0, height = 0;
    std::string atmosphere;
    std::string out_dir;  // absolute
    double threshold = 0.0;
    double reference_tolerance_px = 0.0;
    double reference_seconds = 0.0;
    int reference_threads = 0;
    std::vector<CompareRow> rows;
    std::vector<std::string> notes;  // settings skipped or not reached, and why
    // Straight rays rendered by POV-Ray against the tracer: how far apart the two renderers
    // are with no atmosphere at all, a floor the band models cannot go below.
    std::optional<double> straight_rmse;
    std::string povray_version;
    MachineInfo machine;
    std::string command;       // the command line that reproduces the sweep
    std::string caption_font;  // empty: the contact sheet has no captions
    bool plotted = false;      // gnuplot drew error_vs_time.png and .svg
    std::string csv_path, plot_script, plot_png, plot_svg, sheet_path, summary_path, reference_path;
};

/// Checks the option values; the message names the option and the value at fault.  The
/// reference must be finer than every tolerance of the sweep.
Status validate_compare_options(const CompareOptions& options);

/// Runs the sweep and writes results.csv, error_vs_time.gp/.png/.svg, contact_sheet.png and
/// summary.md to the output directory (renders under renders/, each design's compile output
/// and POV-Ray log under work/).  Every file goes through a temporary name.  Fails before any
/// render on bad options, a missing POV-Ray, a scene that does not parse (file:line:column)
/// or declares no atmosphere; a setting that cannot be compiled or rendered is skipped with a
/// note.
Result<CompareResult> run_comparison(const CompareOptions& options);

/// The `mirage compare` command line with every setting spelled out.
std::string compare_command_line(const CompareOptions& options);

}  // namespace mirage
