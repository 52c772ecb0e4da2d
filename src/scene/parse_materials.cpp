// Textures, pigments, normals, finishes, interiors, materials, fogs, colour and blend maps
// and light source items, after POV-Ray 3.7's parstxtr.cpp (Parse_Pattern, Parse_Pigment,
// Parse_Tnormal, Parse_Finish, Parse_Texture, Parse_Interior, Parse_Material, Parse_Fog,
// Parse_Warp), express.cpp (Parse_Blend_Map, Parse_Blend_List, Parse_Colour_Map) and
// parse.cpp (Parse_Light_Source).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "scene/image_file.h"
#include "scene/material_ops.h"
#include "scene/scene_parser.h"
#include "scene/transform.h"
#include "util/format.h"

namespace mirage::scene_detail {

namespace {

constexpr std::size_t kMaxMapEntries = 256;  // POV-Ray's MAX_BLEND_MAP_ENTRIES
constexpr double kEpsilon = 1e-10;           // POV-Ray's EPSILON
constexpr double kPi = 3.1415926535897932384626;
// The range of an ior or a dispersion: the tracer keeps them in single precision, as POV-Ray
// does, and squares them.
constexpr double kMinIor = 1e-3, kMaxIor = 1e3;

bool one_of(const std::string& w, std::initializer_list<const char*> words) {
    for (const char* x : words) {
        if (w == x) return true;
    }
    return false;
}

bool same_entry(const ColourMapEntry& a, const ColourMapEntry& b) {
    return a.position == b.position && a.colour.rgb == b.colour.rgb &&
           a.colour.filter == b.colour.filter && a.colour.transmit == b.colour.transmit;
}

/// The list patterns: their entries are the list's items at 0, 1, 2... and POV-Ray sets
/// their frequency to 0 (no wave).
int list_pattern_count(PatternKind kind) {
    switch (kind) {
        case PatternKind::Checker:
        case PatternKind::Brick:
            return 2;
        case PatternKind::Hexagon:
            return 3;
        case PatternKind::Square:
            return 4;
        case PatternKind::Triangular:
        case PatternKind::Cubic:
            return 6;
        default:
            return 0;
    }
}

/// Patterns that take no map of their own (POV-Ray refuses color_map and the others on them).
bool refuses_maps(PatternKind kind) {
    return list_pattern_count(kind) > 0 || kind == PatternKind::Solid ||
           kind == PatternKind::ImageMap;
}

/// Pattern keywords outside the ones the tracer evaluates: refused with their name.
bool is_unsupported_pattern(const std::string& w) {
    return one_of(
        w, {"function", "pigment_pattern", "julia", "magnet", "object", "uv_mapping",
            "image_pattern", "density_file", "slope", "aoi", "pavement", "tiling", "facets"});
}

}  // namespace

/// Where a pattern's maps and lists go: the pigment's, normal's or texture's own fields.
struct SceneParser::PatternTargets {
    Colour* colour = nullptr;   // a pigment's plain colour
    Colour* checker = nullptr;  // a pigment's two checker colours
    std::vector<ColourMapEntry>* colour_map = nullptr;
    std::vector<PigmentMapEntry>* pigment_map = nullptr;
    std::vector<NormalMapEntry>* normal_map = nullptr;
    std::vector<SlopeMapEntry>* slope_map = nullptr;
    std::vector<TextureMapEntry>* texture_map = nullptr;
    double* amount = nullptr;  // a normal's bump size
    double* delta = nullptr;   // a normal's accuracy
    bool* no_bump_scale = nullptr;
};

// ---------------------------------------------------------------------------------------
// Patterns

/// slope { [point_at] vector [, lo, hi] [altitude vector [, lo, hi]] }, or slope vector.
void SceneParser::parse_slope_pattern(Pattern& p) {
    const Token tok = next();
    p.kind = PatternKind::Slope;
    p.altitude_vector = glm::dvec3(0.0);
    p.slope_mod = p.altitude_mod = glm::dvec2(0.0);
    p.slope_point_at = false;
    // POV-Ray keeps a range as its low end and width; an empty range is ignored.
    auto range = [&](glm::dvec2& mod) {
        accept_comma();
        mod.x = allow_float(0.0);
        accept_comma();
        mod.y = allow_float(0.0);
        if (mod.y != 0.0 && mod.y == mod.x) {
            mod = glm::dvec2(0.0);
        } else {
            mod.y -= mod.x;
        }
    };
    if (peek_punct("{")) {
        Token open = next();
        p.slope_point_at = accept_word("point_at");
        p.slope_vector = parse_vector();
        range(p.slope_mod);
        if (peek_word("altitude")) {
            Token a = next();
            if (p.slope_point_at) fail(a, "'altitude' cannot be used with 'point_at' in slope");
            p.altitude_vector = parse_vector();
            range(p.altitude_mod);
        }
        expect_punct("}", "to close 'slope'");
        (void)open;
    } else {
        p.slope_vector = parse_vector();
    }
    if (p.slope_point_at) {
        p.slope_len = 1.0;
        p.altitude_len = 0.0;
    } else {
        p.slope_len = glm::length(p.slope_vector);
        p.altitude_len = glm::length(p.altitude_vector);
        if (p.slope_len != 0.0) p.slope_vector /= p.slope_len;
        if (p.altitude_len != 0.0) p.altitude_vector /= p.altitude_len;
        // POV-Ray sums the lengths in single precision.
        const float total = static_cast<float>(p.slope_len + p.altitude_len);
        if (total == 0.0f) fail(tok, "zero length for both slope and altitude");
        p.slope_len /= total;
        p.altitude_len = 1.0 - p.slope_len;
    }
}

/// A pattern the tracer does not evaluate: refused in strict mode; in lenient mode skipped
/// with the rest of its block or map entry, a plain pattern in its place.
void SceneParser::skip_unsupported_pattern(Pattern& p) {
    Token kw = next();
    unsupported(kw, "pattern '" + kw.text() + "'");  // fails in strict mode
    // Lenient mode: the rest of the enclosing block or map entry goes with it.
    int depth = 0;
    while (true) {
        const Token& n = peek(0);
        if (n.is_eof()) fail(n, "expected '}', got end of file");
        if (depth == 0 && (n.is_punct("}") || n.is_punct("]"))) break;
        if (n.is_punct("{") || n.is_punct("[")) ++depth;
        if (n.is_punct("}") || n.is_punct("]")) --depth;
        next();
    }
    p.kind = PatternKind::Solid;
    skipped_pattern_ = true;
}

/// The patterns of a list of colours (checker, brick, hexagon...), with their list.
void SceneParser::parse_list_pattern(Pattern& p, PatternKind list, PatternUse use,
                                     PatternTargets& t) {
    next();
    if (list == PatternKind::Brick && p.kind != PatternKind::Brick) {
        p.brick_size = glm::dvec3(8.0, 3.0, 4.5);
        p.mortar = 0.5 - kEpsilon * 2.0;
    }
    p.kind = list;
    p.frequency = 0.0;
    if (use == PatternUse::Normal) *t.delta = 0.02;
    parse_blend_list(p, list_pattern_count(list), use, t);
}

bool SceneParser::parse_pattern_type(Pattern& p, PatternUse use, PatternTargets& t) {
    const Token tok = peek(0);
    if (use == PatternUse::Pigment && starts_colour(tok)) {
        p.kind = PatternKind::Solid;
        *t.colour = parse_colour(true);
        return true;
    }
    if (!is_keyword(tok)) return false;
    const std::string& w = tok.text();
    auto simple = [&](PatternKind kind, WaveType wave = WaveType::Ramp) {
        next();
        p.kind = kind;
        if (wave != WaveType::Ramp) p.wave = wave;
        return true;
    };
    if (w == "agate") {
        next();
        p.kind = PatternKind::Agate;
        // POV-Ray gives agate a classic turbulence for its octaves, lambda and omega.
        if (!p.turbulence) p.turbulence = Turbulence{};
        p.agate_turb = 1.0;
        return true;
    }
    if (w == "bozo") return simple(PatternKind::Bozo);
    if (w == "granite") return simple(PatternKind::Granite);
    if (w == "leopard") return simple(PatternKind::Leopard);
    if (w == "marble") return simple(PatternKind::Marble, WaveType::Triangle);
    if (w == "onion") return simple(PatternKind::Onion);
    if (w == "spotted") return simple(PatternKind::Spotted);
    if (w == "wood") return simple(PatternKind::Wood, WaveType::Triangle);
    if (w == "radial") return simple(PatternKind::Radial);
    if (w == "cells") return simple(PatternKind::Cells);
    if (w == "waves") return simple(PatternKind::Waves);
    if (w == "ripples") return simple(PatternKind::Ripples);
    if (w == "wrinkles") return simple(PatternKind::Wrinkles);
    if (w == "bumps") return simple(PatternKind::Bumps);
    if (w == "dents") return simple(PatternKind::Dents);
    if (w == "planar") return simple(PatternKind::Planar);
    if (w == "boxed") return simple(PatternKind::Boxed);
    if (w == "spherical") return simple(PatternKind::Spherical);
    if (w == "cylindrical") return simple(PatternKind::Cylindrical);
    if (w == "average") return simple(PatternKind::Average);
    if (w == "mandel") {
        next();
        p.kind = PatternKind::Mandel;
        p.iterations = static_cast<int>(parse_float());
        p.interior_type = 0;
        p.exterior_type = 1;
        p.interior_factor = 1.0;
        p.exterior_factor = 1.0;
        p.fractal_exponent = 2;
        return true;
    }
    if (w == "spiral1" || w == "spiral2") {
        next();
        p.kind = w == "spiral1" ? PatternKind::Spiral1 : PatternKind::Spiral2;
        p.arms = static_cast<short>(parse_float());
        p.wave = WaveType::Triangle;
        return true;
    }
    if (w == "gradient") {
        next();
        Token at = peek(0);
        glm::dvec3 axis = parse_vector();
        if (glm::length(axis) == 0.0) fail(at, "gradient along a zero vector");
        // A checker's two colours become the map (POV-Ray keeps the blend map when the
        // pattern changes).
        if (p.kind == PatternKind::Checker && t.checker && t.colour_map && t.colour_map->empty()) {
            *t.colour_map = {ColourMapEntry{0.0, t.checker[0]}, ColourMapEntry{1.0, t.checker[1]}};
        }
        p.kind = PatternKind::Gradient;
        p.gradient_axis = glm::normalize(axis);
        return true;
    }
    if (w == "crackle") {
        next();
        p.kind = PatternKind::Crackle;
        p.crackle_solid = false;
        p.crackle_form = glm::dvec3(-1.0, 1.0, 0.0);
        p.crackle_metric = 2.0;
        p.crackle_offset = 0.0;
        return true;
    }
    if (w == "quilted") {
        next();
        p.kind = PatternKind::Quilted;
        p.control0 = 1.0;
        p.control1 = 1.0;
        p.frequency = 0.0;
        return true;
    }
    PatternKind list = w == "checker"      ? PatternKind::Checker
                       : w == "brick"      ? PatternKind::Brick
                       : w == "hexagon"    ? PatternKind::Hexagon
                       : w == "square"     ? PatternKind::Square
                       : w == "triangular" ? PatternKind::Triangular
                       : w == "cubic"      ? PatternKind::Cubic
                                           : PatternKind::Solid;
    if (list != PatternKind::Solid) {
        parse_list_pattern(p, list, use, t);
        return true;
    }
    if (w == "image_map" || w == "bump_map") {
        Token kw = next();
        if ((w == "image_map") != (use == PatternUse::Pigment)) {
            fail(kw, "'" + w + "' belongs in a " + (w == "image_map" ? "pigment" : "normal"));
        }
        p.kind = PatternKind::ImageMap;
        p.frequency = 0.0;
        parse_image_map(p, use, kw, t.amount);
        return true;
    }
    if (w == "pigment_pattern") {
        Token item = next();
        p.kind = PatternKind::PigmentPattern;
        auto inner = std::make_shared<Pigment>();
        expect_open_brace(item);
        parse_pigment_body(*inner, item);
        expect_close_brace(item);
        finish_pigment(*inner);
        p.pattern_pigment = inner;
        return true;
    }
    if (w == "slope") {
        parse_slope_pattern(p);
        return true;
    }
    if (is_unsupported_pattern(w)) {
        skip_unsupported_pattern(p);
        return true;
    }
    return false;
}

void SceneParser::parse_blend_list(Pattern& p, int count, PatternUse use, PatternTargets& t) {
    // POV-Ray's Parse_Blend_List: up to `count` colours (or pigments, normals, textures), the
    // rest from the pattern's default list.
    if (use == PatternUse::Pigment) {
        t.pigment_map->clear();
        t.colour_map->clear();
        if (peek_word("pigment")) {
            for (int i = 0; i < count && peek_word("pigment"); ++i) {
                Token kw = next();
                auto entry = std::make_shared<Pigment>(default_texture_.pigment);
                expect_open_brace(kw);
                parse_pigment_body(*entry, kw);
                expect_close_brace(kw);
                finish_pigment(*entry);
                t.pigment_map->push_back(PigmentMapEntry{static_cast<double>(i), entry});
                accept_comma();
            }
            while (static_cast<int>(t.pigment_map->size()) < count) {
                auto entry = std::make_shared<Pigment>(default_texture_.pigment);
                t.pigment_map->push_back(
                    PigmentMapEntry{static_cast<double>(t.pigment_map->size()), entry});
            }
            return;
        }
        const std::vector<ColourMapEntry>& defaults = default_colour_map(p.kind);
        std::vector<Colour> colours;
        while (static_cast<int>(colours.size()) < count && starts_expression(peek(0))) {
            colours.push_back(parse_colour(true));
            accept_comma();
        }
        for (int i = static_cast<int>(colours.size()); i < count; ++i) {
            colours.push_back(defaults[i].colour);
        }
        if (p.kind == PatternKind::Checker) {
            t.checker[0] = colours[0];
            t.checker[1] = colours[1];
            return;
        }
        for (int i = 0; i < count; ++i) {
            t.colour_map->push_back(ColourMapEntry{static_cast<double>(i), colours[i]});
        }
        return;
    }
    if (use == PatternUse::Normal) {
        t.normal_map->clear();
        int i = 0;
        for (; i < count && peek_word("normal"); ++i) {
            Token kw = next();
            auto entry = std::make_shared<Normal>(default_texture_.normal ? *default_texture_.normal
                                                                          : Normal{});
            expect_open_brace(kw);
            parse_normal_body(*entry, kw);
            expect_close_brace(kw);
            t.normal_map->push_back(NormalMapEntry{static_cast<double>(i), entry});
            accept_comma();
        }
        if (i == 0) return;  // the pattern's own values are the bumps
        for (; i < count; ++i) {
            auto entry = std::make_shared<Normal>(default_texture_.normal ? *default_texture_.normal
                                                                          : Normal{});
            t.normal_map->push_back(NormalMapEntry{static_cast<double>(i), entry});
        }
        return;
    }
    t.texture_map->clear();
    int i = 0;
    for (; i < count && peek_word("texture"); ++i) {
        Token kw = next();
        expect_open_brace(kw);
        auto entry = std::make_shared<Texture>(parse_texture_body(kw));
        expect_close_brace(kw);
        t.texture_map->push_back(TextureMapEntry{static_cast<double>(i), entry});
        accept_comma();
    }
    for (; i < count; ++i) {
        t.texture_map->push_back(
            TextureMapEntry{static_cast<double>(i), std::make_shared<Texture>(default_texture_)});
    }
}

/// A modifier of one kind of pattern (brick_size, mortar, form, exterior...) or of normals
/// (accuracy, bump_size, no_bump_scale) at the next token: parses it and returns true, or
/// returns false.
bool SceneParser::parse_pattern_kind_modifier(Pattern& p, PatternUse use, PatternTargets& t) {
    const Token m = peek(0);
    const std::string& w = m.text();
    auto only = [&](const Token& item, bool allowed, const std::string& where) {
        if (!allowed) fail(item, "'" + item.text() + "' can only be used with " + where);
    };
    if (w == "agate_turb") {
        Token item = next();
        only(item, p.kind == PatternKind::Agate, "agate");
        p.agate_turb = parse_float();
        if (!p.turbulence) p.turbulence = Turbulence{};
    } else if (w == "brick_size") {
        Token item = next();
        only(item, p.kind == PatternKind::Brick, "brick");
        p.brick_size = parse_vector();
    } else if (w == "mortar") {
        Token item = next();
        only(item, p.kind == PatternKind::Brick, "brick");
        p.mortar = parse_float() - kEpsilon * 2.0;
    } else if (w == "control0" || w == "control1") {
        Token item = next();
        only(item, p.kind == PatternKind::Quilted, "quilted");
        (w == "control0" ? p.control0 : p.control1) = parse_float();
    } else if (w == "metric") {
        Token item = next();
        only(item, p.kind == PatternKind::Crackle, "crackle");
        p.crackle_metric = parse_vector().x;
    } else if (w == "form") {
        Token item = next();
        only(item, p.kind == PatternKind::Crackle, "crackle");
        p.crackle_form = parse_vector();
    } else if (w == "offset") {
        Token item = next();
        only(item, p.kind == PatternKind::Crackle, "crackle");
        p.crackle_offset = parse_float();
    } else if (w == "solid") {
        Token item = next();
        only(item, p.kind == PatternKind::Crackle, "crackle");
        p.crackle_solid = true;
    } else if (w == "exterior" || w == "interior") {
        Token item = next();
        only(item, p.kind == PatternKind::Mandel, "mandel");
        Token at = peek(0);
        const int type = static_cast<int>(parse_float());
        const int limit = w == "exterior" ? 8 : 6;
        if (type < 0 || type > limit) {
            fail(at, "the fractal pattern's " + w + " type must be 0 to " + std::to_string(limit) +
                         ", got " + std::to_string(type));
        }
        accept_comma();
        const double factor = parse_float();
        if (w == "exterior") {
            p.exterior_type = type;
            p.exterior_factor = factor;
        } else {
            p.interior_type = type;
            p.interior_factor = factor;
        }
    } else if (w == "exponent") {
        Token item = next();
        only(item, p.kind == PatternKind::Mandel, "mandel");
        Token at = peek(0);
        p.fractal_exponent = static_cast<int>(parse_float());
        if (p.fractal_exponent != 2) {
            unsupported(at, "mandel exponent " + std::to_string(p.fractal_exponent) + " (only 2)");
            p.fractal_exponent = 2;
        }
    } else if (w == "accuracy") {
        Token item = next();
        only(item, use == PatternUse::Normal, "normals");
        *t.delta = parse_float();
    } else if (w == "bump_size") {
        Token item = next();
        only(item, use == PatternUse::Normal, "normals");
        *t.amount = parse_float();
    } else if (w == "no_bump_scale") {
        next();
        if (t.no_bump_scale) *t.no_bump_scale = true;
    } else {
        return false;
    }
    return true;
}

/// A map of the pattern's values (color_map, pigment_map, normal_map, slope_map,
/// texture_map) or quick_color at the next token: parses it and returns true, or returns false.
bool SceneParser::parse_pattern_map(Pattern& p, PatternUse use, PatternTargets& t) {
    const Token m = peek(0);
    const std::string& w = m.text();
    if (w == "color_map" || w == "colour_map") {
        Token item = next();
        if (use != PatternUse::Pigment) fail(item, "color_map can only be used in a pigment");
        if (refuses_maps(p.kind)) {
            // POV-Ray refuses it too; in lenient mode the pattern may have been skipped,
            // and in a declaration the pigment may stand in for an opaque one (the
            // declaration is then opaque already).
            const std::string what = p.kind == PatternKind::Solid ? "plain colour" : "checker";
            const bool stand_in = opaque_capture_ && opaque_capture_->captured;
            if ((options_.strict && !stand_in) || p.kind != PatternKind::Solid) {
                fail(item,
                     p.kind == PatternKind::Solid
                         ? "color_map needs a pattern such as gradient (a " + what + " has none)"
                         : "cannot use color_map with this pattern type");
            }
            skip_unsupported(item, Arity::Block, "color_map on a " + what);
            return true;
        }
        *t.colour_map = parse_colour_map(item);
        t.pigment_map->clear();
    } else if (w == "pigment_map") {
        Token item = next();
        if (use != PatternUse::Pigment) fail(item, "pigment_map can only be used in a pigment");
        if (refuses_maps(p.kind)) fail(item, "cannot use pigment_map with this pattern type");
        *t.pigment_map = parse_pigment_map(item);
        t.colour_map->clear();
    } else if (w == "normal_map") {
        Token item = next();
        if (use != PatternUse::Normal) fail(item, "normal_map can only be used in a normal");
        if (refuses_maps(p.kind)) fail(item, "cannot use normal_map with this pattern type");
        *t.normal_map = parse_normal_map(item);
    } else if (w == "slope_map") {
        Token item = next();
        if (use != PatternUse::Normal) fail(item, "slope_map can only be used in a normal");
        if (refuses_maps(p.kind)) fail(item, "cannot use slope_map with this pattern type");
        *t.slope_map = parse_slope_map(item);
    } else if (w == "texture_map") {
        Token item = next();
        if (use != PatternUse::Texture) fail(item, "texture_map can only be used in a texture");
        if (refuses_maps(p.kind)) fail(item, "cannot use texture_map with this pattern type");
        *t.texture_map = parse_texture_map(item);
    } else if (w == "quick_color" || w == "quick_colour") {
        next();
        parse_colour(true);  // only for quick previews
    } else {
        return false;
    }
    return true;
}

void SceneParser::parse_pattern(Pattern& p, PatternUse use, PatternTargets& t, const Token& kw) {
    skipped_pattern_ = false;
    parse_pattern_type(p, use, t);
    if (skipped_pattern_) return;
    if (use == PatternUse::Normal) {
        // normal { pattern [,] bump_size }
        accept_comma();
        *t.amount = allow_float(*t.amount);
    }
    auto turbulence = [&]() -> Turbulence& {
        if (!p.turbulence) p.turbulence = Turbulence{};
        return *p.turbulence;
    };
    while (true) {
        const Token m = peek(0);
        if (m.is_punct("}") || m.is_punct("]")) break;
        Transform tr;
        if (parse_transform_item(tr)) {
            transform_pattern(p, tr);
            continue;
        }
        if (!is_keyword(m)) break;
        const std::string& w = m.text();
        if (w == "turbulence") {
            next();
            turbulence().amount = parse_vector();
        } else if (w == "octaves") {
            next();
            turbulence().octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
        } else if (w == "omega") {
            next();
            turbulence().omega = parse_float();
        } else if (w == "lambda") {
            next();
            turbulence().lambda = parse_float();
        } else if (w == "frequency") {
            next();
            p.frequency = parse_float();
        } else if (w == "phase") {
            next();
            p.phase = parse_float();
        } else if (w == "ramp_wave" || w == "triangle_wave" || w == "sine_wave" ||
                   w == "scallop_wave" || w == "cubic_wave") {
            next();
            p.wave = w == "ramp_wave"       ? WaveType::Ramp
                     : w == "triangle_wave" ? WaveType::Triangle
                     : w == "sine_wave"     ? WaveType::Sine
                     : w == "scallop_wave"  ? WaveType::Scallop
                                            : WaveType::Cubic;
        } else if (w == "poly_wave") {
            next();
            p.wave = WaveType::Poly;
            p.exponent = allow_float(p.exponent);
        } else if (w == "noise_generator") {
            Token item = next();
            Token at = peek(0);
            const int g = static_cast<int>(parse_float());
            if (g < 0 || g > 3)
                fail(at, "noise_generator must be 0, 1, 2 or 3, got " + std::to_string(g));
            p.noise_generator = g;
            (void)item;
        } else if (w == "warp") {
            Token item = next();
            parse_warp(p, item);
        } else if (!parse_pattern_kind_modifier(p, use, t) && !parse_pattern_map(p, use, t)) {
            break;
        }
    }
    if (p.kind == PatternKind::Average) {
        const bool has_map = use == PatternUse::Pigment  ? !t.pigment_map->empty()
                             : use == PatternUse::Normal ? !t.normal_map->empty()
                                                         : !t.texture_map->empty();
        if (!has_map) fail(kw, "average needs a map");
    }
}

void SceneParser::parse_warp(Pattern& p, const Token& kw) {
    expect_open_brace(kw);
    Warp w;
    const Token t = next();
    if (t.is_word("turbulence")) {
        w.kind = Warp::Kind::Turbulence;
        w.turbulence.amount = parse_vector();
        while (true) {
            if (accept_word("octaves")) {
                w.turbulence.octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
            } else if (accept_word("omega")) {
                w.turbulence.omega = parse_float();
            } else if (accept_word("lambda")) {
                w.turbulence.lambda = parse_float();
            } else {
                break;
            }
        }
    } else if (t.is_word("repeat")) {
        w.kind = Warp::Kind::Repeat;
        Token at = peek(0);
        const glm::dvec3 v = parse_vector();
        int axes = 0;
        for (int i = 0; i < 3; ++i) {
            if (v[i] != 0.0) {
                w.axis = i;
                ++axes;
            }
        }
        if (axes == 0) fail(at, "no axis given in repeat");
        if (axes > 1) fail(at, "repeat goes along one axis only");
        w.width = v[w.axis];
        while (true) {
            if (accept_word("offset")) {
                w.offset = parse_vector();
            } else if (accept_word("flip")) {
                const glm::dvec3 f = parse_vector();
                for (int i = 0; i < 3; ++i) w.flip[i] = f[i] != 0.0 ? -1.0 : 1.0;
            } else {
                break;
            }
        }
    } else if (t.is_word("black_hole")) {
        w.kind = Warp::Kind::BlackHole;
        w.centre = parse_vector();
        accept_comma();
        w.radius = parse_float();
        while (true) {
            if (accept_word("strength")) {
                w.strength = parse_float();
            } else if (accept_word("falloff")) {
                w.power = parse_float();
            } else if (accept_word("inverse")) {
                w.inverse = true;
            } else if (peek_word("type")) {
                Token at = next();
                if (parse_float() != 0.0) unsupported(at, "black_hole type other than 0");
            } else if (accept_word("repeat")) {
                w.repeat_vector = parse_vector();
                w.repeat = true;
            } else if (accept_word("turbulence")) {
                w.uncertainty = parse_vector();
                w.uncertain = true;
            } else {
                break;
            }
        }
        if (w.repeat) {
            // POV-Ray's Check_BH_Parameters.
            for (int i = 0; i < 3; ++i) {
                if (w.repeat_vector[i] > 0.0) {
                    if (w.centre[i] < w.radius) w.centre[i] = w.radius;
                    const double least = w.centre[i] + w.radius + w.uncertainty[i];
                    if (w.repeat_vector[i] < least) w.repeat_vector[i] = least;
                    if (w.repeat_vector[i] < kEpsilon) w.repeat_vector[i] = 0.0;
                }
            }
        }
    } else if (t.is_word("cylindrical") || t.is_word("spherical") || t.is_word("toroidal")) {
        w.kind = t.is_word("cylindrical") ? Warp::Kind::Cylindrical
                 : t.is_word("spherical") ? Warp::Kind::Spherical
                                          : Warp::Kind::Toroidal;
        while (true) {
            if (accept_word("orientation")) {
                w.orientation = glm::normalize(parse_vector());
            } else if (accept_word("dist_exp")) {
                w.dist_exp = parse_float();
            } else if (w.kind == Warp::Kind::Toroidal && accept_word("major_radius")) {
                w.major_radius = parse_float();
            } else {
                break;
            }
        }
    } else if (t.is_word("planar")) {
        w.kind = Warp::Kind::Planar;
        if (starts_vector(peek(0))) {
            w.orientation = glm::normalize(parse_vector());
            accept_comma();
            w.planar_offset = parse_float();
        }
    } else if (t.is_word("cubic")) {
        w.kind = Warp::Kind::Cubic;
    } else {
        fail(t,
             "expected a warp type (turbulence, repeat, black_hole, cylindrical, spherical, "
             "toroidal, planar, cubic), got " +
                 describe(t));
    }
    expect_close_brace(kw);
    // POV-Ray puts the new warp first in the chain: the transforms given so far come after it.
    if (p.transform.matrix != glm::dmat4(1.0)) {
        Warp tw;
        tw.kind = Warp::Kind::Transform;
        tw.transform = p.transform;
        p.warps.insert(p.warps.begin(), tw);
        p.transform = Transform{};
    }
    p.warps.insert(p.warps.begin(), w);
}

void SceneParser::parse_image_map(Pattern& p, PatternUse use, const Token& kw, double* amount) {
    expect_open_brace(kw);
    // An old orientation vector is ignored, as POV-Ray ignores it.
    if (starts_vector(peek(0))) parse_vector();
    static const char* const kTypes[] = {"gif",  "tga",  "iff", "ppm", "pgm", "png",
                                         "jpeg", "tiff", "bmp", "exr", "hdr", "sys"};
    Token type_token = peek(0);
    for (const char* type : kTypes) {
        if (type_token.is_word(type)) {
            next();
            break;
        }
    }
    if (peek_word("function")) {
        Token f = next();
        fail(f, "unsupported image_map from a function");
    }
    Token name_at = peek(0);
    if (!starts_string(name_at))
        fail(name_at, "expected the image file name, got " + describe(name_at));
    const std::string name = parse_string(true);
    std::optional<double> gamma;
    while (true) {
        if (accept_word("gamma")) {
            gamma = parse_float();
        } else if (accept_word("premultiplied")) {
            parse_float();
        } else {
            break;
        }
    }
    // Found beside the scene, then on the library paths (POV-Ray's Locate_File).
    const std::string found = find_scene_file(name);
    if (found.empty()) fail(name_at, "cannot find image file '" + name + "'");
    auto image = read_image_rgba(found);
    if (!image) fail(name_at, image.message());
    // An input: no output may replace it.
    if (std::find(scene_.files.begin(), scene_.files.end(), found) == scene_.files.end()) {
        scene_.files.push_back(found);
    }
    // POV-Ray 3.7 decodes an image from its gamma (the file's own, else sRGB; for a #version
    // 3.6 scene with assumed_gamma, that gamma) into the working gamma (assumed_gamma).  A
    // #version 3.6 scene without assumed_gamma uses the values as stored, and so do bump
    // maps, unless `gamma` is given.
    auto data = std::make_shared<ImageData>();
    data->width = image->width;
    data->height = image->height;
    data->file = found;
    data->has_alpha = image->has_alpha;
    data->pixels.resize(static_cast<std::size_t>(image->width) * image->height * 5);
    const bool legacy = language_version_ < 3.7 - 1e-9;
    const bool gamma_none = legacy && !gamma_set_;
    const double working = gamma_set_ ? assumed_gamma_ : 1.0;
    bool correct = use == PatternUse::Pigment && !gamma_none;
    double decode_gamma = image->file_gamma;  // 0: sRGB
    if (correct && legacy && image->file_gamma == 0.0) decode_gamma = working;
    if (gamma) {
        correct = true;
        decode_gamma = *gamma;
    }
    auto decode = [&](double v) {
        if (!correct) return v;
        v = decode_gamma > 0.0 ? std::pow(v, decode_gamma)
            : v <= 0.04045     ? v / 12.92
                               : std::pow((v + 0.055) / 1.055, 2.4);
        return use == PatternUse::Pigment ? std::pow(v, 1.0 / working) : v;
    };
    for (std::size_t i = 0; i < static_cast<std::size_t>(image->width) * image->height; ++i) {
        for (int c = 0; c < 3; ++c) {
            data->pixels[i * 5 + c] = static_cast<float>(decode(image->pixels[i * 4 + c]));
        }
        data->pixels[i * 5 + 3] = 0.0f;
        data->pixels[i * 5 + 4] = image->has_alpha ? 1.0f - image->pixels[i * 4 + 3] : 0.0f;
    }
    p.image = data;
    while (true) {
        const Token m = peek(0);
        if (m.is_punct("}")) break;
        if (accept_word("once")) {
            p.once = true;
        } else if (accept_word("interpolate")) {
            Token at = peek(0);
            p.interpolate = static_cast<int>(parse_float());
            // POV-Ray checks the values only for image maps.
            if (use == PatternUse::Pigment && p.interpolate != 2 && p.interpolate != 3 &&
                p.interpolate != 4) {
                fail(at, "interpolate must be 2, 3 or 4, got " + std::to_string(p.interpolate));
            }
        } else if (use == PatternUse::Normal && accept_word("bump_size")) {
            *amount = parse_float();
        } else if (accept_word("map_type")) {
            Token at = peek(0);
            p.map_type = static_cast<int>(parse_float());
            if (p.map_type != 0 && p.map_type != 1 && p.map_type != 2 && p.map_type != 5) {
                fail(at, "map_type must be 0, 1, 2 or 5, got " + std::to_string(p.map_type));
            }
        } else if (accept_word("use_color") || accept_word("use_colour")) {
            p.use_index = false;
        } else if (accept_word("use_index")) {
            p.use_index = true;
        } else if (accept_word("repeat")) {
            Token at = peek(0);
            const Numeric r = parse_vector_n(2, "a 2-component vector");
            if (r.v[0] <= 0.0 || r.v[1] <= 0.0) fail(at, "image repeat must be positive");
            p.image_repeat = glm::dvec2(r.v[0], r.v[1]);
        } else if (accept_word("offset")) {
            const Numeric o = parse_vector_n(2, "a 2-component vector");
            p.image_offset = glm::dvec2(o.v[0], o.v[1]);
        } else if (peek_word("filter") || peek_word("transmit") || peek_word("alpha")) {
            Token item = next();
            const bool filter = !item.is_word("transmit");
            if (accept_word("all")) {
                (filter ? p.filter_all : p.transmit_all) = parse_float();
            } else {
                fail(item, "unsupported per-palette-index " + item.text() + " (only '" +
                               item.text() + " all')");
            }
        } else {
            reject_unknown_word(m);
            break;
        }
    }
    expect_close_brace(kw);
}

// ---------------------------------------------------------------------------------------
// Maps

std::vector<ColourMapEntry> SceneParser::parse_colour_map(const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0); v && v->holds<ColourMapValue>()) {
        auto entries = identifier_as<ColourMapValue>(next(), "a color_map").entries;
        expect_close_brace(kw);
        return entries;
    }
    std::vector<ColourMapEntry> entries;
    while (peek_punct("[")) {
        Token open = next();
        if (entries.size() >= kMaxMapEntries) fail(open, "color_map with too many entries");
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

std::vector<PigmentMapEntry> SceneParser::parse_pigment_map(const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0); v && v->holds<MaterialValue>()) {
        auto m = identifier_as<MaterialValue>(next(), "a pigment_map");
        if (m.kind != MaterialValue::Kind::PigmentMap)
            fail(kw, "expected a pigment_map identifier");
        expect_close_brace(kw);
        return m.pigment_map;
    }
    std::vector<PigmentMapEntry> entries;
    while (peek_punct("[")) {
        Token open = next();
        if (entries.size() >= kMaxMapEntries) fail(open, "pigment_map with too many entries");
        PigmentMapEntry e;
        e.position = parse_float();
        accept_comma();
        auto pigment = std::make_shared<Pigment>(default_texture_.pigment);
        parse_pigment_body(*pigment, open);
        finish_pigment(*pigment);
        e.pigment = pigment;
        entries.push_back(e);
        expect_punct("]", "to close the pigment_map entry");
    }
    if (entries.empty())
        fail(peek(0), "a pigment_map needs at least one entry, got " + describe(peek(0)));
    expect_close_brace(kw);
    return entries;
}

