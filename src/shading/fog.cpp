#include "shading/fog.h"

#include <cmath>

#include "patterns/noise.h"
#include "patterns/single_precision.h"

namespace mirage {

namespace {

constexpr double kEpsilon = 1.0e-10;

/// The fog's turbulence shortens the distance the light travels in it (both fog types).
double turbulent_width(const Fog& fog, const glm::dvec3& p, double width, int generator) {
    const Turbulence& t = *fog.turbulence;
    const glm::dvec3 q = (p + fog.lowered_by) * t.amount;
    const double k = std::exp(-width / fog.distance);
    return width *
           (1.0 - k * std::min(1.0, turbulence(q, t, generator) * to_single(fog.turb_depth)));
}

double constant_fog(const Fog& fog, const glm::dvec3& origin, const glm::dvec3& direction,
                    double width, int generator) {
    if (fog.turbulence) {
        const glm::dvec3 p = origin + (width / 2.0) * direction;
        width = turbulent_width(fog, p, width, generator);
    }
    return std::exp(-width / fog.distance);
}

double ground_fog(const Fog& fog, const glm::dvec3& origin, const glm::dvec3& direction,
                  double width, int generator) {
    const glm::dvec3 p1 = origin;
    const glm::dvec3 p2 = p1 + direction * width;
    const double y1 = glm::dot(p1, fog.up);
    const double y2 = glm::dot(p2, fog.up);
    const double start = (y1 - fog.offset) / fog.alt;
    const double end = (y2 - fog.offset) / fog.alt;
    // The density 1 / (1 + y^2) above the offset, 1 below, averaged along the ray.
    double density;
    if (start <= 0.0) {
        density = end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
    } else if (end <= 0.0) {
        density = (std::atan(start) - end) / (start - end);
    } else {
        const double delta = start - end;
        density = std::fabs(delta) > kEpsilon ? (std::atan(start) - std::atan(end)) / delta
                                              : 1.0 / (start * start + 1.0);
    }
    if (fog.turbulence) width = turbulent_width(fog, (p1 + p2) * 0.5, width, generator);
    return std::exp(-width * density / fog.distance);
}

}  // namespace

namespace {

void accumulate(const std::vector<Fog>& fogs, const glm::dvec3& origin, const glm::dvec3& direction,
                double depth, int generator, glm::dvec3& sum_att, glm::dvec3& sum_col) {
    // POV-Ray keeps its fogs in a list with the last declared first.
    for (auto it = fogs.rbegin(); it != fogs.rend(); ++it) {
        const Fog& fog = *it;
        if (!(std::fabs(fog.distance) > kEpsilon)) continue;
        double att = fog.type == 2 ? ground_fog(fog, origin, direction, depth, generator)
                                   : constant_fog(fog, origin, direction, depth, generator);
        const glm::dvec3 rgb = to_single(fog.colour.rgb);
        const double filter = to_single(fog.colour.filter);
        const double transmit = to_single(fog.colour.transmit);
        if (att < transmit) att = transmit;
        sum_att *= att * ((1.0 - filter) + filter * rgb);
        sum_col += (1.0 - att) * rgb;
    }
}

}  // namespace

glm::dvec3 apply_fog(const std::vector<Fog>& fogs, const glm::dvec3& origin,
                     const glm::dvec3& direction, double depth, const glm::dvec3& colour,
                     int generator) {
    glm::dvec3 sum_att(1.0);
    glm::dvec3 sum_col(0.0);
    accumulate(fogs, origin, direction, depth, generator, sum_att, sum_col);
    return sum_col + sum_att * colour;
}

glm::dvec3 fog_attenuation(const std::vector<Fog>& fogs, const glm::dvec3& origin,
                           const glm::dvec3& direction, double depth, int generator) {
    glm::dvec3 sum_att(1.0);
    glm::dvec3 sum_col(0.0);
    accumulate(fogs, origin, direction, depth, generator, sum_att, sum_col);
    return sum_att;
}

}  // namespace mirage
