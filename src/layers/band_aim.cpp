#include "layers/band_aim.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

BandWalk::BandWalk(const RevolutionStack& s) : eye_y_(s.eye_y) {
    MIRAGE_CHECK(well_formed(s) && s.radii.size() == 1);
    const int N = s.boundaries();
    k_cam_ = s.layer_at(0.0, s.eye_y);
    bottom_.resize(N + 1);
    top_.resize(N + 1);
    for (int k = 0; k <= N; ++k) {
        bottom_[k] = k == 0 ? 0.0 : s.heights[k - 1][0];
        top_[k] = k == N ? kInf : s.heights[k][0];
    }
    // POV-Ray's ratios (revolution.cpp, trace_meridian with pov_iors): the eye's layer and the
    // gaps are its atmosphere, index 1 in double precision; every other layer holds its index
    // over the eye layer's as a float, and between two such layers the ratio is a quotient of
    // floats.
    auto ior = [&](int layer) { return static_cast<float>(s.index[layer] / s.index[k_cam_]); };
    auto air = [&](int layer) { return layer == k_cam_ || (!s.air.empty() && s.air[layer]); };
    auto ratio = [&](int from, int to) {
        if (air(from) && air(to)) return 1.0;
        if (air(from)) return 1.0 / static_cast<double>(ior(to));
        if (air(to)) return static_cast<double>(ior(from));
        return static_cast<double>(ior(from) / ior(to));
    };
    // POV-Ray passes a ratio within 1e-10 of 1 freely (revolution.cpp does the same).
    auto effective = [&](int from, int to) {
        const double r = ratio(from, to);
        return std::fabs(r - 1.0) < 1e-10 ? 1.0 : r;
    };
    ratio_down_.assign(N + 1, 1.0);
    ratio_up_.assign(N + 1, 1.0);
    for (int k = 0; k <= N; ++k) {
        if (k > 0) ratio_down_[k] = effective(k, k - 1);
        if (k < N) ratio_up_[k] = effective(k, k + 1);
    }
    cos_factor_.assign(N + 1, 1.0);
    for (int k = k_cam_ - 1; k >= 0; --k) cos_factor_[k] = cos_factor_[k + 1] * ratio(k + 1, k);
    for (int k = k_cam_ + 1; k <= N; ++k) cos_factor_[k] = cos_factor_[k - 1] * ratio(k - 1, k);
}

BandWalk::Walk BandWalk::walk(double elevation, double r, int max_events) const {
    Walk w;
    const double c0 = std::cos(elevation);
    double c = c0, sn = std::fabs(std::sin(elevation));
    int dir = elevation > 0.0 ? 1 : (elevation < 0.0 ? -1 : 0);
    double x = 0.0, y = eye_y_;
    int k = k_cam_;
    if (dir == 0 || !(sn > 0.0)) {  // level: it stays in the eye's layer
        w.height = eye_y_;
        return w;
    }
    for (int events = 0;; ++events) {
        if (events >= max_events) {
            w.cut_off = true;
            w.height = kNaN;
            return w;
        }
        const double yb = dir < 0 ? bottom_[k] : top_[k];
        if (!std::isfinite(yb)) {  // above the top boundary: straight for ever
            w.height = y + (r - x) * sn / c;
            return w;
        }
        const double dx = std::fabs(yb - y) * c / sn;
        if (x + dx >= r) {
            w.height = y + dir * (r - x) * sn / c;
            return w;
        }
        x += dx;
        y = yb;
        if (dir < 0 && k == 0) {  // the ground: continued below it
            w.height = y - (r - x) * sn / c;
            return w;
        }
        const int next = k + dir;
        const double ratio = dir < 0 ? ratio_down_[k] : ratio_up_[k];
        if (ratio == 1.0) {  // passed freely
            k = next;
            continue;
        }
        const double cn = c * ratio;
        if (cn >= 1.0) {  // total internal reflection
            dir = -dir;
            ++w.turns;
            continue;
        }
        k = next;
        c = cn;
        sn = std::sqrt((1.0 - cn) * (1.0 + cn));
    }
}

std::optional<double> BandWalk::elevation_leaving_at(double final_elevation) const {
    if (!(final_elevation > 0.0 && final_elevation < 0.5 * M_PI)) return std::nullopt;
    const double c = std::cos(final_elevation) / cos_factor_.back();
    if (!(c > 0.0 && c <= 1.0)) return std::nullopt;
    // acos loses precision near 1: the angle from its sine.
    return std::atan2(std::sqrt((1.0 - c) * (1.0 + c)), c);
}

double BandWalk::height_at(double elevation, double r, int max_events) const {
    return walk(elevation, r, max_events).height;
}