std::vector<NormalMapEntry> SceneParser::parse_normal_map(const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0); v && v->holds<MaterialValue>()) {
        auto m = identifier_as<MaterialValue>(next(), "a normal_map");
        if (m.kind != MaterialValue::Kind::NormalMap) fail(kw, "expected a normal_map identifier");
        expect_close_brace(kw);
        return m.normal_map;
    }
    std::vector<NormalMapEntry> entries;
    while (peek_punct("[")) {
        Token open = next();
        if (entries.size() >= kMaxMapEntries) fail(open, "normal_map with too many entries");
        NormalMapEntry e;
        e.position = parse_float();
        accept_comma();
        auto normal =
            std::make_shared<Normal>(default_texture_.normal ? *default_texture_.normal : Normal{});
        parse_normal_body(*normal, open);
        e.normal = normal;
        entries.push_back(e);
        expect_punct("]", "to close the normal_map entry");
    }
    if (entries.empty())
        fail(peek(0), "a normal_map needs at least one entry, got " + describe(peek(0)));
    expect_close_brace(kw);
    return entries;
}

std::vector<TextureMapEntry> SceneParser::parse_texture_map(const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0); v && v->holds<MaterialValue>()) {
        auto m = identifier_as<MaterialValue>(next(), "a texture_map");
        if (m.kind != MaterialValue::Kind::TextureMap)
            fail(kw, "expected a texture_map identifier");
        expect_close_brace(kw);
        return m.texture_map;
    }
    std::vector<TextureMapEntry> entries;
    while (peek_punct("[")) {
        Token open = next();
        if (entries.size() >= kMaxMapEntries) fail(open, "texture_map with too many entries");
        TextureMapEntry e;
        e.position = parse_float();
        accept_comma();
        Texture t = parse_texture_body(open);
        finish_pigment(t.pigment);
        e.texture = std::make_shared<Texture>(std::move(t));
        entries.push_back(e);
        expect_punct("]", "to close the texture_map entry");
    }
    if (entries.empty())
        fail(peek(0), "a texture_map needs at least one entry, got " + describe(peek(0)));
    expect_close_brace(kw);
    return entries;
}

