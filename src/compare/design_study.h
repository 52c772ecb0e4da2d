// `mirage study`: the band designs compared on the same work, for one scene at one size.
//
// Every camera ray stays in the vertical plane through the eye that contains it, so for any
// medium symmetric about the eye's vertical axis the continuum of the camera's rays (every
// column, every sub-pixel sample, any tilt) is one interval of elevations.  The study samples
// that interval densely and measures, for each candidate geometry, each ray's error wherever
// it may meet an object: the angle seen from the eye between the band path and the exact path
// at every distance of the scene's objects (and the ground), and for rays that leave towards
// the sky the difference of their final directions; in pixels.  It counts each ray's boundary
// crossings (POV-Ray's trace levels, and its cost).  Candidates made of planes are also
// compiled, checked pixel by pixel (centres and sub-pixel samples, reflections included) and
// rendered by POV-Ray for their time.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "util/result.h"
#include "util/scene_input.h"

namespace mirage {

/// The most levels a graded design's grading may add (--graded-steps), and the most levels a
/// graded design may have in all: its levels are laid over the index range the grading widens.
constexpr double kMaxGradedSteps = 4096.0;
constexpr std::size_t kMaxGradedLevels = 16384;

struct StudyOptions : SceneInput {
    StudyOptions() {
        width = 640;
        height = 480;
    }
    std::string out_dir;                                  // default build/study/<scene name>
    std::vector<int> uniform_counts = {16, 32, 64, 128};  // Berger's equal layers
    // Graded layers (layers/graded.h): levels per index range, and the grading as the number
    // of levels a level ray gains from it before h levels off.
    std::vector<int> graded_levels = {64, 128};
    std::vector<double> graded_steps = {0.0, 8.0, 32.0};
    int rays_per_row = 8;  // the continuum: elevations per pixel row of the centre column
    bool render = true;    // render the plane designs with POV-Ray for their time
    std::string povray = "povray", gnuplot = "gnuplot";
    std::function<void(const std::string&)> progress;  // a line per candidate (may be empty)
};

struct StudyRow {
    std::string design;    // e.g. "uniform 64", "fit (centre column)", "graded 128, 8 steps"
    std::string geometry;  // "planes" or "revolution"
    int boundaries = 0;
    double mean_crossings = 0.0;
    int max_crossings = 0;
    double p50_px = 0.0, p95_px = 0.0, max_px = 0.0;  // over the continuum (2D)
    double share_over_px = 0.0;                       // share of the continuum over 1 px
    // Planes only (-1 otherwise): compile's pixel check and POV-Ray.
    double seen_p95_px = -1.0, seen_max_px = -1.0;                  // pixel centres
    double seen_p95_px_samples = -1.0, seen_max_px_samples = -1.0;  // 3x3 samples
    double compile_seconds = -1.0, povray_seconds = -1.0, povray_trace_seconds = -1.0;
    int max_trace_level = -1;
    std::string curve;  // the error against elevation, a file beside the results
};

struct StudyResult {
    std::string scene, name, out_dir;
    int width = 0, height = 0;
    double zone_lo = 0.0, zone_hi = 0.0;  // the distances checked, scene units
    double elevation_lo = 0.0, elevation_hi = 0.0;
    int rays = 0;                        // of the continuum
    double plain_povray_seconds = -1.0;  // POV-Ray on the template without an atmosphere
    std::vector<StudyRow> rows;
    std::vector<std::string> notes;
    std::string csv_path, summary_path, plot_elevation, plot_crossings;
    bool plotted = false;
};

/// Checks the options' values before any work: every count and level count a whole number from
/// 1 to kMaxLayerCount, every grading from 0 to kMaxGradedSteps.
Status validate_study_options(const StudyOptions& options);

/// Runs the study and writes study.csv, summary.md, the curves and their plots.
Result<StudyResult> run_design_study(const StudyOptions& options);

}  // namespace mirage
