// `mirage compile`: a .pov template becomes a POV-Ray scene with a banded refraction
// medium.  A short pipeline of named stages (compile/stages.h): settings (the scene, its
// atmosphere and extent), rays (every pixel centre and a grid of sub-pixel samples), design
// (layers fitted to the camera's rays, within POV-Ray's trace-level budget), emit (the
// layers include, the .ini, the layer table), check (what every pixel and sample shows,
// against the exact paths, with an independent band tracer) and report.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "atmosphere/profile.h"
#include "load/atmosphere_settings.h"
#include "pov/emit_layers.h"
#include "util/result.h"
#include "util/scene_input.h"

namespace mirage {

/// How POV-Ray's camera rays leave the eye: each aimed through the bands to where its exact
/// ray ends (a mesh camera, the default), or as the scene's camera has them.
enum class CameraModel { Corrected, Perspective };

/// The scene (SceneInput) is the template, its size the render's.
struct CompileOptions : SceneInput {
    std::string out_dir;  // where the include, .ini and CSV go
    std::string image;    // the image the .ini renders to (default: out_dir/<scene>.png)
    std::optional<double> tolerance_px;  // overrides Mirage_Tolerance
    std::optional<LayerMode> layers;     // overrides Mirage_Layers
    std::optional<int> layer_count;      // overrides Mirage_Layer_Count
    bool antialias = false;
    std::optional<LayerLayout> layout;  // unset: by the index contrast ("auto")
    int fit_columns = 1;                // image columns the layers are fitted to
    // Also write the pixels' errors here (.exr; R the seen error in pixels, G the shift in
    // rows, B the reflections' error in pixels).
    std::string error_map;
    std::optional<Profile> profile;  // replaces the scene's atmosphere (what-if runs, tests)
    std::string profile_label;       // names the replacement in the report
    int samples_per_side = 3;        // the check's sub-pixel samples: a grid of this many per
                                     // side in every pixel (1: pixel centres only)
    bool progress = true;            // a progress bar on stderr, shown only on a terminal
    CameraModel camera = CameraModel::Corrected;
    // POV-Ray's +K and Declare=: the still's clock and the numbers declared before the scene
    // is parsed, for the compile's parse and in the .ini, so that POV-Ray renders that frame.
    std::optional<double> clock;
    std::map<std::string, double> declares;
};

/// An image row or column and the worst errors of its pixels and samples.
struct LineError {
    int index = 0;
    double max_seen_error_px = 0.0;  // over the line's pixel centres and samples
    int samples_over = 0;            // samples (centres included) over the tolerance
};

/// A camera row whose worst pixel exceeds the tolerance.
struct RowExcess {
    int row = 0;
    double max_error_px = 0.0;
    int pixels_over = 0;
};

struct CompileReport {
    std::string scene, name;
    int width = 0, height = 0;
    std::string atmosphere;  // what the scene declares
    std::string mode;        // "adaptive", "uniform" or "none"
    std::string layout;      // "nested" or "gaps"
    double gap = 0.0;        // gap thickness of the gap layout
    double tolerance_px = 0.0;
    int layers = 0;  // boundaries emitted
    int below_camera = 0, above_camera = 0;
    double p50_error_px = 0.0, p95_error_px = 0.0, p99_error_px = 0.0, max_error_px = 0.0;
    double max_error_px_fitted = 0.0;  // over the column the design was fitted to
    // What the pixels show (compile/pixel_check.h), row-major from the top row, not in the
    // JSON: the angle between the band ray's end and the exact ray's seen from the eye,
    // reflections included, pixels (+inf for a ray cut off); the rows to the nearest pixel
    // of the column where the exact image shows the same (+inf: none does); the reflections'
    // part of the angle.  The errors above are the design's, at the scene's edge.
    std::vector<float> pixel_error_px, pixel_shift_rows, pixel_reflection_error_px;
    double p95_seen_error_px = 0.0, max_seen_error_px = 0.0;
    double p95_shift_rows = 0.0, max_shift_rows = 0.0;  // over the pixels shown somewhere
    int pixels_not_shown = 0;  // pixels showing what no row of their column shows
    // The same over every sub-pixel sample (samples_per_side^2 per pixel, centres included):
    // what an antialiased render, or any ray between pixel centres, meets.
    int samples_per_side = 1;
    double p95_seen_error_px_samples = 0.0, max_seen_error_px_samples = 0.0;
    double p95_shift_rows_samples = 0.0, max_shift_rows_samples = 0.0;
    int samples_not_shown = 0;
    // The camera rays' part of the seen error, without their reflections (with a corrected
    // camera): pixel centres, and every sample.
    double p95_camera_error_px = 0.0, max_camera_error_px = 0.0;
    double p95_camera_error_px_samples = 0.0, max_camera_error_px_samples = 0.0;
    std::vector<LineError> worst_rows, worst_columns;  // by seen error, worst first (5 each)
    std::vector<std::pair<std::string, double>> stage_seconds;  // the pipeline's stages
    int pixels = 0, pixels_over = 0;
    int max_crossings = 0;    // boundary events of a camera ray in the layers
    int max_trace_level = 0;  // with its reflections, as POV-Ray counts levels
    bool within_tolerance = false;
    std::vector<RowExcess> rows_over;
    std::vector<std::string> left_out;  // what the design leaves out, and why
    std::vector<std::string> warnings;
    double extent = 0.0;                 // horizontal reach of the scene from the camera
    double layers_extent = 0.0;          // horizontal reach of the layers
    double lowest = 0.0, highest = 0.0;  // of the boundaries
    double seconds = 0.0;
    std::string include_path, ini_path, csv_path, image_path, report_path;
    std::string error_map_path;  // --error-map, where the options put it (empty: none)
    // The corrected camera (CameraModel::Corrected): "corrected" or "perspective", the
    // samples per pixel POV-Ray shoots through it, its include and the scene that renders
    // the template through it (empty for a perspective camera).
    std::string camera = "perspective";
    int camera_samples = 0;
    std::string camera_path, render_scene_path;
};

/// The most faces a corrected camera's meshes may have in all: about 215 bytes of POV-Ray's
/// memory and 60 bytes of text each (docs/band_designs.md), so 2 GiB of memory.
inline constexpr double kMaxMeshCameraFaces = 1e7;

/// Compiles the scene; on success every output was written (atomically), on failure none
/// was changed and the message names the place at fault.
Result<CompileReport> compile_scene(const CompileOptions& options);

/// The report as JSON (keys layers, max_error_px, p95_error_px, max_crossings, seconds and
/// the rest) and as text for people.
std::string report_json(const CompileReport& report);
std::string report_text(const CompileReport& report);
/// One line: within the tolerance, or missed, with the share of pixels over it and the
/// worst rows.
std::string report_verdict(const CompileReport& report);

}  // namespace mirage