std::vector<SlopeMapEntry> SceneParser::parse_slope_map(const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0); v && v->holds<MaterialValue>()) {
        auto m = identifier_as<MaterialValue>(next(), "a slope_map");
        if (m.kind != MaterialValue::Kind::SlopeMap) fail(kw, "expected a slope_map identifier");
        expect_close_brace(kw);
        return m.slope_map;
    }
    std::vector<SlopeMapEntry> entries;
    while (peek_punct("[")) {
        Token open = next();
        if (entries.size() >= kMaxMapEntries) fail(open, "slope_map with too many entries");
        SlopeMapEntry e;
        e.position = parse_float();
        accept_comma();
        const Numeric uv = parse_vector_n(2, "a 2-component vector");
        e.point_slope = glm::dvec2(uv.v[0], uv.v[1]);
        entries.push_back(e);
        expect_punct("]", "to close the slope_map entry");
    }
    if (entries.empty())
        fail(peek(0), "a slope_map needs at least one entry, got " + describe(peek(0)));
    expect_close_brace(kw);
    return entries;
}

// ---------------------------------------------------------------------------------------
// Pigments, normals, textures

// POV-Ray's Parse_Pigment: an optional identifier, then the pattern (or a colour), then the
// modifiers; it changes the pigment it is given, keeping what is not mentioned.
void SceneParser::parse_pigment_body(Pigment& p, const Token& kw) {
    if (const Value* v = peek_identifier_value(0); v && v->holds<Pigment>()) {
        p = identifier_as<Pigment>(next(), "a pigment");
    }
    PatternTargets t;
    t.colour = &p.colour;
    t.checker = p.checker;
    t.colour_map = &p.colour_map;
    t.pigment_map = &p.pigment_map;
    parse_pattern(p, PatternUse::Pigment, t, kw);
    if (p.kind == PatternKind::Solid) {
        // A plain colour has no warps (Post_Pigment destroys them).
        p.warps.clear();
        p.turbulence.reset();
    }
}

