#include "shading/lights.h"

#include <cmath>

namespace mirage {

namespace {

constexpr double kEpsilon = 1.0e-10;

/// POV-Ray's cubic_spline: 0 below `low`, 1 from `high` on, a smooth step between.
double cubic_spline(double low, double high, double pos) {
    if (pos < low) return 0.0;
    if (pos >= high) return 1.0;
    pos = (pos - low) / (high - low);
    return (3 - 2 * pos) * pos * pos;
}

}  // namespace

glm::dvec3 light_direction(const PointLight& light) {
    const glm::dvec3 d = light.point_at - light.location;
    const double len = glm::length(d);
    return len > kEpsilon ? d / len : d;
}

LightRay light_ray(const PointLight& light, const glm::dvec3& point, const glm::dvec3& jitter) {
    const glm::dvec3 centre = light.location + jitter;
    LightRay r;
    if (light.kind == PointLight::Kind::Cylinder) {
        // Parallel beams: the direction is the light's axis, the depth the projection.
        const glm::dvec3 axis = centre - light.point_at;
        const double axis_length = glm::length(axis);
        r.depth = glm::dot(centre - point, axis) / axis_length;
        r.direction = axis / axis_length;
    } else {
        r.direction = centre - point;
        r.depth = glm::length(r.direction);
        r.direction /= r.depth;
    }
    if (light.parallel) {
        if (light.area_light) {
            const glm::dvec3 v1 = glm::normalize(centre - light.point_at);
            r.depth *= glm::dot(v1, r.direction);
            r.direction = v1;
        } else {
            const glm::dvec3 d = light_direction(light);
            r.depth *= -glm::dot(d, r.direction);
            r.direction = -d;
        }
    }
    return r;
}

double light_attenuation(const PointLight& light, const glm::dvec3& point, const LightRay& ray) {
    double attenuation = 1.0;
    switch (light.kind) {
        case PointLight::Kind::Spot: {
            double costheta = glm::dot(ray.direction, light_direction(light));
            if (ray.depth > 0.0) costheta = -costheta;
            if (costheta <= 0.0) return 0.0;
            attenuation = std::pow(costheta, light.tightness);
            if (light.radius > 0.0 && costheta < light.radius) {
                attenuation *= cubic_spline(light.falloff, light.radius, costheta);
            }
            break;
        }
        case PointLight::Kind::Cylinder: {
            const glm::dvec3 direction = light_direction(light);
            const glm::dvec3 v1 = point - light.location;
            const double k = glm::dot(v1, direction);
            if (k <= 0.0) return 0.0;
            const double len = glm::length(v1 - k * direction);
            if (len >= light.falloff) return 0.0;
            const double dist = 1.0 - len / light.falloff;
            attenuation = std::pow(dist, light.tightness);
            if (light.radius > 0.0 && len > light.radius) {
                attenuation *= cubic_spline(0.0, 1.0 - light.radius / light.falloff, dist);
            }
            break;
        }
        case PointLight::Kind::Point:
            break;
    }
    if (attenuation > 0.0 && light.fade_power > 0.0 && std::fabs(light.fade_distance) > kEpsilon) {
        attenuation *= 2.0 / (1.0 + std::pow(ray.depth / light.fade_distance, light.fade_power));
    }
    return attenuation;
}

glm::dvec3 area_light_offset(const PointLight& light, int u, int v, const glm::dvec3& axis1,
                             const glm::dvec3& axis2) {
    double ju = u, jv = v;
    if (light.circular) {
        ju = ju / (light.size1 - 1) - 0.5 + 0.001;
        jv = jv / (light.size2 - 1) - 0.5 + 0.001;
        double scale = std::fabs(ju) > std::fabs(jv) ? std::fabs(ju) : std::fabs(jv);
        scale /= std::sqrt(ju * ju + jv * jv);
        ju *= scale;
        jv *= scale;
        return axis1 * ju + axis2 * jv;
    }
    glm::dvec3 a(0.0), b(0.0);
    if (light.size1 > 1) a = axis1 * (ju / static_cast<double>(light.size1 - 1) - 0.5);
    if (light.size2 > 1) b = axis2 * (jv / static_cast<double>(light.size2 - 1) - 0.5);
    return a + b;
}

void area_light_axes(const PointLight& light, const glm::dvec3& point, bool full_area,
                     glm::dvec3& axis1, glm::dvec3& axis2) {
    axis1 = light.axis1;
    axis2 = light.axis2;
    if (!light.orient) return;
    const LightRay r = light_ray(light, point);
    const double length = glm::length(axis1);
    // POV-Ray's two copies of this code use different helper vectors (0.1 in the full area
    // lighting one).
    glm::dvec3 helper = std::fabs(std::fabs(r.direction.z) - 1.0) < 0.01
                            ? glm::dvec3(0.0, 1.0, 0.0)
                            : glm::dvec3(0.0, 0.0, full_area ? 0.1 : 1.0);
    axis1 = glm::normalize(glm::cross(r.direction, helper));
    axis2 = glm::normalize(glm::cross(r.direction, axis1));
    axis1 *= length;
    axis2 *= length;
}

}  // namespace mirage
