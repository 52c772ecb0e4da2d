// The compile report as JSON and as text (compile/compile.h).
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "compile/compile.h"
#include "util/format.h"
#include "util/json_text.h"

namespace mirage {

namespace {

/// A figure for the report: the number, or "inf" (JSON has no infinity).
nlohmann::json finite_or_inf(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json("inf");
}

}  // namespace

std::string report_verdict(const CompileReport& r) {
    if (r.within_tolerance)
        return "within the tolerance of " + sig(r.tolerance_px, 3) +
               " px: every pixel's ray ends within it of its exact ray's end";
    std::string s = "missed the tolerance of " + sig(r.tolerance_px, 3) +
                    " px: " + sig(100.0 * r.pixels_over / std::max(1, r.pixels), 3) +
                    "% of pixels over it";
    auto rows = r.rows_over;
    std::sort(rows.begin(), rows.end(), [](const RowExcess& a, const RowExcess& b) {
        return a.max_error_px > b.max_error_px;
    });
    if (!rows.empty()) {
        s += ", worst rows";
        for (size_t i = 0; i < std::min<size_t>(3, rows.size()); ++i)
            s += (i ? ", " : " ") + std::to_string(rows[i].row) + " (" +
                 sig(rows[i].max_error_px, 3) + " px)";
    } else if (r.max_seen_error_px_samples > r.tolerance_px) {
        s += " at the centres, samples up to " + sig(r.max_seen_error_px_samples, 3) + " px";
    }
    return s;
}

std::string report_json(const CompileReport& r) {
    nlohmann::json j;
    j["scene"] = r.scene;
    j["width"] = r.width;
    j["height"] = r.height;
    j["atmosphere"] = r.atmosphere;
    j["mode"] = r.mode;
    j["layout"] = r.layout;
    j["gap"] = r.gap;
    j["tolerance_px"] = r.tolerance_px;
    j["layers"] = r.layers;
    j["layers_below_camera"] = r.below_camera;
    j["layers_above_camera"] = r.above_camera;
    j["p50_error_px"] = r.p50_error_px;
    j["p95_error_px"] = r.p95_error_px;
    j["p95_seen_error_px"] = r.p95_seen_error_px;
    j["max_seen_error_px"] = finite_or_inf(r.max_seen_error_px);
    j["p95_shift_rows"] = r.p95_shift_rows;
    j["max_shift_rows"] = r.max_shift_rows;
    j["pixels_not_shown"] = r.pixels_not_shown;
    j["p99_error_px"] = r.p99_error_px;
    j["max_error_px"] = finite_or_inf(r.max_error_px);
    j["max_error_px_fitted_column"] = r.max_error_px_fitted;
    j["pixels"] = r.pixels;
    j["pixels_over_tolerance"] = r.pixels_over;
    j["within_tolerance"] = r.within_tolerance;
    j["max_crossings"] = r.max_crossings;
    j["max_trace_level"] = r.max_trace_level;
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : r.rows_over)
        rows.push_back({{"row", row.row},
                        {"max_error_px", finite_or_inf(row.max_error_px)},
                        {"pixels_over", row.pixels_over}});
    j["rows_over_tolerance"] = rows;
    j["samples_per_pixel"] = r.samples_per_side * r.samples_per_side;
    j["p95_seen_error_px_samples"] = r.p95_seen_error_px_samples;
    j["max_seen_error_px_samples"] = finite_or_inf(r.max_seen_error_px_samples);
    j["p95_shift_rows_samples"] = r.p95_shift_rows_samples;
    j["max_shift_rows_samples"] = r.max_shift_rows_samples;
    j["samples_not_shown"] = r.samples_not_shown;
    auto lines = [](const std::vector<LineError>& v) {
        nlohmann::json a = nlohmann::json::array();
        for (const auto& l : v)
            a.push_back({{"index", l.index},
                         {"max_seen_error_px", finite_or_inf(l.max_seen_error_px)},
                         {"samples_over", l.samples_over}});
        return a;
    };
    j["worst_rows"] = lines(r.worst_rows);
    j["worst_columns"] = lines(r.worst_columns);
    nlohmann::json stages = nlohmann::json::object();
    for (const auto& [name, sec] : r.stage_seconds) stages[name] = sec;
    j["stage_seconds"] = stages;
    j["left_out"] = r.left_out;
    j["warnings"] = r.warnings;
    j["extent"] = r.extent;
    j["layers_extent"] = r.layers_extent;
    j["seconds"] = r.seconds;
    j["include"] = r.include_path;
    j["ini"] = r.ini_path;
    j["csv"] = r.csv_path;
    j["image"] = r.image_path;
    j["report"] = r.report_path;
    if (!r.error_map_path.empty()) j["error_map"] = r.error_map_path;
    j["camera"] = r.camera;
    if (r.camera == "corrected") {
        j["camera_samples_per_pixel"] = r.camera_samples;
        j["camera_include"] = r.camera_path;
        j["render_scene"] = r.render_scene_path;
        j["p95_camera_error_px"] = finite_or_inf(r.p95_camera_error_px);
        j["max_camera_error_px"] = finite_or_inf(r.max_camera_error_px);
        j["p95_camera_error_px_samples"] = finite_or_inf(r.p95_camera_error_px_samples);
        j["max_camera_error_px_samples"] = finite_or_inf(r.max_camera_error_px_samples);
    }
    j["verdict"] = report_verdict(r);
    return json_text(j) + "\n";
}

