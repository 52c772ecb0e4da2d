// Lathes and surfaces of revolution after POV-Ray 3.7's lathe.cpp and sor.cpp: a spline
// profile (radius against height) turned about the y axis; the ray's polynomial in the spline
// parameter (lathe: order 2, 4 or 6) or in the ray distance (sor: a cubic in r^2(y)) solved by
// POV-Ray's solver; inside tests and normals as POV-Ray computes them.
#include "shapes/lathe_sor.h"

#include <algorithm>
#include <cmath>

#include "shapes/polysolve.h"

namespace mirage {
namespace {

constexpr double kDepthTolerance = 1.0e-4;  // lathe.cpp, sor.cpp
constexpr int kCurve = 0, kBasePlane = 1, kCapPlane = 2;

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

Aabb turned_bounds(double radius, double h1, double h2, const glm::dmat4& to_world) {
    Aabb box;
    for (int i = 0; i < 8; ++i) {
        box.extend(transform_point(to_world, glm::dvec3(i & 1 ? radius : -radius, i & 2 ? h2 : h1,
                                                        i & 4 ? radius : -radius)));
    }
    return box;
}

struct LatheSegment {
    glm::dvec2 A, B, C, D;  // x: radius, y: height
    double h1 = 0, h2 = 0;
};

class LatheShape final : public ComplexShape {
  public:
    LatheShape(std::vector<LatheSegment> s, SplineKind kind, bool sturm, double r1, double r2,
               double h1, double h2, const Transform& t)
        : seg_(std::move(s)),
          kind_(kind),
          sturm_(sturm),
          radius1_(r1),
          radius2_(r2),
          height1_(h1),
          height2_(h2) {
        world_to_local_ = t.inverse;
        local_to_world_ = t.matrix;
        normal_to_world_ = glm::transpose(glm::dmat3(t.inverse));
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        const glm::dvec3 P = transform_point(world_to_local_, origin);
        glm::dvec3 D = glm::dmat3(world_to_local_) * direction;
        const double len = glm::length(D);
        D /= len;
        const double dylen = D.y * len;
        double r0 = std::abs(P.x * D.z - P.z * D.x);
        const double r = D.x * D.x + D.z * D.z;
        if (r > 0.0) r0 /= std::sqrt(r);
        if (r0 > radius2_) return;
        const double m = D.x * P.x + D.z * P.z;
        const double dy2 = D.y * D.y;
        const double lo = sink.t_min() < 0.0 ? sink.t_min() : kDepthTolerance;
        const auto hit = [&](double d, double w, int n) {
            if (d > lo && d < kPovMaxDistance) sink.add(d, kCurve, n, glm::dvec2(w, 0.0));
        };
        for (std::size_t j = 0; j < seg_.size(); ++j) {
            const LatheSegment& e = seg_[j];
            double x1[7], y1[6];
            int n1 = 0;
            const double dyp = e.D.y - P.y;
            const double c_last =
                dyp * (dyp * r + 2.0 * D.y * m) + dy2 * (P.x * P.x + P.z * P.z - e.D.x * e.D.x);
            const double c_lin = 2.0 * (e.C.y * (dyp * r + D.y * m) - e.C.x * e.D.x * dy2);
            switch (kind_) {
                case SplineKind::Linear:
                    x1[0] = e.C.y * e.C.y * r - e.C.x * e.C.x * dy2;
                    x1[1] = c_lin;
                    x1[2] = c_last;
                    n1 = solve_polynomial(2, x1, y1, false, 0.0);
                    break;
                case SplineKind::Quadratic:
                    x1[0] = e.B.y * e.B.y * r - e.B.x * e.B.x * dy2;
                    x1[1] = 2.0 * (e.B.y * e.C.y * r - e.B.x * e.C.x * dy2);
                    x1[2] = r * (2.0 * e.B.y * dyp + e.C.y * e.C.y) + 2.0 * e.B.y * D.y * m -
                            (2.0 * e.B.x * e.D.x + e.C.x * e.C.x) * dy2;
                    x1[3] = c_lin;
                    x1[4] = c_last;
                    n1 = solve_polynomial(4, x1, y1, sturm_, 0.0);
                    break;
                default:
                    x1[0] = e.A.y * e.A.y * r - e.A.x * e.A.x * dy2;
                    x1[1] = 2.0 * (e.A.y * e.B.y * r - e.A.x * e.B.x * dy2);
                    x1[2] = (2.0 * e.A.y * e.C.y + e.B.y * e.B.y) * r -
                            (2.0 * e.A.x * e.C.x + e.B.x * e.B.x) * dy2;
                    x1[3] = 2.0 * ((e.A.y * e.D.y + e.B.y * e.C.y - e.A.y * P.y) * r +
                                   e.A.y * D.y * m - (e.A.x * e.D.x + e.B.x * e.C.x) * dy2);
                    x1[4] = (2.0 * e.B.y * dyp + e.C.y * e.C.y) * r + 2.0 * e.B.y * D.y * m -
                            (2.0 * e.B.x * e.D.x + e.C.x * e.C.x) * dy2;
                    x1[5] = c_lin;
                    x1[6] = c_last;
                    n1 = solve_polynomial(6, x1, y1, sturm_, 0.0);
                    break;
            }
            while (n1--) {
                const double w = y1[n1];
                if (!(w >= 0.0 && w <= 1.0)) continue;
                if (std::abs(D.y) > kPovEpsilon) {
                    const double k = w * (w * (w * e.A.y + e.B.y) + e.C.y) + e.D.y - P.y;
                    hit(k / dylen, w, static_cast<int>(j));
                } else {
                    const double k = w * (w * (w * e.A.x + e.B.x) + e.C.x) + e.D.x;
                    const double x2[3] = {r, 2.0 * m, P.x * P.x + P.z * P.z - k * k};
                    double y2[2];
                    int n2 = solve_polynomial(2, x2, y2, false, 0.0);
                    while (n2--) hit(y2[n2] / len, w, static_cast<int>(j));
                }
            }
        }
    }

