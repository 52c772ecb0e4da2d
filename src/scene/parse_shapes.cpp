// The arguments of each shape, after POV-Ray 3.7's parse.cpp (Parse_Sphere, Parse_Cone...):
// what comes between a shape's '{' and its object modifiers.
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "scene/function.h"
#include "scene/image_file.h"
#include "scene/scene_parser.h"
#include "scene/transform.h"
#include "scene/truetype.h"
#include "util/file_name.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

}  // namespace

// The shapes parse_shape_arguments (or parse_mesh) reads.
const char* const kShapeKeywords[] = {
    "sphere",         "plane",      "box",          "cylinder", "disc",
    "cone",           "torus",      "quadric",      "triangle", "smooth_triangle",
    "polygon",        "mesh",       "mesh2",        "poly",     "cubic",
    "quartic",        "text",       "prism",        "lathe",    "sor",
    "superellipsoid", "isosurface", "height_field", "blob",
};

bool SceneParser::is_shape_keyword(const std::string& word) {
    for (const char* k : kShapeKeywords) {
        if (word == k) return true;
    }
    return false;
}

Shape SceneParser::parse_shape_arguments(const Token& kw) {
    const std::string& w = kw.text();
    if (w == "sphere") {
        Sphere s;
        s.center = parse_vector();
        accept_comma();
        s.radius = parse_float();
        return s;
    }
    if (w == "plane") {
        Plane p;
        Token at = peek(0);
        glm::dvec3 n = parse_vector();
        double length = glm::length(n);
        if (length < kEpsilon) fail(at, "degenerate plane normal");
        p.normal = n / length;
        accept_comma();
        p.distance = parse_float();
        return p;
    }
    if (w == "box") {
        glm::dvec3 a = parse_vector();
        accept_comma();
        glm::dvec3 b = parse_vector();
        // POV-Ray sorts the corners.
        Box box;
        box.corner1 = glm::min(a, b);
        box.corner2 = glm::max(a, b);
        return box;
    }
    if (w == "cylinder") {
        Cylinder c;
        Token at = peek(0);
        c.base = parse_vector();
        accept_comma();
        c.cap = parse_vector();
        accept_comma();
        c.radius = parse_float();
        if (glm::length(c.cap - c.base) < kEpsilon) {
            fail(at, "degenerate cylinder: the base and cap points are the same");
        }
        if (accept_word("open")) c.open = true;
        return c;
    }
    if (w == "disc") {
        Disc d;
        d.center = parse_vector();
        accept_comma();
        Token at = peek(0);
        glm::dvec3 n = parse_vector();
        if (glm::length(n) < kEpsilon) fail(at, "degenerate disc normal");
        d.normal = glm::normalize(n);
        accept_comma();
        d.radius = parse_float();
        accept_comma();
        if (starts_float(peek(0))) d.hole_radius = parse_float();
        return d;
    }
    if (w == "cone") {
        Cone c;
        Token at = peek(0);
        c.base = parse_vector();
        accept_comma();
        c.base_radius = parse_float();
        accept_comma();
        c.cap = parse_vector();
        accept_comma();
        c.cap_radius = parse_float();
        if (glm::length(c.cap - c.base) < kEpsilon) {
            fail(at, "degenerate cone: the base and cap points are the same");
        }
        if (accept_word("open")) c.open = true;
        return c;
    }
    if (w == "torus") {
        Torus t;
        t.major = parse_float();
        accept_comma();
        t.minor = parse_float();
        return t;
    }
    if (w == "quadric") {
        Quadric q;
        q.square = parse_vector();
        accept_comma();
        q.mixed = parse_vector();
        accept_comma();
        q.linear = parse_vector();
        accept_comma();
        q.constant = parse_float();
        return q;
    }
    if (w == "triangle" || w == "smooth_triangle") return parse_triangle(kw);
    if (w == "polygon") return parse_polygon(kw);
    if (w == "text") return parse_text(kw);
    if (w == "isosurface") return parse_isosurface(kw);
    if (w == "superellipsoid") {
        Superellipsoid s;
        Token at = peek(0);
        const glm::dvec3 v = parse_vector();
        s.e = v.x;
        s.n = v.y;
        if (!(s.e > 0.0 && s.n > 0.0)) fail(at, "superellipsoid exponents must be > 0");
        return s;
    }
    if (w == "height_field") return parse_height_field(kw);
    if (w == "blob") return parse_blob(kw);
    if (w == "lathe") return parse_lathe();
    if (w == "sor") return parse_sor();
    if (w == "prism") return parse_prism();
    if (w == "poly" || w == "cubic" || w == "quartic") return parse_poly(kw);
    fail(kw, "expected an object, got " + describe(kw));
}

