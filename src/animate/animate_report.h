// The report of `mirage animate`: per frame and marked object the mirrored image's angular
// size against the eye's distance (vanishing.csv, and gnuplot's vanishing.png and .svg), the
// frames' times (summary.md, report.json).
#pragma once

#include <string>
#include <vector>

#include "animate/marked.h"
#include "util/result.h"

namespace mirage {

/// One marked sphere in one frame.
struct VanishingRow {
    int frame = 0;
    double clock = 0.0;
    MarkedView view;
};

struct AnimationSummary {
    std::string name, scene, model, runner, machine, frame_command, out_dir;
    std::string gnuplot = "gnuplot";
    int width = 0, height = 0, threads = 1;
    double frames_seconds = 0.0, assemble_seconds = 0.0;
    struct Frame {
        int number = 0;
        double clock = 0.0, seconds = 0.0;
        bool rendered_now = false;
    };
    std::vector<Frame> frames;
};

struct ReportFiles {
    std::string csv, script, png, svg, summary, json;  // png and svg empty when not drawn
    std::vector<std::string> notes;
};

/// Writes vanishing.csv, vanishing.gp (and with gnuplot on PATH vanishing.png/.svg),
/// summary.md and report.json into summary.out_dir, each through a temporary name.
Result<ReportFiles> write_animation_report(const AnimationSummary& summary,
                                           const std::vector<VanishingRow>& rows);

}  // namespace mirage
