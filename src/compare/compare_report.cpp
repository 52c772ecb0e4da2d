#include "compare/compare_report.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "util/format.h"
#include "report/gnuplot_run.h"

namespace mirage {

namespace {

const CompareModel kModels[] = {CompareModel::UniformBands,   CompareModel::AdaptiveBands,
                                CompareModel::IndexStepBands, CompareModel::CorrectedBands,
                                CompareModel::Polyline,       CompareModel::Scanline};

bool is_band(CompareModel m) {
    return m == CompareModel::UniformBands || m == CompareModel::AdaptiveBands ||
           m == CompareModel::IndexStepBands || m == CompareModel::CorrectedBands;
}

// Settings that are counts (finer: larger), not tolerances (finer: smaller).
bool counted(CompareModel m) {
    return m == CompareModel::UniformBands || m == CompareModel::IndexStepBands ||
           m == CompareModel::CorrectedBands;
}

std::string csv_number(double v, int digits) {
    return std::isinf(v) ? shortest(v) : sig(v, digits);
}

/// Seconds for people: three significant figures.
std::string secs(double s) { return sig(s, 3) + " s"; }

std::string rmse_text(double e) { return sig(e, 3); }

/// "RMSE 0.0123 (the lowest both reach)": where a comparison is made.
std::string describe_time(const TimeAtError& t) {
    if (t.at_most)
        return "at most " + secs(t.seconds) + " (its fastest setting, " + t.from +
               ", is already below that error)";
    if (t.from == t.to) return secs(t.seconds) + " (at " + t.from + ")";
    return secs(t.seconds) + " (interpolated between " + t.from + " and " + t.to + ")";
}

/// "4.6 times faster" / "at least 4.6 times faster" / "2.1 times slower".
std::string describe_ratio(const EqualError& e, const std::string& b_name) {
    const double r = e.speedup();
    std::string qualifier;
    if (e.b.at_most && !e.a.at_most) qualifier = r >= 1.0 ? "at least " : "at most ";
    if (e.a.at_most && !e.b.at_most) qualifier = r >= 1.0 ? "at most " : "at least ";
    if (r >= 1.0) return b_name + " " + qualifier + sig(r, 3) + " times faster";
    return b_name + " " + qualifier + sig(1.0 / r, 3) + " times slower";
}


/// The threads of a model's renders, "2" or "1-2".
std::string threads_of(const std::vector<CompareRow>& rows, bool bands) {
    int lo = 0, hi = 0;
    for (const auto& r : rows) {
        if (is_band(r.model) != bands || r.threads <= 0) continue;
        lo = lo == 0 ? r.threads : std::min(lo, r.threads);
        hi = std::max(hi, r.threads);
    }
    if (hi == 0) return "?";
    return lo == hi ? std::to_string(hi) : std::to_string(lo) + "-" + std::to_string(hi);
}

/// "- POV-Ray's process took 0.71 s more than its Trace Time (median)...": the fixed cost
/// that wall-clock comparisons with the tracer include.
std::string povray_overhead(const std::vector<CompareRow>& rows) {
    std::vector<double> extra;
    for (const auto& r : rows)
        if (is_band(r.model) && r.render_seconds > 0.0)
            extra.push_back(r.seconds - r.render_seconds);
    if (extra.empty()) return "";
    std::sort(extra.begin(), extra.end());
    const double median = extra[extra.size() / 2];
    return "- POV-Ray's process took " + secs(median) +
           " longer than its Trace Time (median over the band renders): start-up, parsing, "
           "bounding and writing the PNG. Wall-clock comparisons with the tracer include it; "
           "the render-time lines above leave it out.\n";
}

}  // namespace

std::string setting_text(const CompareRow& row) {
    if (counted(row.model)) return std::to_string(static_cast<int>(std::lround(row.setting)));
    return shortest(row.setting);
}

std::string setting_label(const CompareRow& row) {
    if (row.model == CompareModel::UniformBands) return setting_text(row) + " layers";
    if (row.model == CompareModel::IndexStepBands) return setting_text(row) + " steps";
    if (row.model == CompareModel::CorrectedBands) return setting_text(row) + " layers";
    return setting_text(row) + " px";
}

std::vector<TradeoffPoint> model_front(const std::vector<CompareRow>& rows, CompareModel model,
                                       TimeBasis basis) {
    std::vector<TradeoffPoint> points;
    for (const auto& r : rows)
        if (r.model == model)
            points.push_back({basis == TimeBasis::Wall     ? r.seconds
                              : basis == TimeBasis::Render ? r.render_seconds
                                                           : r.process_cpu_seconds,
                              r.rmse, setting_label(r)});
    return pareto_front(std::move(points));
}

Headlines compute_headlines(const std::vector<CompareRow>& rows, TimeBasis basis) {
    const auto uniform = model_front(rows, CompareModel::UniformBands, basis);
    const auto adaptive = model_front(rows, CompareModel::AdaptiveBands, basis);
    const auto steps = model_front(rows, CompareModel::IndexStepBands, basis);
    const auto polyline = model_front(rows, CompareModel::Polyline, basis);
    const auto corrected = model_front(rows, CompareModel::CorrectedBands, basis);
    Headlines h;
    h.corrected_vs_uniform = compare_at_equal_error(uniform, corrected);
    h.corrected_vs_adaptive = compare_at_equal_error(adaptive, corrected);
    h.adaptive_vs_uniform = compare_at_equal_error(uniform, adaptive);
    h.tracer_vs_adaptive = compare_at_equal_error(adaptive, polyline);
    h.tracer_vs_uniform = compare_at_equal_error(uniform, polyline);
    h.steps_vs_uniform = compare_at_equal_error(uniform, steps);
    h.tracer_vs_steps = compare_at_equal_error(steps, polyline);
    return h;
}

std::vector<std::string> error_rises(const std::vector<CompareRow>& rows) {
    std::vector<std::string> out;
    for (CompareModel m : kModels) {
        // From coarse to fine: more layers, or a smaller tolerance.
        std::vector<const CompareRow*> ordered;
        for (const auto& r : rows)
            if (r.model == m) ordered.push_back(&r);
        std::stable_sort(ordered.begin(), ordered.end(), [m](const auto* x, const auto* y) {
            return counted(m) ? x->setting < y->setting : x->setting > y->setting;
        });
        for (size_t i = 1; i < ordered.size(); ++i)
            if (ordered[i]->rmse > ordered[i - 1]->rmse)
                out.push_back(model_name(m) + ": RMSE " + rmse_text(ordered[i]->rmse) + " at " +
                              setting_label(*ordered[i]) + " against " +
                              rmse_text(ordered[i - 1]->rmse) + " at " +
                              setting_label(*ordered[i - 1]));
    }
    return out;
}

std::string results_csv(const CompareResult& result) {
    std::ostringstream out;
    out << "model,setting,layers,seconds,render_seconds,cpu_seconds,threads,compile_seconds,"
           "rmse,psnr,share_over,max_error_px,p95_error_px,p95_shift_rows,max_trace_level,"
           "segments_per_ray,"
           "image,process_cpu_seconds\n";
    for (const auto& r : result.rows) {
        const bool band = is_band(r.model);
        out << model_name(r.model) << ',' << setting_text(r) << ','
            << (band ? std::to_string(r.layers) : "") << ',' << sig(r.seconds, 4) << ','
            << sig(r.render_seconds, 4) << ',' << sig(r.cpu_seconds, 4) << ',' << r.threads << ','
            << (band ? sig(r.compile_seconds, 4) : "") << ',' << sig(r.rmse, 6) << ','
            << csv_number(r.psnr_db, 5) << ',' << sig(r.share_over, 6) << ','
            << csv_number(r.max_error_px, 6) << ',' << (band ? csv_number(r.p95_error_px, 6) : "")
            << ',' << (band ? csv_number(r.p95_shift_rows, 6) : "") << ','
            << (band ? std::to_string(r.max_trace_level) : "") << ','
            << (band ? "" : sig(r.segments_per_ray, 4)) << ',' << r.image << ','
            << sig(r.process_cpu_seconds, 4) << '\n';
    }
    return out.str();
}

std::string gnuplot_script(const CompareResult& result) {
    std::ostringstream gp;
    gp << "# error_vs_time.gp: error against run time for " << result.name << " at " << result.width
       << "x" << result.height << ", written by mirage compare.\n"
       << "# Run it in this directory: gnuplot error_vs_time.gp\n"
       << "if (!exists(\"png_out\")) png_out = \"error_vs_time.png\"\n"
       << "if (!exists(\"svg_out\")) svg_out = \"error_vs_time.svg\"\n\n";
    std::vector<CompareModel> present;
    for (CompareModel m : kModels) {
        bool any = false;
        for (const auto& r : result.rows) any = any || (r.model == m && r.rmse > 0.0);
        if (!any) continue;
        present.push_back(m);
        std::string block = model_name(m);
        std::replace(block.begin(), block.end(), '-', '_');
        gp << "# " << model_name(m) << ": seconds, RMSE, setting\n$" << block << " << EOD\n";
        for (const auto& r : result.rows)
            if (r.model == m && r.rmse > 0.0)  // a log axis cannot show an RMSE of 0
                gp << sig(r.seconds, 6) << ' ' << sig(r.rmse, 6) << ' ' << gnuplot_quoted(setting_text(r))
                   << '\n';
        gp << "EOD\n\n";
    }
    gp << "set title "
       << gnuplot_quoted(result.name + " at " + std::to_string(result.width) + "x" +
                   std::to_string(result.height) +
                   ": error against run time (reference: per-ray paths within " +
                   shortest(result.reference_tolerance_px) + " px)")
       << " noenhanced\n"
       << "set xlabel \"run time, seconds (wall clock: POV-Ray process for bands, tracer for "
          "polylines)\" noenhanced\n"
       << "set ylabel \"RMSE against the reference (8-bit codes / 255)\" noenhanced\n"
       << "set logscale xy\n"
       << "set format x \"%g\"\n"
       << "set format y \"%g\"\n"
       << "set grid xtics ytics mxtics mytics lc rgb \"#dddddd\"\n"
       << "set key top right box opaque noenhanced\n"
       << "set offsets graph 0.05, graph 0.12, graph 0.1, graph 0.05\n";
    const std::map<CompareModel, std::pair<std::string, std::string>> style = {
        {CompareModel::UniformBands, {"#d62728", "7"}},     // red, filled circles
        {CompareModel::AdaptiveBands, {"#1f77b4", "5"}},    // blue, filled squares
        {CompareModel::IndexStepBands, {"#ff7f0e", "13"}},  // orange, filled diamonds
        {CompareModel::CorrectedBands, {"#17becf", "15"}},  // cyan, filled pentagons
        {CompareModel::Polyline, {"#2ca02c", "9"}},         // green, filled triangles
        {CompareModel::Scanline, {"#9467bd", "11"}},        // purple, filled triangles down
    };
    const std::map<CompareModel, std::string> titles = {
        {CompareModel::UniformBands, "uniform-bands (POV-Ray, N equal layers)"},
        {CompareModel::AdaptiveBands, "adaptive-bands (POV-Ray, tolerance px)"},
        {CompareModel::IndexStepBands, "index-step-bands (POV-Ray, N equal index steps)"},
        {CompareModel::CorrectedBands, "corrected-bands (POV-Ray, corrected camera, N layers)"},
        {CompareModel::Polyline, "polyline (tracer, tolerance px)"},
        {CompareModel::Scanline, "scanline (tracer, per-row paths, px)"},
    };
    std::ostringstream plot;
    plot << "plot ";
    for (size_t i = 0; i < present.size(); ++i) {
        std::string block = model_name(present[i]);
        std::replace(block.begin(), block.end(), '-', '_');
        const auto& [colour, pt] = style.at(present[i]);
        if (i > 0) plot << ", \\\n     ";
        plot << "$" << block << " using 1:2 with linespoints lw 2 pt " << pt << " ps 1.2 lc rgb "
             << gnuplot_quoted(colour) << " title " << gnuplot_quoted(titles.at(present[i])) << ", \\\n     $"
             << block << " using 1:2:3 with labels offset char 0.9,0.6 font \",9\" tc rgb "
             << gnuplot_quoted(colour) << " notitle";
    }
    if (present.empty()) plot << "1/0 notitle  # no model has a row to plot";
    gp << "\nif (strstrt(GPVAL_TERMINALS, \"pngcairo\") > 0) {\n"
       << "    set terminal pngcairo size 1100,700 font \"DejaVu Sans,11\"\n"
       << "} else {\n"
       << "    set terminal png size 1100,700\n"
       << "}\n"
       << "set output png_out\n"
       << plot.str() << "\n"
       << "set terminal svg size 1100,700 dynamic font \"DejaVu Sans,11\"\n"
       << "set output svg_out\n"
       << "replot\n"
       << "set output\n";
    return gp.str();
}

namespace {

// The summary's opening: the scene and its reference, and one row per rendered setting.
void write_summary_table(std::ostream& md, const CompareResult& r) {
    md << "# mirage compare: " << r.name << "\n\n"
       << "Scene `" << r.scene << "` at " << r.width << "x" << r.height << ", atmosphere "
       << r.atmosphere << ". Every render is compared with a reference traced along per-ray "
       << "paths within " << shortest(r.reference_tolerance_px) << " px ("
       << secs(r.reference_seconds) << " on " << r.reference_threads << " threads), both "
       << "quantized to POV-Ray's 8-bit PNG codes.\n\n";

    md << "| model | setting | layers | seconds | RMSE | PSNR (dB) | pixels over "
       << shortest(r.threshold) << " | max error (px) | p95 error (px) | p95 shift (rows) |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& row : r.rows) {
        const bool band = is_band(row.model);
        md << "| " << model_name(row.model) << " | " << setting_label(row) << " | "
           << (band ? std::to_string(row.layers) : "") << " | " << sig(row.seconds, 3) << " | "
           << sig(row.rmse, 3) << " | " << sig(row.psnr_db, 3) << " | "
           << sig(100.0 * row.share_over, 3) << " % | "
           << (band ? sig(row.max_error_px, 3) : "<= " + sig(row.max_error_px, 3)) << " | "
           << (band ? sig(row.p95_error_px, 3) : "") << " | "
           << (band ? sig(row.p95_shift_rows, 3) : "") << " |\n";
    }
    if (r.rows.empty()) md << "| (no setting was rendered) | | | | | | | | | |\n";
}

}  // namespace