Shape SceneParser::parse_triangle(const Token& kw) {
    const std::string& w = kw.text();
    // A single triangle keeps double precision (POV-Ray's Triangle object).
    const bool smooth = w == "smooth_triangle";
    auto data = std::make_shared<MeshData>();
    data->single_precision = false;
    MeshData::Face f;
    for (int i = 0; i < 3; ++i) {
        if (i) accept_comma();
        data->vertices.push_back(parse_vector());
        if (smooth) {
            accept_comma();
            glm::dvec3 n = parse_vector();
            if (std::abs(n.x) < kEpsilon && std::abs(n.y) < kEpsilon && std::abs(n.z) < kEpsilon) {
                n = glm::dvec3(1.0, 0.0, 0.0);  // as POV-Ray
            }
            data->normals.push_back(glm::normalize(n));
            f.n[i] = i;
        }
        f.v[i] = i;
    }
    data->faces.push_back(f);
    return Mesh{data};
}

Shape SceneParser::parse_lathe() {
    Lathe lathe;
    if (accept_word("linear_spline")) {
        lathe.spline = SplineKind::Linear;
    } else if (accept_word("quadratic_spline")) {
        lathe.spline = SplineKind::Quadratic;
    } else if (accept_word("cubic_spline")) {
        lathe.spline = SplineKind::Cubic;
    } else if (accept_word("bezier_spline")) {
        lathe.spline = SplineKind::Bezier;
    }
    Token at = peek(0);
    const double n = parse_float();
    const int minimum = lathe.spline == SplineKind::Linear      ? 2
                        : lathe.spline == SplineKind::Quadratic ? 3
                                                                : 4;
    if (n < minimum || n > 1e7 ||
        (lathe.spline == SplineKind::Bezier && (static_cast<int>(n) & 3) != 0)) {
        fail(at, "a lathe with these splines needs at least " + std::to_string(minimum) +
                     " points (four per Bezier segment)");
    }
    for (int i = 0; i < static_cast<int>(n); ++i) {
        accept_comma();
        Token pt = peek(0);
        const glm::dvec3 v = parse_vector();
        if (i > 0 && i < static_cast<int>(n) - 1 && v.x < 0.0) {
            fail(pt, "incorrect point in lathe: a negative radius");
        }
        lathe.points.emplace_back(v.x, v.y);
    }
    return lathe;
}

Shape SceneParser::parse_sor() {
    Sor sor;
    Token at = peek(0);
    const double n = parse_float();
    if (n < 4.0 || n > 1e7) fail(at, "a surface of revolution needs at least four points");
    for (int i = 0; i < static_cast<int>(n); ++i) {
        accept_comma();
        Token pt = peek(0);
        const glm::dvec3 v = parse_vector();
        if (v.x < 0.0 || (i > 1 && i < static_cast<int>(n) - 1 && v.y <= sor.points.back().y)) {
            fail(pt,
                 "incorrect point in surface of revolution (radii >= 0, heights "
                 "increasing)");
        }
        sor.points.emplace_back(v.x, v.y);
    }
    if (accept_word("open")) sor.open = true;
    return sor;
}

Shape SceneParser::parse_prism() {
    Prism prism;
    while (true) {
        if (accept_word("linear_spline")) {
            prism.spline = SplineKind::Linear;
        } else if (accept_word("quadratic_spline")) {
            prism.spline = SplineKind::Quadratic;
        } else if (accept_word("cubic_spline")) {
            prism.spline = SplineKind::Cubic;
        } else if (accept_word("bezier_spline")) {
            prism.spline = SplineKind::Bezier;
        } else if (accept_word("linear_sweep")) {
            prism.conic = false;
        } else if (accept_word("conic_sweep")) {
            prism.conic = true;
        } else {
            break;
        }
    }
    prism.height1 = parse_float();
    accept_comma();
    prism.height2 = parse_float();
    accept_comma();
    if (prism.height1 > prism.height2) std::swap(prism.height1, prism.height2);
    Token at = peek(0);
    const double n = parse_float();
    if (n < 3.0 || n > 1e7) fail(at, "a prism needs at least three points");
    for (int i = 0; i < static_cast<int>(n); ++i) {
        accept_comma();
        const glm::dvec3 v = parse_vector();
        prism.points.emplace_back(v.x, v.y);
    }
    if (accept_word("open")) prism.open = true;
    return prism;
}

