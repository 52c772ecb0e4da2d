// Expressions of the scene language, after POV-Ray 3.7's express.cpp and parsestr.cpp.
//
// Precedence, from loosest: ?: (POV-Ray's Parse_Express), & and | (Parse_Logical),
// comparisons (Parse_Rel_Term), + and - (Parse_Rel_Factor), * and / (Parse_Num_Term),
// factors with unary - + ! and a trailing .x (Parse_Num_Factor).  Where POV-Ray wants a
// float or a vector (a vector's components, an object's parameters) it parses only down from
// + and -, so comparisons there need parentheses, as in POV-Ray.  Mixed sizes widen: a float
// is repeated, a shorter vector padded with zeros.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "scene/keywords.h"
#include "scene/scene_parser.h"
#include "scene/transform.h"
#include "util/format.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON
constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxWidth = 100;  // str() and vstr(): the largest width and precision

bool ftrue(double x) { return std::abs(x) > kEpsilon; }

bool one_of(const std::string& w, std::initializer_list<const char*> words) {
    for (const char* x : words) {
        if (w == x) return true;
    }
    return false;
}

bool is_float_function(const std::string& w) {
    return one_of(w, {"abs",        "acos",        "acosh",   "asc",         "asin",
                      "asinh",      "atan",        "atan2",   "atanh",       "bitwise_and",
                      "bitwise_or", "bitwise_xor", "ceil",    "clock",       "clock_on",
                      "cos",        "cosh",        "defined", "degrees",     "dimension_size",
                      "dimensions", "div",         "exp",     "file_exists", "false",
                      "floor",      "inside",      "int",     "ln",          "log",
                      "max",        "min",         "mod",     "no",          "now",
                      "off",        "on",          "pi",      "pow",         "radians",
                      "rand",       "seed",        "select",  "sin",         "sinh",
                      "sqr",        "sqrt",        "strcmp",  "strlen",      "tan",
                      "tanh",       "true",        "val",     "vdot",        "version",
                      "vlength",    "yes"});
}

bool is_vector_function(const std::string& w) {
    return one_of(w, {"vaxis_rotate", "vcross", "vnormalize", "vrotate", "vturbulence", "x", "y",
                      "z", "min_extent", "max_extent", "trace", "u", "v"});
}

bool is_colour_keyword(const std::string& w) {
    return one_of(w, {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt",
                      "srgbft", "red", "green", "blue", "filter", "transmit", "alpha"});
}

bool is_string_function(const std::string& w) {
    return one_of(w, {"str", "vstr", "concat", "chr", "substr", "strupr", "strlwr", "datetime"});
}

Numeric binary(const Numeric& a0, const Numeric& b0, double (*op)(double, double)) {
    int size = std::max(a0.size, b0.size);
    Numeric a = promote(a0, size), b = promote(b0, size);
    Numeric r;
    r.size = size;
    for (int i = 0; i < size; ++i) r.v[i] = op(a.v[i], b.v[i]);
    return r;
}

double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

Numeric scalar(double x) { return Numeric::scalar(x); }

}  // namespace

// ---------------------------------------------------------------------------------------
// What can start what

bool SceneParser::starts_string(const Token& t) const {
    if (t.kind() == TokenKind::String) return true;
    if (is_keyword(t)) return is_string_function(t.text());
    if (is_identifier(t)) {
        auto sym = t.symbol ? t.symbol : lookup(t.text());
        if (!sym) return false;
        if (auto* a = sym->value.get_if<ArrayValue>()) {
            for (const auto& e : a->elements) {
                if (e) return e->holds<std::string>();
            }
            return false;
        }
        return sym->value.holds<std::string>();
    }
    return false;
}

namespace {
// The size of the numeric value an identifier names (an array: of its elements), or 0.
int identifier_numeric_size(const std::shared_ptr<Symbol>& sym) {
    if (!sym) return 0;
    const Value* v = &sym->value;
    if (auto* a = v->get_if<ArrayValue>()) {
        v = nullptr;
        for (const auto& e : a->elements) {
            if (e) {
                v = e.get();
                break;
            }
        }
        if (!v) return 0;
    }
    if (auto* n = v->get_if<Numeric>()) return n->size;
    return 0;
}
}  // namespace

bool SceneParser::starts_float(const Token& t) const {
    switch (t.kind()) {
        case TokenKind::Number:
            return true;
        case TokenKind::Punct:
            return t.is_punct("(") || t.is_punct("+") || t.is_punct("-") || t.is_punct("!");
        case TokenKind::Identifier: {
            if (is_keyword(t)) return is_float_function(t.text());
            auto sym = t.symbol ? t.symbol : lookup(t.text());
            if (sym && sym->value.holds<std::shared_ptr<const FunctionCode>>()) {
                return true;  // a call of a user function
            }
            return identifier_numeric_size(sym) == 1;
        }
        default:
            return false;
    }
}

