#include "atmosphere/quadratic_profile.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "util/check.h"
#include "util/format.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Sparse table over `values`: level k holds the max (or min) of 2^k consecutive entries.
std::vector<std::vector<double>> sparse_table(std::vector<double> values, bool take_max) {
    std::vector<std::vector<double>> t;
    t.push_back(std::move(values));
    for (size_t len = 2; len <= t[0].size(); len *= 2) {
        const auto& prev = t.back();
        std::vector<double> level(t[0].size() - len + 1);
        for (size_t i = 0; i < level.size(); ++i) {
            const double a = prev[i], b = prev[i + len / 2];
            level[i] = take_max ? std::max(a, b) : std::min(a, b);
        }
        t.push_back(std::move(level));
    }
    return t;
}

// The max (min) of entries l..r (inclusive, l <= r) of a sparse table.
double query(const std::vector<std::vector<double>>& t, int l, int r, bool take_max) {
    const int len = r - l + 1;
    const int k = static_cast<int>(std::bit_width(static_cast<unsigned>(len))) - 1;
    const double a = t[k][l], b = t[k][r - (1 << k) + 1];
    return take_max ? std::max(a, b) : std::min(a, b);
}

// Smallest and largest of e + b u + c u^2 over [u1, u2].
void quadratic_range(double e, double b, double c, double u1, double u2, double& lo, double& hi) {
    auto v = [&](double u) { return e + (b + c * u) * u; };
    lo = std::min(v(u1), v(u2));
    hi = std::max(v(u1), v(u2));
    if (c != 0.0) {
        const double us = -b / (2.0 * c);
        if (us > u1 && us < u2) {
            lo = std::min(lo, v(us));
            hi = std::max(hi, v(us));
        }
    }
}

}  // namespace

Result<QuadraticProfile> QuadraticProfile::make(std::vector<double> knots,
                                                std::vector<double> slopes,
                                                std::vector<double> curvatures, double n0_sq,
                                                double earth_radius) {
    if (knots.size() < 2) return make_error("a quadratic profile needs at least two knots");
    if (slopes.size() + 1 != knots.size() || curvatures.size() + 1 != knots.size())
        return make_error("a quadratic profile needs one slope and one curvature per piece");
    if (knots[0] != 0.0) return make_error("the first knot of a quadratic profile must be at 0 m");
    if (!(std::isfinite(n0_sq) && n0_sq > 0.0))
        return make_error("n^2 at the ground " + shortest(n0_sq) + " must be finite and > 0");
    if (!(std::isfinite(earth_radius) && earth_radius >= 0.0))
        return make_error("Earth radius " + shortest(earth_radius) + " m must be >= 0");
    for (size_t j = 0; j + 1 < knots.size(); ++j) {
        if (!(knots[j + 1] > knots[j]) || !std::isfinite(knots[j + 1]))
            return make_error("knots of a quadratic profile must increase: " + shortest(knots[j]) +
                              " m then " + shortest(knots[j + 1]) + " m");
        if (!std::isfinite(slopes[j]) || !std::isfinite(curvatures[j]))
            return make_error("piece " + std::to_string(j) +
                              " of a quadratic profile is not finite");
    }
    QuadraticProfile p;
    p.y_ = std::move(knots);
    p.b_ = std::move(slopes);
    p.c_ = std::move(curvatures);
    p.n0_sq_ = n0_sq;
    p.earth_radius_ = earth_radius;
    const size_t m = p.b_.size();
    p.e_.assign(m + 1, 0.0);
    p.inc_.assign(m, 0.0);
    p.end_slope_.assign(m, 0.0);
    p.root_abs_c_.assign(m, 0.0);
    for (size_t j = 0; j < m; ++j) {
        const double h = p.y_[j + 1] - p.y_[j];
        p.inc_[j] = (p.b_[j] + p.c_[j] * h) * h;
        p.end_slope_[j] = p.b_[j] + 2.0 * p.c_[j] * h;
        p.root_abs_c_[j] = std::sqrt(std::fabs(p.c_[j]));
        p.e_[j + 1] = p.e_[j] + p.inc_[j];
        if (p.b_[j] != 0.0 || p.c_[j] != 0.0) p.homogeneous_ = false;
    }
    p.build_tables();
    double lo = 0.0, hi = 0.0;
    p.excess_range(0.0, p.top(), lo, hi);
    if (!(n0_sq + lo > 0.0))
        return make_error("the quadratic profile's n^2 falls to " + shortest(n0_sq + lo) +
                          ": it must stay positive");
    return p;
}

