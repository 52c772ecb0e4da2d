#include "layers/fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "atmosphere/exact_ray.h"
#include "layers/outcome.h"
#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Distance t from the eye into one side: y = y0 - sgn t (sgn = +1 below the eye).
struct Side {
    double y0 = 0.0;
    int sgn = 1;
    double y(double t) const { return y0 - sgn * t; }
};

// Whether indices are kept on POV-Ray's float grid (LayerFitSettings::pov_float_grid), for the
// fit running on this thread.
thread_local bool g_float_grid = true;

// POV-Ray keeps each layer's ior (its index over the camera layer's) as a float, so only
// indices on that grid exist in a render: eta^2 - eta0^2 of the float nearest u's index.
double snap_excess(double eta0, double u_cam, double u) {
    if (!g_float_grid) return u;
    const double n_cam = std::sqrt(eta0 * eta0 + u_cam);
    const float f = static_cast<float>(std::sqrt(eta0 * eta0 + u) / n_cam);
    const double fd = f;
    // (n_cam f)^2 - eta0^2 without cancellation.
    return u_cam * fd * fd + eta0 * eta0 * (fd - 1.0) * (fd + 1.0);
}

// The smallest index on the float grid strictly above u.
double snap_above(double eta0, double u_cam, double u) {
    if (!g_float_grid) return std::nextafter(u, std::numeric_limits<double>::infinity());
    const double n_cam = std::sqrt(eta0 * eta0 + u_cam);
    float f = static_cast<float>(std::sqrt(eta0 * eta0 + u) / n_cam);
    double v =
        snap_excess(eta0, u_cam, eta0 * eta0 * (double(f) * f - 1.0) + u_cam * double(f) * f);
    while (!(v > u)) {
        f = std::nextafter(f, 2.0f);
        const double fd = f;
        v = u_cam * fd * fd + eta0 * eta0 * (fd - 1.0) * (fd + 1.0);
    }
    return v;
}

// Index fractions of a gap tried for a new layer, as in the 2D study: dense near both ends.
std::vector<double> gap_fractions() {
    std::vector<double> f;
    for (int i = 0; i < 8; ++i) f.push_back(1e-3 * std::pow(50.0, i / 7.0));
    for (int i = 1; i < 19; ++i) f.push_back(0.05 * i);
    for (int i = 7; i >= 0; --i) f.push_back(1.0 - 1e-3 * std::pow(50.0, i / 7.0));
    std::sort(f.begin(), f.end());
    f.erase(std::unique(f.begin(), f.end()), f.end());
    return f;
}

// The one-way side: boundaries at t'_j, layer j beyond boundary j has excess u[j]; the eye
// layer is before the first boundary.  `ground` is the t' of the ground on that side (inf
// when the side is the sky).
struct OneWay {
    std::vector<double> t;
    std::vector<double> u;
    double ground = kInf;
};

// Horizontal distance a ray of invariant (B, beta) needs to cross the one-way side's layers,
// from the eye height: z at each boundary and at the ground.
void climb_profile(const OneWay& ow, double u_eye, double B, double beta, std::vector<double>& z,
                   double& ground_z) {
    z.clear();
    double zc = 0.0, tc = 0.0, u = u_eye;
    ground_z = kInf;
    for (size_t j = 0; j <= ow.t.size(); ++j) {
        const double t_next = j < ow.t.size() ? ow.t[j] : kInf;
        const double slope = std::sqrt(std::max(0.0, u - B)) / beta;
        const double t_stop = std::min(t_next, ow.ground);
        if (t_stop > tc) {
            const double run = slope > 0.0 ? (t_stop - tc) / slope : kInf;
            if (t_stop == ow.ground && ow.ground <= t_next) {
                ground_z = zc + run;
                return;
            }
            zc += run;
        }
        if (j == ow.t.size()) return;
        z.push_back(zc);
        tc = t_next;
        u = ow.u[j];
    }
}

struct FitRay {
    int id = 0;
    double B = 0.0, beta = 1.0, R = 0.0, px = 0.0;
    double theta_exact = 0.0;
    double t_turn = kInf;          // exact turning point's distance into the turning side
    std::vector<double> climb_z;   // one-way side: z from the return point to each boundary
    double climb_ground_z = kInf;  // one-way side: z from the return point to the ground
    double z_in = 0.0;             // z where the ray reaches the current layer's near boundary
    std::vector<double> zd;        // z at each turning-side boundary passed (zd[0] = 0, the eye)
    // Rays that do not turn inside the atmosphere (they leave it, or reach the ground, still
    // heading into the turning side): nothing downstream compensates their errors, so each
    // boundary must be crossed close to where the exact path crosses its height.
    bool one_way = false;
    ExactRay exact;
    double z_tol = kInf;  // allowed error of the crossing distance, m
};

