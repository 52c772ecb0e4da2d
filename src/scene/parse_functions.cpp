// User functions: `function [(parameters)] { expression }` and `function { internal(n) }`
// as POV-Ray 3.7 reads them (parser/fnsyntax.cpp, vm/fncode.cpp), and their calls in float
// expressions (express.cpp's Parse_Function_Call).
//
// The expression syntax is POV-Ray's function syntax, not its float syntax: `<` and `>`
// compare, there is no `!`, `?:` or vectors; precedence from loosest: `|`, `&`, the
// comparisons, `+ -`, `* /`, unary `- +`.  Inside, x y z (and u v) name the parameters, a
// declared float is a constant, a declared function or a built-in (sin, pow, select, sum...) is
// called.  A pigment function is called with a component (F(x, y, z).red), evaluated by the
// tracer only; functions of patterns, splines and transforms are refused as unsupported.
#include <string>
#include <utility>
#include <vector>

#include "scene/function.h"
#include "scene/object_tree.h"
#include "scene/scene_parser.h"

namespace mirage::scene_detail {

namespace {

using Op = FunctionCode::Op;

int add_node(FunctionCode& f, FunctionCode::Node n) {
    f.nodes.push_back(std::move(n));
    return static_cast<int>(f.nodes.size()) - 1;
}

int constant(FunctionCode& f, double v) {
    FunctionCode::Node n;
    n.op = Op::Constant;
    n.value = v;
    return add_node(f, std::move(n));
}

int binary(FunctionCode& f, Op op, int a, int b) {
    FunctionCode::Node n;
    n.op = op;
    n.a = a;
    n.b = b;
    return add_node(f, std::move(n));
}

// The slot of a variable named `name` (a sum's or prod's variable, then a parameter), or -1.
// x and u name the parameter called x or u, y and v the one called y or v (fncode.cpp).
int slot_of(const FunctionCode& f, const std::string& name) {
    const int params = static_cast<int>(f.parameters.size());
    for (int i = static_cast<int>(f.locals.size()) - 1; i >= 0; --i) {
        if (f.locals[static_cast<std::size_t>(i)] == name) return params + i;
    }
    auto find = [&](const char* a, const char* b) {
        for (int i = 0; i < params; ++i) {
            const std::string& p = f.parameters[static_cast<std::size_t>(i)];
            if (p == a || p == b) return i;
        }
        return -1;
    };
    if (name == "x" || name == "u") return find("x", "u");
    if (name == "y" || name == "v") return find("y", "v");
    if (name == "z") return find("z", "z");
    for (int i = 0; i < params; ++i) {
        if (f.parameters[static_cast<std::size_t>(i)] == name) return i;
    }
    return -1;
}

}  // namespace

Value SceneParser::parse_function_value(const Token& keyword) {
    std::vector<std::string> parameters;
    if (accept_punct("(")) {
        while (true) {
            Token p = next();
            if (p.kind() != TokenKind::Identifier ||
                (is_keyword(p) && !(p.is_word("x") || p.is_word("y") || p.is_word("z") ||
                                    p.is_word("u") || p.is_word("v")))) {
                fail(p, "expected a parameter identifier, got " + describe(p));
            }
            parameters.push_back(p.text());
            if (accept_punct(")")) break;
            expect_punct(",", "between function parameters");
        }
        if (parameters.size() > 56) fail(keyword, "a function takes at most 56 parameters");
    }
    std::shared_ptr<const FunctionCode> f = parse_function_block(keyword, std::move(parameters));
    if (!f) return Value{OpaqueValue{"function", "", FileLoc{}}};
    return Value{f};
}

std::shared_ptr<const FunctionCode> SceneParser::parse_function_block(
    const Token& keyword, std::vector<std::string> parameters) {
    Token open = expect_open_brace(keyword);
    const Token& first = peek(0);
    if (first.is_word("pigment")) {
        // POV-Ray's Parse_DeclareFunction: a pigment function, its colour at (x, y, z).
        Token kw = next();
        auto pigment = std::make_shared<Pigment>();
        expect_open_brace(kw);
        parse_pigment_body(*pigment, kw);
        finish_pigment(*pigment);
        expect_close_brace(kw);
        expect_close_brace(keyword);
        auto f = std::make_shared<FunctionCode>();
        f->pigment = std::move(pigment);
        return f;
    }
    static const char* const kOtherFunctions[] = {"pattern", "spline", "transform", "image_map",
                                                  "pattern_function"};
    for (const char* w : kOtherFunctions) {
        if (first.is_word(w)) {
            // A vector function or a pattern's: the shading side's (or nobody's yet).
            Token at = first;
            unsupported(at, "function { " + at.text() + " }");
            skip_rest_of_block();
            expect_close_brace(keyword);
            return nullptr;
        }
    }
    auto f = std::make_shared<FunctionCode>();
    if (!parameters.empty()) f->parameters = std::move(parameters);
    if (first.is_word("internal")) {
        Token kw = next();
        expect_punct("(", "after 'internal'");
        const double n = parse_float();
        expect_punct(")", "after the number of the internal function");
        std::string name;
        int extra = 0;
        internal_function_known(static_cast<int>(n), &name, &extra);
        if (name.empty() || n != static_cast<int>(n)) {
            fail(kw, "there is no internal function " + std::to_string(n));
        }
        f->internal = static_cast<int>(n);
        expect_close_brace(keyword);
        return f;
    }
    f->root = parse_function_expression(*f, 0);
    const Token& close = peek(0);
    if (!close.is_punct("}")) {
        fail(close, "expected an operator or '}' to close the function opened at " +
                        place(open.loc(), close) + ", got " + describe(close));
    }
    next();
    return f;
}

// Levels: 0 |, 1 &, 2 comparisons, 3 + -, 4 * /, 5 unary.
int SceneParser::parse_function_expression(FunctionCode& f, int level) {
    if (level >= 5) {
        const Token& t = peek(0);
        if (t.is_punct("-")) {
            next();
            FunctionCode::Node n;
            n.op = Op::Neg;
            n.a = parse_function_expression(f, 5);
            return add_node(f, std::move(n));
        }
        if (t.is_punct("+")) {
            next();
            return parse_function_expression(f, 5);
        }
        if (t.is_punct("!")) fail(t, "'!' is not an operator of function expressions");
        return parse_function_primary(f);
    }
    int left = parse_function_expression(f, level + 1);
    while (true) {
        const Token& t = peek(0);
        if (t.kind() != TokenKind::Punct) return left;
        Op op;
        const std::string& p = t.text();
        if (level == 0 && p == "|") {
            op = Op::Or;
        } else if (level == 1 && p == "&") {
            op = Op::And;
        } else if (level == 2 &&
                   (p == "<" || p == "<=" || p == "=" || p == "!=" || p == ">=" || p == ">")) {
            op = p == "<"    ? Op::Lt
                 : p == "<=" ? Op::Le
                 : p == "="  ? Op::Eq
                 : p == "!=" ? Op::Ne
                 : p == ">=" ? Op::Ge
                             : Op::Gt;
        } else if (level == 3 && (p == "+" || p == "-")) {
            op = p == "+" ? Op::Add : Op::Sub;
        } else if (level == 4 && (p == "*" || p == "/")) {
            op = p == "*" ? Op::Mul : Op::Div;
        } else {
            return left;
        }
        next();
        const int right = parse_function_expression(f, level + 1);
        left = binary(f, op, left, right);
    }
}

int SceneParser::parse_function_primary(FunctionCode& f) {
    Token t = next();
    if (t.kind() == TokenKind::Number) return constant(f, t.raw->number);
    if (t.is_punct("(")) {
        const int e = parse_function_expression(f, 0);
        expect_punct(")", "to close the '(' at " + place(t.loc(), peek(0)));
        return e;
    }
    if (t.kind() != TokenKind::Identifier) {
        fail(t, "expected a function expression, got " + describe(t));
    }
    const std::string& name = t.text();
    // Parameters hide everything else (fncode.cpp's compile_variable).
    if (const int s = slot_of(f, name); s >= 0) {
        FunctionCode::Node n;
        n.op = Op::Parameter;
        n.index = s;
        return add_node(f, std::move(n));
    }
    // Arguments of a call, after its '(' : their nodes.
    auto arguments = [&](const Token& callee) {
        std::vector<int> args;
        expect_punct("(", "after '" + callee.text() + "'");
        if (accept_punct(")")) return args;
        while (true) {
            args.push_back(parse_function_expression(f, 0));
            if (accept_punct(")")) return args;
            expect_punct(",", "between the arguments of '" + callee.text() + "'");
        }
    };
    if (is_keyword(t)) {
        if (name == "x" || name == "y" || name == "z" || name == "u" || name == "v") {
            return constant(f, 0.0);  // not a parameter: POV-Ray's unset register
        }
        if (name == "pi") return constant(f, 3.14159265358979323846);
        if (name == "clock") return constant(f, 0.0);
        if (name == "true" || name == "yes" || name == "on") return constant(f, 1.0);
        if (name == "false" || name == "no" || name == "off") return constant(f, 0.0);
        if (name == "sum" || name == "prod") {
            expect_punct("(", "after '" + name + "'");
            Token var = next();
            if (var.kind() != TokenKind::Identifier || is_keyword(var)) {
                fail(var,
                     "expected the name of the variable of '" + name + "', got " + describe(var));
            }
            expect_punct(",", "after the variable of '" + name + "'");
            FunctionCode::Node n;
            n.op = name == "sum" ? Op::Sum : Op::Prod;
            const int from = parse_function_expression(f, 0);
            expect_punct(",", "after the first value of '" + name + "'");
            const int to = parse_function_expression(f, 0);
            expect_punct(",", "after the last value of '" + name + "'");
            f.locals.push_back(var.text());
            n.index = static_cast<int>(f.parameters.size() + f.locals.size()) - 1;
            const int body = parse_function_expression(f, 0);
            expect_punct(")", "after the arguments of '" + name + "'");
            n.args = {from, to, body};
            return add_node(f, std::move(n));
        }
        int arity = 0;
        const int b = function_builtin(name, &arity);
        if (b < 0) fail(t, "'" + name + "' cannot be used in a function expression");
        FunctionCode::Node n;
        n.op = Op::Builtin;
        n.builtin = b;
        n.args = arguments(t);
        const int count = static_cast<int>(n.args.size());
        if (name == "select"                 ? (count != 3 && count != 4)
            : name == "min" || name == "max" ? count < 2
                                             : count != arity) {
            fail(t, "wrong number of arguments for '" + name + "': " + std::to_string(count));
        }
        return add_node(f, std::move(n));
    }
    std::shared_ptr<Symbol> sym = t.symbol ? t.symbol : lookup(name);
    if (!sym) {
        fail(t, "'" + name +
                    "' is neither a parameter of the function nor a declared float or function"
                    " (an internal function needs #include \"functions.inc\")");
    }
    const Value& value = use_value(t, *sym, sym->value);
    if (auto* callee = value.get_if<std::shared_ptr<const FunctionCode>>()) {
        FunctionCode::Node n;
        n.op = Op::Call;
        n.callee = *callee;
        n.args = arguments(t);
        const int want = (*callee)->arity();
        if (static_cast<int>(n.args.size()) != want) {
            fail(t, "the function '" + name + "' takes " + std::to_string(want) +
                        " arguments, got " + std::to_string(n.args.size()));
        }
        if ((*callee)->pigment) {
            // A colour: one of its components (fnsyntax.cpp's member access).
            expect_punct(".", "after the pigment function '" + name +
                                  "' (a colour: .red, "
                                  ".green, .blue, .filter, .transmit or .gray)");
            Token c = next();
            n.index = member_index(c);
            if (n.index < 0) {
                fail(c, "expected red, green, blue, filter, transmit or gray after '.', got " +
                            describe(c));
            }
        }
        return add_node(f, std::move(n));
    }
    if (auto* num = value.get_if<Numeric>()) {
        Numeric v = *num;
        if (peek_punct(".")) {
            Token dot = next();
            v = apply_period(v, dot);
        }
        if (v.size != 1) {
            fail(t, "a function expression takes floats, '" + name + "' is a " +
                        numeric_type_name(v.size));
        }
        return constant(f, v.v[0]);
    }
    fail(t, "expected a function expression, got " + value_type_name(value) + " identifier '" +
                name + "'");
}

double SceneParser::call_function_value(const Token& name, const FunctionCode& f) {
    expect_punct("(", "after the function '" + name.text() + "'");
    std::vector<double> args;
    if (!accept_punct(")")) {
        while (true) {
            args.push_back(parse_float());
            if (accept_punct(")")) break;
            expect_punct(",", "between the arguments of '" + name.text() + "'");
        }
    }
    const int want = f.arity();
    if (static_cast<int>(args.size()) != want) {
        fail(name, "the function '" + name.text() + "' takes " + std::to_string(want) +
                       " arguments, got " + std::to_string(args.size()));
    }
    std::string why;
    if (!function_evaluable(f, &why)) {
        // Like any value outside the subset: a declaration computed from it becomes opaque,
        // a use elsewhere is refused (strict) or skipped with its stand-in 0 (lenient).
        const bool tracer_only = function_evaluable(f, nullptr, true);
        unsupported(name, "function '" + name.text() + "' (it needs " + why +
                              (tracer_only ? ", which mirage evaluates only in shapes it traces)"
                                           : ", which mirage does not evaluate)"));
        return 0.0;
    }
    return evaluate_function(f, args.data(), static_cast<int>(args.size()));
}

}  // namespace mirage::scene_detail
