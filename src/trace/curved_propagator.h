// The continuous model in the tracer: rays follow the exact curved paths of a horizontally
// stratified atmosphere (exact_ray.h), sampled to a tolerance seen from the eye (sampler.h)
// and marched one straight segment at a time through the scene (PolylineMarch).  Per ray, or
// per image row as Khote & Howard do (ScanlinePropagator).
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "atmosphere/exact_path.h"
#include "atmosphere/exact_ray.h"
#include "atmosphere/path_sampler.h"
#include "atmosphere/phase_screens.h"
#include "atmosphere/sampler.h"
#include "scene/scene.h"
#include "trace/propagator.h"
#include "util/result.h"

namespace mirage {

/// How a ray's exact path is sampled.
enum class PathSampling {
    /// To the tolerance wherever the ray may meet a surface (near the boxes of the scene's
    /// bounded objects, at the ground point on a ground plane), coarsely elsewhere, by halving
    /// on a grid (sample_path_near): the first hits are those of the same sampler told
    /// nothing of the scene, which keeps the tolerance everywhere.
    NearSurfaces,
    /// To the tolerance all along, by the sampler's galloping steps (sample_path): the
    /// tracer before the sampling near surfaces, kept as the reference.
    Reference,
};

struct CurvedSettings {
    // The atmosphere in scene units (heights above the ground at y = 0, see
    // profile_in_scene_units and scene_atmosphere): an exponential profile's closed forms or
    // the general engine's model (real air, the curved Earth), whose exact paths
    // (atmosphere/exact_path.h) rays follow; homogeneous air: straight rays.  On the curved
    // Earth the scene is read as drawn in the model's frame: heights above the ground (the
    // flattened heights, with an Earth radius) and horizontal distances along it.
    Atmosphere atmosphere;
    // How far (horizontally, scene units) a path of the general engine is followed at most;
    // beyond, it goes on straight.  0: twice the horizontal reach of the scene's bounded
    // objects from the eye (a ray trapped in a duct turns for ever).  Paths in closed form
    // (Atmosphere::closed_form) are followed as far as the sampler goes.
    double max_dz = 0.0;
    // The largest path error, as a height within the ray's vertical plane: tolerance_m plus
    // tolerance_rad times the path length from where the ray's history began (the eye, or
    // each camera ray's own origin for a camera with many: scene/camera.h, PixelFootprint).
    double tolerance_rad = 0.0;  // rad
    double tolerance_m = 0.0;    // scene units
    PathSampling sampling = PathSampling::NearSurfaces;
    // Where the camera rays start.  Rays from there share an index, by azimuth, of the boxes
    // their vertical planes can cross (built once per scene and thread).
    std::optional<glm::dvec3> eye = std::nullopt;
    // Turbulent air (docs/turbulence.md): when set, every ray's path, curved or straight, camera
    // or reflected, is walked through these screens (ScreenWalk) at time turbulence_time_s, each
    // screen it crosses a kink.  The screens are in metres: scene units times unit_m.
    std::shared_ptr<const PhaseScreens> turbulence = nullptr;
    double turbulence_time_s = 0.0;  // s: the scene's clock
    double unit_m = 1.0;             // metres per scene unit
};

/// One ray's path in its vertical plane: the exact ray and its sampled polyline, and the
/// plane's horizontal direction.
struct CurvedPath {
    std::optional<ExactPath> exact;
    SampledPath path;
    glm::dvec2 heading{0.0, 1.0};  // unit (x, z) direction of the vertical plane
    double earth_radius = 0.0;     // of the atmosphere's flattened frame (0: flat)
};

/// The sampled path of a ray that starts at `origin` along unit `direction`, `travelled`
/// path length from the eye (the sampler's start_distance: the allowance stays an angle seen
/// from the eye for reflected rays).  Nothing when the ray goes straight: no index gradient,
/// a start below the ground (y < 0, or on it heading down), a (nearly) vertical ray, or any
/// ray whose direction cannot turn by more than half the tolerance anywhere in the
/// atmosphere (its straight line then keeps the tolerance everywhere).
/// With NearSurfaces sampling and no scene, the path is sampled to the tolerance everywhere.
std::optional<CurvedPath> curved_path(const CurvedSettings& settings, const glm::dvec3& origin,
                                      const glm::dvec3& direction, double travelled);

/// The same, sampled for the scene: with NearSurfaces, coarsely where the ray's vertical
/// plane holds nothing the path can meet (in a scene with a plane other than the ground,
/// everywhere to the tolerance).
std::optional<CurvedPath> curved_path(const CurvedSettings& settings, const SceneAccel& accel,
                                      const glm::dvec3& origin, const glm::dvec3& direction,
                                      double travelled);

/// Marches `path` from `origin` through the scene, its vertical plane along path.heading; with
/// `settings.turbulence`, walked through its screens (CurvedSettings).
/// After the last sample the ray goes on straight: with the path's asymptotic (or cut) slope
/// for a path that ends in the air, and along the exact path's tangent where it reaches the
/// ground at y = 0 when no surface is there (a scene without a ground object: the ray goes
/// on below it as through the band model's bottom layer).  An escaping ray's direction is
/// the path's final direction, for the sky; on the curved Earth (CurvedPath::earth_radius)
/// turned from the local horizontal where that slope holds to the start's.  Segments marked clear
/// (SampledPath::clear_length) are followed without testing them against the scene.
PathHit march_curved_path(const SceneAccel& accel, const glm::dvec3& origin,
                          const CurvedPath& path, const CurvedSettings& settings = {});

/// The points (scene units) of a ray's path as the tracer follows it: the exact path's samples
/// (a straight ray: its origin alone) walked through the turbulent air's screens when
/// `settings.turbulence` is set, then `tail` scene units along its last direction.  For plots
/// (mirage path's fan of perturbed rays).
std::vector<glm::dvec3> followed_points(const CurvedSettings& settings, const glm::dvec3& origin,
                                        const glm::dvec3& direction, double tail);

/// The horizontal reach of the scene's bounded objects from `eye`: the farthest corner of their
/// boxes (0 without any).
double bounded_reach(const SceneAccel& accel, const glm::dvec3& eye);

/// Every ray (camera and reflected, each from its own start and direction) along its own
/// exact path.  A ray that starts below the ground (a camera with many origins, some under
/// it) goes straight while below it, where the index is the ground's as in the band model's
/// bottom layer, and, rising, along its exact path from the point where it reaches the ground.
class CurvedPropagator final : public Propagator {
  public:
    explicit CurvedPropagator(const CurvedSettings& settings);
    PathHit propagate(const SceneAccel& accel, const RayStart& start) const override;
    const CurvedSettings& settings() const { return settings_; }

