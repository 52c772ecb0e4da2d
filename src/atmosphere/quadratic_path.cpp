#include "atmosphere/quadratic_path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "util/check.h"
#include "util/format.h"

// Crossing times (notation of quadratic_path.h; per piece kappa = c / beta^2, lambda =
// sqrt|kappa|; a monotone run from (y_e, slope s_e, curvature a_e) to (y_x, s_x), dy = y_x - y_e,
// S = s_e + s_x, which has the sign of dy):
//
// * kappa = 0 (a parabola): t = 2 dy / S, exact and without cancellation.
// * kappa > 0: A+- = a +- lambda s obey A+-(z) = A+-(0) exp(+-lambda z), so
//   lambda t = log1p(lambda R+) with R+ = (A+_x - A+_e) / (lambda A+_e)
//            = (dy / S) (2 a_e + lambda S + kappa dy) / (a_e + lambda s_e),
//   used when a_e s_e >= 0 (every term has one sign), else the A- form
//   lambda t = log1p(-lambda R-), R- = (dy / S) (2 a_e + kappa dy - lambda S) / (a_e - lambda s_e).
//   Both use s_x - s_e = (2 a_e dy + kappa dy^2) / S (from s^2 = s_e^2 + 2 a_e dy + kappa dy^2),
//   so that nothing cancels as kappa -> 0, where they tend to the parabola's 2 dy / S.
// * kappa < 0: a + i lambda s turns by the angle lambda t, so
//   lambda t = atan2(lambda Im, M + lambda Re), M = a_e^2 + lambda^2 s_e^2,
//   Im = lambda^2 dy s_e + (s_x - s_e) a_e, Re = lambda ((s_x - s_e) s_e - dy a_e).
// * From a turning point (slope 0, curvature a_v) to the offset dy (same sign as a_v), with
//   r = sqrt(2 dy / a_v) and z = lambda r / 2: t = (2 / lambda) asinh(z) (kappa > 0),
//   (2 / lambda) asin(z) (kappa < 0), r (kappa = 0), each written r * f(z) with f -> 1: the
//   asinh/asin forms, stable for grazing rays however small dy is.
// * Turning points are the roots of Q(y) = n^2(y) - beta^2, a quadratic in each piece, taken
//   in the form without cancellation (q = -(Q' + sign(Q') sqrt(disc)) / 2, roots q / c and Q / q).
//   Q is carried from piece to piece by the pieces' increments of n^2 from the start, so it
//   keeps its relative accuracy at grazing angles (never n^2(y) - beta^2 from two values near 1).

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

struct Basis {
    double S1, S2, C;
};

// S1 = sinh x / x, S2 = (cosh x - 1) / x^2, C = cosh x (kappa > 0), their circular
// counterparts (kappa < 0), or the parabola's 1, 1/2, 1.  Taylor series below |x| = 0.25 (the
// first term left out is under 1e-17 relative).
Basis basis(double kappa, double x) {
    if (kappa == 0.0) return {1.0, 0.5, 1.0};
    const double z = kappa > 0.0 ? x * x : -x * x;  // x^2 with the sign of kappa
    const double ax = std::fabs(x);
    if (ax < 0.25) {
        // Terms 1/(2k+1)! and 1/(2k+2)!, as many as |x| needs.
        double S1, S2;
        if (ax < 0.01) {
            S1 = 1.0 + z * (1.0 / 6 + z * (1.0 / 120 + z * (1.0 / 5040)));
            S2 = 0.5 + z * (1.0 / 24 + z * (1.0 / 720 + z * (1.0 / 40320)));
        } else if (ax < 0.06) {
            S1 = 1.0 + z * (1.0 / 6 +
                            z * (1.0 / 120 + z * (1.0 / 5040 + z * (1.0 / 362880 + z / 39916800))));
            S2 = 0.5 + z * (1.0 / 24 + z * (1.0 / 720 + z * (1.0 / 40320 +
                                                             z * (1.0 / 3628800 + z / 479001600))));
        } else {
            S1 = 1.0 +
                 z * (1.0 / 6 +
                      z * (1.0 / 120 + z * (1.0 / 5040 +
                                            z * (1.0 / 362880 + z * (1.0 / 39916800 +
                                                                     z * (1.0 / 6227020800.0 +
                                                                          z / 1307674368000.0))))));
            S2 = 0.5 +
                 z * (1.0 / 24 +
                      z * (1.0 / 720 + z * (1.0 / 40320 + z * (1.0 / 3628800 +
                                                               z * (1.0 / 479001600 +
                                                                    z * (1.0 / 87178291200.0 +
                                                                         z / 20922789888000.0))))));
        }
        return {S1, S2, 1.0 + z * S2};  // cosh x = 1 + x^2 (cosh x - 1) / x^2
    }
    if (kappa > 0.0) {
        const double h = std::sinh(0.5 * x) / x;
        return {std::sinh(x) / x, 2.0 * h * h, std::cosh(x)};
    }
    const double h = std::sin(0.5 * x) / x;
    return {std::sin(x) / x, 2.0 * h * h, std::cos(x)};
}

