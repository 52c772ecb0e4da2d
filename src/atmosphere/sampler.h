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

#include <array>
#include <cstdint>
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
    // The distance at which end_slope is the path's own slope (path_sampler.h; 0 when not
    // set): on the curved Earth the local horizontal there is tilted by end_slope_dz / R from
    // the start's.
    double end_slope_dz = 0.0;
    bool turns = false;    // a turning point lies on the path (it was mirrored)
    double dz_turn = 0.0;  // where, when it turns
    // Per segment (points[k] to points[k + 1]), from sample_path_near: 0 for a segment within
    // the tolerance, else nothing the path can meet lies near that stretch (the chord is
    // coarse there and need not be tested against the scene) and this is the stretch's
    // length, estimated (the chord is shorter).  Empty: every segment is within the tolerance.
    std::vector<double> clear_length;
    // From sample_path_near: nothing the path can meet lies near its straight end either
    // (the march need not test it; its direction is all that counts, for the sky).
    bool end_clear = false;
};

/// Samples the exact ray to the tolerance.  At least one of tolerance_m and tolerance_rad
/// must be positive, and each either 0 or at least its minimum above.
SampledPath sample_path(const ExactRay& ray, const SampleSettings& settings);

/// Height of the sampled path at horizontal distance dz (linear between points, then its
/// straight end).
double polyline_height(const SampledPath& path, double dz);

/// The allowance at horizontal distance dz where the exact height is y.
double allowed_error(const ExactRay& ray, const SampleSettings& settings, double dz, double y);

/// A line of the ray's vertical plane through (dz, y) with the given slope.
struct PathLine {
    double dz = 0.0;
    double y = 0.0;
    double slope = 0.0;
    double at(double x) const { return y + slope * (x - dz); }
};

/// A region of the ray's vertical plane (horizontal distance dz from the start, height y):
/// the dz in [dz_lo, dz_hi] and the heights above both lower lines and below both upper
/// lines.  The sampler's regions hold a stretch of the exact path and everything within the
/// tolerance of it (its chord among them): a convex path lies below its chord and above its
/// end tangents, a concave one the other way round.
struct PathRegion {
    double dz_lo = 0.0, dz_hi = 0.0;
    std::array<PathLine, 2> lower{};
    std::array<PathLine, 2> upper{};
    int lower_count = 2;  // lines in use: 1 or 2
    int upper_count = 2;
};

/// A region prepared for many rectangle tests (the reciprocals of its slopes taken once).
class RegionTest {
  public:
    explicit RegionTest(const PathRegion& region);
    /// Whether the region meets the rectangle [dz_lo, dz_hi] x [y_lo, y_hi] (bounds may be
    /// infinite): the cut of an axis-aligned box by the ray's vertical plane.
    bool meets(double dz_lo, double dz_hi, double y_lo, double y_hi) const;
    const PathRegion& region() const { return region_; }

  private:
    PathRegion region_;
    std::array<double, 2> inv_lower_{}, inv_upper_{};  // 1 / slope (0 for a level line)
};

/// RegionTest(region).meets(dz_lo, dz_hi, y_lo, y_hi).
bool region_meets_rectangle(const PathRegion& region, double dz_lo, double dz_hi, double y_lo,
                            double y_hi);

/// What a path can meet, as seen in its vertical plane: the scene, for sample_path_near.
class PathObstacles {
  public:
    virtual ~PathObstacles() = default;
    /// Whether anything may lie in the region (false only when nothing does).
    virtual bool may_meet(const PathRegion& region) const = 0;
    /// Whether a surface covers the ground (y = 0): a path meets it at its ground point
    /// (nowhere else: its chords join points of the path, which lies above the ground).
    virtual bool ground() const = 0;
    /// A distance beyond which nothing the path can meet lies (+inf: not known).
    virtual double reach() const { return std::numeric_limits<double>::infinity(); }
};

/// Samples the exact ray to the tolerance wherever it may meet something, and coarsely where
/// nothing can lie near it.  Each monotone piece of the path (from the start to a turning
/// point ahead, then to the ground, the cut, or where the straight end keeps the tolerance)
/// is cut in halves on a grid of powers of two from the piece's start; a half is kept whole
/// once its chord is within the tolerance, or, with obstacles, once the region between its
/// chord and end tangents, widened by the allowance, meets nothing (marked in clear_length).
/// Without obstacles every segment keeps the tolerance, and with them the segments that do
/// are the same ones: the other segments hold nothing those would have met.  The straight
/// end begins where the path's asymptote keeps the tolerance, as in sample_path.
SampledPath sample_path_near(const ExactRay& ray, const SampleSettings& settings,
                             const PathObstacles* obstacles);

/// The same into `path`, whose storage is reused (for many rays in a row).
void sample_path_near(const ExactRay& ray, const SampleSettings& settings,
                      const PathObstacles* obstacles, SampledPath& path);

/// Where the straight end of an escaping path may begin, at or after `from`: a distance from
/// which the line with the asymptotic slope through the path keeps the tolerance (the
/// path's departure from its asymptote is within the allowance).  +inf for a path without
/// an asymptote.
double straight_end_start(const ExactRay& ray, const SampleSettings& settings, double from);

}  // namespace mirage
