// poly, cubic and quartic after POV-Ray 3.7's poly.cpp: the polynomial restricted to the ray
// (the binomial expansion of every term), solved by POV-Ray's solver; inside where it is below
// 1e-4; the normal from the gradient.  Unbounded, as in POV-Ray (bound it with clipped_by).
#include "shapes/poly.h"

#include <array>
#include <cmath>
#include <limits>

#include "shapes/polysolve.h"

namespace mirage {
namespace {

constexpr double kDepthTolerance = 1.0e-4;   // poly.cpp
constexpr double kInsideTolerance = 1.0e-4;  // poly.cpp
constexpr double kRootTolerance = 1.0e-4;    // poly.cpp
constexpr double kCoeffLimit = 1.0e-20;      // poly.cpp

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

double binomial(int n, int k) {
    static const auto table = [] {
        std::array<std::array<double, kMaxPolynomialOrder + 1>, kMaxPolynomialOrder + 1> t{};
        for (int i = 0; i <= kMaxPolynomialOrder; ++i) {
            t[i][0] = 1.0;
            for (int j = 1; j <= i; ++j) t[i][j] = t[i - 1][j - 1] + (j < i ? t[i - 1][j] : 0.0);
        }
        return t;
    }();
    return table[n][k];
}

class PolyShape final : public ComplexShape {
  public:
    PolyShape(const Polynomial& p, const Transform& t)
        : order_(p.order), coeffs_(p.coefficients), sturm_(p.sturm) {
        world_to_local_ = t.inverse;
        normal_to_world_ = glm::transpose(glm::dmat3(t.inverse));
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        const glm::dvec3 P = transform_point(world_to_local_, origin);
        glm::dvec3 D = glm::dmat3(world_to_local_) * direction;
        const double len = glm::length(D);
        D /= len;
        double depths[kMaxPolynomialOrder + 1];
        int count = 0;
        if (order_ == 1) {
            count = linear(P, D, depths);
        } else if (order_ == 2) {
            count = quadratic(P, D, depths);
        } else {
            count = general(P, D, depths);
        }
        const double lo = sink.t_min() < 0.0 ? sink.t_min() * len : kDepthTolerance;
        for (int i = 0; i < count; ++i) {
            if (!(depths[i] > lo)) continue;
            bool same = false;
            for (int j = 0; j < i; ++j) same |= depths[i] == depths[j];
            if (!same) sink.add(depths[i] / len);
        }
    }

    bool inside(const glm::dvec3& point) const override {
        return value(transform_point(world_to_local_, point)) < kInsideTolerance;
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit&) const override {
        const glm::dvec3 n = normal_to_world_ * gradient(transform_point(world_to_local_, point));
        const double l2 = glm::dot(n, n);
        return l2 > 0.0 ? n / std::sqrt(l2) : glm::dvec3(1.0, 0.0, 0.0);
    }

    Aabb bounds() const override {
        Aabb b;
        b.lo = glm::dvec3(-std::numeric_limits<double>::infinity());
        b.hi = glm::dvec3(std::numeric_limits<double>::infinity());
        return b;
    }

  private:
    int linear(const glm::dvec3& P, const glm::dvec3& D, double* depths) const {
        const double* a = coeffs_.data();
        const double t0 = a[0] * P.x + a[1] * P.y + a[2] * P.z;
        const double t1 = a[0] * D.x + a[1] * D.y + a[2] * D.z;
        if (std::abs(t1) < kPovEpsilon) return 0;
        depths[0] = -(a[3] + t0) / t1;
        return 1;
    }

    int quadratic(const glm::dvec3& P, const glm::dvec3& D, double* depths) const {
        const double* a = coeffs_.data();
        const double x = P.x, y = P.y, z = P.z, xx = D.x, yy = D.y, zz = D.z;
        const double ac = a[0] * xx * xx + a[1] * xx * yy + a[2] * xx * zz + a[4] * yy * yy +
                          a[5] * yy * zz + a[7] * zz * zz;
        double bc = 2 * a[0] * x * xx + a[1] * (x * yy + xx * y) + a[2] * (x * zz + xx * z) +
                    a[3] * xx + 2 * a[4] * y * yy + a[5] * (y * zz + yy * z) + a[6] * yy +
                    2 * a[7] * z * zz + a[8] * zz;
        const double cc = a[0] * x * x + a[1] * x * y + a[2] * x * z + a[3] * x + a[4] * y * y +
                          a[5] * y * z + a[6] * y + a[7] * z * z + a[8] * z + a[9];
        if (std::abs(ac) < kCoeffLimit) {
            if (std::abs(bc) < kCoeffLimit) return 0;
            depths[0] = -cc / bc;
            return 1;
        }
        double d = bc * bc - 4.0 * ac * cc;
        if (d < 0.0) return 0;
        d = std::sqrt(d);
        bc = -bc;
        const double t = 2.0 * ac;
        depths[0] = (bc + d) / t;
        depths[1] = (bc - d) / t;
        return 2;
    }

