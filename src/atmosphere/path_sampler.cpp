#include "atmosphere/path_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "atmosphere/chord_bound.h"
#include "atmosphere/step_search.h"
#include "util/check.h"

namespace mirage {

namespace {

// The longest chord from a the bound allows with the curvature m at a alone: m L^2 / 8 <=
// allow + tol_rad L.  A first guess for next_step, not a bound.
double chord_guess(double m, double allow, const SampleSettings& st) {
    if (!(m > 0.0)) return 0.0;
    const double t = st.tolerance_rad;
    return 4.0 * (t + std::sqrt(t * t + 0.5 * m * allow)) / m;
}

}  // namespace

double allowed_error(const ExactPath& path, const SampleSettings& st, double dz, double y) {
    const double dy = y - path.y0();
    return st.tolerance_m + st.tolerance_rad * (st.start_distance + std::sqrt(dz * dz + dy * dy));
}

namespace {

// sample_exact_path's steps over one path: its end, the runs sampled forward, and the first
// turning point sampled outward and reflected.
class ExactSampler {
  public:
    ExactSampler(const ExactPath& path, const SampleSettings& st)
        : path_(path),
          st_(st),
          max_dz_(std::min(st.max_dz, kMaxSampleDistance)),
          ground_(path.hits_ground() && path.dz_ground() <= max_dz_),
          dz_end_(ground_ ? path.dz_ground() : max_dz_) {}

    SampledPath sample() {
        out_.points.push_back({0.0, path_.y0()});
        if (path_.straight()) {
            if (std::isfinite(dz_end_)) point(dz_end_);
            finish(dz_end_);
            return std::move(out_);
        }
        const int count = path_.turning_point_count();
        const bool turns =
            count != 0 && path_.turning_point(0).dz > 0.0 && path_.turning_point(0).dz < dz_end_;
        if (!turns) {
            finish(forward(0.0, dz_end_, true));
            return std::move(out_);
        }
        const bool trapped = count < 0;
        const bool reached_next = about_first_turn(trapped);
        if (straight_after_ || !trapped || !reached_next || next_event_ >= dz_end_) {
            finish(out_.points.back().x);
            return std::move(out_);
        }
        // Trapped: every further run, from one turning point to the next, sampled forward.
        for (int k = 1;; ++k) {
            const double a = path_.turning_point(k).dz;
            if (a >= dz_end_) break;
            const double b = std::min(path_.turning_point(k + 1).dz, dz_end_);
            forward(a, b, false);
            if (b >= dz_end_) break;
        }
        finish(out_.points.back().x);
        return std::move(out_);
    }

  private:
    void finish(double dz_last) {
        if (ground_ && dz_last >= path_.dz_ground()) {
            out_.end = PathEnd::Ground;
        } else if (dz_last >= max_dz_) {
            out_.end = PathEnd::Cut;
            out_.end_slope = path_.slope_at(dz_last);
            out_.end_slope_dz = dz_last;
        } else {
            out_.end = PathEnd::Straight;
            out_.end_slope = path_.asymptotic_slope();
            // The slope the path leaves the profile's top with, where it does.
            const QuadraticPath* q = path_.quadratic();
            out_.end_slope_dz = q && std::isfinite(q->dz_straight()) ? q->dz_straight() : dz_last;
        }
    }
    double height(double dz) const {
        return (ground_ && dz >= path_.dz_ground()) ? 0.0 : path_.height_at(dz);
    }
    void point(double dz) { out_.points.push_back({dz, height(dz)}); }
    double allowance_at(double dz) const { return allowed_error(path_, st_, dz, height(dz)); }
    bool straight_from(double dz) const {
        return path_.asymptote_departure(dz) <= allowance_at(dz);
    }

    // One monotone run [a, b] sampled forward from a (whose point is already out); may end
    // straight when `may_end_straight`.  Returns where it stopped.
    double forward(double a, double b, bool may_end_straight) {
        double previous =
            chord_guess(path_.curvature_bound(height(a), height(a)), allowance_at(a), st_);
        while (a < b && !(may_end_straight && straight_from(a))) {
            const double y_a = height(a), allow_a = allowed_error(path_, st_, a, y_a);
            const double step = next_step(
                a, b,
                [&](double lo, double hi) {
                    hi = std::min(hi, b);
                    const double m = path_.curvature_bound(y_a, height(hi));
                    return chord_within(m, lo, hi, allow_a, st_);
                },
                previous);
            previous = step;
            a = std::min(b, a + step);
            point(a);
        }
        return a;
    }