// f(z) / z for log1p, atan, asinh and asin, by their series near 0 (the first term left out is
// under 1e-16 relative).
double log1pc(double z) {
    const double a = std::fabs(z);
    if (a < 1e-3) return 1.0 + z * (-0.5 + z * (1.0 / 3 + z * (-0.25 + z * (0.2 - z / 6))));
    if (a < 6e-3)
        return 1.0 +
               z * (-0.5 + z * (1.0 / 3 +
                                z * (-0.25 + z * (0.2 + z * (-1.0 / 6 + z * (1.0 / 7 - z / 8))))));
    if (a < 0.03) {
        constexpr double c[12] = {1.0,     1.0 / 2, 1.0 / 3, 1.0 / 4,  1.0 / 5,  1.0 / 6,
                                  1.0 / 7, 1.0 / 8, 1.0 / 9, 1.0 / 10, 1.0 / 11, 1.0 / 12};
        double r = c[11];
        for (int k = 10; k >= 0; --k) r = c[k] - z * r;
        return r;
    }
    return std::log1p(z) / z;
}
double atanc(double z) {
    const double a = std::fabs(z);
    const double w = z * z;
    if (a < 3e-3) return 1.0 + w * (-1.0 / 3 + w * (0.2 - w / 7));
    if (a < 0.02) return 1.0 + w * (-1.0 / 3 + w * (0.2 + w * (-1.0 / 7 + w * (1.0 / 9 - w / 11))));
    if (a < 0.1) {
        constexpr double c[9] = {1.0,      1.0 / 3,  1.0 / 5,  1.0 / 7, 1.0 / 9,
                                 1.0 / 11, 1.0 / 13, 1.0 / 15, 1.0 / 17};
        double r = c[8];
        for (int k = 7; k >= 0; --k) r = c[k] - w * r;
        return r;
    }
    return std::atan(z) / z;
}
double asinhc(double z) {
    if (std::fabs(z) < 0.02) {
        const double w = z * z;
        return 1.0 + w * (-1.0 / 6 + w * (3.0 / 40 + w * (-15.0 / 336 + w * 105.0 / 3456)));
    }
    return std::asinh(z) / z;
}
double asinc(double z) {
    if (std::fabs(z) < 0.02) {
        const double w = z * z;
        return 1.0 + w * (1.0 / 6 + w * (3.0 / 40 + w * (15.0 / 336 + w * 105.0 / 3456)));
    }
    return std::asin(z) / z;
}

// Horizontal distance of a monotone run without a turning point (see the file comment).
double crossing_time(double dy, double s_e, double s_x, double a_e, double kappa, double lambda) {
    const double S = s_e + s_x;
    if (dy == 0.0) return 0.0;
    MIRAGE_CHECK(S != 0.0);
    if (kappa == 0.0) return 2.0 * dy / S;
    if (kappa > 0.0) {
        if (a_e * s_e >= 0.0) {
            const double R =
                dy * (2.0 * a_e + lambda * S + kappa * dy) / (S * (a_e + lambda * s_e));
            return R * log1pc(lambda * R);
        }
        const double R = dy * (2.0 * a_e + kappa * dy - lambda * S) / (S * (a_e - lambda * s_e));
        return R * log1pc(-lambda * R);
    }
    // With d = s_x - s_e = (2 a_e dy + kappa dy^2) / S, Im = lambda^2 dy s_e + d a_e and
    // Re = lambda (d s_e - dy a_e), both over the same S: one division for Im / (M + lambda Re).
    const double g = 2.0 * a_e + kappa * dy;  // d = dy g / S
    const double l2 = lambda * lambda;
    const double M = a_e * a_e + l2 * s_e * s_e;
    const double im_S = dy * (l2 * s_e * S + a_e * g);
    const double den_S = M * S + l2 * dy * (g * s_e - a_e * S);
    if (den_S * S > 0.0) {
        // The angle lies within (-pi/2, pi/2): atan of the quotient (half the cost of atan2).
        const double r = im_S / den_S;
        if (std::fabs(lambda * r) < 0.1) return r * atanc(lambda * r);
        return std::atan(lambda * r) / lambda;
    }
    return std::atan2(lambda * im_S / S, den_S / S) / lambda;
}

// Distance from a turning point (curvature a_v) to the offset dy (same sign as a_v).
double vertex_time(double dy, double a_v, double kappa, double lambda) {
    if (dy == 0.0) return 0.0;
    if (a_v == 0.0) return kInf;  // an extremum of n^2 with beta = n: approached for ever
    const double r = std::sqrt(std::max(0.0, 2.0 * dy / a_v));
    if (kappa == 0.0) return r;
    const double z = 0.5 * lambda * r;
    if (kappa > 0.0) return r * asinhc(z);
    if (z >= 1.0) return kPi / lambda;
    return r * asinc(z);
}

// The first root delta of Q + Np delta + c delta^2 with dir * delta in (lo, dir * db], lo >= 0,
// or NaN.  At a turning point (Q = 0, from_vertex) the root delta = 0 is the start itself.
double first_root(double Q, double Np, double c, double db, int dir, bool from_vertex, double lo) {
    auto ok = [&](double d) { return dir * d > lo && dir * d <= dir * db; };
    if (from_vertex) {
        if (c == 0.0) return kNaN;
        const double d = -Np / c;
        return ok(d) ? d : kNaN;
    }
    if (c == 0.0) {
        if (Np == 0.0) return kNaN;
        const double d = -Q / Np;
        return ok(d) ? d : kNaN;
    }
    const double disc = Np * Np - 4.0 * c * Q;
    if (disc < 0.0) return kNaN;
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (Np + (Np >= 0.0 ? sq : -sq));
    double best = kNaN;
    auto consider = [&](double d) {
        if (ok(d) && (std::isnan(best) || std::fabs(d) < std::fabs(best))) best = d;
    };
    if (q != 0.0) {
        consider(q / c);
        consider(Q / q);
    }
    return best;
}

