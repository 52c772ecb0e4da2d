// Prisms after POV-Ray 3.7's prism.cpp: the profile's spline segments (linear, quadratic,
// cubic, Bezier) swept along y, linearly or conically, with caps; roots by POV-Ray's solver,
// the inside test by counting crossings of the profile, normals from the segment's tangent.
#include "shapes/prism.h"

#include <algorithm>
#include <cmath>

#include "shapes/polysolve.h"

namespace mirage {
namespace {

constexpr double kDepthTolerance = 1.0e-4;  // prism.cpp
constexpr int kBaseHit = 1, kCapHit = 2, kSplineHit = 3;

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

struct Segment {
    glm::dvec2 A, B, C, D;          // x(w) = ((A w + B) w + C) w + D; the profile's x and z
    double v1 = 0, v2 = 0, u2 = 0;  // the segment's rectangle for in_curve
};

class PrismShape final : public ComplexShape {
  public:
    PrismShape(const Prism& prism, const Transform& t, std::vector<Segment> segments, double x1,
               double x2, double y1, double y2, bool degenerate)
        : spline_(prism.spline),
          conic_(prism.conic),
          h1_(prism.height1),
          h2_(prism.height2),
          closed_(!prism.open),
          sturm_(prism.sturm),
          degenerate_(degenerate),
          segments_(std::move(segments)),
          u1_(x1),
          u2_(x2),
          v1_(y1),
          v2_(y2) {
        world_to_local_ = t.inverse;
        local_to_world_ = t.matrix;
        normal_to_world_ = glm::transpose(glm::dmat3(t.inverse));
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        if (degenerate_) return;
        const glm::dvec3 P = transform_point(world_to_local_, origin);
        glm::dvec3 D = glm::dmat3(world_to_local_) * direction;
        const double len = glm::length(D);
        D /= len;
        const double lo = sink.t_min() < 0.0 ? sink.t_min() : kDepthTolerance;
        const double klo = sink.t_min() < 0.0 ? sink.t_min() * len : kDepthTolerance;
        const auto add = [&](double k, int part, int index, double w) {
            const double distance = k / len;
            if (distance > lo && distance < kPovMaxDistance) {
                sink.add(distance, part, index, glm::dvec2(w, 0.0));
            }
        };
        if (std::abs(D.y) < kPovEpsilon) {
            if (P.y < h1_ || P.y > h2_) return;
        } else if (closed_) {
            for (const auto& [h, part] : {std::pair{h2_, kCapHit}, std::pair{h1_, kBaseHit}}) {
                if (conic_ && !(std::abs(h) > kPovEpsilon)) continue;
                const double k = (h - P.y) / D.y;
                if (!(k > klo && k < kPovMaxDistance)) continue;
                double u = P.x + k * D.x, v = P.z + k * D.z;
                if (conic_) {
                    u /= h;
                    v /= h;
                }
                if (in_curve(u, v)) add(k, part, 0, 0.0);
            }
        }
        if (!(std::abs(D.x) > kPovEpsilon || std::abs(D.z) > kPovEpsilon)) return;
        const double k1 = P.z * D.y - P.y * D.z;
        const double k2 = P.y * D.x - P.x * D.y;
        const double k3 = P.x * D.z - P.z * D.x;
        for (std::size_t j = 0; j < segments_.size(); ++j) {
            const Segment& e = segments_[j];
            double x[4], y[3];
            int n = 0;
            if (!conic_) {
                const auto row = [&](const glm::dvec2& c) { return c.x * D.z - c.y * D.x; };
                const double last = D.z * (e.D.x - P.x) - D.x * (e.D.y - P.z);
                switch (spline_) {
                    case SplineKind::Linear:
                        x[0] = row(e.C);
                        x[1] = last;
                        if (std::abs(x[0]) > kPovEpsilon) y[n++] = -x[1] / x[0];
                        break;
                    case SplineKind::Quadratic:
                        x[0] = row(e.B);
                        x[1] = row(e.C);
                        x[2] = last;
                        n = solve_polynomial(2, x, y, false, 0.0);
                        break;
                    default:
                        x[0] = row(e.A);
                        x[1] = row(e.B);
                        x[2] = row(e.C);
                        x[3] = last;
                        n = solve_polynomial(3, x, y, sturm_, 0.0);
                        break;
                }
            } else {
                const auto row = [&](const glm::dvec2& c) { return c.x * k1 + c.y * k2; };
                switch (spline_) {
                    case SplineKind::Linear:
                        x[0] = row(e.C);
                        x[1] = row(e.D) + k3;
                        if (std::abs(x[0]) > kPovEpsilon) y[n++] = -x[1] / x[0];
                        break;
                    case SplineKind::Quadratic:
                        x[0] = row(e.B);
                        x[1] = row(e.C);
                        x[2] = row(e.D) + k3;
                        n = solve_polynomial(2, x, y, false, 0.0);
                        break;
                    default:
                        x[0] = row(e.A);
                        x[1] = row(e.B);
                        x[2] = row(e.C);
                        x[3] = row(e.D) + k3;
                        n = solve_polynomial(3, x, y, sturm_, 0.0);
                        break;
                }
            }
            while (n--) {
                const double w = y[n];
                if (!(w >= 0.0 && w <= 1.0)) continue;
                double k;
                if (!conic_) {
                    if (std::abs(D.x) > kPovEpsilon) {
                        k = (w * (w * (w * e.A.x + e.B.x) + e.C.x) + e.D.x - P.x) / D.x;
                    } else {
                        k = (w * (w * (w * e.A.y + e.B.y) + e.C.y) + e.D.y - P.z) / D.z;
                    }
                } else {
                    k = w * (w * (w * e.A.x + e.B.x) + e.C.x) + e.D.x;
                    double h = D.x - k * D.y;
                    if (std::abs(h) > kPovEpsilon) {
                        k = (k * P.y - P.x) / h;
                    } else {
                        k = w * (w * (w * e.A.y + e.B.y) + e.C.y) + e.D.y;
                        h = D.z - k * D.y;
                        if (!(std::abs(h) > kPovEpsilon)) continue;
                        k = (k * P.y - P.z) / h;
                    }
                }
                const double height = P.y + k * D.y;
                if (height >= h1_ && height <= h2_) add(k, kSplineHit, static_cast<int>(j), w);
            }
        }
    }