    // The first turning point: sampled outward from it (u = |dz - zt|) so that both mirror
    // images of every step keep the tolerance, then reflected (as sampler.cpp does), out to
    // the next turning point (a trapped ray) or the end.  Whether it reached the next one.
    bool about_first_turn(bool trapped) {
        out_.turns = true;
        const double zt = path_.turning_point(0).dz;
        out_.dz_turn = zt;
        next_event_ = trapped ? std::min(path_.turning_point(1).dz, dz_end_) : dz_end_;
        const double next_event = next_event_;
        const double y_turn_path = path_.height_at(zt);
        const double u_before = zt;
        const double u_after_max = next_event - zt;
        auto branch_height = [&](double u) {
            return u <= zt ? path_.height_at(zt - u) : height(std::min(zt + u, dz_end_));
        };
        std::vector<double> us{0.0}, ys{y_turn_path};
        double u_after_end = u_after_max;
        double u = 0.0;
        double previous =
            chord_guess(path_.curvature_bound(y_turn_path, y_turn_path), allowance_at(zt), st_);
        const bool may_end_straight = !trapped;
        while (true) {
            const bool need_before = u < u_before;
            const bool need_after = !straight_after_ && u < u_after_max;
            if (!need_before && !need_after) break;
            const double limit =
                std::max(need_before ? u_before : 0.0, need_after ? u_after_max : 0.0);
            const double y_u = branch_height(u);
            const double allow_after = need_after && u < u_after_max ? allowance_at(zt + u) : 0.0;
            const double step = next_step(
                u, limit,
                [&](double lo, double hi) {
                    const double y_hi = branch_height(hi);
                    const double m = path_.curvature_bound(y_u, y_hi);
                    bool ok = true;
                    if (lo < u_before) {
                        const double p = std::max(0.0, zt - hi);
                        const double y_p = hi <= zt ? y_hi : height(p);
                        ok = ok &&
                             chord_within(m, p, zt - lo, allowed_error(path_, st_, p, y_p), st_);
                    }
                    if (need_after && lo < u_after_max) {
                        const double q = std::min(zt + hi, next_event);
                        ok = ok && chord_within(m, zt + lo, q, allow_after, st_);
                    }
                    return ok;
                },
                previous);
            previous = step;
            u = std::min(limit, u + step);
            us.push_back(u);
            ys.push_back(branch_height(u));
            if (may_end_straight && need_after && u < u_after_max && straight_from(zt + u)) {
                straight_after_ = true;
                u_after_end = u;
            }
        }
        for (size_t k = us.size(); k-- > 1;) {
            if (us[k] < u_before) out_.points.push_back({zt - us[k], ys[k]});
        }
        out_.points.push_back({zt, y_turn_path});
        for (size_t k = 1; k < us.size(); ++k) {
            if (straight_after_ && us[k] > u_after_end) break;
            if (us[k] >= u_after_max) {
                out_.points.push_back({next_event, height(next_event)});
                return true;
            }
            out_.points.push_back({zt + us[k], ys[k]});
        }
        return false;
    }

    const ExactPath& path_;
    const SampleSettings& st_;
    const double max_dz_;
    const bool ground_;
    const double dz_end_;
    SampledPath out_;
    double next_event_ = 0.0;     // where the run after the first turning point ends
    bool straight_after_ = false;  // it ended straight
};

}  // namespace

SampledPath sample_exact_path(const ExactPath& path, const SampleSettings& st) {
    MIRAGE_CHECK(st.tolerance_m > 0.0 || st.tolerance_rad > 0.0);
    MIRAGE_CHECK(st.max_dz >= 0.0);
    return ExactSampler(path, st).sample();
}

// ---------------------------------------------------------------------------------------------
// Sampling near what the path can meet (sample_exact_path_near).

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Whether nothing the path can meet lies anywhere beyond the distance dz.
bool nothing_beyond_dz(const PathObstacles& obstacles, double dz) {
    PathRegion beyond;
    beyond.dz_lo = dz;
    beyond.dz_hi = kInf;
    beyond.lower = {PathLine{dz, -kInf, 0.0}, PathLine{dz, -kInf, 0.0}};
    beyond.upper = {PathLine{dz, kInf, 0.0}, PathLine{dz, kInf, 0.0}};
    beyond.lower_count = beyond.upper_count = 1;
    return !obstacles.may_meet(beyond);
}

class ExactNearSampler {
  public:
    ExactNearSampler(const ExactPath& path, const SampleSettings& st,
                     const PathObstacles* obstacles, SampledPath& out, double dz_ground)
        : path_(path), st_(st), obstacles_(obstacles), out_(out), dz_ground_(dz_ground) {}

