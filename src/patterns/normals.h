// POV-Ray 3.7's normal perturbation (texture/normal.cpp Perturb_Normal): the dedicated
// normals of bumps, dents, ripples, waves, wrinkles and quilted, bump maps, normal maps and
// averages, and for every other pattern the finite difference of its values at the four
// corners of a tetrahedron `accuracy` across, scaled by the bump size (and shaped by a
// slope map).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "patterns/patterns.h"

namespace mirage {

/// Perturbs `normal` (unit, facing the ray) by the normal pattern at `point` (the point in
/// the normal's outer space: the world point for an object's normal).  The result is of
/// unit length unless the normal has no_bump_scale.
void perturb_normal(glm::dvec3& normal, const Normal& pattern, const glm::dvec3& point,
                    const PatternContext& ctx);

}  // namespace mirage