struct PieceGeometry {
    double ylo, yhi, b, c, root_c;
};

PieceGeometry geometry(const QuadraticProfile& p, int j) {
    if (j >= p.piece_count()) return {p.top(), kInf, 0.0, 0.0, 0.0};
    return {p.knot(j), p.knot(j + 1), p.b(j), p.c(j), p.root_abs_c(j)};
}

// The piece a run leaves from height y in direction dir takes (a knot belongs to the piece
// above it going up and to the piece below going down); -1: the ground is reached.
int piece_for(const QuadraticProfile& p, double y, int dir) {
    int j = p.piece_at(y);
    if (dir < 0 && j >= 0 && y == (j < p.piece_count() ? p.knot(j) : p.top())) --j;
    return j;
}

// n^2 - n0^2 at the knot a run reaches leaving piece j in direction dir.
double exit_excess(const QuadraticProfile& p, int j, int dir) { return p.e(dir > 0 ? j + 1 : j); }

struct RunEnd {
    SweepEnd kind = SweepEnd::Top;
    double y = 0.0;
    int piece = 0;
};

// Where the run from (y, piece j, dir) with Q = n^2 - beta^2 = Q_o there ends: its next
// turning point, the ground or the top.  Beyond the origin's piece Q at a knot is
// e_knot - level (level = e_ref - Q_ref, Q_ref the ray's Q at e_ref), and the first piece whose
// smallest n^2 reaches the level is found by the profile's sparse table.
RunEnd run_end(const QuadraticProfile& p, double y, int j, int dir, double Q_o, bool from_vertex,
               double level) {
    const int m = p.piece_count();
    if (dir > 0 && j >= m) return {SweepEnd::Top, std::max(y, p.top()), m};
    if (dir < 0 && j < 0) return {SweepEnd::Ground, 0.0, -1};
    if (j < m) {
        const PieceGeometry g = geometry(p, j);
        const double Np = g.b + 2.0 * g.c * (y - g.ylo);
        const double yb = dir > 0 ? g.yhi : g.ylo;
        const double db = yb - y;
        const double d = first_root(Q_o, Np, g.c, db, dir, from_vertex, 0.0);
        if (!std::isnan(d)) return {SweepEnd::Vertex, y + d, j};
        if (exit_excess(p, j, dir) - level < 0.0 && Q_o + (Np + g.c * db) * db < 0.0)
            return {SweepEnd::Vertex, yb, j};
    }
    j += dir;
    while (true) {
        const int k = p.find_piece_reaching(j, dir, level);
        if (dir > 0 && k >= m) return {SweepEnd::Top, p.top(), m};
        if (dir < 0 && k < 0) return {SweepEnd::Ground, 0.0, -1};
        const PieceGeometry g = geometry(p, k);
        const double y_in = dir > 0 ? g.ylo : g.yhi;
        const double Q_in = std::max(0.0, p.e(dir > 0 ? k : k + 1) - level);
        const double Np = dir > 0 ? g.b : p.end_slope(k);
        const double db = (dir > 0 ? g.yhi : g.ylo) - y_in;
        const double d = first_root(Q_in, Np, g.c, db, dir, false, 0.0);
        if (!std::isnan(d)) return {SweepEnd::Vertex, y_in + d, k};
        if (exit_excess(p, k, dir) - level < 0.0) return {SweepEnd::Vertex, y_in + db, k};
        j = k + dir;
    }
}

const QuadraticSegment& segment_at(const Sweep& s, double t) {
    auto it = std::lower_bound(s.segments.begin(), s.segments.end(), t,
                               [](const QuadraticSegment& g, double v) { return g.t1 < v; });
    if (it == s.segments.end()) --it;
    return *it;
}

double segment_height(const QuadraticSegment& g, double t) {
    const double tau = t - g.ta;
    const Basis B = basis(g.kappa, g.lambda * tau);
    return g.ya + tau * (g.sa * B.S1 + g.aa * tau * B.S2);
}

double segment_slope(const QuadraticSegment& g, double t) {
    const double tau = t - g.ta;
    const Basis B = basis(g.kappa, g.lambda * tau);
    return g.sa * B.C + g.aa * tau * B.S1;
}

}  // namespace

std::string_view path_fate_name(PathFate f) {
    switch (f) {
        case PathFate::Straight:
            return "straight";
        case PathFate::Ground:
            return "ground";
        case PathFate::Escape:
            return "escape";
        case PathFate::Ducted:
            return "ducted";
        case PathFate::Level:
            return "level";
    }
    return "?";
}

double sweep_height(const Sweep& s, double t) {
    if (t >= s.length || s.segments.empty()) {
        if (s.segments.empty() && t <= 0.0) return s.y_start;
        return s.y_end + s.end_slope * (t - s.length);
    }
    return segment_height(segment_at(s, t), t);
}

double sweep_slope(const Sweep& s, double t) {
    if (t >= s.length || s.segments.empty()) return s.end_slope;
    return segment_slope(segment_at(s, t), t);
}

Result<QuadraticPath> QuadraticPath::make(const QuadraticProfile& profile, double y0,
                                          double i_rad) {
    if (!std::isfinite(y0) || y0 < 0.0)
        return make_error("start height y0 = " + shortest(y0) + " m must be finite and >= 0");
    if (!std::isfinite(i_rad) || i_rad <= 0.0 || i_rad >= kPi)
        return make_error("angle from the vertical i = " + shortest(i_rad) +
                          " rad must lie strictly between 0 and pi (a vertical ray has no "
                          "horizontal distance)");
    auto path =
        make_direction(profile, quadratic_start(profile, y0), std::cos(i_rad), std::sin(i_rad));
    if (path) path->i_ = i_rad;
    return path;
}

