// The token stream of the scene parser: frames (main file, includes, macro bodies),
// directives, macro calls and symbol tables, after POV-Ray 3.7's tokenize.cpp.
#include "scene/scene_parser.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/diagnostics.h"
#include "scene/keywords.h"
#include "util/check.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON
constexpr std::size_t kMaxFrames = 1000;
constexpr std::size_t kMaxIncludeDepth = 64;

bool read_text_file(const std::string& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    return true;
}

bool is_regular_file(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

std::string parent_directory(const std::string& path) {
    return std::filesystem::path(path).parent_path().generic_string();
}

// A punctuation mark that continues an expression after an identifier.
bool continues_expression(const Token& t) {
    if (t.kind() != TokenKind::Punct) return false;
    for (const char* p : {"+", "-", "*", "/", ".", "[", "?", "<", ">", "=", "!", "&", "|"}) {
        if (t.text() == p) return true;
    }
    return false;
}

std::string join_path(const std::string& dir, const std::string& name) {
    if (dir.empty()) return name;
    return (std::filesystem::path(dir) / name).lexically_normal().generic_string();
}

}  // namespace

SceneParser::SceneParser(const ParseOptions& options)
    : options_(options), animation_(options.animation.value_or(thread_animation_clock())) {
    tables_.emplace_back();
    // POV-Ray's front end declares these two like Declare= options, after them.
    for (const auto& [name, value] : options_.declares) {
        auto sym = std::make_shared<Symbol>();
        sym->value.data = Numeric::scalar(value);
        sym->loc = FileLoc{"<command line>", 0, 0};
        tables_[0][name] = sym;
    }
    for (const char* name : {"image_width", "image_height"}) {
        auto sym = std::make_shared<Symbol>();
        double v =
            std::string(name) == "image_width" ? options_.image_width : options_.image_height;
        sym->value.data = Numeric::scalar(v);
        sym->loc = FileLoc{"<image size>", 0, 0};
        tables_[0][name] = sym;
    }
    // Then, like POV-Ray's front end, the animation's six (vfe/vfe.cpp, animationprocessing.cpp).
    const std::pair<const char*, double> frame_values[] = {
        {"clock_delta", animation_.clock_delta},     {"final_clock", animation_.final_clock},
        {"final_frame", animation_.final_frame},     {"frame_number", animation_.frame_number},
        {"initial_clock", animation_.initial_clock}, {"initial_frame", animation_.initial_frame},
    };
    for (const auto& [name, value] : frame_values) {
        auto sym = std::make_shared<Symbol>();
        sym->value.data = Numeric::scalar(value);
        sym->loc = FileLoc{"<animation>", 0, 0};
        tables_[0][name] = sym;
    }
}

// ---------------------------------------------------------------------------------------
// Errors and messages

std::vector<std::string> SceneParser::context_lines(
    const std::shared_ptr<const FrameContext>& c) const {
    std::vector<std::string> lines;
    for (const FrameContext* f = c.get(); f && f->kind != FrameContext::Kind::Main;
         f = f->parent.get()) {
        std::string where = f->entered_at.file + ":" + std::to_string(f->entered_at.line) + ":" +
                            std::to_string(f->entered_at.column);
        if (f->kind == FrameContext::Kind::Include) {
            lines.push_back("  included from " + where);
        } else {
            lines.push_back("  in macro '" + f->macro_name + "' called from " + where);
        }
    }
    return lines;
}

void SceneParser::fail_at(const SourceFile& file, int line, int column,
                          const std::shared_ptr<const FrameContext>& context,
                          const std::string& message) const {
    throw ParseFailure{format_diagnostic(file.path, line, column, message, context_lines(context),
                                         file.line_text(line)),
                       message, FileLoc{file.path, line, column}};
}

void SceneParser::fail(const Token& at, const std::string& message) const {
    fail_at(*at.file, at.raw->line, at.raw->column, at.context, message);
}

