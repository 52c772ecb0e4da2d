// What `mirage compare` writes about a sweep: the results table as CSV, the gnuplot script
// of error against run time, and the markdown summary with the figures at equal error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/compare.h"
#include "compare/tradeoff.h"

namespace mirage {

/// "64" for a layer count, "0.5" for a tolerance: the `setting` column.
std::string setting_text(const CompareRow& row);

/// "64 layers" or "0.5 px", for people.
std::string setting_label(const CompareRow& row);

/// Which time a comparison counts.
enum class TimeBasis {
    Wall,    // `seconds`: the whole POV-Ray process, the whole tracer call
    Render,  // `render_seconds`: POV-Ray's Trace Time, the tracer's render loop
    // `process_cpu_seconds`: processor time of the whole POV-Ray process (parse included,
    // without the wall clock's idle waits), of the whole tracer call
    Processor,
};

/// The rows of one model as points of error (RMSE) against time, on their Pareto front.
std::vector<TradeoffPoint> model_front(const std::vector<CompareRow>& rows, CompareModel model,
                                       TimeBasis basis = TimeBasis::Wall);

/// The figures at equal error the summary leads with (empty where a model has no row).
struct Headlines {
    std::optional<EqualError> adaptive_vs_uniform;    // a: uniform, b: adaptive
    std::optional<EqualError> tracer_vs_adaptive;     // a: adaptive, b: polyline
    std::optional<EqualError> tracer_vs_uniform;      // a: uniform, b: polyline
    std::optional<EqualError> steps_vs_uniform;       // a: uniform, b: index steps
    std::optional<EqualError> tracer_vs_steps;        // a: index steps, b: polyline
    std::optional<EqualError> corrected_vs_uniform;   // a: uniform, b: corrected camera
    std::optional<EqualError> corrected_vs_adaptive;  // a: adaptive, b: corrected camera
};
Headlines compute_headlines(const std::vector<CompareRow>& rows, TimeBasis basis = TimeBasis::Wall);

/// A model's RMSE that rises where its setting gets finer: "adaptive-bands: RMSE 0.0141 at
/// 0.1 px against 0.0122 at 0.25 px".
std::vector<std::string> error_rises(const std::vector<CompareRow>& rows);

/// results.csv: one row per setting, columns model, setting, layers, seconds, render_seconds,
/// cpu_seconds, threads, compile_seconds, rmse, psnr, share_over, max_error_px, p95_error_px,
/// p95_shift_rows, max_trace_level, segments_per_ray, image (empty where a column does not
/// apply).
std::string results_csv(const CompareResult& result);

/// error_vs_time.gp: log-log RMSE against seconds, one curve per model with its points
/// labelled by setting, to error_vs_time.png (pngcairo, else png) and error_vs_time.svg, or
/// to the names in the variables png_out and svg_out when they are set (gnuplot -e).
std::string gnuplot_script(const CompareResult& result);

/// summary.md: what was compared, the table, the figures at equal error, the notes, how the
/// figures were measured, the machine and the command.
std::string summary_markdown(const CompareResult& result);

}  // namespace mirage