// POV-Ray's Parse_Tnormal.
void SceneParser::parse_normal_body(Normal& n, const Token& kw) {
    if (const Value* v = peek_identifier_value(0);
        v && v->holds<MaterialValue>() &&
        v->get<MaterialValue>().kind == MaterialValue::Kind::Normal) {
        n = identifier_as<MaterialValue>(next(), "a normal").normal;
    }
    PatternTargets t;
    t.normal_map = &n.normal_map;
    t.slope_map = &n.slope_map;
    t.amount = &n.amount;
    t.delta = &n.delta;
    t.no_bump_scale = &n.no_bump_scale;
    parse_pattern(n, PatternUse::Normal, t, kw);
}

void SceneParser::layer_texture(Texture& texture, Texture top, const Token& at) {
    const std::string error = link_textures(texture, std::move(top));
    if (!error.empty()) fail(at, error);
}

void SceneParser::set_texture(ObjectNode& node, Texture texture, const Token& at) {
    if (!node.texture) {
        node.texture = std::move(texture);
        return;
    }
    layer_texture(*node.texture, std::move(texture), at);
}

Texture SceneParser::parse_texture_body(const Token& kw) {
    Texture tex = default_texture_;
    bool modified = false;
    if (const Value* v = peek_identifier_value(0); v && v->holds<Texture>()) {
        tex = identifier_as<Texture>(next(), "a texture");
        modified = true;
    }
    auto transform_item = [&]() {
        Transform tr;
        if (!parse_transform_item(tr)) return false;
        transform_texture(tex, tr);
        return true;
    };
    if (tex.pattern.kind != PatternKind::Solid) {
        // A patterned texture identifier takes transforms only (Parse_Texture_Transform).
        while (true) {
            if (transform_item()) continue;
            if (accept_word("no_bump_scale")) {
                tex.no_bump_scale = true;
                continue;
            }
            break;
        }
        return tex;
    }
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}") || t.is_punct("]")) break;
        // A pigment, normal or finish identifier alone stands for pigment { Ident }.
        if (const Value* v = peek_identifier_value(0)) {
            if (v->holds<Pigment>()) {
                tex.pigment = identifier_as<Pigment>(next(), "a pigment");
                modified = true;
                continue;
            }
            if (v->holds<Finish>()) {
                tex.finish = identifier_as<Finish>(next(), "a finish");
                modified = true;
                continue;
            }
            if (const auto* m = v->get_if<MaterialValue>();
                m && m->kind == MaterialValue::Kind::Normal) {
                tex.normal = identifier_as<MaterialValue>(next(), "a normal").normal;
                modified = true;
                continue;
            }
        }
        if (transform_item()) {
            modified = true;
            continue;
        }
        if (!is_keyword(t)) break;
        const std::string& w = t.text();
        if (w == "pigment") {
            Token item = next();
            expect_open_brace(item);
            parse_pigment_body(tex.pigment, item);
            expect_close_brace(item);
            modified = true;
            continue;
        }
        if (w == "normal") {
            Token item = next();
            if (!tex.normal) tex.normal = Normal{};
            expect_open_brace(item);
            parse_normal_body(*tex.normal, item);
            expect_close_brace(item);
            modified = true;
            continue;
        }
        if (w == "finish") {
            Token item = next();
            parse_finish_block(tex.finish, item);
            modified = true;
            continue;
        }
        if (w == "no_bump_scale") {
            next();
            tex.no_bump_scale = true;
            if (tex.normal) tex.normal->no_bump_scale = true;
            continue;
        }
        if (modified) break;
        if (w == "tiles") {
            // tiles { texture {...} tile2 texture {...} }: a checker, the first tile at 1.
            Token item = next();
            expect_open_brace(item);
            Texture first, second;
            bool has_first = false, has_second = false;
            while (peek_word("texture")) {
                Token tk = next();
                expect_open_brace(tk);
                Texture layer = parse_texture_body(tk);
                expect_close_brace(tk);
                if (has_first) {
                    layer_texture(first, std::move(layer), tk);
                } else {
                    first = std::move(layer);
                    has_first = true;
                }
            }
            if (!has_first) fail(peek(0), "the first texture is missing from tiles");
            Token tile2 = peek(0);
            if (!accept_word("tile2"))
                fail(tile2, "expected 'tile2' in tiles, got " + describe(tile2));
            while (peek_word("texture")) {
                Token tk = next();
                expect_open_brace(tk);
                Texture layer = parse_texture_body(tk);
                expect_close_brace(tk);
                if (has_second) {
                    layer_texture(second, std::move(layer), tk);
                } else {
                    second = std::move(layer);
                    has_second = true;
                }
            }
            expect_close_brace(item);
            Texture tiles;
            tiles.pattern.kind = PatternKind::Checker;
            tiles.pattern.frequency = 0.0;
            tiles.map = {TextureMapEntry{0.0, std::make_shared<Texture>(
                                                  has_second ? second : default_texture_)},
                         TextureMapEntry{1.0, std::make_shared<Texture>(first)}};
            tex = std::move(tiles);
            while (transform_item()) {
            }
            return tex;
        }
        if (w == "material_map") {
            Token item = next();
            unsupported(item, "texture 'material_map'");
            skip_arguments(Arity::Block, item);
            return tex;
        }
        // A patterned texture: the pattern chooses among the texture_map's entries.
        Texture patterned;
        PatternTargets targets;
        targets.texture_map = &patterned.map;
        parse_pattern(patterned.pattern, PatternUse::Texture, targets, kw);
        if (patterned.pattern.kind == PatternKind::Solid) break;
        if (patterned.map.empty()) fail(t, "a patterned texture needs a texture_map");
        return patterned;
    }
    return tex;
}

