// POV-Ray 3.7's light sources as the shading sees them (render/trace.cpp
// ComputeOneWhiteLightRay, lighting/point.cpp Attenuate_Light): the ray from a surface point
// toward a light (point, spot and cylinder lights, parallel lights, a point of an area light)
// and the light's attenuation along it (the spot and cylinder cones, fade_distance and
// fade_power), and the sample offsets of an area light's grid.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace mirage {

/// The ray from a surface point toward a light source.
struct LightRay {
    glm::dvec3 direction{0.0};  // unit, from the point toward the light
    double depth = 0.0;         // distance to the light along `direction`
};

/// POV-Ray's ComputeOneWhiteLightRay: the ray from `point` toward the light's centre moved by
/// `jitter` (an area light's sample offset; 0 for the centre).
LightRay light_ray(const PointLight& light, const glm::dvec3& point,
                   const glm::dvec3& jitter = glm::dvec3(0.0));

/// POV-Ray's Attenuate_Light: the spot and cylinder falloff and the distance fade, for the
/// ray from `point` (the ray's origin) along `ray`.
double light_attenuation(const PointLight& light, const glm::dvec3& point, const LightRay& ray);

/// The unit direction a spot, cylinder or parallel light points (point_at - location).
glm::dvec3 light_direction(const PointLight& light);

/// The offset of an area light's sample (u, v) from its centre, along `axis1` and `axis2`
/// (the light's axes, or turned to face the point for `orient`), without jitter.
glm::dvec3 area_light_offset(const PointLight& light, int u, int v, const glm::dvec3& axis1,
                             const glm::dvec3& axis2);

/// The axes of an area light for a point: its own, or for `orient` square axes of the first
/// axis' length perpendicular to the ray toward the centre.  `full_area` picks POV-Ray's
/// variant of the full area lighting code (whose helper vector differs).
void area_light_axes(const PointLight& light, const glm::dvec3& point, bool full_area,
                     glm::dvec3& axis1, glm::dvec3& axis2);

}  // namespace mirage