bool SceneParser::starts_vector(const Token& t) const {
    if (starts_float(t) || t.is_punct("<")) return true;
    if (is_keyword(t)) return is_vector_function(t.text());
    if (is_identifier(t)) {
        int size = identifier_numeric_size(t.symbol ? t.symbol : lookup(t.text()));
        return size >= 2 && size <= 4;
    }
    return false;
}

bool SceneParser::starts_colour(const Token& t) const {
    if (is_keyword(t)) return is_colour_keyword(t.text());
    if (is_identifier(t)) {
        return identifier_numeric_size(t.symbol ? t.symbol : lookup(t.text())) == 5;
    }
    return false;
}

// ---------------------------------------------------------------------------------------
// Numeric expressions

// Every number the scene computes stays finite: an overflow or an undefined operation is an
// error where it happens (POV-Ray would carry an inf or a NaN on into the scene).
Numeric SceneParser::finite(const Numeric& value, const Token& at) const {
    for (int i = 0; i < value.size; ++i) {
        if (std::isfinite(value.v[i])) continue;
        if (at.kind() == TokenKind::Number) {
            fail(at, "the number " + at.text() + " is out of the range of a double");
        }
        const std::string what = at.kind() == TokenKind::Punct && at.text() != "(" &&
                                         at.text() != "<" && at.text() != "-" && at.text() != "+" &&
                                         at.text() != "!"
                                     ? "'" + at.text() + "'"
                                     : "this expression";
        fail(at, what + " gives " + shortest(value.v[i]) + ", not a finite number");
    }
    return value;
}

Numeric SceneParser::parse_express() {
    Numeric c = parse_logical();
    if (!peek_punct("?")) return c;
    Token q = next();
    Nested nested(*this, q);  // a ? b : c ? d : e ... recurses here
    if (c.size != 1) {
        fail(q, "the condition before '?' must be a float, got a " + numeric_type_name(c.size));
    }
    Numeric a = parse_express();
    expect_punct(":", "between the two choices of '?'");
    Numeric b = parse_express();
    return ftrue(c.v[0]) ? a : b;
}

Numeric SceneParser::parse_logical() {
    Numeric a = parse_rel_term();
    while (true) {
        if (accept_punct("&")) {
            a = binary(a, parse_rel_term(),
                       [](double x, double y) { return (ftrue(x) && ftrue(y)) ? 1.0 : 0.0; });
        } else if (accept_punct("|")) {
            a = binary(a, parse_rel_term(),
                       [](double x, double y) { return (ftrue(x) || ftrue(y)) ? 1.0 : 0.0; });
        } else {
            return a;
        }
    }
}

Numeric SceneParser::parse_rel_term() {
    if (starts_string(peek(0))) {
        std::string lhs = parse_string(false);
        Token op = next();
        std::string rhs = parse_string(false);
        int c = lhs.compare(rhs);
        bool r;
        if (op.is_punct("<")) {
            r = c < 0;
        } else if (op.is_punct("<=")) {
            r = c <= 0;
        } else if (op.is_punct("=")) {
            r = c == 0;
        } else if (op.is_punct("!=")) {
            r = c != 0;
        } else if (op.is_punct(">=")) {
            r = c >= 0;
        } else if (op.is_punct(">")) {
            r = c > 0;
        } else {
            fail(op, "expected a comparison after a string, got " + describe(op));
        }
        return Numeric::scalar(r ? 1.0 : 0.0);
    }
    Numeric a = parse_rel_factor();
    while (true) {
        const Token& op = peek(0);
        double (*f)(double, double) = nullptr;
        if (op.is_punct("<")) {
            f = [](double x, double y) { return x < y ? 1.0 : 0.0; };
        } else if (op.is_punct("<=")) {
            f = [](double x, double y) { return (x <= y || !ftrue(x - y)) ? 1.0 : 0.0; };
        } else if (op.is_punct("=")) {
            f = [](double x, double y) { return !ftrue(x - y) ? 1.0 : 0.0; };
        } else if (op.is_punct("!=")) {
            f = [](double x, double y) { return ftrue(x - y) ? 1.0 : 0.0; };
        } else if (op.is_punct(">=")) {
            f = [](double x, double y) { return (x >= y || !ftrue(x - y)) ? 1.0 : 0.0; };
        } else if (op.is_punct(">")) {
            f = [](double x, double y) { return x > y ? 1.0 : 0.0; };
        } else {
            return a;
        }
        next();
        a = binary(a, parse_rel_factor(), f);
    }
}