    bool inside(const glm::dvec3& point) const override {
        if (degenerate_) return false;
        glm::dvec3 p = transform_point(world_to_local_, point);
        if (!(p.y >= h1_ && p.y < h2_)) return false;
        if (conic_) {
            if (std::abs(p.y) > kPovEpsilon) {
                p.x /= p.y;
                p.z /= p.y;
            } else {
                return false;  // POV-Ray moves the point to infinity
            }
        }
        return in_curve(p.x, p.z);
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit& hit) const override {
        glm::dvec3 n(0.0, 1.0, 0.0);
        if (hit.part == kSplineHit) {
            const Segment& e = segments_[static_cast<std::size_t>(hit.index)];
            const double w = hit.uv.x;
            const double nx = w * (3.0 * e.A.y * w + 2.0 * e.B.y) + e.C.y;
            const double nz = -(w * (3.0 * e.A.x * w + 2.0 * e.B.x) + e.C.x);
            if (!conic_) {
                n = glm::dvec3(nx, 0.0, nz);
            } else {
                const glm::dvec3 p = transform_point(world_to_local_, point);
                if (std::abs(p.y) > kPovEpsilon)
                    n = glm::dvec3(nx, -(p.x * nx + p.z * nz) / p.y, nz);
            }
        }
        return glm::normalize(normal_to_world_ * n);
    }

    Aabb bounds() const override {
        Aabb box;
        if (degenerate_) return box;
        for (int i = 0; i < 8; ++i) {
            box.extend(transform_point(
                local_to_world_,
                glm::dvec3(i & 1 ? x2_ : x1_, i & 2 ? h2_ : h1_, i & 4 ? y2_ : y1_)));
        }
        return box;
    }

    double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;  // the bounding rectangle in x and z

  private:
    // POV-Ray's in_curve: crossings of the profile to the right of (u, v).
    bool in_curve(double u, double v) const {
        int nc = 0;
        if (!(u >= u1_ && u <= u2_ && v >= v1_ && v <= v2_)) return false;
        for (const Segment& e : segments_) {
            if (!(v >= e.v1 && v <= e.v2 && u <= e.u2)) continue;
            const double x[4] = {e.A.y, e.B.y, e.C.y, e.D.y - v};
            double y[3];
            int n = solve_polynomial(3, x, y, sturm_, 0.0);
            while (n--) {
                const double w = y[n];
                if (w >= 0.0 && w <= 1.0) {
                    const double k = w * (w * (w * e.A.x + e.B.x) + e.C.x) + e.D.x - u;
                    if (k >= 0.0) ++nc;
                }
            }
        }
        return (nc & 1) != 0;
    }

