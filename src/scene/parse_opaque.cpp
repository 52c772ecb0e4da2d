// Opaque values (scene/value.h): declarations the parser keeps without evaluating them, so
// that what a scene never uses costs nothing, and their uses.
#include <utility>

#include "scene/scene_parser.h"

namespace mirage::scene_detail {
namespace {

bool one_of(const std::string& w, std::initializer_list<const char*> words) {
    for (const char* x : words) {
        if (w == x) return true;
    }
    return false;
}

}  // namespace

void SceneParser::directive_file_io(const Token& keyword) {
    // POV-Ray's #fopen, #fclose, #read and #write.  Strict: refused.  Lenient: their arguments
    // are read and nothing is written; #read declares its variables as opaque (nothing read).
    const std::string& w = keyword.text();
    unsupported(keyword, "directive '#" + w + "' (file input and output)");
    if (w == "fopen") {
        next();                           // the file identifier
        parse_string(true);               // the file name
        if (is_keyword(peek(0))) next();  // read, write or append
        return;
    }
    if (w == "fclose") {
        next();
        return;
    }
    expect_punct("(", "after '#" + w + "'");
    next();  // the file identifier
    while (accept_punct(",")) {
        if (w == "read") {
            Token name = next();
            if (!is_identifier(name))
                fail(name, "expected a variable in #read, got " + describe(name));
            declare(name,
                    Value{OpaqueValue{"value", "not read: #read is not supported", name.loc()}},
                    false);
            continue;
        }
        // #write items: strings, numbers, vectors; parse_rvalue-like skipping of one item.
        const Token& t = peek(0);
        if (starts_string(t)) {
            parse_string(false);
        } else {
            parse_express();
        }
    }
    expect_punct(")", "after the arguments of '#" + w + "'");
}

void SceneParser::recover_statement(int balance) {
    // The statement opened braces: read until they are closed again (the failure may lie
    // anywhere inside them).  Without braces: read to its ';' (floats, vectors and colours
    // need one), stopping before what starts the next statement.
    const bool had_braces = brace_balance_ > balance;
    int failures = 0;
    while (true) {
        // A directive met on the way may fail as well (it ran as its tokens were read).
        try {
            peek(0);
        } catch (const ParseFailure& failure) {
            if (failure.fatal || ++failures > 1000) throw;
            continue;
        }
        const Token& t = peek(0);
        if (t.is_eof()) return;
        if (brace_balance_ <= balance) {
            if (had_braces) {
                if (t.is_punct(";")) next();
                return;
            }
            if (t.is_punct(";")) {
                next();
                return;
            }
            if (t.is_punct("}")) return;  // the end of the enclosing block
            if (is_keyword(t) &&
                (starts_object(t) ||
                 one_of(t.text(), {"camera", "background", "sky_sphere", "global_settings", "fog",
                                   "media", "rainbow", "light_source"}))) {
                return;
            }
        }
        next();
    }
}

Value SceneParser::parse_declared_value(const Token& name) {
    // The kind of the value, from what it starts with, for messages and stand-ins.
    std::string what = "value";
    {
        ScopedFlag defer(defer_directives_, true);
        const Token& t = peek(0);
        if (t.kind() == TokenKind::String) {
            what = "string";
        } else if (is_identifier(t)) {
            auto sym = t.symbol ? t.symbol : lookup(t.text());
            if (sym) {
                what = value_type_name(sym->value);
                if (what == "light source") what = "object";
                // F(...) of a function is a float.
                if (what == "function" && peek(1).is_punct("(")) what = "value";
            }
        } else if (is_keyword(t)) {
            const std::string& w = t.text();
            if (w == "light_source" || starts_object(t)) {
                what = "object";
            } else if (w == "colour_map") {
                what = "color_map";
            } else if (!starts_expression(t)) {
                what = w;
            }
        }
    }
    OpaqueCapture capture;
    OpaqueCapture* const outer = std::exchange(opaque_capture_, &capture);
    const int balance = brace_balance_;
    Value value;
    bool failed = false;
    try {
        value = parse_rvalue(name, false);
    } catch (const ParseFailure& failure) {
        opaque_capture_ = outer;
        if (failure.fatal || (options_.strict && !failure.from_opaque)) throw;
        failed = true;
        if (!capture.captured) {
            capture.captured = true;
            capture.reason = failure.reason.empty() ? failure.message : failure.reason;
            capture.loc = failure.loc;
        }
        recover_statement(balance);
    }
    opaque_capture_ = outer;
    // In lenient mode a value read in spite of something unsupported in it (a pattern skipped,
    // an object left out, an opaque value's stand-in) is kept as read: its uses need no more.
    if (!capture.captured || (!options_.strict && !failed)) return value;
    return Value{OpaqueValue{what, capture.reason, capture.loc}};
}

void SceneParser::fail_opaque_use(const Token& name, const Symbol& symbol,
                                  const OpaqueValue& value) {
    std::string message;
    if (value.reason.empty()) {
        message = "unsupported " + value.what + " '" + name.text() + "' (declared at " +
                  to_string(symbol.loc) + ")";
    } else {
        message = value.reason + " (in the " + value.what + " '" + name.text() + "' declared at " +
                  to_string(symbol.loc) + "; the reason at " + to_string(value.loc) + ")";
    }
    try {
        fail(name, message);
    } catch (ParseFailure& failure) {
        failure.from_opaque = true;
        throw;
    }
}

const Value& SceneParser::use_value(const Token& name, const Symbol& symbol, const Value& value) {
    const auto* opaque = value.get_if<OpaqueValue>();
    if (!opaque) return value;
    if (std::exchange(copying_value_, false)) return value;
    if (options_.strict && !opaque_capture_) fail_opaque_use(name, symbol, *opaque);
    const std::string& w = opaque->what;
    const std::string description =
        w + " '" + name.text() + "'" + (opaque->reason.empty() ? "" : " (" + opaque->reason + ")");
    if (opaque_capture_ && !opaque_capture_->captured) {
        opaque_capture_->captured = true;
        opaque_capture_->reason =
            "uses the " + description + " declared at " + to_string(symbol.loc);
        opaque_capture_->loc = name.loc();
    }
    Value stand_in;
    if (w == "pigment") {
        stand_in.data = Pigment{};
    } else if (w == "texture") {
        stand_in.data = default_texture_;
    } else if (w == "finish") {
        stand_in.data = Finish{};
    } else if (w == "color_map") {
        ColourMapEntry black, white;
        white.position = 1.0;
        white.colour.rgb = glm::dvec3(1.0);
        stand_in.data = ColourMapValue{{black, white}};
    } else if (w == "transform") {
        stand_in.data = Transform{};
    } else if (w == "sky_sphere") {
        SkySphere sky;
        sky.pigments.push_back(Pigment{});
        stand_in.data = sky;
    } else if (w == "object") {
        ObjectNode unknown;
        unknown.kind = ObjectNode::Kind::Empty;
        unknown.loc = name.loc();
        unknown.unknown = "object '" + name.text() + "' declared at " + to_string(symbol.loc) +
                          (opaque->reason.empty() ? "" : " (" + opaque->reason + ")");
        stand_in.data = std::move(unknown);
    } else {
        fail_opaque_use(name, symbol, *opaque);
    }
    if (!options_.strict) scene_.skipped.push_back(Skipped{description, name.loc()});
    Value& slot = stand_ins_[name.text() + "@" + to_string(name.loc())];
    slot = std::move(stand_in);
    return slot;
}

}  // namespace mirage::scene_detail
