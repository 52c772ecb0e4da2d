// The extent of a scene's objects, for the atmosphere's reach: the finite objects' bounds and
// what the lenient parser could not represent (unknown objects), bounded by their bounded_by
// or clipped_by objects or taken as unbounded, with a note for the report on each.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shapes/bounds.h"
#include "trace/scene_accel.h"

namespace mirage {

struct SceneExtent {
    Aabb finite;                         // the finite objects and the bounded unknown objects
    std::vector<std::string> bounded;    // unknown objects bounded by their bounded_by/clipped_by
    std::vector<std::string> unbounded;  // unknown objects without an extent (taken as unbounded)
    std::optional<FileLoc> first_unbounded;  // where the first of those is
    std::string first_unbounded_what;
};

/// The extent of the scene prepared in `accel` (built from `scene`).
SceneExtent scene_extent(const Scene& scene, const SceneAccel& accel);

}  // namespace mirage