Numeric SceneParser::parse_rel_factor() {
    Numeric a = parse_num_term();
    while (true) {
        if (peek_punct("+")) {
            Token op = next();
            a = finite(binary(a, parse_num_term(), [](double x, double y) { return x + y; }), op);
        } else if (peek_punct("-")) {
            Token op = next();
            a = finite(binary(a, parse_num_term(), [](double x, double y) { return x - y; }), op);
        } else {
            return a;
        }
    }
}

Numeric SceneParser::parse_num_term() {
    Numeric a = parse_num_factor();
    while (true) {
        if (peek_punct("*")) {
            Token op = next();
            a = finite(binary(a, parse_num_factor(), [](double x, double y) { return x * y; }), op);
        } else if (peek_punct("/")) {
            Token op = next();
            Numeric b = parse_num_factor();
            int size = std::max(a.size, b.size);
            Numeric pb = promote(b, size);
            for (int i = 0; i < size; ++i) {
                // POV-Ray warns and goes on with a huge value; a scene that divides by zero
                // is wrong, so it is an error here.
                if (pb.v[i] == 0.0) fail(op, "division by zero");
            }
            a = finite(binary(a, b, [](double x, double y) { return x / y; }), op);
        } else {
            return a;
        }
    }
}

Numeric SceneParser::parse_num_factor() {
    Numeric value;
    {
        // A factor's own tokens may hold directives and macro calls even where the
        // surrounding expression defers them (POV-Ray's Ok_To_Declare).
        ScopedFlag not_deferred(defer_directives_, false);
        const Token at = peek(0);
        Nested nested(*this, at);
        value = finite(parse_factor_body(), at);
    }
    if (peek_punct(".")) {
        Token dot = next();
        value = apply_period(value, dot);
    }
    return value;
}

int SceneParser::member_index(const Token& member) {
    // POV-Ray's member names (fncode.cpp's compile_member, the same for vectors and colours).
    static const std::pair<const char*, int> kMembers[] = {
        {"x", 0},   {"y", 1},     {"z", 2},    {"t", 3},      {"u", 0},        {"v", 1},
        {"red", 0}, {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}, {"gray", 5}};
    for (const auto& [name, index] : kMembers) {
        if (member.is_word(name)) return index;
    }
    return -1;
}

Numeric SceneParser::apply_period(const Numeric& value, const Token& dot) {
    Token c = next();
    const int index = member_index(c);
    if (index == 5) {
        Numeric n = promote(value, 3);
        return Numeric::scalar(greyscale(glm::dvec3(n.v[0], n.v[1], n.v[2])));
    }
    if (index < 0) {
        fail(c,
             "expected x, y, z, t, u, v, red, green, blue, filter, transmit or gray after '.', "
             "got " +
                 describe(c));
    }
    if (index >= value.size) {
        fail(c, "cannot take '." + c.text() + "' of a " + numeric_type_name(value.size));
    }
    (void)dot;
    return Numeric::scalar(value.v[index]);
}

Numeric SceneParser::parse_factor_body() {
    Token t = next();
    switch (t.kind()) {
        case TokenKind::Number:
            return Numeric::scalar(t.raw->number);
        case TokenKind::Punct:
            if (t.is_punct("(")) {
                Numeric n = parse_express();
                const Token& close = peek(0);
                if (!close.is_punct(")")) {
                    fail(close, "expected ')' to close the '(' at " + place(t.loc(), close) +
                                    ", got " + describe(close));
                }
                next();
                return n;
            }
            if (t.is_punct("<")) {
                Numeric n;
                n.v[0] = parse_float();
                accept_comma();
                n.v[1] = parse_float();
                accept_comma();
                n.size = 2;
                while (n.size < 5 && starts_expression(peek(0))) {
                    n.v[n.size++] = parse_float();
                    accept_comma();
                }
                const Token& close = peek(0);
                if (!close.is_punct(">")) {
                    fail(close, "expected '>' to close the vector opened at " +
                                    place(t.loc(), close) + ", got " + describe(close));
                }
                next();
                return n;
            }
            if (t.is_punct("-")) {
                Numeric n = parse_num_factor();
                for (int i = 0; i < n.size; ++i) n.v[i] = -n.v[i];
                return n;
            }
            if (t.is_punct("+")) return parse_factor_body();
            if (t.is_punct("!")) {
                Numeric n = parse_num_factor();
                for (int i = 0; i < n.size; ++i) n.v[i] = ftrue(n.v[i]) ? 0.0 : 1.0;
                return n;
            }
            break;
        case TokenKind::Identifier:
            if (is_keyword(t)) return parse_function(t);
            return parse_identifier_value(t);
        default:
            break;
    }
    fail(t, "expected a numeric expression, got " + describe(t));
}

