#include "shapes/shape_intersect.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>

#include "shapes/complex_shapes.h"
#include "shapes/polysolve.h"

namespace mirage {

namespace {

// Box sides, numbered as POV-Ray numbers them (boxes.cpp): 2 * axis + 1 for the low side,
// 2 * axis + 2 for the high side; 0 = none.
constexpr int side_low(int axis) { return 2 * axis + 1; }
constexpr int side_high(int axis) { return 2 * axis + 2; }
constexpr int side_axis(int side) { return (side - 1) / 2; }

// Cylinder parts, as POV-Ray's cones.cpp.
constexpr int kBaseHit = 1;
constexpr int kCapHit = 2;
constexpr int kSideHit = 3;

// POV-Ray's CLOSE_TOLERANCE (boxes.cpp): box sides hit within it of each other are
// disambiguated by the direction.
constexpr double kBoxCloseTolerance = 1.0e-6;

std::string where(const Primitive& p) { return place_prefix(p.loc); }

std::string shape_name(const Shape& shape) { return shape_keyword(shape); }

bool all_finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

bool linear_is_identity(const glm::dmat4& m) {
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            if (m[c][r] != (c == r ? 1.0 : 0.0)) return false;
        }
    }
    return true;
}

bool linear_is_diagonal(const glm::dmat4& m) {
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            if (c != r && m[c][r] != 0.0) return false;
        }
    }
    return true;
}

/// The scale s when the linear part is s times a rotation (or reflection), else 0.
double similarity_scale(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    const glm::dmat3 g = glm::transpose(l) * l;
    const double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
    if (!(s2 > 0.0)) return 0.0;
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            const double expected = c == r ? s2 : 0.0;
            if (std::abs(g[c][r] - expected) > 1e-12 * s2) return 0.0;
        }
    }
    return std::sqrt(s2);
}

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

/// Two unit vectors completing `n` (unit) to an orthonormal basis (Duff et al. 2017).
void orthonormal_basis(const glm::dvec3& n, glm::dvec3& u, glm::dvec3& v) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    u = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    v = glm::dvec3(b, sign + n.y * n.y * a, -n.y);
}

/// The affine map taking world points to the frame with origin `o` and axes u, v, w scaled
/// by su, sv, sw (local = ((p - o).u / su, (p - o).v / sv, (p - o).w / sw)).
glm::dmat4 frame_from_world(const glm::dvec3& o, const glm::dvec3& u, const glm::dvec3& v,
                            const glm::dvec3& w, double su, double sv, double sw) {
    glm::dmat4 m(1.0);
    const glm::dvec3 rows[3] = {u / su, v / sv, w / sw};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[c][r] = rows[r][c];
        m[3][r] = -glm::dot(rows[r], o);
    }
    return m;
}

glm::dmat4 frame_to_world(const glm::dvec3& o, const glm::dvec3& u, const glm::dvec3& v,
                          const glm::dvec3& w, double su, double sv, double sw) {
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(u * su, 0.0);
    m[1] = glm::dvec4(v * sv, 0.0);
    m[2] = glm::dvec4(w * sw, 0.0);
    m[3] = glm::dvec4(o, 1.0);
    return m;
}

void set_local_frame(PreparedShape& s, const Transform& t, const glm::dmat4& canonical_to_shape,
                     const glm::dmat4& shape_to_canonical) {
    s.world_to_local = shape_to_canonical * t.inverse;
    s.local_to_world = t.matrix * canonical_to_shape;
    s.normal_to_world = glm::transpose(glm::dmat3(s.world_to_local));
}

}  // namespace

bool sphere_roots(const glm::dvec3& centre, double radius_sq, const glm::dvec3& origin,
                  const glm::dvec3& direction, bool allow_behind, double& t1, double& t2) {
    const glm::dvec3 oc = centre - origin;
    const double oc_sq = glm::dot(oc, oc);
    const double t_closest = glm::dot(oc, direction);
    // Outside and moving away: both roots behind the origin.
    if (!allow_behind && oc_sq >= radius_sq && t_closest < kPovEpsilon) return false;
    const double half_chord_sq = radius_sq - oc_sq + t_closest * t_closest;
    if (!(half_chord_sq > kPovEpsilon)) return false;
    const double half_chord = std::sqrt(half_chord_sq);
    t1 = t_closest - half_chord;
    t2 = t_closest + half_chord;
    return true;
}

