#include "atmosphere/sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "atmosphere/chord_bound.h"
#include "atmosphere/step_search.h"
#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Largest |y''| over a piece of path whose lowest height is y_low.
double curvature_bound(const ExactRay& ray, double y_low) {
    return std::fabs(curvature_at_height(ray, std::max(0.0, y_low)));
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

    const double max_dz = std::min(st.max_dz, kMaxSampleDistance);
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
                    return chord_within(curvature_bound(ray, y_low), lo, hi, allowance_at(lo), st);
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
        const double step = next_step(
            u, limit,
            [&](double lo, double hi) {
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
            },
            previous);
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

// ---------------------------------------------------------------------------------------------
// Sampling near what the path can meet (sample_path_near).

namespace mirage {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A distance from which the path's departure from its asymptote is at most d (the departure
// decreases along the path): the smallest for a bound of the departure, ln(1 + x) <= x for
// inferior paths and -ln(1 - x) <= x / (1 - x) for escaping superior ones, which needs no
// expm1; +inf for d <= 0.
double departure_distance(const ExactRay& ray, double d) {
    if (!(d > 0.0)) return kInf;
    const double z = 0.5 * ray.profile.alpha * d;
    if (ray.s > 0) {
        // (2/alpha) ln(1 + exp(-2u)) <= (2/alpha) exp(-2u) <= d  <=  u >= ln(1 / z) / 2.
        const double u = z >= 1.0 ? 0.0 : -0.5 * std::log(z);
        return ray.dz_turn + u / ray.c;
    }
    // Escaping superior: -(2/alpha) ln(1 - y) <= (2/alpha) y / (1 - y) <= d for
    // y = r exp(-2x) <= z / (1 + z).
    const double ps = ray.P + ray.q;
    const double r = ray.E * ray.E / (ps * ps);
    const double g = z / (1.0 + z);
    const double x = r <= g ? 0.0 : 0.5 * std::log(r / g);
    return x / ray.c;
}

// The smallest power of two above `length` (> 0): 2^e for length = m 2^e, m in [0.5, 1), as
// frexp says; from the bits for a normal double.
double grid_size(double length) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &length, sizeof bits);
    const std::uint64_t biased = (bits >> 52) & 0x7ff;
    if (biased == 0 || biased >= 0x7fe) {
        int e = 0;
        std::frexp(length, &e);
        return std::ldexp(1.0, e);
    }
    const std::uint64_t power = (biased + 1) << 52;
    double size = 0.0;
    std::memcpy(&size, &power, sizeof size);
    return size;
}

// A point of the path: its height, slope and curvature (NaN until needed where marked).
struct PathPoint {
    double dz = 0.0;
    double y = 0.0;
    double slope = kNaN;
    double curvature = kNaN;
};

class NearSampler {
  public:
    NearSampler(const ExactRay& ray, const SampleSettings& st, const PathObstacles* obstacles,
                SampledPath& path)
        : ray_(ray),
          st_(st),
          obstacles_(obstacles),
          // The distance from the start never shrinks along a path whose start slope is at
          // most 1 (below the start height |y'| is at most the start's slope and the path stays
          // above its start tangent, inferior; mirrored for superior), so the allowance at a
          // stretch's near end bounds it over the stretch; otherwise the horizontal distance
          // does.
          distance_grows_(std::fabs(ray.cos_i) <= ray.sin_i),
          convex_(ray.s > 0),
          path_(path) {}

    PathPoint point(double dz) const {
        const PathState s = state_at(ray_, dz);
        return {dz, s.y, s.slope, s.curvature};
    }

    /// Where a stretch ending there must keep the tolerance whatever else: on a surface at
    /// the ground.
    void set_ground_end(double dz) { ground_end_ = dz; }

    /// Samples the monotone piece from a to b.
    void piece(const PathPoint& a, const PathPoint& b) {
        const double length = b.dz - a.dz;
        if (!(length > 0.0)) return;
        const double size = grid_size(length);
        if (obstacles_ && b.dz == ground_end_) {
            ground_node(a, b, size);
        } else {
            node(a, b, size);
        }
    }

