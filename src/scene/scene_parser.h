// The scene parser's internals, shared by its implementation files:
//   token_stream.cpp       frames (files, includes, macro bodies), processed tokens, messages
//   symbols.cpp            symbol tables, identifier values, array elements
//   parse_conditionals.cpp #if, #switch, #while, #for and the rest of the conditional stack
//   parse_directives.cpp   #macro and macro calls, #declare, #undef, #include and the others
//   parse_values.cpp       the right-hand side of #declare, macro arguments, arrays
//   parse_expressions.cpp  float, vector, colour and string expressions
//   parse_objects.cpp      objects, transforms, light sources, the camera
//   parse_materials.cpp    textures, pigments, finishes, colour maps
//   parser.cpp             the public entry points and the top level of a scene file
//
// Like POV-Ray, the parser reads processed tokens: directives are carried out and macros
// expanded as tokens are fetched, so that a directive may appear anywhere between tokens.
// Errors are thrown as ParseFailure (a recursive-descent parser meets them deep down) and
// turned into Result errors at the entry points; nothing escapes the library.
#pragma once

#include <climits>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "scene/camera.h"
#include "scene/lexer.h"
#include "scene/object_tree.h"
#include "scene/parser.h"
#include "scene/scene.h"
#include "scene/value.h"

namespace mirage {
class TrueTypeFont;
}

namespace mirage::scene_detail {

/// A complete, formatted error message, thrown from deep in the parser.
struct ParseFailure {
    std::string message;
    std::string reason;        // the message alone, without its place (for opaque values)
    FileLoc loc;               // its place
    bool from_opaque = false;  // a use of an opaque value (see OpaqueValue)
    bool fatal = false;        // a limit reached or a loop cut: the lenient parse stops too
};

/// Why a file is being read: the main file, an #include, or a macro body.  Chained to the
/// frame it was entered from, for the "included from" lines of messages.
struct FrameContext {
    enum class Kind { Main, Include, Macro };
    Kind kind = Kind::Main;
    std::string macro_name;
    FileLoc entered_at;  // the #include directive or the macro call
    std::shared_ptr<const FrameContext> parent;
};

/// A named value in a symbol table.  Macro parameters passed by reference share the
/// caller's Symbol.
struct Symbol {
    Value value;
    FileLoc loc;
};

/// A processed token: a raw token with the file and frame it came from and, for identifiers,
/// the symbol it named when it was read (POV-Ray resolves identifiers as it reads them).
struct Token {
    const RawToken* raw = nullptr;
    std::shared_ptr<const SourceFile> file;
    std::shared_ptr<const FrameContext> context;
    std::shared_ptr<Symbol> symbol;
    std::size_t index = 0;  // of the raw token in its file
    // A '#' or a macro name read while directives were deferred (see defer_directives_): the
    // directive or the call is carried out when the token is next fetched without deferral.
    bool deferred_directive = false;
    bool deferred_macro = false;

