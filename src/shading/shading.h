// POV-Ray 3.7's shading (render/trace.cpp: ComputeTextureColour, ComputeLightedTexture,
// ComputeShadowTexture, ComputeDiffuseLight, ComputeReflection, ComputeRefraction,
// ComputeFog): layered and patterned textures, perturbed normals, ambient, emission, diffuse
// with brilliance, specular, phong, metallic highlights, iridescence, point, spot, cylinder,
// parallel and area lights with shadow rays filtered by transparent objects, reflection with
// fresnel, falloff, exponent and metallic, filter and transmit, refraction through interiors
// with POV-Ray's chain of indices and fade, total internal reflection, and fog, bounded by
// max_trace_level and adc_bailout.  Rays in the atmosphere travel through a Propagator (they
// may bend); rays inside a refracting object and shadow rays go straight.
#pragma once

#include <cstdint>
#include <deque>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"
#include "patterns/noise.h"
#include "patterns/patterns.h"
#include "trace/propagator.h"
#include "trace/scene_accel.h"
#include "shading/spectral.h"
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
    std::uint64_t reflected_rays = 0;       // secondary rays traced: reflected, refracted and
                                            // transmitted (not cut off)
    std::uint64_t shadow_rays = 0;          // straight rays toward lights
    std::uint64_t segments = 0;             // straight segments of camera and secondary rays
    std::uint64_t segment_queries = 0;      // of them, those tested against the scene
    std::uint64_t trace_level_cutoffs = 0;  // secondary rays not traced: max_trace_level reached
    void add(const TraceCounters& other);
};

/// Refuses what the tracer cannot render as POV-Ray would; the message names the place in
/// the scene file.  Checks that colour maps are in ascending order.
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

    /// The colour at the end of a path that started in the atmosphere (outside every
    /// object): its surface lit by the scene's lights, with reflection and transmission, or
    /// the sky when it escaped; fog is not applied.  `weight` is the path's contribution to
    /// the pixel, `level` the trace level reached (1 for a camera ray's hit) and `travelled`
    /// the path length from the eye to the hit (where secondary rays start).
    glm::dvec3 shade(const PathHit& path, double weight, int level, TraceCounters& counters,
                     double travelled = 0.0) const;

    int max_trace_level() const { return max_trace_level_; }

    /// The interiors a ray is inside, innermost last (POV-Ray's interior list).
    using Interiors = std::vector<const Interior*>;

  private:
    struct Context;  // one intersection's shading state
    struct ShadowCache;

    // `band`: the spectral band of a ray split by a dispersive refraction, else null.
    glm::dvec3 trace_ray(const RayStart& start, double weight, int level, const Interiors& inside,
                         bool continued, TraceCounters& counters,
                         const SpectralBand* band = nullptr) const;
    glm::dvec3 shade_hit(const PathHit& path, const glm::dvec3& origin, double weight, int level,
                         const Interiors& inside, double travelled, TraceCounters& counters,
                         const SpectralBand* band) const;
    glm::dvec3 texture_colour(const Texture& texture, std::vector<const Pattern*>& warps,
                              const glm::dvec3& ipoint, Context& c) const;
    glm::dvec3 lighted_texture(const Texture& texture, const std::vector<const Pattern*>& warps,
                               const glm::dvec3& ipoint, Context& c) const;
    glm::dvec3 layer_normal(const Texture& layer, const std::vector<const Pattern*>& warps,
                            const glm::dvec3& ipoint, const glm::dvec3& raw_normal) const;
    void diffuse_light(const Finish& finish, const glm::dvec3& layer_normal,
                       const glm::dvec3& pigment, double attenuation, Context& c,
                       glm::dvec3& colour) const;
    glm::dvec3 reflect(const Finish& finish, const glm::dvec3& normal, double weight,
                       Context& c) const;
    bool refract(const Finish& finish, const Interior& interior, const glm::dvec3& normal,
                 double weight, Context& c, glm::dvec3& colour) const;
    bool refract_ray(const Finish& finish, double ior, const glm::dvec3& normal, double weight,
                     const Interiors& next, const SpectralBand* band, Context& c,
                     glm::dvec3& colour) const;
    glm::dvec3 shadow_filter(const PointLight& light, const glm::dvec3& point,
                             const glm::dvec3& direction, double depth, const glm::dvec3& colour,
                             const Interiors& inside, TraceCounters& counters) const;
    glm::dvec3 shadow_texture(const Texture& texture, std::vector<const Pattern*>& warps,
                              const glm::dvec3& ipoint, const glm::dvec3& raw_normal,
                              const glm::dvec3& direction, double caustics) const;
    glm::dvec3 area_shadow(const PointLight& light, const glm::dvec3& point,
                           const glm::dvec3& colour, const Interiors& inside,
                           TraceCounters& counters) const;
    double relative_ior(const Interiors& inside, const Interior& interior) const;
    const Interior& interior_of(int primitive) const { return *interiors_[primitive]; }
    Interiors containing_interiors(const glm::dvec3& point) const;

    const Scene* scene_;
    const SceneAccel* accel_;
    const Propagator* propagator_;
    StraightPropagator straight_;
    int max_trace_level_;
    double adc_bailout_;
    WaveSources waves_;
    PatternContext pattern_context_;
    std::deque<Interior> resolved_;           // the interiors with POV-Ray's post-processing
    std::vector<const Interior*> interiors_;  // per primitive
    std::vector<std::uint8_t> opaque_;        // per primitive: POV-Ray's OPAQUE_FLAG
    bool any_transparent_caster_ = false;     // a shadow casting primitive is not opaque
    glm::dvec3 camera_location_{0.0};
    Interiors camera_inside_;  // the interiors the camera is in
};

}  // namespace mirage
