// POV-Ray 3.7's fog (render/trace.cpp ComputeFog, ComputeConstantFogColour,
// ComputeGroundFogColour): constant fog and ground fog, with turbulence, blending the colour
// seen along a ray of a given length with the fogs' colours.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace mirage {

/// Applies the scene's fogs to `colour`, seen along the straight ray from `origin` in unit
/// direction `direction` over `depth` (the hit distance, or POV-Ray's BOUND_HUGE for a ray
/// that escapes).  `generator` is the scene's noise generator (fog turbulence).
glm::dvec3 apply_fog(const std::vector<Fog>& fogs, const glm::dvec3& origin,
                     const glm::dvec3& direction, double depth, const glm::dvec3& colour,
                     int generator);

/// The fogs' attenuation of the light along a shadow ray (POV-Ray's ComputeFog for shadow
/// test rays: no fog colour is added).
glm::dvec3 fog_attenuation(const std::vector<Fog>& fogs, const glm::dvec3& origin,
                           const glm::dvec3& direction, double depth, int generator);

}  // namespace mirage