Numeric SceneParser::parse_identifier_value(const Token& t) {
    std::shared_ptr<Symbol> sym = t.symbol ? t.symbol : lookup(t.text());
    if (!sym) fail(t, "undefined identifier '" + t.text() + "'");
    const Value* value = &sym->value;
    if (auto* a = sym->value.get_if<ArrayValue>()) {
        if (!peek_array_index()) {
            fail(peek(0),
                 "expected '[' after the array '" + t.text() + "', got " + describe(peek(0)));
        }
        Token at = peek(0);
        std::shared_ptr<Value>& e = index_array(*a, t);
        if (!e) fail(at, "element of the array '" + t.text() + "' used before it is set");
        value = e.get();
    }
    value = &use_value(t, *sym, *value);  // an opaque value's use fails here, naming its reason
    if (auto* n = value->get_if<Numeric>()) return *n;
    if (auto* f = value->get_if<std::shared_ptr<const FunctionCode>>()) {
        return Numeric::scalar(call_function_value(t, **f));  // parse_functions.cpp
    }
    fail(t, "expected a numeric expression, got " + value_type_name(*value) + " identifier '" +
                t.text() + "'");
}

double SceneParser::rand_next(int stream, const Token& at) {
    if (stream < 0 || static_cast<std::size_t>(stream) >= rand_streams_.size()) {
        fail(at, "rand() of an unknown random stream " + std::to_string(stream) +
                     " (create one with seed())");
    }
    // POV-Ray's POV_rand (support/randomsequences.cpp), a 32-bit linear congruential generator.
    unsigned& state = rand_streams_[static_cast<std::size_t>(stream)];
    state = state * 1812433253u + 12345u;
    return static_cast<double>(state) / 4294967295.0;
}

/// The built-in constants: pi, true, clock, version, x, t, u...
std::optional<Numeric> SceneParser::builtin_constant(const std::string& f) const {
    if (f == "pi") return scalar(kPi);
    if (f == "true" || f == "yes" || f == "on") return scalar(1.0);
    if (f == "false" || f == "no" || f == "off") return scalar(0.0);
    if (f == "clock") return scalar(animation_.clock);
    if (f == "clock_on") return scalar(animation_.clock_on ? 1.0 : 0.0);
    if (f == "version") return scalar(std::round(language_version_ * 100.0) / 100.0);
    if (f == "x") return Numeric::vector3(glm::dvec3(1.0, 0.0, 0.0));
    if (f == "y") return Numeric::vector3(glm::dvec3(0.0, 1.0, 0.0));
    if (f == "z") return Numeric::vector3(glm::dvec3(0.0, 0.0, 1.0));
    if (f == "t") {
        Numeric n;
        n.size = 4;
        n.v[3] = 1.0;
        return n;
    }
    if (f == "u" || f == "v") {
        Numeric n;
        n.size = 2;
        n.v[f == "u" ? 0 : 1] = 1.0;
        return n;
    }
    return std::nullopt;
}

/// The functions of one float: abs, sin, sqrt, seed, rand...
std::optional<Numeric> SceneParser::parse_one_float_function(const Token& name) {
    const std::string& f = name.text();
    struct Unary {
        const char* name;
        double (*fn)(double);
    };
    static const Unary kUnary[] = {
        {"abs", [](double x) { return std::abs(x); }},
        {"acosh", [](double x) { return std::acosh(x); }},
        {"asinh", [](double x) { return std::asinh(x); }},
        {"atan", [](double x) { return std::atan(x); }},
        {"atanh", [](double x) { return std::atanh(x); }},
        {"ceil", [](double x) { return std::ceil(x); }},
        {"cos", [](double x) { return std::cos(x); }},
        {"cosh", [](double x) { return std::cosh(x); }},
        {"degrees", [](double x) { return x * 180.0 / kPi; }},
        {"exp", [](double x) { return std::exp(x); }},
        {"floor", [](double x) { return std::floor(x); }},
        {"int", [](double x) { return std::trunc(x); }},
        {"radians", [](double x) { return x * kPi / 180.0; }},
        {"sin", [](double x) { return std::sin(x); }},
        {"sinh", [](double x) { return std::sinh(x); }},
        {"sqr", [](double x) { return x * x; }},
        {"tan", [](double x) { return std::tan(x); }},
        {"tanh", [](double x) { return std::tanh(x); }},
    };
    for (const Unary& u : kUnary) {
        if (f == u.name) return scalar(u.fn(parse_float_param()));
    }
    if (f == "acos" || f == "asin") {
        double x = parse_float_param();
        if (x > 1.0 || x < -1.0) {
            add_message(name, "warning", "domain error in " + f + ", argument clipped to [-1, 1]");
            x = std::clamp(x, -1.0, 1.0);
        }
        return scalar(f == "acos" ? std::acos(x) : std::asin(x));
    }
    if (f == "sqrt") {
        double x = parse_float_param();
        if (x < 0.0) fail(name, "sqrt of a negative number (" + format_str(x, 0, -1) + ")");
        return scalar(std::sqrt(x));
    }
    if (f == "ln" || f == "log") {
        double x = parse_float_param();
        if (x <= 0.0)
            fail(name, f + " of a number that is not positive (" + format_str(x, 0, -1) + ")");
        return scalar(f == "ln" ? std::log(x) : std::log10(x));
    }
    if (f == "seed") {
        double s = parse_float_param();
        rand_streams_.push_back(static_cast<unsigned>(int_value(s, name, "seed")));
        return scalar(static_cast<double>(rand_streams_.size() - 1));
    }
    if (f == "rand") {
        Token at = peek(0);
        return scalar(rand_next(int_value(parse_float_param(), at, "rand() stream"), at));
    }
    return std::nullopt;
}

