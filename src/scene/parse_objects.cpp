// Objects, transforms, light sources and the camera, after POV-Ray 3.7's parse.cpp.
#include <algorithm>
#include <cmath>

#include "scene/scene_parser.h"
#include "scene/transform.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

bool one_of(const std::string& w, std::initializer_list<const char*> words) {
    for (const char* x : words) {
        if (w == x) return true;
    }
    return false;
}

// How the arguments of POV-Ray's object modifiers outside the subset are skipped.
struct ModifierArity {
    const char* name;
    Arity arity;
};
constexpr ModifierArity kUnsupportedObjectModifiers[] = {
    {"normal", Arity::Block},
    {"interior", Arity::Block},
    {"material", Arity::Block},
    {"photons", Arity::Block},
    {"interior_texture", Arity::Block},
    {"radiosity", Arity::Block},
    {"no_image", Arity::OptionalFloat},
    {"no_reflection", Arity::OptionalFloat},
    {"no_radiosity", Arity::OptionalFloat},
    {"double_illuminate", Arity::OptionalFloat},
    {"cutaway_textures", Arity::None},
    {"uv_mapping", Arity::None},
    {"debug_tag", Arity::String},
    {"dtag", Arity::String},
};

constexpr ModifierArity kUnsupportedLightModifiers[] = {
    {"spotlight", Arity::None},
    {"cylinder", Arity::None},
    {"parallel", Arity::None},
    {"area_light", Arity::AreaLight},
    {"point_at", Arity::Vector},
    {"radius", Arity::Float},
    {"falloff", Arity::Float},
    {"tightness", Arity::Float},
    {"fade_distance", Arity::Float},
    {"fade_power", Arity::Float},
    {"jitter", Arity::None},
    {"orient", Arity::None},
    {"circular", Arity::None},
    {"adaptive", Arity::Float},
    {"area_illumination", Arity::OptionalFloat},
    {"looks_like", Arity::Block},
    {"projected_through", Arity::Block},
    {"photons", Arity::Block},
    {"color_map", Arity::Block},
    {"colour_map", Arity::Block},
};

constexpr ModifierArity kUnsupportedCameraItems[] = {
    {"mesh_camera", Arity::Block},
    {"aperture", Arity::Float},
    {"blur_samples", Arity::FloatOptionalFloat},
    {"focal_point", Arity::Vector},
    {"confidence", Arity::Float},
    {"variance", Arity::Float},
    {"normal", Arity::Block},
    {"bokeh", Arity::Block},
};

struct CameraKeyword {
    const char* name;
    CameraType type;
};
constexpr CameraKeyword kCameraTypes[] = {
    {"perspective", CameraType::Perspective}, {"orthographic", CameraType::Orthographic},
    {"fisheye", CameraType::Fisheye},         {"ultra_wide_angle", CameraType::UltraWideAngle},
    {"omnimax", CameraType::Omnimax},         {"panoramic", CameraType::Panoramic},
    {"spherical", CameraType::Spherical},
};

template <std::size_t N>
const ModifierArity* find_arity(const ModifierArity (&table)[N], const std::string& w) {
    for (const ModifierArity& m : table) {
        if (w == m.name) return &m;
    }
    return nullptr;
}

}  // namespace

bool SceneParser::is_unsupported_object_keyword(const Token& t) const {
    return is_keyword(t) && !is_shape_keyword(t.text()) &&
           one_of(t.text(), {"bicubic_patch", "blob",         "cubic",
                             "height_field",  "julia_fractal",
                             "lathe",         "light_group",  "mesh",
                             "mesh2",         "ovus",         "parametric",
                             "poly",          "polygon",      "polynomial",
                             "prism",         "quartic",      "smooth_triangle",
                             "sor",           "sphere_sweep", "superellipsoid",
                             "text",          "triangle",     "composite"});
}

