// The paper's sampled ray path (Khote & Howard, section 4): the exact path is sampled
// adaptively where its slope changes, reflected about its turning point, continued by a
// straight line beyond the bend, and cut where the ray meets the ground or leaves the
// atmosphere's extent.
//
// Tolerance: at every horizontal distance dz the polyline's height differs from the exact
// path's by at most  tolerance_m + tolerance_rad * (start_distance + |exact point - start|),
// i.e. a fixed allowance plus an angle seen from the observer (the eye, start_distance
// behind the start along the ray's history).  This is guaranteed by bounding the chord
// error of each segment with max|y''| (Delta dz)^2 / 8, and y'' depends on the height only.
#pragma once

#include <glm/vec2.hpp>
#include <limits>
#include <vector>

#include "atmosphere/exact_ray.h"

namespace mirage {

/// The finest tolerances a path is sampled to.  Samples grow as tolerance^-1/2: at 1e-10 rad
/// a ray of the paper's profile takes about 48 000 of them; far below, the chords shrink to
/// the rounding of their heights and the count has no bound.
constexpr double kMinToleranceRad = 1e-10;
constexpr double kMinToleranceM = 1e-9;

struct SampleSettings {
    double tolerance_m = 0.0;     // fixed allowance on the height error, m
    double tolerance_rad = 0.0;   // allowance as an angle seen from the observer, rad
    double start_distance = 0.0;  // path length from the observer to the ray's start, m
    double max_dz = std::numeric_limits<double>::infinity();  // end of the atmosphere, m
};

/// How the sampled path ends after its last point.
enum class PathEnd {
    Ground,    // the last point is on the ground (y = 0)
    Straight,  // beyond the last point the path is a straight line of slope end_slope
    Cut,       // the atmosphere ends at the last point; straight beyond, slope end_slope
};

/// A sampled path in the ray's vertical plane: points (dz, y), the first is the start.
struct SampledPath {
    std::vector<glm::dvec2> points;
    PathEnd end = PathEnd::Straight;
    double end_slope = 0.0;  // dy/dz after the last point (Straight and Cut)
    bool turns = false;      // a turning point lies on the path (it was mirrored)
    double dz_turn = 0.0;    // where, when it turns
};

/// Samples the exact ray to the tolerance.  At least one of tolerance_m and tolerance_rad
/// must be positive, and each either 0 or at least its minimum above.
SampledPath sample_path(const ExactRay& ray, const SampleSettings& settings);

/// Height of the sampled path at horizontal distance dz (linear between points, then its
/// straight end).
double polyline_height(const SampledPath& path, double dz);

/// The allowance at horizontal distance dz where the exact height is y.
double allowed_error(const ExactRay& ray, const SampleSettings& settings, double dz, double y);

}  // namespace mirage