class SequentialFit {
  public:
    SequentialFit(const Profile& p, double y0, int sgn_turn, double u_eye, double u_far,
                  const OneWay& ow, double tol_px)
        : profile_(p),
          y0_(y0),
          turn_{y0, sgn_turn},
          one_{y0, -sgn_turn},
          u_eye_(u_eye),
          u_far_(u_far),
          ow_(ow),
          tol_(tol_px) {}

    void add_ray(FitRay r) { rays_.push_back(std::move(r)); }
    /// A ray that crosses every layer of the turning side and ends on the ground there.
    void add_passing_ray(FitRay r) { passing_.push_back(std::move(r)); }

    // Runs the fit; returns the boundaries' t (outward) and the excess of the layer before
    // each boundary (the eye layer's first).
    void run(const std::vector<double>* fixed_u) {
        std::sort(rays_.begin(), rays_.end(),
                  [](const FitRay& a, const FitRay& b) { return a.B > b.B; });
        T_ = {0.0};
        for (auto& r : rays_) r.zd = {0.0};
        std::vector<int> queue(rays_.size());
        for (size_t i = 0; i < rays_.size(); ++i) queue[i] = static_cast<int>(i);
        double t_cur = 0.0;
        double prev_B = kInf;
        const double t_limit = turn_.sgn > 0 ? y0_ : kInf;  // the ground on the turning side
        std::vector<double> fractions;
        for (double f : gap_fractions())
            if (f >= gap_lo_ && f <= gap_hi_) fractions.push_back(f);
        if (fractions.empty()) fractions = {0.5 * (gap_lo_ + gap_hi_)};
        size_t layer = 0;
        while (!queue.empty()) {
            if (t_limit - t_cur <= std::max(1e-9 * y0_, 2.0 * min_thickness_)) break;
            const bool fixed = fixed_u != nullptr && layer > 0;
            if (fixed_u != nullptr && layer > fixed_u->size()) break;
            Choice best;
            if (layer == 0 && fixed_u == nullptr) {
                best = evaluate(queue, u_eye_, t_cur, t_limit);
            } else if (fixed_u != nullptr) {
                const double u = layer == 0 ? u_eye_ : (*fixed_u)[layer - 1];
                const double u_next = layer < fixed_u->size() ? (*fixed_u)[layer] : u_far_;
                best = evaluate_fixed(queue, u, u_next, t_cur, t_limit);
            } else {
                for (double u : candidates_in_gap(rays_[queue.front()].B, prev_B, fractions)) {
                    Choice c = evaluate(queue, u, t_cur, t_limit);
                    if (better(c, best)) best = c;
                }
            }
            if (best.m == 0 && !fixed) {
                std::vector<double> candidates;
                if (layer == 0) {
                    candidates = {u_eye_};
                } else {
                    candidates = candidates_in_gap(rays_[queue.front()].B, prev_B, fractions);
                }
                best = single_ray_best(queue.front(), candidates, t_cur, t_limit);
                ++violations_;
            }
            // Apply the layer: the first best.m rays of the queue reflect on its far boundary.
            const double D = best.D;
            U_.push_back(best.u);
            T_.push_back(t_cur + D);
            std::vector<int> rest;
            for (size_t q = 0; q < queue.size(); ++q) {
                FitRay& r = rays_[queue[q]];
                if (q < best.m) {
                    prev_B = r.B;
                    continue;
                }
                const double s = std::sqrt(std::max(0.0, best.u - r.B)) / r.beta;
                r.z_in += s > 0.0 ? D / s : kInf;
                r.zd.push_back(r.z_in);
                if (r.z_in < r.R) rest.push_back(queue[q]);  // else it left while crossing
            }
            queue = std::move(rest);
            for (auto& r : passing_) {
                const double s = std::sqrt(std::max(0.0, best.u - r.B)) / r.beta;
                r.z_in += s > 0.0 ? D / s : kInf;
            }
            t_cur += D;
            ++layer;
        }
    }

    const std::vector<double>& boundaries_t() const { return T_; }
    const std::vector<double>& layer_excess() const { return U_; }
    int violations() const { return violations_; }
    void set_min_thickness(double t) { min_thickness_ = t; }
    void set_gap_range(double lo, double hi) {
        gap_lo_ = lo;
        gap_hi_ = hi;
    }

  private:
    struct Choice {
        double u = 0.0;
        size_t m = 0;
        double D = 0.0;
        double width = -1.0;
        int bad = std::numeric_limits<int>::max();
    };

    // Indices at the given fractions of the gap (lo, hi), moved to POV-Ray's float grid; those
    // that leave the gap are dropped.  A gap narrower than the grid gets the grid's first
    // index above lo: the rays just above it then share the layer before.
    std::vector<double> candidates_in_gap(double lo, double hi,
                                          const std::vector<double>& fractions) const {
        std::vector<double> out;
        for (double f : fractions) {
            const double u = snap_excess(profile_.eta0, u_eye_, lo + f * (hi - lo));
            if (u > lo && u < hi && (out.empty() || u != out.back())) out.push_back(u);
        }
        if (out.empty()) out.push_back(snap_above(profile_.eta0, u_eye_, lo));
        return out;
    }