// ---------------------------------------------------------------------------------------
// Finishes, interiors, materials

void SceneParser::parse_finish_block(Finish& f, const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0); v && v->holds<Finish>()) {
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
            f.diffuse_back = allow_float(0.0);
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
        } else if (w == "metallic") {
            next();
            f.metallic = starts_float(peek(0)) ? parse_float() : 1.0;
        } else if (w == "crand") {
            next();
            f.crand = parse_float();
        } else if (w == "conserve_energy") {
            next();
            f.conserve_energy = true;
        } else if (w == "reflection_exponent") {
            next();
            f.reflection_exponent = 1.0 / parse_float();
        } else if (w == "irid") {
            Token item = next();
            expect_open_brace(item);
            f.irid = parse_float();
            while (true) {
                if (accept_word("thickness")) {
                    f.irid_thickness = parse_float();
                } else if (accept_word("turbulence")) {
                    f.irid_turbulence = parse_vector().x;
                } else {
                    break;
                }
            }
            expect_close_brace(item);
        } else if (w == "ior") {
            next();
            f.ior = parse_index_of_refraction("ior");
        } else if (w == "caustics") {
            next();
            f.caustics = parse_float();
        } else if (w == "refraction") {
            next();
            f.refraction = parse_float();
        } else if (w == "reflection") {
            Token item = next();
            if (peek_punct("{")) {
                // reflection { min [, max] [fresnel] [falloff F] [exponent E] [metallic M] }
                next();
                const glm::dvec3 min = parse_rgb_colour();
                accept_comma();
                bool second = false;
                glm::dvec3 max = min;
                if (starts_expression(peek(0))) {
                    max = parse_rgb_colour();
                    second = true;
                }
                f.reflection = max;
                f.reflection_min = min;
                f.reflection_fresnel = false;
                while (!peek_punct("}") && !peek(0).is_eof()) {
                    const Token o = peek(0);
                    if (o.is_word("fresnel")) {
                        next();
                        const double on = allow_float(1.0);
                        f.reflection_fresnel = on != 0.0;
                        // A fresnel reflection without a second colour goes from 0.
                        if (!second && f.reflection_fresnel) f.reflection_min = glm::dvec3(0.0);
                    } else if (o.is_word("falloff")) {
                        next();
                        f.reflection_falloff = parse_float();
                    } else if (o.is_word("exponent")) {
                        next();
                        f.reflection_exponent = 1.0 / parse_float();
                    } else if (o.is_word("metallic")) {
                        next();
                        f.reflection_metallic = allow_float(1.0);
                    } else {
                        fail(o, "expected '}' to close 'reflection' opened at " +
                                    place(item.loc(), o) + ", got " + describe(o));
                    }
                }
                expect_punct("}", "to close 'reflection'");
            } else {
                // The old form: one colour for every angle.
                f.reflection = parse_rgb_colour();
                f.reflection_min.reset();
                f.reflection_falloff = 1.0;
                f.reflection_fresnel = false;
            }
        } else if (w == "subsurface") {
            Token item = next();
            skip_unsupported(item, Arity::Block, "finish item 'subsurface'");
        } else {
            break;
        }
    }
    expect_close_brace(kw);
    // The `albedo` forms rescale so that 1 reflects all the light (POV-Ray's Parse_Finish).
    if (diffuse_albedo) {
        f.diffuse *= (f.brilliance + 1.0) / 2.0;
        f.diffuse_back *= (f.brilliance + 1.0) / 2.0;
    }
    if (phong_albedo) f.phong *= (f.phong_size + 1.0) / 2.0;
    if (specular_albedo) {
        double r = f.roughness != 0.0 ? 1.0 / f.roughness : 0.0;  // POV-Ray's inverted roughness
        f.specular *= (r + 2.0) / (4.0 * (2.0 - std::pow(2.0, -r / 2.0)));
    }
}