    // POV-Ray's Poly::intersect: substitute P + t D into every term.
    int general(const glm::dvec3& P, const glm::dvec3& D, double* depths) const {
        const int n = order_;
        double pv[3][kMaxPolynomialOrder + 1], dv[3][kMaxPolynomialOrder + 1];
        for (int a = 0; a < 3; ++a) {
            pv[a][0] = dv[a][0] = 1.0;
            pv[a][1] = P[a];
            dv[a][1] = D[a];
            for (int i = 2; i <= n; ++i) {
                pv[a][i] = pv[a][1] * pv[a][i - 1];
                dv[a][i] = dv[a][1] * dv[a][i - 1];
            }
        }
        double eqn[kMaxPolynomialOrder + 1] = {};
        double t[3][kMaxPolynomialOrder + 1];
        int term = 0;
        for (int i = n; i >= 0; --i) {
            for (int h = 0; h <= i; ++h) t[0][h] = binomial(i, h) * dv[0][i - h] * pv[0][h];
            for (int j = n - i; j >= 0; --j) {
                for (int h = 0; h <= j; ++h) t[1][h] = binomial(j, h) * dv[1][j - h] * pv[1][h];
                for (int k = n - (i + j); k >= 0; --k) {
                    if (coeffs_[term] != 0.0) {
                        for (int h = 0; h <= k; ++h) {
                            t[2][h] = binomial(k, h) * dv[2][k - h] * pv[2][h];
                        }
                        const int offset = n - (i + j + k);
                        for (int i1 = 0; i1 <= i; ++i1) {
                            for (int j1 = 0; j1 <= j; ++j1) {
                                for (int k1 = 0; k1 <= k; ++k1) {
                                    double val = coeffs_[term];
                                    val *= t[0][i1];
                                    val *= t[1][j1];
                                    val *= t[2][k1];
                                    eqn[offset + i1 + j1 + k1] += val;
                                }
                            }
                        }
                    }
                    ++term;
                }
            }
        }
        int first = 0, degree = n;
        while (first <= n && eqn[first] == 0.0) {
            ++first;
            --degree;
        }
        if (degree <= 1) return 0;
        return solve_polynomial(degree, eqn + first, depths, sturm_, kRootTolerance);
    }

    double value(const glm::dvec3& p) const {
        const int n = order_;
        double x[kMaxPolynomialOrder + 1], y[kMaxPolynomialOrder + 1], z[kMaxPolynomialOrder + 1];
        powers(p, x, y, z);
        double result = 0.0;
        int term = 0;
        for (int i = n; i >= 0; --i) {
            for (int j = n - i; j >= 0; --j) {
                for (int k = n - (i + j); k >= 0; --k) {
                    const double c = coeffs_[term++];
                    if (c != 0.0) result += c * x[i] * y[j] * z[k];
                }
            }
        }
        return result;
    }

    glm::dvec3 gradient(const glm::dvec3& p) const {
        const int n = order_;
        double x[kMaxPolynomialOrder + 1], y[kMaxPolynomialOrder + 1], z[kMaxPolynomialOrder + 1];
        powers(p, x, y, z);
        glm::dvec3 g(0.0);
        int term = 0;
        for (int i = n; i >= 0; --i) {
            for (int j = n - i; j >= 0; --j) {
                for (int k = n - (i + j); k >= 0; --k) {
                    const double a = coeffs_[term++];
                    if (i >= 1) g.x += i * a * x[i - 1] * y[j] * z[k];
                    if (j >= 1) g.y += j * a * x[i] * y[j - 1] * z[k];
                    if (k >= 1) g.z += k * a * x[i] * y[j] * z[k - 1];
                }
            }
        }
        return g;
    }

    void powers(const glm::dvec3& p, double* x, double* y, double* z) const {
        x[0] = y[0] = z[0] = 1.0;
        x[1] = p.x;
        y[1] = p.y;
        z[1] = p.z;
        for (int i = 2; i <= order_; ++i) {
            x[i] = x[1] * x[i - 1];
            y[i] = y[1] * y[i - 1];
            z[i] = z[1] * z[i - 1];
        }
    }

    int order_;
    std::vector<double> coeffs_;
    bool sturm_;
    glm::dmat4 world_to_local_{1.0};
    glm::dmat3 normal_to_world_{1.0};
};

}  // namespace

int polynomial_term_count(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }

Result<std::shared_ptr<const ComplexShape>> prepare_poly(const Polynomial& poly,
                                                         const Primitive& p) {
    if (poly.order < 1 || poly.order > kMaxPolynomialOrder ||
        static_cast<int>(poly.coefficients.size()) != polynomial_term_count(poly.order)) {
        return make_error(primitive_place(p) + "poly: order " + std::to_string(poly.order) +
                          " needs " + std::to_string(polynomial_term_count(poly.order)) +
                          " coefficients, has " + std::to_string(poly.coefficients.size()));
    }
    return std::shared_ptr<const ComplexShape>(std::make_shared<PolyShape>(poly, p.transform));
}

}  // namespace mirage
