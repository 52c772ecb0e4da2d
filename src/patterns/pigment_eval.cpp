#include "patterns/pigment_eval.h"

#include <cmath>

#include "scene/material_ops.h"
#include "patterns/image_map.h"
#include "patterns/single_precision.h"
#include "patterns/warps.h"

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

/// POV-Ray's Search_Blend_Map over positions held in single precision: the entries below
/// and above `value` (the same one when `value` is on or beyond an entry at an end).
template <class Entry>
void search_map(const std::vector<Entry>& map, double value, std::size_t& prev, std::size_t& cur) {
    const std::size_t last = map.size() - 1;
    prev = cur = 0;
    if (value >= to_single(map[last].position)) {
        prev = cur = last;
    } else {
        while (value > to_single(map[cur].position)) prev = cur++;
    }
    if (value == to_single(map[cur].position)) prev = cur;
}

PigmentColour colour_map_lookup(const std::vector<ColourMapEntry>& map, double value) {
    std::size_t prev, cur;
    search_map(map, value, prev, cur);
    const PigmentColour c_cur = from_colour(map[cur].colour);
    if (prev == cur) return c_cur;
    const double p0 = to_single(map[prev].position);
    const double p1 = to_single(map[cur].position);
    return mix(from_colour(map[prev].colour), c_cur, (value - p0) / (p1 - p0));
}

}  // namespace

double pattern_value(const Pigment& pigment, const glm::dvec3& p) {
    return evaluate_pattern(pigment, p, default_pattern_context());
}

bool compute_pigment(const Pigment& pigment, const glm::dvec3& point, const PatternContext& ctx,
                     PigmentColour& out) {
    if (pigment.kind == PatternKind::Solid) {
        out = from_colour(pigment.colour);
        return true;
    }
    const glm::dvec3 p = warp_point(pigment, point);
    if (pigment.kind == PatternKind::ImageMap) {
        return image_map_colour(pigment, p, out);
    }
    if (pigment.kind == PatternKind::Average) {
        // Do_Average_Pigments: the entries' weights are their positions.
        out = PigmentColour{};
        float total = 0.0f;
        for (const PigmentMapEntry& e : pigment.pigment_map) {
            PigmentColour c;
            compute_pigment(*e.pigment, p, ctx, c);
            const double w = to_single(e.position);
            out.rgb += c.rgb * w;
            out.filter += c.filter * w;
            out.transmit += c.transmit * w;
            total += static_cast<float>(w);
        }
        if (total != 0.0f) {
            out.rgb /= static_cast<double>(total);
            out.filter /= static_cast<double>(total);
            out.transmit /= static_cast<double>(total);
        }
        return true;
    }
    const double value = evaluate_pattern(pigment, p, ctx);
    if (!pigment.pigment_map.empty()) {
        std::size_t prev, cur;
        search_map(pigment.pigment_map, value, prev, cur);
        // The entries are evaluated at the warped point (POV-Ray's Compute_Pigment).
        bool found = compute_pigment(*pigment.pigment_map[cur].pigment, p, ctx, out);
        if (prev != cur) {
            PigmentColour below;
            found |= compute_pigment(*pigment.pigment_map[prev].pigment, p, ctx, below);
            const double p0 = to_single(pigment.pigment_map[prev].position);
            const double p1 = to_single(pigment.pigment_map[cur].position);
            out = mix(below, out, (value - p0) / (p1 - p0));
        }
        return found;
    }
    if (pigment.kind == PatternKind::Checker && pigment.colour_map.empty()) {
        out = from_colour(pigment.checker[value > 0.5 ? 1 : 0]);
        return true;
    }
    out = colour_map_lookup(
        pigment.colour_map.empty() ? default_colour_map(pigment.kind) : pigment.colour_map, value);
    return true;
}

PigmentColour evaluate_pigment(const Pigment& pigment, const glm::dvec3& world_point) {
    PigmentColour c;
    compute_pigment(pigment, world_point, default_pattern_context(), c);
    return c;
}

glm::dvec3 sky_colour(const Scene& scene, const glm::dvec3& direction, const PatternContext& ctx) {
    // ComputeSky for language version 3.7: layers as a layered texture of a genuine sphere.
    glm::dvec3 colour(0.0);
    glm::dvec3 filter(1.0);
    if (scene.sky_sphere && !scene.sky_sphere->pigments.empty()) {
        const auto& sky = *scene.sky_sphere;
        // POV-Ray transforms the direction as a point (MInvTransPoint).
        const glm::dvec3 p = glm::dvec3(sky.transform.inverse * glm::dvec4(direction, 1.0));
        for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
            PigmentColour c;
            compute_pigment(*it, p, ctx, c);
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