double SceneParser::parse_index_of_refraction(const char* name) {
    const Token at = peek(0);
    const double v = parse_float();
    // The tracer works in single precision here, as POV-Ray does: 1e308 would be infinite.
    if (v == 0.0 || (v >= kMinIor && v <= kMaxIor)) return v;
    fail(at, std::string(name) + " " + shortest(v) + " must be 0 or from " + shortest(kMinIor) +
                 " to " + shortest(kMaxIor));
}

void SceneParser::parse_interior_block(Interior& interior, const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0);
        v && v->holds<MaterialValue>() &&
        v->get<MaterialValue>().kind == MaterialValue::Kind::Interior) {
        interior = identifier_as<MaterialValue>(next(), "an interior").interior;
    }
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        if (accept_word("ior")) {
            interior.ior = parse_index_of_refraction("ior");
        } else if (accept_word("dispersion")) {
            interior.dispersion = parse_index_of_refraction("dispersion");
        } else if (peek_word("dispersion_samples")) {
            next();
            Token at = peek(0);
            interior.dispersion_samples = static_cast<int>(parse_float());
            if (interior.dispersion_samples < 2) fail(at, "dispersion_samples must be 2 or more");
        } else if (accept_word("caustics")) {
            interior.caustics = parse_float() * 45.0;
        } else if (accept_word("fade_colour") || accept_word("fade_color")) {
            interior.fade_colour = parse_rgb_colour();
        } else if (accept_word("fade_distance")) {
            interior.fade_distance = parse_float();
        } else if (accept_word("fade_power")) {
            interior.fade_power = parse_float();
        } else if (accept_word("refraction")) {
            interior.refraction = parse_float();
        } else if (peek_word("media")) {
            Token item = next();
            skip_unsupported(item, Arity::Block, "interior item 'media'");
        } else {
            reject_unknown_word(t);
            break;
        }
    }
    expect_close_brace(kw);
}

