// POV-Ray 3.7's shading of the scene subset (render/trace.cpp: ComputeLightedTexture,
// ComputeDiffuseLight, ComputeShadowColour, ComputeReflection): ambient, emission, diffuse
// with brilliance, specular (Blinn with roughness), phong, point lights with straight shadow
// rays, and recursive reflection bounded by max_trace_level and adc_bailout.  Primary and
// reflected rays travel through a Propagator; shadow rays are straight.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "scene/scene.h"
#include "trace/propagator.h"
#include "trace/scene_accel.h"
#include "util/result.h"

namespace mirage {

/// POV-Ray's SMALL_TOLERANCE and SHADOW_TOLERANCE: a shadow ray counts only blockers
/// farther than this from the lit point and from the light.
inline constexpr double kShadowTolerance = 1.0e-3;
/// POV-Ray's default adc_bailout: rays weighing less are not traced (they return black).
inline constexpr double kAdcBailout = 1.0 / 255.0;
/// POV-Ray's largest max_trace_level.
inline constexpr int kMaxTraceLevelLimit = 256;

/// What a render traced, summed over its rays (integers, so sums are deterministic).
struct TraceCounters {
    std::uint64_t camera_rays = 0;          // rays from the camera
    std::uint64_t reflected_rays = 0;       // reflected rays traced (not cut off)
    std::uint64_t shadow_rays = 0;          // straight rays toward lights
    std::uint64_t segments = 0;             // straight segments of camera and reflected rays
    std::uint64_t segment_queries = 0;      // of them, those tested against the scene
    std::uint64_t trace_level_cutoffs = 0;  // reflections not traced: max_trace_level reached
    void add(const TraceCounters& other);
};

/// Refuses what the tracer does not render as POV-Ray would: filter or transmit in an
/// object's pigment (transparency), an assumed_gamma other than 1.  The message names the
/// place in the scene file.
Status check_supported(const Scene& scene);

/// Shades rays of a scene.  Holds references: the scene, the accel and the propagator must
/// outlive it.  Thread-safe: every method is const and keeps no state.
class Shader {
  public:
    Shader(const Scene& scene, const SceneAccel& accel, const Propagator& propagator);

    /// The linear colour seen along a camera ray (POV-Ray's TraceRay at trace level 0 with
    /// weight 1).  `direction` must be of unit length.
    glm::dvec3 trace_camera_ray(const glm::dvec3& origin, const glm::dvec3& direction,
                                TraceCounters& counters) const;

    /// The same for a camera ray that names its image position (start.travelled is 0).
    glm::dvec3 trace_camera_ray(const RayStart& start, TraceCounters& counters) const;

    /// The colour at the end of a path: its surface lit by the scene's lights, plus
    /// reflection, or the sky when it escaped.  `weight` is the path's contribution to the
    /// pixel, `level` the trace level reached (1 for a camera ray's hit) and `travelled` the
    /// path length from the eye to the hit (where a reflected ray starts).
    glm::dvec3 shade(const PathHit& path, double weight, int level, TraceCounters& counters,
                     double travelled = 0.0) const;

    int max_trace_level() const { return max_trace_level_; }

  private:
    glm::dvec3 trace_ray(const RayStart& start, double weight, int level,
                         TraceCounters& counters) const;

    const Scene* scene_;
    const SceneAccel* accel_;
    const Propagator* propagator_;
    int max_trace_level_;
};

}  // namespace mirage