    // Whether an index on the float grid fits strictly between two rays' invariants.
    bool gap_has_index(double lo, double hi) const {
        return snap_above(profile_.eta0, u_eye_, lo) < hi;
    }

    static bool better(const Choice& a, const Choice& b) {
        if (a.bad != b.bad) return a.bad < b.bad;
        if (a.m != b.m) return a.m > b.m;
        return a.width > b.width;
    }

    // Signed error (pixels) of ray r reflected on the far boundary of the current layer,
    // oriented so that it decreases as the layer thickens.
    double g(const FitRay& r, double u, double t_cur, double D) const {
        const double s = std::sqrt(std::max(0.0, u - r.B)) / r.beta;
        const double z_floor = r.z_in + (s > 0.0 ? D / s : kInf);
        double y;
        double theta;
        if (r.R <= z_floor) {
            y = turn_.y(t_cur + s * (r.R - r.z_in));
            theta = std::atan2(y - y0_, r.R);
        } else if (r.R <= 2.0 * z_floor) {
            const double q = 2.0 * z_floor - r.R;
            double t;
            if (q >= r.z_in) {
                t = t_cur + s * (q - r.z_in);
            } else {
                auto it = std::upper_bound(r.zd.begin(), r.zd.end(), q);
                const size_t i = static_cast<size_t>(it - r.zd.begin()) - 1;
                const double z0 = r.zd[i], z1 = r.zd[i + 1];
                t = T_[i] + (T_[i + 1] - T_[i]) * (z1 > z0 ? (q - z0) / (z1 - z0) : 0.0);
            }
            y = turn_.y(t);
            theta = std::atan2(y - y0_, r.R);
        } else {
            const double w = r.R - 2.0 * z_floor;
            if (w >= r.climb_ground_z) {
                theta = std::atan2(-y0_, 2.0 * z_floor + r.climb_ground_z);
            } else {
                auto it = std::upper_bound(r.climb_z.begin(), r.climb_z.end(), w);
                const size_t j = static_cast<size_t>(it - r.climb_z.begin());
                const double t0 = j == 0 ? 0.0 : ow_.t[j - 1];
                const double z0 = j == 0 ? 0.0 : r.climb_z[j - 1];
                const double uj = j == 0 ? u_eye_ : ow_.u[j - 1];
                const double slope = std::sqrt(std::max(0.0, uj - r.B)) / r.beta;
                y = one_.y(t0 + slope * (w - z0));
                theta = std::atan2(y - y0_, r.R);
            }
        }
        return turn_.sgn * (theta - r.theta_exact) / r.px;
    }

    // Feasible thickness interval of ray r: g <= tol for D >= lo, g >= -tol for D <= hi.
    bool interval(const FitRay& r, double u, double t_cur, double d_min, double d_max, double& lo,
                  double& hi) const {
        const double g_min = g(r, u, t_cur, d_min), g_max = g(r, u, t_cur, d_max);
        if (g_max > tol_ || g_min < -tol_) return false;
        auto bisect = [&](double target, bool above) {
            double a = std::log(d_min), b = std::log(d_max);
            for (int it = 0; it < 60; ++it) {
                const double m = 0.5 * (a + b);
                const double gm = g(r, u, t_cur, std::exp(m));
                if (gm > target)
                    a = m;
                else
                    b = m;
            }
            return above ? std::exp(b) : std::exp(a);
        };
        lo = g_min <= tol_ ? d_min : bisect(tol_, true);
        hi = g_max >= -tol_ ? d_max : bisect(-tol_, false);
        return lo <= hi;
    }

    double d_max_for(double t_cur, double t_limit) const {
        if (std::isfinite(t_limit))
            return std::max(min_thickness_, (t_limit - t_cur) * (1.0 - 1e-9) - min_thickness_);
        return std::max(1e3 * y0_, 1e4);
    }

