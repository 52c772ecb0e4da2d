// Blobs after POV-Ray 3.7's blob.cpp: a density field summed over spherical and cylindrical
// components, each strength (1 - r^2 / radius^2)^2 within its radius, and the surface where
// the field equals the threshold.  A cylinder component is a cylinder and two hemispheres at
// its ends (Make_Blob).  Along a ray the components' entry and exit depths cut the ray into
// intervals; in each the field is one quartic in the depth, solved by POV-Ray's solver
// (All_Blob_Intersections) after the same Bezier sign test, with the same tolerances.
#include "shapes/blob.h"

#include <algorithm>
#include <cmath>

#include "shapes/polysolve.h"

namespace mirage {
namespace {

constexpr double kDepthTolerance = 1.0e-2;   // blob.cpp DEPTH_TOLERANCE
constexpr double kInsideTolerance = 1.0e-6;  // blob.cpp INSIDE_TOLERANCE
constexpr double kSmallTolerance = 1.0e-3;   // POV-Ray's SMALL_TOLERANCE
constexpr double kSolveEpsilon = 1.0e-11;    // the epsilon All_Blob_Intersections passes

enum class ElementType : std::uint8_t { Sphere, Ellipsoid, BaseHemisphere, ApexHemisphere, Cylinder };

/// One of POV-Ray's Blob_Element: a sphere (no transform), an ellipsoid (a sphere under a
/// transform), or a cylinder's body or end caps in the cylinder's own space (z from 0 to len).
struct Element {
    ElementType type = ElementType::Sphere;
    glm::dmat4 to_local{1.0};   // blob space to the element's space (Trans's inverse)
    glm::dmat3 normal_m{1.0};   // the element's normals to blob space: transpose(to_local)
    glm::dmat4 to_blob{1.0};    // the element's space to blob space (Trans)
    glm::dvec3 o{0.0};          // sphere, ellipsoid: the centre in the element's space
    double rad2 = 1.0;
    double len = 0.0;           // cylinder and its caps: the axis length
    double c[3] = {0, 0, 0};    // density = c0 r^4 + c1 r^2 + c2
    int component = 0;          // index into Blob::components
};

glm::dvec3 xform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}
glm::dvec3 xform_dir(const glm::dmat4& m, const glm::dvec3& d) { return glm::dmat3(m) * d; }

bool is_translation(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (l[i][j] != (i == j ? 1.0 : 0.0)) return false;
        }
    }
    return true;
}