bool SceneParser::starts_object(const Token& t) const {
    if (is_keyword(t)) {
        return is_shape_keyword(t.text()) ||
               one_of(t.text(),
                      {"union", "difference", "intersection", "merge", "object", "light_source"}) ||
               is_unsupported_object_keyword(t);
    }
    if (is_identifier(t)) {
        auto sym = t.symbol ? t.symbol : lookup(t.text());
        if (!sym) return false;
        if (auto* a = sym->value.get_if<ArrayValue>()) {
            for (const auto& e : a->elements) {
                if (e) return e->holds<ObjectNode>();
            }
            return false;
        }
        if (auto* opaque = sym->value.get_if<OpaqueValue>())
            return opaque->what == "object";
        return sym->value.holds<ObjectNode>();
    }
    return false;
}

// The objects' parse recurses once per level of nesting: the functions on that path fill the
// node they are given instead of returning one, and what a level needs rarely (a copy of a
// declared object, a mesh, an unreadable object) is made in a frame of its own, so that a
// level costs no more stack than one node.

std::optional<ObjectNode> SceneParser::parse_object() {
    std::optional<ObjectNode> out(std::in_place);
    if (!parse_object_to(*out)) out.reset();
    return out;
}

bool SceneParser::parse_object_to(ObjectNode& out) {
    if (options_.strict) return parse_object_unguarded(out);
    // Lenient: an object that cannot be read becomes an unknown object (no extent), and the
    // parse goes on after it.
    const int balance = brace_balance_;
    const Token start = peek(0);
    try {
        return parse_object_unguarded(out);
    } catch (const ParseFailure& failure) {
        if (failure.fatal || !starts_object(start)) throw;
        recover_statement(balance);
        [&]() __attribute__((noinline)) {
            ObjectNode unknown;
            unknown.kind = ObjectNode::Kind::Empty;
            unknown.loc = start.loc();
            unknown.unknown = "'" + start.text() + "' that mirage cannot read (" + failure.reason +
                              " at " + failure.loc.file + ":" + std::to_string(failure.loc.line) +
                              ":" + std::to_string(failure.loc.column) + ")";
            out = std::move(unknown);
        }
        ();
        return true;
    }
}

bool SceneParser::parse_object_unguarded(ObjectNode& out) {
    const Token t = peek(0);
    if (!starts_object(t)) return false;
    Nested nested(*this, t);
    if (is_identifier(t)) {
        copy_named_object(out);
        return true;
    }
    Token kw = next();
    count_objects(1, kw);
    const std::string& w = kw.text();
    if (w == "union") {
        parse_union(kw, out);
    } else if (w == "difference" || w == "intersection" || w == "merge") {
        parse_csg(kw, out);
    } else if (w == "object") {
        parse_object_statement(kw, out);
    } else if (w == "light_source") {
        parse_light_source(kw, out);
    } else if (is_unsupported_object_keyword(kw)) {
        unsupported(kw, "object '" + w + "'");
        parse_unknown_object(kw, out);
    } else {
        parse_shape(kw, out);
    }
    return true;
}

void SceneParser::copy_named_object(ObjectNode& out) {
    const Token name = next();
    Value v = identifier_value(name);
    auto* object = v.get_if<ObjectNode>();
    if (!object) fail(name, "expected an object, got " + value_type_name(v));
    out = std::move(*object);
}

void SceneParser::parse_unknown_object(const Token& kw, ObjectNode& unknown) {
    // Its own arguments are left out; the bounded_by, clipped_by and transforms at its level
    // are read, for its extent.
    unknown.kind = ObjectNode::Kind::Empty;
    unknown.loc = kw.loc();
    unknown.unknown = "object '" + kw.text() + "'";
    expect_open_brace(kw);
    int depth = 0;
    while (true) {
        const Token& t = peek(0);
        if (t.is_eof()) {
            fail(t, "expected '}' to close '" + kw.text() + "' opened at " + place(kw.loc(), t) +
                        ", got end of file");
        }
        if (depth == 0) {
            if (t.is_punct("}")) break;
            Transform tr;
            if (parse_transform_item(tr)) {
                transform_object(unknown, tr);
                continue;
            }
            if (t.is_word("bounded_by") || t.is_word("clipped_by")) {
                parse_bound_or_clip(unknown);
                continue;
            }
        }
        const Token x = next();
        if (x.is_punct("{")) ++depth;
        if (x.is_punct("}")) --depth;
    }
    expect_close_brace(kw);
}