    Choice evaluate(const std::vector<int>& queue, double u, double t_cur, double t_limit) const {
        Choice c;
        c.u = u;
        const double d_max = d_max_for(t_cur, t_limit);
        const double d_min = std::max({1e-12, 1e-9 * d_max, min_thickness_});
        double A = d_min, Bd = d_max;
        size_t m = 0;
        for (; m < queue.size(); ++m) {
            const FitRay& r = rays_[queue[m]];
            if (!(u > r.B)) break;
            double lo, hi;
            if (!interval(r, u, t_cur, d_min, d_max, lo, hi)) break;
            const double a = std::max(A, lo), b = std::min(Bd, hi);
            if (a > b) break;
            A = a;
            Bd = b;
        }
        // The next layer's index must fit, on POV-Ray's float grid, between the group's last
        // ray and the first after it: end the group where it can.
        while (m > 1 && m < queue.size() &&
               !gap_has_index(rays_[queue[m]].B, rays_[queue[m - 1]].B))
            --m;
        if (m > 0 && m < queue.size()) {
            // Recompute the group's interval for the shortened group.
            A = d_min;
            Bd = d_max;
            for (size_t q = 0; q < m; ++q) {
                double lo, hi;
                interval(rays_[queue[q]], u, t_cur, d_min, d_max, lo, hi);
                A = std::max(A, lo);
                Bd = std::min(Bd, hi);
            }
        }
        c.m = m;
        if (m == 0) return c;
        c.width = (Bd - A) / std::max(Bd, 1e-300);
        // Anchor the floor near the exact turning point of the group's deepest ray, kept a
        // little inside the feasible interval.
        const FitRay& last = rays_[queue[m - 1]];
        double anchor = std::isfinite(last.t_turn) ? last.t_turn - t_cur : 0.5 * (A + Bd);
        // The margin is a tenth of the interval, counted only up to a few times the anchor:
        // rays that do not turn inside the scene allow any thickness beyond some, and the
        // layer should not grow far past where the exact paths go.
        const double top = std::min(Bd, std::max(4.0 * std::max(anchor, A), 2.0 * A));
        const double inner = 0.1 * (top - A);
        anchor = std::clamp(anchor, A + inner, top - inner);
        // Rays after the group that leave the atmosphere while crossing this layer are final
        // now: count those the layer's index puts out of tolerance (independent of D).
        int left_bad = 0;
        std::vector<const FitRay*> crossing;
        for (size_t q = m; q < queue.size(); ++q) {
            const FitRay& r = rays_[queue[q]];
            const double s = std::sqrt(std::max(0.0, u - r.B)) / r.beta;
            if (r.z_in + (s > 0.0 ? anchor / s : kInf) < r.R) {
                if (r.one_way) crossing.push_back(&r);
                continue;
            }
            const double y = turn_.y(t_cur + s * (r.R - r.z_in));
            const double err = (std::atan2(y - y0_, r.R) - r.theta_exact) / r.px;
            if (std::fabs(err) > tol_) ++left_bad;
        }
        for (const auto& r : passing_)
            if (r.z_in < r.R) crossing.push_back(&r);
        // One-way rays crossing the whole layer: its far boundary should be crossed near where
        // the exact path crosses that height.  Among thicknesses the group allows, take the
        // one that keeps most of them so (then the smallest worst mismatch, then the anchor).
        auto mismatch = [&](double D, int& off) {
            const double y_floor = turn_.y(t_cur + D);
            double worst = 0.0;
            off = 0;
            for (const FitRay* r : crossing) {
                const double s = std::sqrt(std::max(0.0, u - r->B)) / r->beta;
                const double z_band = r->z_in + (s > 0.0 ? D / s : kInf);
                const double z_exact = distance_to_height(r->exact, y_floor);
                if (!(z_exact < r->R) && !(z_band < r->R)) continue;
                const double w = std::fabs(z_band - z_exact) / r->z_tol;
                if (!(w <= 1.0)) ++off;
                worst = std::max(worst, std::isfinite(w) ? w : 1e300);
            }
            return worst;
        };
        double best_D = anchor;
        int best_off = 0;
        double best_worst = crossing.empty() ? 0.0 : mismatch(anchor, best_off);
        if (!crossing.empty() && (best_off > 0 || best_worst > 0.5)) {
            const double lo = A + inner, hi = top - inner;
            for (int k = 0; k <= 16; ++k) {
                const double D = lo * std::pow(hi / lo, k / 16.0);
                int off;
                const double w = mismatch(D, off);
                if (off < best_off || (off == best_off && w < best_worst)) {
                    best_off = off;
                    best_worst = w;
                    best_D = D;
                }
            }
        }
        c.D = best_D;
        const int bad = left_bad + best_off;
        c.bad = bad;
        return c;
    }

    Choice single_ray_best(int id, const std::vector<double>& candidates, double t_cur,
                           double t_limit) const {
        const FitRay& r = rays_[id];
        const double d_max = d_max_for(t_cur, t_limit);
        const double d_min = std::max({1e-12, 1e-9 * d_max, min_thickness_});
        Choice best;
        double best_err = kInf;
        for (double u : candidates) {
            if (!(u > r.B)) continue;
            for (int k = 0; k <= 400; ++k) {
                const double D = d_min * std::pow(d_max / d_min, k / 400.0);
                const double e = std::fabs(g(r, u, t_cur, D));
                if (e < best_err) {
                    best_err = e;
                    best.u = u;
                    best.D = D;
                    best.m = 1;
                }
            }
        }
        if (best.m == 0) {  // no candidate admits the ray: a thin layer, it reflects before it
            best.u = candidates.front();
            best.D = d_min;
        }
        best.bad = 0;
        return best;
    }

