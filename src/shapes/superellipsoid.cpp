// Superellipsoids after POV-Ray 3.7's super.cpp: the ray clipped to the box [-1.01, 1.01]^3,
// cut by nine planes through the origin into pieces where the implicit function changes sign
// at most once, each root found by POV-Ray's mix of secant and bisection steps; its inside
// test and normal.
#include "shapes/superellipsoid.h"

#include <algorithm>
#include <cmath>

namespace mirage {
namespace {

constexpr double kDepthTolerance = 1.0e-4;
constexpr double kZeroTolerance = 1.0e-10;
constexpr double kMinValue = -1.01, kMaxValue = 1.01;
constexpr int kMaxIterations = 20;
constexpr int kPlaneCount = 9;
constexpr double kPlanes[kPlaneCount][4] = {{1, 1, 0, 0},  {1, -1, 0, 0}, {1, 0, 1, 0},
                                            {1, 0, -1, 0}, {0, 1, 1, 0},  {0, 1, -1, 0},
                                            {1, 0, 0, 0},  {0, 1, 0, 0},  {0, 0, 1, 0}};

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

// POV-Ray's power: exact products for small integer exponents.
double power(double x, double e) {
    const int i = static_cast<int>(e);
    if (e == static_cast<double>(i)) {
        double b = x;
        switch (i) {
            case 0:
                return 1.0;
            case 1:
                return b;
            case 2:
                return b * b;
            case 3:
                return b * b * b;
            case 4:
                b *= b;
                return b * b;
            case 5:
                b *= b;
                return b * b * x;
            case 6:
                b *= b;
                return b * b * b;
            default:
                return std::pow(x, e);
        }
    }
    return std::pow(x, e);
}

double evaluate_g(double x, double y, double e) {
    double g = 0.0;
    if (x > y) {
        g = 1.0 + power(y / x, e);
        if (g != 1.0) g = power(g, 1.0 / e);
        g *= x;
    } else if (y != 0.0) {
        g = 1.0 + power(x / y, e);
        if (g != 1.0) g = power(g, 1.0 / e);
        g *= y;
    }
    return g;
}

class SuperellipsoidShape final : public ComplexShape {
  public:
    SuperellipsoidShape(const Superellipsoid& s, const Transform& t) {
        power_ = glm::dvec3(2.0 / s.e, s.e / s.n, 2.0 / s.n);
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
        const double tol = sink.t_min() < 0.0 ? sink.t_min() * len : kDepthTolerance;
        double t1, t2;
        if (!intersect_box(P, D, tol, t1, t2)) return;
        if (t2 < tol) return;
        if (t1 < tol) t1 = tol;
        double dists[kPlaneCount + 2];
        int cnt = 0;
        dists[cnt++] = t1;
        dists[cnt++] = t2;
        cnt = ray_plane_points(P, D, cnt, dists, t1, t2);
        if (cnt <= 1) return;
        const double lo = sink.t_min() < 0.0 ? sink.t_min() : kDepthTolerance;
        const auto insert = [&](double depth) {
            if (depth > lo && depth < kPovMaxDistance) {
                sink.add(depth);
                return true;
            }
            return false;
        };
        glm::dvec3 P0 = P + dists[0] * D;
        double v0 = value(P0);
        if (std::abs(v0) < kZeroTolerance) insert(dists[0] / len);
        for (int i = 1; i < cnt; ++i) {
            const glm::dvec3 P1 = P + dists[i] * D;
            const double v1 = value(P1);
            if (std::abs(v1) < kZeroTolerance) {
                insert(dists[i] / len);
            } else if (v0 * v1 < 0.0) {
                const glm::dvec3 P2 = solve_hit1(v0, P0, v1, P1);
                insert(glm::length(P2 - P) / len);
            } else {
                double t;
                glm::dvec3 Q;
                glm::dvec3 p0 = P0;
                if (check_hit2(P, D, dists[i - 1], p0, v0, dists[i], t, Q)) {
                    if (!insert(t / len)) break;
                }
            }
            v0 = v1;
            P0 = P1;
        }
    }

    bool inside(const glm::dvec3& point) const override {
        return value(transform_point(world_to_local_, point)) < kPovEpsilon;
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit&) const override {
        glm::dvec3 P = transform_point(world_to_local_, point);
        const glm::dvec3& E = power_;
        double r = 0.0, z2n = 0.0;
        if (P.z != 0.0) {
            z2n = power(std::abs(P.z), E.z);
            P.z = z2n / P.z;
        }
        if (std::abs(P.x) > std::abs(P.y)) {
            r = power(std::abs(P.y / P.x), E.x);
            P.x = (1.0 - z2n) / P.x;
            P.y = P.y != 0.0 ? (1.0 - z2n) * r / P.y : 0.0;
        } else if (P.y != 0.0) {
            r = power(std::abs(P.x / P.y), E.x);
            P.x = P.x != 0.0 ? (1.0 - z2n) * r / P.x : 0.0;
            P.y = (1.0 - z2n) / P.y;
        }
        if (P.z != 0.0) P.z *= (1.0 + r);
        return glm::normalize(normal_to_world_ * P);
    }

    Aabb bounds() const override {
        Aabb box;
        for (int i = 0; i < 8; ++i) {
            box.extend(transform_point(
                local_to_world_, glm::dvec3(i & 1 ? 1.0001 : -1.0001, i & 2 ? 1.0001 : -1.0001,
                                            i & 4 ? 1.0001 : -1.0001)));
        }
        return box;
    }

  private:
    double value(const glm::dvec3& p) const {
        return evaluate_g(evaluate_g(std::abs(p.x), std::abs(p.y), power_.x), std::abs(p.z),
                          power_.z) -
               1.0;
    }