Shape SceneParser::parse_poly(const Token& kw) {
    const std::string& w = kw.text();
    Polynomial poly;
    Token at = peek(0);
    if (w == "poly") {
        const double order = parse_float();
        if (order < 2.0 || order > 35.0 || std::floor(order) != order) {
            fail(at, "poly order " + format_str(order, 0, -1) + ": must be 2 to 35");
        }
        poly.order = static_cast<int>(order);
        accept_comma();
    } else {
        poly.order = w == "cubic" ? 3 : 4;
    }
    const int count = (poly.order + 1) * (poly.order + 2) * (poly.order + 3) / 6;
    Token open = expect_punct("<", "before the coefficients of '" + w + "'");
    while (!peek_punct(">")) {
        if (!poly.coefficients.empty()) accept_comma();
        if (peek_punct(">")) break;
        poly.coefficients.push_back(parse_float());
    }
    next();
    if (static_cast<int>(poly.coefficients.size()) != count) {
        fail(open, "'" + w + "' of order " + std::to_string(poly.order) + " needs " +
                       std::to_string(count) + " coefficients, got " +
                       std::to_string(poly.coefficients.size()));
    }
    return poly;
}

std::string SceneParser::find_scene_file(const std::string& name,
                                         const std::string& extension) const {
    namespace fs = std::filesystem;
    std::vector<std::string> dirs;
    if (!frames_.empty())
        dirs.push_back(fs::path(frames_.back().file->path).parent_path().string());
    for (const std::string& lib : options_.library_paths) dirs.push_back(lib);
    for (const std::string& candidate : {name, name + extension}) {
        std::error_code ec;
        if (fs::path(candidate).is_absolute()) {
            if (fs::is_regular_file(candidate, ec)) return candidate;
            continue;
        }
        for (const std::string& d : dirs) {
            const fs::path p = d.empty() ? fs::path(candidate) : fs::path(d) / candidate;
            if (fs::is_regular_file(p, ec)) return p.lexically_normal().string();
        }
    }
    return "";
}

Shape SceneParser::parse_text(const Token& kw) {
    // text { ttf "font" "string" thickness, offset }
    if (!peek_word("ttf")) {
        Token t = peek(0);
        if (t.is_word("internal")) {
            next();
            unsupported(t, "text with an internal font");
            parse_float();
            accept_comma();
            parse_string(false);
            accept_comma();
            parse_float();
            accept_comma();
            parse_vector();
            return Text{};
        }
        fail(t, "expected 'ttf' after 'text {', got " + describe(t));
    }
    next();
    Token at = peek(0);
    const std::string font_name = parse_string(true);
    accept_comma();
    const std::string string = parse_string(false);
    accept_comma();
    const double thickness = parse_float();
    accept_comma();
    const glm::dvec3 offset = parse_vector();
    const std::string path = find_scene_file(font_name, ".ttf");
    if (path.empty()) fail(at, "cannot find the font file '" + font_name + "'");
    auto& font = fonts_[path];
    if (!font) {
        auto loaded = load_truetype_font(path);
        if (!loaded) fail(at, loaded.message());
        font = *loaded;
        scene_.files.push_back(path);  // an input: no output may replace it
    }
    auto text = layout_text(*font, string, thickness, offset);
    if (!text) fail(at, text.message());
    (void)kw;
    return *text;
}

