// What the exact path does with a camera ray, and the error of a model against it in the
// common unit: the angle seen from the eye divided by the angular size of a pixel.
#pragma once

#include "atmosphere/profile.h"
#include "layers/stack.h"

namespace mirage {

class Atmosphere;  // atmosphere/exact_path.h

/// The exact path's outcome, in the terms of trace_band: the ground hit if it lies before
/// scene_dz, else the height and slope at scene_dz; whether it then goes to the sky (never
/// meets the ground) and its final (asymptotic) slope.
BandOutcome exact_outcome(const Profile& profile, double y0, double elevation, double scene_dz);
/// The same in any atmosphere (the one implementation), by its exact path
/// (atmosphere/exact_path.h); a ray trapped in a
/// duct never reaches the sky, and its final slope is its slope at scene_dz.  On the curved
/// Earth the final slope is the slope at scene_dz turned from the local horizontal there to
/// the eye's (by scene_dz / R), the direction the tracer looks the sky up with.
BandOutcome exact_outcome(const Atmosphere& air, double y0, double elevation, double scene_dz);

/// Angle (rad) between where a model's ray ends and where the exact ray ends, seen from the
/// eye at height y0: the angle between the eye's lines of sight to the two end points in the
/// scene, and for rays that leave the scene towards the sky also the angle between their
/// final directions; the larger.
double outcome_error_rad(double y0, const BandOutcome& exact, const BandOutcome& model);

}  // namespace mirage