double QuadraticPath::i_rad() const {
    if (std::isnan(i_)) i_ = std::atan2(sin_i_, cos_i_);
    return i_;
}

QuadraticStart quadratic_start(const QuadraticProfile& profile, double y0) {
    QuadraticStart st;
    st.y0 = y0;
    if (!std::isfinite(y0) || y0 < 0.0) return st;
    st.e0 = profile.excess(y0);
    st.piece_up = piece_for(profile, y0, 1);
    st.piece_down = piece_for(profile, y0, -1);
    return st;
}

Result<QuadraticPath> QuadraticPath::make_direction(const QuadraticProfile& profile,
                                                    const QuadraticStart& start, double cos_i,
                                                    double sin_i) {
    const double y0 = start.y0;
    if (!std::isfinite(y0) || y0 < 0.0)
        return make_error("start height y0 = " + shortest(y0) + " m must be finite and >= 0");
    if (!std::isfinite(cos_i) || !(sin_i > 0.0) || !std::isfinite(sin_i) ||
        !(std::fabs(cos_i * cos_i + sin_i * sin_i - 1.0) < 1e-12))
        return make_error("direction (cos i, sin i) = (" + shortest(cos_i) + ", " +
                          shortest(sin_i) +
                          ") must be a unit vector with a horizontal part (sin i > 0)");
    // A path starts inside a run (n^2 - beta^2 > 0 there: a start exactly at a turning point
    // would be taken for one in the direction of cos i's sign).  make(i) never gives |cos i|
    // below cos of the double nearest pi/2; a direction nearer level is given that.
    constexpr double kMinCos = 6.123233995736766e-17;
    if (std::fabs(cos_i) < kMinCos) cos_i = std::signbit(cos_i) ? -kMinCos : kMinCos;
    QuadraticPath r;
    r.profile_ = &profile;
    r.y0_ = y0;
    r.i_ = kNaN;
    r.cos_i_ = cos_i;
    r.sin_i_ = sin_i;
    r.slope0_ = r.cos_i_ / r.sin_i_;
    r.sg_ = r.cos_i_ < 0.0 ? -1 : 1;
    r.e0_ = start.e0;
    const double N0 = profile.n0_sq() + r.e0_;
    r.eta_p_ = std::sqrt(N0);
    r.beta_ = r.eta_p_ * r.sin_i_;
    r.inv_beta_ = 1.0 / r.beta_;
    r.inv_beta_sq_ = r.inv_beta_ * r.inv_beta_;
    r.Q0_ = N0 * r.cos_i_ * r.cos_i_;
    r.slope_straight_ = kNaN;
    Sweep& s = r.sweep_;
    if (profile.homogeneous()) {
        r.fate_ = PathFate::Straight;
        r.slope_straight_ = r.slope0_;
        s.y_start = y0;
        s.dir = r.sg_;
        s.end = r.sg_ < 0 ? SweepEnd::Ground : SweepEnd::Top;
        s.y_end = r.sg_ < 0 ? 0.0 : y0;
        s.length = r.sg_ < 0 ? y0 / -r.slope0_ : 0.0;
        s.end_slope = r.slope0_;
        r.cur_.done = true;
        return r;
    }
    const double level = r.e0_ - r.Q0_;  // n^2 - n0^2 where the ray is level (Q = 0)
    const int m = profile.piece_count();
    auto slope_at_end = [&](const RunEnd& e, int dir) {
        // At the ground or the top: from Q = e - level there.
        const double e_end = e.kind == SweepEnd::Ground ? 0.0 : profile.e(m);
        return dir * std::sqrt(std::max(0.0, e_end - level)) * r.inv_beta_;
    };
    if (y0 == 0.0 && r.sg_ < 0) {
        r.fate_ = PathFate::Ground;
        s.y_start = s.y_end = 0.0;
        s.end = SweepEnd::Ground;
        s.end_slope = r.slope0_;
        s.dir = -1;
        r.cur_.done = true;
        return r;
    }
    const int start_piece = r.sg_ > 0 ? start.piece_up : start.piece_down;
    r.hint_a_ = r.hint_b_ = std::clamp(start_piece, 0, m - 1);
    const RunEnd ahead = run_end(profile, y0, start_piece, r.sg_, r.Q0_, false, level);
    if (ahead.kind == SweepEnd::Vertex) {
        const PieceGeometry g = geometry(profile, ahead.piece);
        const double a_v = 0.5 * (g.b + 2.0 * g.c * (ahead.y - g.ylo)) * r.inv_beta_sq_;
        // The ray stays at this height for ever.
        auto stay_level = [&]() {
            r.fate_ = PathFate::Level;
            r.slope_straight_ = 0.0;
            s.y_start = s.y_end = y0;
            s.end = SweepEnd::Top;
            r.cur_.done = true;
        };
        if (a_v == 0.0) {
            if (ahead.y == y0) {
                // Level at an extremum of n^2: the ray stays at this height.
                stay_level();
                return r;
            }
            return make_error("the ray from " + shortest(y0) + " m at i = " + shortest(r.i_rad()) +
                              " rad is tangent to an extremum of the index at " +
                              shortest(ahead.y) + " m: it approaches that height for ever");
        }
        // The run back from the first turning point passes the start and ends where the
        // reversed ray from the start ends.
        const RunEnd behind = run_end(profile, y0, r.sg_ > 0 ? start.piece_down : start.piece_up,
                                      -r.sg_, r.Q0_, false, level);
        if (behind.kind == SweepEnd::Vertex && behind.y == ahead.y) {
            // Level at a maximum of n^2 with a corner (an inversion's sharp bottom): n^2 falls
            // on both sides, so the ray cannot leave this height.
            stay_level();
            return r;
        }
        r.vertex_ahead_ = true;
        r.t1_known_ = false;
        s.dir = -r.sg_;
        s.y_start = ahead.y;
        s.end = behind.kind;
        s.y_end = behind.y;
        r.end_piece_ = behind.piece;
        r.cur_.j = ahead.piece;
        r.cur_.y = ahead.y;
        r.cur_.Q = 0.0;
        r.cur_.at_vertex = true;
        switch (behind.kind) {
            case SweepEnd::Vertex:
                r.periodic_ = true;
                r.fate_ = PathFate::Ducted;
                s.end_slope = 0.0;
                break;
            case SweepEnd::Ground:
                r.fate_ = PathFate::Ground;
                s.end_slope = slope_at_end(behind, s.dir);
                break;
            case SweepEnd::Top:
                r.fate_ = PathFate::Escape;
                s.end_slope = slope_at_end(behind, s.dir);
                r.slope_straight_ = s.end_slope;
                break;
        }
    } else {
        s.dir = r.sg_;
        s.y_start = y0;
        s.end = ahead.kind;
        s.y_end = ahead.y;
        s.end_slope = slope_at_end(ahead, s.dir);
        if (y0 >= profile.top() && r.sg_ > 0) s.end_slope = r.slope0_;
        r.end_piece_ = ahead.piece;
        r.cur_.j = start_piece;
        r.cur_.y = y0;
        r.cur_.Q = r.Q0_;
        r.cur_.slope = r.slope0_;
        r.fate_ = ahead.kind == SweepEnd::Ground ? PathFate::Ground : PathFate::Escape;
        if (r.fate_ == PathFate::Escape) r.slope_straight_ = s.end_slope;
    }
    return r;
}

