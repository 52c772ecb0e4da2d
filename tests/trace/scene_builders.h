// Test helpers: scenes of the supported subset built in C++, as the parser would build them.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>

#include "scene/scene.h"

namespace mirage::testing {

inline Transform make_transform(const glm::dmat4& m) { return Transform{m, glm::inverse(m)}; }
inline Transform translate(const glm::dvec3& v) {
    return make_transform(glm::translate(glm::dmat4(1.0), v));
}
inline Transform scale(const glm::dvec3& v) {
    return make_transform(glm::scale(glm::dmat4(1.0), v));
}
/// POV-Ray's `rotate <x, y, z>` in degrees: about x, then y, then z.
inline Transform rotate(const glm::dvec3& deg) {
    glm::dmat4 m(1.0);
    m = glm::rotate(glm::dmat4(1.0), glm::radians(deg.x), glm::dvec3(1, 0, 0)) * m;
    m = glm::rotate(glm::dmat4(1.0), glm::radians(deg.y), glm::dvec3(0, 1, 0)) * m;
    m = glm::rotate(glm::dmat4(1.0), glm::radians(deg.z), glm::dvec3(0, 0, 1)) * m;
    return make_transform(m);
}
/// `a` then `b` (POV-Ray applies transforms in the order written).
inline Transform then(const Transform& a, const Transform& b) {
    return Transform{b.matrix * a.matrix, a.inverse * b.inverse};
}

inline Colour rgb(double r, double g, double b) { return Colour{glm::dvec3(r, g, b), 0.0, 0.0}; }

inline Pigment solid(const Colour& c) {
    Pigment p;
    p.kind = PigmentKind::Solid;
    p.colour = c;
    return p;
}
inline Pigment checker(const Colour& a, const Colour& b, const Transform& t = {}) {
    Pigment p;
    p.kind = PigmentKind::Checker;
    p.checker[0] = a;
    p.checker[1] = b;
    p.transform = t;
    return p;
}
inline Pigment gradient(const glm::dvec3& axis, std::vector<ColourMapEntry> map,
                        const Transform& t = {}) {
    Pigment p;
    p.kind = PigmentKind::Gradient;
    p.gradient_axis = axis;
    p.colour_map = std::move(map);
    p.transform = t;
    return p;
}

inline Texture texture(const Pigment& pigment, const Finish& finish = {}) {
    Texture t;
    t.pigment = pigment;
    t.finish = finish;
    return t;
}

inline Primitive primitive(Shape shape, const Texture& tex, const Transform& t = {}) {
    Primitive p;
    p.shape = std::move(shape);
    p.texture = tex;
    p.transform = t;
    return p;
}

inline PointLight light(const glm::dvec3& at, const glm::dvec3& colour = glm::dvec3(1.0),
                        bool shadowless = false) {
    PointLight l;
    l.location = at;
    l.colour = colour;
    l.shadowless = shadowless;
    return l;
}

/// POV-Ray's camera with look_at: direction of length `direction_length` toward the
/// target, right of length `right_length` (the aspect ratio), up of length 1.
inline Camera look_at_camera(const glm::dvec3& location, const glm::dvec3& target,
                             double right_length = 4.0 / 3.0, double direction_length = 1.0) {
    Camera c;
    c.location = location;
    const glm::dvec3 d = glm::normalize(target - location);
    c.direction = d * direction_length;
    c.right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), d)) * right_length;
    c.up = glm::normalize(glm::cross(d, c.right));
    return c;
}

}  // namespace mirage::testing