    /// Whether something may lie near an escaping path anywhere, its straight end included:
    /// the path lies in the wedge from its start between the slopes of its start and its
    /// asymptote (its slope moves monotonically from one to the other), above its turning
    /// point; the allowance grows with the distance, by at most tol_rad sqrt(1 + s^2) per
    /// unit of dz for slopes up to s.
    bool wedge_may_meet() const {
        const double s0 = ray_.cos_i / ray_.sin_i;
        const double s1 = asymptotic_slope(ray_);
        MIRAGE_CHECK(std::isfinite(s0) && std::isfinite(s1));
        const double s_max = std::max(std::fabs(s0), std::fabs(s1));
        const double spread =
            st_.tolerance_rad * std::sqrt(1.0 + s_max * s_max) + 1e-9 * (1.0 + s_max);
        const double margin = st_.tolerance_m + st_.tolerance_rad * st_.start_distance +
                              1e-9 * (1.0 + std::fabs(ray_.y0));
        const double lo_slope = convex_ ? s0 : s1;
        const double hi_slope = convex_ ? s1 : s0;
        PathRegion wedge;
        wedge.dz_lo = 0.0;
        wedge.dz_hi = kInf;
        const PathLine below{0.0, ray_.y0 - margin, lo_slope - spread};
        wedge.lower = {below, below};
        wedge.lower_count = 1;
        if (ray_.ray_class == RayClass::InfTurn) {
            wedge.lower[1] = PathLine{0.0, ray_.y_turn - margin, -spread};
            wedge.lower_count = 2;
        }
        const PathLine above{0.0, ray_.y0 + margin, hi_slope + spread};
        wedge.upper = {above, above};
        wedge.upper_count = 1;
        return obstacles_->may_meet(wedge);
    }

  private:
    double allowance_at(double dz, double y) const {
        double dist = dz;
        if (distance_grows_) {
            const double dy = y - ray_.y0;
            dist = std::sqrt(dz * dz + dy * dy);
        }
        return st_.tolerance_m + st_.tolerance_rad * (st_.start_distance + dist);
    }

    // The sampler's test: the chord from a to b keeps the tolerance.  |y''| is largest at the
    // lower end (it falls with height in both profiles; a stretch lies within one monotone
    // piece).
    bool fine(const PathPoint& a, const PathPoint& b) const {
        const double m = std::fabs(a.y < b.y ? a.curvature : b.curvature);
        return chord_within(m, a.dz, b.dz, allowance_at(a.dz, a.y), st_);
    }

    // Whether nothing the path can meet lies near the stretch from a to b; then its length.
    bool clear(const PathPoint& a, const PathPoint& b, double& length) const {
        const double sa = a.slope;
        const double sb = b.slope;
        MIRAGE_CHECK(std::isfinite(sa) && std::isfinite(sb));
        const double w = b.dz - a.dz;
        const double dy = b.y - a.y;
        // The corner where the end tangents meet; the path lies in the triangle it makes with
        // the chord (convex: above both tangents and below the chord).
        double apex_dz = a.dz;
        if (sa != sb) apex_dz = std::clamp(a.dz + (dy - sb * w) / (sa - sb), a.dz, b.dz);
        const double ta = a.y + sa * (apex_dz - a.dz);
        const double tb = b.y + sb * (apex_dz - b.dz);
        const double apex_y = convex_ ? std::max(ta, tb) : std::min(ta, tb);
        const double y_lo = std::min({a.y, b.y, apex_y});
        const double y_hi = std::max({a.y, b.y, apex_y});
        // Everything within the allowance of the path: the allowance over the stretch is at
        // most that of the farthest point of the triangle from the start.
        const double far_dy = std::max(std::fabs(y_hi - ray_.y0), std::fabs(y_lo - ray_.y0));
        const double reach = std::sqrt(b.dz * b.dz + far_dy * far_dy);
        const double slack = 1e-9 * (1.0 + b.dz + std::max(std::fabs(y_lo), std::fabs(y_hi)));
        const double margin =
            st_.tolerance_m + st_.tolerance_rad * (st_.start_distance + reach) + slack;
        const PathLine chord{a.dz, a.y, dy / w};
        const PathLine tangent_a{a.dz, a.y, sa};
        const PathLine tangent_b{b.dz, b.y, sb};
        auto shifted = [](PathLine l, double by) {
            l.y += by;
            return l;
        };
        PathRegion region;
        region.dz_lo = a.dz;
        region.dz_hi = b.dz;
        if (convex_) {
            region.lower = {shifted(tangent_a, -margin), shifted(tangent_b, -margin)};
            region.upper = {shifted(chord, margin), shifted(chord, margin)};
            region.upper_count = 1;
        } else {
            region.lower = {shifted(chord, -margin), shifted(chord, -margin)};
            region.lower_count = 1;
            region.upper = {shifted(tangent_a, margin), shifted(tangent_b, margin)};
        }
        if (obstacles_->may_meet(region)) return false;
        // The arc lies between the chord and the tangents' two legs: (2 chord + legs) / 3 is
        // its length to fourth order in the angle it turns through.
        auto leg = [](double x, double y) { return std::sqrt(x * x + y * y); };
        const double legs = leg(apex_dz - a.dz, apex_y - a.y) + leg(b.dz - apex_dz, b.y - apex_y);
        length = (2.0 * leg(w, dy) + legs) / 3.0;
        return true;
    }