// POV-Ray's Parse_Isosurface (parse.cpp): the function first, then in any order its container,
// threshold, accuracy, max_gradient, max_trace, evaluate, open and all_intersections; values
// POV-Ray replaces with a warning are replaced the same way.  A function mirage cannot
// evaluate (a pattern's, or an internal one it does not know) leaves `function` null: the
// object is unsupported.
Shape SceneParser::parse_isosurface(const Token& kw) {
    Isosurface iso;
    const Token f = next();
    if (!f.is_word("function")) {
        fail(f, "expected 'function' to begin the isosurface, got " + describe(f));
    }
    iso.function = parse_function_block(f, {});
    if (iso.function) {
        std::string why;
        if (!function_evaluable(*iso.function, &why, true)) {
            unsupported(
                f, "isosurface function (it needs " + why + ", which mirage does not evaluate)");
            iso.function = nullptr;
        }
    }
    constexpr int kMaxTrace = 10;  // POV-Ray's ISOSURFACE_MAXTRACE
    while (true) {
        const Token t = peek(0);
        if (t.is_word("contained_by")) {
            next();
            expect_open_brace(t);
            const Token c = peek(0);
            if (c.is_word("box")) {
                next();
                expect_open_brace(c);
                const glm::dvec3 a = parse_vector();
                accept_comma();
                const glm::dvec3 b = parse_vector();
                expect_close_brace(c);
                iso.sphere_container = false;
                iso.corner1 = glm::min(a, b);
                iso.corner2 = glm::max(a, b);
            } else if (c.is_word("sphere")) {
                next();
                expect_open_brace(c);
                iso.centre = parse_vector();
                accept_comma();
                iso.radius = parse_float();
                expect_close_brace(c);
                iso.sphere_container = true;
            }
            expect_close_brace(t);
        } else if (t.is_word("threshold")) {
            next();
            iso.threshold = parse_float();
        } else if (t.is_word("accuracy")) {
            next();
            iso.accuracy = parse_float();
        } else if (t.is_word("max_gradient")) {
            next();
            iso.max_gradient = parse_float();
        } else if (t.is_word("max_trace")) {
            next();
            // POV-Ray keeps it in a short.
            iso.max_trace = static_cast<short>(static_cast<int>(parse_float()));
        } else if (t.is_word("evaluate")) {
            next();
            iso.evaluate = true;
            iso.eval_params.x = parse_float();
            accept_comma();
            iso.eval_params.y = parse_float();
            accept_comma();
            iso.eval_params.z = parse_float();
        } else if (t.is_word("open")) {
            next();
            iso.open = true;
        } else if (t.is_word("all_intersections")) {
            next();
            iso.all_intersections = true;
            iso.max_trace = kMaxTrace;
        } else {
            break;
        }
    }
    if (iso.accuracy <= 0.0) {
        add_message(kw, "warning", "isosurface 'accuracy' is not positive, using 0.001");
        iso.accuracy = 0.001;
    }
    if (iso.max_gradient <= 0.0) {
        add_message(kw, "warning", "isosurface 'max_gradient' is not positive, using 1.1");
        iso.max_gradient = 1.1;
    }
    if (iso.max_trace > kMaxTrace) {
        add_message(kw, "warning", "isosurface 'max_trace' exceeds 10, using 10");
        iso.max_trace = kMaxTrace;
    }
    if (iso.max_trace < 1) {
        add_message(kw, "warning", "isosurface 'max_trace' is not positive, using 1");
        iso.max_trace = 1;
    }
    return iso;
}

Shape SceneParser::parse_polygon(const Token& kw) {
    Token at = peek(0);
    const int number = static_cast<int>(parse_float());
    if (number < 3) fail(at, "a polygon needs at least three points");
    std::vector<glm::dvec3> points;
    for (int i = 0; i < number; ++i) {
        accept_comma();
        points.push_back(parse_vector());
    }
    // POV-Ray's Parse_Polygon: a point repeating the current sub-polygon's first closes it;
    // an open polygon is closed.
    bool closed = false;
    glm::dvec3 first = points[0];
    for (int i = 1; i < number; ++i) {
        closed = false;
        if (std::abs(first.x - points[i].x) < kEpsilon &&
            std::abs(first.y - points[i].y) < kEpsilon &&
            std::abs(first.z - points[i].z) < kEpsilon) {
            points[i] = first;
            ++i;
            if (i < number) first = points[i];
            closed = true;
        }
    }
    if (!closed) {
        add_message(kw, "warning", "polygon not closed: closing it");
        points.push_back(first);
    }
    // POV-Ray's Compute_Polygon: a frame u, v, w with w normal to the plane.
    Polygon poly;
    const int n = static_cast<int>(points.size());
    const glm::dvec3 o = points[0];
    glm::dvec3 u(0.0), v(0.0), wv(0.0);
    int i = 1;
    for (; i < n; ++i) {
        u = points[i] - o;
        if (glm::dot(u, u) > kEpsilon) break;
    }
    if (i == n) poly.degenerate = true;
    for (++i; i < n; ++i) {
        v = points[i] - o;
        wv = glm::cross(u, v);
        if (glm::dot(v, v) > kEpsilon && glm::dot(wv, wv) > kEpsilon) break;
    }
    if (i >= n) poly.degenerate = true;
    if (!poly.degenerate) {
        u = glm::normalize(glm::cross(v, wv));
        v = glm::normalize(glm::cross(wv, u));
        wv = glm::normalize(wv);
        glm::dmat4 to_shape(1.0);
        to_shape[0] = glm::dvec4(u, 0.0);
        to_shape[1] = glm::dvec4(v, 0.0);
        to_shape[2] = glm::dvec4(wv, 0.0);
        to_shape[3] = glm::dvec4(o, 1.0);
        poly.plane_to_shape = to_shape;
        for (const glm::dvec3& p : points) {
            const glm::dvec3 q = p - o;
            if (std::abs(glm::dot(q, wv)) > 1e-10) poly.degenerate = true;  // not coplanar
            poly.points.emplace_back(glm::dot(q, u), glm::dot(q, v));
        }
    }
    if (poly.degenerate) add_message(kw, "warning", "degenerate polygon: ignored, as POV-Ray does");
    return poly;
}