void QuadraticProfile::build_tables() {
    const int m = piece_count();
    std::vector<double> ks(m + 1, 0.0), mins(m), maxs(m);
    for (int j = 0; j <= m; ++j) {
        double s = 0.0;
        if (j < m) s = std::fabs(b_[j]);
        if (j > 0) {
            const double h = y_[j] - y_[j - 1];
            s = std::max(s, std::fabs(b_[j - 1] + 2.0 * c_[j - 1] * h));
        }
        ks[j] = s;
    }
    for (int j = 0; j < m; ++j)
        quadratic_range(e_[j], b_[j], c_[j], 0.0, y_[j + 1] - y_[j], mins[j], maxs[j]);
    knot_slope_max_ = sparse_table(std::move(ks), true);
    piece_min_ = sparse_table(std::move(mins), false);
    piece_max_ = sparse_table(std::move(maxs), true);
}

Result<QuadraticProfile> QuadraticProfile::rescaled(double unit) const {
    std::vector<double> knots(y_.size()), slopes(b_.size()), curvatures(c_.size());
    for (size_t j = 0; j < knots.size(); ++j) knots[j] = y_[j] / unit;
    for (size_t j = 0; j < b_.size(); ++j) {
        slopes[j] = b_[j] * unit;  // d(n^2)/dy per unit: per metre times metres per unit
        curvatures[j] = c_[j] * unit * unit;
    }
    auto p = make(std::move(knots), std::move(slopes), std::move(curvatures), n0_sq_,
                  earth_radius_ / unit);
    if (!p) return p.error();
    p->sky_at_top_ = sky_at_top_;
    if (!spans_.empty()) {
        p->spans_ = spans_;
        for (CoarseSpan& sp : p->spans_) {
            sp.b *= unit;
            sp.c *= unit * unit;
            sp.root_c *= unit;
            sp.end_slope *= unit;
            sp.slope_slack *= unit;
        }
        p->span_up_ = span_up_;
        p->span_down_ = span_down_;
    }
    return p;
}

