// How a ray travels through the scene: the interface that lets rays bend.  The tracer never
// assumes a straight ray except through StraightPropagator; a curved propagator follows a
// polyline, one straight segment at a time, with SceneAccel::closest_hit (PolylineMarch
// does the bookkeeping of the joints).
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "trace/scene_accel.h"

namespace mirage {

/// POV-Ray's MIN_ISECT_DEPTH (configbackend.h): every ray ignores surfaces closer than this
/// to its origin, which keeps reflected rays off the surface they leave.
inline constexpr double kMinIsectDepth = 1.0e-4;

/// Where a ray starts and what it has behind it.
struct RayStart {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};  // unit, the direction of travel at the origin
    double travelled = 0.0;  // path length from the eye to the origin: 0 for a camera ray, the
                             // camera ray's path (and earlier bounces') for a reflected ray
    // Camera rays: the image position the ray goes through, in pixels from the top-left
    // corner (a pixel's centre is (col + 0.5, row + 0.5)); empty for other rays.
    std::optional<glm::dvec2> image_position = std::nullopt;
};

/// The end of a ray's path.
struct PathHit {
    bool hit = false;
    SurfaceHit surface;         // valid when hit; surface.t is along the last segment
    glm::dvec3 direction{0.0};  // unit direction of travel at the hit point, or the final
                                // direction when the ray escapes (sky lookup)
    double length = 0.0;        // path length from the start to the hit (when hit)
    int segments = 0;           // straight segments followed (statistics)
    int queries = 0;            // of them, those tested against the scene (statistics)
};

/// Follows a ray from `start.origin` along unit `start.direction` through the scene, possibly
/// bending, to the first surface it meets or out of the scene.  Implementations must be
/// thread-safe (propagate is called concurrently) and ignore surfaces within kMinIsectDepth
/// of the origin along the path, as POV-Ray does.
class Propagator {
  public:
    virtual ~Propagator() = default;
    virtual PathHit propagate(const SceneAccel& accel, const RayStart& start) const = 0;
};

/// Straight rays: one segment to infinity (POV-Ray's BOUND_HUGE).
class StraightPropagator final : public Propagator {
  public:
    PathHit propagate(const SceneAccel& accel, const RayStart& start) const override;
};

/// Marches a path along a polyline, one straight segment at a time, stopping at the first
/// surface.  Joints are robust: each segment's query reaches a little (kJointTolerance
/// relative to the coordinates) past its end and starts as far before its start, and the
/// march stops at the first hit, so a surface through a joint is found exactly once and
/// never lost between two segments.  The first kMinIsectDepth of path length is ignored,
/// as for straight rays.
///
///     PolylineMarch march(accel, eye);
///     for (const auto& vertex : path_vertices)
///         if (march.segment_to(vertex)) break;
///     if (!march.done()) march.ray(final_direction);
///     PathHit result = march.result();
class PolylineMarch {
  public:
    /// Joint overlap, relative to 1 + the largest coordinate of the joint.
    static constexpr double kJointTolerance = 1.0e-9;

    PolylineMarch(const SceneAccel& accel, const glm::dvec3& origin,
                  double min_depth = kMinIsectDepth);

    /// Follows the straight segment from the current point to `to`.  Returns true when it
    /// meets a surface: the march is then done and `result()` holds the hit.  A segment of
    /// zero length is skipped.  Must not be called once done.
    bool segment_to(const glm::dvec3& to);

    /// Moves to `to` along a stretch of path known to meet nothing, without testing it
    /// against the scene; `length` is the stretch's path length.  Must not be called once
    /// done.
    void skip_to(const glm::dvec3& to, double length);

    /// Follows a last straight ray from the current point along unit `direction` to
    /// infinity; the march is done afterwards, hit or not (then `result().direction` is
    /// `direction`, for the sky).
    bool ray(const glm::dvec3& direction);

    /// The same for a last ray known to meet nothing: not tested; the march is done, without
    /// a hit, its direction `direction`.
    void skip_ray(const glm::dvec3& direction);

    bool done() const { return done_; }
    const PathHit& result() const { return result_; }
    const glm::dvec3& point() const { return point_; }
    double path_length() const { return length_; }

  private:
    bool query(const glm::dvec3& direction, double length);

    const SceneAccel* accel_;
    glm::dvec3 point_;
    double length_ = 0.0;
    double min_depth_;
    bool done_ = false;
    PathHit result_;
};

}  // namespace mirage