/// The functions of two or more floats: atan2, pow, min, bitwise_and, select...
std::optional<Numeric> SceneParser::parse_float_list_function(const Token& name) {
    const std::string& f = name.text();
    if (f == "atan2" || f == "div" || f == "mod" || f == "pow") {
        expect_punct("(", "after '" + f + "'");
        double a = parse_float();
        accept_comma();
        double b = parse_float();
        expect_punct(")", "after the arguments of '" + f + "'");
        if (f == "atan2") {
            if (!ftrue(a) && !ftrue(b)) fail(name, "atan2(0, 0) is undefined");
            return scalar(std::atan2(a, b));
        }
        if (f == "pow") {
            if (a == 0.0 && b == 0.0) fail(name, "pow(0, 0) is undefined");
            return scalar(std::pow(a, b));
        }
        if (b == 0.0) fail(name, "division by zero in " + f + "()");
        if (f == "div") return scalar(std::trunc(a / b));
        return scalar(std::fmod(a, b));
    }
    if (f == "min" || f == "max" || f == "bitwise_and" || f == "bitwise_or" || f == "bitwise_xor") {
        expect_punct("(", "after '" + f + "'");
        const bool bitwise = f.rfind("bitwise", 0) == 0;
        Token at = peek(0);
        double r = parse_float();
        if (bitwise) r = int_value(r, at, "an argument of " + f + "()");
        while (accept_punct(",")) {
            at = peek(0);
            double b = parse_float();
            if (f == "min") r = std::min(r, b);
            if (f == "max") r = std::max(r, b);
            if (!bitwise) continue;
            const int x = static_cast<int>(r), y = int_value(b, at, "an argument of " + f + "()");
            if (f == "bitwise_and") r = x & y;
            if (f == "bitwise_or") r = x | y;
            if (f == "bitwise_xor") r = x ^ y;
        }
        expect_punct(")", "after the arguments of '" + f + "'");
        return scalar(r);
    }
    if (f == "select") {
        expect_punct("(", "after 'select'");
        double c = parse_float();
        accept_comma();
        double less = parse_float();
        accept_comma();
        double equal = parse_float();
        if (accept_punct(",")) {
            double greater = parse_float();
            expect_punct(")", "after the arguments of 'select'");
            return scalar(c < 0.0 ? less : (c == 0.0 ? equal : greater));
        }
        expect_punct(")", "after the arguments of 'select'");
        return scalar(c < 0.0 ? less : equal);
    }
    return std::nullopt;
}

/// The numeric functions of strings: strlen, val, asc, file_exists, strcmp.
std::optional<Numeric> SceneParser::parse_string_argument_function(const Token& name) {
    const std::string& f = name.text();
    if (f == "strlen" || f == "val" || f == "asc" || f == "file_exists") {
        expect_punct("(", "after '" + f + "'");
        std::string s = parse_string(f == "file_exists");
        expect_punct(")", "after the argument of '" + f + "'");
        if (f == "strlen") return scalar(static_cast<double>(s.size()));
        if (f == "val") return scalar(std::atof(s.c_str()));
        if (f == "asc") return scalar(s.empty() ? 0.0 : static_cast<unsigned char>(s[0]));
        return scalar(find_scene_file(s).empty() ? 0.0 : 1.0);
    }
    if (f == "strcmp") {
        expect_punct("(", "after 'strcmp'");
        std::string a = parse_string(false);
        accept_comma();
        std::string b = parse_string(false);
        expect_punct(")", "after the arguments of 'strcmp'");
        int c = a.compare(b);
        return scalar(c < 0 ? -1.0 : (c > 0 ? 1.0 : 0.0));
    }
    return std::nullopt;
}

