#include "layers/air_bands.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "atmosphere/exact_path.h"
#include "util/check.h"

namespace mirage {

namespace {

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

bool air_has_gradient(const Atmosphere& air) { return air.has_gradient(); }

double air_earth_radius(const Atmosphere& air) { return air.earth_radius(); }

double air_constant_above(const Atmosphere& air) {
    const QuadraticProfile* q = air.quadratic_profile();
    return q ? q->top() : std::numeric_limits<double>::infinity();
}

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

std::vector<double> equal_index_boundaries(const Atmosphere& air, double top, int count,
                                           double min_thickness) {
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
    const double step = (hi - lo) / count;
    for (size_t i = 0; i + 1 < ys.size(); ++i) {
        const double na = ns[i], nb = ns[i + 1];
        // Levels strictly between the two samples' indices (a level hit exactly at a sample
        // belongs to the interval it starts).
        const double a = std::min(na, nb), b = std::max(na, nb);
        const int k0 = static_cast<int>(std::floor((a - lo) / step)) + 1;
        std::vector<double> here;
        for (int k = std::max(k0, 1); k < count && lo + k * step <= b; ++k) {
            const double level = lo + k * step;
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

}  // namespace mirage