    bool inside(const glm::dvec3& point) const override {
        const glm::dvec3 P = transform_point(world_to_local_, point);
        int nc = 0;
        if (P.y >= height1_ && P.y <= height2_) {
            const double r = std::sqrt(P.x * P.x + P.z * P.z);
            if (r >= radius1_ && r <= radius2_) {
                for (const LatheSegment& e : seg_) {
                    if (!(P.y >= e.h1 - kPovEpsilon && P.y <= e.h2 + kPovEpsilon)) continue;
                    const double x[4] = {e.A.y, e.B.y, e.C.y, e.D.y - P.y};
                    double y[3];
                    int n = solve_polynomial(3, x, y, sturm_, 0.0);
                    while (n--) {
                        const double w = y[n];
                        if (w >= 0.0 && w <= 1.0) {
                            const double k = w * (w * (w * e.A.x + e.B.x) + e.C.x) + e.D.x - r;
                            if (k >= 0.0) ++nc;
                        }
                    }
                }
            }
        }
        return (nc & 1) != 0;
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit& hit) const override {
        const LatheSegment& e = seg_[static_cast<std::size_t>(hit.index)];
        const glm::dvec3 P = transform_point(world_to_local_, point);
        double r = P.x * P.x + P.z * P.z;
        glm::dvec3 n(0.0, 1.0, 0.0);
        if (r > kPovEpsilon) {
            r = std::sqrt(r);
            const double w = hit.uv.x;
            const double dx = w * (3.0 * e.A.x * w + 2.0 * e.B.x) + e.C.x;
            const double dy = w * (3.0 * e.A.y * w + 2.0 * e.B.y) + e.C.y;
            n = glm::dvec3(dy * P.x, -dx * r, dy * P.z);
        }
        return glm::normalize(normal_to_world_ * n);
    }

    Aabb bounds() const override {
        return turned_bounds(radius2_, height1_, height2_, local_to_world_);
    }