    // Fixed indices: the group is every queued ray at or above the next layer's index; the
    // thickness minimises the group's largest error (g is decreasing in D for every ray, so
    // max g + min g is too, and its root is the minimax).  An empty group gets the
    // thickness that puts the far boundary at the exact turning point of a ray whose
    // invariant is the next index.
    Choice evaluate_fixed(const std::vector<int>& queue, double u, double u_next, double t_cur,
                          double t_limit) const {
        Choice c;
        c.u = u;
        const double d_max = d_max_for(t_cur, t_limit);
        const double d_min = std::max({1e-12, 1e-9 * d_max, min_thickness_});
        size_t m = 0;
        while (m < queue.size() && rays_[queue[m]].B >= u_next) ++m;
        c.m = m;
        c.bad = 0;
        if (m == 0) {
            const double y_nat = height_of_excess(profile_, u_next);
            const double t_nat = std::isfinite(y_nat) ? turn_.sgn * (y0_ - y_nat) : kInf;
            c.D = std::clamp(t_nat - t_cur, d_min, 0.5 * d_max);
            if (!std::isfinite(c.D)) c.D = d_min;
            return c;
        }
        auto h = [&](double D) {
            double hi = -kInf, lo = kInf;
            for (size_t q = 0; q < m; ++q) {
                const double v = g(rays_[queue[q]], u, t_cur, D);
                hi = std::max(hi, v);
                lo = std::min(lo, v);
            }
            return hi + lo;
        };
        double a = std::log(d_min), b = std::log(d_max);
        if (h(d_min) <= 0.0) {
            c.D = d_min;
        } else if (h(d_max) >= 0.0) {
            c.D = d_max;
        } else {
            for (int it = 0; it < 60; ++it) {
                const double mid = 0.5 * (a + b);
                if (h(std::exp(mid)) > 0.0)
                    a = mid;
                else
                    b = mid;
            }
            c.D = std::exp(0.5 * (a + b));
        }
        return c;
    }

  private:
    Profile profile_;
    double y0_;
    Side turn_, one_;
    double u_eye_;
    double u_far_;
    OneWay ow_;
    double tol_;
    std::vector<FitRay> rays_;
    std::vector<FitRay> passing_;
    std::vector<double> T_, U_;
    int violations_ = 0;
    double gap_lo_ = 0.0, gap_hi_ = 1.0;
    double min_thickness_ = 0.0;
};

// Exact horizontal distance for a ray of invariant beta between heights a and b on a part
// of its path that is monotone in height.
double exact_run(const Profile& p, double beta, double a, double b) {
    const double n_a = eta(p, a);
    const double cos_e = std::min(1.0, beta / n_a);
    const double e = std::acos(cos_e) * (b > a ? 1.0 : -1.0);
    auto ray = make_exact_ray(p, a, M_PI / 2 - e);
    MIRAGE_CHECK(ray.ok());
    // Bisection on the distance at which the path reaches b.
    double lo = 0.0, hi = std::fabs(b - a) / std::max(std::fabs(std::tan(e)), 1e-300);
    auto reached = [&](double dz) {
        return b > a ? height_at(*ray, dz) >= b : height_at(*ray, dz) <= b;
    };
    for (int i = 0; i < 200 && !reached(hi); ++i) hi *= 2.0;
    for (int i = 0; i < 100; ++i) {
        const double m = 0.5 * (lo + hi);
        if (reached(m))
            hi = m;
        else
            lo = m;
    }
    return 0.5 * (lo + hi);
}

// One-way layers geometric in w = |eta^2(y) - eta^2(y0)|: w_1 = c1 s1, ratio q, up to
// W (1 - flat); each index such that the most grazing ray (invariant B*) crosses its layer
// in the exact horizontal distance.
OneWay geometric_oneway(const Profile& p, double y0, int sgn_one, double u_eye, double s1, double q,
                        double flat) {
    OneWay ow;
    const double u_lim = sgn_one < 0 ? eta_sq_excess(p, std::numeric_limits<double>::infinity())
                                     : 0.0;  // sky side: eta(inf); ground side: eta0
    // sgn_one: the one-way side's t grows with y0 - sgn_one t; sky side is sgn_one = -1.
    const double W = std::fabs(u_lim - u_eye);
    if (!(W > 0.0) || !(s1 > 0.0)) return ow;
    const double w_top = W * (1.0 - flat);
    std::vector<double> ws;
    for (double w = 0.25 * s1; w < w_top; w *= q) ws.push_back(w);
    if (ws.empty() || ws.back() < w_top) ws.push_back(w_top);
    const double dir = u_lim > u_eye ? 1.0 : -1.0;
    for (double w : ws) {
        const double y = height_of_excess(p, u_eye + dir * w);
        ow.t.push_back(std::fabs(y - y0));
    }
    if (sgn_one > 0) ow.ground = y0;  // the ground lies on this side
    const double B_star = u_eye - s1;
    const double beta = std::sqrt(p.eta0 * p.eta0 + B_star);
    for (size_t j = 0; j + 1 < ow.t.size(); ++j) {
        const double ya = y0 - sgn_one * ow.t[j], yb = y0 - sgn_one * ow.t[j + 1];
        const double run = exact_run(p, beta, ya, yb);
        const double slope = std::fabs(yb - ya) / run;
        ow.u.push_back(snap_excess(p.eta0, u_eye, B_star + slope * slope * beta * beta));
    }
    // Beyond the last boundary: eta(inf) on the sky side, eta0 down to the ground.
    ow.u.push_back(snap_excess(p.eta0, u_eye, u_lim));
    // The ground side ends at the ground: drop boundaries at or below it.
    while (!ow.t.empty() && ow.t.back() >= ow.ground) {
        ow.t.pop_back();
        ow.u.pop_back();
    }
    if (!ow.u.empty() && sgn_one > 0) ow.u.back() = snap_excess(p.eta0, u_eye, u_lim);
    return ow;
}