bool box_roots(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& p, const glm::dvec3& d,
               double t_start, double& t_near, int& s_near, double& t_far, int& s_far) {
    double tmin = t_start;
    double tmax = kPovBoundHuge;
    int smin = 0;
    int smax = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double da = d[axis];
        // The first axis takes its planes as they come; the others break near-ties between
        // sides by which axis the ray runs more along (POV-Ray's [DB 9/94] fix).
        const double close = axis == 0 ? 0.0 : kBoxCloseTolerance;
        const bool ties = axis != 0;
        if (da < -kPovEpsilon || da > kPovEpsilon) {
            const bool negative = da < 0.0;
            const double far_plane = negative ? lo[axis] : hi[axis];
            const double near_plane = negative ? hi[axis] : lo[axis];
            const int far_side = negative ? side_low(axis) : side_high(axis);
            const int near_side = negative ? side_high(axis) : side_low(axis);
            const double ad = std::abs(da);

            double t = (far_plane - p[axis]) / da;
            if (t < tmin) return false;
            if (t <= tmax - close) {
                smax = far_side;
                tmax = t;
            } else if (ties && t <= tmax + close && smax != 0 &&
                       ad > std::abs(d[side_axis(smax)])) {
                smax = far_side;
            }
            t = (near_plane - p[axis]) / da;
            if (t >= tmin + close) {
                if (t > tmax) return false;
                smin = near_side;
                tmin = t;
            } else if (ties && t >= tmin - close && smin != 0 &&
                       ad > std::abs(d[side_axis(smin)])) {
                smin = near_side;
            }
        } else if (p[axis] < lo[axis] || p[axis] > hi[axis]) {
            return false;
        }
    }
    t_near = tmin;
    s_near = smin;
    t_far = tmax;
    s_far = smax;
    return true;
}

namespace {

/// The primitive's transform: finite, invertible, and its inverse the one carried.
Status check_transform(const Primitive& primitive) {
    const Transform& t = primitive.transform;
    const std::string name = shape_name(primitive.shape);
    if (!all_finite(t.matrix) || !all_finite(t.inverse)) {
        return make_error(where(primitive) + name + ": transform is not finite");
    }
    const double det = glm::determinant(glm::dmat3(t.matrix));
    if (!(std::abs(det) > 0.0)) {
        return make_error(where(primitive) + name +
                          ": transform cannot be inverted (a scale by 0?)");
    }
    // The scene carries both directions; a wrong inverse would silently misplace the shape.
    const glm::dmat4 product = t.matrix * t.inverse;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            const double scale = 1.0 + std::abs(t.matrix[c][r]);
            if (std::abs(product[c][r] - (c == r ? 1.0 : 0.0)) > 1e-9 * scale * scale) {
                return make_error(where(primitive) + name +
                                  ": transform and its inverse do not match");
            }
        }
    }
    return Ok{};
}

void prepare_sphere(const Transform& t, const Sphere& sphere, PreparedShape& s) {
    s.radius = sphere.radius;
    s.radius_sq = sphere.radius * sphere.radius;
    if (linear_is_identity(t.matrix)) {
        s.kind = ShapeKind::Sphere;
        s.centre = transform_point(t.matrix, sphere.center);
    } else if (const double scale = similarity_scale(t.matrix); scale > 0.0) {
        // POV-Ray keeps a rotated or uniformly scaled sphere a sphere.
        s.kind = ShapeKind::Sphere;
        s.centre = transform_point(t.matrix, sphere.center);
        s.radius = sphere.radius * scale;
        s.radius_sq = s.radius * s.radius;
    } else {
        s.kind = ShapeKind::Ellipsoid;
        s.centre = sphere.center;
        set_local_frame(s, t, glm::dmat4(1.0), glm::dmat4(1.0));
    }
}

Status prepare_plane(const Primitive& primitive, const Plane& plane, PreparedShape& s) {
    const Transform& t = primitive.transform;
    const double length = glm::length(plane.normal);
    if (!(length > kPovEpsilon)) {
        return make_error(where(primitive) + "plane: degenerate normal (zero length)");
    }
    s.kind = ShapeKind::Plane;
    if (linear_is_identity(t.matrix)) {
        // As POV-Ray's Plane::Translate: Distance -= normal . translation.
        s.normal = plane.normal;
        s.pov_distance = -plane.distance - glm::dot(plane.normal, glm::dvec3(t.matrix[3]));
    } else {
        const glm::dvec3 n = glm::normalize(glm::transpose(glm::dmat3(t.inverse)) * plane.normal);
        const glm::dvec3 on_plane = plane.normal * (plane.distance / (length * length));
        s.normal = n;
        s.pov_distance = -glm::dot(n, transform_point(t.matrix, on_plane));
    }
    return Ok{};
}

void prepare_box(const Transform& t, const Box& box, PreparedShape& s) {
    const glm::dvec3 lo = glm::min(box.corner1, box.corner2);
    const glm::dvec3 hi = glm::max(box.corner1, box.corner2);
    if (linear_is_diagonal(t.matrix)) {
        // Translated and scaled, POV-Ray moves the corners and keeps no transform.
        s.kind = ShapeKind::Box;
        const glm::dvec3 a = transform_point(t.matrix, lo);
        const glm::dvec3 b = transform_point(t.matrix, hi);
        s.lo = glm::min(a, b);
        s.hi = glm::max(a, b);
    } else {
        s.kind = ShapeKind::TransformedBox;
        s.lo = lo;
        s.hi = hi;
        set_local_frame(s, t, glm::dmat4(1.0), glm::dmat4(1.0));
    }
}