    TokenKind kind() const { return raw->kind; }
    const std::string& text() const { return raw->text; }
    bool is_punct(std::string_view p) const { return kind() == TokenKind::Punct && text() == p; }
    bool is_word(std::string_view w) const {
        return kind() == TokenKind::Identifier && text() == w;
    }
    bool is_eof() const { return kind() == TokenKind::EndOfFile; }
    bool is_deferred() const { return deferred_directive || deferred_macro; }
    FileLoc loc() const { return FileLoc{file->path, raw->line, raw->column}; }
};

/// One entry of the conditional stack (POV-Ray's Cond_Stack).
enum class Cond {
    IfTrue,
    IfFalse,
    Else,
    While,
    For,
    Switch,
    CaseTrue,
    CaseFalse,
    SkipTilEnd,
    DeclaringMacro,
};

struct CondEntry {
    Cond type = Cond::IfTrue;
    std::string directive;  // "#if", "#while"... for messages
    FileLoc loc;
    int frame_id = 0;
    std::size_t loop_pos = 0;  // #while: the condition; #for: the first token of the body
    std::string for_variable;
    double for_end = 0.0, for_step = 1.0;
    double switch_value = 0.0;
    bool case_allowed = false;        // #switch: a #case or #range may follow
    std::shared_ptr<MacroDef> macro;  // #macro being declared
    // While the entry's condition or value is read ("the condition of '#while' at 1:1"): no
    // directive in it may close or change the entry.
    std::string busy;
    int directive_depth = 0;   // how many directives were being carried out when it opened
    std::uint64_t serial = 0;  // tells entries apart
};

/// A directive being carried out: its '#' and its keyword ("#declare"), for messages.
struct ActiveDirective {
    FileLoc loc;
    std::string keyword;
};

/// A file being read: the main file, an include or a macro body.
struct Frame {
    std::shared_ptr<const SourceFile> file;
    std::size_t pos = 0;
    std::size_t end = 0;  // one past the last token to read (the '#' of a macro's #end)
    FrameContext::Kind kind = FrameContext::Kind::Main;
    std::shared_ptr<const FrameContext> context;
    int id = 0;
    bool owns_table = false;  // includes and macros have their own #local table
};

/// How the arguments of an unsupported keyword are skipped in lenient mode.
enum class Arity {
    None,
    OptionalFloat,
    Float,
    FloatOptionalFloat,
    Vector,
    Colour,
    String,
    Block,
    AreaLight,  // vector, vector, float, float
    Rest,       // unknown: skip to the end of the enclosing block
};

/// Sets a flag for the lifetime of the scope.
class ScopedFlag {
  public:
    ScopedFlag(bool& flag, bool value) : flag_(flag), saved_(flag) { flag_ = value; }
    ~ScopedFlag() { flag_ = saved_; }
    ScopedFlag(const ScopedFlag&) = delete;
    ScopedFlag& operator=(const ScopedFlag&) = delete;

  private:
    bool& flag_;
    bool saved_;
};

class SceneParser {
  public:
    /// One more level of nesting (a parenthesis, an object, a directive...) for the lifetime
    /// of the scope; past ParseLimits::max_nesting the parse fails at `at`, long before the
    /// recursion could overflow the stack.
    class Nested {
      public:
        Nested(SceneParser& parser, const Token& at);
        ~Nested() { --parser_.nesting_; }
        Nested(const Nested&) = delete;
        Nested& operator=(const Nested&) = delete;

      private:
        SceneParser& parser_;
    };

    explicit SceneParser(const ParseOptions& options);

    /// Parses a whole scene.  Throws ParseFailure.
    Scene parse(std::shared_ptr<SourceFile> main_file);

    /// Reads and lexes a file (path as shown in messages); throws ParseFailure with `at`'s
    /// place when the file cannot be lexed.
    std::shared_ptr<SourceFile> load_file(const std::string& path, const std::string& text);

    /// The text of a file for the parse, which must be a regular file within the size limits
    /// (ParseLimits); `at` is the #include naming it, null for the main file.  Throws
    /// ParseFailure naming the file and what is wrong with it.
    std::string read_source(const std::string& path, const Token* at);

  private:
    // ---- errors and messages (token_stream.cpp) ----
    [[noreturn]] void fail(const Token& at, const std::string& message) const;
    /// fail() for a limit or a broken structure: no lenient recovery goes on after it (it
    /// would go round the same loop, or past the limit, again).
    [[noreturn]] void fail_fatal(const Token& at, const std::string& message) const;
    [[noreturn]] void fail_at(const SourceFile& file, int line, int column,
                              const std::shared_ptr<const FrameContext>& context,
                              const std::string& message) const;
    std::vector<std::string> context_lines(const std::shared_ptr<const FrameContext>& c) const;
    void add_message(const Token& at, const std::string& kind, const std::string& text);
    static std::string describe(const Token& t);
    static std::string place(const FileLoc& loc, const Token& relative_to);

    // ---- limits (token_stream.cpp) ----
    void count_objects(std::size_t count, const Token& at);
    void count_array_elements(std::size_t count, const Token& at);
    void check_string_size(const std::string& s, const Token& at) const;
    /// `v` as an int (truncated, as POV-Ray converts); an error naming `what` when it lies
    /// outside [lo, hi].
    int int_value(double v, const Token& at, const std::string& what, int lo = INT_MIN,
                  int hi = INT_MAX) const;

    // ---- token stream (token_stream.cpp) ----
    const Token& peek(std::size_t ahead = 0);
    Token next();
    bool peek_punct(std::string_view p, std::size_t ahead = 0) { return peek(ahead).is_punct(p); }
    bool peek_word(std::string_view w, std::size_t ahead = 0) { return peek(ahead).is_word(w); }
    bool accept_punct(std::string_view p);
    bool accept_word(std::string_view w);
    Token expect_punct(std::string_view p, std::string_view after);
    Token expect_open_brace(const Token& keyword);
    void expect_close_brace(const Token& keyword);
    void accept_comma() { accept_punct(","); }