/// The functions of vectors: vdot, vcross, vrotate, vlength, vnormalize, vaxis_rotate.
std::optional<Numeric> SceneParser::parse_vector_function(const Token& name) {
    const std::string& f = name.text();
    if (f == "vdot" || f == "vcross" || f == "vrotate") {
        expect_punct("(", "after '" + f + "'");
        glm::dvec3 a = parse_vector();
        accept_comma();
        glm::dvec3 b = parse_vector();
        expect_punct(")", "after the arguments of '" + f + "'");
        if (f == "vdot") return scalar(glm::dot(a, b));
        if (f == "vcross") return Numeric::vector3(glm::cross(a, b));
        return Numeric::vector3(transform_point(make_rotation(b), a));
    }
    if (f == "vlength" || f == "vnormalize") {
        expect_punct("(", "after '" + f + "'");
        glm::dvec3 a = parse_vector();
        expect_punct(")", "after the argument of '" + f + "'");
        if (f == "vlength") return scalar(glm::length(a));
        if (a == glm::dvec3(0.0)) {
            add_message(name, "warning", "vnormalize of a zero-length vector");
            return Numeric::vector3(glm::dvec3(0.0));
        }
        return Numeric::vector3(glm::normalize(a));
    }
    if (f == "vaxis_rotate") {
        expect_punct("(", "after 'vaxis_rotate'");
        glm::dvec3 p = parse_vector();
        accept_comma();
        glm::dvec3 axis = parse_vector();
        accept_comma();
        double degrees = parse_float();
        expect_punct(")", "after the arguments of 'vaxis_rotate'");
        if (glm::length(axis) == 0.0) fail(name, "vaxis_rotate about a zero-length axis");
        return Numeric::vector3(transform_point(make_axis_rotation(axis, degrees), p));
    }
    return std::nullopt;
}

/// The sizes of an array: dimensions, dimension_size.
std::optional<Numeric> SceneParser::parse_array_function(const Token& name) {
    const std::string& f = name.text();
    if (f == "dimensions" || f == "dimension_size") {
        expect_punct("(", "after '" + f + "'");
        Token a = next();
        auto sym = is_identifier(a) ? (a.symbol ? a.symbol : lookup(a.text())) : nullptr;
        auto* array = sym ? sym->value.get_if<ArrayValue>() : nullptr;
        if (!array) fail(a, "expected an array identifier, got " + describe(a));
        double r = static_cast<double>(array->sizes.size());
        if (f == "dimension_size") {
            accept_comma();
            const double d = parse_float() - 1.0;
            r = (d < 0.0 || d >= static_cast<double>(array->sizes.size()))
                    ? 0.0
                    : array->sizes[static_cast<std::size_t>(d)];
        }
        expect_punct(")", "after the arguments of '" + f + "'");
        return scalar(r);
    }
    return std::nullopt;
}

Numeric SceneParser::parse_function(const Token& name) {
    const std::string& f = name.text();
    if (auto n = builtin_constant(f)) return *n;
    if (auto n = parse_one_float_function(name)) return *n;
    if (auto n = parse_float_list_function(name)) return *n;
    if (auto n = parse_string_argument_function(name)) return *n;
    if (auto n = parse_vector_function(name)) return *n;
    if (auto n = parse_array_function(name)) return *n;
    if (f == "defined") return Numeric::scalar(parse_ifdef_param() ? 1.0 : 0.0);

    if (one_of(f, {"inside", "trace", "min_extent", "max_extent"})) {
        return parse_object_function(name);  // parse_queries.cpp
    }
    if (one_of(f, {"now", "vturbulence"})) {
        fail(name, "unsupported function '" + f + "'");
    }
    if (is_string_function(f)) {
        fail(name, "expected a numeric expression, got the string function '" + f + "'");
    }
    if (is_colour_keyword(f)) {
        fail(name, "expected a numeric expression, got '" + f +
                       "' (colour keywords cannot appear inside an expression)");
    }
    fail(name, "expected a numeric expression, got " + describe(name));
}

// ---------------------------------------------------------------------------------------
// Floats, vectors and colours where POV-Ray wants them

double SceneParser::parse_float() {
    Token at = peek(0);
    Numeric n = parse_rel_factor();
    if (n.size != 1) fail(at, "expected a float, got a " + numeric_type_name(n.size));
    return n.v[0];
}