// A texture of a mesh's triangle: texture { ... } or texture_list { T1 T2 T3 } (POV-Ray
// interpolates the three; mirage takes the first).
std::optional<Texture> SceneParser::parse_mesh_triangle_texture() {
    if (peek_word("texture")) {
        Token item = next();
        expect_open_brace(item);
        Texture t = parse_texture_body(item);
        expect_close_brace(item);
        return t;
    }
    if (peek_word("texture_list")) {
        Token item = next();
        unsupported(item, "texture_list on a mesh triangle (three interpolated textures)");
        expect_open_brace(item);
        std::optional<Texture> first;
        while (peek_word("texture")) {
            Token t = next();
            expect_open_brace(t);
            Texture tex = parse_texture_body(t);
            expect_close_brace(t);
            if (!first) first = tex;
        }
        expect_close_brace(item);
        return first;
    }
    return std::nullopt;
}

namespace {

bool degenerate_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return glm::length(glm::cross(b - a, c - a)) == 0.0;
}

glm::dvec3 as_float(const glm::dvec3& v) {
    return glm::dvec3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

glm::dvec3 nonzero_normal(glm::dvec3 n) {
    if (std::abs(n.x) < kEpsilon && std::abs(n.y) < kEpsilon && std::abs(n.z) < kEpsilon) {
        n = glm::dvec3(1.0, 0.0, 0.0);  // POV-Ray: "Normal vector in mesh cannot be zero"
    }
    return glm::normalize(n);
}

}  // namespace

/// A mesh's faces as parsed, with the texture each one names (an index into `textures`, -1:
/// none).
struct SceneParser::MeshParts {
    std::shared_ptr<MeshData> data = std::make_shared<MeshData>();
    std::vector<Texture> textures;
    std::vector<int> face_texture;
};

ObjectNode SceneParser::parse_mesh(const Token& kw) {
    MeshParts parts;
    if (kw.is_word("mesh")) {
        parse_mesh_items(parts);
    } else {
        parse_mesh2_items(kw, parts);
    }
    if (parts.data->faces.empty()) fail(kw, "no triangles in the " + kw.text());
    return mesh_object(kw, parts);
}

/// mesh: triangles and smooth triangles (each with its texture, if any), inside_vector.
void SceneParser::parse_mesh_items(MeshParts& parts) {
    MeshData* data = parts.data.get();
    while (true) {
        const Token t = peek(0);
        if (t.is_word("triangle") || t.is_word("smooth_triangle")) {
            Token item = next();
            const bool smooth = item.is_word("smooth_triangle");
            expect_open_brace(item);
            glm::dvec3 p[3], n[3];
            for (int i = 0; i < 3; ++i) {
                if (i) accept_comma();
                p[i] = parse_vector();
                if (smooth) {
                    accept_comma();
                    n[i] = nonzero_normal(parse_vector());
                }
            }
            if (peek_word("uv_vectors")) {
                next();
                for (int i = 0; i < 3; ++i) {
                    if (i) accept_comma();
                    parse_vector();  // uv coordinates: only uv_mapping uses them
                }
            }
            const std::optional<Texture> tex = parse_mesh_triangle_texture();
            expect_close_brace(item);
            if (degenerate_triangle(p[0], p[1], p[2])) continue;
            MeshData::Face f;
            for (int i = 0; i < 3; ++i) {
                f.v[i] = static_cast<int>(data->vertices.size());
                data->vertices.push_back(as_float(p[i]));
                if (smooth) {
                    f.n[i] = static_cast<int>(data->normals.size());
                    data->normals.push_back(as_float(n[i]));
                }
            }
            data->faces.push_back(f);
            if (tex) {
                parts.textures.push_back(*tex);
                parts.face_texture.push_back(static_cast<int>(parts.textures.size()) - 1);
            } else {
                parts.face_texture.push_back(-1);
            }
            continue;
        }
        if (t.is_word("inside_vector")) {
            next();
            data->inside_vector = parse_vector();
            continue;
        }
        break;
    }
}