/// The rotation taking +z to the unit vector `up`, then the translation to `origin`: POV-Ray's
/// Compute_Coordinate_Transform with radius and length 1 (an axis rotation about z x up).
glm::dmat4 coordinate_frame(const glm::dvec3& origin, glm::dvec3 up) {
    glm::dvec3 axis;
    if (std::abs(up.z) > 1.0 - kPovEpsilon) {
        axis = glm::dvec3(1.0, 0.0, 0.0);
        up.z = up.z < 0.0 ? -1.0 : 1.0;
    } else {
        axis = glm::normalize(glm::dvec3(-up.y, up.x, 0.0));
    }
    const double angle = std::acos(up.z);
    const double cs = std::cos(angle), sn = std::sin(angle);
    glm::dmat4 m(1.0);
    // Rodrigues: R = cos I + sin [a]x + (1 - cos) a a^T; glm is column-major (m[col][row]).
    const double k[3][3] = {{0.0, -axis.z, axis.y}, {axis.z, 0.0, -axis.x}, {-axis.y, axis.x, 0.0}};
    for (int r = 0; r < 3; ++r) {
        for (int col = 0; col < 3; ++col) {
            m[col][r] = (r == col ? cs : 0.0) + sn * k[r][col] + (1.0 - cs) * axis[r] * axis[col];
        }
    }
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

std::vector<Element> make_elements(const Blob& blob) {
    std::vector<Element> out;
    for (std::size_t i = 0; i < blob.components.size(); ++i) {
        const BlobComponent& comp = blob.components[i];
        const double rad2 = comp.radius * comp.radius;
        const double coeff = comp.strength;
        Element e;
        e.rad2 = rad2;
        e.c[0] = coeff / (rad2 * rad2);
        e.c[1] = -(2.0 * coeff) / rad2;
        e.c[2] = coeff;
        e.component = static_cast<int>(i);
        if (!comp.cylinder) {
            if (is_translation(comp.to_world)) {
                e.type = ElementType::Sphere;
                e.o = comp.centre + glm::dvec3(comp.to_world[3]);
            } else {
                e.type = ElementType::Ellipsoid;
                e.o = comp.centre;
                e.to_blob = comp.to_world;
                e.to_local = comp.from_world;
                e.normal_m = glm::transpose(glm::dmat3(e.to_local));
            }
            out.push_back(e);
            continue;
        }
        const glm::dvec3 axis = comp.end - comp.centre;
        e.len = glm::length(axis);
        e.to_blob = comp.to_world * coordinate_frame(comp.centre, axis / e.len);
        e.to_local = glm::inverse(e.to_blob);
        e.normal_m = glm::transpose(glm::dmat3(e.to_local));
        e.type = ElementType::Cylinder;
        out.push_back(e);
        e.type = ElementType::BaseHemisphere;
        out.push_back(e);
        e.type = ElementType::ApexHemisphere;
        out.push_back(e);
    }
    return out;
}

/// POV-Ray's calculate_element_field.
double element_field(const Element& e, const glm::dvec3& p) {
    if (!(e.rad2 > 0.0)) return 0.0;  // radius 0: nothing (POV-Ray's would give 0 or NaN)
    double r2 = 0.0;
    switch (e.type) {
        case ElementType::Sphere: {
            const glm::dvec3 v = p - e.o;
            r2 = glm::dot(v, v);
            return r2 < e.rad2 ? r2 * (r2 * e.c[0] + e.c[1]) + e.c[2] : 0.0;
        }
        case ElementType::Ellipsoid: {
            const glm::dvec3 v = xform_point(e.to_local, p) - e.o;
            r2 = glm::dot(v, v);
            return r2 < e.rad2 ? r2 * (r2 * e.c[0] + e.c[1]) + e.c[2] : 0.0;
        }
        case ElementType::BaseHemisphere: {
            const glm::dvec3 q = xform_point(e.to_local, p);
            if (q.z > 0.0) return 0.0;
            r2 = glm::dot(q, q);
            break;
        }
        case ElementType::ApexHemisphere: {
            glm::dvec3 q = xform_point(e.to_local, p);
            q.z -= e.len;
            if (q.z < 0.0) return 0.0;
            r2 = glm::dot(q, q);
            break;
        }
        case ElementType::Cylinder: {
            const glm::dvec3 q = xform_point(e.to_local, p);
            if (!(q.z >= 0.0 && q.z <= e.len)) return 0.0;
            r2 = q.x * q.x + q.y * q.y;
            break;
        }
    }
    return r2 <= e.rad2 ? r2 * (r2 * e.c[0] + e.c[1]) + e.c[2] : 0.0;
}

/// POV-Ray's element_normal: adds the element's share of the (outward) field gradient.
void add_element_normal(const Element& e, const glm::dvec3& p, glm::dvec3& result) {
    if (!(e.rad2 > 0.0)) return;
    glm::dvec3 v;
    switch (e.type) {
        case ElementType::Sphere:
            v = p - e.o;
            break;
        case ElementType::Ellipsoid:
            v = xform_point(e.to_local, p) - e.o;
            break;
        case ElementType::BaseHemisphere:
            v = xform_point(e.to_local, p);
            if (v.z > 0.0) return;
            break;
        case ElementType::ApexHemisphere:
            v = xform_point(e.to_local, p);
            v.z -= e.len;
            if (v.z < 0.0) return;
            break;
        case ElementType::Cylinder:
            v = xform_point(e.to_local, p);
            if (!(v.z >= 0.0 && v.z <= e.len)) return;
            v.z = 0.0;
            break;
    }
    const double r2 = glm::dot(v, v);
    if (r2 > e.rad2) return;
    const double val = -2.0 * e.c[0] * r2 - e.c[1];
    result += val * (e.type == ElementType::Sphere ? v : e.normal_m * v);
}

/// A sphere met by P + t D (D of any length, in the sphere's space): POV-Ray's
/// intersect_sphere and intersect_ellipsoid.
bool sphere_span(const glm::dvec3& v1, const glm::dvec3& dd, double len, double rad2,
                 double mindist, double& tmin, double& tmax) {
    const double b = glm::dot(v1, dd);
    const double t = glm::dot(v1, v1);
    double d = b * b - t + rad2;
    if (d < kPovEpsilon) return false;
    d = std::sqrt(d);
    tmax = (-b + d) / len;
    if (tmax < mindist) tmax = 0.0;
    tmin = (-b - d) / len;
    if (tmin < mindist) tmin = 0.0;
    if (tmax == tmin) return false;
    if (tmax < tmin) std::swap(tmin, tmax);
    return true;
}

/// Where the ray P + t D (blob space, D unit) is within the element's reach: POV-Ray's
/// intersect_element.
bool element_span(const Element& e, const glm::dvec3& P, const glm::dvec3& D, double mindist,
                  double& tmin, double& tmax) {
    tmin = kPovBoundHuge;
    tmax = -kPovBoundHuge;
    if (e.type == ElementType::Sphere) {
        return sphere_span(P - e.o, D, 1.0, e.rad2, mindist, tmin, tmax);
    }
    glm::dvec3 pp = xform_point(e.to_local, P);
    glm::dvec3 dd = xform_dir(e.to_local, D);
    const double len = glm::length(dd);
    dd /= len;
    if (e.type == ElementType::Ellipsoid) {
        return sphere_span(pp - e.o, dd, len, e.rad2, mindist, tmin, tmax);
    }
    if (e.type == ElementType::Cylinder) {
        const double a = dd.x * dd.x + dd.y * dd.y;
        const auto take = [&](double t) {
            tmin = std::min(tmin, t);
            tmax = std::max(tmax, t);
        };
        if (a > kPovEpsilon) {
            const double b = pp.x * dd.x + pp.y * dd.y;
            const double c = pp.x * pp.x + pp.y * pp.y - e.rad2;
            double d = b * b - a * c;
            if (d > kPovEpsilon) {
                d = std::sqrt(d);
                for (const double t : {(-b + d) / a, (-b - d) / a}) {
                    const double w = pp.z + t * dd.z;
                    if (w >= 0.0 && w <= e.len) take(t);
                }
            }
        }
        if (std::abs(dd.z) > kPovEpsilon) {
            for (const double z : {0.0, e.len}) {
                const double t = (z - pp.z) / dd.z;
                const double u = pp.x + t * dd.x, v = pp.y + t * dd.y;
                if (u * u + v * v <= e.rad2) take(t);
            }
        }
        tmin /= len;
        tmax /= len;
        if (tmin < mindist) tmin = 0.0;
        if (tmax < mindist) tmax = 0.0;
        return tmin < tmax;
    }
    // The hemispheres (intersect_hemisphere): the sphere cut at the plane z = 0 (base, the
    // half z <= 0) or z = len (apex, the half beyond it).
    const bool apex = e.type == ElementType::ApexHemisphere;
    if (apex) pp.z -= e.len;
    const double b = glm::dot(pp, dd);
    const double t = glm::dot(pp, pp);
    double d = b * b - t + e.rad2;
    if (d < kPovEpsilon) return false;
    d = std::sqrt(d);
    tmax = -b + d;
    tmin = -b - d;
    if (tmax < tmin) std::swap(tmin, tmax);
    const double z1 = pp.z + tmin * dd.z;
    const double z2 = pp.z + tmax * dd.z;
    const bool in1 = apex ? z1 <= 0.0 : z1 >= 0.0;  // on the side the hemisphere leaves out
    const bool in2 = apex ? z2 <= 0.0 : z2 >= 0.0;
    if (in1 && in2) return false;
    if (!in1 && !in2) {
        tmin /= len;
        tmax /= len;
        return true;
    }
    const double tp = -pp.z / dd.z;
    if (in1) {
        tmin = tp < mindist ? 0.0 : tp;
    } else {
        tmax = tp < mindist ? 0.0 : tp;
    }
    tmin /= len;
    tmax /= len;
    return true;
}

/// The field of one element along P + t D as a quartic in t (coefficients of t^4 first):
/// the `fcoeffs` of All_Blob_Intersections.
void element_quartic(const Element& e, const glm::dvec3& P, const glm::dvec3& D, double scale,
                     double* f) {
    double t0, t1, t2;
    if (e.type == ElementType::Sphere) {
        const glm::dvec3 v = P - e.o;
        t0 = glm::dot(v, v);
        t1 = glm::dot(v, D);
        t2 = scale * scale;
    } else {
        glm::dvec3 pp = xform_point(e.to_local, P);
        const glm::dvec3 dd = xform_dir(e.to_local, D);
        if (e.type == ElementType::Cylinder) {
            t0 = pp.x * pp.x + pp.y * pp.y;
            t1 = pp.x * dd.x + pp.y * dd.y;
            t2 = dd.x * dd.x + dd.y * dd.y;
        } else {
            if (e.type == ElementType::Ellipsoid) pp -= e.o;
            if (e.type == ElementType::ApexHemisphere) pp.z -= e.len;
            t0 = glm::dot(pp, pp);
            t1 = glm::dot(pp, dd);
            t2 = glm::dot(dd, dd);
        }
    }
    const double c0 = e.c[0], c1 = e.c[1], c2 = e.c[2];
    f[0] = c0 * t2 * t2;
    f[1] = 4.0 * c0 * t1 * t2;
    f[2] = 2.0 * c0 * (2.0 * t1 * t1 + t0 * t2) + c1 * t2;
    f[3] = 2.0 * t1 * (2.0 * c0 * t0 + c1);
    f[4] = t0 * (c0 * t0 + c1) + c2;
}

struct Bound {
    double t;
    bool entering;
    int element;
};

class BlobShape final : public ComplexShape {
  public:
    BlobShape(std::vector<Element> elements, double threshold, bool sturm, const Transform& t)
        : el_(std::move(elements)), threshold_(threshold), sturm_(sturm) {
        world_to_local_ = t.inverse;
        local_to_world_ = t.matrix;
        normal_to_world_ = glm::transpose(glm::dmat3(t.inverse));
        // Compute_Blob_BBox: the bounding spheres of the components of positive strength.
        Aabb local;
        for (const Element& e : el_) {
            if (!(e.c[2] > 0.0)) continue;
            glm::dvec3 c;
            double r2 = e.rad2;
            bool transformed = true;
            switch (e.type) {
                case ElementType::Sphere:
                    c = e.o;
                    transformed = false;
                    break;
                case ElementType::Ellipsoid:
                    c = e.o;
                    break;
                case ElementType::BaseHemisphere:
                    c = glm::dvec3(0.0);
                    break;
                case ElementType::ApexHemisphere:
                    c = glm::dvec3(0.0, 0.0, e.len);
                    break;
                case ElementType::Cylinder:
                    c = glm::dvec3(0.0, 0.0, 0.5 * e.len);
                    r2 = e.rad2 + 0.25 * e.len * e.len;
                    break;
            }
            double r = std::sqrt(r2);
            if (transformed) {
                // get_element_bounding_sphere: the largest side of the box of the transformed
                // cube [0, r]^3 becomes the radius.
                c = xform_point(e.to_blob, c);
                Aabb cube;
                for (int i = 0; i < 8; ++i) {
                    cube.extend(xform_dir(e.to_blob, glm::dvec3(i & 1 ? r : 0.0, i & 2 ? r : 0.0,
                                                                 i & 4 ? r : 0.0)));
                }
                const glm::dvec3 side = cube.hi - cube.lo;
                r = std::sqrt(std::max({side.x, side.y, side.z}) *
                                  std::max({side.x, side.y, side.z}) +
                              kPovEpsilon);
            }
            local.extend(c - glm::dvec3(r));
            local.extend(c + glm::dvec3(r));
        }
        if (!local.empty()) {
            for (int i = 0; i < 8; ++i) {
                bounds_.extend(xform_point(local_to_world_, glm::dvec3(i & 1 ? local.hi.x : local.lo.x,
                                                                      i & 2 ? local.hi.y : local.lo.y,
                                                                      i & 4 ? local.hi.z : local.lo.z)));
            }
        }
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        glm::dvec3 P = xform_point(world_to_local_, origin);
        glm::dvec3 D = xform_dir(world_to_local_, direction);
        const double len = glm::length(D);
        D /= len;
        const double depth_tolerance = sink.t_min() < 0.0 ? 0.0 : kDepthTolerance;

        // determine_influences and insert_hit: entries and exits sorted by depth, an entry
        // before the first bound not below it, its exit after the entry likewise.
        std::vector<Bound> iv;
        iv.reserve(2 * el_.size());
        for (std::size_t k = 0; k < el_.size(); ++k) {
            double t0, t1;
            if (!element_span(el_[k], P, D, depth_tolerance, t0, t1)) continue;
            std::size_t at = 0;
            while (at < iv.size() && t0 > iv[at].t) ++at;
            iv.insert(iv.begin() + static_cast<std::ptrdiff_t>(at),
                      Bound{t0, true, static_cast<int>(k)});
            std::size_t out = at + 1;
            while (out < iv.size() && t1 > iv[out].t) ++out;
            iv.insert(iv.begin() + static_cast<std::ptrdiff_t>(out),
                      Bound{t1, false, static_cast<int>(k)});
        }
        if (iv.empty()) return;

        // Start at the first interval and scale the ray to the last, against loss of digits.
        double start = iv[0].t;
        if (start < kSmallTolerance) start = 0.0;
        double max_bound = 0.0;
        for (Bound& b : iv) b.t -= start;
        P += start * D;
        max_bound = iv[0].t;
        for (const Bound& b : iv) max_bound = std::max(max_bound, b.t);
        if (max_bound != 0.0) {
            D *= max_bound;
            for (Bound& b : iv) b.t /= max_bound;
        } else {
            max_bound = 1.0;
        }

        double coeffs[5] = {0.0, 0.0, 0.0, 0.0, -threshold_};
        std::vector<double> fco(5 * el_.size(), 0.0);
        int active = 0;
        for (std::size_t i = 0; i < iv.size(); ++i) {
            double* f = &fco[5 * static_cast<std::size_t>(iv[i].element)];
            if (iv[i].entering) {
                ++active;
                element_quartic(el_[static_cast<std::size_t>(iv[i].element)], P, D, max_bound,
                                f);
                for (int j = 0; j < 5; ++j) coeffs[j] += f[j];
            } else {
                for (int j = 0; j < 5; ++j) coeffs[j] -= f[j];
                if (--active == 0) continue;
            }
            if (i + 1 >= iv.size()) break;
            if (std::abs(iv[i].t - iv[i + 1].t) < kPovEpsilon) continue;
            // The quartic over [l, l + w] mapped to [0, 1] and its Bezier control values: no
            // root when they all have one sign.
            const double l = iv[i].t;
            const double w = iv[i + 1].t - l;
            const double n0 = coeffs[0] * w * w * w * w;
            const double n1 = (coeffs[1] + 4.0 * coeffs[0] * l) * w * w * w;
            const double n2 = (3.0 * l * (2.0 * coeffs[0] * l + coeffs[1]) + coeffs[2]) * w * w;
            const double n3 =
                (2.0 * l * (2.0 * l * (coeffs[0] * l + 0.75 * coeffs[1]) + coeffs[2]) + coeffs[3]) *
                w;
            const double n4 =
                l * (l * (l * (coeffs[0] * l + coeffs[1]) + coeffs[2]) + coeffs[3]) + coeffs[4];
            const double dk[5] = {n4, n4 + 0.25 * n3, n4 + 0.5 * (n3 + n2 / 3.0),
                                  n4 + 0.5 * (1.5 * n3 + n2 + 0.5 * n1), n4 + n3 + n2 + n1 + n0};
            bool all_pos = true, all_neg = true;
            for (const double v : dk) {
                if (!(v >= 0.0)) all_pos = false;
                if (!(v <= 0.0)) all_neg = false;
            }
            if (all_pos || all_neg) continue;
            double roots[4];
            const int n = solve_polynomial(4, coeffs, roots, sturm_, kSolveEpsilon);
            for (int j = 0; j < n; ++j) {
                const double r = roots[j];
                if (!(r >= iv[i].t && r <= iv[i + 1].t)) continue;
                const double dist = (r * max_bound + start) / len;
                if (dist > depth_tolerance && dist < kPovMaxDistance) sink.add(dist);
            }
        }
    }

    bool inside(const glm::dvec3& point) const override {
        return field(xform_point(world_to_local_, point)) > threshold_ - kInsideTolerance;
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit&) const override {
        const glm::dvec3 p = xform_point(world_to_local_, point);
        glm::dvec3 n(0.0);
        for (const Element& e : el_) add_element_normal(e, p, n);
        const double l2 = glm::dot(n, n);
        n = l2 == 0.0 ? glm::dvec3(1.0, 0.0, 0.0) : n / std::sqrt(l2);
        return glm::normalize(normal_to_world_ * n);
    }

    Aabb bounds() const override { return bounds_; }

    double field(const glm::dvec3& p) const {
        double sum = 0.0;
        for (const Element& e : el_) sum += element_field(e, p);
        return sum;
    }

  private:
    std::vector<Element> el_;
    double threshold_;
    bool sturm_;
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
    Aabb bounds_;
};

}  // namespace

double blob_field(const Blob& blob, const glm::dvec3& point) {
    double sum = 0.0;
    for (const Element& e : make_elements(blob)) sum += element_field(e, point);
    return sum;
}

std::vector<double> blob_component_fields(const Blob& blob, const glm::dvec3& point) {
    std::vector<double> out(blob.components.size(), 0.0);
    for (const Element& e : make_elements(blob)) {
        out[static_cast<std::size_t>(e.component)] += element_field(e, point);
    }
    return out;
}

Result<std::shared_ptr<const ComplexShape>> prepare_blob(const Blob& blob, const Primitive& p) {
    if (blob.components.empty()) {
        return make_error(primitive_place(p) + "a blob needs at least one component");
    }
    for (const BlobComponent& c : blob.components) {
        if (c.cylinder && glm::length(c.end - c.centre) < kPovEpsilon) {
            return make_error(primitive_place(p) + "degenerate cylindrical component in blob");
        }
    }
    return std::shared_ptr<const ComplexShape>(
        std::make_shared<BlobShape>(make_elements(blob), blob.threshold, blob.sturm, p.transform));
}

}  // namespace mirage