int BandWalk::turns_before(double elevation, double r, int max_events) const {
    return walk(elevation, r, max_events).turns;
}

std::optional<double> elevation_through(const BandWalk& walk, double r, double y, double guess,
                                        double step, double tolerance_m, double max_offset) {
    MIRAGE_CHECK(step > 0.0 && tolerance_m > 0.0 && r >= 0.0);
    auto f = [&](double e) { return walk.height_at(e, r) - y; };
    const double f0 = f(guess);
    if (std::fabs(f0) <= tolerance_m) return guess;
    // Refines a bracket with a change of sign (Illinois); nothing when the change is a jump
    // (a window of elevations ends there: the height is not continuous across it).
    auto refine = [&](double a, double fa, double b, double fb) -> std::optional<double> {
        int side = 0;
        for (int it = 0; it < 200; ++it) {
            double m = (a * fb - b * fa) / (fb - fa);
            if (!(m > std::min(a, b) && m < std::max(a, b))) m = 0.5 * (a + b);
            if (it % 8 == 7) m = 0.5 * (a + b);  // bisect now and then: a sure shrink
            const double fm = f(m);
            if (!std::isfinite(fm)) return std::nullopt;
            if (std::fabs(fm) <= tolerance_m) return m;
            if ((fm < 0.0) == (fa < 0.0)) {
                a = m;
                fa = fm;
                if (side == -1) fb *= 0.5;
                side = -1;
            } else {
                b = m;
                fb = fm;
                if (side == 1) fa *= 0.5;
                side = 1;
            }
            if (std::fabs(b - a) <=
                4.0 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(a), std::fabs(b)))
                return std::nullopt;
        }
        return std::nullopt;
    };
    // Outward from the guess, both sides alternately, in growing steps.
    double last_off[2] = {0.0, 0.0}, last_f[2] = {f0, f0};
    for (double off = step / 16.0; off <= max_offset; off *= 1.5) {
        for (int s = 0; s < 2; ++s) {
            const double sign = s == 0 ? 1.0 : -1.0;
            const double e = guess + sign * off;
            if (std::fabs(e) >= 0.5 * M_PI) continue;
            const double fe = f(e);
            const double fp = last_f[s];
            const double ep = guess + sign * last_off[s];
            last_off[s] = off;
            last_f[s] = fe;
            if (!std::isfinite(fe) || !std::isfinite(fp)) continue;
            if (std::fabs(fe) <= tolerance_m) return e;
            if ((fe < 0.0) != (fp < 0.0)) {
                if (auto root = refine(ep, fp, e, fe)) return root;
            }
        }
    }
    return std::nullopt;
}

glm::dvec3 direction_at_elevation(const glm::dvec3& d, double elevation) {
    const double hl = std::hypot(d.x, d.z);
    MIRAGE_CHECK(hl > 0.0);
    return glm::dvec3(std::cos(elevation) * d.x / hl, std::sin(elevation),
                      std::cos(elevation) * d.z / hl);
}

MeshDirection mesh_direction(const glm::dvec3& d) {
    MeshDirection m;
    const double a[3] = {std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
    m.pivot = a[0] > a[1] ? (a[0] > a[2] ? 0 : 2) : (a[1] > a[2] ? 1 : 2);
    const double scale = 1.0 / a[m.pivot];
    for (int i = 0; i < 3; ++i)
        m.value[i] = i == m.pivot ? (d[i] < 0.0 ? -1.0f : 1.0f) : static_cast<float>(d[i] * scale);
    return m;
}

MeshFace mesh_face(const MeshDirection& m) {
    const int w = m.pivot, u = (w + 1) % 3, v = (w + 2) % 3;
    const float p = m.value[w], a = m.value[u], b = m.value[v];
    MeshFace f;
    f.p2[u] = 0.0f;
    f.p2[v] = p;
    f.p2[w] = -b;
    f.p3[u] = p;
    f.p3[v] = 0.0f;
    f.p3[w] = -a;
    if (p < 0.0f) std::swap(f.p2, f.p3);
    return f;
}

glm::dvec3 mesh_camera_direction(const glm::dvec3& direction) {
    const MeshFace f = mesh_face(mesh_direction(direction));
    const glm::dvec3 v1(f.p2), v2(f.p3);  // P1 is the origin
    glm::dvec3 n(v2.y * v1.z - v2.z * v1.y, v2.z * v1.x - v2.x * v1.z, v2.x * v1.y - v2.y * v1.x);
    n /= std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const glm::dvec3 stored(static_cast<float>(n.x), static_cast<float>(n.y),
                            static_cast<float>(n.z));
    return stored / std::sqrt(stored.x * stored.x + stored.y * stored.y + stored.z * stored.z);
}

}  // namespace mirage
