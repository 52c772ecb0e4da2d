#include "layers/air_bands.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "atmosphere/exact_path.h"
#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The mean of n^2 - n0^2 over [a, b]: composite Simpson over 16 panels (the fitted model is
// piecewise quadratic; this is exact within a piece and close across knots).
double mean_excess(const Atmosphere& air, double n0_sq, double a, double b) {
    if (!(b > a)) return air.n_sq(a) - n0_sq;
    constexpr int kPanels = 16;
    const double h = (b - a) / kPanels;
    double s = 0.0;
    for (int i = 0; i <= kPanels; ++i) {
        const double w = (i == 0 || i == kPanels) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        s += w * (air.n_sq(a + i * h) - n0_sq);
    }
    return s * h / 3.0 / (b - a);
}

}  // namespace

LayerStack air_layers(const Atmosphere& air, const std::vector<double>& heights) {
    LayerStack s;
    const double n0_sq = air.n_sq(0.0);
    s.profile.kind = ProfileKind::None;
    s.profile.eta0 = std::sqrt(n0_sq);
    s.heights = heights;
    double below = 0.0;
    for (double h : heights) {
        MIRAGE_CHECK(h > below || (below == 0.0 && h > 0.0));
        s.excess.push_back(mean_excess(air, n0_sq, below, h));
        below = h;
    }
    s.excess.push_back(air.n_sq(below) - n0_sq);
    return s;
}

LayerStack air_layers_for_eye(const Atmosphere& air, const std::vector<double>& heights,
                              double eye_y) {
    LayerStack s = air_layers(air, heights);
    s.excess[s.layer_at(eye_y)] = air.n_sq(eye_y) - air.n_sq(0.0);
    return s;
}

LayerStack keep_layers_off_skimming_rays(const Atmosphere& air, const LayerStack& stack,
                                         double eye_y, const std::vector<double>& elevations) {
    LayerStack s = stack;
    const int k_cam = s.layer_at(eye_y);
    const double n_cam = s.index(k_cam);
    std::vector<double> cosines(elevations.size());
    for (size_t i = 0; i < elevations.size(); ++i) cosines[i] = std::cos(elevations[i]);
    std::sort(cosines.begin(), cosines.end());
    const int n = s.boundaries();
    for (int k = 0; k < n; ++k) {
        if (k == k_cam) continue;
        // n over the layer's heights, over the camera layer's index.
        const double a = air.n(k == 0 ? 0.0 : s.heights[k - 1]) / n_cam;
        const double b = air.n(s.heights[k]) / n_cam;
        const double wanted = 0.25 * std::fabs(b - a);
        if (!(wanted > 0.0)) continue;
        // How far ior c is above the cos e of the nearest ray that enters a layer of ior c,
        // in units of `wanted`; +inf when no ray enters.
        auto clearance = [&](float c) {
            const double cd = static_cast<double>(c);
            auto it = std::upper_bound(cosines.begin(), cosines.end(), cd);
            if (it == cosines.begin()) return kInfinity;
            return (cd - *std::prev(it)) / wanted;
        };
        const float c0 = pov_relative_ior(s, k_cam, k);
        if (!(c0 < 1.0f) || clearance(c0) >= 1.0) continue;
        // The floats between n at the layer's floor and at its top; its neighbours' floats are
        // left to them (equal iors would merge the boundary away).
        const float lo = std::min(static_cast<float>(std::min(a, b)), c0);
        const float hi = std::min(std::max(static_cast<float>(std::max(a, b)), c0), 1.0f);
        const float below = k > 0 ? pov_relative_ior(s, k_cam, k - 1) : -1.0f;
        const float above = pov_relative_ior(s, k_cam, k + 1);
        float best = c0;
        double best_clear = clearance(c0), best_dist = 0.0;
        int tried = 0;
        for (float c = lo; c < hi && tried < 4096; c = std::nextafter(c, 2.0f), ++tried) {
            if (c == below || c == above || c == c0) continue;
            const double clear = std::min(clearance(c), 1.0);
            const double dist = std::fabs(static_cast<double>(c) - static_cast<double>(c0));
            if (clear > best_clear || (clear == best_clear && dist < best_dist)) {
                best = c;
                best_clear = clear;
                best_dist = dist;
            }
        }
        if (best != c0) {
            const double index = static_cast<double>(best) * n_cam;
            s.excess[k] = index * index - s.profile.eta0 * s.profile.eta0;
            MIRAGE_CHECK(pov_relative_ior(s, k_cam, k) == best);
        }
    }
    return s;
}

