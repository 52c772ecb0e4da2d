#include "scene/material_ops.h"

#include <initializer_list>
#include <utility>

#include "scene/object_tree.h"
#include "scene/transform.h"

namespace mirage {

namespace {

std::vector<ColourMapEntry> make_map(std::initializer_list<std::pair<double, glm::dvec3>> entries) {
    std::vector<ColourMapEntry> map;
    for (const auto& [position, rgb] : entries) {
        ColourMapEntry e;
        e.position = position;
        e.colour.rgb = rgb;
        map.push_back(e);
    }
    return map;
}

bool colour_is_opaque(const Colour& c) { return c.filter == 0.0 && c.transmit == 0.0; }

bool pigment_is_opaque(const Pigment& p) {
    if (p.kind == PatternKind::Solid) return colour_is_opaque(p.colour);
    if (!p.pigment_map.empty()) {
        for (const PigmentMapEntry& e : p.pigment_map) {
            if (!pigment_is_opaque(*e.pigment)) return false;
        }
        return true;
    }
    if (p.kind == PatternKind::Checker && p.colour_map.empty()) {
        return colour_is_opaque(p.checker[0]) && colour_is_opaque(p.checker[1]);
    }
    if (p.kind == PatternKind::ImageMap) {
        return !p.once && p.filter_all == 0.0 && p.transmit_all == 0.0 &&
               !(p.image && p.image->has_alpha);
    }
    for (const ColourMapEntry& e : p.colour_map) {
        if (!colour_is_opaque(e.colour)) return false;
    }
    return true;
}

}  // namespace

const std::vector<ColourMapEntry>& default_colour_map(PatternKind kind) {
    // Post_Pigment's default maps (texture/pigment.cpp).
    static const auto gray = make_map({{0.0, glm::dvec3(0.0)}, {1.0, glm::dvec3(1.0)}});
    static const auto bozo = make_map({{0.4, {1, 1, 1}},
                                       {0.4, {0, 1, 0}},
                                       {0.6, {0, 1, 0}},
                                       {0.6, {0, 0, 1}},
                                       {0.8, {0, 0, 1}},
                                       {0.8, {1, 0, 0}}});
    static const auto wood = make_map({{0.6, {0.666, 0.312, 0.2}}, {0.6, {0.4, 0.1333, 0.066}}});
    static const auto mandel = make_map({{0.001, {0, 0, 0}},
                                         {0.001, {0, 1, 1}},
                                         {0.012, {1, 1, 0}},
                                         {0.015, {1, 0, 1}},
                                         {0.1, {0, 1, 1}}});
    static const auto agate = make_map({{0.0, {1, 1, 1}},
                                        {0.5, {0.95, 0.75, 0.5}},
                                        {0.5, {0.9, 0.7, 0.5}},
                                        {0.6, {0.9, 0.7, 0.4}},
                                        {0.6, {1.0, 0.7, 0.4}},
                                        {1.0, {0.6, 0.3, 0.0}}});
    static const auto radial =
        make_map({{0.0, {0, 1, 1}}, {0.333, {1, 1, 0}}, {0.666, {1, 0, 1}}, {1.0, {0, 1, 1}}});
    static const auto marble =
        make_map({{0.0, {0.9, 0.8, 0.8}}, {0.9, {0.9, 0.08, 0.08}}, {0.9, {0, 0, 0}}});
    static const auto brick = make_map({{0.0, {0.5, 0.5, 0.5}}, {1.0, {0.6, 0.15, 0.15}}});
    static const auto hexagon = make_map({{0.0, {0, 0, 1}}, {1.0, {0, 1, 0}}, {2.0, {1, 0, 0}}});
    // POV-Ray's checker map takes the hexagon's first two entries.
    static const auto checker = std::vector<ColourMapEntry>(hexagon.begin(), hexagon.begin() + 2);
    // Cubic_Entries, which POV-Ray also uses for square (4 entries) and triangular (6).
    static const auto cubic = make_map({{0.0, {1, 0, 0}},
                                        {1.0, {0, 1, 0}},
                                        {1.0, {0, 0, 1}},
                                        {1.0, {1, 1, 0}},
                                        {1.0, {0, 1, 1}},
                                        {2.0, {1, 0, 1}}});
    static const auto square = std::vector<ColourMapEntry>(cubic.begin(), cubic.begin() + 4);
    switch (kind) {
        case PatternKind::Bozo:
            return bozo;
        case PatternKind::Brick:
            return brick;
        case PatternKind::Wood:
            return wood;
        case PatternKind::Mandel:
            return mandel;
        case PatternKind::Radial:
            return radial;
        case PatternKind::Agate:
            return agate;
        case PatternKind::Marble:
            return marble;
        case PatternKind::Hexagon:
            return hexagon;
        case PatternKind::Checker:
            return checker;
        case PatternKind::Square:
            return square;
        case PatternKind::Triangular:
        case PatternKind::Cubic:
            return cubic;
        default:
            return gray;
    }
}

void transform_pattern(Pattern& pattern, const Transform& t) {
    pattern.transform = compose_transforms(pattern.transform, t);
}

void transform_texture(Texture& texture, const Transform& t) {
    // Transform_Textures: each layer's pigment and normal, or a patterned texture's pattern.
    if (texture.pattern.kind != PatternKind::Solid) {
        transform_pattern(texture.pattern, t);
    } else {
        transform_pattern(texture.pigment, t);
        if (texture.normal) transform_pattern(*texture.normal, t);
    }
    for (Texture& layer : texture.layers_below) transform_texture(layer, t);
}

bool texture_is_opaque(const Texture& texture) {
    if (texture.pattern.kind != PatternKind::Solid) return false;
    if (pigment_is_opaque(texture.pigment)) return true;
    for (const Texture& layer : texture.layers_below) {
        if (pigment_is_opaque(layer.pigment)) return true;
    }
    return false;
}

void finish_pigment(Pigment& pigment) {
    // Post_Pigment gives a pattern without a map its default map.
    switch (pigment.kind) {
        case PatternKind::Solid:
        case PatternKind::Checker:
        case PatternKind::ImageMap:
        case PatternKind::Average:
            return;
        default:
            break;
    }
    if (pigment.colour_map.empty() && pigment.pigment_map.empty()) {
        pigment.colour_map = default_colour_map(pigment.kind);
    }
}

void transform_light(PointLight& light, const Transform& t) {
    light.location = transform_point(t, light.location);
    light.point_at = transform_point(t, light.point_at);
    light.axis1 = transform_direction(t, light.axis1);
    light.axis2 = transform_direction(t, light.axis2);
}

std::string link_textures(Texture& texture, Texture top) {
    if (texture.pattern.kind != PatternKind::Solid) return "cannot layer over a patterned texture";
    if (top.pattern.kind != PatternKind::Solid) {
        return "cannot layer a patterned texture over another";
    }
    // The new texture's layers go on top: its own layers, then the old texture's.
    Texture below = std::move(texture);
    std::vector<Texture> lower = std::move(below.layers_below);
    below.layers_below.clear();
    texture = std::move(top);
    texture.layers_below.push_back(std::move(below));
    for (Texture& l : lower) texture.layers_below.push_back(std::move(l));
    return "";
}

}  // namespace mirage
