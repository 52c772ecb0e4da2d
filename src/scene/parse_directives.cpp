// The directives that are not conditionals: #macro and macro calls, #declare, #local,
// #undef, #include, #version, #debug, #warning, #error and #default.
#include <filesystem>
#include <optional>

#include "scene/keywords.h"
#include "scene/scene_parser.h"
#include "util/text_escape.h"

namespace mirage::scene_detail {
namespace {

constexpr std::size_t kMaxIncludeDepth = 64;

// Where an include is looked for: anything but a directory counts as found, so that a
// device or a pipe named in #include is refused by what reads it with a message saying so.
bool is_candidate(const std::string& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    return !ec && std::filesystem::exists(status) && !std::filesystem::is_directory(status);
}

std::string parent_directory(const std::string& path) {
    return std::filesystem::path(path).parent_path().generic_string();
}

std::string join_path(const std::string& dir, const std::string& name) {
    if (dir.empty()) return name;
    return (std::filesystem::path(dir) / name).lexically_normal().generic_string();
}

}  // namespace

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
    // An array element is remembered by its index: the directives in the value may declare
    // the array anew, and a pointer into the old one would dangle.
    std::optional<std::size_t> element;
    const void* elements = nullptr;
    if (sym && sym->value.holds<ArrayValue>() && peek_array_index()) {
        ArrayValue& array = sym->value.get<ArrayValue>();
        element = static_cast<std::size_t>(&index_array(array, name) - array.elements.data());
        elements = array.elements.data();
    }
    expect_punct("=", "after '" + name.text() + "'");
    // The value may end inside a macro's body (#local V = F(x) with F's last token a ';'),
    // while that macro's table is still open: the identifier belongs to this scope.
    const std::size_t scope = tables_.size();
    Value value = parse_declared_value(name);
    if (element) {
        auto* array = sym->value.get_if<ArrayValue>();
        if (!array || array->elements.data() != elements || *element >= array->elements.size()) {
            fail(name, "the array '" + name.text() +
                           "' was declared anew while the value of its element was read");
        }
        array->elements[*element] = std::make_shared<Value>(std::move(value));
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
        fail_fatal(at, "too many nested include files");
    }
    std::vector<std::string> searched;
    std::string found;
    if (std::filesystem::path(name).is_absolute()) {
        searched.push_back(name);
        if (is_candidate(name)) found = name;
    } else {
        std::string dir = parent_directory(frames_.back().file->path);
        std::vector<std::string> dirs{dir};
        for (const std::string& lib : options_.library_paths) dirs.push_back(lib);
        for (const std::string& d : dirs) {
            std::string candidate = join_path(d, name);
            searched.push_back(d.empty() ? "." : d);
            if (is_candidate(candidate)) {
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
        std::string text = read_source(found, &at);
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
    // The scene's own words, printed on a terminal: NULs and escape sequences as escapes
    // (its line ends kept: "#debug concat(..., \"\\n\")" ends its own lines).
    std::string text = escape_terminal(parse_string(false));
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
        } else if (item.is_word("normal")) {
            if (!default_texture_.normal) default_texture_.normal = Normal{};
            expect_open_brace(item);
            parse_normal_body(*default_texture_.normal, item);
            expect_close_brace(item);
        } else if (item.is_word("radiosity") || item.is_word("camera")) {
            skip_unsupported(item, Arity::Block, "#default item '" + item.text() + "'");
        } else {
            fail(item,
                 "expected texture, pigment, finish or '}' in #default, got " + describe(item));
        }
    }
    expect_close_brace(keyword);
}

}  // namespace mirage::scene_detail