    Token make_token(const std::shared_ptr<const SourceFile>& file, std::size_t index,
                     const std::shared_ptr<const FrameContext>& context);
    Token raw_next();
    void fetch();
    void fetch_until(std::size_t count);
    void run_deferred(std::size_t at);
    void resolve(Token& t);
    bool is_keyword(const Token& t) const;
    bool is_identifier(const Token& t) const;
    /// Ends the parse at `t` when it is a word that is neither a keyword nor declared: a
    /// typo where a block's item or its closing brace belongs.
    void reject_unknown_word(const Token& t);

    void push_frame(std::shared_ptr<const SourceFile> file, std::size_t begin, std::size_t end,
                    FrameContext::Kind kind, const std::string& macro_name, const Token& at);
    void pop_frame();
    void check_cond_closed_at_frame_end(const Token& eof);

    // ---- directives (parse_conditionals.cpp, parse_directives.cpp) ----
    void handle_directive(const Token& hash);
    void directive_if(const Token& hash, const Token& keyword, Cond true_type, bool value);
    void directive_else(const Token& hash, const Token& keyword);
    void directive_elseif(const Token& hash, const Token& keyword);
    void directive_end(const Token& hash, const Token& keyword);
    void directive_case(const Token& hash, const Token& keyword);
    void directive_switch(const Token& hash, const Token& keyword);
    void directive_while(const Token& hash, const Token& keyword);
    void directive_for(const Token& hash, const Token& keyword);
    void directive_break(const Token& hash, const Token& keyword);
    void directive_declare(const Token& keyword, bool local);
    void directive_undef(const Token& keyword);
    void directive_macro(const Token& hash, const Token& keyword);
    void directive_include(const Token& hash, const Token& keyword);
    void directive_version(const Token& keyword);
    void directive_message(const Token& hash, const Token& keyword);
    void directive_default(const Token& keyword);
    void directive_file_io(const Token& keyword);  // parse_opaque.cpp
    void push_cond(Cond type, const Token& hash, const Token& keyword);
    /// Reads a float parameter of the directive at `hash` while the top entry of the
    /// conditional stack is `busy_with` (see CondEntry::busy); `read` parses it.
    template <class Read>
    auto read_param_of_top(const Token& hash, const std::string& busy_with, Read read);
    void count_loop_pass(const CondEntry& loop, const Token& at);
    /// The loop on top of the conditional stack runs its body once more (a pass counted),
    /// or, when not `again`, its body is skipped to its #end.
    void go_round_or_skip(bool again, const Token& hash);
    /// Fails when the top entry of this frame is busy (CondEntry::busy).
    void check_not_busy(const Token& hash, const Token& keyword) const;
    void skip_tokens(Cond type);
    double parse_cond_param();
    bool parse_ifdef_param();
    void invoke_macro(const Token& name, const std::shared_ptr<const MacroDef>& macro);
    int current_frame_id() const { return frames_.back().id; }

    // ---- symbols (symbols.cpp) ----
    std::shared_ptr<Symbol> lookup(const std::string& name, int* depth = nullptr) const;
    /// #local declares into the table `scope` levels deep (default: the innermost), the
    /// scope the directive stands in even when its value ended inside a macro's body.
    void declare(const Token& name_token, Value value, bool local, std::size_t scope = 0);

    // ---- values (parse_values.cpp; identifier values in symbols.cpp) ----
    Value parse_rvalue(const Token& for_name, bool is_macro_argument);
    Value parse_array_declaration(const Token& keyword);
    void parse_array_initializer(ArrayValue& array, std::size_t dim, std::size_t base,
                                 const Token& name);
    Value parse_unsupported_value(const Token& keyword);
    const Value* peek_identifier_value(std::size_t ahead = 0);
    Value identifier_value(const Token& name);
    /// The value of the identifier `name` (just read) as a T; an error naming `expected`
    /// otherwise (an array element may differ from the element the dispatch looked at).
    template <class T>
    T identifier_as(const Token& name, const char* expected) {
        Value v = identifier_value(name);
        if (auto* x = v.get_if<T>()) return std::move(*x);
        fail(name, std::string("expected ") + expected + ", got " + value_type_name(v));
    }
    std::shared_ptr<Value>& index_array(ArrayValue& array, const Token& name);
    // Whether '[' follows (an array index).  The look never runs a directive: POV-Ray peeks
    // at the characters after an array name.
    bool peek_array_index(std::size_t ahead = 0) {
        ScopedFlag defer(defer_directives_, true);
        return peek_punct("[", ahead);
    }

