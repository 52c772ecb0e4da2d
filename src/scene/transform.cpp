// Transform construction and application, after POV-Ray's math/matrices.cpp.
#include "scene/transform.h"

#include <cmath>

namespace mirage {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

// Rotation about one axis by the usual (right-hand-rule) formula, as a column-vector matrix.
glm::dmat4 axis_matrix(int axis, double radians) {
    double c = std::cos(radians), s = std::sin(radians);
    glm::dmat4 m(1.0);
    int a = (axis + 1) % 3, b = (axis + 2) % 3;  // the plane turned: (y,z), (z,x), (x,y)
    // glm is column-major: m[col][row].
    m[a][a] = c;
    m[b][b] = c;
    m[a][b] = s;  // a goes toward b
    m[b][a] = -s;
    return m;
}

}  // namespace

Transform identity_transform() { return Transform{}; }

Transform make_translation(const glm::dvec3& v) {
    Transform t;
    t.matrix[3] = glm::dvec4(v, 1.0);
    t.inverse[3] = glm::dvec4(-v, 1.0);
    return t;
}

Transform make_rotation(const glm::dvec3& degrees) {
    glm::dmat4 rx = axis_matrix(0, degrees.x * kDegToRad);
    glm::dmat4 ry = axis_matrix(1, degrees.y * kDegToRad);
    glm::dmat4 rz = axis_matrix(2, degrees.z * kDegToRad);
    Transform t;
    t.matrix = rz * ry * rx;
    // A rotation's inverse is its transpose, exactly.
    t.inverse = glm::transpose(t.matrix);
    return t;
}

Transform make_scaling(const glm::dvec3& s) {
    Transform t;
    t.matrix[0][0] = s.x;
    t.matrix[1][1] = s.y;
    t.matrix[2][2] = s.z;
    t.inverse[0][0] = 1.0 / s.x;
    t.inverse[1][1] = 1.0 / s.y;
    t.inverse[2][2] = 1.0 / s.z;
    return t;
}

Transform make_axis_rotation(const glm::dvec3& axis, double degrees) {
    glm::dvec3 u = glm::normalize(axis);
    double c = std::cos(degrees * kDegToRad), s = std::sin(degrees * kDegToRad);
    double k = 1.0 - c;
    // Rodrigues' formula; column j is the image of basis vector j.
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(u.x * u.x * k + c, u.x * u.y * k + u.z * s, u.x * u.z * k - u.y * s, 0.0);
    m[1] = glm::dvec4(u.x * u.y * k - u.z * s, u.y * u.y * k + c, u.y * u.z * k + u.x * s, 0.0);
    m[2] = glm::dvec4(u.x * u.z * k + u.y * s, u.y * u.z * k - u.x * s, u.z * u.z * k + c, 0.0);
    Transform t;
    t.matrix = m;
    t.inverse = glm::transpose(m);
    return t;
}

Transform make_matrix_transform(const std::array<double, 12>& m) {
    Transform t;
    // POV-Ray's row i is our column i.
    for (std::size_t i = 0; i < 4; ++i) {
        t.matrix[static_cast<int>(i)] =
            glm::dvec4(m[3 * i], m[3 * i + 1], m[3 * i + 2], i == 3 ? 1.0 : 0.0);
    }
    t.inverse = glm::inverse(t.matrix);
    return t;
}

Transform compose_transforms(const Transform& first, const Transform& second) {
    Transform t;
    t.matrix = second.matrix * first.matrix;
    t.inverse = first.inverse * second.inverse;
    return t;
}

Transform invert_transform(const Transform& t) { return Transform{t.inverse, t.matrix}; }

glm::dvec3 transform_point(const Transform& t, const glm::dvec3& p) {
    return glm::dvec3(t.matrix * glm::dvec4(p, 1.0));
}

glm::dvec3 transform_direction(const Transform& t, const glm::dvec3& d) {
    return glm::dvec3(t.matrix * glm::dvec4(d, 0.0));
}

glm::dvec3 transform_normal(const Transform& t, const glm::dvec3& n) {
    return glm::dvec3(glm::transpose(t.inverse) * glm::dvec4(n, 0.0));
}

glm::dvec3 inverse_transform_point(const Transform& t, const glm::dvec3& p) {
    return glm::dvec3(t.inverse * glm::dvec4(p, 1.0));
}

glm::dvec3 inverse_transform_direction(const Transform& t, const glm::dvec3& d) {
    return glm::dvec3(t.inverse * glm::dvec4(d, 0.0));
}

}  // namespace mirage
