// The arguments of each shape, after POV-Ray 3.7's parse.cpp (Parse_Sphere, Parse_Cone...):
// what comes between a shape's '{' and its object modifiers.
#include <cmath>

#include "scene/scene_parser.h"
#include "scene/transform.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

}  // namespace

const char* const kShapeKeywords[] = {"sphere", "plane", "box",   "cylinder",
                                      "disc",   "cone",  "torus", "quadric"};

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
    fail(kw, "expected an object, got " + describe(kw));
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