Status prepare_cylinder(const Primitive& primitive, const Cylinder& cyl, PreparedShape& s) {
    const Transform& t = primitive.transform;
    const glm::dvec3 axis = cyl.cap - cyl.base;
    const double length = glm::length(axis);
    if (!(length > kPovEpsilon)) {
        return make_error(where(primitive) + "cylinder: degenerate, base point = cap point");
    }
    const double radius = std::abs(cyl.radius);
    if (!(radius > 0.0)) return make_error(where(primitive) + "cylinder: radius is 0");
    const glm::dvec3 w = axis / length;
    glm::dvec3 u, v;
    orthonormal_basis(w, u, v);
    s.kind = ShapeKind::Cylinder;
    s.open = cyl.open;
    set_local_frame(s, t, frame_to_world(cyl.base, u, v, w, radius, radius, length),
                    frame_from_world(cyl.base, u, v, w, radius, radius, length));
    return Ok{};
}

Status prepare_disc(const Primitive& primitive, const Disc& disc, PreparedShape& s) {
    const Transform& t = primitive.transform;
    const double length = glm::length(disc.normal);
    if (!(length > kPovEpsilon)) {
        return make_error(where(primitive) + "disc: degenerate normal (zero length)");
    }
    const glm::dvec3 w = disc.normal / length;
    glm::dvec3 u, v;
    orthonormal_basis(w, u, v);
    s.kind = ShapeKind::Disc;
    s.inner_sq = disc.hole_radius * disc.hole_radius;
    s.outer_sq = disc.radius * disc.radius;
    set_local_frame(s, t, frame_to_world(disc.center, u, v, w, 1.0, 1.0, 1.0),
                    frame_from_world(disc.center, u, v, w, 1.0, 1.0, 1.0));
    // POV-Ray carries the disc's normal in world space: transformed as a normal, normalised.
    s.normal = glm::normalize(glm::transpose(glm::dmat3(t.inverse)) * w);
    return Ok{};
}

Status prepare_cone(const Primitive& primitive, const Cone& cone, PreparedShape& s) {
    const Transform& t = primitive.transform;
    // POV-Ray's Compute_Cone_Data: the first point is its "apex"; the bigger end goes on
    // top, at z = 1 of a canonical cone x^2 + y^2 = z^2 whose tip is the origin.
    glm::dvec3 apex = cone.base, base = cone.cap;
    double apex_r = cone.base_radius, base_r = cone.cap_radius;
    glm::dvec3 axis = apex - base;
    const double len = glm::length(axis);
    if (!(len >= kPovEpsilon)) {
        return make_error(where(primitive) + "cone: degenerate, base point = cap point");
    }
    axis /= len;
    s.open = cone.open;
    glm::dvec3 u, v;
    const auto cylinder = [&](const glm::dvec3& from, const glm::dvec3& to, double r) {
        glm::dvec3 w = to - from;
        const double l = glm::length(w);
        w /= l;
        orthonormal_basis(w, u, v);
        s.kind = ShapeKind::Cylinder;
        set_local_frame(s, t, frame_to_world(from, u, v, w, r, r, l),
                        frame_from_world(from, u, v, w, r, r, l));
    };
    if (std::abs(apex_r - base_r) < kPovEpsilon) {
        cylinder(base, apex, apex_r);
        return Ok{};
    }
    if (apex_r < base_r) {
        std::swap(apex, base);
        std::swap(apex_r, base_r);
        axis = -axis;
    }
    const double to_tip = base_r * len / (apex_r - base_r);
    const glm::dvec3 origin = base - axis * to_tip;
    const double tlen = to_tip + len;
    if ((apex_r - base_r) * len / tlen < kPovEpsilon) {
        cylinder(base, apex, apex_r);
        return Ok{};
    }
    s.kind = ShapeKind::Cone;
    s.cone_dist = to_tip / tlen;
    orthonormal_basis(axis, u, v);
    set_local_frame(s, t, frame_to_world(origin, u, v, axis, apex_r, apex_r, tlen),
                    frame_from_world(origin, u, v, axis, apex_r, apex_r, tlen));
    return Ok{};
}

}  // namespace

