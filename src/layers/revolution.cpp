#include "layers/revolution.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The node interval holding r (the last one beyond the last node).
int cell_of(const std::vector<double>& radii, double r) {
    const int n = static_cast<int>(radii.size());
    if (n < 2) return 0;
    const int j =
        static_cast<int>(std::upper_bound(radii.begin(), radii.end(), r) - radii.begin()) - 1;
    return std::clamp(j, 0, n - 2);
}

// The slope of boundary k at node j, from its neighbours (one-sided at the ends).
double nodal_slope(const RevolutionStack& s, int k, int j) {
    const int n = static_cast<int>(s.radii.size());
    if (n < 2) return 0.0;
    const int a = std::max(0, j - 1), b = std::min(n - 1, j + 1);
    if (j == 0) return 0.0;  // on the axis a surface of revolution is level (or has a cusp)
    return (s.heights[k][b] - s.heights[k][a]) / (s.radii[b] - s.radii[a]);
}

}  // namespace

double RevolutionStack::height(int k, double r) const {
    const std::vector<double>& h = heights[k];
    if (radii.size() < 2 || r >= radii.back()) return h.back();
    const int j = cell_of(radii, r);
    const double f = (r - radii[j]) / (radii[j + 1] - radii[j]);
    return h[j] + f * (h[j + 1] - h[j]);
}