    double height(double dz) const { return dz >= dz_ground_ ? 0.0 : path_.height_at(dz); }

    /// Where a stretch ending there must keep the tolerance whatever else: on a surface at the
    /// ground.
    void set_ground_end(double dz) { ground_end_ = dz; }

    /// An escaping path that meets no ground: it may stop where nothing lies beyond (its end is
    /// then straight, with the asymptotic slope), and its far end's height is computed only if
    /// a test needs it.
    void set_may_stop() { may_stop_ = obstacles_ != nullptr; }
    bool stopped() const { return stopped_; }
    void stop() { stopped_ = true; }

    /// After a stop: the point at dz (beyond the last one) by a stretch that meets nothing.
    void reach_clear(double dz) {
        const Point last{out_.points.back().x, out_.points.back().y};
        const Point to{dz, height(dz)};
        const double w = to.dz - last.dz, dy = to.y - last.y;
        emit(to, std::sqrt(w * w + dy * dy));
    }

    /// Samples the monotone run from (a, ya) to (b, yb); yb NaN: not computed yet.
    void run(double a, double ya, double b, double yb) {
        if (!(b > a) || stopped_) return;
        int e = 0;
        std::frexp(b - a, &e);
        node({a, ya}, {b, yb}, std::ldexp(1.0, e));
    }

  private:
    struct Point {
        double dz, y;  // y NaN: not computed yet
    };

    bool fine(const Point& a, double b_dz, double m) const {
        return chord_within(m, a.dz, b_dz, allowed_error(path_, st_, a.dz, a.y), st_);
    }

    // Whether nothing lies beyond dz: monotone in dz (true beyond any dz where it is true), so
    // the answers found so far settle most questions without asking the scene.
    bool nothing_beyond(double dz) const {
        if (dz >= clear_from_) return true;
        if (dz <= busy_until_) return false;
        if (nothing_beyond_dz(*obstacles_, dz)) {
            clear_from_ = dz;
            return true;
        }
        busy_until_ = dz;
        return false;
    }

    // Whether nothing the path can meet lies near the stretch from a to b (within one monotone
    // run, so between the heights of its ends, and within m w^2 / 8 of its chord); then its
    // length, estimated.
    bool clear(const Point& a, const Point& b, double m, double& length) const {
        const double w = b.dz - a.dz;
        const double dy = b.y - a.y;
        const double bulge = 0.125 * m * w * w;
        const double y_lo = std::min(a.y, b.y), y_hi = std::max(a.y, b.y);
        const double y0 = path_.y0();
        const double far_dy = std::max(std::fabs(y_hi - y0), std::fabs(y_lo - y0)) + bulge;
        const double reach = std::sqrt(b.dz * b.dz + far_dy * far_dy);
        const double slack = 1e-9 * (1.0 + b.dz + std::max(std::fabs(y_lo), std::fabs(y_hi)));
        const double margin =
            st_.tolerance_m + st_.tolerance_rad * (st_.start_distance + reach) + slack;
        const double slope = dy / w;
        PathRegion region;
        region.dz_lo = a.dz;
        region.dz_hi = b.dz;
        region.lower = {PathLine{a.dz, a.y - bulge - margin, slope},
                        PathLine{a.dz, y_lo - margin, 0.0}};
        region.upper = {PathLine{a.dz, a.y + bulge + margin, slope},
                        PathLine{a.dz, y_hi + margin, 0.0}};
        if (obstacles_->may_meet(region)) return false;
        // The arc exceeds its chord by about w theta^2 / 24 for a turn theta (under 1e-6 of
        // it for rays within a few degrees of level): the chord is the estimate.
        length = std::sqrt(w * w + dy * dy);
        return true;
    }

    void emit(const Point& b, double clear_length) {
        out_.points.push_back({b.dz, b.y});
        if (obstacles_) out_.clear_length.push_back(clear_length);
    }

    // Halves the node [a.dz, a.dz + size] cut at b.dz, its parts before the end first.
    void split(const Point& a, const Point& b, double size) {
        while (a.dz + 0.5 * size >= b.dz) size *= 0.5;  // the node's part before the end
        const double mid = a.dz + 0.5 * size;
        MIRAGE_CHECK(mid > a.dz && mid < b.dz);
        const Point p{mid, height(mid)};
        node(a, p, 0.5 * size);
        node(p, b, 0.5 * size);
    }