Result<PreparedShape> prepare_shape(const Primitive& primitive) {
    if (auto st = check_transform(primitive); !st) return st.error();
    const Transform& t = primitive.transform;

    PreparedShape s;
    s.inverse = primitive.inverse;

    if (const auto* sphere = std::get_if<Sphere>(&primitive.shape)) {
        prepare_sphere(t, *sphere, s);
        return s;
    }

    if (const auto* plane = std::get_if<Plane>(&primitive.shape)) {
        if (auto st = prepare_plane(primitive, *plane, s); !st) return st.error();
        return s;
    }

    if (const auto* box = std::get_if<Box>(&primitive.shape)) {
        prepare_box(t, *box, s);
        return s;
    }

    if (const auto* cyl = std::get_if<Cylinder>(&primitive.shape)) {
        if (auto st = prepare_cylinder(primitive, *cyl, s); !st) return st.error();
        return s;
    }

    if (const auto* disc = std::get_if<Disc>(&primitive.shape)) {
        if (auto st = prepare_disc(primitive, *disc, s); !st) return st.error();
        return s;
    }

    if (const auto* cone = std::get_if<Cone>(&primitive.shape)) {
        if (auto st = prepare_cone(primitive, *cone, s); !st) return st.error();
        return s;
    }

    if (const auto* torus = std::get_if<Torus>(&primitive.shape)) {
        s.kind = ShapeKind::Torus;
        s.major = torus->major;
        s.minor = torus->minor;
        s.sturm = torus->sturm;
        set_local_frame(s, t, glm::dmat4(1.0), glm::dmat4(1.0));
        return s;
    }

    if (const auto* quadric = std::get_if<Quadric>(&primitive.shape)) {
        s.kind = ShapeKind::Quadric;
        const double q[10] = {quadric->square.x, quadric->square.y, quadric->square.z,
                              quadric->mixed.x,  quadric->mixed.y,  quadric->mixed.z,
                              quadric->linear.x, quadric->linear.y, quadric->linear.z,
                              quadric->constant};
        std::copy(std::begin(q), std::end(q), std::begin(s.q));
        set_local_frame(s, t, glm::dmat4(1.0), glm::dmat4(1.0));
        return s;
    }

    auto complex = prepare_complex_shape(primitive);
    if (!complex) return complex.error();
    s.kind = ShapeKind::Complex;
    s.complex = std::move(*complex);
    return s;
}

