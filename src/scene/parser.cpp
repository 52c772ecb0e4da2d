// The public entry points, the top level of a scene file (POV-Ray 3.7's Parse_Frame) and the
// lenient mode's skipping.
#include "scene/parser.h"

#include <pthread.h>

#include <algorithm>
#include <cmath>
#include <new>

#include "scene/scene_parser.h"
#include "scene/transform.h"
#include "util/format.h"

namespace mirage {
namespace scene_detail {
namespace {

constexpr int kMaxTraceLevelLimit = 256;  // POV-Ray's MAX_TRACE_LEVEL_LIMIT

struct ItemArity {
    const char* name;
    Arity arity;
};

constexpr ItemArity kUnsupportedGlobalSettings[] = {
    {"photons", Arity::Block},     {"radiosity", Arity::Block},
    {"subsurface", Arity::Block},  {"hf_gray_16", Arity::OptionalFloat},
    {"mm_per_unit", Arity::Float},
};

/// What a declared value is, when it is a material (for Scene::material_symbols).
const char* material_kind(const Value& v) {
    if (v.holds<Texture>()) return "texture";
    if (v.holds<Pigment>()) return "pigment";
    if (v.holds<Finish>()) return "finish";
    if (v.holds<ColourMapValue>()) return "color_map";
    if (v.holds<SkySphere>()) return "sky_sphere";
    if (const auto* n = v.get_if<Numeric>(); n && n->size == 5) return "colour";
    if (const auto* m = v.get_if<MaterialValue>()) {
        switch (m->kind) {
            case MaterialValue::Kind::Normal:
                return "normal";
            case MaterialValue::Kind::Interior:
                return "interior";
            case MaterialValue::Kind::Material:
                return "material";
            case MaterialValue::Kind::Fog:
                return "fog";
            case MaterialValue::Kind::PigmentMap:
                return "pigment_map";
            case MaterialValue::Kind::NormalMap:
                return "normal_map";
            case MaterialValue::Kind::TextureMap:
                return "texture_map";
            case MaterialValue::Kind::SlopeMap:
                return "slope_map";
        }
    }
    return nullptr;
}

/// The lowest address the parse's recursion may use on this thread's stack: its low end
/// plus a reserve (an eighth of the stack, at least 1 MiB) for the frames between two checks
/// of the nesting and for what runs at the deepest level (a macro call, an include, a
/// value's copy).  0 where the stack's bounds are not known.
std::uintptr_t stack_floor_of_this_thread() {
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) != 0) return 0;
    void* low = nullptr;
    std::size_t size = 0;
    const bool known = pthread_attr_getstack(&attr, &low, &size) == 0;
    pthread_attr_destroy(&attr);
    if (!known || size == 0) return 0;
    const std::size_t reserve = std::max<std::size_t>(size / 8, std::size_t{1} << 20);
    const auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    const auto floor = reinterpret_cast<std::uintptr_t>(low) + reserve;
    // A stack too small for the reserve: the parse may still go as deep as half of what is
    // left below this frame.
    return floor < here ? floor : here - (here - reinterpret_cast<std::uintptr_t>(low)) / 2;
}

}  // namespace

Scene SceneParser::parse(std::shared_ptr<SourceFile> main_file) {
    stack_floor_ = stack_floor_of_this_thread();
    scene_.file = main_file->path;
    push_frame(main_file, 0, main_file->tokens.size() - 1, FrameContext::Kind::Main, "", Token{});
    parse_top_level();
    export_symbols();
    // POV-Ray takes the noise generator from the last #version unless the scene sets it.
    scene_.global.language_version = language_version_;
    scene_.global.assumed_gamma_given = gamma_set_;
    if (!explicit_noise_generator_) {
        scene_.global.noise_generator = language_version_ >= 3.5 - 1e-9 ? 2 : 1;
    }
    // f_noise3d uses the scene's noise generator, whatever came before global_settings.
    const auto set_noise = [&](Primitive& p) {
        if (auto* iso = std::get_if<Isosurface>(&p.shape)) {
            iso->noise_generator = scene_.global.noise_generator;
        }
    };
    for (Primitive& p : scene_.primitives) set_noise(p);
    for (UnknownObject& u : scene_.unknown_objects) {
        for (auto& bound : u.bounds) {
            for (Primitive& p : bound) set_noise(p);
        }
    }
    return std::move(scene_);
}