    // The grid node [a.dz, a.dz + size], cut at the run's end b.dz.
    void node(const Point& a, Point b, double size) {
        if (stopped_) return;
        if (std::isnan(b.y)) {
            // The far end of an escaping path: where the chord test surely fails (its bound is
            // at least the curvature at a), a node needs b's height only if something lies
            // beyond a; with nothing there the path stops at a.  The decisions are those made
            // with b's height.
            if (may_stop_ && !fine(a, b.dz, path_.curvature_bound(a.y, a.y))) {
                if (nothing_beyond(a.dz)) {
                    stopped_ = true;
                    return;
                }
                split(a, b, size);
                return;
            }
            b.y = height(b.dz);
        }
        const double m = path_.curvature_bound(a.y, b.y);
        if (fine(a, b.dz, m)) {
            emit(b, 0.0);
            if (may_stop_ && nothing_beyond(b.dz)) stopped_ = true;
            return;
        }
        double length = 0.0;
        if (obstacles_ && b.dz != ground_end_ && clear(a, b, m, length)) {
            emit(b, length);
            if (may_stop_ && nothing_beyond(b.dz)) stopped_ = true;
            return;
        }
        if (may_stop_ && nothing_beyond(a.dz)) {
            stopped_ = true;
            return;
        }
        split(a, b, size);
    }

    const ExactPath& path_;
    const SampleSettings& st_;
    const PathObstacles* obstacles_;
    SampledPath& out_;
    double dz_ground_;
    double ground_end_ = kNaN;
    bool may_stop_ = false;
    mutable double clear_from_ = kInf, busy_until_ = -kInf;
    bool stopped_ = false;
};

// Whether a path that rises from its start and turns nowhere before `end` meets nothing, all
// the way, and (cut at `end`) nothing lies beyond the cut either, where the tracer would go on
// straight.  Its slope depends on its height only, so over the heights it crosses (from the
// start to the end's height; escaping, to the profile's top, above which it is straight) it
// lies in the wedge from its start between the smallest and largest slope there; everything
// within the allowance of it lies within tol_rad sqrt(1 + s^2) per unit of dz more.  Such a
// path is kept as its start and its end direction, not to be tested: the end a path the sampler
// stops has, and the sky is seen in the same direction.
bool wedge_is_clear(const ExactPath& path, const SampleSettings& st,
                    const PathObstacles& obstacles, bool escapes, double end) {
    const QuadraticPath* q = path.quadratic();
    if (!q || !(q->cos_i() > 0.0) || !(end > 0.0)) return false;
    const double y0 = path.y0();
    const double top = q->profile().top();
    const double y_hi = escapes ? std::max(y0, top) : path.height_at(end);
    if (!(y_hi >= y0)) return false;
    double s_lo, s_hi;
    q->abs_slope_bounds(y0, y_hi, s_lo, s_hi);
    if (!std::isfinite(s_hi)) return false;
    const double spread = st.tolerance_rad * std::sqrt(1.0 + s_hi * s_hi) + 1e-9 * (1.0 + s_hi);
    const double margin =
        st.tolerance_m + st.tolerance_rad * st.start_distance + 1e-9 * (1.0 + std::fabs(y0));
    PathRegion wedge;
    wedge.dz_lo = 0.0;
    wedge.dz_hi = escapes ? kInf : end;
    const PathLine below{0.0, y0 - margin, s_lo - spread};
    wedge.lower = {below, below};
    wedge.lower_count = 1;
    const PathLine above{0.0, y0 + margin, s_hi + spread};
    if (escapes) {
        wedge.upper = {above, above};
        wedge.upper_count = 1;
    } else {
        wedge.upper = {above, PathLine{0.0, y_hi + margin, spread}};
    }
    if (obstacles.may_meet(wedge)) return false;
    if (escapes) return true;
    return nothing_beyond_dz(obstacles, end);
}

}  // namespace