LayerStack assemble(const Profile& p, double y0, int sgn_turn, double u_eye,
                    const std::vector<double>& T, const std::vector<double>& U, double u_far,
                    const OneWay& ow) {
    // Turning side: boundaries at T[1..], the layer before boundary i has U[i-1] (U[0] the
    // eye layer's); beyond the last boundary u_far.  One-way side: boundaries ow.t, layer
    // beyond boundary j has ow.u[j].
    struct B {
        double y;
        double u_above;
    };
    std::vector<B> bs;
    // Each boundary with the excess of the layer above it.
    for (size_t i = 1; i < T.size(); ++i) {
        const double y = y0 - sgn_turn * T[i];
        const double u_near = U[i - 1];                       // eye side of it
        const double u_beyond = i < U.size() ? U[i] : u_far;  // far side of it
        bs.push_back({y, sgn_turn > 0 ? u_near : u_beyond});
    }
    for (size_t j = 0; j < ow.t.size(); ++j) {
        const double y = y0 + sgn_turn * ow.t[j];
        const double u_near = j == 0 ? u_eye : ow.u[j - 1];
        const double u_beyond = ow.u[j];
        bs.push_back({y, sgn_turn > 0 ? u_beyond : u_near});
    }
    std::sort(bs.begin(), bs.end(), [](const B& a, const B& b) { return a.y < b.y; });
    LayerStack s;
    s.profile = p;
    // The lowest layer, below the lowest boundary: the far side of the turning side
    // (inferior) or of the one-way side (superior), or the eye's layer when that side is empty.
    double u_bottom;
    if (sgn_turn > 0) {
        u_bottom = T.size() > 1 ? u_far : u_eye;
    } else {
        u_bottom = ow.t.empty() ? u_eye : ow.u.back();
    }
    if (bs.empty()) {
        s.excess = {u_eye};
        return s;
    }
    s.excess.push_back(u_bottom);
    for (const auto& b : bs) {
        s.heights.push_back(b.y);
        s.excess.push_back(b.u_above);
    }
    return s;
}

// The ground layer of an inferior stack: eta0 makes the cut between rays that turn and
// rays that reach the ground exact for every elevation.  For the design's own rays any index
// in the gap between the ground-reaching invariants and the turning ones gives the same cut;
// within that gap the one that brings the ground-reaching rays closest to their exact ground
// points is taken.
void optimize_ground_layer(LayerStack& s, double y0, const std::vector<DesignRay>& rays,
                           double layers_dz) {
    const double u_eye = s.excess[s.layer_at(y0)];
    const double n_eye2 = s.profile.eta0 * s.profile.eta0 + u_eye;
    double b_ground = -kInf, b_turn = kInf;
    std::vector<const DesignRay*> ground;
    for (const auto& r : rays) {
        if (r.elevation >= 0.0) continue;
        const double B = u_eye - n_eye2 * std::sin(r.elevation) * std::sin(r.elevation);
        if (B <= 0.0) {
            b_ground = std::max(b_ground, B);
            ground.push_back(&r);
        } else {
            b_turn = std::min(b_turn, B);
        }
    }
    if (ground.empty()) return;
    const double lo = b_ground, hi = std::min(b_turn, s.excess[1]);
    if (!(hi > lo)) return;
    auto worst = [&](double u) {
        s.excess[0] = snap_excess(s.profile.eta0, u_eye, u);
        double w = 0.0;
        for (const DesignRay* r : ground) {
            const BandOutcome b = trace_band(s, y0, r->elevation, r->exit_dz, layers_dz);
            const BandOutcome e = exact_outcome(s.profile, y0, r->elevation, r->exit_dz);
            w = std::max(w, outcome_error_rad(y0, e, b) / r->pixel_rad);
        }
        return w;
    };
    double best_u = 0.0, best = worst(0.0);
    for (int i = 1; i < 400; ++i) {
        const double f = i / 400.0;
        const double u = lo + f * (hi - lo);
        const double w = worst(u);
        if (w < best) {
            best = w;
            best_u = u;
        }
    }
    s.excess[0] = snap_excess(s.profile.eta0, u_eye, best_u);
}

}  // namespace

namespace {

FitResult fit_once(const Profile& profile, double y0, const std::vector<DesignRay>& rays,
                   const LayerFitSettings& settings, const std::vector<double>* fixed_excess);

}  // namespace

