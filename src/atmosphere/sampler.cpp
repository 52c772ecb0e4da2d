#include "atmosphere/sampler.h"

#include <algorithm>
#include <cmath>

#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Paths are followed at most this far (m); beyond, they continue straight.  Far larger than
// any scene, and small enough that no coordinate overflows.
constexpr double kMaxDistance = 1e9;

// Largest |y''| over a piece of path whose lowest height is y_low.
double curvature_bound(const ExactRay& ray, double y_low) {
    return std::fabs(curvature_at_height(ray, std::max(0.0, y_low)));
}

// How far the path beyond dz still departs from its asymptote (0 when it has none).
// Inferior, after the vertex: (2/alpha) ln(1 + exp(-2u)), u = c (dz - dz_t).
// Escaping superior, going up: (2/alpha) |ln(1 - r exp(-2x))|, r = E0 / (P + sigma)^2.
double asymptote_departure(const ExactRay& ray, double dz) {
    const double alpha = ray.profile.alpha;
    if (ray.s > 0) {
        const double u = ray.c * (dz - ray.dz_turn);
        if (u <= 0.0) return kInf;
        return (2.0 / alpha) * std::log1p(std::exp(-2.0 * u));
    }
    if (ray.ray_class == RayClass::SupEscapeUp && ray.k2 < 0.0) {
        const double ps = ray.P + ray.q;
        const double r = ray.E * ray.E / (ps * ps);
        return (2.0 / alpha) * -std::log1p(-r * std::exp(-2.0 * ray.c * dz));
    }
    return kInf;
}

bool has_asymptote(const ExactRay& ray) {
    return (ray.s > 0 && !ray.hits_ground) ||
           (ray.ray_class == RayClass::SupEscapeUp && ray.k2 < 0.0);
}

// Whether the chord over the dz interval [p, q] keeps the tolerance when |y''| <= m there.
// Linear interpolation errs by at most m (x - p)(q - x) / 2 at x; the allowance is at least
// allow_p (it grows away from the start) and at least tol_m + tol_rad (start_distance + x)
// (the distance from the start is at least the horizontal one).  Either bound suffices; the
// second matters next to the start, where an angular allowance vanishes.
bool chord_within(double m, double p, double q, double allow_p, const SampleSettings& st) {
    if (q <= p) return true;
    if (m * (q - p) * (q - p) <= 8.0 * allow_p) return true;
    if (st.tolerance_rad <= 0.0) return false;
    // max over x in [p, q] of m (x - p)(q - x)/2 - tol_rad x, a downward parabola.
    const double x = std::clamp(0.5 * (p + q) - st.tolerance_rad / m, p, q);
    const double excess = 0.5 * m * (x - p) * (q - x) - st.tolerance_rad * x;
    return excess <= st.tolerance_m + st.tolerance_rad * st.start_distance;
}

