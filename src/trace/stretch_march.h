// A stretch of a ray's path given as a polyline (a sampled segment of the path bent at each of
// the turbulent air's screens it crosses, docs/turbulence.md) marched through the scene with
// one test for the whole stretch where it passes far from everything.
#pragma once

#include <glm/vec3.hpp>
#include <span>

#include "trace/propagator.h"
#include "trace/scene_accel.h"

namespace mirage {

/// Marches on from the march's point through `points` in order, one straight segment to each,
/// as PolylineMarch::segment_to does, and returns true on a hit (the march is then done).  The
/// segments are queried only where they can meet something: a polyline lies within the largest
/// distance of its vertices from the chord that joins its ends (the distance to a segment is a
/// convex function), so when no finite object's box grown by that distance and the joints'
/// overlap meets the chord, the polyline stays above a ground plane and the scene has no other
/// unbounded object, no segment's query can return a hit, and the stretch is moved along
/// untested (skip_to, with each segment's length as segment_to would add it).  Otherwise it is
/// cut in two at its middle vertex and each half tried the same way, down to single segments,
/// which are queried.  The march ends as querying every segment would leave it; only its count
/// of queries differs.
bool march_stretch(PolylineMarch& march, const SceneAccel& accel,
                   std::span<const glm::dvec3> points);

}  // namespace mirage