    SplineKind spline_;
    bool conic_;
    double h1_, h2_;
    bool closed_, sturm_, degenerate_;
    std::vector<Segment> segments_;
    double u1_, u2_, v1_, v2_;
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
};

// Whether POV-Ray's Parse_Prism finds the profile closed; `first` ends as the first point of
// the last sub-loop (not for Bezier splines).
bool profile_closed(const std::vector<glm::dvec2>& P, SplineKind kind, glm::dvec2& first) {
    const int number = static_cast<int>(P.size());
    bool closed = false;
    if (kind != SplineKind::Bezier) {
        int i = kind == SplineKind::Linear ? 1 : 2;
        first = kind == SplineKind::Linear ? P[0] : P[1];
        for (; i < number; ++i) {
            closed = false;
            if (std::abs(first.x - P[i].x) < kPovEpsilon &&
                std::abs(first.y - P[i].y) < kPovEpsilon) {
                i += kind == SplineKind::Linear ? 1 : kind == SplineKind::Quadratic ? 2 : 3;
                if (i < number) first = P[i];
                closed = true;
            }
        }
        return closed;
    }
    int loop_start = 0;
    for (int i = 4; i < number; i += 4) {
        if (std::abs(P[i].x - P[i - 1].x) > kPovEpsilon ||
            std::abs(P[i].y - P[i - 1].y) > kPovEpsilon) {
            if (std::abs(P[i - 1].x - P[loop_start].x) > kPovEpsilon ||
                std::abs(P[i - 1].y - P[loop_start].y) > kPovEpsilon)
                return false;
            loop_start = i;
        }
    }
    return !(std::abs(P[number - 1].x - P[loop_start].x) > kPovEpsilon ||
             std::abs(P[number - 1].y - P[loop_start].y) > kPovEpsilon);
}

// Compute_Prism's segment from point i: its coefficients and the corners of its rectangle
// (x, y), the extremes of a quadratic or cubic segment among them; false when the points run
// out.
bool spline_segment(const std::vector<glm::dvec2>& P, SplineKind kind, int i, Segment& e,
                    double x[4], double y[4]) {
    const int number = static_cast<int>(P.size());
    const int i1 = i + 1, i2 = i + 2, i3 = i + 3;
    switch (kind) {
        case SplineKind::Linear:
            if (i1 >= number) return false;
            e.A = glm::dvec2(0.0);
            e.B = glm::dvec2(0.0);
            e.C = -1.0 * P[i] + 1.0 * P[i1];
            e.D = 1.0 * P[i];
            x[0] = x[2] = P[i].x;
            x[1] = x[3] = P[i1].x;
            y[0] = y[2] = P[i].y;
            y[1] = y[3] = P[i1].y;
            return true;
        case SplineKind::Quadratic:
            if (i2 >= number) return false;
            e.A = glm::dvec2(0.0);
            e.B = 0.5 * P[i] - 1.0 * P[i1] + 0.5 * P[i2];
            e.C = -0.5 * P[i] + 0.5 * P[i2];
            e.D = 1.0 * P[i1];
            break;
        case SplineKind::Cubic:
            if (i3 >= number) return false;
            e.A = -0.5 * P[i] + 1.5 * P[i1] - 1.5 * P[i2] + 0.5 * P[i3];
            e.B = P[i] - 2.5 * P[i1] + 2.0 * P[i2] - 0.5 * P[i3];
            e.C = -0.5 * P[i] + 0.5 * P[i2];
            e.D = P[i1];
            break;
        case SplineKind::Bezier:
            if (i3 >= number) return false;
            e.A = P[i] - 3.0 * P[i1] + 3.0 * P[i2] - P[i3];
            e.B = 3.0 * P[i1] - 6.0 * P[i2] + 3.0 * P[i3];
            e.C = 3.0 * P[i2] - 3.0 * P[i3];
            e.D = P[i3];
            for (int k = 0; k < 4; ++k) {
                x[k] = P[i + k].x;
                y[k] = P[i + k].y;
            }
            return true;
    }
    // Quadratic and cubic: from point i1 to i2, and the segment's extremes join its rectangle.
    x[0] = x[2] = P[i1].x;
    x[1] = x[3] = P[i2].x;
    y[0] = y[2] = P[i1].y;
    y[1] = y[3] = P[i2].y;
    for (int axis = 0; axis < 2; ++axis) {
        const double c[3] = {3.0 * e.A[axis], 2.0 * e.B[axis], e.C[axis]};
        double r[2];
        int n = solve_polynomial(2, c, r, false, 0.0);
        double* out = axis == 0 ? x : y;
        while (n--) {
            if (r[n] >= 0.0 && r[n] <= 1.0)
                out[n] = r[n] * (r[n] * (r[n] * e.A[axis] + e.B[axis]) + e.C[axis]) + e.D[axis];
        }
    }
    return true;
}

// Compute_Prism's step past a segment ending on the sub-loop's first point (and Bezier
// segments' own points): the index the loop's ++i goes on from, and the next loop's first.
int step_past_segment(const std::vector<glm::dvec2>& P, SplineKind kind, int i,
                      glm::dvec2& first) {
    const int number = static_cast<int>(P.size());
    const int i1 = i + 1, i2 = i + 2;
    auto at_first = [&](const glm::dvec2& q) {
        return std::abs(q.x - first.x) < kPovEpsilon && std::abs(q.y - first.y) < kPovEpsilon;
    };
    switch (kind) {
        case SplineKind::Linear:
            if (at_first(P[i1])) {
                ++i;
                if (i + 1 < number) first = P[i + 1];
            }
            break;
        case SplineKind::Quadratic:
            if (at_first(P[i2])) {
                i += 2;
                if (i + 2 < number) first = P[i + 2];
            }
            break;
        case SplineKind::Cubic:
            if (at_first(P[i2])) {
                i += 3;
                if (i + 2 < number) first = P[i + 2];
            }
            break;
        case SplineKind::Bezier:
            i += 3;
            break;
    }
    return i;
}

}  // namespace

Result<std::shared_ptr<const ComplexShape>> prepare_prism(const Prism& prism, const Primitive& p) {
    // POV-Ray's Parse_Prism (closing) and Compute_Prism (segments and rectangles).
    std::vector<glm::dvec2> P = prism.points;
    const SplineKind kind = prism.spline;
    const int minimum = kind == SplineKind::Linear      ? 3
                        : kind == SplineKind::Quadratic ? 5
                        : kind == SplineKind::Cubic     ? 6
                                                        : 4;
    const int given = static_cast<int>(P.size());
    if (given < minimum || (kind == SplineKind::Bezier && (given & 3) != 0)) {
        return make_error(primitive_place(p) + "prism: too few points for its spline (" +
                          std::to_string(given) + ")");
    }
    bool degenerate = false;
    glm::dvec2 first(0.0);
    if (!profile_closed(P, kind, first)) {
        if (kind == SplineKind::Linear) {
            P.push_back(first);  // POV-Ray closes an open linear prism
        } else {
            degenerate = true;  // and ignores another
        }
    }
    const int number = static_cast<int>(P.size());
    std::vector<Segment> segments;
    double xmin = kPovBoundHuge, xmax = -kPovBoundHuge, ymin = kPovBoundHuge, ymax = -kPovBoundHuge;
    first = kind == SplineKind::Linear ? P[0] : P[std::min(1, number - 1)];
    for (int i = 0; i < number - 1; ++i) {
        Segment e;
        double x[4], y[4];
        if (!spline_segment(P, kind, i, e, x, y))
            return make_error(primitive_place(p) + "prism: too few points");
        const double sx1 = std::min(std::min(x[0], x[1]), std::min(x[2], x[3]));
        const double sx2 = std::max(std::max(x[0], x[1]), std::max(x[2], x[3]));
        const double sy1 = std::min(std::min(y[0], y[1]), std::min(y[2], y[3]));
        const double sy2 = std::max(std::max(y[0], y[1]), std::max(y[2], y[3]));
        e.u2 = sx2;
        e.v1 = sy1;
        e.v2 = sy2;
        xmin = std::min(xmin, sx1);
        xmax = std::max(xmax, sx2);
        ymin = std::min(ymin, sy1);
        ymax = std::max(ymax, sy2);
        segments.push_back(e);
        i = step_past_segment(P, kind, i, first);
    }
    auto shape = std::make_shared<PrismShape>(prism, p.transform, std::move(segments), xmin, xmax,
                                              ymin, ymax, degenerate);
    // The bounding box: the profile's rectangle, scaled by the heights for a conic sweep.
    double bx1 = xmin, bx2 = xmax, by1 = ymin, by2 = ymax;
    if (prism.conic) {
        const double h1 = prism.height1, h2 = prism.height2;
        bx1 = std::min({xmin * h1, xmin * h2, xmax * h1, xmax * h2});
        bx2 = std::max({xmin * h1, xmin * h2, xmax * h1, xmax * h2});
        by1 = std::min({ymin * h1, ymin * h2, ymax * h1, ymax * h2});
        by2 = std::max({ymin * h1, ymin * h2, ymax * h1, ymax * h2});
    }
    shape->x1_ = bx1;
    shape->x2_ = bx2;
    shape->y1_ = by1;
    shape->y2_ = by2;
    return std::shared_ptr<const ComplexShape>(std::move(shape));
}

}  // namespace mirage