int QuadraticProfile::piece_from(double y, int hint) const {
    const int m = piece_count();
    if (!(y >= 0.0)) return -1;
    if (y >= y_[m]) return m;
    // Bracket y between knots lo and hi (y_[lo] <= y < y_[hi]) by steps doubling from the hint.
    int lo = hint, hi = hint + 1;
    if (y >= y_[hint]) {
        for (int step = 1; y >= y_[hi]; step *= 2) {
            lo = hi;
            hi = std::min(m, hi + step);
        }
    } else {
        hi = hint;
        lo = hint - 1;
        for (int step = 1; y < y_[lo]; step *= 2) {
            hi = lo;
            lo = std::max(0, lo - step);
        }
    }
    while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        if (y >= y_[mid]) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

int QuadraticProfile::piece_at(double y) const {
    if (y < 0.0) return -1;
    if (y >= y_.back()) return piece_count();
    return static_cast<int>(std::upper_bound(y_.begin(), y_.end(), y) - y_.begin()) - 1;
}

double QuadraticProfile::excess(double y) const {
    const int j = piece_at(y);
    if (j < 0) return piece_value(0, y);
    if (j >= piece_count()) return e_.back();
    return piece_value(j, y - y_[j]);
}

double QuadraticProfile::n(double y) const { return std::sqrt(n_sq(y)); }

double QuadraticProfile::slope(double y) const {
    const int j = piece_at(y);
    if (j < 0) return b_[0] + 2.0 * c_[0] * y;
    if (j >= piece_count()) return 0.0;
    return b_[j] + 2.0 * c_[j] * (y - y_[j]);
}

double QuadraticProfile::max_abs_slope(double ya, double yb) const {
    int a = -1, b = -1;
    return max_abs_slope(ya, yb, a, b);
}

double QuadraticProfile::max_abs_slope(double ya, double yb, int& hint_a, int& hint_b) const {
    if (ya > yb) {
        std::swap(ya, yb);
        std::swap(hint_a, hint_b);
    }
    ya = std::max(ya, 0.0);
    yb = std::max(yb, 0.0);
    const int m = piece_count();
    const int ja = hint_a = piece_at(ya, hint_a);
    const int jb = hint_b = yb == ya ? ja : piece_at(yb, hint_b);
    auto slope_in = [&](int j, double y) {
        return j >= m ? 0.0 : b_[j] + 2.0 * c_[j] * (y - y_[j]);
    };
    double s = std::max(std::fabs(slope_in(ja, ya)), std::fabs(slope_in(jb, yb)));
    if (jb > ja) s = std::max(s, query(knot_slope_max_, ja + 1, std::min(jb, m), true));
    return s;
}

void QuadraticProfile::n_sq_range(double ya, double yb, double& lo, double& hi) const {
    excess_range(ya, yb, lo, hi);
    lo += n0_sq_;
    hi += n0_sq_;
}

int QuadraticProfile::find_piece_reaching(int j, int dir, double level) const {
    const int m = piece_count();
    const auto& t = piece_min_;
    const int levels = static_cast<int>(t.size());
    if (dir > 0) {
        if (j < 0) j = 0;
        if (j >= m) return m;
        if (t[0][j] <= level) return j;
        int pos = j + 1;
        for (int L = levels - 1; L >= 0; --L) {
            const int len = 1 << L;
            if (pos + len <= m && t[L][pos] > level) pos += len;
        }
        return pos;  // m when none
    }
    if (j >= m) j = m - 1;
    if (j < 0) return -1;
    if (t[0][j] <= level) return j;
    int pos = j - 1;
    for (int L = levels - 1; L >= 0; --L) {
        const int len = 1 << L;
        if (pos - len + 1 >= 0 && t[L][pos - len + 1] > level) pos -= len;
    }
    return pos;  // -1 when none
}

void QuadraticProfile::excess_range(double ya, double yb, double& lo, double& hi) const {
    if (ya > yb) std::swap(ya, yb);
    ya = std::max(ya, 0.0);
    yb = std::max(yb, 0.0);
    const int m = piece_count();
    const int ja = piece_at(ya), jb = piece_at(yb);
    lo = kInf;
    hi = -kInf;
    auto add = [&](double l, double h) {
        lo = std::min(lo, l);
        hi = std::max(hi, h);
    };
    auto partial = [&](int j, double y1, double y2) {
        if (j >= m) {
            add(e_.back(), e_.back());
            return;
        }
        double l, h;
        quadratic_range(e_[j], b_[j], c_[j], y1 - y_[j], y2 - y_[j], l, h);
        add(l, h);
    };
    if (ja == jb) {
        partial(ja, ya, yb);
    } else {
        partial(ja, ya, y_[ja + 1]);
        if (jb >= m) {
            add(e_.back(), e_.back());
        } else {
            partial(jb, y_[jb], yb);
        }
        const int last_full = std::min(jb, m) - 1;
        if (last_full >= ja + 1) {
            add(query(piece_min_, ja + 1, last_full, false),
                query(piece_max_, ja + 1, last_full, true));
        }
    }
}

namespace {

// The largest error of the interval's two quadratics at the checked heights, in n.
struct Trial {
    double err = 0.0, err_y = 0.0, s_mid = 0.0, c_left = 0.0, c_right = 0.0;
    bool finite = true;
};

/// The Hermite interpolant on [a, b] with its midpoint knot, checked against the profile.
template <class Excess>
Trial trial(const ProfileFunction& f, Excess& excess, double a, double b, double fa, double sa,
            double fb, double sb) {
    Trial t;
    const double h = b - a, mid = a + 0.5 * h;
    // Schumaker's midpoint knot: the slope there makes the two halves meet.
    t.s_mid = 2.0 * (fb - fa) / h - 0.5 * (sa + sb);
    t.c_left = (t.s_mid - sa) / h;
    t.c_right = (sb - t.s_mid) / h;
    const double f_mid = fa + (sa + t.c_left * 0.5 * h) * 0.5 * h;
    t.finite = std::isfinite(t.s_mid) && std::isfinite(f_mid);
    constexpr int kChecks = 12;
    for (int side = 0; side < 2 && t.finite; ++side) {
        for (int q = (side == 0 ? 1 : 0); q < kChecks; ++q) {
            const double u = 0.5 * h * q / kChecks;
            const double y = (side == 0 ? a : mid) + u;
            const double fit =
                side == 0 ? fa + (sa + t.c_left * u) * u : f_mid + (t.s_mid + t.c_right * u) * u;
            const double truth = excess(y);
            if (!std::isfinite(truth)) {
                t.finite = false;
                break;
            }
            const double dn =
                std::fabs(fit - truth) / (std::sqrt(f.n0_sq + fit) + std::sqrt(f.n0_sq + truth));
            if (dn > t.err) {
                t.err = dn;
                t.err_y = y;
            }
        }
    }
    return t;
}

/// The fine model's pieces, marched up each smooth stretch between `edges`.
struct FinePieces {
    std::vector<double> knots{0.0}, slopes, curvatures;
    std::vector<int> edge_knots{0};  // the knots at the ends of the smooth stretches
    double worst = 0.0, worst_y = 0.0;
};

/// Fits the pieces; `fail(height, why)` makes the error of a profile that cannot be fitted.
template <class Excess, class Fail>
Result<FinePieces> fit_pieces(const ProfileFunction& f, const FitSettings& settings,
                              const std::vector<double>& edges, Excess& excess, Fail fail) {
    FinePieces fp;
    // Marching from the bottom of each smooth stretch with step-size control: the error of
    // the interpolant grows as h^3, so the next interval's length is predicted from the last
    // error.  An interval is kept when its checked error is within 0.9 of the tolerance (the
    // error is smooth, and 23 checked heights find its maximum to about 1 %).
    const double accept = 0.9 * settings.tolerance_n;
    for (size_t k = 0; k + 1 < edges.size(); ++k) {
        const double A = edges[k], B = edges[k + 1];
        double a = A, fa = excess(A), sa = f.excess_slope(A, +1);
        double h = B - A;
        while (a < B) {
            double b = a + h;
            if (b > B - 0.1 * h) b = B;
            const double fb = excess(b);
            const double sb = b == B ? f.excess_slope(B, -1) : f.excess_slope(b, +1);
            const Trial t = trial(f, excess, a, b, fa, sa, fb, sb);
            if (!t.finite)
                return fail(0.5 * (a + b),
                            "the profile is not finite near " + shortest(0.5 * (a + b)) + " m");
            const double hb = b - a;
            const double ratio = t.err > 0.0 ? std::cbrt(0.7 * settings.tolerance_n / t.err) : 2.0;
            if (t.err > accept) {
                if (hb * 0.5 < settings.min_interval)
                    return fail(t.err_y, "the profile changes too fast near " + sig(t.err_y, 6) +
                                             " m to be fitted within " +
                                             shortest(settings.tolerance_n) +
                                             " in n (intervals of " + sig(hb, 3) +
                                             " m still miss by " + sig(t.err, 3) + ")");
                h = hb * std::clamp(ratio, 0.1, 0.9);
                continue;
            }
            fp.knots.push_back(a + 0.5 * hb);
            fp.knots.push_back(b);
            fp.slopes.push_back(sa);
            fp.curvatures.push_back(t.c_left);
            fp.slopes.push_back(t.s_mid);
            fp.curvatures.push_back(t.c_right);
            if (t.err > fp.worst) {
                fp.worst = t.err;
                fp.worst_y = t.err_y;
            }
            if (static_cast<int>(fp.slopes.size()) > settings.max_pieces)
                return fail(b, "the profile needs more than " +
                                   std::to_string(settings.max_pieces) +
                                   " pieces to be fitted within " + shortest(settings.tolerance_n) +
                                   " in n");
            a = b;
            fa = fb;
            sa = b == B ? sa : sb;
            h = hb * std::clamp(ratio, 0.5, 4.0);
        }
        fp.edge_knots.push_back(static_cast<int>(fp.knots.size()) - 1);
    }
    return fp;
}

}  // namespace

void QuadraticProfile::add_coarse_spans(const ProfileFunction& f, const FitSettings& settings,
                                        const std::vector<int>& edge_knots,
                                        const std::function<double(double)>& excess, long& checks) {
    QuadraticProfile& q = *this;
    auto n_of = [&](double e) { return std::sqrt(f.n0_sq + e); };
    const int m = q.piece_count();
    // Spans do not cross a breakpoint where the profile's slope jumps (a corner).
    std::vector<char> edge(m + 1, 0);
    for (int k : edge_knots) {
        if (k == 0 || k == m) continue;
        const double y = q.y_[k];
        const double left = f.excess_slope(y, -1), right = f.excess_slope(y, +1);
        if (!(std::fabs(left - right) <= 1e-9 * std::max(std::fabs(left), std::fabs(right))))
            edge[k] = 1;
    }
    const double eps = settings.tolerance_n;
    // The fine model's bound on directions, the share of it a span may use.
    const double bound = settings.span_allowance * M_PI * std::sqrt(eps);
    q.span_up_.assign(m + 1, -1);
    q.span_down_.assign(m + 1, -1);
    // The profile at every fine knot and halfway between them, once: a span checks its
    // error at those inside it.
    std::vector<double> at_knot(m + 1), at_middle(m);
    for (int k = 0; k <= m; ++k) at_knot[k] = excess(q.y_[k]);
    for (int k = 0; k < m; ++k) at_middle[k] = excess(0.5 * (q.y_[k] + q.y_[k + 1]));
    // The span over the fine knots lo..hi, or none when it is no use to any ray.
    auto make_span = [&](int lo, int hi, CoarseSpan& sp) {
        const double a = q.y_[lo], h = q.y_[hi] - a;
        const double fa = q.e_[lo], fb = q.e_[hi], fm = excess(a + 0.5 * h);
        if (!std::isfinite(fm)) return false;
        sp.lo = lo;
        sp.hi = hi;
        sp.c = 2.0 * (fb - 2.0 * fm + fa) / (h * h);
        sp.b = (fb - fa) / h - sp.c * h;
        sp.root_c = std::sqrt(std::fabs(sp.c));
        sp.end_slope = sp.b + 2.0 * sp.c * h;
        // Its error: at 23 heights evenly apart, and at every knot of the fine model inside
        // it and halfway between them (where the profile's curvature may change: a
        // breakpoint where only the slope is continuous).
        double err = 0.0;
        bool finite = true;
        auto check = [&](double y, double truth) {
            const double u = y - a;
            const double fit = fa + (sp.b + sp.c * u) * u;
            if (!std::isfinite(truth)) finite = false;
            err = std::max(err, std::fabs(fit - truth) / (n_of(fit) + n_of(truth)));
        };
        constexpr int kChecks = 24;
        for (int k = 1; k < kChecks; ++k) {
            const double y = a + h * k / kChecks;
            check(y, excess(y));
        }
        for (int j = lo; j < hi; ++j) {
            if (j > lo) check(q.y_[j], at_knot[j]);
            check(0.5 * (q.y_[j] + q.y_[j + 1]), at_middle[j]);
        }
        checks += 2 * (hi - lo);
        if (!finite) return false;
        // Within 0.9 of the bound, as the fine fit's intervals; never below the rounding of n.
        sp.error_n = std::max(err / 0.9, 8.0 * std::numeric_limits<double>::epsilon());
        double lo_sq, hi_sq;
        q.n_sq_range(a, a + h, lo_sq, hi_sq);
        const double D = 1.01 * (eps + sp.error_n);
        const double direction = lo_sq - 4.02 * eps - hi_sq * (3.0 * D + D * D / (bound * bound));
        const double share = lo_sq - 2.02 * (eps + sp.error_n) / QuadraticProfile::kSpanShareOfQ;
        sp.max_beta_sq = std::min(direction, share);
        return sp.max_beta_sq > 0.0;
    };
    // Spans of 1, 2, 4, 8, ... fine intervals, so that a ray can step over as many as its
    // direction allows wherever it is: from every node (the fine intervals' ends) in a
    // model of up to kSpansFromEveryNode intervals.  In a larger one those of up to
    // kSpanStarts intervals start at every node, longer ones of len intervals at every (len /
    // kSpanStarts)-th: a ray crosses a long stretch in a few more steps, and the spans cost
    // O(kSpanStarts) checks of each fine interval per length, O(m log m) in all (from every
    // node they cost O(m^2): 10^4 sounding rows took minutes).
    std::vector<int> nodes;
    for (int k = 0; k <= m; k += 2) nodes.push_back(k);
    const int intervals = static_cast<int>(nodes.size()) - 1;
    std::vector<int> edges_before(nodes.size(), 0);  // edges among nodes[1..i]
    for (size_t i = 1; i < nodes.size(); ++i)
        edges_before[i] = edges_before[i - 1] + (i + 1 < nodes.size() && edge[nodes[i]]);
    constexpr int kSpansFromEveryNode = 2048, kSpanStarts = 8;
    for (int len = 1; len <= intervals; len *= 2) {
        bool any = false;
        const int stride = intervals <= kSpansFromEveryNode ? 1 : std::max(1, len / kSpanStarts);
        for (int i = 0; i + len <= intervals; i += stride) {
            // No corner strictly inside.
            if (edges_before[i + len - 1] - edges_before[i] > 0) continue;
            CoarseSpan sp;
            if (!make_span(nodes[i], nodes[i + len], sp)) continue;
            any = true;
            const int id = static_cast<int>(q.spans_.size());
            sp.finer_same_lo = q.span_up_[sp.lo];
            sp.finer_same_hi = q.span_down_[sp.hi];
            q.span_up_[sp.lo] = id;
            q.span_down_[sp.hi] = id;
            // How far its slope departs from the pieces' over the pieces it covers (both
            // linear there: at the pieces' ends).
            for (int j = sp.lo; j < sp.hi; ++j) {
                for (int end = 0; end < 2; ++end) {
                    const double u = q.y_[j + end] - q.y_[j];
                    const double piece = q.b_[j] + 2.0 * q.c_[j] * u;
                    const double span = sp.b + 2.0 * sp.c * (q.y_[j + end] - q.y_[sp.lo]);
                    sp.slope_slack = std::max(sp.slope_slack, std::fabs(span - piece));
                }
            }
            q.spans_.push_back(sp);
        }
        if (!any) break;
    }
}

Result<QuadraticProfile> fit_quadratic_profile(const ProfileFunction& f,
                                               const FitSettings& settings, FitReport* report) {
    MIRAGE_CHECK(f.excess && f.excess_slope);
    if (!(f.top > 0.0 && std::isfinite(f.top)))
        return make_error("the profile's top " + shortest(f.top) + " m must be finite and > 0");
    if (!(settings.tolerance_n > 0.0))
        return make_error("fit tolerance " + shortest(settings.tolerance_n) + " must be > 0");
    std::vector<double> edges{0.0};
    for (double b : f.breakpoints) {
        if (b > 0.0 && b < f.top) edges.push_back(b);
    }
    edges.push_back(f.top);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    // The fit's work for the report: every evaluation of the profile goes through here, and
    // every comparison with a value evaluated before is counted too.
    long checks = 0;
    std::function<double(double)> excess = [&](double y) {
        ++checks;
        return f.excess(y);
    };
    auto failed = [&](double y, const std::string& why) {
        if (report) {
            report->checks = checks;
            report->failure_height = y;
        }
        return make_error(why);
    };
    auto fp = fit_pieces(f, settings, edges, excess, failed);
    if (!fp) return fp.error();
    auto model = QuadraticProfile::make(std::move(fp->knots), std::move(fp->slopes),
                                        std::move(fp->curvatures), f.n0_sq, f.earth_radius);
    if (!model) return model.error();
    if (settings.coarse_spans) model->add_coarse_spans(f, settings, fp->edge_knots, excess, checks);
    if (report) {
        report->pieces = model->piece_count();
        report->max_error_n = fp->worst;
        report->worst_height = fp->worst_y;
        report->checks = checks;
    }
    return model;
}

std::vector<Duct> find_ducts(const QuadraticProfile& p) {
    std::vector<Duct> ducts;
    const int m = p.piece_count();
    // Local maxima of n^2: inside a piece (c < 0, vertex inside) or at a knot where the slope
    // goes from positive to non-positive.
    std::vector<double> peaks;
    for (int j = 0; j < m; ++j) {
        const double h = p.knot(j + 1) - p.knot(j);
        if (p.c(j) < 0.0) {
            const double us = -p.b(j) / (2.0 * p.c(j));
            if (us > 0.0 && us < h) peaks.push_back(p.knot(j) + us);
        }
        if (j > 0) {
            const double left = p.b(j - 1) + 2.0 * p.c(j - 1) * (p.knot(j) - p.knot(j - 1));
            if (left > 0.0 && p.b(j) <= 0.0 && !(p.b(j) == 0.0 && p.c(j) > 0.0))
                peaks.push_back(p.knot(j));
        }
    }
    // The top is where n^2 stops changing; a peak there is no duct (the sky side is flat).
    for (double y : peaks) {
        double lo_below, hi_below, lo_above, hi_above;
        p.n_sq_range(0.0, y, lo_below, hi_below);
        p.n_sq_range(y, p.top(), lo_above, hi_above);
        const double spill = std::max(lo_below, lo_above);
        const double peak = p.n_sq(y);
        if (!(peak > spill)) continue;
        // The edges: the nearest heights below and above the peak where n^2 falls to the
        // spill level.
        auto edge = [&](int dir) {
            double y_here = y;
            int j = std::min(p.piece_at(y), m - 1);
            if (dir < 0 && j > 0 && p.knot(j) == y) --j;  // a peak on a knot: start below it
            for (; j >= 0 && j < m; j += dir) {
                const double y_end = dir > 0 ? p.knot(j + 1) : p.knot(j);
                const double lo_y = std::min(y_here, y_end), hi_y = std::max(y_here, y_end);
                double lo, hi;
                p.n_sq_range(lo_y, hi_y, lo, hi);
                if (lo <= spill) {
                    // Where n^2 is smallest on this stretch, and the start of the monotone
                    // descent to it (after a maximum inside the stretch, if there is one).
                    const double u_vertex = p.c(j) != 0.0 ? -p.b(j) / (2.0 * p.c(j)) : kInf;
                    const double y_vertex = p.knot(j) + u_vertex;
                    const bool inside = y_vertex > lo_y && y_vertex < hi_y;
                    double y_min = p.n_sq(y_end) <= p.n_sq(y_here) ? y_end : y_here;
                    double y_from = y_here;
                    if (inside && p.c(j) > 0.0) y_min = y_vertex;
                    if (inside && p.c(j) < 0.0) y_from = y_vertex;
                    double a = y_from, b = y_min;  // n^2(a) > spill >= n^2(b)
                    for (int it = 0; it < 200 && a != b; ++it) {
                        const double mid = 0.5 * (a + b);
                        if (mid == a || mid == b) break;
                        if (p.n_sq(mid) > spill) {
                            a = mid;
                        } else {
                            b = mid;
                        }
                    }
                    return 0.5 * (a + b);
                }
                y_here = y_end;
            }
            return y_here;
        };
        Duct d;
        d.peak = y;
        d.peak_sq = peak;
        d.spill_sq = spill;
        d.bottom = edge(-1);
        d.top = edge(+1);
        bool merged = false;
        for (auto& other : ducts) {
            if (std::fabs(other.bottom - d.bottom) < 1e-9 && std::fabs(other.top - d.top) < 1e-9) {
                if (d.peak_sq > other.peak_sq) other = d;
                merged = true;
            }
        }
        if (!merged) ducts.push_back(d);
    }
    std::sort(ducts.begin(), ducts.end(),
              [](const Duct& a, const Duct& b) { return a.bottom < b.bottom; });
    return ducts;
}

}  // namespace mirage