  private:
    std::vector<LatheSegment> seg_;
    SplineKind kind_;
    bool sturm_;
    double radius1_, radius2_, height1_, height2_;
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
};

struct SorSegment {
    double A, B, C, D;  // r^2(y) = ((A y + B) y + C) y + D
    double h1, h2;
};

class SorShape final : public ComplexShape {
  public:
    SorShape(std::vector<SorSegment> s, bool closed, bool sturm, double r2, double h1, double h2,
             double base_sq, double cap_sq, const Transform& t)
        : seg_(std::move(s)),
          closed_(closed),
          sturm_(sturm),
          radius2_(r2),
          height1_(h1),
          height2_(h2),
          base_sq_(base_sq),
          cap_sq_(cap_sq) {
        world_to_local_ = t.inverse;
        local_to_world_ = t.matrix;
        normal_to_world_ = glm::transpose(glm::dmat3(t.inverse));
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        const glm::dvec3 P = transform_point(world_to_local_, origin);
        glm::dvec3 D = glm::dmat3(world_to_local_) * direction;
        const double len = glm::length(D);
        D /= len;
        double r0 = P.x * D.z - P.z * D.x;  // POV-Ray's test, without the absolute value
        const double a = D.x * D.x + D.z * D.z;
        if (a > 0.0) r0 /= std::sqrt(a);
        if (r0 > radius2_) return;
        const double lo = sink.t_min() < 0.0 ? sink.t_min() : kDepthTolerance;
        const auto hit = [&](double d, int part, int n) {
            if (d > lo && d < kPovMaxDistance) sink.add(d, part, n);
        };
        if (closed_ && std::abs(D.y) > kPovEpsilon) {
            if (base_sq_ > kDepthTolerance) {
                const double k = (height1_ - P.y) / D.y;
                const double u = P.x + k * D.x, v = P.z + k * D.z;
                if (u * u + v * v <= base_sq_) hit(k / len, kBasePlane, 0);
            }
            if (cap_sq_ > kDepthTolerance) {
                const double k = (height2_ - P.y) / D.y;
                const double u = P.x + k * D.x, v = P.z + k * D.z;
                if (u * u + v * v <= cap_sq_) hit(k / len, kCapPlane, 0);
            }
        }
        for (std::size_t j = 0; j < seg_.size(); ++j) {
            const SorSegment& e = seg_[j];
            const double x[4] = {
                e.A * D.y * D.y * D.y, D.y * D.y * (3.0 * e.A * P.y + e.B) - a,
                D.y * (P.y * (3.0 * e.A * P.y + 2.0 * e.B) + e.C) - 2.0 * (P.x * D.x + P.z * D.z),
                P.y * (P.y * (e.A * P.y + e.B) + e.C) + e.D - P.x * P.x - P.z * P.z};
            double y[3];
            int n = solve_polynomial(3, x, y, sturm_, 0.0);
            while (n--) {
                const double k = y[n];
                const double h = P.y + k * D.y;
                if (h >= e.h1 && h <= e.h2) hit(k / len, kCurve, static_cast<int>(j));
            }
        }
    }

    bool inside(const glm::dvec3& point) const override {
        const glm::dvec3 P = transform_point(world_to_local_, point);
        if (!(P.y >= height1_ && P.y <= height2_)) return false;
        const double r0 = P.x * P.x + P.z * P.z;
        if (!(r0 <= radius2_ * radius2_)) return false;
        for (const SorSegment& e : seg_) {
            if (P.y >= e.h1 && P.y <= e.h2) {
                const double r = P.y * (P.y * (P.y * e.A + e.B) + e.C) + e.D;
                return r0 <= r;
            }
        }
        return false;
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit& hit) const override {
        glm::dvec3 n(0.0, hit.part == kBasePlane ? -1.0 : 1.0, 0.0);
        if (hit.part == kCurve) {
            const SorSegment& e = seg_[static_cast<std::size_t>(hit.index)];
            const glm::dvec3 P = transform_point(world_to_local_, point);
            const double k = 0.5 * (P.y * (3.0 * e.A * P.y + 2.0 * e.B) + e.C);
            n = glm::dvec3(P.x, -k, P.z);
        }
        return glm::normalize(normal_to_world_ * n);
    }

    Aabb bounds() const override {
        return turned_bounds(radius2_, height1_, height2_, local_to_world_);
    }