Material SceneParser::parse_material_block(Material m, const Token& kw) {
    expect_open_brace(kw);
    if (const Value* v = peek_identifier_value(0);
        v && v->holds<MaterialValue>() &&
        v->get<MaterialValue>().kind == MaterialValue::Kind::Material) {
        Token name = next();
        const Material id = identifier_as<MaterialValue>(name, "a material").material;
        if (id.texture) {
            if (m.texture) {
                layer_texture(*m.texture, *id.texture, name);
            } else {
                m.texture = id.texture;
            }
        }
        if (id.interior_texture) {
            if (m.interior_texture) {
                layer_texture(*m.interior_texture, *id.interior_texture, name);
            } else {
                m.interior_texture = id.interior_texture;
            }
        }
        m.interior = id.interior;  // replaces (or removes) the interior, as in POV-Ray
    }
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        Transform tr;
        if (parse_transform_item(tr)) {
            if (m.texture) transform_texture(*m.texture, tr);
            if (m.interior_texture) transform_texture(*m.interior_texture, tr);
            continue;
        }
        if (t.is_word("texture")) {
            Token item = next();
            expect_open_brace(item);
            Texture tex = parse_texture_body(item);
            expect_close_brace(item);
            if (m.texture) {
                layer_texture(*m.texture, std::move(tex), item);
            } else {
                m.texture = std::move(tex);
            }
            continue;
        }
        if (t.is_word("interior")) {
            Token item = next();
            Interior interior = m.interior.value_or(Interior{});
            parse_interior_block(interior, item);
            m.interior = interior;
            continue;
        }
        if (t.is_word("interior_texture")) {
            Token item = next();
            expect_open_brace(item);
            Texture tex = parse_texture_body(item);
            expect_close_brace(item);
            if (m.interior_texture) {
                layer_texture(*m.interior_texture, std::move(tex), item);
            } else {
                m.interior_texture = std::move(tex);
            }
            continue;
        }
        reject_unknown_word(t);
        fail(t, "expected texture, interior or a transform in 'material', got " + describe(t));
    }
    expect_close_brace(kw);
    return m;
}

Fog SceneParser::parse_fog_block(const Token& kw) {
    expect_open_brace(kw);
    Fog fog;
    fog.loc = kw.loc();
    if (const Value* v = peek_identifier_value(0);
        v && v->holds<MaterialValue>() &&
        v->get<MaterialValue>().kind == MaterialValue::Kind::Fog) {
        fog = identifier_as<MaterialValue>(next(), "a fog").fog;
        fog.loc = kw.loc();
    }
    auto turb = [&]() -> Turbulence& {
        if (!fog.turbulence) fog.turbulence = Turbulence{};
        return *fog.turbulence;
    };
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        if (starts_colour(t)) {
            fog.colour = parse_colour(true);
        } else if (accept_word("distance")) {
            fog.distance = parse_float();
        } else if (starts_float(t)) {
            add_message(t, "warning", "the fog's distance should follow the distance keyword");
            fog.distance = parse_float();
        } else if (accept_word("fog_type")) {
            Token at = peek(0);
            fog.type = static_cast<int>(parse_float());
            if (fog.type != 1 && fog.type != 2) add_message(at, "warning", "unknown fog type");
        } else if (accept_word("fog_alt")) {
            fog.alt = parse_float();
        } else if (accept_word("fog_offset")) {
            fog.offset = parse_float();
        } else if (accept_word("turb_depth")) {
            fog.turb_depth = parse_float();
        } else if (accept_word("up")) {
            fog.up = parse_vector();
        } else if (accept_word("turbulence")) {
            turb().amount = parse_vector();
        } else if (accept_word("octaves")) {
            turb().octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
        } else if (accept_word("omega")) {
            turb().omega = parse_float();
        } else if (accept_word("lambda")) {
            turb().lambda = parse_float();
        } else if (peek_word("translate")) {
            Token item = next();
            parse_vector();
            add_message(item, "warning", "a fog's up vector can't be translated");
        } else {
            Transform tr;
            if (parse_transform_item(tr)) {
                fog.up = transform_direction(tr, fog.up);
                continue;
            }
            reject_unknown_word(t);
            break;
        }
    }
    expect_close_brace(kw);
    const double len = glm::length(fog.up);
    if (len > 0.0) fog.up /= len;
    return fog;
}

