// Textures, pigments, finishes and colour maps, after POV-Ray 3.7's parstxtr.cpp.
#include <cmath>

#include "scene/scene_parser.h"
#include "scene/transform.h"

namespace mirage::scene_detail {
namespace {

constexpr std::size_t kMaxColourMapEntries = 256;  // POV-Ray's MAX_BLEND_MAP_ENTRIES

bool one_of(const std::string& w, std::initializer_list<const char*> words) {
    for (const char* x : words) {
        if (w == x) return true;
    }
    return false;
}

bool is_other_pattern(const std::string& w) {
    return one_of(w, {"agate",     "aoi",       "average",         "boxed",
                      "bozo",      "brick",     "bumps",           "cells",
                      "crackle",   "cubic",     "cylindrical",     "density_file",
                      "dents",     "facets",    "function",        "granite",
                      "hexagon",   "image_map", "image_pattern",   "julia",
                      "leopard",   "magnet",    "mandel",          "marble",
                      "onion",     "pavement",  "pigment_pattern", "planar",
                      "quilted",   "radial",    "ripples",         "slope",
                      "spherical", "spiral1",   "spiral2",         "spotted",
                      "square",    "tiling",    "triangular",      "uv_mapping",
                      "waves",     "wood",      "wrinkles",        "object"});
}

struct ItemArity {
    const char* name;
    Arity arity;
};

constexpr ItemArity kUnsupportedPatternModifiers[] = {
    {"turbulence", Arity::Vector},     {"octaves", Arity::Float},
    {"omega", Arity::Float},           {"lambda", Arity::Float},
    {"frequency", Arity::Float},       {"phase", Arity::Float},
    {"ramp_wave", Arity::None},        {"triangle_wave", Arity::None},
    {"sine_wave", Arity::None},        {"scallop_wave", Arity::None},
    {"cubic_wave", Arity::None},       {"poly_wave", Arity::OptionalFloat},
    {"noise_generator", Arity::Float}, {"warp", Arity::Block},
    {"pigment_map", Arity::Block},
};

constexpr ItemArity kUnsupportedFinishItems[] = {
    {"conserve_energy", Arity::None},
    {"metallic", Arity::OptionalFloat},
    {"crand", Arity::Float},
    {"irid", Arity::Block},
    {"ior", Arity::Float},
    {"caustics", Arity::Float},
    {"refraction", Arity::Float},
    {"subsurface", Arity::Block},
    {"reflection_exponent", Arity::Float},
};

template <std::size_t N>
const ItemArity* find_item(const ItemArity (&table)[N], const std::string& w) {
    for (const ItemArity& m : table) {
        if (w == m.name) return &m;
    }
    return nullptr;
}

bool same_entry(const ColourMapEntry& a, const ColourMapEntry& b) {
    return a.position == b.position && a.colour.rgb == b.colour.rgb &&
           a.colour.filter == b.colour.filter && a.colour.transmit == b.colour.transmit;
}

}  // namespace

void SceneParser::set_texture(ObjectNode& node, Texture texture, const Token& at) {
    // A second texture is layered over the first; an opaque one hides it completely, which
    // is all the subset can represent.
    if (node.texture && !texture_is_opaque(texture)) {
        unsupported(at, "texture layered over another with filter or transmit");
    }
    node.texture = std::move(texture);
}

Texture SceneParser::parse_texture_body(const Token& kw) {
    Texture tex = default_texture_;
    if (const Value* v = peek_identifier_value(0); v && std::holds_alternative<Texture>(v->data)) {
        tex = identifier_as<Texture>(next(), "a texture");
    }
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        // A pigment or finish identifier alone stands for pigment { Ident } (POV-Ray allows it).
        if (const Value* v = peek_identifier_value(0)) {
            if (std::holds_alternative<Pigment>(v->data)) {
                tex.pigment = identifier_as<Pigment>(next(), "a pigment");
                continue;
            }
            if (std::holds_alternative<Finish>(v->data)) {
                tex.finish = identifier_as<Finish>(next(), "a finish");
                continue;
            }
        }
        Transform tr;
        if (parse_transform_item(tr)) {
            transform_texture(tex, tr);
            continue;
        }
        if (is_keyword(t)) {
            const std::string& w = t.text();
            if (w == "pigment") {
                Token item = next();
                expect_open_brace(item);
                parse_pigment_body(tex.pigment, item);
                expect_close_brace(item);
                continue;
            }
            if (w == "finish") {
                Token item = next();
                parse_finish_block(tex.finish, item);
                continue;
            }
            if (w == "no_bump_scale") {
                next();  // only matters for normals
                continue;
            }
            if (w == "normal") {
                Token item = next();
                skip_unsupported(item, Arity::Block, "texture item 'normal'");
                continue;
            }
            if (w == "tiles" || w == "material_map" || w == "texture_map" || is_other_pattern(w) ||
                w == "checker" || w == "gradient") {
                Token item = next();
                skip_unsupported(item, Arity::Rest, "patterned texture '" + item.text() + "'");
                continue;
            }
        }
        reject_unknown_word(t);
        break;
    }
    (void)kw;
    return tex;
}