  private:
    std::vector<SorSegment> seg_;
    bool closed_, sturm_;
    double radius2_, height1_, height2_, base_sq_, cap_sq_;
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
};

// The segment's rectangle: its end points and, for quadratic and cubic splines, its extremes.
void segment_extremes(SplineKind kind, const glm::dvec2& A, const glm::dvec2& B,
                      const glm::dvec2& C, const glm::dvec2& D, double* x, double* y) {
    if (kind != SplineKind::Quadratic && kind != SplineKind::Cubic) return;
    for (int axis = 0; axis < 2; ++axis) {
        const double c[3] = {3.0 * A[axis], 2.0 * B[axis], C[axis]};
        double r[2];
        int n = solve_polynomial(2, c, r, false, 0.0);
        double* out = axis == 0 ? x : y;
        while (n--) {
            if (r[n] >= 0.0 && r[n] <= 1.0) {
                out[n] = r[n] * (r[n] * (r[n] * A[axis] + B[axis]) + C[axis]) + D[axis];
            }
        }
    }
}

}  // namespace

Result<std::shared_ptr<const ComplexShape>> prepare_lathe(const Lathe& lathe, const Primitive& p) {
    const std::vector<glm::dvec2>& P = lathe.points;
    const int number = static_cast<int>(P.size());
    const SplineKind kind = lathe.spline;
    int segments = 0;
    switch (kind) {
        case SplineKind::Linear:
            segments = number - 1;
            break;
        case SplineKind::Quadratic:
            segments = number - 2;
            break;
        case SplineKind::Cubic:
            segments = number - 3;
            break;
        case SplineKind::Bezier:
            segments = number / 4;
            break;
    }
    if (segments < 1) return make_error(primitive_place(p) + "lathe: too few points");
    std::vector<LatheSegment> seg;
    double xmin = kPovBoundHuge, xmax = -kPovBoundHuge, ymin = kPovBoundHuge, ymax = -kPovBoundHuge;
    for (int i = 0, s = 0; s < segments; ++s) {
        const int i1 = i + 1, i2 = i + 2, i3 = i + 3;
        LatheSegment e;
        double x[4], y[4];
        switch (kind) {
            case SplineKind::Linear:
                e.A = glm::dvec2(0.0);
                e.B = glm::dvec2(0.0);
                e.C = -1.0 * P[i] + 1.0 * P[i1];
                e.D = 1.0 * P[i];
                x[0] = x[2] = P[i].x;
                x[1] = x[3] = P[i1].x;
                y[0] = y[2] = P[i].y;
                y[1] = y[3] = P[i1].y;
                break;
            case SplineKind::Quadratic:
                e.A = glm::dvec2(0.0);
                e.B = 0.5 * P[i] - 1.0 * P[i1] + 0.5 * P[i2];
                e.C = -0.5 * P[i] + 0.5 * P[i2];
                e.D = 1.0 * P[i1];
                x[0] = x[2] = P[i1].x;
                x[1] = x[3] = P[i2].x;
                y[0] = y[2] = P[i1].y;
                y[1] = y[3] = P[i2].y;
                break;
            case SplineKind::Cubic:
                e.A = -0.5 * P[i] + 1.5 * P[i1] - 1.5 * P[i2] + 0.5 * P[i3];
                e.B = P[i] - 2.5 * P[i1] + 2.0 * P[i2] - 0.5 * P[i3];
                e.C = -0.5 * P[i] + 0.5 * P[i2];
                e.D = P[i1];
                x[0] = x[2] = P[i1].x;
                x[1] = x[3] = P[i2].x;
                y[0] = y[2] = P[i1].y;
                y[1] = y[3] = P[i2].y;
                break;
            case SplineKind::Bezier:
                e.A = P[i3] - 3.0 * P[i2] + 3.0 * P[i1] - P[i];
                e.B = 3.0 * P[i2] - 6.0 * P[i1] + 3.0 * P[i];
                e.C = 3.0 * P[i1] - 3.0 * P[i];
                e.D = P[i];
                x[0] = P[i].x;
                x[1] = P[i1].x;
                x[2] = P[i2].x;
                x[3] = P[i3].x;
                y[0] = P[i].y;
                y[1] = P[i1].y;
                y[2] = P[i2].y;
                y[3] = P[i3].y;
                break;
        }
        segment_extremes(kind, e.A, e.B, e.C, e.D, x, y);
        const double r1 = std::min(std::min(x[0], x[1]), std::min(x[2], x[3]));
        const double r2 = std::max(std::max(x[0], x[1]), std::max(x[2], x[3]));
        e.h1 = std::min(std::min(y[0], y[1]), std::min(y[2], y[3]));
        e.h2 = std::max(std::max(y[0], y[1]), std::max(y[2], y[3]));
        xmin = std::min(xmin, r1);
        xmax = std::max(xmax, r2);
        ymin = std::min(ymin, e.h1);
        ymax = std::max(ymax, e.h2);
        seg.push_back(e);
        i += kind == SplineKind::Bezier ? 4 : 1;
    }
    return std::shared_ptr<const ComplexShape>(std::make_shared<LatheShape>(
        std::move(seg), kind, lathe.sturm, xmin, xmax, ymin, ymax, p.transform));
}

Result<std::shared_ptr<const ComplexShape>> prepare_sor(const Sor& sor, const Primitive& p) {
    const std::vector<glm::dvec2>& P = sor.points;
    const int number = static_cast<int>(P.size()) - 3;
    if (number < 1) return make_error(primitive_place(p) + "sor: at least four points");
    std::vector<SorSegment> seg;
    double xmin = kPovBoundHuge, xmax = -kPovBoundHuge, ymin = kPovBoundHuge, ymax = -kPovBoundHuge;
    for (int i = 0; i < number; ++i) {
        if (std::abs(P[i + 2].y - P[i].y) < kPovEpsilon ||
            std::abs(P[i + 3].y - P[i + 1].y) < kPovEpsilon) {
            return make_error(primitive_place(p) + "sor: incorrect point " + std::to_string(i + 1) +
                              " (heights must increase)");
        }
        double k[4];
        k[0] = P[i + 1].x * P[i + 1].x;
        k[1] = P[i + 2].x * P[i + 2].x;
        k[2] = (P[i + 2].x - P[i].x) / (P[i + 2].y - P[i].y) * 2.0 * P[i + 1].x;
        k[3] = (P[i + 3].x - P[i + 1].x) / (P[i + 3].y - P[i + 1].y) * 2.0 * P[i + 2].x;
        // The cubic through (y1, r1^2) and (y2, r2^2) with the slopes k[2], k[3]: POV-Ray's
        // matrix (rows: value at y1, value at y2, slope at y1, slope at y2), inverted.
        const double w1 = P[i + 1].y, w2 = P[i + 2].y;
        glm::dmat4 m;  // m[col][row]
        const double rows[4][4] = {{w1 * w1 * w1, w1 * w1, w1, 1.0},
                                   {w2 * w2 * w2, w2 * w2, w2, 1.0},
                                   {3.0 * w1 * w1, 2.0 * w1, 1.0, 0.0},
                                   {3.0 * w2 * w2, 2.0 * w2, 1.0, 0.0}};
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) m[c][r] = rows[r][c];
        }
        const glm::dmat4 inv = glm::inverse(m);
        double coef[4];
        for (int r = 0; r < 4; ++r) {
            coef[r] = k[0] * inv[0][r] + k[1] * inv[1][r] + k[2] * inv[2][r] + k[3] * inv[3][r];
            if (std::abs(coef[r]) < kPovEpsilon) coef[r] = 0.0;
        }
        SorSegment e{coef[0], coef[1], coef[2], coef[3], w1, w2};
        double x[4] = {P[i + 1].x, P[i + 2].x, P[i + 1].x, P[i + 2].x};
        const double c[3] = {3.0 * e.A, 2.0 * e.B, e.C};
        double r[2];
        int n = solve_polynomial(2, c, r, false, 0.0);
        while (n--) {
            if (r[n] >= w1 && r[n] <= w2)
                x[n] = std::sqrt(r[n] * (r[n] * (r[n] * e.A + e.B) + e.C) + e.D);
        }
        xmin = std::min({xmin, x[0], x[1], x[2], x[3]});
        xmax = std::max({xmax, x[0], x[1], x[2], x[3]});
        ymin = std::min(ymin, w1);
        ymax = std::max(ymax, w2);
        seg.push_back(e);
    }
    const auto r2_at = [&](const SorSegment& e, double w) {
        return std::max(0.0, w * (w * (e.A * w + e.B) + e.C) + e.D);
    };
    const double cap = r2_at(seg.back(), seg.back().h2);
    const double base = r2_at(seg.front(), seg.front().h1);
    return std::shared_ptr<const ComplexShape>(std::make_shared<SorShape>(
        std::move(seg), !sor.open, sor.sturm, xmax, ymin, ymax, base, cap, p.transform));
}

}  // namespace mirage
