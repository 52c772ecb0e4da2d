// The conditional directives and loops, after POV-Ray 3.7's parse of #if, #ifdef, #ifndef,
// #else, #elseif, #switch, #case, #range, #break, #while, #for and #end over its conditional
// stack (Cond_Stack): skipped regions, loop positions and the #end that closes each.
#include "scene/keywords.h"
#include "scene/scene_parser.h"
#include "util/check.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

}  // namespace

// ---------------------------------------------------------------------------------------
// Directives

void SceneParser::push_cond(Cond type, const Token& hash, const Token& keyword) {
    if (static_cast<int>(cond_.size()) >= options_.limits.max_nesting) {
        fail_fatal(hash, "conditional directives nested more than " +
                             std::to_string(options_.limits.max_nesting) + " deep, mirage's limit");
    }
    CondEntry e;
    e.type = type;
    e.directive = "#" + keyword.text();
    e.loc = hash.loc();
    e.frame_id = current_frame_id();
    e.serial = ++cond_serial_;
    e.directive_depth = static_cast<int>(directives_.size());
    cond_.push_back(std::move(e));
}

void SceneParser::check_not_busy(const Token& hash, const Token& keyword) const {
    if (!cond_.empty() && cond_.back().frame_id == current_frame_id() && !cond_.back().busy.empty())
        fail(hash, "'#" + keyword.text() + "' inside " + cond_.back().busy);
}

template <class Read>
auto SceneParser::read_param_of_top(const Token& hash, const std::string& busy_with, Read read) {
    const std::size_t level = cond_.size();
    const std::uint64_t serial = cond_.back().serial;
    cond_.back().busy = busy_with;
    auto value = read();
    if (cond_.size() < level || cond_[level - 1].serial != serial) {
        fail(hash, busy_with + " runs past the end of its macro or file");
    }
    if (cond_.size() > level) {
        const CondEntry& open = cond_[level];
        fail(hash, "'" + open.directive + "' at " + place(open.loc, hash) + " is not closed in " +
                       busy_with);
    }
    cond_.back().busy.clear();
    return value;
}

void SceneParser::go_round_or_skip(bool again, const Token& hash) {
    if (again) {
        count_loop_pass(cond_.back(), hash);
        return;
    }
    cond_.back().type = Cond::SkipTilEnd;
    skip_tokens(Cond::SkipTilEnd);
}

void SceneParser::count_loop_pass(const CondEntry& loop, const Token& at) {
    if (++loop_passes_ <= options_.limits.max_loop_passes) return;
    const Frame& frame = frames_.back();  // a loop lies in one frame: this one
    if (frame.file->path == loop.loc.file) {
        try {
            fail_at(*frame.file, loop.loc.line, loop.loc.column, frame.context,
                    "'" + loop.directive + "' reached mirage's limit of " +
                        std::to_string(options_.limits.max_loop_passes) +
                        " loop passes (all loops together): an endless loop?");
        } catch (ParseFailure& failure) {
            failure.fatal = true;
            throw;
        }
    }
    fail_fatal(at, "'" + loop.directive + "' at " + place(loop.loc, at) +
                       " reached mirage's limit of " +
                       std::to_string(options_.limits.max_loop_passes) +
                       " loop passes (all loops together): an endless loop?");
}

// Reads and ignores tokens (carrying out only the conditional directives) while the top of
// the conditional stack keeps type `type` or something was pushed above it: POV-Ray's
// Skip_Tokens.
void SceneParser::skip_tokens(Cond type) {
    MIRAGE_CHECK(lookahead_.empty());
    const std::size_t level = cond_.size();
    ScopedFlag skipping(skipping_, true);
    while (cond_.size() > level ||
           (cond_.size() == level && level > 0 && cond_.back().type == type)) {
        Token t = raw_next();
        if (t.is_eof()) {
            check_cond_closed_at_frame_end(t);
            fail(t, "unexpected end of file");
        }
        if (t.is_punct("#")) handle_directive(t);
    }
}

double SceneParser::parse_cond_param() {
    ScopedFlag skipping(skipping_, false);
    return parse_float_param();
}