    // ---- opaque values (parse_opaque.cpp) ----
    /// Collects the first reason a declaration cannot be evaluated (see OpaqueValue).
    struct OpaqueCapture {
        bool captured = false;
        std::string reason;
        FileLoc loc;
    };
    /// The right-hand side of a #declare or #local: parse_rvalue, kept as an OpaqueValue when
    /// something in it is unsupported (strict and lenient) or cannot be read (lenient).
    Value parse_declared_value(const Token& name);
    /// What the value of the identifier `name` stands for when it is used: the value itself,
    /// or for an opaque value its lenient stand-in; fails at the use (with the opaque value's
    /// reason) when there is none.  Inside a declaration the use makes that one opaque too.
    const Value& use_value(const Token& name, const Symbol& symbol, const Value& value);
    [[noreturn]] void fail_opaque_use(const Token& name, const Symbol& symbol,
                                      const OpaqueValue& value);
    /// After a failure in a statement that began with brace balance `balance`: skips to its end
    /// (the braces opened since closed, or the ';' of a value without braces).
    void recover_statement(int balance);
    OpaqueCapture* opaque_capture_ = nullptr;
    bool copying_value_ = false;   // parse_rvalue copies an identifier: opaque values stay so
    int brace_balance_ = 0;        // '{' minus '}' read by next()
    std::size_t tokens_read_ = 0;  // tokens read by next()
    std::map<std::string, Value> stand_ins_;

    // ---- expressions (parse_expressions.cpp) ----
    Numeric parse_express();
    Numeric parse_logical();
    Numeric parse_rel_term();
    Numeric parse_rel_factor();
    Numeric parse_num_term();
    Numeric parse_num_factor();
    Numeric parse_factor_body();
    Numeric parse_function(const Token& name);
    // The built-in functions by family (parse_expressions.cpp): the value, or nullopt when
    // the name is not one of the family's.
    std::optional<Numeric> builtin_constant(const std::string& name) const;
    std::optional<Numeric> parse_one_float_function(const Token& name);
    std::optional<Numeric> parse_float_list_function(const Token& name);
    std::optional<Numeric> parse_string_argument_function(const Token& name);
    std::optional<Numeric> parse_vector_function(const Token& name);
    std::optional<Numeric> parse_array_function(const Token& name);
    Numeric parse_object_function(const Token& name);  // trace, inside, min/max_extent
    // ---- user functions (parse_functions.cpp) ----
    /// After 'function': [( parameters )] { expression | internal(n) }.
    Value parse_function_value(const Token& keyword);
    std::shared_ptr<const FunctionCode> parse_function_block(const Token& keyword,
                                                             std::vector<std::string> parameters);
    /// A call F(a, b, ...) of a function value in a float expression.
    double call_function_value(const Token& name, const FunctionCode& f);
    int parse_function_expression(FunctionCode& f, int level);
    int parse_function_primary(FunctionCode& f);
    Numeric parse_identifier_value(const Token& t);
    Numeric apply_period(const Numeric& value, const Token& dot);
    /// The component a member name after '.' takes, as POV-Ray numbers them: x, y, z, t (u, v;
    /// red, green, blue, filter, transmit) 0 to 4, gray 5; -1 for any other token.
    static int member_index(const Token& member);
    double parse_float();
    double parse_float_param();
    glm::dvec3 parse_vector();
    Numeric parse_vector_n(int size, std::string_view what);
    glm::dvec3 parse_scale_vector();
    Colour parse_colour(bool expect_filter_transmit);
    glm::dvec3 parse_rgb_colour();
    std::string parse_string(bool pathname);
    std::string parse_string_body(bool pathname);
    /// `value` when every component is finite; an error at `at` otherwise.
    Numeric finite(const Numeric& value, const Token& at) const;
    bool starts_string(const Token& t) const;
    bool starts_float(const Token& t) const;
    bool starts_vector(const Token& t) const;
    bool starts_colour(const Token& t) const;
    bool starts_expression(const Token& t) const { return starts_vector(t) || starts_colour(t); }
    double allow_float(double default_value);
    std::string format_str(double value, int width, int precision) const;
    double rand_next(int stream, const Token& at);

