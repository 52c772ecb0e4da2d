#include "trace/shape_intersect.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

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

std::string where(const Primitive& p) {
    std::ostringstream out;
    if (!p.loc.file.empty()) out << p.loc.file << ":" << p.loc.line << ":" << p.loc.column << ": ";
    return out.str();
}

std::string shape_name(const Shape& shape) {
    static const char* const names[] = {"sphere", "plane", "box", "cylinder", "disc"};
    return names[shape.index()];
}

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

/// Accepts t when it lies in [t_min, t_max] and is closer than the best so far.
inline void consider(double t, int part, double t_min, double t_max, ShapeHit& best, bool& found) {
    if (t >= t_min && t <= t_max && (!found || t < best.t)) {
        best.t = t;
        best.part = part;
        found = true;
    }
}

/// POV-Ray's Sphere::Intersect: the two depths along a unit direction, or false for a miss
/// (including rays that only graze, half chord^2 <= EPSILON).
inline bool sphere_roots(const glm::dvec3& centre, double radius_sq, const glm::dvec3& origin,
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

/// POV-Ray's Box::Intersect (boxes.cpp) in the box's own space, unnormalised direction: the
/// entry and exit depths with the sides hit, the sides disambiguated where the ray passes
/// within CLOSE_TOLERANCE of an edge.  `t_start` is where the entry depth starts (POV-Ray: 0).
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

}  // namespace

Result<PreparedShape> prepare_shape(const Primitive& primitive) {
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

    PreparedShape s;
    s.inverse = primitive.inverse;

    if (const auto* sphere = std::get_if<Sphere>(&primitive.shape)) {
        s.radius = sphere->radius;
        s.radius_sq = sphere->radius * sphere->radius;
        if (linear_is_identity(t.matrix)) {
            s.kind = ShapeKind::Sphere;
            s.centre = transform_point(t.matrix, sphere->center);
        } else if (const double scale = similarity_scale(t.matrix); scale > 0.0) {
            // POV-Ray keeps a rotated or uniformly scaled sphere a sphere.
            s.kind = ShapeKind::Sphere;
            s.centre = transform_point(t.matrix, sphere->center);
            s.radius = sphere->radius * scale;
            s.radius_sq = s.radius * s.radius;
        } else {
            s.kind = ShapeKind::Ellipsoid;
            s.centre = sphere->center;
            set_local_frame(s, t, glm::dmat4(1.0), glm::dmat4(1.0));
        }
        return s;
    }

    if (const auto* plane = std::get_if<Plane>(&primitive.shape)) {
        const double length = glm::length(plane->normal);
        if (!(length > kPovEpsilon)) {
            return make_error(where(primitive) + "plane: degenerate normal (zero length)");
        }
        s.kind = ShapeKind::Plane;
        if (linear_is_identity(t.matrix)) {
            // As POV-Ray's Plane::Translate: Distance -= normal . translation.
            s.normal = plane->normal;
            s.pov_distance = -plane->distance - glm::dot(plane->normal, glm::dvec3(t.matrix[3]));
        } else {
            const glm::dvec3 n =
                glm::normalize(glm::transpose(glm::dmat3(t.inverse)) * plane->normal);
            const glm::dvec3 on_plane = plane->normal * (plane->distance / (length * length));
            s.normal = n;
            s.pov_distance = -glm::dot(n, transform_point(t.matrix, on_plane));
        }
        return s;
    }

    if (const auto* box = std::get_if<Box>(&primitive.shape)) {
        const glm::dvec3 lo = glm::min(box->corner1, box->corner2);
        const glm::dvec3 hi = glm::max(box->corner1, box->corner2);
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
        return s;
    }

    if (const auto* cyl = std::get_if<Cylinder>(&primitive.shape)) {
        const glm::dvec3 axis = cyl->cap - cyl->base;
        const double length = glm::length(axis);
        if (!(length > kPovEpsilon)) {
            return make_error(where(primitive) + "cylinder: degenerate, base point = cap point");
        }
        const double radius = std::abs(cyl->radius);
        if (!(radius > 0.0)) return make_error(where(primitive) + "cylinder: radius is 0");
        const glm::dvec3 w = axis / length;
        glm::dvec3 u, v;
        orthonormal_basis(w, u, v);
        s.kind = ShapeKind::Cylinder;
        s.open = cyl->open;
        set_local_frame(s, t, frame_to_world(cyl->base, u, v, w, radius, radius, length),
                        frame_from_world(cyl->base, u, v, w, radius, radius, length));
        return s;
    }

    const auto& disc = std::get<Disc>(primitive.shape);
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
    return s;
}