bool QuadraticPath::extend() const {
    Cursor& c = cur_;
    Sweep& s = sweep_;
    if (c.done) return false;
    const QuadraticProfile& p = *profile_;
    const int m = p.piece_count();
    const int dir = s.dir;
    if ((dir < 0 && c.j < 0) || (dir > 0 && c.j >= m)) {
        c.done = true;
        s.length = c.t;
        if (!t1_known_) {  // passing the start exactly at the run's end
            t1_ = c.t;
            t1_known_ = true;
        }
        return false;
    }
    const PieceGeometry g = geometry(p, c.j);
    const double Np = g.b + 2.0 * g.c * (c.y - g.ylo);
    const double a_here = 0.5 * Np * inv_beta_sq_;
    const double kappa = g.c * inv_beta_sq_;
    const double lambda = g.root_c * inv_beta_;
    if (s.segments.empty()) s.segments.reserve(64);
    QuadraticSegment seg;
    seg.piece = c.j;
    seg.kappa = kappa;
    seg.lambda = lambda;
    seg.t0 = c.t;
    // The start, if this piece holds it: its run distance is the first turn's dz.
    auto mark = [&](double y_from, double y_to, auto time_to) {
        if (t1_known_) return;
        if (y0_ >= std::min(y_from, y_to) && y0_ <= std::max(y_from, y_to)) {
            t1_ = y0_ == y_from ? c.t : time_to(y0_);
            t1_known_ = true;
        }
    };
    if (s.end == SweepEnd::Vertex && c.j == end_piece_) {
        const double y_v = s.y_end;
        const double a_v = 0.5 * (g.b + 2.0 * g.c * (y_v - g.ylo)) * inv_beta_sq_;
        seg.y1 = y_v;
        if (c.at_vertex) {
            // Turning point to turning point in one piece: half an oscillation.
            MIRAGE_CHECK(kappa < 0.0);
            seg.ta = c.t;
            seg.ya = c.y;
            seg.aa = a_here;
            seg.t1 = c.t + kPi / lambda;
            mark(c.y, y_v,
                 [&](double ym) { return c.t + vertex_time(ym - c.y, a_here, kappa, lambda); });
        } else {
            seg.ta = c.t + vertex_time(c.y - y_v, a_v, kappa, lambda);
            seg.ya = y_v;
            seg.aa = a_v;
            seg.t1 = seg.ta;
            mark(c.y, y_v,
                 [&](double ym) { return seg.ta - vertex_time(ym - y_v, a_v, kappa, lambda); });
        }
        s.segments.push_back(seg);
        c.t = seg.t1;
        c.done = true;
        s.length = c.t;
        return true;
    }
    const double yb = dir > 0 ? g.yhi : g.ylo;
    const double db = yb - c.y;
    // n^2 - beta^2 at the exit: from the entry in the origin's piece, else from the knot.
    const double Qb =
        c.first ? c.Q + (Np + g.c * db) * db : p.e(dir > 0 ? c.j + 1 : c.j) - (e0_ - Q0_);
    const double s_b = dir * std::sqrt(std::max(0.0, Qb)) * inv_beta_;
    seg.ta = c.t;
    seg.ya = c.y;
    seg.sa = c.slope;
    seg.aa = a_here;
    seg.y1 = yb;
    double dt;
    if (g.yhi == kInf) {
        dt = db / c.slope;  // above the top: straight
    } else if (c.at_vertex) {
        dt = vertex_time(db, a_here, kappa, lambda);
    } else {
        dt = crossing_time(db, c.slope, s_b, a_here, kappa, lambda);
    }
    seg.t1 = c.t + dt;
    mark(c.y, yb, [&](double ym) {
        const double dm = ym - c.y;
        if (g.yhi == kInf) return c.t + dm / c.slope;
        if (c.at_vertex) return c.t + vertex_time(dm, a_here, kappa, lambda);
        const double s_m = dir * std::sqrt(Q0_) * inv_beta_;  // the start's own slope
        return c.t + crossing_time(dm, c.slope, s_m, a_here, kappa, lambda);
    });
    s.segments.push_back(seg);
    c.t = seg.t1;
    c.y = yb;
    c.Q = std::max(0.0, Qb);
    c.slope = s_b;
    c.at_vertex = false;
    c.first = false;
    c.j += dir;
    return true;
}