bool SceneParser::parse_ifdef_param() {
    expect_punct("(", "after #ifdef, #ifndef or defined");
    // The name is read as written: a macro name is not called, an undefined one is fine.
    Token name = lookahead_.empty() ? raw_next() : next();
    if (!is_identifier(name)) {
        if (is_keyword(name)) return false;  // reserved words are never "defined"
        fail(name, "expected an identifier, got " + describe(name));
    }
    auto sym = lookup(name.text());
    bool defined = sym != nullptr;
    if (sym && sym->value.holds<ArrayValue>() && peek_array_index()) {
        defined = index_array(sym->value.get<ArrayValue>(), name) != nullptr;
    }
    expect_punct(")", "after the identifier");
    return defined;
}

void SceneParser::handle_directive(const Token& hash) {
    Nested nested(*this, hash);
    // The directives being carried out, innermost last, for the loops' #end (directive_end).
    struct Active {
        SceneParser& parser;
        explicit Active(SceneParser& p, const Token& hash) : parser(p) {
            parser.directives_.push_back(ActiveDirective{hash.loc(), "#"});
        }
        ~Active() { parser.directives_.pop_back(); }
    } active(*this, hash);
    // The keyword follows the '#' as written (POV-Ray allows white space between them).
    Token keyword = lookahead_.empty() ? raw_next() : next();
    if (keyword.kind() != TokenKind::Identifier) {
        // POV-Ray reads on: a '#' before something that is not a directive is ignored.
        if (!skipping_) lookahead_.push_back(keyword);
        return;
    }
    const std::string& w = keyword.text();
    directives_.back().keyword = "#" + w;

    if (w == "if" || w == "ifdef" || w == "ifndef") {
        if (skipping_) {
            push_cond(Cond::SkipTilEnd, hash, keyword);
            skip_tokens(Cond::SkipTilEnd);
            return;
        }
        bool value;
        if (w == "if") {
            value = std::abs(parse_cond_param()) > kEpsilon;
        } else {
            value = parse_ifdef_param() == (w == "ifdef");
        }
        directive_if(hash, keyword, Cond::IfTrue, value);
        return;
    }
    if (w == "while" || w == "for" || w == "switch" || w == "macro") {
        if (skipping_) {
            push_cond(Cond::SkipTilEnd, hash, keyword);
            skip_tokens(Cond::SkipTilEnd);
            return;
        }
        if (w == "while") directive_while(hash, keyword);
        if (w == "for") directive_for(hash, keyword);
        if (w == "switch") directive_switch(hash, keyword);
        if (w == "macro") directive_macro(hash, keyword);
        return;
    }
    if (w == "else") return directive_else(hash, keyword);
    if (w == "elseif") return directive_elseif(hash, keyword);
    if (w == "end") return directive_end(hash, keyword);
    if (w == "case" || w == "range") return directive_case(hash, keyword);
    if (w == "break") {
        if (!skipping_) directive_break(hash, keyword);
        return;
    }
    if (skipping_) return;  // nothing else matters in a skipped region

    if (w == "declare" || w == "local") return directive_declare(keyword, w == "local");
    if (w == "undef") return directive_undef(keyword);
    if (w == "include") return directive_include(hash, keyword);
    if (w == "version") return directive_version(keyword);
    if (w == "debug" || w == "warning" || w == "error" || w == "render" || w == "statistics") {
        return directive_message(hash, keyword);
    }
    if (w == "default") return directive_default(keyword);
    if (w == "fopen" || w == "fclose" || w == "read" || w == "write") {
        return directive_file_io(keyword);  // parse_opaque.cpp
    }
    // '#' before a macro call is allowed, as in POV-Ray.
    if (is_identifier(keyword)) {
        if (auto sym = lookup(w)) {
            if (auto* m = sym->value.get_if<std::shared_ptr<const MacroDef>>()) {
                Token call = keyword;
                call.symbol = sym;
                return invoke_macro(call, *m);
            }
        }
    }
    fail(keyword, "unknown directive '#" + w + "'");
}

void SceneParser::directive_if(const Token& hash, const Token& keyword, Cond true_type,
                               bool value) {
    push_cond(value ? true_type : Cond::IfFalse, hash, keyword);
    if (!value) skip_tokens(Cond::IfFalse);
}

void SceneParser::directive_else(const Token& hash, const Token& keyword) {
    if (cond_.empty() || cond_.back().frame_id != current_frame_id()) {
        fail(hash, "#else without #if, #ifdef, #ifndef or #switch");
    }
    check_not_busy(hash, keyword);
    CondEntry& top = cond_.back();
    switch (top.type) {
        case Cond::IfTrue:
            top.type = Cond::SkipTilEnd;
            skip_tokens(Cond::SkipTilEnd);
            break;
        case Cond::IfFalse:
            top.type = Cond::Else;
            break;
        case Cond::CaseTrue:
        case Cond::SkipTilEnd:
            break;
        case Cond::CaseFalse:
            top.type = Cond::CaseTrue;
            break;
        default:
            fail(hash, "#else inside '" + top.directive + "' opened at " + place(top.loc, hash));
    }
}