bool intersect_shape(const PreparedShape& s, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_min, double t_max, ShapeHit& hit) {
    bool found = false;
    const bool allow_behind = t_min < 0.0;
    switch (s.kind) {
        case ShapeKind::Sphere: {
            double t1, t2;
            if (!sphere_roots(s.centre, s.radius_sq, origin, direction, allow_behind, t1, t2)) {
                return false;
            }
            if (t1 < kPovMaxDistance) consider(t1, 0, t_min, t_max, hit, found);
            if (t2 < kPovMaxDistance) consider(t2, 0, t_min, t_max, hit, found);
            return found;
        }
        case ShapeKind::Ellipsoid: {
            const glm::dvec3 p = transform_point(s.world_to_local, origin);
            glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
            const double len = glm::length(d);
            d *= 1.0 / len;
            double t1, t2;
            if (!sphere_roots(s.centre, s.radius_sq, p, d, allow_behind, t1, t2)) return false;
            // MAX_DISTANCE applies in the ellipsoid's own space, as in POV-Ray.
            if (t1 < kPovMaxDistance) consider(t1 / len, 0, t_min, t_max, hit, found);
            if (t2 < kPovMaxDistance) consider(t2 / len, 0, t_min, t_max, hit, found);
            return found;
        }
        case ShapeKind::Plane: {
            const double n_dot_d = glm::dot(s.normal, direction);
            if (std::abs(n_dot_d) < kPovEpsilon) return false;
            const double n_dot_o = glm::dot(s.normal, origin);
            const double t = -(n_dot_o + s.pov_distance) / n_dot_d;
            if (t <= kPovMaxDistance) consider(t, 0, t_min, t_max, hit, found);
            return found;
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
            if (!box_roots(s.lo, s.hi, p, d, t_start, t_near, s_near, t_far, s_far)) {
                return false;
            }
            if (s_near != 0) consider(t_near, s_near, t_min, t_max, hit, found);
            if (s_far != 0) consider(t_far, s_far, t_min, t_max, hit, found);
            return found;
        }
        case ShapeKind::Cylinder: {
            const glm::dvec3 p = transform_point(s.world_to_local, origin);
            glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
            const double len = glm::length(d);
            d *= 1.0 / len;
            // POV-Ray's Cone::Intersect for a cylinder: canonical depths, MAX_DISTANCE there.
            const double a = d.x * d.x + d.y * d.y;
            if (a > kPovEpsilon) {
                const double b = p.x * d.x + p.y * d.y;
                const double c = p.x * p.x + p.y * p.y - 1.0;
                double disc = b * b - a * c;
                if (disc >= 0.0) {
                    disc = std::sqrt(disc);
                    for (const double t : {(-b + disc) / a, (-b - disc) / a}) {
                        const double z = p.z + t * d.z;
                        if (t < kPovMaxDistance && z >= 0.0 && z <= 1.0) {
                            consider(t / len, kSideHit, t_min, t_max, hit, found);
                        }
                    }
                }
            }
            if (!s.open && std::abs(d.z) > kPovEpsilon) {
                for (const auto& [plane_z, part] :
                     {std::pair{1.0, kCapHit}, std::pair{0.0, kBaseHit}}) {
                    const double t = (plane_z - p.z) / d.z;
                    const double u = p.x + t * d.x;
                    const double v = p.y + t * d.y;
                    if (u * u + v * v <= 1.0 && t < kPovMaxDistance) {
                        consider(t / len, part, t_min, t_max, hit, found);
                    }
                }
            }
            return found;
        }
        case ShapeKind::Disc: {
            const glm::dvec3 p = transform_point(s.world_to_local, origin);
            glm::dvec3 d = glm::dmat3(s.world_to_local) * direction;
            const double len = glm::length(d);
            d *= 1.0 / len;
            if (std::abs(d.z) <= kPovEpsilon) return false;
            const double t = -p.z / d.z;
            const double u = p.x + t * d.x;
            const double v = p.y + t * d.y;
            const double r2 = u * u + v * v;
            if (r2 >= s.inner_sq && r2 <= s.outer_sq) {
                const double depth = t / len;
                if (depth < kPovMaxDistance) consider(depth, 0, t_min, t_max, hit, found);
            }
            return found;
        }
    }
    return false;
}

glm::dvec3 shape_normal(const PreparedShape& s, const glm::dvec3& point, int part) {
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
        case ShapeKind::Cylinder: {
            glm::dvec3 local(0.0, 0.0, part == kCapHit ? 1.0 : -1.0);
            if (part == kSideHit) {
                local = transform_point(s.world_to_local, point);
                local.z = 0.0;
            }
            n = glm::normalize(s.normal_to_world * local);
            break;
        }
    }
    return s.inverse ? -n : n;
}

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
            box.lo = glm::dvec3(-std::numeric_limits<double>::infinity());
            box.hi = glm::dvec3(std::numeric_limits<double>::infinity());
            break;
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
        case ShapeKind::Disc: {
            const double r = std::sqrt(s.outer_sq);
            corners(glm::dvec3(-r, -r, 0.0), glm::dvec3(r, r, 0.0));
            break;
        }
    }
    return box;
}

}  // namespace mirage