void QuadraticPath::cross_pieces(double t_stop) const {
    // extend()'s general case, piece after piece with the cursor in locals: the run enters
    // each piece at a knot (not at its origin or a turning point) and leaves it at the next
    // knot, before the end piece and the top; it stops before the piece holding the start
    // while the start's run distance is unknown (extend() marks it there).  The same
    // arithmetic as extend(), so the segments are the same.
    Cursor& c = cur_;
    Sweep& s = sweep_;
    if (c.done || c.first || c.at_vertex) return;
    const QuadraticProfile& p = *profile_;
    const int m = p.piece_count();
    const int dir = s.dir;
    const int stop_piece = s.end == SweepEnd::Vertex ? end_piece_ : -2;
    const double level = e0_ - Q0_;
    const std::vector<double>& knots = p.knots();
    int j = c.j;
    double y = c.y, t = c.t, slope = c.slope, Qb = c.Q;
    if (s.segments.empty()) s.segments.reserve(64);
    const bool spans = p.has_spans();
    const double beta_sq = beta_ * beta_;
    // A piece or a span (n^2 = ... + cq u^2), entered at y_in with the path's slope there
    // (np_in: d(n^2)/dy there): its segment, and the cursor moved to its far end y_out
    // (n^2 - n0^2 there: e_out).
    auto cross = [&](double y_in, double np_in, double cq, double root_c, double y_out,
                     double e_out) {
        const double a_here = 0.5 * np_in * inv_beta_sq_;
        const double kappa = cq * inv_beta_sq_;
        const double lambda = root_c * inv_beta_;
        Qb = e_out - level;
        const double s_b = dir * std::sqrt(std::max(0.0, Qb)) * inv_beta_;
        QuadraticSegment& seg = s.segments.emplace_back();
        seg.piece = j;
        seg.kappa = kappa;
        seg.lambda = lambda;
        seg.t0 = t;
        seg.ta = t;
        seg.ya = y_in;
        seg.sa = slope;
        seg.aa = a_here;
        seg.y1 = y_out;
        t += crossing_time(y_out - y_in, slope, s_b, a_here, kappa, lambda);
        seg.t1 = t;
        y = y_out;
        slope = s_b;
    };
    while (t < t_stop && j >= 0 && j < m && j != stop_piece) {
        const double ylo = knots[j], yhi = knots[j + 1];
        if (spans) {
            // The coarsest span from this knot on that this ray may cross: not holding the
            // end's piece, nor the start while its run distance is still to be found.
            int id = dir > 0 ? p.span_up(j) : p.span_down(j + 1);
            while (id >= 0) {
                const CoarseSpan& sp = p.spans()[id];
                if (beta_sq <= sp.max_beta_sq && (stop_piece < sp.lo || stop_piece >= sp.hi) &&
                    (t1_known_ || y0_ < knots[sp.lo] || y0_ > knots[sp.hi]))
                    break;
                id = dir > 0 ? sp.finer_same_lo : sp.finer_same_hi;
            }
            if (id >= 0) {
                const CoarseSpan& sp = p.spans()[id];
                span_slack_ = std::max(span_slack_, sp.slope_slack);
                ++spans_crossed_;
                if (dir > 0) {
                    cross(knots[sp.lo], sp.b, sp.c, sp.root_c, knots[sp.hi], p.e(sp.hi));
                    j = sp.hi;
                } else {
                    cross(knots[sp.hi], sp.end_slope, sp.c, sp.root_c, knots[sp.lo], p.e(sp.lo));
                    j = sp.lo - 1;
                }
                continue;
            }
        }
        if (!t1_known_ && y0_ >= ylo && y0_ <= yhi) break;
        const double np_in = p.b(j) + 2.0 * p.c(j) * (y - ylo);
        cross(y, np_in, p.c(j), p.root_abs_c(j), dir > 0 ? yhi : ylo, p.e(dir > 0 ? j + 1 : j));
        j += dir;
    }
    if (j == c.j) return;
    c.j = j;
    c.y = y;
    c.t = t;
    c.slope = slope;
    c.Q = std::max(0.0, Qb);
}

void QuadraticPath::complete() const {
    do {
        cross_pieces(kInf);
    } while (extend());
}

void QuadraticPath::ensure_time(double t) const {
    while (!cur_.done && cur_.t < t) {
        cross_pieces(t);
        if (cur_.t >= t) break;
        extend();
    }
}

void QuadraticPath::ensure_t1() const {
    while (!t1_known_) {
        cross_pieces(kInf);
        if (!extend()) break;
    }
    if (!t1_known_) {
        t1_ = sweep_.length;
        t1_known_ = true;
    }
}