void SceneParser::parse_top_level() {
    while (true) {
        if (options_.strict) {
            if (!parse_top_level_item()) return;
            continue;
        }
        // Lenient: a statement that cannot be read is left out (the compiler needs only the
        // camera, the atmosphere and the objects' extent; objects recover on their own).
        const int balance = brace_balance_;
        const std::size_t read = tokens_read_;
        bool camera = false;
        {
            // A statement that starts with a word nobody declared is not POV-Ray either.
            const Token& t = peek(0);
            if (is_identifier(t) && !t.symbol && !lookup(t.text())) reject_unknown_word(t);
        }
        try {
            camera = peek(0).is_word("camera");
            if (!parse_top_level_item()) return;
        } catch (const ParseFailure& failure) {
            if (camera || failure.fatal) throw;
            // At the end of the file there is nothing left to skip to: a statement that fails
            // there (an '#if' left open, an expression cut short) ends the parse with its
            // message, or the lenient parse would meet the same failure again for ever.
            if (tokens_read_ == read && peek(0).is_eof()) throw;
            scene_.skipped.push_back(Skipped{failure.reason, failure.loc});
            recover_statement(balance);
            if (tokens_read_ == read && !peek(0).is_eof()) next();
        }
    }
}

bool SceneParser::parse_top_level_item() {
    {
        const Token t = peek(0);
        if (t.is_eof()) {
            check_cond_closed_at_frame_end(t);
            return false;
        }
        if (is_keyword(t)) {
            const std::string& w = t.text();
            if (w == "camera") {
                parse_camera_into_scene(next());
                return true;
            }
            if (w == "background") {
                parse_background(next());
                return true;
            }
            if (w == "sky_sphere") {
                parse_sky_sphere(next());
                return true;
            }
            if (w == "global_settings") {
                parse_global_settings(next());
                return true;
            }
            if (w == "max_trace_level") {
                // Outside global_settings: POV-Ray takes it with a warning.
                Token item = next();
                const double level = parse_float();
                scene_.global.max_trace_level =
                    static_cast<int>(std::clamp(level, 1.0, double(kMaxTraceLevelLimit)));
                add_message(item, "warning", "max_trace_level belongs in global_settings");
                return true;
            }
            if (w == "default") {
                // POV-Ray still takes the old form without '#'.
                directive_default(next());
                return true;
            }
            if (w == "fog") {
                scene_.fogs.push_back(parse_fog_block(next()));
                return true;
            }
            if (w == "media" || w == "rainbow") {
                Token item = next();
                skip_unsupported(item, Arity::Block, "atmospheric effect '" + w + "'");
                return true;
            }
            if (w == "declare" || w == "local" || w == "include") {
                fail(t, "'" + w + "' needs a '#' before it");
            }
        }
        if (starts_object(t)) {
            std::optional<ObjectNode> object = parse_object();
            add_object_to_scene(*object);
            return true;
        }
        reject_unknown_word(t);
        fail(t, "expected an object, camera, light_source or directive, got " + describe(t));
    }
}

void SceneParser::add_object_to_scene(const ObjectNode& object) {
    // POV-Ray gives untextured objects the default texture as each top-level object is
    // finished (Post_Process), so a later #default does not change them.
    flatten_object(object, default_texture_, scene_);
}