void SceneParser::parse_bound_or_clip(ObjectNode& node) {
    Token item = next();
    const bool clip = item.is_word("clipped_by");
    expect_open_brace(item);
    std::vector<ObjectNode>& list = clip ? node.clip : node.bound;
    if (peek_word(clip ? "bounded_by" : "clipped_by")) {
        // clipped_by { bounded_by } and bounded_by { clipped_by }: the same objects.
        next();
        list = clip ? node.bound : node.clip;
    } else {
        list.clear();
        parse_objects_into(list);
        if (list.empty()) {
            fail(peek(0), "expected an object in '" + item.text() + "', got " + describe(peek(0)));
        }
    }
    expect_close_brace(item);
}

// `sphere { Ident ... }` and the like copy the object named (POV-Ray's Parse_Object_Id).
static bool starts_with_object_identifier(const Value* v) {
    return v && v->holds<ObjectNode>();
}

void SceneParser::parse_objects_into(std::vector<ObjectNode>& list) {
    while (true) {
        list.emplace_back();
        if (!parse_object_to(list.back())) {
            list.pop_back();
            return;
        }
    }
}

void SceneParser::parse_shape(const Token& kw, ObjectNode& node) {
    expect_open_brace(kw);
    if (starts_with_object_identifier(peek_identifier_value(0))) {
        copy_named_object(node);
        parse_object_modifiers(node, kw);
        return;
    }
    if (kw.is_word("mesh") || kw.is_word("mesh2")) {
        [&]() __attribute__((noinline)) { node = parse_mesh(kw); }
        ();
    } else {
        node.kind = ObjectNode::Kind::Shape;
        node.loc = kw.loc();
        node.shape = parse_shape_arguments(kw);
        // POV-Ray turns text by 0.001 degrees about each axis, against cracks along the axes.
        if (kw.is_word("text")) transform_object(node, make_rotation(glm::dvec3(0.001)));
    }
    parse_object_modifiers(node, kw);
    if (const auto* iso = std::get_if<Isosurface>(&node.shape); iso && !iso->function) {
        // Its function is outside the subset (reported where it was read): left out in
        // lenient mode, as an object mirage cannot read.
        node.kind = ObjectNode::Kind::Empty;
        node.unknown = "object 'isosurface'";
    }
}

/// `union { Obj translate x }` and the like: the object named, moved (true); `union { A B }`
/// is a union of two (false).
bool SceneParser::parse_modified_copy(const Token& kw, ObjectNode& node) {
    if (!starts_with_object_identifier(peek_identifier_value(0)) || peek_punct("}", 1)) {
        return false;
    }
    const Value* next_value = peek_identifier_value(1);
    if (starts_with_object_identifier(next_value) || starts_object(peek(1))) return false;
    copy_named_object(node);
    parse_object_modifiers(node, kw);
    return true;
}

void SceneParser::parse_union(const Token& kw, ObjectNode& u) {
    expect_open_brace(kw);
    if (parse_modified_copy(kw, u)) return;
    u.kind = ObjectNode::Kind::Union;
    u.loc = kw.loc();
    parse_objects_into(u.children);
    if (u.children.size() < 2) {
        add_message(kw, "warning", "a union should have at least 2 objects");
    }
    parse_object_modifiers(u, kw);
}