void SceneParser::add_message(const Token& at, const std::string& kind, const std::string& text) {
    scene_.messages.push_back(at.file->path + ":" + std::to_string(at.raw->line) + ":" +
                              std::to_string(at.raw->column) + ": " + kind + ": " + text);
}

std::string SceneParser::describe(const Token& t) {
    if (t.deferred_directive) return "'#'";
    switch (t.kind()) {
        case TokenKind::EndOfFile:
            return "end of file";
        case TokenKind::String:
            return "string \"" + t.text() + "\"";
        case TokenKind::Number:
        case TokenKind::Punct:
            return "'" + t.text() + "'";
        case TokenKind::Identifier:
            if (is_reserved_word(t.text())) return "'" + t.text() + "'";
            if (t.symbol)
                return value_type_name(t.symbol->value) + " identifier '" + t.text() + "'";
            return "undefined identifier '" + t.text() + "'";
    }
    return "'" + t.text() + "'";
}

std::string SceneParser::place(const FileLoc& loc, const Token& relative_to) {
    std::string lc = std::to_string(loc.line) + ":" + std::to_string(loc.column);
    return loc.file == relative_to.file->path ? lc : loc.file + ":" + lc;
}

// ---------------------------------------------------------------------------------------
// Files and frames

std::shared_ptr<SourceFile> SceneParser::load_file(const std::string& path,
                                                   const std::string& text) {
    auto file = std::make_shared<SourceFile>();
    file->path = path;
    file->text = text;
    if (auto error = lex_source(*file)) {
        std::shared_ptr<const FrameContext> context =
            frames_.empty() ? nullptr : frames_.back().context;
        fail_at(*file, error->line, error->column, context, error->message);
    }
    return file;
}

void SceneParser::push_frame(std::shared_ptr<const SourceFile> file, std::size_t begin,
                             std::size_t end, FrameContext::Kind kind,
                             const std::string& macro_name, const Token& at) {
    if (frames_.size() >= kMaxFrames) {
        fail(at, "too many nested macro calls and include files (more than " +
                     std::to_string(kMaxFrames) + "): endless recursion?");
    }
    auto context = std::make_shared<FrameContext>();
    context->kind = kind;
    context->macro_name = macro_name;
    if (at.raw) context->entered_at = at.loc();
    context->parent = frames_.empty() ? nullptr : frames_.back().context;
    Frame frame;
    frame.file = std::move(file);
    frame.pos = begin;
    frame.end = end;
    frame.kind = kind;
    frame.context = context;
    frame.id = next_frame_id_++;
    frame.owns_table = kind != FrameContext::Kind::Main;
    if (frame.owns_table) tables_.emplace_back();
    if (kind == FrameContext::Kind::Macro) ++macro_depth_;
    frames_.push_back(std::move(frame));
}

void SceneParser::pop_frame() {
    Frame& f = frames_.back();
    // A macro body left with an open conditional: drop it with the body.
    while (!cond_.empty() && cond_.back().frame_id == f.id) cond_.pop_back();
    if (f.owns_table) tables_.pop_back();
    if (f.kind == FrameContext::Kind::Macro) --macro_depth_;
    frames_.pop_back();
}

void SceneParser::check_cond_closed_at_frame_end(const Token& eof) {
    if (!cond_.empty() && cond_.back().frame_id == frames_.back().id) {
        const CondEntry& open = cond_.back();
        fail(eof, "expected '#end' to close '" + open.directive + "' opened at " +
                      place(open.loc, eof) + ", got end of file");
    }
}

Token SceneParser::make_token(const std::shared_ptr<const SourceFile>& file, std::size_t index,
                              const std::shared_ptr<const FrameContext>& context) {
    Token t;
    t.raw = &file->tokens[index];
    t.file = file;
    t.context = context;
    t.index = index;
    return t;
}

Token SceneParser::raw_next() {
    while (true) {
        Frame& f = frames_.back();
        if (f.pos < f.end) {
            std::size_t index = f.pos++;
            return make_token(f.file, index, f.context);
        }
        if (f.kind == FrameContext::Kind::Main) {
            return make_token(f.file, f.file->tokens.size() - 1, f.context);
        }
        if (f.kind == FrameContext::Kind::Include) {
            check_cond_closed_at_frame_end(
                make_token(f.file, f.file->tokens.size() - 1, f.context));
        }
        pop_frame();
    }
}