  private:
    CurvedSettings settings_;
    StraightPropagator straight_;
};

/// The paper's scheme: one sampled path per image row, that of the row's central column
/// (x = width / 2), rotated about the vertical into each camera ray's azimuth; every pixel of
/// a row thus gets the row's elevation, which is exact only for a cylindrical projection.
/// Where the central ray goes straight (curved_path), the row's rays go straight at its
/// elevation.  Needs a level camera (up vertical, direction and right horizontal).  Reflected
/// rays, and camera rays without an image position, follow their own paths as with
/// CurvedPropagator.
class ScanlinePropagator final : public Propagator {
  public:
    /// Samples the rows' paths; fails for a camera that is not level (the message names the
    /// camera's place in the scene file).
    static Result<ScanlinePropagator> make(const CurvedSettings& settings, const Camera& camera,
                                           int width, int height);
    PathHit propagate(const SceneAccel& accel, const RayStart& start) const override;

  private:
    struct Row {
        std::optional<CurvedPath> path;  // empty where the central ray goes straight
        double slope = 0.0;              // the central ray's initial dy / (horizontal distance)
    };
    ScanlinePropagator(const CurvedSettings& settings, std::vector<Row> rows);

    CurvedPropagator per_ray_;
    StraightPropagator straight_;
    std::vector<Row> rows_;  // index: image row, top first
};

/// With the general engine: how far paths from `eye` are followed when CurvedSettings::max_dz
/// is 0: twice the horizontal reach of the scene's bounded objects from it (the farthest corner
/// of their boxes), and at least 1e4 scene units.
double general_path_reach(const SceneAccel& accel, const glm::dvec3& eye);

/// Whether the camera is level: up along +y, direction and right horizontal (within 1e-9
/// relative).
bool camera_is_level(const Camera& camera);

}  // namespace mirage
