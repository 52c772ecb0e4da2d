// Polynomial roots after POV-Ray 3.7's math/polysolv.cpp (see polysolve.h).  The constants
// and the order of the floating-point operations follow it: they decide which grazing rays
// find a root.
#include "shapes/polysolve.h"

#include <cmath>

namespace mirage {
namespace {

constexpr double kFudge1 = 1.0e12;  // coefficients this far apart in magnitude: use Sturm
constexpr double kTwoPiOver3 = 2.0943951023931954923084;
constexpr double kFourPiOver3 = 4.1887902047863909846168;
constexpr int kMaxIterations = 50;
constexpr double kSmallEnough = 1.0e-10;
constexpr double kRelError = 1.0e-12;
constexpr double kMaxDistance = 1.0e7;

struct Poly {
    int ord = 0;
    double coef[kMaxPolynomialOrder + 1] = {};  // coef[i] multiplies x^i
};

double poly_eval(double x, int n, const double* c) {
    double v = c[n];
    for (int i = n - 1; i >= 0; --i) v = v * x + c[i];
    return v;
}

// The remainder of u / v into r; returns its order.
int mod_poly(const Poly& u, const Poly& v, Poly& r) {
    r = u;
    if (v.coef[v.ord] < 0.0) {
        for (int k = u.ord - v.ord - 1; k >= 0; k -= 2) r.coef[k] = -r.coef[k];
        for (int k = u.ord - v.ord; k >= 0; --k) {
            for (int j = v.ord + k - 1; j >= k; --j) {
                r.coef[j] = -r.coef[j] - r.coef[v.ord + k] * v.coef[j - k];
            }
        }
    } else {
        for (int k = u.ord - v.ord; k >= 0; --k) {
            for (int j = v.ord + k - 1; j >= k; --j) r.coef[j] -= r.coef[v.ord + k] * v.coef[j - k];
        }
    }
    int k = v.ord - 1;
    while (k >= 0 && std::fabs(r.coef[k]) < kSmallEnough) {
        r.coef[k] = 0.0;
        --k;
    }
    r.ord = k < 0 ? 0 : k;
    return r.ord;
}

// The Sturm sequence of seq[0] (its derivative normalised, then negated remainders); returns
// the index of its last member.
int build_sturm(int ord, Poly* seq) {
    seq[0].ord = ord;
    seq[1].ord = ord - 1;
    double f = std::fabs(seq[0].coef[ord] * ord);
    for (int i = 1; i <= ord; ++i) seq[1].coef[i - 1] = seq[0].coef[i] * i / f;
    Poly* sp = seq + 2;
    for (; mod_poly(sp[-2], sp[-1], *sp); ++sp) {
        f = -std::fabs(sp->coef[sp->ord]);
        for (int i = sp->ord; i >= 0; --i) sp->coef[i] /= f;
    }
    sp->coef[0] = -sp->coef[0];
    return static_cast<int>(sp - seq);
}

int sign_changes(int np, const Poly* seq, double a) {
    int changes = 0;
    double lf = poly_eval(a, seq[0].ord, seq[0].coef);
    for (int i = 1; i <= np; ++i) {
        const double f = poly_eval(a, seq[i].ord, seq[i].coef);
        if (lf == 0.0 || lf * f < 0.0) ++changes;
        lf = f;
    }
    return changes;
}

// The roots at infinity minus at zero, as POV-Ray's visible_roots counts them.
int visible_roots(int np, const Poly* seq) {
    int at_inf = 0, at_zero = 0;
    double lf = seq[0].coef[seq[0].ord];
    for (int i = 1; i <= np; ++i) {
        const double f = seq[i].coef[seq[i].ord];
        if (lf == 0.0 || lf * f < 0.0) ++at_inf;
        lf = f;
    }
    lf = seq[0].coef[0];
    for (int i = 1; i <= np; ++i) {
        const double f = seq[i].coef[0];
        if (lf == 0.0 || lf * f < 0.0) ++at_zero;
        lf = f;
    }
    return at_zero - at_inf;
}

bool regula_falsi(int order, const double* coef, double a, double b, double* val) {
    double fa = poly_eval(a, order, coef);
    double fb = poly_eval(b, order, coef);
    if (fa * fb > 0.0) return false;
    if (std::fabs(fa) < kSmallEnough) {
        *val = a;
        return true;
    }
    if (std::fabs(fb) < kSmallEnough) {
        *val = b;
        return true;
    }
    double lfx = fa;
    for (int its = 0; its < kMaxIterations; ++its) {
        const double x = (fb * a - fa * b) / (fb - fa);
        const double fx = poly_eval(x, order, coef);
        if (std::fabs(x) > kRelError) {
            if (std::fabs(fx / x) < kRelError) {
                *val = x;
                return true;
            }
        } else if (std::fabs(fx) < kRelError) {
            *val = x;
            return true;
        }
        // Illinois: halve the value at the end that stays.
        if (fa < 0.0) {
            if (fx < 0.0) {
                a = x;
                fa = fx;
                if (lfx * fx > 0.0) fb /= 2.0;
            } else {
                b = x;
                fb = fx;
                if (lfx * fx > 0.0) fa /= 2.0;
            }
        } else {
            if (fx < 0.0) {
                b = x;
                fb = fx;
                if (lfx * fx > 0.0) fa /= 2.0;
            } else {
                a = x;
                fa = fx;
                if (lfx * fx > 0.0) fb /= 2.0;
            }
        }
        if (std::fabs(b - a) < kRelError) {
            *val = x;
            return true;
        }
        lfx = fx;
    }
    return false;
}

// True when the bisection has shrunk the interval to the root.
bool converged(double mid, double lo, double hi) {
    if (std::fabs(mid) > kRelError) return std::fabs((hi - lo) / mid) < kRelError;
    return std::fabs(hi - lo) < kRelError;
}

int sturm_bisect(int np, const Poly* seq, double lo, double hi, int at_lo, int at_hi,
                 double* roots) {
    double mid = 0.0;
    if (at_lo - at_hi == 1) {
        if (regula_falsi(seq->ord, seq->coef, lo, hi, roots)) return 1;
        for (int its = 0; its < kMaxIterations; ++its) {
            mid = (lo + hi) / 2.0;
            const int at_mid = sign_changes(np, seq, mid);
            if (at_mid < at_hi || at_mid > at_lo) return 0;  // POV-Ray: "if there is a bug"
            if (converged(mid, lo, hi)) {
                roots[0] = mid;
                return 1;
            }
            if (at_lo - at_mid == 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        roots[0] = mid;
        return 1;
    }
    for (int its = 0; its < kMaxIterations; ++its) {
        mid = (lo + hi) / 2.0;
        const int at_mid = sign_changes(np, seq, mid);
        if (at_mid < at_hi || at_mid > at_lo) return 0;
        if (converged(mid, lo, hi)) {
            roots[0] = mid;
            return 1;
        }
        int n1 = at_lo - at_mid;
        int n2 = at_mid - at_hi;
        if (n1 != 0 && n2 != 0) {
            n1 = sturm_bisect(np, seq, lo, mid, at_lo, at_mid, roots);
            n2 = sturm_bisect(np, seq, mid, hi, at_mid, at_hi, roots + n1);
            return n1 + n2;
        }
        if (n1 == 0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    roots[0] = mid;
    return 1;
}

int sturm_solve(int order, const double* c, double* roots) {
    Poly seq[kMaxPolynomialOrder + 1];
    for (int i = 0; i <= order; ++i) seq[0].coef[order - i] = c[i] / c[0];
    const int np = build_sturm(order, seq);
    if (visible_roots(np, seq) == 0) return 0;
    const int at_lo = sign_changes(np, seq, 0.0);
    const int at_hi = sign_changes(np, seq, kMaxDistance);
    if (at_lo - at_hi == 0) return 0;
    return sturm_bisect(np, seq, 0.0, kMaxDistance, at_lo, at_hi, roots);
}

int solve_quadratic(const double* x, double* y) {
    double a = x[0];
    double b = -x[1];
    double c = x[2];
    if (a == 0.0) {
        if (b == 0.0) return 0;
        y[0] = c / b;
        return 1;
    }
    b /= a;
    c /= a;
    a = 1.0;
    double d = b * b - 4.0 * a * c;
    if (d > -kSmallEnough && d < kSmallEnough) {
        y[0] = 0.5 * b / a;
        return 1;
    }
    if (d < 0.0) return 0;
    d = std::sqrt(d);
    const double t = 2.0 * a;
    y[0] = (b + d) / t;
    y[1] = (b - d) / t;
    return 2;
}

int solve_cubic(const double* x, double* y) {
    const double a0 = x[0];
    if (a0 == 0.0) return solve_quadratic(x + 1, y);
    double a1 = x[1], a2 = x[2], a3 = x[3];
    if (a0 != 1.0) {
        a1 = x[1] / a0;
        a2 = x[2] / a0;
        a3 = x[3] / a0;
    }
    const double A2 = a1 * a1;
    const double Q = (A2 - 3.0 * a2) / 9.0;
    const double R = (a1 * (A2 - 4.5 * a2) + 13.5 * a3) / 27.0;
    const double Q3 = Q * Q * Q;
    const double R2 = R * R;
    const double d = Q3 - R2;
    const double an = a1 / 3.0;
    if (d >= 0.0) {
        const double theta = std::acos(R / std::sqrt(Q3)) / 3.0;
        const double sQ = -2.0 * std::sqrt(Q);
        y[0] = sQ * std::cos(theta) - an;
        y[1] = sQ * std::cos(theta + kTwoPiOver3) - an;
        y[2] = sQ * std::cos(theta + kFourPiOver3) - an;
        return 3;
    }
    const double sQ = std::pow(std::sqrt(R2 - Q3) + std::fabs(R), 1.0 / 3.0);
    y[0] = R < 0.0 ? (sQ + Q / sQ) - an : -(sQ + Q / sQ) - an;
    return 1;
}

// POV-Ray's test for coefficients too far apart for the closed form.  It keeps the signed
// value as "biggest" (so a negative largest coefficient never triggers it): kept as it is.
bool difficult_coefficients(int n, const double* x) {
    double biggest = 0.0;
    for (int i = 0; i <= n; ++i) {
        if (std::fabs(x[i]) > biggest) biggest = x[i];
    }
    if (biggest == 0.0) return false;
    for (int i = 0; i <= n; ++i) {
        if (x[i] != 0.0 && std::fabs(biggest / x[i]) > kFudge1) return true;
    }
    return false;
}

int solve_quartic(const double* x, double* results) {
    double c1 = x[1], c2 = x[2], c3 = x[3], c4 = x[4];
    const double c0 = x[0];
    if (c0 != 1.0) {
        c1 = x[1] / c0;
        c2 = x[2] / c0;
        c3 = x[3] / c0;
        c4 = x[4] / c0;
    }
    // The cubic resolvent of the depressed quartic.
    const double c12 = c1 * c1;
    double p = -0.375 * c12 + c2;
    const double q = 0.125 * c12 * c1 - 0.5 * c1 * c2 + c3;
    const double r = -0.01171875 * c12 * c12 + 0.0625 * c12 * c2 - 0.25 * c1 * c3 + c4;
    const double cubic[4] = {1.0, -0.5 * p, -r, 0.5 * r * p - 0.125 * q * q};
    double roots[3];
    if (solve_cubic(cubic, roots) <= 0) return 0;
    const double z = roots[0];
    double d1 = 2.0 * z - p;
    double d2;
    if (d1 < 0.0) {
        if (d1 > -kSmallEnough) {
            d1 = 0.0;
        } else {
            return 0;
        }
    }
    if (d1 < kSmallEnough) {
        d2 = z * z - r;
        if (d2 < 0.0) return 0;
        d2 = std::sqrt(d2);
    } else {
        d1 = std::sqrt(d1);
        d2 = 0.5 * q / d1;
    }
    const double q1 = d1 * d1;
    const double q2 = -0.25 * c1;
    int i = 0;
    p = q1 - 4.0 * (z - d2);
    if (p == 0.0) {
        results[i++] = -0.5 * d1 - q2;
    } else if (p > 0.0) {
        p = std::sqrt(p);
        results[i++] = -0.5 * (d1 + p) + q2;
        results[i++] = -0.5 * (d1 - p) + q2;
    }
    p = q1 - 4.0 * (z + d2);
    if (p == 0.0) {
        results[i++] = 0.5 * d1 - q2;
    } else if (p > 0.0) {
        p = std::sqrt(p);
        results[i++] = 0.5 * (d1 + p) + q2;
        results[i++] = 0.5 * (d1 - p) + q2;
    }
    return i;
}

}  // namespace

int solve_polynomial(int n, const double* c0, double* r, bool sturm, double epsilon) {
    int i = 0;
    while (i < n && std::fabs(c0[i]) < kSmallEnough) ++i;
    n -= i;
    const double* c = c0 + i;
    switch (n) {
        case 0:
            return 0;
        case 1:
            if (c[0] != 0.0) {
                r[0] = -c[1] / c[0];
                return 1;
            }
            return 0;
        case 2:
            return solve_quadratic(c, r);
        case 3:
            if (epsilon > 0.0 && c[2] != 0.0 && std::fabs(c[3] / c[2]) < epsilon) {
                return solve_quadratic(c, r);
            }
            return sturm ? sturm_solve(3, c, r) : solve_cubic(c, r);
        case 4:
            if (epsilon > 0.0 && c[3] != 0.0 && std::fabs(c[4] / c[3]) < epsilon) {
                return sturm ? sturm_solve(3, c, r) : solve_cubic(c, r);
            }
            if (difficult_coefficients(4, c)) sturm = true;
            return sturm ? sturm_solve(4, c, r) : solve_quartic(c, r);
        default:
            // POV-Ray eliminates the small root here too but then solves the whole
            // polynomial anyway: the elimination has no effect above order 4.
            if (n > kMaxPolynomialOrder) return 0;
            return sturm_solve(n, c, r);
    }
}

}  // namespace mirage