bool SceneParser::is_keyword(const Token& t) const {
    return t.kind() == TokenKind::Identifier && is_reserved_word(t.text());
}

bool SceneParser::is_identifier(const Token& t) const {
    return t.kind() == TokenKind::Identifier && !is_reserved_word(t.text());
}

void SceneParser::reject_unknown_word(const Token& t) {
    if (!is_identifier(t)) return;
    auto sym = t.symbol ? t.symbol : lookup(t.text());
    if (!sym) fail(t, "unknown keyword '" + t.text() + "'");
    // An opaque value where a block's item belongs: its use is what fails.
    if (auto* opaque = std::get_if<OpaqueValue>(&sym->value.data))
        fail_opaque_use(t, *sym, *opaque);
}

void SceneParser::resolve(Token& t) {
    if (is_identifier(t)) t.symbol = lookup(t.text());
}

// Fetches at least one processed token into the lookahead, carrying out directives and
// macro calls on the way.  A directive or call runs with an empty lookahead of its own (it
// reads what follows it); whatever it read ahead is appended after the tokens already there.
void SceneParser::fetch() {
    while (true) {
        Token t = raw_next();
        bool directive = t.is_punct("#");
        std::shared_ptr<const MacroDef> macro;
        if (!directive && is_identifier(t)) {
            resolve(t);
            if (t.symbol) {
                if (auto* m = std::get_if<std::shared_ptr<const MacroDef>>(&t.symbol->value.data)) {
                    macro = *m;
                }
            }
        }
        if (!directive && !macro) {
            lookahead_.push_back(std::move(t));
            return;
        }
        if (defer_directives_) {
            (directive ? t.deferred_directive : t.deferred_macro) = true;
            lookahead_.push_back(std::move(t));
            return;
        }
        std::deque<Token> saved;
        saved.swap(lookahead_);
        std::size_t before = saved.size();
        if (directive) {
            handle_directive(t);
        } else {
            invoke_macro(t, macro);
        }
        for (Token& x : lookahead_) saved.push_back(std::move(x));
        lookahead_.swap(saved);
        if (lookahead_.size() > before) return;
    }
}

void SceneParser::run_deferred(std::size_t at) {
    Token t = lookahead_[at];
    lookahead_.erase(lookahead_.begin() + static_cast<std::ptrdiff_t>(at));
    std::deque<Token> saved;
    saved.swap(lookahead_);
    if (t.deferred_directive) {
        t.deferred_directive = false;
        handle_directive(t);
    } else {
        t.deferred_macro = false;
        // The name may have been redeclared meanwhile; then it is an identifier like others.
        auto* macro = std::get_if<std::shared_ptr<const MacroDef>>(&t.symbol->value.data);
        if (macro) {
            auto def = *macro;
            invoke_macro(t, def);
        } else {
            lookahead_.push_back(t);
        }
    }
    for (Token& x : lookahead_) saved.push_back(std::move(x));
    lookahead_.swap(saved);
}

const Token& SceneParser::peek(std::size_t ahead) {
    while (true) {
        bool restarted = false;
        for (std::size_t i = 0; i < lookahead_.size() && i <= ahead; ++i) {
            if (lookahead_[i].is_deferred()) {
                // Deferred tokens are walls: nothing is read past them until they have run.
                if (defer_directives_) return lookahead_[i];
                run_deferred(i);
                restarted = true;
                break;
            }
        }
        if (restarted) continue;
        if (lookahead_.size() > ahead) return lookahead_[ahead];
        fetch();
    }
}

Token SceneParser::next() {
    Token t = peek(0);
    lookahead_.pop_front();
    ++tokens_read_;
    if (t.kind() == TokenKind::Punct)
        brace_balance_ += t.text() == "{" ? 1 : t.text() == "}" ? -1 : 0;
    return t;
}