void sample_exact_path_near(const ExactPath& path, const SampleSettings& st,
                            const PathObstacles* obstacles, SampledPath& out) {
    MIRAGE_CHECK(st.tolerance_m > 0.0 || st.tolerance_rad > 0.0);
    MIRAGE_CHECK(st.max_dz >= 0.0);
    if (path.straight()) {
        out = sample_exact_path(path, st);
        out.clear_length.clear();
        out.end_clear = false;
        return;
    }
    out.points.clear();
    out.clear_length.clear();
    out.end = PathEnd::Straight;
    out.end_slope = 0.0;
    out.end_clear = false;
    out.turns = false;
    out.dz_turn = 0.0;
    const double y0 = path.y0();
    out.points.push_back({0.0, y0});

    const double max_dz = std::min(st.max_dz, kMaxSampleDistance);
    const bool ground = path.hits_ground() && path.dz_ground() <= max_dz;
    const double end = ground ? path.dz_ground() : max_dz;
    ExactNearSampler sampler(path, st, obstacles, out, ground ? path.dz_ground() : kInf);
    if (ground && obstacles && obstacles->ground()) sampler.set_ground_end(path.dz_ground());
    // A path that does not end on the ground is followed to the cut (the end of the reach);
    // with obstacles it stops where nothing lies beyond.
    const bool escapes = !ground && path.fate() == PathFate::Escape && path.quadratic() &&
                         std::isfinite(path.asymptotic_slope());
    if (!ground) sampler.set_may_stop();

    // Nothing lies beyond the obstacles' reach: a path that does not end on the ground is
    // sampled no farther than the node of a run's grid (from the run's start, powers of two)
    // that covers it, where the sampler would stop.
    const double reach = !ground && obstacles ? obstacles->reach() : kInf;
    auto covering_node_end = [&](double from) {
        const double r = reach - from;
        if (!(r > 0.0)) return from;
        if (!std::isfinite(r)) return kInf;
        int e = 0;
        std::frexp(r, &e);  // r in [2^(e-1), 2^e)
        double size = std::ldexp(1.0, e);
        if (0.5 * size >= r) size *= 0.5;
        return from + size;
    };
    // The turning points before the end split the path into monotone runs; each is asked for
    // when the run before it has been sampled, so that none is computed beyond a stop.
    const int count = path.turning_point_count();
    int next_k = 0;
    bool no_more = count == 0;
    auto next_turn = [&](double after, double& dz) {
        while (!no_more && (count < 0 || next_k < count)) {
            TurningPoint tp;
            if (!path.turning_point_before(next_k++, end, tp)) break;
            if (tp.dz > after) {
                dz = tp.dz;
                return true;
            }
        }
        no_more = true;
        return false;
    };
    double b = 0.0;
    bool turn_ahead = next_turn(0.0, b);
    out.turns = turn_ahead;
    if (turn_ahead) out.dz_turn = b;
    // A path rising from its start that turns nowhere before the end, met by nothing near it:
    // kept as its start and its end direction (wedge_is_clear).
    const bool whole_clear =
        obstacles && !ground && !turn_ahead && wedge_is_clear(path, st, *obstacles, escapes, end);
    double a = 0.0, ya = y0;
    while (!whole_clear && !sampler.stopped()) {
        const double run_end = turn_ahead ? b : end;
        const double c = covering_node_end(a);
        if (c < run_end) {
            if (c > a) sampler.run(a, ya, c, sampler.height(c));
            sampler.stop();
            break;
        }
        if (!turn_ahead) {
            // The far end's height waits until a test needs it (escaping paths).
            sampler.run(a, ya, end, escapes ? kNaN : sampler.height(end));
            break;
        }
        const double yb = sampler.height(b);
        sampler.run(a, ya, b, yb);
        a = b;
        ya = yb;
        turn_ahead = next_turn(a, b);
    }
    if (ground) {
        out.end = PathEnd::Ground;
    } else if (escapes) {
        // Its direction where it is cut, at max_dz (or where it leaves the profile's top,
        // before): the same whether it stopped early or not, and the ray's true direction
        // there (the one the sky is seen in; on the curved Earth its local horizontal).
        double at = max_dz;
        if (path.height_at(max_dz) >= path.quadratic()->profile().top()) {
            at = std::min(at, path.quadratic()->dz_straight());
        }
        const bool stopped = whole_clear || sampler.stopped();
        out.end = stopped ? PathEnd::Straight : PathEnd::Cut;
        out.end_slope = path.slope_at(at);
        out.end_slope_dz = at;
        out.end_clear = stopped;
    } else {
        // Cut at the end.  A path stopped where nothing lies beyond still reaches the cut, by
        // one clear stretch: beyond the cut it goes on straight and may meet the ground there.
        if (sampler.stopped() && out.points.back().x < end) sampler.reach_clear(end);
        out.end = PathEnd::Cut;
        out.end_slope = path.slope_at(end);
        out.end_slope_dz = end;
        out.end_clear = whole_clear;
    }
}

SampledPath sample_path(const ExactPath& path, const SampleSettings& st) {
    if (const ExactRay* ray = path.exponential()) return sample_path(*ray, st);
    return sample_exact_path(path, st);
}

void sample_path_near(const ExactPath& path, const SampleSettings& st,
                      const PathObstacles* obstacles, SampledPath& out) {
    if (const ExactRay* ray = path.exponential()) {
        sample_path_near(*ray, st, obstacles, out);
    } else {
        sample_exact_path_near(path, st, obstacles, out);
    }
}

}  // namespace mirage