std::string summary_markdown(const CompareResult& r) {
    std::ostringstream md;
    write_summary_table(md, r);

    md << "\n## At equal error\n\n"
       << "Each model's settings form a curve of RMSE against seconds; settings that took longer "
          "for less than "
       << sig(100.0 * kMinErrorGain, 3)
       << " % less error are left out of it. Seconds at a common RMSE are interpolated in "
          "log-log between the two neighbouring settings of each curve; the common RMSE is the "
          "lowest both curves reach.\n\n";
    const Headlines h = compute_headlines(r.rows);
    const Headlines hr = compute_headlines(r.rows, TimeBasis::Render);
    const Headlines hp = compute_headlines(r.rows, TimeBasis::Processor);
    const std::string tracer_threads = threads_of(r.rows, false);
    const std::string povray_threads = threads_of(r.rows, true);
    // One headline: "at RMSE e, <a> takes <time> [on N threads] and <b> <time>: <ratio>", then
    // the same on render time alone.  `b_is`: the ratio's subject with its verb ("the tracer
    // is"); the render-time line names the subject alone.
    auto headline = [&md](const std::optional<EqualError>& wall,
                          const std::optional<EqualError>& render,
                          const std::optional<EqualError>& processor, const std::string& title,
                          const std::string& a_takes, const std::string& a_threads,
                          const std::string& b, const std::string& b_threads,
                          const std::string& b_is) {
        if (!wall) return false;
        const EqualError& e = *wall;
        md << "- **" << title << ":** at RMSE " << rmse_text(e.error) << ", " << a_takes << " "
           << describe_time(e.a) << a_threads << " and " << b << " " << describe_time(e.b)
           << b_threads << ": " << describe_ratio(e, b_is) << ".\n";
        const std::string subject = b_is.substr(0, b_is.rfind(' '));
        for (const auto& [other, basis] :
             {std::pair{&render, "render time alone (POV-Ray's Trace Time, the tracer's render "
                                 "loop)"},
              std::pair{&processor, "processor time (the whole process, parse included, without "
                                    "the wall clock's idle waits)"}})
            if (*other)
                md << "  - On " << basis << ", at RMSE " << rmse_text((*other)->error) << ": "
                   << describe_time((*other)->a) << " against " << describe_time((*other)->b)
                   << ", " << describe_ratio(**other, subject) << ".\n";
        return true;
    };
    const std::string on_povray = " on " + povray_threads + " threads";
    const std::string on_tracer = " on " + tracer_threads + " threads";
    if (!headline(h.adaptive_vs_uniform, hr.adaptive_vs_uniform, hp.adaptive_vs_uniform,
                  "Adaptive against uniform layers", "uniform layers take", "", "adaptive layers",
                  "", "adaptive layers are"))
        md << "- Adaptive against uniform layers: not compared (a model has no rendered "
              "setting).\n";
    headline(h.corrected_vs_uniform, hr.corrected_vs_uniform, hp.corrected_vs_uniform,
             "The corrected camera against uniform layers", "uniform layers take", "",
             "the corrected camera", "", "the corrected camera is");
    headline(h.corrected_vs_adaptive, hr.corrected_vs_adaptive, hp.corrected_vs_adaptive,
             "The corrected camera against adaptive layers", "adaptive layers take", "",
             "the corrected camera", "", "the corrected camera is");
    headline(h.tracer_vs_adaptive, hr.tracer_vs_adaptive, hp.tracer_vs_adaptive,
             "The tracer against POV-Ray with adaptive layers", "POV-Ray takes", on_povray,
             "the tracer", on_tracer, "the tracer is");
    headline(h.steps_vs_uniform, hr.steps_vs_uniform, hp.steps_vs_uniform,
             "Index steps against uniform layers", "uniform layers take", "", "equal index steps",
             "", "index steps are");
    headline(h.tracer_vs_steps, hr.tracer_vs_steps, hp.tracer_vs_steps,
             "The tracer against POV-Ray with index steps", "POV-Ray takes", on_povray,
             "the tracer", on_tracer, "the tracer is");
    headline(h.tracer_vs_uniform, hr.tracer_vs_uniform, hp.tracer_vs_uniform,
             "The tracer against POV-Ray with uniform layers", "POV-Ray takes", "", "the tracer",
             "", "the tracer is");
    if (r.straight_rmse && *r.straight_rmse == 0.0) {
        md << "- **The renderers agree:** with straight rays (no atmosphere) POV-Ray and the "
              "tracer draw the same 8-bit picture (RMSE 0), so the band models' error is the "
              "bands' own.\n";
    } else if (r.straight_rmse) {
        md << "- **The renderers' floor:** with straight rays (no atmosphere) POV-Ray's render "
              "and the tracer's differ by RMSE "
           << rmse_text(*r.straight_rmse)
           << ". The band models, rendered by POV-Ray, cannot be expected below about that; the "
              "polylines are rendered by the reference's own tracer and can reach 0.\n";
    }
    const auto rises = error_rises(r.rows);
    if (!rises.empty()) {
        md << "\n## Where the error does not fall with a finer setting\n\n";
        for (const auto& s : rises) md << "- " << s << "\n";
    }
    if (!r.notes.empty()) {
        md << "\n## Notes\n\n";
        for (const auto& n : r.notes) md << "- " << n << "\n";
    }
    md << "\n## How the figures were measured\n\n"
       << "- **seconds**: wall clock of the whole POV-Ray process (parse, bounding, render, PNG) "
          "for the band models, and of the whole tracer call (parse, render, PNG) for the "
          "polylines. `results.csv` also has `render_seconds` (POV-Ray's \"Trace Time\", the "
          "tracer's render loop), `cpu_seconds`, `process_cpu_seconds` (processor time of the "
          "whole POV-Ray process, parse included: POV-Ray 3.7 waits about 0.6 s of wall clock "
          "on even a 1x1 image, which this leaves out) and `threads`; compile time is in "
          "`compile_seconds` and not counted.\n"
       << "- **RMSE, PSNR, pixels over " << shortest(r.threshold)
       << "**: over all pixels and channels of 8-bit codes / 255; POV-Ray's PNGs as written, "
          "the tracer's linear images encoded as POV-Ray encodes them.\n"
       << "- **max error, p95 error (px)**: for the band models, the path error of every pixel "
          "centre's camera ray in the layers against the exact ray, in pixels, as `mirage "
          "compile` measures it (inf: a ray cut off at POV-Ray's trace-level ceiling). For the "
          "polylines, the tracer's tolerance, which bounds their path error by construction; "
          "it is not measured.\n"
       << "- **p95 shift (rows)**: for the band models, how many rows in its column the "
          "picture of 95 % of the pixels is from where the exact image shows the same "
          "(`mirage compile`'s pixel check: every pixel's ray to the objects and through the "
          "reflections).\n"
       << povray_overhead(r.rows)
       << "- The uniform counts double until a design's camera rays, with their reflections, "
          "need more than POV-Ray's "
       << kPovrayMaxTraceLevel
       << " trace levels; for real air the counts of index steps double the same way, up to "
          "256, and stop where `mirage compile` has to use fewer.\n";
    md << "\n## Machine\n\n"
       << "- " << r.machine.cores << " cores (nproc), "
       << (r.machine.cpu.empty() ? "CPU unknown" : r.machine.cpu) << "; load average "
       << (r.machine.load.empty() ? "unknown" : r.machine.load) << " when the sweep started.\n"
       << "- POV-Ray " << (r.povray_version.empty() ? "(version unknown)" : r.povray_version)
       << " on " << povray_threads << " threads; the tracer on " << tracer_threads << " threads.\n";
    md << "\n## Files\n\n"
       << "`results.csv`, `error_vs_time.png` and `.svg` (from `error_vs_time.gp`), "
          "`contact_sheet.png`"
       << (r.caption_font.empty() ? " (no captions: OpenImageIO found no font; the tiles "
                                    "follow the table's order after the reference)"
                                  : "")
       << ", `reference.png`, the renders under `renders/`, each design's `mirage compile` "
          "output and POV-Ray log under `work/`.\n";
    md << "\n## Command\n\n```\n" << r.command << "\n```\n";
    return md.str();
}

}  // namespace mirage