bool SceneParser::accept_punct(std::string_view p) {
    if (!peek(0).is_punct(p)) return false;
    next();
    return true;
}

bool SceneParser::accept_word(std::string_view w) {
    if (!peek(0).is_word(w)) return false;
    next();
    return true;
}

Token SceneParser::expect_punct(std::string_view p, std::string_view after) {
    const Token& t = peek(0);
    if (!t.is_punct(p)) {
        fail(t, "expected '" + std::string(p) + "' " + std::string(after) + ", got " + describe(t));
    }
    return next();
}

Token SceneParser::expect_open_brace(const Token& keyword) {
    return expect_punct("{", "after '" + keyword.text() + "'");
}

void SceneParser::expect_close_brace(const Token& keyword) {
    const Token& t = peek(0);
    if (!t.is_punct("}")) {
        fail(t, "expected '}' to close '" + keyword.text() + "' opened at " +
                    place(keyword.loc(), t) + ", got " + describe(t));
    }
    next();
}

// ---------------------------------------------------------------------------------------
// Symbols

std::shared_ptr<Symbol> SceneParser::lookup(const std::string& name, int* depth) const {
    for (std::size_t i = tables_.size(); i-- > 0;) {
        auto it = tables_[i].find(name);
        if (it != tables_[i].end()) {
            if (depth) *depth = static_cast<int>(i);
            return it->second;
        }
    }
    return nullptr;
}

void SceneParser::declare(const Token& name_token, Value value, bool local, std::size_t scope) {
    const std::string& name = name_token.text();
    if (local) {
        auto& table = scope > 0 && scope <= tables_.size() ? tables_[scope - 1] : tables_.back();
        auto it = table.find(name);
        if (it != table.end()) {
            it->second->value = std::move(value);
            it->second->loc = name_token.loc();
            return;
        }
        table[name] = std::make_shared<Symbol>(Symbol{std::move(value), name_token.loc()});
        return;
    }
    // #declare changes the identifier where it is visible, else creates a global one.
    if (auto sym = lookup(name)) {
        sym->value = std::move(value);
        sym->loc = name_token.loc();
        return;
    }
    tables_[0][name] = std::make_shared<Symbol>(Symbol{std::move(value), name_token.loc()});
}

// ---------------------------------------------------------------------------------------
// Directives

void SceneParser::push_cond(Cond type, const Token& hash, const Token& keyword) {
    CondEntry e;
    e.type = type;
    e.directive = "#" + keyword.text();
    e.loc = hash.loc();
    e.frame_id = current_frame_id();
    cond_.push_back(std::move(e));
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
    if (sym && std::holds_alternative<ArrayValue>(sym->value.data) && peek_array_index()) {
        defined = index_array(std::get<ArrayValue>(sym->value.data), name) != nullptr;
    }
    expect_punct(")", "after the identifier");
    return defined;
}