namespace {

// POV-Ray's tolerances (torus.cpp): roots this close to the ray's start are dropped before
// solving, against acne.
constexpr double kTorusRootTolerance = 1.0e-4;

template <class Emit>
void torus_roots(const PreparedShape& s, const glm::dvec3& origin, const glm::dvec3& direction,
                 double t_min, Emit&& emit) {
    glm::dvec3 p = transform_point(s.world_to_local, origin);
    glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
    const double len = glm::length(d);
    d /= len;
    const double R = s.major, r = s.minor;
    // POV-Ray's Test_Thick_Cylinder: the ray must meet the cylinder shell around the torus.
    // Its tests look forward only (k > EPSILON); a query reaching behind its origin (a
    // polyline joint) moves the start back first.
    const double back = t_min < 0.0 ? t_min * len : 0.0;
    const glm::dvec3 p0 = p + back * d;
    const double h1 = -r, h2 = r;
    const double r1 = R < r ? 0.0 : (R - r) * (R - r), r2 = (R + r) * (R + r);
    const auto thick_cylinder = [&]() {
        if (std::abs(d.y) < kPovEpsilon) {
            if (p0.y < h1 || p0.y > h2) return false;
        } else {
            for (const double h : {h2, h1}) {
                const double k = (h - p0.y) / d.y;
                const double u = p0.x + k * d.x, v = p0.z + k * d.z;
                if (k > kPovEpsilon && k < kPovMaxDistance) {
                    const double rr = u * u + v * v;
                    if (rr >= r1 && rr <= r2) return true;
                }
            }
        }
        const double a = d.x * d.x + d.z * d.z;
        if (a > kPovEpsilon) {
            const double b = p0.x * d.x + p0.z * d.z;
            for (const double rr : {r2, r1}) {
                const double c = p0.x * p0.x + p0.z * p0.z - rr;
                double disc = b * b - a * c;
                if (disc < 0.0) continue;
                disc = std::sqrt(disc);
                for (const double k : {(-b + disc) / a, (-b - disc) / a}) {
                    if (k > kPovEpsilon && k < kPovMaxDistance) {
                        const double h = p0.y + k * d.y;
                        if (h >= h1 && h <= h2) return true;
                    }
                }
            }
        }
        return false;
    };
    if (!thick_cylinder()) return;
    // Start near the bounding sphere for precise roots, as POV-Ray does.
    const double sphere_r = R + r + r;
    double closer = 0.0;
    const double dist_sq = glm::dot(p, p);
    if (dist_sq > sphere_r * sphere_r) {
        closer = std::sqrt(dist_sq) - sphere_r;
        p += closer * d;
    }
    const double R2 = R * R, rr2 = r * r;
    const double Py2 = p.y * p.y, Dy2 = d.y * d.y, PDy2 = p.y * d.y;
    const double k1 = p.x * p.x + p.z * p.z + Py2 - R2 - rr2;
    const double k2 = p.x * d.x + p.z * d.z + PDy2;
    const double c[5] = {1.0, 4.0 * k2, 2.0 * (k1 + 2.0 * (k2 * k2 + R2 * Dy2)),
                         4.0 * (k2 * k1 + 2.0 * R2 * PDy2), k1 * k1 + 4.0 * R2 * (Py2 - rr2)};
    double roots[4];
    // Against acne POV-Ray drops a root at the start; a query starting behind it keeps it.
    const int n = solve_polynomial(4, c, roots, s.sturm, t_min < 0.0 ? 0.0 : kTorusRootTolerance);
    for (int i = n; i-- > 0;) {
        const double depth = (roots[i] + closer) / len;
        if (depth < kPovMaxDistance) emit(depth, 0);
    }
}

template <class Emit>
void quadric_roots(const PreparedShape& s, const glm::dvec3& origin, const glm::dvec3& direction,
                   Emit&& emit) {
    // POV-Ray's Quadric::Intersect with the quadric in its own space (POV-Ray transforms the
    // coefficients instead: the same roots).
    const glm::dvec3 o = transform_point(s.world_to_local, origin);
    const glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
    const double QA = s.q[0], QE = s.q[1], QH = s.q[2], QB = s.q[3], QC = s.q[4], QF = s.q[5],
                 QD = s.q[6], QG = s.q[7], QI = s.q[8], QJ = s.q[9];
    const double a =
        d.x * (QA * d.x + QB * d.y + QC * d.z) + d.y * (QE * d.y + QF * d.z) + d.z * QH * d.z;
    const double b = d.x * (QA * o.x + 0.5 * (QB * o.y + QC * o.z + QD)) +
                     d.y * (QE * o.y + 0.5 * (QB * o.x + QF * o.z + QG)) +
                     d.z * (QH * o.z + 0.5 * (QC * o.x + QF * o.y + QI));
    const double c = o.x * (QA * o.x + QB * o.y + QC * o.z + QD) +
                     o.y * (QE * o.y + QF * o.z + QG) + o.z * (QH * o.z + QI) + QJ;
    if (a != 0.0) {
        double disc = b * b - a * c;
        if (disc <= 0.0) return;
        disc = std::sqrt(disc);
        for (const double t : {(-b + disc) / a, (-b - disc) / a}) {
            if (t < kPovMaxDistance) emit(t, 0);
        }
    } else if (b != 0.0) {
        const double t = -0.5 * c / b;
        if (t < kPovMaxDistance) emit(t, 0);
    }
}

/// Every root of the shape along the ray, unfiltered by [t_min, t_max] (emit filters), with
/// the part it belongs to.
template <class Emit>
void shape_roots(const PreparedShape& s, const glm::dvec3& origin, const glm::dvec3& direction,
                 double t_min, Emit&& emit) {
    const bool allow_behind = t_min < 0.0;
    switch (s.kind) {
        case ShapeKind::Sphere: {
            double t1, t2;
            if (!sphere_roots(s.centre, s.radius_sq, origin, direction, allow_behind, t1, t2)) {
                return;
            }
            if (t1 < kPovMaxDistance) emit(t1, 0);
            if (t2 < kPovMaxDistance) emit(t2, 0);
            return;
        }
        case ShapeKind::Ellipsoid: {
            const glm::dvec3 p = transform_point(s.world_to_local, origin);
            glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
            const double len = glm::length(d);
            d *= 1.0 / len;
            double t1, t2;
            if (!sphere_roots(s.centre, s.radius_sq, p, d, allow_behind, t1, t2)) return;
            // MAX_DISTANCE applies in the ellipsoid's own space, as in POV-Ray.
            if (t1 < kPovMaxDistance) emit(t1 / len, 0);
            if (t2 < kPovMaxDistance) emit(t2 / len, 0);
            return;
        }
        case ShapeKind::Plane: {
            const double n_dot_d = glm::dot(s.normal, direction);
            if (std::abs(n_dot_d) < kPovEpsilon) return;
            const double n_dot_o = glm::dot(s.normal, origin);
            const double t = -(n_dot_o + s.pov_distance) / n_dot_d;
            if (t <= kPovMaxDistance) emit(t, 0);
            return;
        }
        case ShapeKind::Box:
        case ShapeKind::TransformedBox: {
            glm::dvec3 p = origin;
            glm::dvec3 d = direction;
            if (s.kind == ShapeKind::TransformedBox) {
                p = transform_point(s.world_to_local, origin);
                d = glm::dmat3(s.world_to_local) * direction;
            }
            double t_near, t_far;
            int s_near, s_far;
            // POV-Ray starts the entry depth at 0, where an entry closer than CLOSE_TOLERANCE
            // does not register; a query reaching behind its origin (a polyline joint) starts
            // far enough back for entries from t_min on to register.
            const double t_start = t_min < 0.0 ? t_min - 2.0 * kBoxCloseTolerance : 0.0;
            if (!box_roots(s.lo, s.hi, p, d, t_start, t_near, s_near, t_far, s_far)) return;
            if (s_near != 0) emit(t_near, s_near);
            if (s_far != 0) emit(t_far, s_far);
            return;
        }
        case ShapeKind::Cylinder:
        case ShapeKind::Cone: {
            const glm::dvec3 p = transform_point(s.world_to_local, origin);
            glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
            const double len = glm::length(d);
            d *= 1.0 / len;
            const bool cylinder = s.kind == ShapeKind::Cylinder;
            const double dist = cylinder ? 0.0 : s.cone_dist;
            // POV-Ray's Cone::Intersect: canonical depths, MAX_DISTANCE there.
            const auto side = [&](double t) {
                const double z = p.z + t * d.z;
                if (t < kPovMaxDistance && z >= dist && z <= 1.0) emit(t / len, kSideHit);
            };
            if (cylinder) {
                const double a = d.x * d.x + d.y * d.y;
                if (a > kPovEpsilon) {
                    const double b = p.x * d.x + p.y * d.y;
                    const double c = p.x * p.x + p.y * p.y - 1.0;
                    double disc = b * b - a * c;
                    if (disc >= 0.0) {
                        disc = std::sqrt(disc);
                        side((-b + disc) / a);
                        side((-b - disc) / a);
                    }
                }
            } else {
                const double a = d.x * d.x + d.y * d.y - d.z * d.z;
                const double b = d.x * p.x + d.y * p.y - d.z * p.z;
                const double c = p.x * p.x + p.y * p.y - p.z * p.z;
                if (std::abs(a) < kPovEpsilon) {
                    if (std::abs(b) > kPovEpsilon) side(-0.5 * c / b);
                } else {
                    double disc = b * b - a * c;
                    if (disc >= 0.0) {
                        disc = std::sqrt(disc);
                        side((-b - disc) / a);
                        side((-b + disc) / a);
                    }
                }
            }
            if (!s.open && std::abs(d.z) > kPovEpsilon) {
                const double base_sq = cylinder ? 1.0 : dist * dist;
                for (const auto& [plane_z, part, limit] :
                     {std::tuple{1.0, kCapHit, 1.0}, std::tuple{dist, kBaseHit, base_sq}}) {
                    const double t = (plane_z - p.z) / d.z;
                    const double u = p.x + t * d.x;
                    const double v = p.y + t * d.y;
                    if (u * u + v * v <= limit && t < kPovMaxDistance) emit(t / len, part);
                }
            }
            return;
        }
        case ShapeKind::Disc: {
            const glm::dvec3 p = transform_point(s.world_to_local, origin);
            glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
            const double len = glm::length(d);
            d *= 1.0 / len;
            if (std::abs(d.z) <= kPovEpsilon) return;
            const double t = -p.z / d.z;
            const double u = p.x + t * d.x;
            const double v = p.y + t * d.y;
            const double r2 = u * u + v * v;
            if (r2 >= s.inner_sq && r2 <= s.outer_sq) {
                const double depth = t / len;
                if (depth < kPovMaxDistance) emit(depth, 0);
            }
            return;
        }
        case ShapeKind::Torus:
            torus_roots(s, origin, direction, t_min, emit);
            return;
        case ShapeKind::Quadric:
            quadric_roots(s, origin, direction, emit);
            return;
        case ShapeKind::Complex:
            return;  // through ComplexShape::intersect
    }
}

}  // namespace

