// POV-Ray 3.7's warp chain (pattern/warps.cpp): the point at which a pattern is evaluated,
// taken through its transforms and warps (turbulence, repeat, black_hole, cylindrical,
// spherical, toroidal, planar) and its classic turbulence, and a surface normal taken
// through the chain's transforms and back.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace mirage {

/// POV-Ray's Warp_EPoint: `point` through the pattern's warp chain, first entry first.
/// The classic turbulence is skipped for the patterns that apply it themselves (marble,
/// wood).  Coordinates are clipped to +-1e17 as POV-Ray clips them.
glm::dvec3 warp_point(const Pattern& pattern, const glm::dvec3& point);

/// POV-Ray's Warp_Normal: a normal into the pattern's space through the chain's transforms
/// (normalised before and after unless `dont_scale_bumps`).
glm::dvec3 warp_normal(const Pattern& pattern, const glm::dvec3& normal, bool dont_scale_bumps);

/// POV-Ray's UnWarp_Normal: back from the pattern's space, last transform first.
glm::dvec3 unwarp_normal(const Pattern& pattern, const glm::dvec3& normal, bool dont_scale_bumps);

/// Whether a pattern type applies its classic turbulence itself (marble, wood; the warp
/// chain skips it for them).
bool pattern_applies_own_turbulence(PatternKind kind);

}  // namespace mirage