const Sweep& QuadraticPath::sweep() const {
    complete();
    return sweep_;
}

double QuadraticPath::first_turn_dz() const {
    if (!vertex_ahead_) return 0.0;
    ensure_t1();
    return t1_;
}

double QuadraticPath::dz_ground() const {
    if (fate_ == PathFate::Straight) return hits_ground() ? sweep_.length : kInf;
    if (fate_ != PathFate::Ground) return kInf;
    complete();
    return (vertex_ahead_ ? first_turn_dz() : 0.0) + sweep_.length;
}

double QuadraticPath::dz_straight() const {
    if (fate_ == PathFate::Straight || fate_ == PathFate::Level) return 0.0;
    if (fate_ != PathFate::Escape) return kInf;
    complete();
    return (vertex_ahead_ ? first_turn_dz() : 0.0) + sweep_.length;
}

double QuadraticPath::run_time(double dz, int& sign) const {
    sign = 1;
    if (!vertex_ahead_) return dz;
    ensure_t1();
    if (dz <= t1_) {
        sign = -1;
        return t1_ - dz;
    }
    double tau = dz - t1_;
    if (periodic_) {
        ensure_time(tau);
        if (cur_.done && tau > sweep_.length) {
            const double period = 2.0 * sweep_.length;
            tau = std::fmod(tau, period);
            if (tau > sweep_.length) {
                sign = -1;
                return period - tau;
            }
        }
    }
    return tau;
}

const QuadraticSegment& QuadraticPath::segment_for(double t) const {
    // Queries come mostly in order: the last segment or its neighbour, else a binary search.
    const auto& segs = sweep_.segments;
    const size_t n = segs.size();
    size_t k = seg_hint_ < n ? seg_hint_ : 0;
    auto holds = [&](size_t j) { return t <= segs[j].t1 && (j == 0 || t > segs[j - 1].t1); };
    if (!holds(k)) {
        if (k + 1 < n && holds(k + 1)) {
            ++k;
        } else if (k > 0 && holds(k - 1)) {
            --k;
        } else {
            k = &segment_at(sweep_, t) - segs.data();
        }
    }
    seg_hint_ = k;
    return segs[k];
}

double QuadraticPath::height_at(double dz) const {
    if (dz == 0.0 || fate_ == PathFate::Level) return y0_;
    if (fate_ == PathFate::Straight) return y0_ + dz * slope0_;
    int sign;
    const double t = run_time(dz, sign);
    ensure_time(t);
    if (cur_.done && t >= sweep_.length) return sweep_height(sweep_, t);
    if (sweep_.segments.empty()) return sweep_.y_start;
    return segment_height(segment_for(t), t);
}

double QuadraticPath::slope_at(double dz) const {
    if (dz == 0.0 || fate_ == PathFate::Straight) return slope0_;
    if (fate_ == PathFate::Level) return 0.0;
    int sign;
    const double t = run_time(dz, sign);
    ensure_time(t);
    if (cur_.done && t >= sweep_.length) return sign * sweep_slope(sweep_, t);
    if (sweep_.segments.empty()) return sign * sweep_.end_slope;
    return sign * segment_slope(segment_for(t), t);
}

// Run distance at which segment g (of a run in direction dir) is at height y, between its
// ends: from its anchor by the closed forms, the slope at y from the segment's own quadratic
// (s^2 = s_a^2 + 2 a_a dy + kappa dy^2, which a coarse span's segment keeps as well).
double segment_time_at_height(const QuadraticSegment& g, double y, int dir) {
    const double dy = y - g.ya;
    if (dy == 0.0) return g.ta;
    if (g.sa == 0.0) {
        // Anchored at a turning point: the run's origin (a lowest point or an apex) or its end.
        const double tv = vertex_time(dy, g.aa, g.kappa, g.lambda);
        return g.ta == g.t0 ? g.ta + tv : g.ta - tv;
    }
    if (g.kappa == 0.0 && g.aa == 0.0) return g.ta + dy / g.sa;  // straight (above the top)
    const double s_y =
        dir * std::sqrt(std::max(0.0, g.sa * g.sa + (2.0 * g.aa + g.kappa * dy) * dy));
    return g.ta + crossing_time(dy, g.sa, s_y, g.aa, g.kappa, g.lambda);
}

double QuadraticPath::distance_to_height(double y) const {
    if (y == y0_) return 0.0;
    const int towards = y > y0_ ? 1 : -1;
    if (fate_ == PathFate::Level) return kInf;
    if (fate_ == PathFate::Straight) {
        if (towards != sg_ || (towards < 0 && y < 0.0)) return kInf;
        return (y - y0_) / slope0_;
    }
    const Sweep& s = sweep_;
    if (towards != sg_) return kInf;
    if (vertex_ahead_) {
        // Before the first turning point the ray runs from y0 to the sweep's origin, the
        // vertex: back along the sweep's first stretch, from its distance t1 at y0.
        if (towards * (y - s.y_start) > 0.0) return kInf;
        ensure_t1();
        if (y == s.y_start) return t1_;
        const auto& segs = s.segments;
        // The sweep leaves the vertex in direction s.dir = -sg_: its heights fall back
        // towards y0, monotone in run distance.
        for (const QuadraticSegment& g : segs) {
            if (g.t0 > t1_) break;
            if (s.dir * (g.y1 - y) >= 0.0) {
                const double t = segment_time_at_height(g, y, s.dir);
                return t1_ - std::clamp(t, g.t0, g.t1);
            }
        }
        return kInf;
    }
    // No turning point ahead: one run from the start to the ground or the top.
    complete();
    if (s.dir * (y - s.y_end) > 0.0) {
        if (s.end != SweepEnd::Top || !(s.end_slope != 0.0)) return kInf;
        return s.length + (y - s.y_end) / s.end_slope;  // straight beyond the top
    }
    const auto& segs = s.segments;
    auto it = std::lower_bound(segs.begin(), segs.end(), y, [&](const QuadraticSegment& g,
                                                                 double v) {
        return s.dir * (g.y1 - v) < 0.0;
    });
    if (it == segs.end()) return kInf;
    return std::clamp(segment_time_at_height(*it, y, s.dir), it->t0, it->t1);
}

