#include "trace/shading.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "trace/pigment_eval.h"
#include "trace/shape_intersect.h"
#include "trace/single_precision.h"
#include "util/check.h"

namespace mirage {

namespace {

std::string place(const FileLoc& loc) {
    if (loc.file.empty()) return "";
    std::ostringstream out;
    out << loc.file << ":" << loc.line << ":" << loc.column << ": ";
    return out.str();
}

bool is_transparent(const Colour& c) { return c.filter != 0.0 || c.transmit != 0.0; }

/// Whether some colour of an object pigment carries filter or transmit.
bool pigment_is_transparent(const Pigment& p) {
    switch (p.kind) {
        case PigmentKind::Solid:
            return is_transparent(p.colour);
        case PigmentKind::Checker:
            return is_transparent(p.checker[0]) || is_transparent(p.checker[1]);
        case PigmentKind::Gradient:
            return std::any_of(p.colour_map.begin(), p.colour_map.end(),
                               [](const ColourMapEntry& e) { return is_transparent(e.colour); });
    }
    return false;
}

Status check_colour_map(const Pigment& p, const FileLoc& loc, const std::string& what) {
    for (std::size_t i = 1; i < p.colour_map.size(); ++i) {
        if (p.colour_map[i].position < p.colour_map[i - 1].position) {
            return make_error(place(loc) + what +
                              ": colour_map entries must be in ascending order");
        }
    }
    return Ok{};
}

inline double max3(const glm::dvec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

/// POV-Ray stores 1 / roughness, and keeps 0 for a roughness of 0 (with a warning).
inline double specular_exponent(const Finish& f) {
    return f.roughness != 0.0 ? 1.0 / f.roughness : 0.0;
}

}  // namespace

void TraceCounters::add(const TraceCounters& o) {
    camera_rays += o.camera_rays;
    reflected_rays += o.reflected_rays;
    shadow_rays += o.shadow_rays;
    segments += o.segments;
    segment_queries += o.segment_queries;
    trace_level_cutoffs += o.trace_level_cutoffs;
}

Status check_supported(const Scene& scene) {
    if (scene.global.assumed_gamma != 1.0) {
        std::ostringstream out;
        out << scene.file << (scene.file.empty() ? "" : ": ") << "assumed_gamma "
            << scene.global.assumed_gamma
            << " is not supported by the built-in tracer (use assumed_gamma 1.0)";
        return make_error(out.str());
    }
    for (const Primitive& p : scene.primitives) {
        const Pigment& pigment = p.texture.pigment;
        if (pigment_is_transparent(pigment)) {
            return make_error(place(p.loc) +
                              "pigment with filter or transmit: transparency is not supported "
                              "by the built-in tracer");
        }
        if (auto s = check_colour_map(pigment, p.loc, "pigment"); !s) return s;
    }
    if (scene.sky_sphere) {
        for (const Pigment& pigment : scene.sky_sphere->pigments) {
            if (auto s = check_colour_map(pigment, scene.sky_sphere->loc, "sky_sphere pigment");
                !s) {
                return s;
            }
        }
    }
    return Ok{};
}

Shader::Shader(const Scene& scene, const SceneAccel& accel, const Propagator& propagator)
    : scene_(&scene),
      accel_(&accel),
      propagator_(&propagator),
      max_trace_level_(std::clamp(scene.global.max_trace_level, 1, kMaxTraceLevelLimit)) {
    MIRAGE_CHECK(accel.primitive_count() == static_cast<int>(scene.primitives.size()));
}

glm::dvec3 Shader::trace_camera_ray(const glm::dvec3& origin, const glm::dvec3& direction,
                                    TraceCounters& counters) const {
    RayStart start;
    start.origin = origin;
    start.direction = direction;
    return trace_camera_ray(start, counters);
}

glm::dvec3 Shader::trace_camera_ray(const RayStart& start, TraceCounters& counters) const {
    MIRAGE_CHECK(start.travelled == 0.0);
    ++counters.camera_rays;
    return trace_ray(start, 1.0, 0, counters);
}

glm::dvec3 Shader::trace_ray(const RayStart& start, double weight, int level,
                             TraceCounters& counters) const {
    // TraceRay: out of trace levels, or too faint to matter, is black (not the sky).
    if (level >= max_trace_level_ || weight < kAdcBailout) {
        if (level >= max_trace_level_) ++counters.trace_level_cutoffs;
        return glm::dvec3(0.0);
    }
    if (level > 0) ++counters.reflected_rays;
    const PathHit path = propagator_->propagate(*accel_, start);
    counters.segments += static_cast<std::uint64_t>(path.segments);
    counters.segment_queries += static_cast<std::uint64_t>(path.queries);
    return shade(path, weight, level + 1, counters, start.travelled + path.length);
}

glm::dvec3 Shader::shade(const PathHit& path, double weight, int level, TraceCounters& counters,
                         double travelled) const {
    if (!path.hit) return sky_colour(*scene_, path.direction);

    const SurfaceHit& hit = path.surface;
    const Primitive& primitive = scene_->primitives[hit.primitive];
    const Finish& finish = primitive.texture.finish;
    const glm::dvec3& ray_dir = path.direction;
    const glm::dvec3& point = hit.point;

    // POV-Ray turns the normal to face the incoming ray.
    glm::dvec3 normal = hit.normal;
    if (glm::dot(normal, ray_dir) > 0.0) normal = -normal;

    const PigmentColour pigment = evaluate_pigment(primitive.texture.pigment, point);
    // The layer's opacity (1 - filter - transmit); 1 for the opaque pigments we accept.
    const double att = 1.0 - pigment.filter - pigment.transmit;

    glm::dvec3 colour =
        pigment.rgb * to_single(finish.ambient) * to_single(scene_->global.ambient_light) * att;
    colour += pigment.rgb * to_single(finish.emission) * att;

    if (finish.diffuse != 0.0 || finish.specular != 0.0 || finish.phong != 0.0) {
        const glm::dvec3 reye = -ray_dir;
        for (const PointLight& light : scene_->lights) {
            const glm::dvec3 light_colour = to_single(light.colour);
            if (std::abs(light_colour.x) < kPovEpsilon && std::abs(light_colour.y) < kPovEpsilon &&
                std::abs(light_colour.z) < kPovEpsilon) {
                continue;
            }
            glm::dvec3 to_light = light.location - point;
            const double distance = glm::length(to_light);
            if (!(distance > 0.0)) continue;  // a light on the surface lights nothing there
            to_light *= 1.0 / distance;
            // Lit from behind the surface (as seen from the ray): no contribution.
            const double cos_in = glm::dot(normal, to_light);
            if (cos_in < kPovEpsilon) continue;
            if (!light.shadowless) {
                ++counters.shadow_rays;
                if (accel_->any_shadow_hit(point, to_light, kShadowTolerance,
                                           distance - kShadowTolerance)) {
                    continue;
                }
            }
            // ComputeDiffuseColour.
            if (finish.diffuse > 0.0) {
                double intensity = finish.brilliance != 1.0
                                       ? std::pow(std::abs(cos_in), finish.brilliance)
                                       : std::abs(cos_in);
                intensity *= finish.diffuse * att;
                colour += intensity * pigment.rgb * light_colour;
            }
            // Highlights; a shadowless light is a fill light and gives none.
            if (light.shadowless) continue;
            if (finish.phong > 0.0) {
                // ComputePhongColour: the mirror direction of the ray against the light.
                const glm::dvec3 reflected = ray_dir + (-2.0 * glm::dot(ray_dir, normal)) * normal;
                const double c = glm::dot(reflected, to_light);
                if (c > 0.0 && (finish.phong_size < 60.0 || c > 0.0008)) {
                    colour += finish.phong * std::pow(c, finish.phong_size) * light_colour;
                }
            }
            if (finish.specular > 0.0) {
                // ComputeSpecularColour: Blinn's halfway vector, exponent 1 / roughness.
                const glm::dvec3 halfway = 0.5 * (reye + to_light);
                const double length = glm::length(halfway);
                if (length > 0.0) {
                    const double c = glm::dot(halfway, normal) / length;
                    if (c > 0.0) {
                        colour +=
                            finish.specular * std::pow(c, specular_exponent(finish)) * light_colour;
                    }
                }
            }
        }
    }

    // Reflection (ComputeReflectivity type 0 with reflection_min = reflection_max, then
    // ComputeReflection): the reflected ray starts on the surface; its weight is the
    // path's times the strongest reflection channel.
    const glm::dvec3 reflectivity = to_single(finish.reflection);
    if (reflectivity != glm::dvec3(0.0)) {
        glm::dvec3 reflected = ray_dir + (-2.0 * glm::dot(ray_dir, normal)) * normal;
        RayStart bounce;
        bounce.origin = point;
        bounce.direction = glm::normalize(reflected);
        // A curved propagator keeps the reflected ray's error an angle seen from the eye.
        bounce.travelled = travelled;
        const glm::dvec3 seen = trace_ray(bounce, weight * max3(reflectivity), level, counters);
        colour += reflectivity * seen;
    }
    return colour;
}

}  // namespace mirage
