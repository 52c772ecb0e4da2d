// The transfer curve of mirage studies (Young's "transfer curve"): for points at one distance,
// the apparent elevation at which the eye sees each of them against its true (geometric)
// elevation, with the profile of the air beside it.  Where the curve folds, one point is seen
// at several elevations: the multiple images of a superior mirage or a Fata Morgana.  Drawn by
// gnuplot as SVG and PNG.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "atmosphere/exact_path.h"
#include "util/output_set.h"
#include "util/result.h"

namespace mirage {

struct TransferSettings {
    Atmosphere atmosphere;
    double eye_height = 1.5;   // m above the ground (the sphere with an Earth radius)
    double distance = 1000.0;  // m, of the target points (along the ground)
    double from_deg = -0.25;   // apparent elevations traced, degrees
    double to_deg = 0.25;
    int count = 2001;  // rays traced
};

struct TransferPoint {
    double apparent_rad = 0.0;  // the ray's elevation at the eye
    double true_rad = 0.0;      // geometric elevation of the point it reaches at the distance
    double height_m = 0.0;      // that point's height above the ground
    bool reached = false;       // false: the ray meets the ground before the distance
};

struct TransferCurve {
    std::vector<TransferPoint> points;  // by apparent elevation
    int max_images = 0;                 // most apparent elevations seeing one point
    double max_images_height_m = 0.0;   // a target height seen that many times
};

/// Traces the settings' rays.  Fails on bad settings (the message names the value).
Result<TransferCurve> transfer_curve(const TransferSettings& settings);

/// The geometric elevation, seen from an eye at height h0, of a point at height h and distance
/// d along the ground (on a sphere of radius R; R = 0: flat).
double true_elevation(double h0, double h, double d, double earth_radius);

/// What the profile panel shows, over heights above the ground.
struct ProfilePanel {
    std::function<double(double)> temperature_k;   // empty: not known (the index is drawn)
    std::function<double(double)> refractivity;    // n - 1
    std::vector<std::pair<double, double>> ducts;  // height ranges to shade, m
    std::string label;                             // the profile's description
};

/// The gnuplot script drawing the profile and the transfer curve to `svg_out` and/or `png_out`
/// (either may be empty).
std::string transfer_gnuplot_script(const TransferSettings& settings, const TransferCurve& curve,
                                    const ProfilePanel& panel, const std::string& svg_out,
                                    const std::string& png_out);

/// Draws the diagram with gnuplot (found on PATH) to the given files (either may be empty),
/// staged in `outputs`: gnuplot writes their temporary names, and the caller's commit() puts
/// them in place with its other outputs.  Nothing is staged when gnuplot fails.
Status draw_transfer_diagram(const TransferSettings& settings, const TransferCurve& curve,
                             const ProfilePanel& panel, OutputSet& outputs,
                             const std::string& svg_path, const std::string& png_path,
                             const std::string& gnuplot = "gnuplot");

}  // namespace mirage