/// mesh2: vertex_vectors, normal_vectors, uv_vectors, texture_list, face_indices, uv_indices,
/// normal_indices, inside_vector.
void SceneParser::parse_mesh2_items(const Token& kw, MeshParts& parts) {
    MeshData* data = parts.data.get();
    std::vector<glm::dvec3> normals;
    std::vector<glm::ivec3> normal_indices;
    bool have_normal_indices = false;
    const auto count_of = [&](const Token& item) {
        Token at = peek(0);
        const double n = parse_float();
        if (n < 0.0 || n > 1e8) {
            fail(at, "'" + item.text() + "': bad count " + format_str(n, 0, -1));
        }
        accept_comma();
        return static_cast<int>(n);
    };
    while (true) {
        const Token t = peek(0);
        if (t.is_word("vertex_vectors") || t.is_word("normal_vectors") || t.is_word("uv_vectors")) {
            Token item = next();
            expect_open_brace(item);
            const int n = count_of(item);
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 v = parse_vector();
                accept_comma();
                if (item.is_word("vertex_vectors")) data->vertices.push_back(as_float(v));
                if (item.is_word("normal_vectors")) normals.push_back(as_float(nonzero_normal(v)));
            }
            expect_close_brace(item);
            continue;
        }
        if (t.is_word("texture_list")) {
            Token item = next();
            expect_open_brace(item);
            const int n = count_of(item);
            for (int i = 0; i < n; ++i) {
                Token tk = peek(0);
                if (!tk.is_word("texture")) {
                    fail(tk, "expected 'texture' in texture_list, got " + describe(tk));
                }
                next();
                expect_open_brace(tk);
                parts.textures.push_back(parse_texture_body(tk));
                expect_close_brace(tk);
                accept_comma();
            }
            expect_close_brace(item);
            continue;
        }
        if (t.is_word("face_indices")) {
            Token item = next();
            expect_open_brace(item);
            const int n = count_of(item);
            for (int i = 0; i < n; ++i) {
                Token at = peek(0);
                const glm::dvec3 v = parse_vector();
                accept_comma();
                MeshData::Face f;
                const int nv = static_cast<int>(data->vertices.size());
                for (int k = 0; k < 3; ++k) {
                    f.v[k] = static_cast<int>(v[k]);
                    if (f.v[k] < 0 || f.v[k] >= nv) {
                        fail(at, "face index " + std::to_string(f.v[k]) + " out of range 0 to " +
                                     std::to_string(nv - 1));
                    }
                }
                int tex = -1;
                for (int k = 0; k < 3 && starts_float(peek(0)); ++k) {
                    Token tat = peek(0);
                    const int ti = static_cast<int>(parse_float());
                    accept_comma();
                    if (ti < 0 || ti >= static_cast<int>(parts.textures.size())) {
                        fail(tat, "texture index " + std::to_string(ti) + " out of range");
                    }
                    if (k == 0) tex = ti;
                    if (k == 1) unsupported(tat, "three interpolated textures on a mesh2 face");
                }
                data->faces.push_back(f);
                parts.face_texture.push_back(tex);
            }
            expect_close_brace(item);
            continue;
        }
        if (t.is_word("normal_indices") || t.is_word("uv_indices")) {
            Token item = next();
            expect_open_brace(item);
            const int n = count_of(item);
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 v = parse_vector();
                accept_comma();
                if (item.is_word("normal_indices")) normal_indices.emplace_back(v);
            }
            if (item.is_word("normal_indices")) have_normal_indices = true;
            expect_close_brace(item);
            continue;
        }
        if (t.is_word("inside_vector")) {
            next();
            data->inside_vector = parse_vector();
            continue;
        }
        break;
    }
    // Normals without normal_indices pair with the vertices (POV-Ray's shortcut).
    if (!have_normal_indices && !normals.empty() && normals.size() == data->vertices.size()) {
        for (const auto& f : data->faces) normal_indices.emplace_back(f.v[0], f.v[1], f.v[2]);
    }
    data->normals = normals;
    for (std::size_t i = 0; i < data->faces.size() && i < normal_indices.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const int ni = normal_indices[i][k];
            if (ni < 0 || ni >= static_cast<int>(normals.size())) {
                fail(kw, "mesh2: normal index " + std::to_string(ni) + " out of range");
            }
            data->faces[i].n[k] = ni;
        }
    }
    // Degenerate faces are left out.
    std::vector<MeshData::Face> kept;
    std::vector<int> kept_texture;
    for (std::size_t i = 0; i < data->faces.size(); ++i) {
        const auto& f = data->faces[i];
        if (degenerate_triangle(data->vertices[f.v[0]], data->vertices[f.v[1]],
                                data->vertices[f.v[2]])) {
            continue;
        }
        kept.push_back(f);
        kept_texture.push_back(parts.face_texture[i]);
    }
    data->faces = std::move(kept);
    parts.face_texture = std::move(kept_texture);
}