bool intersect_shape(const PreparedShape& s, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_min, double t_max, ShapeHit& hit) {
    HitSink sink(t_min, t_max);
    if (s.kind == ShapeKind::Complex) {
        s.complex->intersect(origin, direction, sink);
    } else {
        shape_roots(s, origin, direction, t_min, [&](double t, int part) { sink.add(t, part); });
    }
    if (!sink.found()) return false;
    hit = sink.closest();
    return true;
}

void intersect_shape_all(const PreparedShape& s, const glm::dvec3& origin,
                         const glm::dvec3& direction, double t_min, double t_max,
                         std::vector<ShapeHit>& hits) {
    HitSink sink(t_min, t_max, &hits);
    if (s.kind == ShapeKind::Complex) {
        s.complex->intersect(origin, direction, sink);
    } else {
        shape_roots(s, origin, direction, t_min, [&](double t, int part) { sink.add(t, part); });
    }
}

bool inside_shape(const PreparedShape& s, const glm::dvec3& point) {
    switch (s.kind) {
        case ShapeKind::Sphere:
        case ShapeKind::Ellipsoid: {
            const glm::dvec3 p =
                s.kind == ShapeKind::Sphere ? point : transform_point(s.world_to_local, point);
            const glm::dvec3 oc = s.centre - p;
            const double oc_sq = glm::dot(oc, oc);
            return s.inverse ? oc_sq > s.radius_sq : oc_sq < s.radius_sq;
        }
        case ShapeKind::Plane: {
            // POV-Ray inverts a plane by negating it: the same test on the other side.
            const double side = glm::dot(point, s.normal) + s.pov_distance;
            return (s.inverse ? -side : side) < kPovEpsilon;
        }
        case ShapeKind::Box:
        case ShapeKind::TransformedBox: {
            const glm::dvec3 p =
                s.kind == ShapeKind::Box ? point : transform_point(s.world_to_local, point);
            const bool in = !(p.x < s.lo.x || p.x > s.hi.x || p.y < s.lo.y || p.y > s.hi.y ||
                              p.z < s.lo.z || p.z > s.hi.z);
            return in != s.inverse;
        }
        case ShapeKind::Cylinder:
        case ShapeKind::Cone: {
            const glm::dvec3 p = transform_point(s.world_to_local, point);
            const double offset = s.open ? kPovEpsilon : -kPovEpsilon;
            const double w2 = p.x * p.x + p.y * p.y;
            const bool out =
                s.kind == ShapeKind::Cylinder
                    ? (w2 > 1.0 + offset || p.z < 0.0 - offset || p.z > 1.0 + offset)
                    : (w2 > p.z * p.z + offset || p.z < s.cone_dist - offset || p.z > 1.0 + offset);
            return out == s.inverse;
        }
        case ShapeKind::Disc: {
            const glm::dvec3 p = transform_point(s.world_to_local, point);
            return (p.z < 0.0) != s.inverse;
        }
        case ShapeKind::Torus: {
            const glm::dvec3 p = transform_point(s.world_to_local, point);
            const double r = std::sqrt(p.x * p.x + p.z * p.z);
            const double r2 = p.y * p.y + (r - s.major) * (r - s.major);
            return (r2 <= s.minor * s.minor) != s.inverse;
        }
        case ShapeKind::Quadric: {
            const glm::dvec3 p = transform_point(s.world_to_local, point);
            const double QA = s.q[0], QE = s.q[1], QH = s.q[2], QB = s.q[3], QC = s.q[4],
                         QF = s.q[5], QD = s.q[6], QG = s.q[7], QI = s.q[8], QJ = s.q[9];
            const double v = p.x * (QA * p.x + QB * p.y + QD) + p.y * (QE * p.y + QF * p.z + QG) +
                             p.z * (QH * p.z + QC * p.x + QI) + QJ;
            return (v <= 0.0) != s.inverse;
        }
        case ShapeKind::Complex:
            return s.complex->inside(point) != s.inverse;
    }
    return false;
}