// POV-Ray's Parse_Pigment: an optional identifier, then the pattern (or a colour), then the
// modifiers; it changes the pigment it is given, keeping what is not mentioned.
void SceneParser::parse_pigment_body(Pigment& p, const Token& kw) {
    if (const Value* v = peek_identifier_value(0); v && std::holds_alternative<Pigment>(v->data)) {
        p = identifier_as<Pigment>(next(), "a pigment");
    }
    const Token t = peek(0);
    if (starts_colour(t)) {
        p.kind = PigmentKind::Solid;
        p.colour = parse_colour(true);
    } else if (t.is_word("checker")) {
        next();
        if (peek_word("pigment")) {
            Token item = next();
            skip_unsupported(item, Arity::Rest, "checker of pigments");
            return;
        }
        p.kind = PigmentKind::Checker;
        // POV-Ray's default checker colours (Check_Default_Map): blue and green.
        p.checker[0] = Colour{glm::dvec3(0.0, 0.0, 1.0), 0.0, 0.0};
        p.checker[1] = Colour{glm::dvec3(0.0, 1.0, 0.0), 0.0, 0.0};
        for (int i = 0; i < 2 && starts_expression(peek(0)); ++i) {
            p.checker[i] = parse_colour(true);
            accept_comma();
        }
    } else if (t.is_word("gradient")) {
        next();
        Token at = peek(0);
        glm::dvec3 axis = parse_vector();
        if (glm::length(axis) == 0.0) fail(at, "gradient along a zero vector");
        // A pattern keeps the map it had; a checker's two colours become one (POV-Ray keeps
        // the blend map when the pattern changes).
        if (p.kind == PigmentKind::Checker) {
            p.colour_map = {ColourMapEntry{0.0, p.checker[0]}, ColourMapEntry{1.0, p.checker[1]}};
        }
        p.kind = PigmentKind::Gradient;
        p.gradient_axis = glm::normalize(axis);  // POV-Ray normalises it
    } else if (is_keyword(t) && is_other_pattern(t.text())) {
        Token item = next();
        skip_unsupported(item, Arity::Rest, "pigment pattern '" + item.text() + "'");
        return;
    }
    while (true) {
        const Token m = peek(0);
        if (m.is_punct("}")) break;
        Transform tr;
        if (parse_transform_item(tr)) {
            p.transform = compose_transforms(p.transform, tr);
            continue;
        }
        if (is_keyword(m)) {
            const std::string& w = m.text();
            if (w == "color_map" || w == "colour_map") {
                Token item = next();
                if (p.kind != PigmentKind::Gradient) {
                    // POV-Ray refuses it too; in lenient mode the pattern may have been skipped.
                    std::string what = p.kind == PigmentKind::Solid ? "plain colour" : "checker";
                    if (options_.strict && !opaque_capture_) {
                        fail(item, "color_map needs a pattern such as gradient (a " + what +
                                       " has none)");
                    }
                    skip_unsupported(item, Arity::Block, "color_map on a " + what);
                    continue;
                }
                p.colour_map = parse_colour_map(item);
                continue;
            }
            if (w == "quick_color" || w == "quick_colour") {
                next();
                parse_colour(true);  // only for quick previews
                continue;
            }
            if (const ItemArity* a = find_item(kUnsupportedPatternModifiers, w)) {
                Token item = next();
                skip_unsupported(item, a->arity, "pigment modifier '" + item.text() + "'");
                continue;
            }
        }
        reject_unknown_word(m);
        break;
    }
    (void)kw;
}