    // POV-Ray's intersect_box, forward from `tol` on (from behind for a query reaching back).
    static bool intersect_box(const glm::dvec3& P, const glm::dvec3& D, double tol, double& dmin,
                              double& dmax) {
        const double eps = tol < 0.0 ? tol : kPovEpsilon;
        if (std::abs(D.x) > kPovEpsilon) {
            if (D.x > kPovEpsilon) {
                dmin = (kMinValue - P.x) / D.x;
                dmax = (kMaxValue - P.x) / D.x;
                if (dmax < eps) return false;
            } else {
                dmax = (kMinValue - P.x) / D.x;
                if (dmax < eps) return false;
                dmin = (kMaxValue - P.x) / D.x;
            }
            if (dmin > dmax) return false;
        } else {
            if (P.x < kMinValue || P.x > kMaxValue) return false;
            dmin = -kPovBoundHuge;
            dmax = kPovBoundHuge;
        }
        for (int axis = 1; axis < 3; ++axis) {
            const double d = D[axis], p = P[axis];
            if (std::abs(d) > kPovEpsilon) {
                double tmin, tmax;
                if (d > kPovEpsilon) {
                    tmin = (kMinValue - p) / d;
                    tmax = (kMaxValue - p) / d;
                } else {
                    tmax = (kMinValue - p) / d;
                    tmin = (kMaxValue - p) / d;
                }
                if (tmax < dmax) {
                    if (tmax < eps) return false;
                    if (tmin > dmin) {
                        if (tmin > tmax) return false;
                        dmin = tmin;
                    } else if (dmin > tmax) {
                        return false;
                    }
                    dmax = tmax;
                } else if (tmin > dmin) {
                    if (tmin > dmax) return false;
                    dmin = tmin;
                }
            } else if (p < kMinValue || p > kMaxValue) {
                return false;
            }
        }
        return true;
    }

    static int ray_plane_points(const glm::dvec3& P, const glm::dvec3& D, int cnt, double* dists,
                                double mindist, double maxdist) {
        // Widened a little: the box's own planes are easy to miss by round off.
        const double t = kPovEpsilon * (maxdist - mindist);
        mindist -= t;
        maxdist += t;
        for (const auto& plane : kPlanes) {
            const double d = D.x * plane[0] + D.y * plane[1] + D.z * plane[2];
            if (std::abs(d) < kPovEpsilon) continue;
            const double s = (plane[3] - (P.x * plane[0] + P.y * plane[1] + P.z * plane[2])) / d;
            if (s >= mindist && s <= maxdist) dists[cnt++] = s;
        }
        std::sort(dists, dists + cnt);
        return cnt;
    }

    glm::dvec3 solve_hit1(double v0, glm::dvec3 P0, double v1, glm::dvec3 P1) const {
        for (int i = 0; i < kMaxIterations; ++i) {
            if (std::abs(v0) < kZeroTolerance) return P0;
            if (std::abs(v1) < kZeroTolerance) return P1;
            const double x = std::abs(v0) / std::abs(v1 - v0);
            const glm::dvec3 P2 = P0 + x * (P1 - P0);
            const double v2 = value(P2);
            const glm::dvec3 P3 = P0 + 0.5 * (P1 - P0);
            const double v3 = value(P3);
            if (v2 * v3 < 0.0) {
                v0 = v2;
                P0 = P2;
                v1 = v3;
                P1 = P3;
            } else if (std::abs(v2) < std::abs(v3)) {
                if (v0 * v2 < 0.0) {
                    v1 = v2;
                    P1 = P2;
                } else {
                    v0 = v2;
                    P0 = P2;
                }
            } else {
                if (v0 * v3 < 0.0) {
                    v1 = v3;
                    P1 = P3;
                } else {
                    v0 = v3;
                    P0 = P3;
                }
            }
        }
        return std::abs(v0) < std::abs(v1) ? P0 : P1;
    }

    bool check_hit2(const glm::dvec3& P, const glm::dvec3& D, double t0, glm::dvec3& P0, double v0,
                    double t1, double& t, glm::dvec3& Q) const {
        double dt0 = t0;
        double dt1 = t0 + 0.0001 * (t1 - t0);
        const double maxdelta = t1 - t0;
        double deltat = 0.0;
        for (int i = 0; dt0 < t1 && i < kMaxIterations; ++i) {
            const glm::dvec3 P1 = P + dt1 * D;
            const double v1 = value(P1);
            if (v0 * v1 < 0.0) {
                Q = solve_hit1(v0, P0, v1, P1);
                P0 = Q - P;
                t = glm::length(P0);
                return true;
            }
            if (std::abs(v1) < kZeroTolerance) {
                Q = P + dt1 * D;
                t = dt1;
                return true;
            }
            if ((v0 > 0.0 && v1 > v0) || (v0 < 0.0 && v1 < v0)) break;
            if (v1 == v0) break;
            deltat = v1 * (dt1 - dt0) / (v1 - v0);
            if (std::abs(deltat) > maxdelta) break;
            v0 = v1;
            dt0 = dt1;
            dt1 -= deltat;
        }
        return false;
    }

    glm::dvec3 power_;
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
};

}  // namespace

Result<std::shared_ptr<const ComplexShape>> prepare_superellipsoid(const Superellipsoid& s,
                                                                   const Primitive& p) {
    if (!(s.e > 0.0 && s.n > 0.0)) {
        return make_error(primitive_place(p) + "superellipsoid: the exponents must be > 0, got <" +
                          std::to_string(s.e) + ", " + std::to_string(s.n) + ">");
    }
    return std::shared_ptr<const ComplexShape>(
        std::make_shared<SuperellipsoidShape>(s, p.transform));
}

}  // namespace mirage