void SceneParser::handle_directive(const Token& hash) {
    // The keyword follows the '#' as written (POV-Ray allows white space between them).
    Token keyword = lookahead_.empty() ? raw_next() : next();
    if (keyword.kind() != TokenKind::Identifier) {
        // POV-Ray reads on: a '#' before something that is not a directive is ignored.
        if (!skipping_) lookahead_.push_back(keyword);
        return;
    }
    const std::string& w = keyword.text();

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
        return directive_file_io(keyword);
    }
    // '#' before a macro call is allowed, as in POV-Ray.
    if (is_identifier(keyword)) {
        if (auto sym = lookup(w)) {
            if (auto* m = std::get_if<std::shared_ptr<const MacroDef>>(&sym->value.data)) {
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
    (void)keyword;
}

void SceneParser::directive_elseif(const Token& hash, const Token& keyword) {
    if (cond_.empty() || cond_.back().frame_id != current_frame_id()) {
        fail(hash, "#elseif without #if");
    }
    switch (cond_.back().type) {
        case Cond::IfTrue:
            cond_.back().type = Cond::SkipTilEnd;
            skip_tokens(Cond::SkipTilEnd);
            break;
        case Cond::IfFalse:
            if (std::abs(parse_cond_param()) > kEpsilon) cond_.back().type = Cond::IfTrue;
            break;
        case Cond::SkipTilEnd:
            break;
        default:
            fail(hash, "#elseif inside '" + cond_.back().directive + "' opened at " +
                           place(cond_.back().loc, hash));
    }
    (void)keyword;
}

void SceneParser::directive_end(const Token& hash, const Token& keyword) {
    if (cond_.empty() || cond_.back().frame_id != current_frame_id()) {
        fail(hash, "#end without #if, #ifdef, #ifndef, #while, #for, #switch or #macro");
    }
    CondEntry& top = cond_.back();
    switch (top.type) {
        case Cond::While: {
            Frame& frame = frames_.back();
            frame.pos = top.loop_pos;
            if (std::abs(parse_cond_param()) <= kEpsilon) {
                cond_.back().type = Cond::SkipTilEnd;
                skip_tokens(Cond::SkipTilEnd);
            }
            break;
        }
        case Cond::For: {
            auto it = tables_.back().find(top.for_variable);
            Numeric* n = it == tables_.back().end() ? nullptr
                                                    : std::get_if<Numeric>(&it->second->value.data);
            if (!n || n->size != 1) {
                fail(hash, "the #for loop variable '" + top.for_variable +
                               "' must stay defined and a float during the loop");
            }
            n->v[0] += top.for_step;
            bool done = (top.for_step > 0 && n->v[0] > top.for_end + kEpsilon) ||
                        (top.for_step < 0 && n->v[0] < top.for_end - kEpsilon);
            // Back to the body either way: when done, POV-Ray skips it to this #end.
            frames_.back().pos = top.loop_pos;
            if (done) {
                top.type = Cond::SkipTilEnd;
                skip_tokens(Cond::SkipTilEnd);
            }
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
    (void)keyword;
}

void SceneParser::directive_while(const Token& hash, const Token& keyword) {
    push_cond(Cond::While, hash, keyword);
    // The condition is read again at every #end.
    std::size_t pos = lookahead_.empty() ? frames_.back().pos : lookahead_.front().index;
    cond_.back().loop_pos = pos;
    if (std::abs(parse_cond_param()) <= kEpsilon) {
        cond_.back().type = Cond::SkipTilEnd;
        skip_tokens(Cond::SkipTilEnd);
    }
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
    if (!run) {
        e.type = Cond::SkipTilEnd;
        skip_tokens(Cond::SkipTilEnd);
    }
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
    CondEntry& top = cond_.back();
    if (top.type == Cond::SkipTilEnd) return;
    bool from_switch = top.type == Cond::Switch;
    if (!from_switch && top.type != Cond::CaseTrue && top.type != Cond::CaseFalse) {
        fail(hash, "#" + keyword.text() + " inside '" + top.directive + "' opened at " +
                       place(top.loc, hash));
    }
    bool match;
    {
        ScopedFlag not_skipping(skipping_, false);
        if (keyword.is_word("case")) {
            double v = parse_float_param();
            match = std::abs(v - cond_.back().switch_value) < kEpsilon;
        } else {
            expect_punct("(", "after #range");
            double lo = parse_float();
            accept_comma();
            double hi = parse_float();
            expect_punct(")", "after the #range bounds");
            double s = cond_.back().switch_value;
            match = s >= lo && s <= hi;
        }
    }
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
    (void)keyword;
}

void SceneParser::directive_macro(const Token& hash, const Token& keyword) {
    Token name = lookahead_.empty() ? raw_next() : next();
    if (!is_identifier(name)) {
        fail(name, "expected the macro name after #macro, got " + describe(name));
    }
    auto macro = std::make_shared<MacroDef>();
    macro->name = name.text();
    macro->loc = name.loc();
    macro->file = frames_.back().file;
    Token open = raw_next();
    if (!open.is_punct("(")) fail(open, "expected '(' after the macro name, got " + describe(open));
    // Commas between parameters are optional and a trailing one is allowed, as in POV-Ray.
    while (true) {
        Token p = raw_next();
        if (p.is_punct(")")) break;
        if (p.is_punct(",") && !macro->parameters.empty()) continue;
        if (!is_identifier(p)) {
            fail(p, "expected a parameter name or ')' in #macro " + macro->name + ", got " +
                        describe(p));
        }
        macro->parameters.push_back(p.text());
    }
    macro->body_begin = frames_.back().pos;
    // Macros are global, as in POV-Ray.
    tables_[0][macro->name] =
        std::make_shared<Symbol>(Symbol{Value{std::shared_ptr<const MacroDef>(macro)}, name.loc()});
    push_cond(Cond::DeclaringMacro, hash, keyword);
    cond_.back().macro = macro;
    skip_tokens(Cond::DeclaringMacro);
}

void SceneParser::invoke_macro(const Token& name, const std::shared_ptr<const MacroDef>& macro) {
    expect_punct("(", "after the macro name '" + macro->name + "'");
    const std::size_t expected = macro->parameters.size();
    std::vector<std::shared_ptr<Symbol>> args;
    auto count_error = [&](std::size_t got) {
        fail(name, "macro '" + macro->name + "' expects " + std::to_string(expected) +
                       (expected == 1 ? " argument" : " arguments") + ", got " +
                       std::to_string(got) + " (declared at " + place(macro->loc, name) + ")");
    };
    for (std::size_t i = 0; i < expected; ++i) {
        if (peek_punct(")")) count_error(i);
        const Token& a = peek(0);
        // A lone identifier is passed by reference: the macro may change it.
        if (is_identifier(a) && a.symbol && (peek_punct(",", 1) || peek_punct(")", 1))) {
            args.push_back(a.symbol);
            next();
        } else {
            Token at = peek(0);
            args.push_back(std::make_shared<Symbol>(Symbol{parse_rvalue(at, true), at.loc()}));
        }
        accept_comma();
    }
    if (!peek_punct(")")) {
        std::size_t got = expected;
        while (!peek_punct(")") && !peek(0).is_eof()) {
            parse_rvalue(peek(0), true);
            ++got;
            accept_comma();
        }
        count_error(got);
    }
    next();  // ')'
    push_frame(macro->file, macro->body_begin, macro->body_end, FrameContext::Kind::Macro,
               macro->name, name);
    for (std::size_t i = 0; i < expected; ++i) tables_.back()[macro->parameters[i]] = args[i];
}

void SceneParser::directive_declare(const Token& keyword, bool local) {
    Token name = lookahead_.empty() ? raw_next() : next();
    if (name.is_word("deprecated")) {
        // #declare deprecated [once] ["message"] Name = ...: the warning is not kept.
        name = raw_next();
        if (name.is_word("once")) name = raw_next();
        if (name.kind() == TokenKind::String) name = raw_next();
    }
    if (name.kind() != TokenKind::Identifier) {
        fail(name, "expected an identifier after #" + keyword.text() + ", got " + describe(name));
    }
    if (is_reserved_word(name.text())) {
        fail(name, "cannot #" + keyword.text() + " '" + name.text() + "': it is a reserved word");
    }
    std::shared_ptr<Symbol> sym = lookup(name.text());
    std::shared_ptr<Value>* element = nullptr;
    if (sym && std::holds_alternative<ArrayValue>(sym->value.data) && peek_array_index()) {
        element = &index_array(std::get<ArrayValue>(sym->value.data), name);
    }
    expect_punct("=", "after '" + name.text() + "'");
    // The value may end inside a macro's body (#local V = F(x) with F's last token a ';'),
    // while that macro's table is still open: the identifier belongs to this scope.
    const std::size_t scope = tables_.size();
    Value value = parse_declared_value(name);
    if (element) {
        *element = std::make_shared<Value>(std::move(value));
    } else {
        declare(name, std::move(value), local, scope);
    }
}

void SceneParser::directive_undef(const Token& keyword) {
    Token name = lookahead_.empty() ? raw_next() : next();
    if (!is_identifier(name))
        fail(name, "expected an identifier after #undef, got " + describe(name));
    for (std::size_t i = tables_.size(); i-- > 0;) {
        if (tables_[i].erase(name.text())) return;
    }
    add_message(name, "warning", "#undef of an undefined identifier '" + name.text() + "'");
    (void)keyword;
}

void SceneParser::directive_include(const Token& hash, const Token& keyword) {
    Token at = peek(0);
    std::string name = parse_string(/*pathname=*/true);
    if (frames_.size() > kMaxIncludeDepth + static_cast<std::size_t>(macro_depth_)) {
        fail(at, "too many nested include files");
    }
    std::vector<std::string> searched;
    std::string found;
    if (std::filesystem::path(name).is_absolute()) {
        searched.push_back(name);
        if (is_regular_file(name)) found = name;
    } else {
        std::string dir = parent_directory(frames_.back().file->path);
        std::vector<std::string> dirs{dir};
        for (const std::string& lib : options_.library_paths) dirs.push_back(lib);
        for (const std::string& d : dirs) {
            std::string candidate = join_path(d, name);
            searched.push_back(d.empty() ? "." : d);
            if (is_regular_file(candidate)) {
                found = candidate;
                break;
            }
        }
    }
    if (found.empty()) {
        std::string list;
        for (const std::string& s : searched) list += (list.empty() ? "" : ", ") + s;
        fail(at, "cannot find include file '" + name + "' (searched: " + list + ")");
    }
    std::shared_ptr<SourceFile> file;
    if (auto it = file_cache_.find(found); it != file_cache_.end()) {
        file = it->second;
    } else {
        std::string text;
        if (!read_text_file(found, text)) fail(at, "cannot read include file '" + found + "'");
        // Lex errors in the included file name the include chain.
        auto context = std::make_shared<FrameContext>();
        context->kind = FrameContext::Kind::Include;
        context->entered_at = hash.loc();
        context->parent = frames_.back().context;
        file = std::make_shared<SourceFile>();
        file->path = found;
        file->text = std::move(text);
        if (auto error = lex_source(*file)) {
            fail_at(*file, error->line, error->column, context, error->message);
        }
        file_cache_[found] = file;
    }
    push_frame(file, 0, file->tokens.size() - 1, FrameContext::Kind::Include, "", hash);
    (void)keyword;
}

void SceneParser::directive_version(const Token& keyword) {
    if (peek_word("unofficial")) next();
    double version;
    {
        ScopedFlag defer(defer_directives_, true);
        Token at = peek(0);
        version = parse_float();
        accept_punct(";");
        if (version > 3.71) {
            fail(at, "this scene needs POV-Ray " + format_str(version, 0, -1) +
                         "; mirage reads the language of POV-Ray 3.7");
        }
        if (version < 3.5) {
            unsupported(at, "language version " + format_str(version, 0, 2) +
                                " (mirage follows the language of 3.5 and later)");
        }
    }
    language_version_ = version;
    (void)keyword;
}

void SceneParser::directive_message(const Token& hash, const Token& keyword) {
    std::string text = parse_string(false);
    if (keyword.is_word("error")) fail(hash, "#error: " + text);
    add_message(hash, keyword.is_word("warning") ? "warning" : "debug", text);
}

void SceneParser::directive_default(const Token& keyword) {
    expect_open_brace(keyword);
    while (true) {
        const Token& t = peek(0);
        if (t.is_punct("}")) break;
        Token item = next();
        if (item.is_word("texture")) {
            expect_open_brace(item);
            default_texture_ = parse_texture_body(item);
            expect_close_brace(item);
        } else if (item.is_word("pigment")) {
            expect_open_brace(item);
            parse_pigment_body(default_texture_.pigment, item);
            expect_close_brace(item);
        } else if (item.is_word("finish")) {
            parse_finish_block(default_texture_.finish, item);
        } else if (item.is_word("normal") || item.is_word("radiosity") || item.is_word("camera")) {
            skip_unsupported(item, Arity::Block, "#default item '" + item.text() + "'");
        } else {
            fail(item,
                 "expected texture, pigment, finish or '}' in #default, got " + describe(item));
        }
    }
    expect_close_brace(keyword);
}

// ---------------------------------------------------------------------------------------
// Values: the right-hand side of #declare, macro arguments, identifiers (POV-Ray's
// Parse_RValue)

const Value* SceneParser::peek_identifier_value(std::size_t ahead) {
    const Token& t = peek(ahead);
    if (!is_identifier(t)) return nullptr;
    std::shared_ptr<Symbol> sym = t.symbol ? t.symbol : lookup(t.text());
    if (!sym) return nullptr;
    if (auto* a = std::get_if<ArrayValue>(&sym->value.data)) {
        if (peek_array_index(ahead + 1)) {
            // The first element assigned stands for the type of the array's elements.
            for (const auto& e : a->elements) {
                if (e) return e.get();
            }
            return nullptr;
        }
    }
    return &use_value(t, *sym, sym->value);
}

std::shared_ptr<Value>& SceneParser::index_array(ArrayValue& array, const Token& name) {
    std::size_t index = 0;
    for (std::size_t d = 0; d < array.sizes.size(); ++d) {
        Token open = expect_punct("[", "for an index of the array '" + name.text() + "'");
        double v = parse_float();
        int k = static_cast<int>(v + kEpsilon);
        if (v < -kEpsilon || k < 0 || k >= array.sizes[d]) {
            fail(open, "index " + format_str(v, 0, -1) + " of the array '" + name.text() +
                           "' is out of range 0 to " + std::to_string(array.sizes[d] - 1));
        }
        index = index * static_cast<std::size_t>(array.sizes[d]) + static_cast<std::size_t>(k);
        expect_punct("]", "after an array index");
    }
    return array.elements[index];
}

Value SceneParser::identifier_value(const Token& name) {
    std::shared_ptr<Symbol> sym = name.symbol ? name.symbol : lookup(name.text());
    if (!sym) fail(name, "undefined identifier '" + name.text() + "'");
    if (auto* a = std::get_if<ArrayValue>(&sym->value.data)) {
        if (peek_array_index()) {
            Token at = peek(0);
            std::shared_ptr<Value>& e = index_array(*a, name);
            if (!e) fail(at, "element of the array '" + name.text() + "' used before it is set");
            return deep_copy(use_value(name, *sym, *e));
        }
    }
    return deep_copy(use_value(name, *sym, sym->value));
}

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
        if (v && std::holds_alternative<Numeric>(v->data)) return numeric();
        if (v && std::holds_alternative<std::shared_ptr<const FunctionCode>>(v->data)) {
            ScopedFlag defer(defer_directives_, true);
            if (peek(1).is_punct("(")) return numeric();  // F(...): a call, not a copy
        }
        if (v && std::holds_alternative<OpaqueValue>(v->data)) {
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
                if (!texture_is_opaque(top)) {
                    unsupported(layer, "layered texture with filter or transmit");
                }
                tex = top;
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
    while (peek_deferred("[")) {
        Token open = next();
        double v = parse_float();
        int n = static_cast<int>(v + kEpsilon);
        if (n <= 0) fail(open, "an array dimension must be at least 1");
        array.sizes.push_back(n);
        expect_punct("]", "after an array dimension");
    }
    if (array.sizes.empty()) {
        fail(peek(0), "expected '[' and a size after 'array', got " + describe(peek(0)));
    }
    std::size_t total = 1;
    for (int s : array.sizes) total *= static_cast<std::size_t>(s);
    if (total > 100000000) fail(keyword, "array too large");
    array.elements.resize(total);
    if (peek_deferred("{")) parse_array_initializer(array, 0, 0, keyword);
    return Value{std::move(array)};
}

void SceneParser::parse_array_initializer(ArrayValue& array, std::size_t dim, std::size_t base,
                                          const Token& name) {
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