void SceneParser::parse_finish_block(Finish& f, const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0); v && std::holds_alternative<Finish>(v->data)) {
        f = identifier_as<Finish>(next(), "a finish");
    }
    bool diffuse_albedo = false, phong_albedo = false, specular_albedo = false;
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        if (!is_keyword(t)) {
            reject_unknown_word(t);
            break;
        }
        const std::string& w = t.text();
        if (w == "ambient") {
            next();
            f.ambient = parse_rgb_colour();
        } else if (w == "emission") {
            next();
            f.emission = parse_rgb_colour();
        } else if (w == "diffuse") {
            next();
            diffuse_albedo = accept_word("albedo");
            f.diffuse = parse_float();
            accept_comma();
            if (starts_expression(peek(0))) {
                Token at = peek(0);
                double back = parse_float();
                if (back != 0.0) unsupported(at, "finish item 'diffuse' with a back side value");
            }
        } else if (w == "brilliance") {
            next();
            f.brilliance = parse_float();
        } else if (w == "specular") {
            next();
            specular_albedo = accept_word("albedo");
            f.specular = parse_float();
        } else if (w == "roughness") {
            Token item = next();
            f.roughness = parse_float();
            if (f.roughness == 0.0) add_message(item, "warning", "zero roughness");
        } else if (w == "phong") {
            next();
            phong_albedo = accept_word("albedo");
            f.phong = parse_float();
        } else if (w == "phong_size") {
            next();
            f.phong_size = parse_float();
        } else if (w == "reflection") {
            Token item = next();
            if (peek_punct("{")) {
                // reflection { min [, max] [fresnel] [falloff] [exponent] [metallic] }
                Token open = next();
                glm::dvec3 min = parse_rgb_colour();
                accept_comma();
                glm::dvec3 max = min;
                if (starts_expression(peek(0))) max = parse_rgb_colour();
                while (!peek_punct("}") && !peek(0).is_eof()) {
                    const Token o = peek(0);
                    if (o.is_word("fresnel") || o.is_word("falloff") || o.is_word("exponent") ||
                        o.is_word("metallic")) {
                        Token option = next();
                        skip_unsupported(option,
                                         option.is_word("falloff") || option.is_word("exponent")
                                             ? Arity::Float
                                             : Arity::OptionalFloat,
                                         "reflection option '" + option.text() + "'");
                        continue;
                    }
                    fail(o, "expected '}' to close 'reflection' opened at " + place(item.loc(), o) +
                                ", got " + describe(o));
                }
                expect_punct("}", "to close 'reflection'");
                if (min != max) {
                    unsupported(open, "reflection with different minimum and maximum");
                }
                f.reflection = max;
            } else {
                f.reflection = parse_rgb_colour();
            }
        } else if (const ItemArity* a = find_item(kUnsupportedFinishItems, w)) {
            Token item = next();
            skip_unsupported(item, a->arity, "finish item '" + item.text() + "'");
        } else {
            break;
        }
    }
    expect_close_brace(kw);
    // The `albedo` forms rescale so that 1 reflects all the light (POV-Ray's Parse_Finish).
    if (diffuse_albedo) f.diffuse *= (f.brilliance + 1.0) / 2.0;
    if (phong_albedo) f.phong *= (f.phong_size + 1.0) / 2.0;
    if (specular_albedo) {
        double r = f.roughness != 0.0 ? 1.0 / f.roughness : 0.0;  // POV-Ray's inverted roughness
        f.specular *= (r + 2.0) / (4.0 * (2.0 - std::pow(2.0, -r / 2.0)));
    }
}

std::vector<ColourMapEntry> SceneParser::parse_colour_map(const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0);
        v && std::holds_alternative<ColourMapValue>(v->data)) {
        auto entries = identifier_as<ColourMapValue>(next(), "a color_map").entries;
        expect_close_brace(kw);
        return entries;
    }
    std::vector<ColourMapEntry> entries;
    while (peek_punct("[")) {
        Token open = next();
        if (entries.size() >= kMaxColourMapEntries) fail(open, "color_map with too many entries");
        ColourMapEntry entry;
        entry.position = parse_float();
        accept_comma();
        const Token t = peek(0);
        if (starts_colour(t)) {
            entry.colour = parse_colour(true);
            entries.push_back(entry);
        } else if (starts_float(t)) {
            Numeric n = parse_express();
            if (n.size == 1) {
                // The old form [start, end colour C1 colour C2].
                ColourMapEntry second;
                second.position = n.v[0];
                entry.colour = parse_colour(true);
                if (!accept_word("color") && !accept_word("colour")) {
                    fail(peek(0), "expected 'color' before the second colour of the entry, got " +
                                      describe(peek(0)));
                }
                second.colour = parse_colour(true);
                entries.push_back(entry);
                entries.push_back(second);
            } else if (n.size == 5) {
                entry.colour = numeric_to_colour(n);
                entries.push_back(entry);
            } else {
                fail(t, "expected a colour in the color_map entry, got a " +
                            numeric_type_name(n.size));
            }
        } else {
            fail(t, "expected a colour in the color_map entry, got " + describe(t));
        }
        const Token& close = peek(0);
        if (!close.is_punct("]")) {
            fail(close, "expected ']' to close the color_map entry opened at " +
                            place(open.loc(), close) + ", got " + describe(close));
        }
        next();
    }
    if (entries.empty())
        fail(peek(0), "a color_map needs at least one entry, got " + describe(peek(0)));
    expect_close_brace(kw);
    // POV-Ray drops an entry identical to the one before it.
    std::vector<ColourMapEntry> unique;
    for (const ColourMapEntry& e : entries) {
        if (unique.empty() || !same_entry(unique.back(), e)) unique.push_back(e);
    }
    return unique;
}

}  // namespace mirage::scene_detail
