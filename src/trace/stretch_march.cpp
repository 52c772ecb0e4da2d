#include "trace/stretch_march.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mirage {

namespace {

double largest_coordinate(const glm::dvec3& p) {
    return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

// How far a query along a segment with these ends may reach beyond it: each query reaches
// PolylineMarch::kJointTolerance (1 + the joint's largest coordinate) before and after its
// segment; four times that covers it and the rounding of the distances below.
double slack(double largest) { return 4.0 * PolylineMarch::kJointTolerance * (1.0 + largest); }

// The square of the distance of p from the segment a + t ab, t in [0, 1] (ab2 = |ab|^2).
double distance2_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& ab,
                            double ab2) {
    const glm::dvec3 ap = p - a;
    const double t = ab2 > 0.0 ? std::clamp(glm::dot(ap, ab) / ab2, 0.0, 1.0) : 0.0;
    const glm::dvec3 e = ap - t * ab;
    return glm::dot(e, e);
}

// Whether no query along the polyline from `from` through `points` can meet a finite object.
bool clear_of_boxes(const SceneAccel& accel, const glm::dvec3& from,
                    std::span<const glm::dvec3> points) {
    const glm::dvec3& to = points.back();
    const glm::dvec3 chord = to - from;
    const double chord2 = glm::dot(chord, chord);
    double reach2 = 0.0, largest = std::max(largest_coordinate(from), largest_coordinate(to));
    for (const glm::dvec3& p : points.first(points.size() - 1)) {
        reach2 = std::max(reach2, distance2_to_segment(p, from, chord, chord2));
        largest = std::max(largest, largest_coordinate(p));
    }
    return !accel.segment_may_meet(from, to, std::sqrt(reach2) + slack(largest));
}

// The stretch from the march's point through `points`, none of whose queries can meet the
// ground: moved along untested where it is clear of the boxes, else in halves, down to single
// segments, which are queried.
bool march_above_ground(PolylineMarch& march, const SceneAccel& accel,
                        std::span<const glm::dvec3> points) {
    if (points.empty()) return false;
    if (points.size() == 1) return march.segment_to(points[0]);
    if (clear_of_boxes(accel, march.point(), points)) {
        for (const glm::dvec3& p : points) {
            const double length = glm::length(p - march.point());
            if (length > 0.0) march.skip_to(p, length);  // as segment_to, which skips a zero
        }
        return false;
    }
    const std::size_t half = points.size() / 2;
    return march_above_ground(march, accel, points.first(half)) ||
           march_above_ground(march, accel, points.subspan(half));
}

}  // namespace

bool march_stretch(PolylineMarch& march, const SceneAccel& accel,
                   std::span<const glm::dvec3> points) {
    std::size_t above = points.size();
    if (accel.unbounded_elsewhere()) {
        above = 0;  // a plane elsewhere may be met anywhere: every segment queried
    } else if (accel.has_ground_plane()) {
        // Only a segment that reaches the ground (within the slack) can meet a ground plane:
        // the stretch before the first one is marched above it.
        glm::dvec3 from = march.point();
        for (above = 0; above < points.size(); ++above) {
            const glm::dvec3& to = points[above];
            const double s = slack(std::max(largest_coordinate(from), largest_coordinate(to)));
            if (std::min(from.y, to.y) <= s) break;
            from = to;
        }
    }
    if (march_above_ground(march, accel, points.first(above))) return true;
    for (const glm::dvec3& p : points.subspan(above))
        if (march.segment_to(p)) return true;
    return false;
}

}  // namespace mirage
