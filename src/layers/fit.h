// Fitting a stack of horizontal layers to a set of camera rays.
//
// The rays that bend back (inferior: downward rays that turn above the ground; superior:
// upward rays that reach an apex) are fitted by a sequential fit from the eye outward: each
// new layer's index is placed in the gap between two consecutive rays' invariants and its
// thickness chosen so that the largest possible run of the remaining rays, reflected on its
// far boundary, ends within the tolerance of the exact path.  Since a layer's far boundary
// is fixed only after everything nearer the eye, each layer compensates the errors of the
// ones before it and nothing accumulates.  The other side of the eye (the one-way side: the
// sky above a hot ground, the ground below cold air) gets layers spaced geometrically in
// eta^2, each index set so that the most grazing ray crosses it in the exact horizontal
// distance.  Three rules fix the rest: the eye's layer has eta(y0), the half-space beyond the
// last boundary on the sky side has eta(infinity), and the layer on the ground has eta0
// (inferior), so every sky direction and the mirage/ground cut are exact.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "atmosphere/profile.h"
#include "layers/stack.h"

namespace mirage {

/// A camera ray as the layer design sees it: a horizontal stack acts on its elevation only.
struct DesignRay {
    double elevation = 0.0;  // rad, > 0 up
    double exit_dz = 0.0;    // horizontal distance at which it leaves the atmosphere, m
    double pixel_rad = 0.0;  // angular size of a pixel at this ray, rad
    int col = 0, row = 0;    // pixel, for reports
};

struct LayerFitSettings {
    double tolerance_px = 0.5;    // largest allowed error of a fitted ray, pixels
    int max_crossings = 255;      // trace-level budget of a camera ray
    double flat_fraction = 1e-2;  // one-way layers stop where eta^2 is within this of its limit
    double layers_extent_factor = 1000.0;  // layers reach this many times the scene's extent
    double oneway_margin = 0.97;  // share of the tolerance one-way rays may use per boundary
    double min_thickness = 0.0;   // thinnest layer (and lowest floor above the ground), m
    bool pov_float_grid = true;   // indices only where POV-Ray's float iors can hold them
    double gap_lo = 0.1;          // a new index lies at least this fraction into its gap
    double gap_hi = 0.9;          // and at most this fraction
};

/// How well a stack serves a set of rays (measured with the band trace against the exact
/// paths).
struct FitQuality {
    double max_error_px = 0.0;
    int max_crossings = 0;
};

/// A fitted design and what it left out.
struct FitResult {
    FitQuality quality;  // over the rays it was fitted to
    LayerStack stack;
    int turning_boundaries = 0;          // boundaries on the turning side
    int oneway_boundaries = 0;           // boundaries on the one-way side
    std::vector<double> turning_excess;  // indices of the turning side's layers, outward
    int violations = 0;                  // layers where no ray could be brought within tolerance
    std::vector<std::string> notes;      // what was left out, and why
};

/// The sequential design for the rays (typically one column of the image), eye at y0: every
/// ray within the tolerance when the budget allows, else the most accurate design within the
/// budget (FitResult::quality says which).
/// `fixed_excess`, when given, imposes the indices of the turning side's layers (outward
/// from the eye) and fits only their thicknesses.
FitResult fit_layers(const Profile& profile, double y0, const std::vector<DesignRay>& rays,
                     const LayerFitSettings& settings,
                     const std::vector<double>* fixed_excess = nullptr);

/// The largest error and crossing count of `stack` over `rays`; the layers reach
/// layers_factor times each ray's exit distance.
FitQuality measure_fit(const LayerStack& stack, double y0, const std::vector<DesignRay>& rays,
                       double layers_factor);

/// Berger, Trout & Levit's mirage box: `count` equal layers from the ground to `top`, each
/// with the index at its mid-height, the half-space above with eta(top).
LayerStack uniform_layers(const Profile& profile, double y0, int count, double top);

}  // namespace mirage