int RevolutionStack::layer_at(double r, double y) const {
    // Boundaries are ordered at every radius: the first one above y.
    int lo = 0, hi = boundaries();
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (height(mid, r) <= y)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

bool well_formed(const RevolutionStack& s) {
    if (s.radii.empty() || s.radii.front() != 0.0) return false;
    for (size_t j = 1; j < s.radii.size(); ++j)
        if (!(s.radii[j] > s.radii[j - 1])) return false;
    if (s.index.size() != s.heights.size() + 1) return false;
    if (!s.air.empty() && s.air.size() != s.index.size()) return false;
    for (double n : s.index)
        if (!(n > 0.0) || !std::isfinite(n)) return false;
    for (size_t k = 0; k < s.heights.size(); ++k) {
        if (s.heights[k].size() != s.radii.size()) return false;
        for (size_t j = 0; j < s.radii.size(); ++j) {
            if (!std::isfinite(s.heights[k][j])) return false;
            if (k > 0 && !(s.heights[k][j] > s.heights[k - 1][j])) return false;
        }
    }
    return true;
}

RevolutionStack revolution_of(const LayerStack& stack, double eye_y) {
    RevolutionStack r;
    r.eye_y = eye_y;
    r.radii = {0.0};
    for (double h : stack.heights) r.heights.push_back({h});
    for (int k = 0; k <= stack.boundaries(); ++k) r.index.push_back(stack.index(k));
    r.air = stack.air;
    return r;
}

MeridianPath trace_meridian(const RevolutionStack& s, double elevation, double reach,
                            int max_events, bool pov_iors) {
    MIRAGE_CHECK(well_formed(s) && reach > 0.0);
    MeridianPath out;
    glm::dvec2 p(0.0, s.eye_y);
    glm::dvec2 d(std::cos(elevation), std::sin(elevation));
    int k = s.layer_at(0.0, s.eye_y);
    const int k_cam = k;
    const int N = s.boundaries();
    const int nodes = static_cast<int>(s.radii.size());
    out.points.push_back(p);
    auto ior = [&](int layer) { return static_cast<float>(s.index[layer] / s.index[k_cam]); };
    auto air = [&](int layer) { return layer == k_cam || (!s.air.empty() && s.air[layer]); };
    auto ratio = [&](int from, int to) {
        // POV-Ray's quotients: the eye's layer and the gaps are its atmosphere (1, in double
        // precision); between two layers, one float over the other.
        if (!pov_iors) return s.index[from] / s.index[to];
        if (air(from) && air(to)) return 1.0;
        if (air(from)) return 1.0 / static_cast<double>(ior(to));
        if (air(to)) return static_cast<double>(ior(from));
        return static_cast<double>(ior(from) / ior(to));
    };
    for (int events = 0;; ++events) {
        if (events >= max_events) {
            out.cut_off = true;
            out.direction = d;
            return out;
        }
        if (d.x <= 0.0) {  // towards the axis: leaves the half-plane's model
            out.back = true;
            out.direction = d;
            return out;
        }
        // The first boundary event along d: the floor (k - 1), the ceiling (k), the ground.
        double t_best = kInf;
        int b_best = -2;
        const double t_reach = (reach - p.x) / d.x;
        if (d.y < 0.0) {  // the ground, wherever the boundaries lie
            t_best = -p.y / d.y;
            b_best = -1;
        }
        for (int j = cell_of(s.radii, p.x); j < nodes; ++j) {
            const double r0 = std::max(p.x, s.radii[j]);
            const double r1 = j + 1 < nodes ? s.radii[j + 1] : kInf;
            const double t0 = (r0 - p.x) / d.x;
            if (t0 > std::min(t_best, t_reach)) break;
            for (int b : {k - 1, k}) {
                if (b < 0 || b >= N) continue;
                // The boundary in this cell: y = ya + sl (r - ra).
                double ra, ya, sl;
                if (j + 1 < nodes) {
                    ra = s.radii[j];
                    ya = s.heights[b][j];
                    sl = (s.heights[b][j + 1] - ya) / (s.radii[j + 1] - ra);
                } else {
                    ra = s.radii[j];
                    ya = s.heights[b][j];
                    sl = 0.0;
                }
                const double den = d.y - sl * d.x;
                if (den == 0.0) continue;
                const double t = (ya + sl * (p.x - ra) - p.y) / den;
                const double r = p.x + t * d.x;
                // Within this cell, ahead of the ray (a hit at the very start is the boundary
                // just left: ignored, as POV-Ray ignores hits nearer than its minimum depth).
                if (t > 1e-12 * (1.0 + std::fabs(p.x) + std::fabs(p.y)) && r >= r0 - 1e-12 &&
                    r <= r1 && t < t_best) {
                    t_best = t;
                    b_best = b;
                }
            }
        }
        if (t_reach <= t_best) {
            p += t_reach * d;
            out.points.push_back(p);
            out.direction = d;
            return out;
        }
        p += t_best * d;
        out.points.push_back(p);
        if (b_best == -1) {
            out.ground = true;
            out.direction = d;
            return out;
        }
        const int next = b_best == k ? k + 1 : k - 1;
        // The interpolated normal, facing the incoming ray.
        double sl = 0.0;
        if (nodes >= 2 && p.x < s.radii.back()) {
            const int j = cell_of(s.radii, p.x);
            const double f = (p.x - s.radii[j]) / (s.radii[j + 1] - s.radii[j]);
            sl = (1.0 - f) * nodal_slope(s, b_best, j) + f * nodal_slope(s, b_best, j + 1);
        }
        glm::dvec2 n = glm::dvec2(-sl, 1.0) / std::sqrt(1.0 + sl * sl);
        double cos_i = -(d.x * n.x + d.y * n.y);
        if (cos_i < 0.0) {
            n = -n;
            cos_i = -cos_i;
        }
        const double eta = ratio(k, next);
        if (std::fabs(eta - 1.0) < 1e-10) {  // POV-Ray passes a ratio of 1 freely
            k = next;
            continue;
        }
        ++out.crossings;
        const double k2 = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
        if (k2 < 0.0) {
            d += 2.0 * cos_i * n;  // total internal reflection
        } else {
            d = eta * d + (eta * cos_i - std::sqrt(k2)) * n;
            k = next;
        }
        d /= std::sqrt(d.x * d.x + d.y * d.y);
    }
}

double path_height(const MeridianPath& path, double r) {
    const auto& P = path.points;
    for (size_t i = 1; i < P.size(); ++i) {
        if (P[i].x >= r && P[i - 1].x <= r) {
            const double dr = P[i].x - P[i - 1].x;
            if (dr <= 0.0) return P[i].y;
            return P[i - 1].y + (r - P[i - 1].x) / dr * (P[i].y - P[i - 1].y);
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace mirage