double air_peak_below(const Atmosphere& air, double y0, double elevation, double scene_dz,
                      double ceiling) {
    auto path = ExactPath::make(air, y0, M_PI / 2 - elevation);
    MIRAGE_CHECK(path.ok());
    double end = scene_dz;
    if (path->hits_ground()) end = std::min(end, path->dz_ground());
    constexpr int kSamples = 64;
    double highest = y0, counted = y0;
    for (int k = 1; k <= kSamples; ++k) {
        const double y = path->height_at(end * k / kSamples);
        highest = std::max(highest, y);
        if (y <= ceiling) counted = highest;
    }
    return counted;
}

std::vector<double> equal_height_boundaries(double top, int count) {
    MIRAGE_CHECK(count >= 1 && top > 0.0);
    std::vector<double> h;
    for (int j = 1; j <= count; ++j) h.push_back(top * j / count);
    return h;
}

namespace {

// Boundaries where n crosses the levels of `level_at` (ascending in k, level_at(0) and
// level_at(count) the extremes of n over [0, top]): k = 1 .. count - 1, every crossing.
template <class Levels>
std::vector<double> boundaries_at_levels(const Atmosphere& air, double top, int count,
                                         double min_thickness, const Levels& level_at) {
    MIRAGE_CHECK(count >= 1 && top > 0.0);
    // The profile on a grid fine enough for every knot of the model below the top: each
    // piece of the model is one quadratic, so between grid points n is monotonic unless a
    // piece has its extremum inside (found as a sign change of the slope between samples).
    std::vector<double> ys;
    constexpr int kPerSpan = 8;
    std::vector<double> knots = {0.0};
    if (const QuadraticProfile* q = air.quadratic_profile())
        for (double k : q->knots())
            if (k > 0.0 && k < top) knots.push_back(k);
    knots.push_back(top);
    // At least 4096 samples over [0, top] as well, for profiles with few knots.
    for (size_t j = 0; j + 1 < knots.size(); ++j) {
        const double a = knots[j], b = knots[j + 1];
        const int steps = std::max(kPerSpan, static_cast<int>(std::ceil(4096.0 * (b - a) / top)));
        for (int i = 0; i < steps; ++i) ys.push_back(a + (b - a) * i / steps);
    }
    ys.push_back(top);
    std::vector<double> ns(ys.size());
    for (size_t i = 0; i < ys.size(); ++i) ns[i] = air.n(ys[i]);
    const double lo = *std::min_element(ns.begin(), ns.end());
    const double hi = *std::max_element(ns.begin(), ns.end());
    std::vector<double> out;
    if (!(hi > lo)) return out;
    std::vector<double> levels;
    for (int k = 1; k < count; ++k) levels.push_back(level_at(lo, hi, k));
    for (size_t i = 0; i + 1 < ys.size(); ++i) {
        const double na = ns[i], nb = ns[i + 1];
        // Levels above the lower of the two samples' indices and up to the higher (a level hit
        // exactly at a sample belongs to the interval it starts).
        const double a = std::min(na, nb), b = std::max(na, nb);
        std::vector<double> here;
        for (auto it = std::upper_bound(levels.begin(), levels.end(), a);
             it != levels.end() && *it <= b; ++it) {
            const double level = *it;
            if (level == na && i > 0) continue;
            // Bisection for n(y) = level on [ys[i], ys[i+1]].
            double ya = ys[i], yb = ys[i + 1];
            const bool rising = nb > na;
            for (int it = 0; it < 60; ++it) {
                const double ym = 0.5 * (ya + yb);
                if ((air.n(ym) < level) == rising)
                    ya = ym;
                else
                    yb = ym;
            }
            here.push_back(0.5 * (ya + yb));
        }
        std::sort(here.begin(), here.end());
        for (double y : here)
            if (y - (out.empty() ? 0.0 : out.back()) >= min_thickness && y < top) out.push_back(y);
    }
    return out;
}

}  // namespace

std::vector<double> equal_index_boundaries(const Atmosphere& air, double top, int count,
                                           double min_thickness) {
    return boundaries_at_levels(
        air, top, count, min_thickness,
        [count](double lo, double hi, int k) { return lo + k * ((hi - lo) / count); });
}

std::vector<double> equal_turning_boundaries(const Atmosphere& air, double top, double eye_y,
                                             int count, double min_thickness) {
    // The levels of equal_index_boundaries at and above n at the eye; below it as many steps
    // (and one more) of sqrt(n_eye - n), from n_eye down to the lowest n.
    const double n_eye = air.n(eye_y);
    return boundaries_at_levels(
        air, top, count, min_thickness, [n_eye, count](double lo, double hi, int k) {
            const double step = (hi - lo) / count;
            if (!(n_eye > lo)) return lo + k * step;
            const int below = std::min(count, static_cast<int>(std::ceil((n_eye - lo) / step)));
            if (k >= below) return lo + k * step;
            const double s = std::sqrt(n_eye - lo) * (below - k) / below;
            return n_eye - s * s;
        });
}

}  // namespace mirage
