#include "trace/pigment_eval.h"

#include <cmath>

#include "trace/shape_intersect.h"
#include "trace/single_precision.h"

namespace mirage {

namespace {

PigmentColour from_colour(const Colour& c) {
    PigmentColour out;
    // POV-Ray keeps colours and colour map positions in single precision.
    out.rgb = to_single(c.rgb);
    out.filter = to_single(c.filter);
    out.transmit = to_single(c.transmit);
    return out;
}

PigmentColour mix(const PigmentColour& a, const PigmentColour& b, double fraction) {
    // POV-Ray: colour = prev + fraction * (cur - prev).
    PigmentColour out;
    out.rgb = a.rgb + fraction * (b.rgb - a.rgb);
    out.filter = a.filter + fraction * (b.filter - a.filter);
    out.transmit = a.transmit + fraction * (b.transmit - a.transmit);
    return out;
}

/// POV-Ray's Search_Blend_Map and the interpolation of Compute_Pigment.
PigmentColour colour_map_lookup(const std::vector<ColourMapEntry>& map, double value) {
    if (map.empty()) {
        // POV-Ray's default map for gradient (Gray_Default_Map): black at 0, white at 1.
        const double v = std::min(std::max(value, 0.0), 1.0);
        PigmentColour c;
        c.rgb = glm::dvec3(v);
        return c;
    }
    const std::size_t last = map.size() - 1;
    std::size_t prev = 0;
    std::size_t cur = 0;
    if (value >= to_single(map[last].position)) {
        prev = cur = last;
    } else {
        while (value > to_single(map[cur].position)) prev = cur++;
    }
    if (value == to_single(map[cur].position)) prev = cur;
    const PigmentColour c_cur = from_colour(map[cur].colour);
    if (prev == cur) return c_cur;
    const double p0 = to_single(map[prev].position);
    const double p1 = to_single(map[cur].position);
    return mix(from_colour(map[prev].colour), c_cur, (value - p0) / (p1 - p0));
}

}  // namespace

double pattern_value(const Pigment& pigment, const glm::dvec3& p) {
    switch (pigment.kind) {
        case PigmentKind::Checker: {
            // checker_pattern; POV-Ray sets its frequency to 0, so no wave is applied.
            const int value =
                static_cast<int>(std::floor(p.x + kPovEpsilon) + std::floor(p.y + kPovEpsilon) +
                                 std::floor(p.z + kPovEpsilon));
            return (value & 1) ? 1.0 : 0.0;
        }
        case PigmentKind::Gradient: {
            // gradient_pattern with the axis normalised as POV-Ray's parser does, then
            // Evaluate_TPat's ramp wave with frequency 1 and phase 0.
            const double length = glm::length(pigment.gradient_axis);
            const glm::dvec3 axis =
                length > 0.0 ? pigment.gradient_axis * (1.0 / length) : pigment.gradient_axis;
            double value = glm::dot(p, axis);
            if (value > 1.0) value = std::fmod(value, 1.0);
            value = std::fmod(value * 1.0 + 0.0, 1.00001);
            if (value < 0.0) value -= std::floor(value);
            return value;
        }
        case PigmentKind::Solid:
            return 0.0;
    }
    return 0.0;
}

PigmentColour evaluate_pigment(const Pigment& pigment, const glm::dvec3& world_point) {
    if (pigment.kind == PigmentKind::Solid) return from_colour(pigment.colour);
    const glm::dvec3 p = glm::dvec3(pigment.transform.inverse * glm::dvec4(world_point, 1.0));
    const double value = pattern_value(pigment, p);
    if (pigment.kind == PigmentKind::Checker) {
        return from_colour(pigment.checker[value > 0.5 ? 1 : 0]);
    }
    return colour_map_lookup(pigment.colour_map, value);
}

glm::dvec3 sky_colour(const Scene& scene, const glm::dvec3& direction) {
    // ComputeSky for language version 3.7: layers as a layered texture of a genuine sphere.
    glm::dvec3 colour(0.0);
    glm::dvec3 filter(1.0);
    if (scene.sky_sphere && !scene.sky_sphere->pigments.empty()) {
        const auto& sky = *scene.sky_sphere;
        // POV-Ray transforms the direction as a point (MInvTransPoint).
        const glm::dvec3 p = glm::dvec3(sky.transform.inverse * glm::dvec4(direction, 1.0));
        for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
            const PigmentColour c = evaluate_pigment(*it, p);
            const double opacity = 1.0 - c.filter - c.transmit;
            colour += c.rgb * opacity * filter * to_single(sky.emission);
            filter *= c.rgb * c.filter + glm::dvec3(c.transmit);
        }
    }
    // The background: POV-Ray's parser (3.7, no alpha output) precomposes it over black,
    // rgb * (1 - transmit), and drops its filter; ComputeSky then takes it as opaque.
    const PigmentColour background = from_colour(scene.background);
    colour += background.rgb * (1.0 - background.transmit) * filter;
    return colour;
}

}  // namespace mirage