void SceneParser::parse_csg(const Token& kw, ObjectNode& c) {
    expect_open_brace(kw);
    if (parse_modified_copy(kw, c)) return;
    c.kind = ObjectNode::Kind::Csg;
    c.csg = kw.is_word("merge") ? CsgKind::Merge : CsgKind::Intersection;
    c.loc = kw.loc();
    parse_objects_into(c.children);
    // POV-Ray's Parse_CSG: a difference is the intersection of the first object with the
    // inverse of every other.
    if (kw.is_word("difference")) {
        for (std::size_t i = 1; i < c.children.size(); ++i) invert_object(c.children[i]);
    }
    if (c.children.size() < 2) {
        add_message(kw, "warning", "a " + kw.text() + " should have at least 2 objects");
    }
    parse_object_modifiers(c, kw);
}

void SceneParser::parse_object_statement(const Token& kw, ObjectNode& inner) {
    expect_open_brace(kw);
    if (!parse_object_to(inner)) {
        const Token& t = peek(0);
        if (is_identifier(t) && !t.symbol && !lookup(t.text())) {
            fail(t, "undefined identifier '" + t.text() + "'");
        }
        fail(t, "expected an object inside 'object', got " + describe(t));
    }
    parse_object_modifiers(inner, kw);
}

void SceneParser::parse_light_source(const Token& kw, ObjectNode& node) {
    expect_open_brace(kw);
    if (starts_with_object_identifier(peek_identifier_value(0))) {
        copy_named_object(node);
        parse_object_modifiers(node, kw);
        return;
    }
    node.kind = ObjectNode::Kind::Light;
    node.loc = kw.loc();
    node.light.loc = kw.loc();
    node.light.location = parse_vector();
    accept_comma();
    node.light.colour = parse_rgb_colour();
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        Transform tr;
        if (parse_transform_item(tr)) {
            transform_object(node, tr);
            continue;
        }
        if (parse_light_item(node.light)) continue;  // spotlight, area_light, fade, media...
        if (t.is_word("shadowless")) {
            next();
            node.light.shadowless = true;
            continue;
        }
        if (t.is_word("media_interaction") || t.is_word("media_attenuation")) {
            // No media in the subset, so these change nothing.
            next();
            allow_float(1.0);
            continue;
        }
        if (is_keyword(t)) {
            if (const ModifierArity* m = find_arity(kUnsupportedLightModifiers, t.text())) {
                Token item = next();
                skip_unsupported(item, m->arity,
                                 "light source modifier '" + item.text() + "' (only point lights)");
                continue;
            }
        }
        reject_unknown_word(t);
        break;
    }
    expect_close_brace(kw);
}

void SceneParser::parse_object_modifiers(ObjectNode& node, const Token& kw) {
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        Transform tr;
        if (parse_transform_item(tr)) {
            transform_object(node, tr);
            continue;
        }
        if (parse_material_modifier(node)) continue;  // normal, interior, material, hollow
        if (is_keyword(t)) {
            const std::string& w = t.text();
            if (w == "texture") {
                Token item = next();
                expect_open_brace(item);
                Texture tex = parse_texture_body(item);
                expect_close_brace(item);
                set_texture(node, std::move(tex), item);
                continue;
            }
            if (w == "pigment" || w == "finish") {
                Token item = next();
                // They change the object's texture, or a copy of the default one.
                if (!node.texture) node.texture = default_texture_;
                if (w == "pigment") {
                    expect_open_brace(item);
                    parse_pigment_body(node.texture->pigment, item);
                    expect_close_brace(item);
                } else {
                    parse_finish_block(node.texture->finish, item);
                }
                continue;
            }
            if (w == "no_shadow") {
                next();
                node.no_shadow = true;
                continue;
            }
            if (w == "inverse") {
                next();
                invert_object(node);
                continue;
            }
            if (w == "bounded_by" || w == "clipped_by") {
                parse_bound_or_clip(node);
                continue;
            }
            if (w == "sturm" && node.kind == ObjectNode::Kind::Shape) {
                next();
                const bool on = allow_float(1.0) != 0.0;
                std::visit(
                    [&](auto& shape) {
                        if constexpr (requires { shape.sturm; }) shape.sturm = on;
                    },
                    node.shape);
                continue;
            }
            if (w == "split_union" || w == "hierarchy") {
                next();  // bounding hints: no effect on the image
                if (w == "split_union") {
                    parse_float();
                } else {
                    allow_float(1.0);
                }
                continue;
            }
            if (w == "hollow") {
                // Only media and fog see the difference, and they are outside the subset.
                next();
                allow_float(1.0);
                continue;
            }
            if (starts_colour(t)) {
                // A "quick colour": POV-Ray ignores it outside a texture.
                Token at = peek(0);
                parse_colour(true);
                add_message(at, "warning", "a colour outside a pigment is ignored");
                continue;
            }
            if (const ModifierArity* m = find_arity(kUnsupportedObjectModifiers, w)) {
                Token item = next();
                skip_unsupported(item, m->arity,
                                 "modifier '" + item.text() + "' in '" + kw.text() + "'");
                continue;
            }
        }
        reject_unknown_word(t);
        break;
    }
    expect_close_brace(kw);
}