glm::dvec3 shape_normal(const PreparedShape& s, const glm::dvec3& point, const ShapeHit& hit) {
    const int part = hit.part;
    glm::dvec3 n(0.0);
    switch (s.kind) {
        case ShapeKind::Sphere:
            n = (point - s.centre) * (1.0 / s.radius);
            break;
        case ShapeKind::Ellipsoid:
            n = glm::normalize(s.normal_to_world *
                               (transform_point(s.world_to_local, point) - s.centre));
            break;
        case ShapeKind::Plane:
        case ShapeKind::Disc:
            n = s.normal;
            break;
        case ShapeKind::Box:
        case ShapeKind::TransformedBox: {
            const int axis = side_axis(part);
            n[axis] = part == side_high(axis) ? 1.0 : -1.0;
            if (s.kind == ShapeKind::TransformedBox) n = glm::normalize(s.normal_to_world * n);
            break;
        }
        case ShapeKind::Cylinder:
        case ShapeKind::Cone: {
            glm::dvec3 local(0.0, 0.0, part == kCapHit ? 1.0 : -1.0);
            if (part == kSideHit) {
                local = transform_point(s.world_to_local, point);
                local.z = s.kind == ShapeKind::Cylinder ? 0.0 : -local.z;
            }
            n = glm::normalize(s.normal_to_world * local);
            break;
        }
        case ShapeKind::Torus: {
            const glm::dvec3 p = transform_point(s.world_to_local, point);
            const double dist = std::sqrt(p.x * p.x + p.z * p.z);
            glm::dvec3 m(0.0);
            if (dist > kPovEpsilon) m = glm::dvec3(s.major * p.x / dist, 0.0, s.major * p.z / dist);
            n = glm::normalize(s.normal_to_world * (p - m));
            break;
        }
        case ShapeKind::Quadric: {
            const glm::dvec3 p = transform_point(s.world_to_local, point);
            const double QA = s.q[0], QE = s.q[1], QH = s.q[2], QB = s.q[3], QC = s.q[4],
                         QF = s.q[5], QD = s.q[6], QG = s.q[7], QI = s.q[8];
            const glm::dvec3 g(2.0 * QA * p.x + QB * p.y + QC * p.z + QD,
                               QB * p.x + 2.0 * QE * p.y + QF * p.z + QG,
                               QC * p.x + QF * p.y + 2.0 * QH * p.z + QI);
            const glm::dvec3 w = s.normal_to_world * g;
            const double l = glm::length(w);
            n = l == 0.0 ? glm::dvec3(1.0, 0.0, 0.0) : w / l;
            break;
        }
        case ShapeKind::Complex:
            n = s.complex->normal(point, hit);
            break;
    }
    return s.inverse ? -n : n;
}

glm::dvec3 shape_normal(const PreparedShape& s, const glm::dvec3& point, int part) {
    ShapeHit hit;
    hit.part = part;
    return shape_normal(s, point, hit);
}