double SceneParser::parse_float_param() {
    Token open = expect_punct("(", "before the parameter");
    Token at = peek(0);
    Numeric n = parse_express();
    if (n.size != 1) fail(at, "expected a float, got a " + numeric_type_name(n.size));
    const Token& close = peek(0);
    if (!close.is_punct(")")) {
        fail(close, "expected ')' to close the '(' at " + place(open.loc(), close) + ", got " +
                        describe(close));
    }
    next();
    return n.v[0];
}

double SceneParser::allow_float(double default_value) {
    return starts_expression(peek(0)) ? parse_float() : default_value;
}

glm::dvec3 SceneParser::parse_vector() {
    Token at = peek(0);
    Numeric n = parse_rel_factor();
    if (n.size > 3) fail(at, "expected a vector, got a " + numeric_type_name(n.size));
    return promote(n, 3).xyz();
}

Numeric SceneParser::parse_vector_n(int size, std::string_view what) {
    Token at = peek(0);
    Numeric n = parse_rel_factor();
    if (n.size > size) {
        fail(at, "expected " + std::string(what) + ", got a " + numeric_type_name(n.size));
    }
    return promote(n, size);
}

glm::dvec3 SceneParser::parse_scale_vector() {
    Token at = peek(0);
    glm::dvec3 s = parse_vector();
    for (int i = 0; i < 3; ++i) {
        if (s[i] == 0.0) {
            // POV-Ray's Parse_Scale_Vector does the same.
            add_message(at, "warning", std::string("scale by 0 in ") + "xyz"[i] + ", changed to 1");
            s[i] = 1.0;
        }
    }
    return s;
}

// POV-Ray's Parse_Colour: an optional `color`, then rgb/rgbf/rgbt/rgbft/srgb... with an
// expression, a colour identifier or expression, and any number of red/green/blue/filter/
// transmit items changing one component.
Colour SceneParser::parse_colour(bool expect_filter_transmit) {
    const int terms = expect_filter_transmit ? 5 : 3;
    bool had_keyword = accept_word("color") || accept_word("colour");
    Numeric c;
    c.size = 5;
    bool started = false;
    while (true) {
        Token t = peek(0);
        if (is_keyword(t) && is_colour_keyword(t.text()) && !t.is_word("color") &&
            !t.is_word("colour")) {
            const std::string& w = t.text();
            if (w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit" ||
                w == "alpha") {
                next();
                int index = w == "red"        ? 0
                            : w == "green"    ? 1
                            : w == "blue"     ? 2
                            : w == "transmit" ? 4
                                              : 3;
                c.v[index] = parse_float();
                started = true;
                continue;
            }
            if (started) break;
            next();
            bool srgb = w[0] == 's';
            std::string kind = srgb ? w.substr(1) : w;
            if (srgb && !gamma_set_) {
                fail(t, "'" + w + "' needs assumed_gamma to be set first (in global_settings)");
            }
            int size = kind == "rgb" ? 3 : kind == "rgbft" ? 5 : 4;
            Numeric n = promote(parse_express(), size);
            for (int i = 0; i < std::min(n.size, 5); ++i) c.v[i] = n.v[i];
            if (kind == "rgbt") {
                c.v[4] = c.v[3];
                c.v[3] = 0.0;
            }
            if (srgb) {
                for (int i = 0; i < 3; ++i) {
                    c.v[i] = std::pow(srgb_to_linear(c.v[i]), 1.0 / assumed_gamma_);
                }
            }
            started = true;
            continue;
        }
        if (starts_colour(t) || starts_vector(t)) {
            if (started) break;
            // POV-Ray widens whatever comes (a float to all five components, a vector with
            // zeros): `color 0.5` has filter and transmit 0.5 too, `color <1, 0, 0>` is red.
            Numeric n = promote(parse_express(), terms);
            for (int i = 0; i < std::min(n.size, 5); ++i) c.v[i] = n.v[i];
            started = true;
            continue;
        }
        break;
    }
    if (!started) {
        fail(peek(0), std::string("expected a colour") + (had_keyword ? " after 'color'" : "") +
                          ", got " + describe(peek(0)));
    }
    return numeric_to_colour(c);
}

glm::dvec3 SceneParser::parse_rgb_colour() {
    Token at = peek(0);
    Colour c = parse_colour(false);
    if (c.filter != 0.0 || c.transmit != 0.0) {
        add_message(at, "warning", "filter and transmit have no effect here and are ignored");
    }
    return c.rgb;
}

// ---------------------------------------------------------------------------------------
// Strings