/// The parsed mesh as an object: one mesh, or, when its triangles name textures, one mesh per
/// texture in a union.
ObjectNode SceneParser::mesh_object(const Token& kw, const MeshParts& parts) {
    const std::shared_ptr<MeshData>& data = parts.data;
    ObjectNode node;
    node.kind = ObjectNode::Kind::Shape;
    node.loc = kw.loc();
    bool textured = false;
    for (int t : parts.face_texture) textured |= t >= 0;
    if (!textured) {
        node.shape = Mesh{data};
        return node;
    }
    // One mesh per texture, in a union (the untextured triangles take the mesh's texture).
    node.kind = ObjectNode::Kind::Union;
    std::map<int, std::shared_ptr<MeshData>> groups;
    for (std::size_t i = 0; i < data->faces.size(); ++i) {
        auto& g = groups[parts.face_texture[i]];
        if (!g) {
            g = std::make_shared<MeshData>();
            g->vertices = data->vertices;
            g->normals = data->normals;
            g->inside_vector = data->inside_vector;
        }
        g->faces.push_back(data->faces[i]);
    }
    for (auto& [t, g] : groups) {
        ObjectNode part;
        part.kind = ObjectNode::Kind::Shape;
        part.loc = kw.loc();
        part.shape = Mesh{g};
        if (t >= 0) part.texture = parts.textures[static_cast<std::size_t>(t)];
        node.children.push_back(std::move(part));
    }
    return node;
}

// POV-Ray's Parse_HField: the image (Parse_Image with HF_FILE: a file, or function W, H
// { ... } evaluated as Make_Pattern_Image does), then water_level and smooth in any order.
HeightField SceneParser::parse_height_field(const Token& kw) {
    static const char* const kTypes[] = {"gif", "tga",  "iff",  "ppm", "pgm", "png",
                                         "pot", "jpeg", "tiff", "exr", "hdr", "sys"};
    Token type_token = peek(0);
    std::string type;
    for (const char* t : kTypes) {
        if (type_token.is_word(t)) {
            type = next().text();
            break;
        }
    }
    // The heights are POV-Ray's HF_VAL / 65536 (exact in a float).
    auto data = std::make_shared<HeightFieldData>();
    if (type.empty() && peek_word("function")) {
        Token f = next();
        Token at = peek(0);
        const double w = std::floor(parse_float() + 0.5);
        accept_comma();
        const double h = std::floor(parse_float() + 0.5);
        if (!(w >= 2.0 && h >= 2.0 && w * h <= 1e8)) {
            fail(at, "a height_field function needs at least 2 x 2 points");
        }
        data->width = static_cast<int>(w);
        data->depth = static_cast<int>(h);
        data->heights.assign(static_cast<std::size_t>(w * h), 65535.0f / 65536.0f);
        std::shared_ptr<const FunctionCode> code = parse_function_block(f, {"x", "y", "z"});
        std::string why;
        if (code && !function_evaluable(*code, &why)) {
            unsupported(f, "height_field function: it calls " + why);
            code = nullptr;
        }
        if (code) {
            // Make_Pattern_Image: the value at x = column / (W - 1), y = row / (H - 1) in a
            // 16-bit grey image, row 0 on top; image_height_at scales it back.
            for (int row = 0; row < data->depth; ++row) {
                for (int col = 0; col < data->width; ++col) {
                    const double args[3] = {col / (w - 1.0), row / (h - 1.0), 0.0};
                    double v = evaluate_function(*code, args, 3);
                    v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
                    const float grey = static_cast<float>(std::lround(v * 65535.0)) / 65535.0f;
                    data->heights[static_cast<std::size_t>(data->depth - 1 - row) * data->width +
                                  col] =
                        static_cast<float>(static_cast<std::uint16_t>(grey * 65535.0f)) / 65536.0f;
                }
            }
        }
        // Unevaluated (reported above): the heights are taken at their highest, which
        // keeps the extent (the unit box) for the compiler.
    } else {
        Token name_at = peek(0);
        if (!starts_string(name_at)) {
            fail(name_at, "expected the height field's image file name, got " + describe(name_at));
        }
        const std::string name = parse_string(true);
        if (type.empty()) {
            // The type from the extension (POV-Ray's InferFileTypeFromExt), else the
            // platform's default, PNG.
            const std::string ext = lower_extension(name);
            static const char* const kExtensions[] = {".tga",  ".png", ".pgm",  ".ppm", ".jpg",
                                                      ".jpeg", ".tif", ".tiff", ".exr", ".hdr",
                                                      ".gif",  ".iff", ".bmp",  ".pot", ""};
            bool known = false;
            for (const char* e : kExtensions) known = known || ext == e;
            if (!known) {
                fail(name_at, "could not determine a valid image file type from the extension '" +
                                  ext + "'");
            }
            type = ext == ".gif" ? "gif" : ext == ".pot" ? "pot" : ext == ".iff" ? "iff" : "png";
        }
        if (type == "gif" || type == "pot" || type == "iff") {
            // POV-Ray reads these as palette images (pot: two halves of one 16-bit map);
            // the image library here expands palettes to colour.
            fail(type_token, "unsupported height_field image type '" + type + "'");
        }
        const std::string found = find_scene_file(name);
        if (found.empty()) fail(name_at, "cannot find height field image file '" + name + "'");
        auto image = read_height_image(found);
        if (!image) fail(name_at, image.message());
        if (image->width < 2 || image->height < 2) {
            fail(name_at, found + ": a height field needs an image of at least 2 x 2 pixels");
        }
        // An input: no output may replace it.
        if (std::find(scene_.files.begin(), scene_.files.end(), found) == scene_.files.end()) {
            scene_.files.push_back(found);
        }
        data->width = image->width;
        data->depth = image->height;
        data->heights.resize(image->heights.size());
        for (int z = 0; z < data->depth; ++z) {  // Compute_HField: image row max_z - z - 1
            for (int x = 0; x < data->width; ++x) {
                data->heights[static_cast<std::size_t>(z) * data->width + x] =
                    image
                        ->heights[static_cast<std::size_t>(data->depth - 1 - z) * data->width + x] /
                    65536.0f;
            }
        }
    }
    while (true) {
        if (accept_word("water_level")) {
            data->water_level = parse_float();
        } else if (accept_word("smooth")) {
            data->smooth = true;
        } else {
            break;
        }
    }
    HeightField hf;
    hf.data = std::move(data);
    return hf;
}