    void emit(const PathPoint& b, double clear_length) {
        path_.points.push_back({b.dz, b.y});
        if (obstacles_) path_.clear_length.push_back(clear_length);
    }

    // The grid node [a.dz, a.dz + size], cut at the piece's end b.dz.
    void node(const PathPoint& a, const PathPoint& b, double size) {
        if (fine(a, b)) {
            emit(b, 0.0);
            return;
        }
        double length = 0.0;
        if (obstacles_ && clear(a, b, length)) {
            emit(b, length);
            return;
        }
        while (a.dz + 0.5 * size >= b.dz) size *= 0.5;  // the node's part before the end
        const double mid = a.dz + 0.5 * size;
        MIRAGE_CHECK(mid > a.dz && mid < b.dz);
        const PathPoint m = point(mid);
        node(a, m, 0.5 * size);
        node(m, b, 0.5 * size);
    }

    // The same for a node ending on a surface at the ground, whose last stretch must keep the
    // tolerance: the nodes that end there are halved until one does, as node() would halve
    // them, and their left halves are first tested together (a clear union holds nothing
    // their own segments would meet).  The path descends to the ground here, so every such
    // node's lowest point is its end on the ground; a node the chord test fails even with
    // the largest allowance it could have there is halved without the path's point at its
    // start (computed only if the halves are needed one by one).
    void ground_node(const PathPoint& a, const PathPoint& b, double size) {
        const double m = std::fabs(b.curvature);
        const double far_dy = std::max(std::fabs(a.y - ray_.y0), ray_.y0);
        auto surely_coarse = [&](double p) {
            const double reach = distance_grows_ ? std::sqrt(p * p + far_dy * far_dy) : p;
            const double allowance =
                st_.tolerance_m + st_.tolerance_rad * (st_.start_distance + reach);
            return !chord_within(m, p, b.dz, allowance, st_);
        };
        int count = 0;  // halves set aside: [starts[k], starts[k + 1]], grid sizes sizes[k]
        double starts[kMaxHalves + 1];
        double sizes[kMaxHalves];
        starts[0] = a.dz;
        PathPoint lo = a;
        bool lo_known = true;
        while (true) {
            if (!lo_known && !surely_coarse(lo.dz)) {
                lo = point(lo.dz);
                lo_known = true;
            }
            if (lo_known && fine(lo, b)) break;
            while (lo.dz + 0.5 * size >= b.dz) size *= 0.5;
            const double mid = lo.dz + 0.5 * size;
            MIRAGE_CHECK(mid > lo.dz && mid < b.dz && count < kMaxHalves);
            size *= 0.5;
            sizes[count] = size;
            starts[++count] = mid;
            lo.dz = mid;
            lo_known = false;
        }
        double length = 0.0;
        if (count > 1 && clear(a, lo, length)) {
            emit(lo, length);
        } else {
            PathPoint left = a;
            for (int k = 0; k < count; ++k) {
                const PathPoint right = k + 1 == count ? lo : point(starts[k + 1]);
                node(left, right, sizes[k]);
                left = right;
            }
        }
        emit(b, 0.0);
    }

    static constexpr int kMaxHalves = 1100;  // a double halves at most this often

    const ExactRay& ray_;
    const SampleSettings& st_;
    const PathObstacles* obstacles_;
    bool distance_grows_;
    bool convex_;
    double ground_end_ = kNaN;
    SampledPath& path_;
};

}  // namespace

RegionTest::RegionTest(const PathRegion& region) : region_(region) {
    // Only the lines in use (meets() reads no others).
    for (int k = 0; k < region.lower_count; ++k) {
        const double sl = region.lower[k].slope;
        inv_lower_[k] = sl != 0.0 ? 1.0 / sl : 0.0;
    }
    for (int k = 0; k < region.upper_count; ++k) {
        const double su = region.upper[k].slope;
        inv_upper_[k] = su != 0.0 ? 1.0 / su : 0.0;
    }
}

bool RegionTest::meets(double dz_lo, double dz_hi, double y_lo, double y_hi) const {
    const PathRegion& r = region_;
    double lo = std::max(dz_lo, r.dz_lo);
    double hi = std::min(dz_hi, r.dz_hi);
    if (!(lo <= hi)) return false;
    // Each line leaves a half-line of dz, on one side of where it crosses the level: a lower
    // line must be at or below y_hi, an upper one at or above y_lo.
    for (int k = 0; k < r.lower_count; ++k) {
        const PathLine& l = r.lower[k];
        if (l.slope == 0.0) {
            if (l.y > y_hi) return false;
            continue;
        }
        const double cross = l.dz + (y_hi - l.y) * inv_lower_[k];
        if (l.slope > 0.0) {
            hi = std::min(hi, cross);
        } else {
            lo = std::max(lo, cross);
        }
    }
    for (int k = 0; k < r.upper_count; ++k) {
        const PathLine& u = r.upper[k];
        if (u.slope == 0.0) {
            if (u.y < y_lo) return false;
            continue;
        }
        const double cross = u.dz + (y_lo - u.y) * inv_upper_[k];
        if (u.slope > 0.0) {
            lo = std::max(lo, cross);
        } else {
            hi = std::min(hi, cross);
        }
    }
    return lo <= hi;
}