FitQuality measure_fit(const LayerStack& stack, double y0, const std::vector<DesignRay>& rays,
                       double layers_factor) {
    FitQuality q;
    for (const auto& r : rays) {
        const BandOutcome b =
            trace_band(stack, y0, r.elevation, r.exit_dz, layers_factor * r.exit_dz);
        const BandOutcome e = exact_outcome(stack.profile, y0, r.elevation, r.exit_dz);
        q.max_error_px = std::max(q.max_error_px, outcome_error_rad(y0, e, b) / r.pixel_rad);
        q.max_crossings = std::max(q.max_crossings, b.crossings);
    }
    return q;
}

FitResult fit_layers(const Profile& profile, double y0, const std::vector<DesignRay>& rays,
                     const LayerFitSettings& settings, const std::vector<double>* fixed_excess) {
    // The sequential fit aims at the tolerance ray by ray, but the rays it does not steer
    // directly (those that cross layers fitted for others) can end outside it, and the
    // greedy choices depend on the aim.  Variants are tried, the first within the tolerance
    // and the budget is kept, else the most accurate within the budget, else the one with
    // the fewest crossings.
    FitResult best;
    FitQuality best_q{std::numeric_limits<double>::infinity(), std::numeric_limits<int>::max()};
    auto in_budget = [&](const FitQuality& q) { return q.max_crossings <= settings.max_crossings; };
    // Tries one aim (a tolerance factor) with each margin; keeps the best design seen.
    // Returns whether the aim's best try kept the budget, and whether the tolerance was met.
    auto attempt = [&](double aim_factor, bool& kept_budget) {
        kept_budget = false;
        for (double margin : {0.97, 0.9, 0.8}) {
            LayerFitSettings aim = settings;
            aim.tolerance_px = settings.tolerance_px * aim_factor;
            aim.oneway_margin = margin;
            FitResult f = fit_once(profile, y0, rays, aim, fixed_excess);
            const FitQuality q = measure_fit(f.stack, y0, rays, settings.layers_extent_factor);
            kept_budget = kept_budget || in_budget(q);
            if ((in_budget(q) && (!in_budget(best_q) || q.max_error_px < best_q.max_error_px)) ||
                (!in_budget(q) && !in_budget(best_q) && q.max_crossings < best_q.max_crossings)) {
                best = std::move(f);
                best_q = q;
            }
            if (in_budget(q) && q.max_error_px <= settings.tolerance_px) return true;
        }
        return false;
    };
    bool kept = false;
    for (double aim : {1.0, 0.85, 0.7})
        if (attempt(aim, kept)) return best.quality = best_q, best;
    // Out of reach: find the tightest aim that keeps the budget.  Loosen geometrically until
    // the budget is kept, then bisect between the last aim over it and the first within.
    double over = 0.7, within = 0.0;
    if (kept) {
        within = 0.7;
        over = 0.0;
    }
    for (double aim = 1.2; within == 0.0 && aim < 1e4; aim *= 1.5) {
        if (attempt(aim, kept)) return best.quality = best_q, best;
        if (kept)
            within = aim;
        else
            over = aim;
    }
    for (int i = 0; i < 6 && within > 0.0 && over > 0.0; ++i) {
        const double mid = std::sqrt(over * within);
        if (attempt(mid, kept)) break;
        if (kept)
            within = mid;
        else
            over = mid;
    }
    best.quality = best_q;
    return best;
}

