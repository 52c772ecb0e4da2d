// Where a ray leaves the whole atmosphere for the sky: on the curved Earth, for a model that
// describes the air to its top (AirSpec::upper_air, QuadraticProfile::sky_at_top), the
// direction past the model's top, so that a sun near the horizon is refracted all the way
// (docs/colour.md).
#pragma once

#include <optional>

#include "atmosphere/exact_path.h"

namespace mirage {

struct SkyExit {
    double elevation = 0.0;  // over the local horizontal where the ray leaves, in vacuum, rad
    double dz = 0.0;         // horizontal distance from the start to there (flattened frame)
};

/// The exit of an escaping path through a piecewise-quadratic model on the curved Earth that
/// looks the sky up at its top: its slope there (the flattening is conformal: the elevation
/// over the local horizontal), taken on into vacuum by one refraction at the top's sphere,
/// n_top cos e = cos e'.  Nothing for any other path or model: the sky is then seen where the
/// tracer stops following the ray.  The direction from the start's frame is
/// elevation - dz / R.
std::optional<SkyExit> sky_exit(const ExactPath& path);

}  // namespace mirage
