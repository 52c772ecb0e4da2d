// Values: the right-hand side of #declare, macro arguments (POV-Ray's Parse_RValue), and
// array declarations with their initializers.
#include "scene/keywords.h"
#include "scene/scene_parser.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

// A punctuation mark that continues an expression after an identifier.
bool continues_expression(const Token& t) {
    if (t.kind() != TokenKind::Punct) return false;
    for (const char* p : {"+", "-", "*", "/", ".", "[", "?", "<", ">", "=", "!", "&", "|"}) {
        if (t.text() == p) return true;
    }
    return false;
}

}  // namespace

Value SceneParser::parse_rvalue(const Token& for_name, bool is_macro_argument) {
    const Token t = peek(0);
    // Floats, vectors and colours need a ';' after a #declare (POV-Ray 3.5 and later); the
    // look for it must not run the directive that may follow.
    auto finish_numeric = [&](const Numeric& n) -> Value {
        if (!is_macro_argument) {
            ScopedFlag defer(defer_directives_, true);
            if (!accept_punct(";")) {
                fail(peek(0), "expected ';' after the value of '" + for_name.text() + "', got " +
                                  describe(peek(0)));
            }
        }
        return Value{n};
    };
    auto finish_other = [&](Value v) -> Value {
        if (!is_macro_argument) {
            ScopedFlag defer(defer_directives_, true);
            accept_punct(";");
        }
        return v;
    };
    auto numeric = [&]() -> Value {
        Numeric n;
        {
            ScopedFlag defer(defer_directives_, true);
            n = parse_rel_factor();
        }
        return finish_numeric(n);
    };

    if (is_identifier(t)) {
        // A copy keeps an opaque value opaque; one used in an expression is a use.
        const Value* v;
        {
            ScopedFlag copying(copying_value_, true);
            v = peek_identifier_value(0);
        }
        if (!v && !t.symbol && !lookup(t.text())) {
            fail(t, "undefined identifier '" + t.text() + "'");
        }
        if (v && v->holds<Numeric>()) return numeric();
        if (v && v->holds<std::shared_ptr<const FunctionCode>>()) {
            ScopedFlag defer(defer_directives_, true);
            if (peek(1).is_punct("(")) return numeric();  // F(...): a call, not a copy
        }
        if (v && v->holds<OpaqueValue>()) {
            ScopedFlag defer(defer_directives_, true);
            // An operator after it, or '(' (a call of a function kept opaque): a use.
            if (continues_expression(peek(1)) || peek(1).is_punct("(")) return numeric();
        }
        Token name = next();
        ScopedFlag copying(copying_value_, true);
        return finish_other(identifier_value(name));
    }
    if (starts_string(t)) return finish_other(Value{parse_string(false)});
    if (starts_colour(t)) {
        Colour c;
        {
            ScopedFlag defer(defer_directives_, true);
            c = parse_colour(true);
        }
        return finish_numeric(Numeric::colour(c));
    }
    if (starts_vector(t)) return numeric();
    if (is_keyword(t)) {
        const std::string& w = t.text();
        if (w == "pigment") {
            Token kw = next();
            Pigment p = default_texture_.pigment;
            expect_open_brace(kw);
            parse_pigment_body(p, kw);
            expect_close_brace(kw);
            return finish_other(Value{p});
        }
        if (w == "finish") {
            Token kw = next();
            Finish f = default_texture_.finish;
            parse_finish_block(f, kw);
            return finish_other(Value{f});
        }
        if (w == "texture") {
            Token kw = next();
            expect_open_brace(kw);
            Texture tex = parse_texture_body(kw);
            expect_close_brace(kw);
            // More textures would be layered on top.
            while (true) {
                {
                    ScopedFlag defer(defer_directives_, true);
                    if (!peek_word("texture")) break;
                }
                Token layer = next();
                expect_open_brace(layer);
                Texture top = parse_texture_body(layer);
                expect_close_brace(layer);
                layer_texture(tex, std::move(top), layer);
            }
            return finish_other(Value{tex});
        }
        if (w == "color_map" || w == "colour_map") {
            Token kw = next();
            return finish_other(Value{ColourMapValue{parse_colour_map(kw)}});
        }
        if (w == "transform") {
            Token kw = next();
            return finish_other(Value{parse_transform_block(kw)});
        }
        if (w == "camera") {
            Token kw = next();
            return finish_other(Value{parse_camera(kw)});
        }
        if (w == "sky_sphere") {
            Token kw = next();
            return finish_other(Value{parse_sky_sphere_value(kw)});
        }
        if (w == "array") {
            Token kw = next();
            return finish_other(parse_array_declaration(kw));
        }
        if (w == "function") {
            Token kw = next();
            return finish_other(parse_function_value(kw));
        }
        if (auto m = parse_material_value()) return finish_other(std::move(*m));
        static const char* const kUnsupportedValues[] = {
            "normal",     "interior",    "material",  "media",       "density",
            "fog",        "rainbow",     "spline",    "function",    "pigment_map",
            "normal_map", "texture_map", "slope_map", "density_map", "interior_texture"};
        for (const char* u : kUnsupportedValues) {
            if (w == u) return finish_other(parse_unsupported_value(next()));
        }
        if (starts_object(t)) {
            std::optional<ObjectNode> object = parse_object();
            return finish_other(Value{std::move(*object)});
        }
    }
    fail(t, "expected a value for '" + for_name.text() + "', got " + describe(t));
}

