// What the scene language asks of an object while it is parsed: trace(), inside(),
// min_extent() and max_extent(), answered with the tracer's own intersection code, as POV-Ray
// answers them with its own.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "scene/object_queries.h"
#include "scene/object_tree.h"
#include "shapes/bounds.h"
#include "util/result.h"

namespace mirage {

/// POV-Ray's trace(): the closest hit of the ray origin + t normalize(direction), t >= 1e-4.
Result<std::optional<ObjectTraceHit>> trace_object(const ObjectNode& object,
                                                   const glm::dvec3& origin,
                                                   const glm::dvec3& direction);

/// POV-Ray's inside(): whether the point is inside the object (its clipping objects too).
Result<bool> point_inside_object(const ObjectNode& object, const glm::dvec3& point);

/// min_extent() and max_extent(): the object's bounding box (empty when it has no surface).
Result<Aabb> object_extent(const ObjectNode& object);

/// The three above, for the parser (ParseOptions::object_queries).
ObjectQueries tracer_object_queries();

}  // namespace mirage