std::string SceneParser::format_str(double value, int width, int precision) const {
    // POV-Ray's str(): "%<width>.<precision>f", a negative width meaning zero padding and a
    // negative precision the default.
    char format[32];
    int at = std::snprintf(format, sizeof format, "%%");
    if (width > 0) at += std::snprintf(format + at, sizeof format - at, "%d", width);
    if (width < 0) at += std::snprintf(format + at, sizeof format - at, "0%d", -width);
    if (precision >= 0) at += std::snprintf(format + at, sizeof format - at, ".%d", precision);
    std::snprintf(format + at, sizeof format - at, "f");
    char buffer[512];
    int n = std::snprintf(buffer, sizeof buffer, format, value);
    if (n < 0 || n >= static_cast<int>(sizeof buffer)) {
        format[at] = 'g';
        std::snprintf(buffer, sizeof buffer, format, value);
    }
    return buffer;
}

std::string SceneParser::parse_string(bool pathname) {
    const Token at = peek(0);
    Nested nested(*this, at);
    std::string s = parse_string_body(pathname);
    check_string_size(s, at);
    return s;
}

std::string SceneParser::parse_string_body(bool pathname) {
    Token t = next();
    if (t.kind() == TokenKind::String) {
        if (pathname) return t.text();
        std::size_t bad = 0;
        auto s = unescape_string(t.text(), &bad);
        if (!s) {
            fail(t, "illegal escape sequence '" + t.text().substr(bad, 2) + "' in a string");
        }
        return *s;
    }
    if (is_identifier(t)) {
        Value v = identifier_value(t);
        if (auto* s = v.get_if<std::string>()) return *s;
        fail(t, "expected a string, got " + value_type_name(v) + " identifier '" + t.text() + "'");
    }
    const std::string& f = t.text();
    if (is_keyword(t) && is_string_function(f)) {
        expect_punct("(", "after '" + f + "'");
        std::string result;
        if (f == "str") {
            double v = parse_float();
            accept_comma();
            Token at = peek(0);
            const int width =
                int_value(parse_float(), at, "the width of str()", -kMaxWidth, kMaxWidth);
            accept_comma();
            at = peek(0);
            const int precision =
                int_value(parse_float(), at, "the precision of str()", -kMaxWidth, kMaxWidth);
            result = format_str(v, width, precision);
        } else if (f == "vstr") {
            int dims = static_cast<int>(std::clamp(parse_float(), 2.0, 5.0));
            accept_comma();
            Numeric n = parse_rel_factor();
            // A float is not repeated here: POV-Ray's Parse_Unknown_Vector pads with zeros.
            if (n.size == 1) {
                for (int i = 1; i < 5; ++i) n.v[i] = 0.0;
            }
            n = promote(n, 5);
            accept_comma();
            std::string separator = parse_string(pathname);
            accept_comma();
            Token at = peek(0);
            const int width =
                int_value(parse_float(), at, "the width of vstr()", -kMaxWidth, kMaxWidth);
            accept_comma();
            at = peek(0);
            const int precision =
                int_value(parse_float(), at, "the precision of vstr()", -kMaxWidth, kMaxWidth);
            for (int i = 0; i < dims; ++i) {
                if (i) result += separator;
                result += format_str(n.v[i], width, precision);
            }
        } else if (f == "concat") {
            result = parse_string(pathname);
            while (accept_punct(",")) result += parse_string(pathname);
        } else if (f == "chr") {
            const double code = parse_float();
            if (!(code >= 0.0 && code < 0x10000)) fail(t, "chr() of a code out of range");
            append_utf8(result, static_cast<unsigned>(code));
        } else if (f == "substr") {
            std::string s = parse_string(pathname);
            accept_comma();
            const double start = std::trunc(parse_float());
            accept_comma();
            const double length = std::trunc(parse_float());
            if (!(start >= 1.0 && length >= 0.0 &&
                  start + length - 1.0 <= static_cast<double>(s.size()))) {
                fail(t, "substr(\"" + s.substr(0, 40) + (s.size() > 40 ? "..." : "") + "\", " +
                            shortest(start) + ", " + shortest(length) + ") is outside the string");
            }
            result =
                s.substr(static_cast<std::size_t>(start - 1), static_cast<std::size_t>(length));
        } else if (f == "strupr" || f == "strlwr") {
            result = parse_string(pathname);
            for (char& ch : result) {
                ch =
                    static_cast<char>(f == "strupr" ? std::toupper(static_cast<unsigned char>(ch))
                                                    : std::tolower(static_cast<unsigned char>(ch)));
            }
        } else {
            fail(t, "unsupported function '" + f + "'");
        }
        expect_punct(")", "after the arguments of '" + f + "'");
        return result;
    }
    fail(t, "expected a string, got " + describe(t));
}

}  // namespace mirage::scene_detail