bool SceneParser::parse_transform_item(Transform& t) {
    const Token& p = peek(0);
    if (!is_keyword(p)) return false;
    const std::string& w = p.text();
    if (w == "translate") {
        next();
        t = make_translation(parse_vector());
    } else if (w == "rotate") {
        next();
        t = make_rotation(parse_vector());
    } else if (w == "scale") {
        next();
        t = make_scaling(parse_scale_vector());
    } else if (w == "matrix") {
        Token kw = next();
        t = make_matrix_transform(parse_matrix(kw));
    } else if (w == "transform") {
        Token kw = next();
        t = parse_transform_block(kw);
    } else {
        return false;
    }
    return true;
}

Transform SceneParser::parse_transform_block(const Token& kw) {
    // `transform Ident` (the old syntax) or `transform { ... }`.
    if (const Value* v = peek_identifier_value(0);
        v && v->holds<Transform>()) {
        return identifier_as<Transform>(next(), "a transform");
    }
    expect_open_brace(kw);
    Transform t;
    bool inverse = false;
    while (true) {
        const Token p = peek(0);
        if (p.is_punct("}")) break;
        if (p.is_word("inverse")) {
            next();
            inverse = true;
            continue;
        }
        if (const Value* v = peek_identifier_value(0);
            v && v->holds<Transform>()) {
            t = compose_transforms(t, identifier_as<Transform>(next(), "a transform"));
            continue;
        }
        Transform item;
        if (parse_transform_item(item)) {
            t = compose_transforms(t, item);
            continue;
        }
        reject_unknown_word(p);
        break;
    }
    expect_close_brace(kw);
    return inverse ? invert_transform(t) : t;
}

std::array<double, 12> SceneParser::parse_matrix(const Token& kw) {
    Token open = expect_punct("<", "after 'matrix'");
    std::array<double, 12> m{};
    for (int i = 0; i < 12; ++i) {
        if (i) accept_comma();
        m[i] = parse_float();
    }
    const Token& close = peek(0);
    if (!close.is_punct(">")) {
        fail(close, "expected '>' after the 12 values of 'matrix', got " + describe(close));
    }
    next();
    // POV-Ray's Parse_Matrix: a column of zeros would scale by 0; it becomes 1 on the diagonal.
    for (int i = 0; i < 3; ++i) {
        if (std::abs(m[i]) < kEpsilon && std::abs(m[3 + i]) < kEpsilon &&
            std::abs(m[6 + i]) < kEpsilon) {
            add_message(kw, "warning", "matrix column scales by 0, changed to 1");
            m[3 * i + i] = 1.0;
        }
    }
    glm::dmat3 linear(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]);
    if (std::abs(glm::determinant(linear)) < 1e-300) fail(open, "the matrix is singular");
    return m;
}