// POV-Ray's Parse_Blob: the threshold (1 unless given) and the components, the old
// `component strength, radius, <centre>` or `sphere { <centre>, radius, [strength] s mods }`
// and `cylinder { <a>, <b>, radius, [strength] s mods }`, until the first object modifier.
// A component's radius is squared at once, so a negative radius acts as its magnitude and a
// radius of 0 gives a component without effect (POV-Ray's "degenerate blob element").
Shape SceneParser::parse_blob(const Token& kw) {
    Blob blob;
    while (true) {
        const Token t = peek(0);
        if (accept_word("threshold")) {
            blob.threshold = parse_float();
            continue;
        }
        if (accept_word("component")) {
            BlobComponent c;
            c.strength = parse_float();
            accept_comma();
            c.radius = parse_float();
            accept_comma();
            c.centre = parse_vector();
            blob.components.push_back(c);
            continue;
        }
        if (t.is_word("sphere") || t.is_word("cylinder")) {
            const Token item = next();
            expect_open_brace(item);
            BlobComponent c;
            c.cylinder = t.is_word("cylinder");
            Token at = peek(0);
            c.centre = parse_vector();
            accept_comma();
            if (c.cylinder) {
                c.end = parse_vector();
                accept_comma();
            }
            c.radius = parse_float();
            accept_comma();
            accept_word("strength");
            c.strength = parse_float();
            if (c.cylinder && glm::length(c.end - c.centre) < kEpsilon) {
                fail(at, "degenerate cylindrical component in blob: its ends are the same point");
            }
            Transform mods;
            while (true) {
                const Token m = peek(0);
                Transform tr;
                if (parse_transform_item(tr)) {
                    mods = compose_transforms(mods, tr);
                    continue;
                }
                if (m.is_word("texture") || m.is_word("pigment") || m.is_word("normal") ||
                    m.is_word("finish")) {
                    fail(m, "a blob component's own " + m.text() +
                                " is not supported yet (give the blob one texture)");
                }
                break;
            }
            expect_close_brace(item);
            c.to_world = mods.matrix;
            c.from_world = mods.inverse;
            blob.components.push_back(c);
            continue;
        }
        break;
    }
    if (blob.components.empty()) fail(kw, "a blob needs at least one component");
    return blob;
}

}  // namespace mirage::scene_detail

namespace mirage {

const char* shape_keyword(const Shape& shape) {
    static const char* const names[] = {
        "sphere",       "plane",          "box",  "cylinder", "disc",  "cone",  "torus", "quadric",
        "poly",         "superellipsoid", "mesh", "polygon",  "prism", "lathe", "sor",   "blob",
        "height_field", "isosurface",     "text"};
    static_assert(sizeof(names) / sizeof(names[0]) == std::variant_size_v<Shape>);
    return names[shape.index()];
}

}  // namespace mirage