Value SceneParser::parse_unsupported_value(const Token& keyword) {
    unsupported(keyword, "'" + keyword.text() + "'");
    if (keyword.is_word("function") && peek_punct("(")) {
        // function (x, y, z) { ... }
        while (!peek_punct(")") && !peek(0).is_eof()) next();
        expect_punct(")", "after the function parameters");
    }
    if (peek_punct("{")) skip_block();
    return Value{OpaqueValue{keyword.text(), "", FileLoc{}}};
}

Value SceneParser::parse_array_declaration(const Token& keyword) {
    ArrayValue array;
    // Looking for one more dimension or an initializer must not run the directive that
    // may follow (POV-Ray's Parse_Array_Declare clears Ok_To_Declare).
    auto peek_deferred = [&](std::string_view p) {
        ScopedFlag defer(defer_directives_, true);
        return peek_punct(p);
    };
    const std::size_t max_elements = options_.limits.max_array_elements;
    std::size_t total = 1;
    while (peek_deferred("[")) {
        Token open = next();
        double v = parse_float();
        if (!(v + kEpsilon >= 1.0)) fail(open, "an array dimension must be at least 1");
        // Checked before it is multiplied in: the product of the sizes cannot overflow.
        if (v + kEpsilon >= static_cast<double>(max_elements) + 1.0 ||
            total * static_cast<std::size_t>(v + kEpsilon) > max_elements) {
            fail(open, "an array of more than " + std::to_string(max_elements) +
                           " elements, mirage's limit");
        }
        const int n = static_cast<int>(v + kEpsilon);
        total *= static_cast<std::size_t>(n);
        array.sizes.push_back(n);
        expect_punct("]", "after an array dimension");
    }
    if (array.sizes.empty()) {
        fail(peek(0), "expected '[' and a size after 'array', got " + describe(peek(0)));
    }
    count_array_elements(total, keyword);
    array.elements.resize(total);
    if (peek_deferred("{")) parse_array_initializer(array, 0, 0, keyword);
    return Value{std::move(array)};
}

void SceneParser::parse_array_initializer(ArrayValue& array, std::size_t dim, std::size_t base,
                                          const Token& name) {
    Nested nested(*this, peek(0));
    Token open = expect_punct("{", "to start the initializer of an array dimension");
    std::size_t stride = 1;
    for (std::size_t d = dim + 1; d < array.sizes.size(); ++d) {
        stride *= static_cast<std::size_t>(array.sizes[d]);
    }
    for (int i = 0; i < array.sizes[dim]; ++i) {
        if (peek_punct("}")) {
            fail(peek(0), "too few initializers: this array dimension has " +
                              std::to_string(array.sizes[dim]) + " elements");
        }
        std::size_t at = base + static_cast<std::size_t>(i) * stride;
        if (dim + 1 < array.sizes.size()) {
            parse_array_initializer(array, dim + 1, at, name);
        } else {
            Token first = peek(0);
            array.elements[at] = std::make_shared<Value>(parse_rvalue(first, true));
            accept_comma();
        }
    }
    if (!peek_punct("}")) {
        fail(peek(0), "too many initializers: this array dimension has " +
                          std::to_string(array.sizes[dim]) + " elements");
    }
    next();
    if (dim > 0) accept_comma();
    (void)open;
}

}  // namespace mirage::scene_detail