CameraState SceneParser::parse_camera(const Token& kw) {
    expect_open_brace(kw);
    CameraState base;
    if (const Value* v = peek_identifier_value(0);
        v && v->holds<CameraState>()) {
        // `camera { Ident ... }`: POV-Ray 3.5+ allows only transforms after the identifier.
        base = identifier_as<CameraState>(next(), "a camera");
        CameraModifiers mods;
        Transform tr;
        while (parse_transform_item(tr)) mods.transform = compose_transforms(mods.transform, tr);
        expect_close_brace(kw);
        auto result = apply_camera_statement(base, mods);
        if (!result) fail(kw, result.message());
        return *result;
    }
    CameraModifiers mods;
    bool other_type = false;  // lenient mode after an unsupported camera type
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        Transform tr;
        if (parse_transform_item(tr)) {
            mods.transform = compose_transforms(mods.transform, tr);
            continue;
        }
        if (is_keyword(t)) {
            const std::string& w = t.text();
            bool projection = false;
            for (const CameraKeyword& k : kCameraTypes) {
                if (w == k.name) {
                    next();
                    mods.type = k.type;
                    projection = true;
                }
            }
            if (projection) continue;
            if (w == "cylinder") {
                next();
                Token at = peek(0);
                const int n = static_cast<int>(parse_float());
                if (n < 1 || n > 4)
                    fail(at,
                         "cylinder camera type " + std::to_string(n) + ": valid are types 1 to 4");
                mods.type = n == 1   ? CameraType::Cylinder1
                            : n == 2 ? CameraType::Cylinder2
                            : n == 3 ? CameraType::Cylinder3
                                     : CameraType::Cylinder4;
                continue;
            }
            std::optional<glm::dvec3>* vector = w == "location"    ? &mods.location
                                                : w == "direction" ? &mods.direction
                                                : w == "up"        ? &mods.up
                                                : w == "right"     ? &mods.right
                                                : w == "sky"       ? &mods.sky
                                                : w == "look_at"   ? &mods.look_at
                                                                   : nullptr;
            if (vector) {
                next();
                *vector = parse_vector();
                continue;
            }
            if (w == "angle") {
                next();
                Token at = peek(0);
                const CameraType type = mods.type.value_or(base.type);
                // The orthographic camera's angle is optional.
                double angle = type == CameraType::Orthographic ? allow_float(0.0) : parse_float();
                if (other_type) continue;
                if (angle < 0.0) fail(at, "negative viewing angle");
                const bool flat =
                    type == CameraType::Perspective || type == CameraType::Orthographic;
                if (flat && angle >= 180.0) {
                    fail(at, "the viewing angle must be smaller than 180 degrees");
                }
                mods.angle_deg = angle;
                if (type == CameraType::Spherical) {
                    // angle H [, V]: the vertical angle defaults to half the horizontal.
                    accept_comma();
                    mods.v_angle_deg = allow_float(angle * 0.5);
                }
                continue;
            }
            if (const ModifierArity* m = find_arity(kUnsupportedCameraItems, w)) {
                Token item = next();
                if (w == "mesh_camera") other_type = true;
                skip_unsupported(item, m->arity, "camera item '" + item.text() + "'");
                continue;
            }
        }
        reject_unknown_word(t);
        break;
    }
    expect_close_brace(kw);
    auto result = apply_camera_statement(base, mods);
    if (!result) fail(kw, result.message());
    if (!camera_vectors_perpendicular(*result)) {
        add_message(kw, "warning", "camera vectors are not perpendicular");
    }
    return *result;
}

void SceneParser::parse_camera_into_scene(const Token& kw) {
    CameraState state = parse_camera(kw);
    if (had_camera_) {
        add_message(kw, "warning", "more than one camera: the previous one is ignored");
    }
    had_camera_ = true;
    scene_.camera = camera_from_state(state);
    scene_.camera.loc = kw.loc();
    scene_.has_camera = true;
}

}  // namespace mirage::scene_detail