void SceneParser::parse_global_settings(const Token& kw) {
    expect_open_brace(kw);
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        if (t.is_word("assumed_gamma")) {
            next();
            if (peek_word("srgb")) {
                Token item = next();
                unsupported(item, "assumed_gamma srgb");
                continue;
            }
            Token at = peek(0);
            double gamma = parse_float();
            if (gamma <= 0.0) fail(at, "assumed_gamma must be positive");
            scene_.global.assumed_gamma = gamma;
            assumed_gamma_ = gamma;
            gamma_set_ = true;
            continue;
        }
        if (t.is_word("max_trace_level")) {
            Token item = next();
            const double level = parse_float();
            if (level >= kMaxTraceLevelLimit + 1) {
                add_message(item, "warning",
                            "max_trace_level " + shortest(std::trunc(level)) + " reduced to 256");
            }
            scene_.global.max_trace_level =
                static_cast<int>(std::clamp(level, 1.0, double(kMaxTraceLevelLimit)));
            continue;
        }
        if (t.is_word("ambient_light")) {
            next();
            scene_.global.ambient_light = parse_rgb_colour();
            continue;
        }
        if (t.is_word("max_intersections")) {
            next();  // no effect in POV-Ray 3.7
            parse_float();
            continue;
        }
        if (parse_material_global_setting()) continue;
        if (t.is_word("charset")) {
            Token item = next();
            unsupported(item, "global setting 'charset'");
            next();  // ascii, utf8 or sys
            continue;
        }
        if (is_keyword(t)) {
            bool known = false;
            for (const ItemArity& s : kUnsupportedGlobalSettings) {
                if (t.is_word(s.name)) {
                    Token item = next();
                    skip_unsupported(item, s.arity, "global setting '" + item.text() + "'");
                    known = true;
                    break;
                }
            }
            if (known) continue;
        }
        reject_unknown_word(t);
        break;
    }
    expect_close_brace(kw);
}

void SceneParser::parse_background(const Token& kw) {
    expect_open_brace(kw);
    scene_.background = parse_colour(true);
    expect_close_brace(kw);
}

void SceneParser::parse_sky_sphere(const Token& kw) {
    SkySphere sky = parse_sky_sphere_value(kw);
    if (scene_.sky_sphere) {
        add_message(kw, "warning", "more than one sky_sphere: the last one is used");
    }
    scene_.sky_sphere = std::move(sky);
}

SkySphere SceneParser::parse_sky_sphere_value(const Token& kw) {
    expect_open_brace(kw);
    SkySphere sky;
    sky.loc = kw.loc();
    if (const Value* v = peek_identifier_value(0); v && v->holds<SkySphere>()) {
        sky = identifier_as<SkySphere>(next(), "a sky_sphere");
    }
    while (true) {
        const Token t = peek(0);
        if (t.is_punct("}")) break;
        Transform tr;
        if (parse_transform_item(tr)) {
            sky.transform = compose_transforms(sky.transform, tr);
            continue;
        }
        if (t.is_word("pigment")) {
            Token item = next();
            Pigment p;  // black, as POV-Ray's Create_Pigment
            expect_open_brace(item);
            parse_pigment_body(p, item);
            expect_close_brace(item);
            finish_pigment(p);
            sky.pigments.push_back(std::move(p));
            continue;
        }
        if (t.is_word("emission")) {
            next();
            sky.emission = parse_rgb_colour();
            continue;
        }
        reject_unknown_word(t);
        break;
    }
    expect_close_brace(kw);
    if (sky.pigments.empty()) fail(kw, "a sky_sphere needs at least one pigment");
    return sky;
}

void SceneParser::export_symbols() {
    for (const auto& [name, sym] : tables_[0]) {
        if (sym->loc.file == "<image size>") continue;
        Declared d;
        d.loc = sym->loc;
        if (const char* kind = material_kind(sym->value)) scene_.material_symbols[name] = kind;
        if (auto* n = sym->value.get_if<Numeric>()) {
            if (n->size == 1) {
                d.value = n->v[0];
            } else if (n->size == 3) {
                d.value = n->xyz();
            } else {
                continue;
            }
        } else if (auto* s = sym->value.get_if<std::string>()) {
            d.value = *s;
        } else {
            continue;
        }
        scene_.symbols[name] = d;
    }
}