void SceneParser::directive_elseif(const Token& hash, const Token& keyword) {
    if (cond_.empty() || cond_.back().frame_id != current_frame_id()) {
        fail(hash, "#elseif without #if");
    }
    check_not_busy(hash, keyword);
    switch (cond_.back().type) {
        case Cond::IfTrue:
            cond_.back().type = Cond::SkipTilEnd;
            skip_tokens(Cond::SkipTilEnd);
            break;
        case Cond::IfFalse: {
            const double v =
                read_param_of_top(hash, "the condition of '#elseif' at " + place(hash.loc(), hash),
                                  [&] { return parse_cond_param(); });
            if (std::abs(v) > kEpsilon) cond_.back().type = Cond::IfTrue;
            break;
        }
        case Cond::SkipTilEnd:
            break;
        default:
            fail(hash, "#elseif inside '" + cond_.back().directive + "' opened at " +
                           place(cond_.back().loc, hash));
    }
}

void SceneParser::directive_end(const Token& hash, const Token& keyword) {
    if (cond_.empty() || cond_.back().frame_id != current_frame_id()) {
        fail(hash, "#end without #if, #ifdef, #ifndef, #while, #for, #switch or #macro");
    }
    check_not_busy(hash, keyword);
    CondEntry& top = cond_.back();
    const int depth = static_cast<int>(directives_.size());  // this #end's included
    if ((top.type == Cond::While || top.type == Cond::For) && depth != top.directive_depth) {
        // Going back to the loop's start here would begin, in the middle of a directive (a
        // #declare whose value the #end cuts), the whole body again: inside itself.
        if (depth > top.directive_depth) {
            const ActiveDirective& cut = directives_[top.directive_depth - 1];
            fail_fatal(hash, "'#end' of the '" + top.directive + "' at " + place(top.loc, hash) +
                                 " comes inside the '" + cut.keyword + "' at " +
                                 place(cut.loc, hash) +
                                 ": a loop must end after the directives in it");
        }
        fail_fatal(hash, "'#end' of the '" + top.directive + "' at " + place(top.loc, hash) +
                             " comes after the directive it was opened in has ended");
    }
    switch (top.type) {
        case Cond::While: {
            Frame& frame = frames_.back();
            frame.pos = top.loop_pos;
            const double v =
                read_param_of_top(hash, "the condition of '#while' at " + place(top.loc, hash),
                                  [&] { return parse_cond_param(); });
            go_round_or_skip(std::abs(v) > kEpsilon, hash);
            break;
        }
        case Cond::For: {
            auto it = tables_.back().find(top.for_variable);
            Numeric* n = it == tables_.back().end() ? nullptr
                                                    : it->second->value.get_if<Numeric>();
            if (!n || n->size != 1) {
                fail(hash, "the #for loop variable '" + top.for_variable +
                               "' must stay defined and a float during the loop");
            }
            n->v[0] += top.for_step;
            bool done = (top.for_step > 0 && n->v[0] > top.for_end + kEpsilon) ||
                        (top.for_step < 0 && n->v[0] < top.for_end - kEpsilon);
            // Back to the body either way: when done, POV-Ray skips it to this #end.
            frames_.back().pos = top.loop_pos;
            go_round_or_skip(!done, hash);
            break;
        }
        case Cond::DeclaringMacro:
            if (top.macro) top.macro->body_end = hash.index;
            cond_.pop_back();
            break;
        case Cond::Switch:
            fail(hash, "#switch must be followed by #case or #range");
        default:
            cond_.pop_back();
            break;
    }
}

void SceneParser::directive_while(const Token& hash, const Token& keyword) {
    push_cond(Cond::While, hash, keyword);
    // The condition is read again at every #end.
    std::size_t pos = lookahead_.empty() ? frames_.back().pos : lookahead_.front().index;
    cond_.back().loop_pos = pos;
    const double v =
        read_param_of_top(hash, "the condition of '#while' at " + place(hash.loc(), hash),
                          [&] { return parse_cond_param(); });
    go_round_or_skip(std::abs(v) > kEpsilon, hash);
}

