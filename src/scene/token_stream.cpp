// The token stream of the scene parser, after POV-Ray 3.7's tokenize.cpp: the frames being
// read (main file, includes, macro bodies), processed tokens with directives carried out and
// macros expanded as they are fetched, and the messages that name a token's place.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/diagnostics.h"
#include "scene/keywords.h"
#include "scene/scene_parser.h"
#include "util/format.h"
#include "util/input_file.h"

namespace mirage::scene_detail {
namespace {

constexpr std::size_t kMaxFrames = 1000;

}  // namespace

// ---------------------------------------------------------------------------------------
// Limits

SceneParser::Nested::Nested(SceneParser& parser, const Token& at) : parser_(parser) {
    const int limit = parser_.options_.limits.max_nesting;
    if (parser_.nesting_ >= limit) {
        parser_.fail_fatal(at, "nesting too deep: more than " + std::to_string(limit) +
                                   " levels of parentheses, objects and directives inside each "
                                   "other");
    }
    const auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    if (here < parser_.stack_floor_) {
        parser_.fail_fatal(at,
                           "nesting too deep: " + std::to_string(parser_.nesting_) +
                               " levels of parentheses, objects and directives inside each other "
                               "fill the stack this parse has");
    }
    ++parser_.nesting_;
}

void SceneParser::count_objects(std::size_t count, const Token& at) {
    objects_ += count;
    if (objects_ > options_.limits.max_objects) {
        fail_fatal(at, "more than " + std::to_string(options_.limits.max_objects) +
                           " objects parsed or copied in all, mirage's limit");
    }
}

void SceneParser::count_array_elements(std::size_t count, const Token& at) {
    array_elements_ += count;
    if (array_elements_ > options_.limits.max_total_array_elements) {
        fail_fatal(at, "more than " + std::to_string(options_.limits.max_total_array_elements) +
                           " array elements made or copied in all, mirage's limit");
    }
}

void SceneParser::check_string_size(const std::string& s, const Token& at) const {
    if (s.size() > options_.limits.max_string_bytes) {
        fail(at, "a string of " + std::to_string(s.size()) + " bytes, more than the " +
                     bytes_text(options_.limits.max_string_bytes) + " mirage keeps");
    }
}

int SceneParser::int_value(double v, const Token& at, const std::string& what, int lo,
                           int hi) const {
    if (!(v >= lo && v <= hi)) {
        fail(at, what + " " + shortest(v) + " is out of range: it must be from " +
                     std::to_string(lo) + " to " + std::to_string(hi));
    }
    return static_cast<int>(v);
}

std::string SceneParser::read_source(const std::string& path, const Token* at) {
    auto refuse = [&](const std::string& why) {
        if (at) fail_fatal(*at, "include file '" + path + "' " + why);
        ParseFailure failure{path + ": " + why};
        failure.fatal = true;
        throw failure;
    };
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
        refuse(std::string("cannot be opened: ") +
               (ec ? ec.message() : std::string(std::strerror(ENOENT))));
    }
    if (fs::is_directory(status)) refuse("is a directory, not a scene file");
    if (!fs::is_regular_file(status)) {
        refuse("is not a regular file (a device, a pipe or a socket?): scenes are read from files");
    }
    const ParseLimits& limits = options_.limits;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) refuse("cannot be read: " + ec.message());
    auto too_large = [&](std::uintmax_t bytes) {
        refuse((source_bytes_ == 0 ? "is " : "would bring the files read to ") + bytes_text(bytes) +
               ", more than the " + bytes_text(limits.max_source_bytes) +
               " mirage reads (the scene and its include files together)");
    };
    if (source_bytes_ + size > limits.max_source_bytes) too_large(source_bytes_ + size);
    std::ifstream in(path, std::ios::binary);
    if (!in) refuse(std::string("cannot be opened: ") + std::strerror(errno));
    std::string text;
    text.reserve(static_cast<std::size_t>(size));
    if (!read_at_most(in, limits.max_source_bytes - source_bytes_, text))
        too_large(source_bytes_ + text.size());
    if (in.bad()) refuse(std::string("cannot be read: ") + std::strerror(errno));
    source_bytes_ += text.size();
    scene_.files.push_back(path);
    return text;
}

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
        const std::string where = to_string(f->entered_at);
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

void SceneParser::fail_fatal(const Token& at, const std::string& message) const {
    try {
        fail(at, message);
    } catch (ParseFailure& failure) {
        failure.fatal = true;
        throw;
    }
}

void SceneParser::fail(const Token& at, const std::string& message) const {
    fail_at(*at.file, at.raw->line, at.raw->column, at.context, message);
}

void SceneParser::add_message(const Token& at, const std::string& kind, const std::string& text) {
    scene_.messages.push_back(to_string(at.loc()) + ": " + kind + ": " + text);
}

std::string SceneParser::describe(const Token& t) {
    if (t.deferred_directive) return "'#'";
    // A long word is shown by its start.
    const std::string text = t.text().size() <= 40 ? t.text() : t.text().substr(0, 40) + "...";
    switch (t.kind()) {
        case TokenKind::EndOfFile:
            return "end of file";
        case TokenKind::String:
            return "string \"" + text + "\"";
        case TokenKind::Number:
        case TokenKind::Punct:
            return "'" + text + "'";
        case TokenKind::Identifier:
            if (is_reserved_word(t.text())) return "'" + text + "'";
            if (t.symbol) return value_type_name(t.symbol->value) + " identifier '" + text + "'";
            return "undefined identifier '" + text + "'";
    }
    return "'" + text + "'";
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
        fail_fatal(at, "too many nested macro calls and include files (more than " +
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
            Token t = make_token(f.file, index, f.context);
            if (++raw_tokens_read_ > options_.limits.max_tokens) {
                fail_fatal(t, "the scene reached mirage's limit of " +
                                  std::to_string(options_.limits.max_tokens) +
                                  " tokens read (those of loops, macros and include files each "
                                  "time they are read): an endless loop?");
            }
            return t;
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
    if (auto* opaque = sym->value.get_if<OpaqueValue>()) fail_opaque_use(t, *sym, *opaque);
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
                if (auto* m = t.symbol->value.get_if<std::shared_ptr<const MacroDef>>()) {
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
        auto* macro = t.symbol->value.get_if<std::shared_ptr<const MacroDef>>();
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

}  // namespace mirage::scene_detail