std::string report_text(const CompileReport& r) {
    std::ostringstream s;
    s << r.name << " at " << r.width << "x" << r.height << ": " << r.atmosphere << ", " << r.mode
      << " layers, " << r.layout << " layout";
    if (r.layout == "gaps") s << " (gaps of " << sig(r.gap, 3) << " units)";
    s << "\n";
    s << "  layers      " << r.layers << " boundaries (" << r.below_camera << " below the camera, "
      << r.above_camera << " above)";
    if (r.layers > 0) s << " from y = " << sig(r.lowest, 6) << " to " << sig(r.highest, 6);
    s << "\n";
    s << "  error       p50 " << sig(r.p50_error_px, 3) << " px, p95 " << sig(r.p95_error_px, 3)
      << " px, max " << sig(r.max_error_px, 3) << " px over " << r.pixels
      << " pixel centres (tolerance " << sig(r.tolerance_px, 3) << " px)\n";
    if (r.layers > 0) {
        s << "  seen        p95 " << sig(r.p95_seen_error_px, 3) << " px, max "
          << sig(r.max_seen_error_px, 3)
          << " px: where the pixels' rays meet the objects, reflections included\n";
        s << "  shift       p95 " << sig(r.p95_shift_rows, 3) << " rows, max "
          << sig(r.max_shift_rows, 3) << " rows to where the exact image shows the same; "
          << r.pixels_not_shown << " pixels show what no row of their column shows\n";
        if (r.samples_per_side > 1) {
            s << "  samples     seen p95 " << sig(r.p95_seen_error_px_samples, 3) << " px, max "
              << sig(r.max_seen_error_px_samples, 3) << " px; shift p95 "
              << sig(r.p95_shift_rows_samples, 3) << " rows, max "
              << sig(r.max_shift_rows_samples, 3) << " rows over "
              << r.samples_per_side * r.samples_per_side << " samples per pixel\n";
        }
        auto list = [&](const char* what, const std::vector<LineError>& v) {
            s << "  worst " << what;
            for (size_t i = 0; i < v.size(); ++i)
                s << (i ? ", " : " ") << v[i].index << " (" << sig(v[i].max_seen_error_px, 3)
                  << " px)";
            s << "\n";
        };
        if (!r.worst_rows.empty()) list("rows   ", r.worst_rows);
        if (!r.worst_columns.empty()) list("columns", r.worst_columns);
    }
    if (!r.rows_over.empty()) {
        s << "  over        " << r.pixels_over << " pixels in " << r.rows_over.size()
          << " rows exceed the tolerance; worst rows:";
        auto rows = r.rows_over;
        std::sort(rows.begin(), rows.end(), [](const RowExcess& a, const RowExcess& b) {
            return a.max_error_px > b.max_error_px;
        });
        for (size_t i = 0; i < std::min<size_t>(5, rows.size()); ++i)
            s << " row " << rows[i].row << " (" << sig(rows[i].max_error_px, 3) << " px, "
              << rows[i].pixels_over << " px over)"
              << (i + 1 < std::min<size_t>(5, rows.size()) ? "," : "");
        s << "\n";
    }
    s << "  budget      " << r.max_crossings << " boundary crossings per camera ray, trace level "
      << r.max_trace_level << " of 256 with reflections\n";
    for (const auto& l : r.left_out) s << "  left out    " << l << "\n";
    for (const auto& w : r.warnings) s << "  warning     " << w << "\n";
    if (r.camera == "corrected")
        s << "  camera      corrected: every pixel's ray aimed through the layers to its exact "
             "end ("
          << r.camera_samples << (r.camera_samples == 1 ? " ray" : " rays")
          << " per pixel); without reflections p95 " << sig(r.p95_camera_error_px, 3) << " px, max "
          << sig(r.max_camera_error_px, 3) << " px (samples: p95 "
          << sig(r.p95_camera_error_px_samples, 3) << " px, max "
          << sig(r.max_camera_error_px_samples, 3) << " px)\n";
    s << "  wrote       " << r.include_path << "\n              " << r.ini_path
      << "\n              " << r.csv_path << "\n              " << r.report_path << "\n";
    if (r.camera == "corrected")
        s << "              " << r.camera_path << "\n              " << r.render_scene_path << "\n";
    if (!r.error_map_path.empty()) s << "              " << r.error_map_path << "\n";
    s << "  time        " << sig(r.seconds, 3) << " s";
    if (!r.stage_seconds.empty()) {
        s << " (";
        for (size_t i = 0; i < r.stage_seconds.size(); ++i)
            s << (i ? ", " : "") << r.stage_seconds[i].first << " "
              << sig(r.stage_seconds[i].second, 2);
        s << ")";
    }
    s << "\n";
    s << "  verdict     " << report_verdict(r) << "\n";
    return s.str();
}

}  // namespace mirage