void SceneParser::directive_for(const Token& hash, const Token& keyword) {
    expect_punct("(", "after #for");
    Token name = lookahead_.empty() ? raw_next() : next();
    if (!is_identifier(name))
        fail(name, "expected the loop variable after '#for (', got " + describe(name));
    accept_comma();
    double start = parse_float();
    accept_comma();
    double end = parse_float();
    accept_comma();
    double step = allow_float(1.0);
    if (std::abs(step) < kEpsilon) fail(keyword, "the #for step must not be zero");
    Token close = expect_punct(")", "after the #for parameters");
    // The loop variable lives in the current table (#local semantics).
    declare(name, Value{Numeric::scalar(start)}, true);
    push_cond(Cond::For, hash, keyword);
    CondEntry& e = cond_.back();
    e.for_variable = name.text();
    e.for_end = end;
    e.for_step = step;
    e.loop_pos = lookahead_.empty() ? frames_.back().pos : lookahead_.front().index;
    bool run = (step > 0 && start < end + kEpsilon) || (step < 0 && start > end - kEpsilon);
    go_round_or_skip(run, hash);
    (void)close;
}

void SceneParser::directive_switch(const Token& hash, const Token& keyword) {
    double value = parse_cond_param();
    push_cond(Cond::Switch, hash, keyword);
    cond_.back().switch_value = value;
    // Only a #case or #range may follow.
    Token h = lookahead_.empty() ? raw_next() : next();
    Token k = h.is_punct("#") ? raw_next() : h;
    if (!h.is_punct("#") || !(k.is_word("case") || k.is_word("range"))) {
        fail(h, "#switch must be followed by #case or #range, got " + describe(h));
    }
    cond_.back().case_allowed = true;
    directive_case(h, k);
}

void SceneParser::directive_case(const Token& hash, const Token& keyword) {
    if (cond_.empty() || cond_.back().frame_id != current_frame_id()) {
        fail(hash, "#" + keyword.text() + " outside #switch");
    }
    check_not_busy(hash, keyword);
    CondEntry& top = cond_.back();
    if (top.type == Cond::SkipTilEnd) return;
    bool from_switch = top.type == Cond::Switch;
    if (!from_switch && top.type != Cond::CaseTrue && top.type != Cond::CaseFalse) {
        fail(hash, "#" + keyword.text() + " inside '" + top.directive + "' opened at " +
                       place(top.loc, hash));
    }
    const double s = top.switch_value;
    const bool match = read_param_of_top(
        hash, "the value of '#" + keyword.text() + "' at " + place(hash.loc(), hash), [&] {
            ScopedFlag not_skipping(skipping_, false);
            if (keyword.is_word("case")) return std::abs(parse_float_param() - s) < kEpsilon;
            expect_punct("(", "after #range");
            const double lo = parse_float();
            accept_comma();
            const double hi = parse_float();
            expect_punct(")", "after the #range bounds");
            return s >= lo && s <= hi;
        });
    CondEntry& entry = cond_.back();
    if (from_switch) {
        entry.type = match ? Cond::CaseTrue : Cond::CaseFalse;
        if (!match) skip_tokens(Cond::CaseFalse);
    } else if (match && entry.type == Cond::CaseFalse) {
        entry.type = Cond::CaseTrue;
    }
    // Without #break a true case runs on into the next one, as in POV-Ray.
}

void SceneParser::directive_break(const Token& hash, const Token& keyword) {
    check_not_busy(hash, keyword);
    while (true) {
        if (!cond_.empty() && cond_.back().frame_id == current_frame_id()) {
            Cond type = cond_.back().type;
            if (type == Cond::While || type == Cond::For || type == Cond::CaseTrue) {
                cond_.back().type = Cond::SkipTilEnd;
                skip_tokens(Cond::SkipTilEnd);
                return;
            }
            // Leave the enclosing #if (or the like) first.
            const std::size_t level = cond_.size();
            ScopedFlag skipping(skipping_, true);
            while (cond_.size() >= level && !cond_.empty()) {
                Token t = raw_next();
                if (t.is_eof()) check_cond_closed_at_frame_end(t);
                if (t.is_punct("#")) handle_directive(t);
            }
            continue;
        }
        if (frames_.back().kind == FrameContext::Kind::Macro) {
            pop_frame();  // #break in a macro returns from it
            return;
        }
        fail(hash, "#break outside #while, #for, #switch or a macro");
    }
}

}  // namespace mirage::scene_detail