// Chooses the next step from `a` (at most to `limit`) so that every dz image of [a, a+step]
// that `within(lo, hi)` checks keeps the tolerance.  `previous` is the step before (0 for
// none): where the search starts.
template <class Within>
double next_step(double a, double limit, Within within, double previous) {
    const double room = limit - a;
    MIRAGE_CHECK(std::isfinite(room) && room > 0.0);
    // The whole room if it passes; else the room halved k times for the smallest k that
    // passes, then grown back while it passes: steps are within a factor 2 of the largest
    // that passes.  A step passes whenever a longer one does (the chord error and the
    // curvature bound grow with the step), so k is found by galloping from the previous
    // step's k and bisecting, in a handful of tests instead of one per halving (the room is
    // up to 1e9 m).  ldexp(room, -k) is the room halved k times, exactly.
    double step = room;
    if (within(a, a + step)) return step;
    constexpr int kMaxHalvings = 1074;  // below, room * 2^-k is no longer a positive double
    auto passes = [&](int k) { return within(a, a + std::ldexp(room, -k)); };
    int fail = 0;  // the room fails
    int pass = 0;
    int k = 1;
    if (previous > 0.0) {
        k = std::clamp(static_cast<int>(std::lround(std::log2(room / previous))), 1,
                       kMaxHalvings);
    }
    if (passes(k)) {
        pass = k;
        for (int d = 1; pass - d > fail; d *= 2) {
            if (!passes(pass - d)) {
                fail = pass - d;
                break;
            }
            pass -= d;
        }
    } else {
        fail = k;
        for (int d = 1; pass == 0; d *= 2) {
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
    step = std::ldexp(room, -pass);
    MIRAGE_CHECK(a + step > a);
    for (int iter = 0; iter < 60; ++iter) {
        const double grown = 1.5 * step;
        if (grown >= room || !within(a, a + grown)) break;
        step = grown;
    }
    return step;
}

}  // namespace

double allowed_error(const ExactRay& ray, const SampleSettings& st, double dz, double y) {
    const double dist = std::hypot(dz, y - ray.y0);
    return st.tolerance_m + st.tolerance_rad * (st.start_distance + dist);
}

SampledPath sample_path(const ExactRay& ray, const SampleSettings& st) {
    MIRAGE_CHECK(st.tolerance_m > 0.0 || st.tolerance_rad > 0.0);
    MIRAGE_CHECK(st.max_dz >= 0.0);
    SampledPath path;
    path.points.push_back({0.0, ray.y0});

    const double max_dz = std::min(st.max_dz, kMaxDistance);
    const bool ground = ray.hits_ground && ray.dz_ground <= max_dz;
    const double dz_end = ground ? ray.dz_ground : max_dz;
    auto finish = [&](double dz_last) {
        if (ground && dz_last >= ray.dz_ground) {
            path.end = PathEnd::Ground;
        } else if (dz_last >= max_dz) {
            path.end = PathEnd::Cut;
            path.end_slope = slope_at(ray, dz_last);
        } else {
            path.end = PathEnd::Straight;
            path.end_slope = ray.s == 0 ? slope_at(ray, 0.0) : asymptotic_slope(ray);
        }
    };
    auto point = [&](double dz) {
        const double y = (ground && dz >= ray.dz_ground) ? 0.0 : height_at(ray, dz);
        path.points.push_back({dz, y});
    };
    auto allowance_at = [&](double dz) { return allowed_error(ray, st, dz, height_at(ray, dz)); };

    if (ray.s == 0) {
        if (std::isfinite(dz_end)) point(dz_end);
        finish(dz_end);
        return path;
    }

    // Beyond dz the line through the path with the asymptotic slope departs from the path by
    // at most the departure at dz (the departure shrinks monotonically).
    auto straight_from = [&](double dz) {
        return has_asymptote(ray) && asymptote_departure(ray, dz) <= allowance_at(dz);
    };

    const bool vertex_ahead =
        (ray.ray_class == RayClass::InfTurn || ray.ray_class == RayClass::SupTrappedUp) &&
        ray.dz_turn > 0.0 && ray.dz_turn < dz_end;
    if (!vertex_ahead) {
        // One monotone piece from the start.
        double a = 0.0;
        double previous = 0.0;
        const bool rising = ray.sg > 0;  // inferior up / escaping up; else descending
        while (a < dz_end && !straight_from(a)) {
            const double step = next_step(
                a, dz_end,
                [&](double lo, double hi) {
                    hi = std::min(hi, dz_end);
                    const double y_low = rising ? height_at(ray, lo) : height_at(ray, hi);
                    return chord_within(curvature_bound(ray, y_low), lo, hi, allowance_at(lo),
                                        st);
                },
                previous);
            previous = step;
            a = std::min(dz_end, a + step);
            point(a);
        }
        finish(a);
        return path;
    }

    // A turning point lies ahead: sample one branch outward from it (u = |dz - dz_t|) so
    // that both mirror images of every step keep the tolerance, then reflect.
    path.turns = true;
    path.dz_turn = ray.dz_turn;
    const double zt = ray.dz_turn;
    const double y_turn_path = height_at(ray, zt);
    const double u_before = zt;  // the start lies this far before the vertex
    const double u_after_max = dz_end - zt;
    // Height of the mirror images at distance u from the vertex (equal on both sides; taken
    // on the side that exists: the part before the vertex always lies above the ground).
    auto branch_height = [&](double u) {
        return u <= zt ? height_at(ray, zt - u) : height_at(ray, std::min(zt + u, dz_end));
    };
    // |y''| grows downward: the inferior vertex is the lowest point, the superior apex the
    // highest, so the bound is taken at the near or the far end of each step.
    auto lowest = [&](double lo, double hi) {
        return ray.s > 0 ? branch_height(lo) : branch_height(hi);
    };
    std::vector<double> us{0.0};
    std::vector<double> ys{y_turn_path};
    bool straight_after = false;
    double u_after_end = u_after_max;
    double u = 0.0;
    double previous = 0.0;
    while (true) {
        const bool need_before = u < u_before;
        const bool need_after = !straight_after && u < u_after_max;
        if (!need_before && !need_after) break;
        const double limit = std::max(need_before ? u_before : 0.0, need_after ? u_after_max : 0.0);
        const double step = next_step(u, limit, [&](double lo, double hi) {
            const double m = curvature_bound(ray, lowest(lo, hi));
            bool ok = true;
            if (lo < u_before) {
                const double p = std::max(0.0, zt - hi);
                ok = ok && chord_within(m, p, zt - lo, allowance_at(p), st);
            }
            if (need_after && lo < u_after_max) {
                const double q = std::min(zt + hi, dz_end);
                ok = ok && chord_within(m, zt + lo, q, allowance_at(zt + lo), st);
            }
            return ok;
        }, previous);
        previous = step;
        u = std::min(limit, u + step);
        us.push_back(u);
        ys.push_back(branch_height(u));
        if (need_after && u < u_after_max && straight_from(zt + u)) {
            straight_after = true;
            u_after_end = u;
        }
    }
    // Before the vertex: the mirror images at zt - u, from the start down to the vertex.
    for (size_t k = us.size(); k-- > 1;) {
        if (us[k] < u_before) path.points.push_back({zt - us[k], ys[k]});
    }
    path.points.push_back({zt, y_turn_path});
    // After it: the same samples reflected, up to the straight end, the ground or the cut.
    for (size_t k = 1; k < us.size(); ++k) {
        if (straight_after && us[k] > u_after_end) break;
        if (us[k] >= u_after_max) {
            path.points.push_back({dz_end, ground ? 0.0 : height_at(ray, dz_end)});
            break;
        }
        path.points.push_back({zt + us[k], ys[k]});
    }
    finish(path.points.back().x);
    return path;
}

double polyline_height(const SampledPath& path, double dz) {
    const auto& p = path.points;
    MIRAGE_CHECK(!p.empty());
    if (dz >= p.back().x) return p.back().y + path.end_slope * (dz - p.back().x);
    auto it = std::upper_bound(p.begin(), p.end(), dz,
                               [](double v, const glm::dvec2& q) { return v < q.x; });
    if (it == p.begin()) return p.front().y;
    const glm::dvec2 a = *(it - 1);
    const glm::dvec2 b = *it;
    if (b.x == a.x) return b.y;
    return a.y + (b.y - a.y) * (dz - a.x) / (b.x - a.x);
}

}  // namespace mirage