// ---------------------------------------------------------------------------------------
// Hooks for the object, light, declaration and global settings parsers

bool SceneParser::parse_material_modifier(ObjectNode& node) {
    const Token t = peek(0);
    if (!is_keyword(t)) return false;
    const std::string& w = t.text();
    if (w == "normal") {
        Token item = next();
        // It changes the object's texture, or a copy of the default one.
        if (!node.texture) node.texture = default_texture_;
        if (node.texture->pattern.kind != PatternKind::Solid) {
            layer_texture(*node.texture, default_texture_, item);
        }
        if (!node.texture->normal) node.texture->normal = Normal{};
        expect_open_brace(item);
        parse_normal_body(*node.texture->normal, item);
        expect_close_brace(item);
        return true;
    }
    if (w == "interior") {
        Token item = next();
        Interior interior = node.interior ? *node.interior : Interior{};
        parse_interior_block(interior, item);
        node.interior = std::make_shared<const Interior>(interior);
        return true;
    }
    if (w == "material") {
        Token item = next();
        Material m;
        m.texture = node.texture;
        m.interior_texture = node.interior_texture;
        if (node.interior) m.interior = *node.interior;
        m = parse_material_block(std::move(m), item);
        node.texture = m.texture;
        node.interior_texture = m.interior_texture;
        node.interior = m.interior ? std::make_shared<const Interior>(*m.interior) : nullptr;
        return true;
    }
    if (w == "interior_texture") {
        Token item = next();
        expect_open_brace(item);
        Texture tex = parse_texture_body(item);
        expect_close_brace(item);
        if (node.interior_texture) {
            layer_texture(*node.interior_texture, std::move(tex), item);
        } else {
            node.interior_texture = std::move(tex);
        }
        return true;
    }
    if (w == "hollow") {
        next();
        const bool on = allow_float(1.0) != 0.0;
        Interior interior = node.interior ? *node.interior : Interior{};
        interior.hollow = on;
        node.interior = std::make_shared<const Interior>(interior);
        return true;
    }
    return false;
}

bool SceneParser::parse_light_item(PointLight& light) {
    const Token t = peek(0);
    if (!is_keyword(t)) return false;
    const std::string& w = t.text();
    const bool cone =
        light.kind == PointLight::Kind::Spot || light.kind == PointLight::Kind::Cylinder;
    auto not_with = [&](const Token& item) {
        fail(item, "'" + item.text() + "' cannot be used with a standard light source");
    };
    if (w == "spotlight") {
        next();
        light.kind = PointLight::Kind::Spot;
        light.radius = std::cos(30 * kPi / 180);
        light.falloff = std::cos(45 * kPi / 180);
        light.tightness = 0;
    } else if (w == "cylinder") {
        next();
        light.kind = PointLight::Kind::Cylinder;
        light.radius = 0.75;
        light.falloff = 1;
        light.tightness = 0;
        light.parallel = true;
    } else if (w == "parallel") {
        next();
        light.parallel = true;
    } else if (w == "point_at") {
        Token item = next();
        if (!cone && !light.parallel) not_with(item);
        light.point_at = parse_vector();
    } else if (w == "tightness") {
        Token item = next();
        if (!cone) not_with(item);
        light.tightness = parse_float();
    } else if (w == "radius" || w == "falloff") {
        Token item = next();
        if (!cone) not_with(item);
        double v = parse_float();
        if (light.kind == PointLight::Kind::Spot) v = std::cos(v * kPi / 180);
        (w == "radius" ? light.radius : light.falloff) = v;
    } else if (w == "fade_distance") {
        next();
        light.fade_distance = parse_float();
    } else if (w == "fade_power") {
        next();
        light.fade_power = parse_float();
    } else if (w == "area_light") {
        next();
        light.area_light = true;
        light.axis1 = parse_vector();
        accept_comma();
        light.axis2 = parse_vector();
        accept_comma();
        Token at = peek(0);
        light.size1 = static_cast<int>(parse_float());
        if (light.size1 == 0) fail(at, "area size must be greater than zero");
        accept_comma();
        at = peek(0);
        light.size2 = static_cast<int>(parse_float());
        if (light.size2 == 0) fail(at, "area size must be greater than zero");
    } else if (w == "jitter") {
        Token item = next();
        light.jitter = true;
        add_message(item, "warning",
                    "the built-in tracer samples area lights without jitter (deterministic)");
    } else if (w == "orient") {
        next();
        light.orient = true;
    } else if (w == "circular") {
        next();
        light.circular = true;
    } else if (w == "adaptive") {
        next();
        light.adaptive = static_cast<int>(parse_float());
    } else if (w == "area_illumination") {
        next();
        light.area_illumination = allow_float(1.0) > 0.0;
    } else if (w == "media_attenuation") {
        next();
        light.media_attenuation = allow_float(1.0) > 0.0;
    } else if (w == "media_interaction") {
        next();
        light.media_interaction = allow_float(1.0) > 0.0;
    } else {
        return false;
    }
    // POV-Ray's checks after parsing: orient needs a circular light, a circular light more
    // than one sample each way.
    if (light.orient && light.area_light) light.circular = true;
    if (light.circular && light.area_light && (light.size1 <= 1 || light.size2 <= 1)) {
        light.circular = false;
    }
    return true;
}

std::optional<Value> SceneParser::parse_material_value() {
    const Token t = peek(0);
    if (!is_keyword(t)) return std::nullopt;
    const std::string& w = t.text();
    MaterialValue m;
    if (w == "normal") {
        Token kw = next();
        m.kind = MaterialValue::Kind::Normal;
        m.normal = default_texture_.normal.value_or(Normal{});
        expect_open_brace(kw);
        parse_normal_body(m.normal, kw);
        expect_close_brace(kw);
    } else if (w == "interior") {
        Token kw = next();
        m.kind = MaterialValue::Kind::Interior;
        parse_interior_block(m.interior, kw);
    } else if (w == "material") {
        Token kw = next();
        m.kind = MaterialValue::Kind::Material;
        m.material = parse_material_block(Material{}, kw);
    } else if (w == "fog") {
        Token kw = next();
        m.kind = MaterialValue::Kind::Fog;
        m.fog = parse_fog_block(kw);
    } else if (w == "pigment_map") {
        m.kind = MaterialValue::Kind::PigmentMap;
        m.pigment_map = parse_pigment_map(next());
    } else if (w == "normal_map") {
        m.kind = MaterialValue::Kind::NormalMap;
        m.normal_map = parse_normal_map(next());
    } else if (w == "texture_map") {
        m.kind = MaterialValue::Kind::TextureMap;
        m.texture_map = parse_texture_map(next());
    } else if (w == "slope_map") {
        m.kind = MaterialValue::Kind::SlopeMap;
        m.slope_map = parse_slope_map(next());
    } else {
        return std::nullopt;
    }
    return Value{std::move(m)};
}

bool SceneParser::parse_material_global_setting() {
    const Token t = peek(0);
    if (t.is_word("noise_generator")) {
        next();
        Token at = peek(0);
        const int g = static_cast<int>(parse_float());
        if (g < 1 || g > 3) fail(at, "noise_generator must be 1, 2 or 3, got " + std::to_string(g));
        scene_.global.noise_generator = g;
        explicit_noise_generator_ = true;
        return true;
    }
    if (t.is_word("number_of_waves")) {
        next();
        Token at = peek(0);
        const int n = static_cast<int>(parse_float());
        if (n <= 0) fail(at, "number_of_waves must be positive, got " + std::to_string(n));
        scene_.global.number_of_waves = n;
        return true;
    }
    if (t.is_word("adc_bailout")) {
        next();
        scene_.global.adc_bailout = parse_float();
        return true;
    }
    if (t.is_word("irid_wavelength")) {
        next();
        scene_.global.irid_wavelength = parse_rgb_colour();
        return true;
    }
    return false;
}

}  // namespace mirage::scene_detail
