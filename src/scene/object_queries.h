// What the scene language asks of an object while it is parsed: trace(), inside(),
// min_extent() and max_extent().  POV-Ray answers them with its own intersection code; mirage
// answers them with its tracer's (trace/object_query.h: tracer_object_queries()), which the
// commands hand to the parser through ParseOptions.  The scene module stands below the
// tracer, so it names the questions here and leaves the answers to the tracer.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <utility>

#include "scene/object_tree.h"
#include "util/result.h"

namespace mirage {

struct ObjectTraceHit {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};  // unit, outward (flipped for inverse), as POV-Ray's trace() gives
};

struct ObjectQueries {
    /// POV-Ray's trace(): the closest hit of the ray origin + t normalize(direction), t >= 1e-4.
    std::function<Result<std::optional<ObjectTraceHit>>(
        const ObjectNode& object, const glm::dvec3& origin, const glm::dvec3& direction)>
        trace;
    /// POV-Ray's inside(): whether the point is inside the object (its clipping objects too).
    std::function<Result<bool>(const ObjectNode& object, const glm::dvec3& point)> inside;
    /// min_extent() and max_extent(): the object's bounding box, lowest and highest corner;
    /// nullopt when it has no surface.
    std::function<Result<std::optional<std::pair<glm::dvec3, glm::dvec3>>>(
        const ObjectNode& object)>
        extent;
};

}  // namespace mirage