// ---------------------------------------------------------------------------------------
// Lenient mode

void SceneParser::unsupported(const Token& at, const std::string& description) {
    if (opaque_capture_ && !opaque_capture_->captured) {
        // Inside a declaration: the declared value becomes opaque (see OpaqueValue).
        opaque_capture_->captured = true;
        opaque_capture_->reason = "unsupported " + description;
        opaque_capture_->loc = at.loc();
    }
    if (options_.strict && !opaque_capture_) fail(at, "unsupported " + description);
    if (!options_.strict) scene_.skipped.push_back(Skipped{description, at.loc()});
}

void SceneParser::skip_block() {
    Token open = expect_punct("{", "to open a block");
    int depth = 1;
    while (depth > 0) {
        Token t = next();
        if (t.is_eof()) {
            fail(t, "expected '}' to close the '{' opened at " + place(open.loc(), t) +
                        ", got end of file");
        }
        if (t.is_punct("{")) ++depth;
        if (t.is_punct("}")) --depth;
    }
}

void SceneParser::skip_rest_of_block() {
    int depth = 0;
    while (true) {
        const Token& t = peek(0);
        if (t.is_eof()) fail(t, "expected '}', got end of file");
        if (t.is_punct("}") && depth == 0) return;
        if (t.is_punct("{")) ++depth;
        if (t.is_punct("}")) --depth;
        next();
    }
}

void SceneParser::skip_arguments(Arity arity, const Token& keyword) {
    switch (arity) {
        case Arity::None:
            break;
        case Arity::OptionalFloat:
            allow_float(0.0);
            break;
        case Arity::Float:
            parse_float();
            break;
        case Arity::FloatOptionalFloat:
            parse_float();
            accept_comma();
            allow_float(0.0);
            break;
        case Arity::Vector:
            parse_vector();
            break;
        case Arity::Colour:
            parse_colour(true);
            break;
        case Arity::String:
            parse_string(false);
            break;
        case Arity::Block:
            if (!peek_punct("{")) {
                fail(peek(0),
                     "expected '{' after '" + keyword.text() + "', got " + describe(peek(0)));
            }
            skip_block();
            break;
        case Arity::AreaLight:
            parse_vector();
            accept_comma();
            parse_vector();
            accept_comma();
            parse_float();
            accept_comma();
            parse_float();
            break;
        case Arity::Rest:
            skip_rest_of_block();
            break;
    }
}

void SceneParser::skip_unsupported(const Token& keyword, Arity arity,
                                   const std::string& description) {
    unsupported(keyword, description);
    skip_arguments(arity, keyword);
}

}  // namespace scene_detail

namespace {

/// Runs a parse whose main file's text `read` gives; nothing thrown leaves here.
template <class Read>
Result<Scene> run_parse(const std::string& name, const ParseOptions& options, Read read) {
    try {
        scene_detail::SceneParser parser(options);
        auto file = parser.load_file(name, read(parser));
        return parser.parse(file);
    } catch (const scene_detail::ParseFailure& failure) {
        return make_error(failure.message);
    } catch (const std::bad_alloc&) {
        return make_error(name + ": out of memory while parsing");
    } catch (const std::exception& e) {
        // Not expected (the parser reports its own errors); still no exception leaves here.
        return make_error(name + ": internal error while parsing: " + e.what());
    }
}

}  // namespace

Result<Scene> parse_scene_text(std::string_view text, const std::string& name,
                               const ParseOptions& options) {
    return run_parse(name, options, [&](scene_detail::SceneParser&) { return std::string(text); });
}

Result<Scene> parse_scene_file(const std::string& path, const ParseOptions& options) {
    return run_parse(path, options, [&](scene_detail::SceneParser& parser) {
        return parser.read_source(path, nullptr);
    });
}

}  // namespace mirage