namespace {

Aabb infinite_box() {
    Aabb box;
    box.lo = glm::dvec3(-std::numeric_limits<double>::infinity());
    box.hi = glm::dvec3(std::numeric_limits<double>::infinity());
    return box;
}

// The box of a quadric in its own space, for the forms POV-Ray bounds (Quadric::Compute_BBox:
// the ellipsoid without mixed terms); others are unbounded.
bool quadric_local_box(const double* q, glm::dvec3& lo, glm::dvec3& hi) {
    double A = q[0], E = q[1], H = q[2];
    const double B = q[3] / 2.0, C = q[4] / 2.0, F = q[5] / 2.0;
    double D = q[6] / 2.0, G = q[7] / 2.0, I = q[8] / 2.0, J = q[9];
    if (std::abs(B) >= kPovEpsilon || std::abs(C) >= kPovEpsilon || std::abs(F) >= kPovEpsilon) {
        return false;
    }
    // Complete the squares: the centre T, then A x^2 + E y^2 + H z^2 + J' = 0 around it.
    const glm::dvec3 T(A != 0.0 ? -D / A : 0.0, E != 0.0 ? -G / E : 0.0, H != 0.0 ? -I / H : 0.0);
    if ((A == 0.0 && D != 0.0) || (E == 0.0 && G != 0.0) || (H == 0.0 && I != 0.0)) return false;
    J -= A * T.x * T.x + E * T.y * T.y + H * T.z * T.z;
    if (A < 0.0) {
        A = -A;
        E = -E;
        H = -H;
        J = -J;
    }
    if (!(A > 0.0 && E > 0.0 && H > 0.0 && J < 0.0)) return false;
    const glm::dvec3 half(std::sqrt(-J / A), std::sqrt(-J / E), std::sqrt(-J / H));
    lo = T - half;
    hi = T + half;
    return true;
}

}  // namespace

Aabb shape_bounds(const PreparedShape& s) {
    Aabb box;
    const auto corners = [&](const glm::dvec3& lo, const glm::dvec3& hi) {
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 c((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
            box.extend(transform_point(s.local_to_world, c));
        }
    };
    switch (s.kind) {
        case ShapeKind::Sphere:
            box.extend(s.centre - glm::dvec3(std::abs(s.radius)));
            box.extend(s.centre + glm::dvec3(std::abs(s.radius)));
            break;
        case ShapeKind::Ellipsoid: {
            // Exact: the image of the sphere spans r |row i of the linear map| along axis i.
            const glm::dvec3 c = transform_point(s.local_to_world, s.centre);
            glm::dvec3 half;
            for (int i = 0; i < 3; ++i) {
                const glm::dvec3 row(s.local_to_world[0][i], s.local_to_world[1][i],
                                     s.local_to_world[2][i]);
                half[i] = std::abs(s.radius) * glm::length(row);
            }
            box.extend(c - half);
            box.extend(c + half);
            break;
        }
        case ShapeKind::Plane:
            return infinite_box();
        case ShapeKind::Box:
            box.lo = s.lo;
            box.hi = s.hi;
            break;
        case ShapeKind::TransformedBox:
            corners(s.lo, s.hi);
            break;
        case ShapeKind::Cylinder:
            corners(glm::dvec3(-1.0, -1.0, 0.0), glm::dvec3(1.0, 1.0, 1.0));
            break;
        case ShapeKind::Cone:
            corners(glm::dvec3(-1.0, -1.0, s.cone_dist), glm::dvec3(1.0, 1.0, 1.0));
            break;
        case ShapeKind::Disc: {
            const double r = std::sqrt(s.outer_sq);
            corners(glm::dvec3(-r, -r, 0.0), glm::dvec3(r, r, 0.0));
            break;
        }
        case ShapeKind::Torus: {
            const double r2 = std::abs(s.major) + std::abs(s.minor);
            const double r1 = std::abs(s.minor);
            corners(glm::dvec3(-r2, -r1, -r2), glm::dvec3(r2, r1, r2));
            break;
        }
        case ShapeKind::Quadric: {
            glm::dvec3 lo, hi;
            if (!quadric_local_box(s.q, lo, hi)) return infinite_box();
            corners(lo, hi);
            break;
        }
        case ShapeKind::Complex:
            return s.complex->bounds();
    }
    return box;
}

Aabb shape_inside_bounds(const PreparedShape& s) {
    if (s.inverse) return infinite_box();
    switch (s.kind) {
        case ShapeKind::Plane: {
            // POV-Ray's Compute_Plane_Min_Max: an axis-aligned plane bounds one side.
            Aabb box = infinite_box();
            for (int axis = 0; axis < 3; ++axis) {
                const double n = s.normal[axis];
                bool aligned = true;
                for (int other = 0; other < 3; ++other) {
                    if (other != axis && s.normal[other] != 0.0) aligned = false;
                }
                if (!aligned || n == 0.0) continue;
                // Inside: n * p[axis] + Distance < 0.
                const double at = -s.pov_distance / n;
                if (n > 0.0) {
                    box.hi[axis] = at;
                } else {
                    box.lo[axis] = at;
                }
            }
            return box;
        }
        case ShapeKind::Disc:
            return infinite_box();  // its inside is a half-space
        case ShapeKind::Cylinder:
        case ShapeKind::Cone:
            return shape_bounds(s);  // open or not, the inside is within the shell
        default:
            return shape_bounds(s);
    }
}

}  // namespace mirage