namespace {

FitResult fit_once(const Profile& profile, double y0, const std::vector<DesignRay>& rays,
                   const LayerFitSettings& settings, const std::vector<double>* fixed_excess) {
    MIRAGE_CHECK(y0 > 0.0);
    g_float_grid = settings.pov_float_grid;
    FitResult result;
    const int s = profile_sign(profile);
    const double u_eye = eta_sq_excess(profile, y0);
    const double n_eye2 = profile.eta0 * profile.eta0 + u_eye;
    result.stack.profile = profile;
    result.stack.excess = {u_eye};
    if (s == 0 || profile.eta1 == 0.0 || rays.empty()) return result;
    // The turning side: below the eye for an inferior profile, above it for a superior one.
    const int sgn_turn = s > 0 ? 1 : -1;
    const double u_far_turn =
        snap_excess(profile.eta0, u_eye, s > 0 ? 0.0 : eta_sq_excess(profile, kInf));

    // The most grazing ray that reaches the one-way side fixes its layers.
    double s1 = kInf;
    for (const auto& r : rays) {
        const double sin2 = std::sin(r.elevation) * std::sin(r.elevation);
        s1 = std::min(s1, n_eye2 * std::max(sin2, 1e-30));
    }
    // Choose the one-way design: the fewest layers that keep the one-way rays within the
    // tolerance; else the most accurate.
    OneWay best_ow;
    double best_err = kInf;
    size_t best_count = std::numeric_limits<size_t>::max();
    double layers_dz = 0.0;
    for (const auto& r : rays) layers_dz = std::max(layers_dz, r.exit_dz);
    layers_dz *= settings.layers_extent_factor;
    for (double q : {6.0, 4.0, 3.0, 2.0, 1.6, 1.3, 1.15}) {
        OneWay ow = geometric_oneway(profile, y0, -sgn_turn, u_eye, s1, q, settings.flat_fraction);
        LayerStack st = assemble(profile, y0, sgn_turn, u_eye, {0.0}, {u_eye}, u_far_turn, ow);
        double worst = 0.0;
        for (const auto& r : rays) {
            const bool toward_oneway = sgn_turn > 0 ? r.elevation >= 0.0 : r.elevation < 0.0;
            if (!toward_oneway) continue;
            const BandOutcome b = trace_band(st, y0, r.elevation, r.exit_dz, layers_dz);
            const BandOutcome e = exact_outcome(profile, y0, r.elevation, r.exit_dz);
            worst = std::max(worst, outcome_error_rad(y0, e, b) / r.pixel_rad);
        }
        const bool ok = worst <= settings.tolerance_px;
        const bool best_ok = best_err <= settings.tolerance_px;
        if ((ok && (!best_ok || ow.t.size() < best_count)) ||
            (!ok && !best_ok && worst < best_err)) {
            best_ow = ow;
            best_err = worst;
            best_count = ow.t.size();
        }
    }

    // Rays that bend back on the turning side.
    SequentialFit fit(profile, y0, sgn_turn, u_eye, u_far_turn, best_ow, settings.tolerance_px);
    for (size_t i = 0; i < rays.size(); ++i) {
        const auto& r = rays[i];
        const bool toward_turn = sgn_turn > 0 ? r.elevation < 0.0 : r.elevation > 0.0;
        if (!toward_turn) continue;
        const double a = std::fabs(r.elevation);
        const double B = u_eye - n_eye2 * std::sin(a) * std::sin(a);
        FitRay f;
        f.id = static_cast<int>(i);
        f.B = B;
        f.beta = std::sqrt(profile.eta0 * profile.eta0 + B);
        f.R = r.exit_dz;
        f.px = r.pixel_rad;
        const BandOutcome e = exact_outcome(profile, y0, r.elevation, r.exit_dz);
        f.theta_exact = std::atan2(e.y - y0, e.dz);
        auto ray = make_exact_ray(profile, y0, M_PI / 2 - r.elevation);
        MIRAGE_CHECK(ray.ok());
        f.exact = *ray;
        const bool turns_inside = ray->turn_kind == TurnKind::Ahead && ray->dz_turn < r.exit_dz &&
                                  !(ray->hits_ground && ray->dz_ground < ray->dz_turn);
        // Where the floor of its group should lie: at its turning point if it turns inside
        // the scene, else as deep as it gets there.
        f.t_turn =
            turns_inside ? std::fabs(ray->y_turn - y0) : (e.ground ? kInf : std::fabs(e.y - y0));
        // A shift dz of where the ray is moves its end by about |slope| dz, which must stay
        // within the tolerance seen from the eye (a little margin for what follows).
        const double tol_rad = settings.oneway_margin * settings.tolerance_px * r.pixel_rad;
        if (e.ground) {
            f.z_tol = 0.8 * tol_rad * e.dz * e.dz / y0;
        } else {
            f.z_tol = tol_rad * r.exit_dz / std::max(std::fabs(e.slope), 1e-12);
        }
        f.one_way = !turns_inside;
        climb_profile(best_ow, u_eye, B, f.beta, f.climb_z, f.climb_ground_z);
        if (!(B > u_far_turn)) {
            fit.add_passing_ray(std::move(f));  // reaches the ground / escapes: no turn to fit
        } else {
            fit.add_ray(std::move(f));
        }
    }
    fit.set_gap_range(settings.gap_lo, settings.gap_hi);
    fit.set_min_thickness(settings.min_thickness);
    fit.run(fixed_excess);
    const auto& T = fit.boundaries_t();
    const auto& U = fit.layer_excess();
    result.stack = assemble(profile, y0, sgn_turn, u_eye, T, U, u_far_turn, best_ow);
    if (sgn_turn > 0 && result.stack.boundaries() > 0)
        optimize_ground_layer(result.stack, y0, rays, layers_dz);
    result.turning_boundaries = static_cast<int>(T.size()) - 1;
    result.oneway_boundaries = static_cast<int>(best_ow.t.size());
    result.turning_excess.assign(U.begin() + (U.empty() ? 0 : 1), U.end());
    result.violations = fit.violations();
    MIRAGE_CHECK(well_formed(result.stack));
    return result;
}

}  // namespace

LayerStack uniform_layers(const Profile& profile, double y0, int count, double top) {
    (void)y0;
    MIRAGE_CHECK(count >= 0 && top > 0.0);
    LayerStack s;
    s.profile = profile;
    for (int j = 0; j <= count; ++j) {
        if (j < count) s.heights.push_back(top * (j + 1) / count);
        const double mid = j < count ? top * (j + 0.5) / count : top;
        s.excess.push_back(eta_sq_excess(profile, mid));
    }
    return s;
}

}  // namespace mirage