    // ---- objects (parse_objects.cpp) ----
    bool starts_object(const Token& t) const;
    bool is_unsupported_object_keyword(const Token& t) const;
    std::optional<ObjectNode> parse_object();
    // The recursive path of the object parse fills the (default) node it is given: false
    // when no object starts here.
    bool parse_object_to(ObjectNode& out);
    bool parse_object_unguarded(ObjectNode& out);
    void parse_objects_into(std::vector<ObjectNode>& list);
    void copy_named_object(ObjectNode& out);  // the declared object named next
    bool parse_modified_copy(const Token& keyword, ObjectNode& out);
    void parse_shape(const Token& keyword, ObjectNode& out);
    void parse_union(const Token& keyword, ObjectNode& out);
    void parse_csg(const Token& keyword, ObjectNode& out);
    void parse_unknown_object(const Token& keyword, ObjectNode& out);
    void parse_bound_or_clip(ObjectNode& object);
    // ---- shapes (parse_shapes.cpp) ----
    static bool is_shape_keyword(const std::string& word);
    Shape parse_shape_arguments(const Token& keyword);
    Shape parse_blob(const Token& keyword);
    Shape parse_polygon(const Token& keyword);
    Shape parse_triangle(const Token& keyword);  // triangle, smooth_triangle
    Shape parse_lathe();
    Shape parse_sor();
    Shape parse_prism();
    Shape parse_poly(const Token& keyword);  // poly, cubic, quartic
    HeightField parse_height_field(const Token& keyword);
    ObjectNode parse_mesh(const Token& keyword);
    struct MeshParts;  // a mesh's faces and their textures (parse_shapes.cpp)
    void parse_mesh_items(MeshParts& parts);
    void parse_mesh2_items(const Token& keyword, MeshParts& parts);
    static ObjectNode mesh_object(const Token& keyword, const MeshParts& parts);
    Shape parse_text(const Token& keyword);
    Shape parse_isosurface(const Token& keyword);
    /// A file the scene names (a font, an image, a height field, file_exists' argument), looked
    /// up as POV-Ray does: in the including file's directory, then the library paths (an
    /// absolute name as given), each also with `extension` added when there is one; "" if none.
    std::string find_scene_file(const std::string& name, const std::string& extension = "") const;
    std::map<std::string, std::shared_ptr<TrueTypeFont>> fonts_;
    std::optional<Texture> parse_mesh_triangle_texture();
    void parse_object_statement(const Token& keyword, ObjectNode& out);
    void parse_light_source(const Token& keyword, ObjectNode& out);
    void parse_object_modifiers(ObjectNode& object, const Token& keyword);
    bool parse_transform_item(Transform& t);
    Transform parse_transform_block(const Token& keyword);
    std::array<double, 12> parse_matrix(const Token& keyword);
    CameraState parse_camera(const Token& keyword);
    void parse_camera_into_scene(const Token& keyword);

    // ---- materials (parse_materials.cpp) ----
    Texture parse_texture_body(const Token& keyword);
    void parse_pigment_body(Pigment& pigment, const Token& keyword);
    void parse_normal_body(Normal& normal, const Token& keyword);
    void parse_finish_block(Finish& finish, const Token& keyword);
    void parse_interior_block(Interior& interior, const Token& keyword);
    /// An ior or dispersion: 0 or from 0.001 to 1000 (an error at its place otherwise).
    double parse_index_of_refraction(const char* name);
    Material parse_material_block(Material base, const Token& keyword);
    Fog parse_fog_block(const Token& keyword);
    std::vector<ColourMapEntry> parse_colour_map(const Token& keyword);
    void set_texture(ObjectNode& object, Texture texture, const Token& at);
    /// The texture `top` laid over `texture` (POV-Ray's Link_Textures), an error at `at` when
    /// a patterned texture is involved.
    void layer_texture(Texture& texture, Texture top, const Token& at);
    /// An object modifier of the materials (normal, interior, material, hollow) at the next
    /// token: parses it into `object` and returns true, or returns false.
    bool parse_material_modifier(ObjectNode& object);
    /// A light source item beyond the colour and shadowless (spotlight, area_light, fade...):
    /// parses it and returns true, or returns false.
    bool parse_light_item(PointLight& light);
    /// The value of a #declare of a normal, interior, material, fog or map, when the next
    /// token starts one.
    std::optional<Value> parse_material_value();
    /// global_settings items of the materials (noise_generator, number_of_waves...).
    bool parse_material_global_setting();