double QuadraticPath::curvature_at_height(double y) const {
    return 0.5 * profile_->slope(y) * inv_beta_sq_;
}

double QuadraticPath::curvature_bound(double ya, double yb) const {
    // Heights between two computed points of the path: every span it crosses there has been
    // crossed, and span_slack_ covers them.
    return 0.5 * (profile_->max_abs_slope(ya, yb, hint_a_, hint_b_) + span_slack_) * inv_beta_sq_;
}

int QuadraticPath::turning_point_count() const {
    if (!vertex_ahead_) return 0;
    if (periodic_) return -1;
    return 1;
}

TurningPoint QuadraticPath::turning_point(int k) const {
    MIRAGE_CHECK(vertex_ahead_ && k >= 0 && (periodic_ || k == 0));
    TurningPoint tp;
    if (k > 0) complete();
    tp.dz = first_turn_dz() + k * sweep_.length;
    tp.y = k % 2 == 0 ? sweep_.y_start : sweep_.y_end;
    // Once: a lowest point when the path rises after it.  Trapped: the lower of the two
    // turning heights is the lowest point.
    if (periodic_) {
        tp.lowest = k % 2 == 0 ? sweep_.y_start < sweep_.y_end : sweep_.y_end < sweep_.y_start;
    } else {
        tp.lowest = sweep_.dir > 0;
    }
    return tp;
}

bool QuadraticPath::turning_point_before(int k, double dz, TurningPoint& tp) const {
    if (!vertex_ahead_ || k < 0 || (k > 0 && !periodic_)) return false;
    if (k > 0) {
        // The k-th lies at t1 + k L, L the run's length, which is at least the part computed.
        const double t1 = first_turn_dz();
        while (!cur_.done && t1 + k * cur_.t < dz) {
            cross_pieces((dz - t1) / k);
            if (t1 + k * cur_.t < dz) extend();
        }
        if (!cur_.done) return false;
    }
    tp = turning_point(k);
    return tp.dz < dz;
}

int QuadraticPath::first_turning_point_after(double dz) const {
    if (!vertex_ahead_) return -1;
    if (dz <= first_turn_dz()) return 0;
    if (!periodic_) return -1;
    complete();
    return static_cast<int>(std::ceil((dz - t1_) / sweep_.length));
}

double QuadraticPath::asymptote_departure(double dz) const {
    if (fate_ == PathFate::Straight || fate_ == PathFate::Level) return 0.0;
    if (fate_ != PathFate::Escape) return kInf;
    if (vertex_ahead_ && dz < first_turn_dz()) return kInf;
    const QuadraticProfile& p = *profile_;
    const double y = height_at(dz);
    if (y >= p.top()) return 0.0;
    // |1 - s_inf / s| = |1 - sqrt(Q_top / Q)| over Q = e - level on [y, top].
    const double q_top = p.e(p.piece_count()) - (e0_ - Q0_);
    double q_lo, q_hi;
    q_range(y, p.top(), q_lo, q_hi);
    if (!(q_lo > 0.0)) return kInf;
    const double worst = std::max(std::fabs(1.0 - std::sqrt(q_top / q_lo)),
                                  std::fabs(1.0 - std::sqrt(q_top / q_hi)));
    return (p.top() - y) * worst;
}

void QuadraticPath::q_range(double ya, double yb, double& q_lo, double& q_hi) const {
    // n^2 - beta^2 = e - level, e = n^2 - n0^2.
    const double level = e0_ - Q0_;
    double e_lo, e_hi;
    profile_->excess_range(ya, yb, e_lo, e_hi);
    q_lo = e_lo - level;
    q_hi = e_hi - level;
    if (profile_->has_spans()) {  // where the ray crosses spans instead of pieces
        q_lo *= 1.0 - QuadraticProfile::kSpanShareOfQ;
        q_hi *= 1.0 + QuadraticProfile::kSpanShareOfQ;
    }
}

void QuadraticPath::abs_slope_bounds(double ya, double yb, double& lo, double& hi) const {
    // |dy/dz| = sqrt(n^2 - beta^2) / beta.
    double q_lo, q_hi;
    q_range(ya, yb, q_lo, q_hi);
    lo = std::sqrt(std::max(0.0, q_lo)) * inv_beta_;
    hi = std::sqrt(std::max(0.0, q_hi)) * inv_beta_;
}

std::vector<QuadraticSegment> QuadraticPath::release_storage() {
    std::vector<QuadraticSegment> out = std::move(sweep_.segments);
    out.clear();
    sweep_.segments.clear();
    return out;
}

void QuadraticPath::adopt_storage(std::vector<QuadraticSegment>&& storage) {
    if (!sweep_.segments.empty() || storage.capacity() <= sweep_.segments.capacity()) return;
    storage.clear();
    sweep_.segments = std::move(storage);
}

}  // namespace mirage
