#include "atmosphere/path_sampler.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "atmosphere/chord_bound.h"
#include "util/check.h"

namespace mirage {

namespace {

// The step from `a` (at most to `limit`): the room halved k times for the smallest k >= 0 that
// passes, found by galloping from the k of `guess` (the previous step, or an estimate from the
// local curvature; 0: start from the whole room) and bisecting, then grown by 1.5 while it
// passes.  A step passes whenever a longer one does.  Starting near the answer keeps the
// tested points close to `a`, so a lazily computed path is computed only as far as needed.
template <class Within>
double next_step(double a, double limit, Within within, double guess) {
    const double room = limit - a;
    MIRAGE_CHECK(std::isfinite(room) && room > 0.0);
    constexpr int kMaxHalvings = 1074;
    auto halved = [&](int k) {
        // room * 2^-k, exactly: by the exponent's bits while 2^-k is normal.
        if (k < 1022)
            return room * std::bit_cast<double>(static_cast<std::uint64_t>(1023 - k) << 52);
        return std::ldexp(room, -k);
    };
    auto passes = [&](int k) { return within(a, a + halved(k)); };
    int k0 = 0;
    if (guess > 0.0 && guess < room)
        k0 = std::clamp(static_cast<int>(std::lround(std::log2(room / guess))), 0, kMaxHalvings);
    int fail = -1, pass = -1;  // fail < pass: the room halved `fail` times fails, `pass` passes
    if (passes(k0)) {
        pass = k0;
        for (int d = 1; pass > 0; d *= 2) {
            const int t = std::max(0, pass - d);
            if (t <= fail) break;
            if (passes(t)) {
                pass = t;
            } else {
                fail = t;
                break;
            }
        }
    } else {
        fail = k0;
        for (int d = 1; pass < 0; d *= 2) {
            const int t = std::min(fail + d, kMaxHalvings);
            if (passes(t)) {
                pass = t;
            } else {
                MIRAGE_CHECK(t < kMaxHalvings);
                fail = t;
            }
        }
    }
    while (pass - fail > 1) {
        const int mid = fail + (pass - fail) / 2;
        if (passes(mid)) {
            pass = mid;
        } else {
            fail = mid;
        }
    }
    double step = halved(pass);
    MIRAGE_CHECK(a + step > a);
    for (int iter = 0; iter < 60; ++iter) {
        const double grown = 1.5 * step;
        if (grown >= room || !within(a, a + grown)) break;
        step = grown;
    }
    return step;
}

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

SampledPath sample_exact_path(const ExactPath& path, const SampleSettings& st) {
    MIRAGE_CHECK(st.tolerance_m > 0.0 || st.tolerance_rad > 0.0);
    MIRAGE_CHECK(st.max_dz >= 0.0);
    SampledPath out;
    const double y0 = path.y0();
    out.points.push_back({0.0, y0});

    const double max_dz = std::min(st.max_dz, kMaxSampleDistance);
    const bool ground = path.hits_ground() && path.dz_ground() <= max_dz;
    const double dz_end = ground ? path.dz_ground() : max_dz;
    auto finish = [&](double dz_last) {
        if (ground && dz_last >= path.dz_ground()) {
            out.end = PathEnd::Ground;
        } else if (dz_last >= max_dz) {
            out.end = PathEnd::Cut;
            out.end_slope = path.slope_at(dz_last);
        } else {
            out.end = PathEnd::Straight;
            out.end_slope = path.asymptotic_slope();
        }
    };
    auto height = [&](double dz) {
        return (ground && dz >= path.dz_ground()) ? 0.0 : path.height_at(dz);
    };
    auto point = [&](double dz) { out.points.push_back({dz, height(dz)}); };
    auto allowance_at = [&](double dz) { return allowed_error(path, st, dz, height(dz)); };

    if (path.straight()) {
        if (std::isfinite(dz_end)) point(dz_end);
        finish(dz_end);
        return out;
    }
    auto straight_from = [&](double dz) {
        return path.asymptote_departure(dz) <= allowance_at(dz);
    };

    // One monotone run [a, b] sampled forward from a (whose point is already out); may end
    // straight when `may_end_straight`.  Returns where it stopped.
    auto forward = [&](double a, double b, bool may_end_straight) {
        double previous =
            chord_guess(path.curvature_bound(height(a), height(a)), allowance_at(a), st);
        while (a < b && !(may_end_straight && straight_from(a))) {
            const double y_a = height(a), allow_a = allowed_error(path, st, a, y_a);
            const double step = next_step(
                a, b,
                [&](double lo, double hi) {
                    hi = std::min(hi, b);
                    const double m = path.curvature_bound(y_a, height(hi));
                    return chord_within(m, lo, hi, allow_a, st);
                },
                previous);
            previous = step;
            a = std::min(b, a + step);
            point(a);
        }
        return a;
    };

    const int count = path.turning_point_count();
    const bool turns =
        count != 0 && path.turning_point(0).dz > 0.0 && path.turning_point(0).dz < dz_end;
    if (!turns) {
        finish(forward(0.0, dz_end, true));
        return out;
    }

    // The first turning point: sample outward from it (u = |dz - zt|) so that both mirror
    // images of every step keep the tolerance, then reflect (as sampler.cpp does).
    out.turns = true;
    const double zt = path.turning_point(0).dz;
    out.dz_turn = zt;
    const bool trapped = count < 0;
    // The run after the turning point ends at the next one (trapped rays) or the end.
    const double next_event = trapped ? std::min(path.turning_point(1).dz, dz_end) : dz_end;
    const double y_turn_path = path.height_at(zt);
    const double u_before = zt;
    const double u_after_max = next_event - zt;
    auto branch_height = [&](double u) {
        return u <= zt ? path.height_at(zt - u) : height(std::min(zt + u, dz_end));
    };
    std::vector<double> us{0.0}, ys{y_turn_path};
    bool straight_after = false;
    double u_after_end = u_after_max;
    double u = 0.0;
    double previous =
        chord_guess(path.curvature_bound(y_turn_path, y_turn_path), allowance_at(zt), st);
    const bool may_end_straight = !trapped;
    while (true) {
        const bool need_before = u < u_before;
        const bool need_after = !straight_after && u < u_after_max;
        if (!need_before && !need_after) break;
        const double limit = std::max(need_before ? u_before : 0.0, need_after ? u_after_max : 0.0);
        const double y_u = branch_height(u);
        const double allow_after = need_after && u < u_after_max ? allowance_at(zt + u) : 0.0;
        const double step = next_step(
            u, limit,
            [&](double lo, double hi) {
                const double y_hi = branch_height(hi);
                const double m = path.curvature_bound(y_u, y_hi);
                bool ok = true;
                if (lo < u_before) {
                    const double p = std::max(0.0, zt - hi);
                    const double y_p = hi <= zt ? y_hi : height(p);
                    ok = ok && chord_within(m, p, zt - lo, allowed_error(path, st, p, y_p), st);
                }
                if (need_after && lo < u_after_max) {
                    const double q = std::min(zt + hi, next_event);
                    ok = ok && chord_within(m, zt + lo, q, allow_after, st);
                }
                return ok;
            },
            previous);
        previous = step;
        u = std::min(limit, u + step);
        us.push_back(u);
        ys.push_back(branch_height(u));
        if (may_end_straight && need_after && u < u_after_max && straight_from(zt + u)) {
            straight_after = true;
            u_after_end = u;
        }
    }
    for (size_t k = us.size(); k-- > 1;) {
        if (us[k] < u_before) out.points.push_back({zt - us[k], ys[k]});
    }
    out.points.push_back({zt, y_turn_path});
    bool reached_next = false;
    for (size_t k = 1; k < us.size(); ++k) {
        if (straight_after && us[k] > u_after_end) break;
        if (us[k] >= u_after_max) {
            out.points.push_back({next_event, height(next_event)});
            reached_next = true;
            break;
        }
        out.points.push_back({zt + us[k], ys[k]});
    }
    if (straight_after || !trapped || !reached_next || next_event >= dz_end) {
        finish(out.points.back().x);
        return out;
    }
    // Trapped: every further run, from one turning point to the next, sampled forward.
    for (int k = 1;; ++k) {
        const double a = path.turning_point(k).dz;
        if (a >= dz_end) break;
        const double b = std::min(path.turning_point(k + 1).dz, dz_end);
        forward(a, b, false);
        if (b >= dz_end) break;
    }
    finish(out.points.back().x);
    return out;
}

}  // namespace mirage
