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

/// Whether n changes with height anywhere.
bool air_has_gradient(const Atmosphere& air);

/// The radius of the Earth the air is flattened for (0: flat ground).
double air_earth_radius(const Atmosphere& air);

/// The height above which n no longer changes (the fitted model's top; +inf for the
/// exponential profiles).
double air_constant_above(const Atmosphere& air);

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

}  // namespace mirage