    struct PatternTargets;  // where a pattern's maps and lists go (parse_materials.cpp)
    enum class PatternUse { Pigment, Normal, Texture };
    void parse_pattern(Pattern& pattern, PatternUse use, PatternTargets& targets,
                       const Token& keyword);
    bool parse_pattern_type(Pattern& pattern, PatternUse use, PatternTargets& targets);
    void parse_slope_pattern(Pattern& pattern);
    bool parse_pattern_kind_modifier(Pattern& pattern, PatternUse use, PatternTargets& targets);
    bool parse_pattern_map(Pattern& pattern, PatternUse use, PatternTargets& targets);
    void skip_unsupported_pattern(Pattern& pattern);
    void parse_list_pattern(Pattern& pattern, PatternKind list, PatternUse use,
                            PatternTargets& targets);
    void parse_blend_list(Pattern& pattern, int count, PatternUse use, PatternTargets& targets);
    void parse_warp(Pattern& pattern, const Token& keyword);
    void parse_image_map(Pattern& pattern, PatternUse use, const Token& keyword, double* amount);
    std::vector<PigmentMapEntry> parse_pigment_map(const Token& keyword);
    std::vector<NormalMapEntry> parse_normal_map(const Token& keyword);
    std::vector<TextureMapEntry> parse_texture_map(const Token& keyword);
    std::vector<SlopeMapEntry> parse_slope_map(const Token& keyword);
    bool explicit_noise_generator_ = false;
    bool skipped_pattern_ = false;  // lenient mode skipped an unsupported pattern

    // ---- the scene (parser.cpp) ----
    void parse_top_level();
    bool parse_top_level_item();  // false at the end of the file
    void parse_global_settings(const Token& keyword);
    void parse_background(const Token& keyword);
    void parse_sky_sphere(const Token& keyword);
    SkySphere parse_sky_sphere_value(const Token& keyword);
    void add_object_to_scene(const ObjectNode& object);
    void export_symbols();

    // ---- lenient mode (parser.cpp) ----
    // `description` names the feature, e.g. "object 'isosurface'" or "modifier 'normal' in
    // 'sphere'": strict mode fails with "unsupported <description>", lenient mode records it.
    void unsupported(const Token& at, const std::string& description);
    void skip_arguments(Arity arity, const Token& keyword);
    void skip_block();
    void skip_rest_of_block();
    void skip_unsupported(const Token& keyword, Arity arity, const std::string& description);

    const ParseOptions& options_;
    const AnimationClock animation_;  // clock, clock_on and the frame identifiers
    Scene scene_;

    std::vector<Frame> frames_;
    int next_frame_id_ = 0;
    std::deque<Token> lookahead_;
    std::vector<CondEntry> cond_;
    bool skipping_ = false;
    bool defer_directives_ = false;
    int macro_depth_ = 0;

    int nesting_ = 0;
    // The lowest stack address the parse may reach before a Nested refuses to go deeper
    // (set by parse(); 0: not known, only max_nesting applies).  The level count alone does
    // not bound the stack: a level's frames are some hundred bytes in an optimized build and
    // over 100 KiB with AddressSanitizer, and threads have smaller stacks than the main one.
    std::uintptr_t stack_floor_ = 0;
    std::vector<ActiveDirective> directives_;  // innermost last
    std::uint64_t cond_serial_ = 0;
    std::int64_t loop_passes_ = 0;
    std::int64_t raw_tokens_read_ = 0;  // every token read, each time it is read (max_tokens)
    std::size_t objects_ = 0, array_elements_ = 0;
    std::uintmax_t source_bytes_ = 0;

    std::vector<std::unordered_map<std::string, std::shared_ptr<Symbol>>> tables_;
    std::map<std::string, std::shared_ptr<SourceFile>> file_cache_;

    double language_version_ = 3.7;
    bool gamma_set_ = false;  // assumed_gamma given (srgb colours need it)
    double assumed_gamma_ = 1.0;
    Texture default_texture_;
    std::vector<unsigned> rand_streams_;
    bool had_camera_ = false;
};

}  // namespace mirage::scene_detail