bool region_meets_rectangle(const PathRegion& region, double dz_lo, double dz_hi, double y_lo,
                            double y_hi) {
    return RegionTest(region).meets(dz_lo, dz_hi, y_lo, y_hi);
}

double straight_end_start(const ExactRay& ray, const SampleSettings& st, double from) {
    if (!has_asymptote(ray)) return kInf;
    // The allowance is at least A(dz) = tol_m + tol_rad (start_distance + dz) (the distance
    // from the start is at least the horizontal one), so any T with departure(T) <= A(T)
    // will do, that is T >= g(T) = departure_distance(A(T)).  g decreases, so max(x, g(x))
    // is such a T for every x; two steps x <- g(x) from the path's own length scale 1/c
    // close in on the smallest.
    auto g = [&](double dz) {
        const double a = st.tolerance_m + st.tolerance_rad * (st.start_distance + dz);
        return std::max(from, departure_distance(ray, a));
    };
    double x = from + 1.0 / ray.c;
    double best = kInf;
    for (int iter = 0; iter < 2; ++iter) {
        const double gx = g(x);
        best = std::min(best, std::max(x, gx));
        if (gx == x) break;
        x = gx;
    }
    return std::min(best, kMaxSampleDistance);
}

SampledPath sample_path_near(const ExactRay& ray, const SampleSettings& st,
                             const PathObstacles* obstacles) {
    SampledPath path;
    sample_path_near(ray, st, obstacles, path);
    return path;
}

void sample_path_near(const ExactRay& ray, const SampleSettings& st, const PathObstacles* obstacles,
                      SampledPath& path) {
    MIRAGE_CHECK(st.tolerance_m > 0.0 || st.tolerance_rad > 0.0);
    MIRAGE_CHECK(st.max_dz >= 0.0);
    if (ray.s == 0) {  // a straight line: one segment
        path = sample_path(ray, st);
        return;
    }
    path.points.clear();
    path.clear_length.clear();
    path.end = PathEnd::Straight;
    path.end_slope = 0.0;
    path.end_clear = false;
    path.points.push_back({0.0, ray.y0});
    NearSampler sampler(ray, st, obstacles, path);

    const double max_dz = std::min(st.max_dz, kMaxSampleDistance);
    const bool ground = ray.hits_ground && ray.dz_ground <= max_dz;
    double end = ground ? ray.dz_ground : max_dz;
    if (ground && obstacles && obstacles->ground()) sampler.set_ground_end(ray.dz_ground);

    const bool vertex_ahead =
        (ray.ray_class == RayClass::InfTurn || ray.ray_class == RayClass::SupTrappedUp) &&
        ray.dz_turn > 0.0 && ray.dz_turn < end;
    const double start = vertex_ahead ? ray.dz_turn : 0.0;
    path.turns = vertex_ahead;
    path.dz_turn = vertex_ahead ? ray.dz_turn : 0.0;
    const bool escapes = !ground && has_asymptote(ray);
    if (escapes && st.max_dz >= kMaxSampleDistance && obstacles && !sampler.wedge_may_meet()) {
        // Nothing lies near the path anywhere, its straight end included: all that counts is
        // its final direction (for the sky), so it is kept as its start and a straight end of
        // the asymptotic slope from there, not to be tested.  That line lies in the wedge too
        // (between the start's slope and the asymptote's, from the start), so the path's
        // polyline still meets nothing; the distance where the asymptote keeps the tolerance
        // and the path's height there are not needed.
        path.end = PathEnd::Straight;
        path.end_slope = asymptotic_slope(ray);
        path.end_clear = true;
        return;
    }
    bool straight = false;
    if (escapes) {
        const double t = straight_end_start(ray, st, start);
        if (t < end) {
            end = t;
            straight = true;
        }
    }

    PathPoint a = sampler.point(0.0);
    if (vertex_ahead) {
        const PathPoint vertex = sampler.point(ray.dz_turn);
        sampler.piece(a, vertex);
        a = vertex;
    }
    const PathPoint b = sampler.point(end);
    if (end > start) sampler.piece(a, b);

    const double last = path.points.back().x;
    if (ground) {
        path.end = PathEnd::Ground;
    } else if (straight) {
        path.end = PathEnd::Straight;
        path.end_slope = asymptotic_slope(ray);
    } else {
        path.end = PathEnd::Cut;
        path.end_slope = slope_at(ray, last);
    }
}

}  // namespace mirage
