// Bands for any stratified atmosphere (real air: soundings, temperature forms, the flattened
// profile of the curved Earth), from n(y) alone: equal-height layers, or layers placed where
// the index changes by equal steps.  Each layer holds the mean of n^2 over its heights, the
// half-space above the last boundary n^2 there.  No closed form of the exponential profiles is
// used: the designs of fit.h need those and are not for real air.
#pragma once

#include <vector>

#include "layers/stack.h"

namespace mirage {

class Atmosphere;  // atmosphere/exact_path.h


/// The stack with the given boundaries (strictly ascending, > 0): layer k holds the mean of
/// n^2 over (heights[k-1], heights[k]) (heights[-1] = 0), the top half-space n^2 at the last
/// boundary.  Its eta0 is n(0).
LayerStack air_layers(const Atmosphere& air, const std::vector<double>& heights);

/// The same, its camera's layer (the one holding eye_y) holding n^2 at eye_y instead of the
/// mean: a band ray keeps n cos(e) across every boundary, so with the eye's own index every
/// camera ray carries the exact path's invariant, and the directions it takes in every other
/// layer (where it turns, the sky it leaves for) are those the layers' indices give the exact
/// path (docs/atmospheres.md, "Bands for real air").
LayerStack air_layers_for_eye(const Atmosphere& air, const std::vector<double>& heights,
                              double eye_y);

/// The stack with the index of every layer but the camera's (and the top half-space) moved,
/// within the range n takes over the layer's heights, so that no camera ray skims it.  A band
/// ray from the eye at elevation e keeps n_eye cos(e); in a layer of ior c (over the camera's)
/// just above cos(e) it is nearly level, at sqrt(2 (c - cos e)), and runs the layer's
/// thickness h over that, along the layer and without limit as the two meet, where an exact
/// ray turning within those heights runs at most about 2 h sqrt(2 dn) / dn (dn the layer's
/// range of n over n_eye): a mirage's ground far off, the verge beside a van, drawn along whole
/// rows of the image.  The bound holds when c - cos(e) >= dn / 4, which each layer's ior is
/// moved to keep for every ray of `elevations` (rad, > 0 up: the pixel centres POV-Ray renders)
/// that enters it: the float ior nearest the layer's own that does, else the one that comes
/// closest.  `eye_y` is in the camera's layer, which holds n at the eye (air_layers_for_eye).
/// docs/atmospheres.md, "Rays that skim a layer".
LayerStack keep_layers_off_skimming_rays(const Atmosphere& air, const LayerStack& stack,
                                         double eye_y, const std::vector<double>& elevations);

/// The highest point of the exact path from height y0 at `elevation` (rad) over the
/// horizontal distance [0, scene_dz] (to the ground, if it meets it first), counted only as
/// far as the path is at or below `ceiling` afterwards: a path that rises above the ceiling
/// and stays above it to the end gives its highest point before that rise (at least y0).
/// Sampled at 64 points of the distance.
double air_peak_below(const Atmosphere& air, double y0, double elevation, double scene_dz,
                      double ceiling);

/// `count` equal layers from the ground to `top`.
std::vector<double> equal_height_boundaries(double top, int count);

/// Boundaries where n crosses the levels n_lo + k (n_hi - n_lo) / count, k = 1 .. count - 1,
/// n_lo and n_hi the extremes of n over [0, top]: every crossing of every level (a profile
/// that is not monotonic crosses a level more than once), boundaries closer than
/// `min_thickness` to the one below (or to the ground) left out.  Empty when n does not
/// change over [0, top].
std::vector<double> equal_index_boundaries(const Atmosphere& air, double top, int count,
                                           double min_thickness);

/// The same, with the levels below n_e, the index at the eye (`eye_y`), at equal steps of
/// sqrt(n_e - n) instead: as many steps from n_e down to the lowest n as equal index steps
/// take there (rounded up), those at and above n_e as equal_index_boundaries places them.  A
/// ray from the eye turns only where n < n_e, at elevation e where n_e - n = n_e e^2 / 2, so
/// below the eye these are equal steps of the elevation of the rays that turn at each
/// boundary.  Equal index steps are sqrt(2 dn) of elevation apart next to the eye's index,
/// several pixels, where the weak gradient at the eye makes them thick and the near-level rays
/// turn hundreds of metres out inside them (docs/atmospheres.md, "Rays that skim a layer").
std::vector<double> equal_turning_boundaries(const Atmosphere& air, double top, double eye_y,
                                             int count, double min_thickness);

}  // namespace mirage
