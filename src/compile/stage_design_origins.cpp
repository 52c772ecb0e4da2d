// Stage "design" of mirage compile for cameras whose rays start at different points
// (orthographic, cylinder 3 and 4; compile/stages.h).  The fit of layers/fit.h places
// boundaries where the rays of one eye turn and weighs errors as angles seen from it; rays
// from many origins share neither.  These layers are placed at equal steps of the index (or
// at equal heights) over the heights the rays' own exact paths reach inside the scene, each
// holding the mean of eta^2 over its heights, and POV-Ray renders them in the gap layout,
// whose disjoint slabs give every origin the one interior it is in.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "atmosphere/exact_path.h"
#include "atmosphere/exact_ray.h"
#include "compile/stages.h"
#include "layers/air_bands.h"
#include "util/format.h"
#include "util/parallel.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using HeightFunction = std::function<double(double)>;

// The mean of f over [a, b]: composite Simpson over 16 panels.
double mean_over(const HeightFunction& f, double a, double b) {
    if (!(b > a)) return f(a);
    constexpr int kPanels = 16;
    const double h = (b - a) / kPanels;
    double s = 0.0;
    for (int i = 0; i <= kPanels; ++i) {
        const double w = (i == 0 || i == kPanels) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        s += w * f(a + i * h);
    }
    return s * h / 3.0 / (b - a);
}

// Boundaries where f crosses the levels f_lo + k (f_hi - f_lo) / count, k = 0 .. count, the
// extremes taken over [lo, hi] (on a grid of 4096 samples, each crossing found by
// bisection: a profile that is not monotonic crosses a level more than once), none closer
// than min_thickness to the one below or to the ground.
std::vector<double> equal_steps(const HeightFunction& f, double lo, double hi, int count,
                                double min_thickness) {
    constexpr int kSamples = 4096;
    std::vector<double> ys(kSamples + 1), fs(kSamples + 1);
    for (int i = 0; i <= kSamples; ++i) {
        ys[i] = lo + (hi - lo) * i / kSamples;
        fs[i] = f(ys[i]);
    }
    const double f_lo = *std::min_element(fs.begin(), fs.end());
    const double f_hi = *std::max_element(fs.begin(), fs.end());
    std::vector<double> out;
    if (!(f_hi > f_lo)) return out;
    const double step = (f_hi - f_lo) / count;
    std::vector<double> found;
    for (int i = 0; i < kSamples; ++i) {
        const double a = std::min(fs[i], fs[i + 1]), b = std::max(fs[i], fs[i + 1]);
        for (int k = std::max(0, static_cast<int>(std::ceil((a - f_lo) / step)));
             k <= count && f_lo + k * step <= b; ++k) {
            const double level = f_lo + k * step;
            if (level == fs[i + 1] && i + 1 < kSamples) continue;  // the next interval's
            double ya = ys[i], yb = ys[i + 1];
            const bool rising = fs[i + 1] > fs[i];
            for (int it = 0; it < 60; ++it) {
                const double ym = 0.5 * (ya + yb);
                if ((f(ym) < level) == rising)
                    ya = ym;
                else
                    yb = ym;
            }
            found.push_back(0.5 * (ya + yb));
        }
    }
    std::sort(found.begin(), found.end());
    for (double y : found)
        if (y - (out.empty() ? 0.0 : out.back()) >= min_thickness) out.push_back(y);
    return out;
}

// The lowest and highest heights ray i's exact path reaches inside the scene, from its own
// origin (below the ground: from where it rises to it).
struct Reach {
    double lo = kInf, hi = -kInf;
};

Reach ray_reach(const CompileContext& ctx, const glm::dvec3& origin, const glm::dvec3& dir) {
    Reach r;
    const auto from = entry_into_atmosphere(origin, dir);
    if (!from) return r;
    const double y0 = std::max(from->y, 0.0);
    const double hl = std::hypot(dir.x, dir.z);
    if (hl < 1e-12) {  // vertical: straight up or down
        r.lo = dir.y < 0.0 ? 0.0 : y0;
        r.hi = dir.y < 0.0 ? y0 : kInf;
        return r;
    }
    const double exit =
        distance_to_box_edge(ctx.scene_box, from->x, from->z, dir.x / hl, dir.z / hl);
    const double i = std::atan2(hl, dir.y);
    r.lo = r.hi = y0;
    auto take = [&](double y) {
        r.lo = std::min(r.lo, y);
        r.hi = std::max(r.hi, y);
    };
    auto path = ExactPath::make(ctx.atmosphere, y0, i);
    if (!path) return r;
    const double end = std::min(exit, path->dz_ground());
    TurningPoint t;
    for (int k = 0; path->turning_point_before(k, end, t); ++k)
        if (t.dz > 0.0) take(t.y);
    if (std::isfinite(end)) take(path->height_at(end));
    if (path->dz_ground() <= exit) take(0.0);
    return r;
}

}  // namespace

std::optional<glm::dvec3> entry_into_atmosphere(const glm::dvec3& origin, const glm::dvec3& dir) {
    if (origin.y >= 0.0) return origin;
    if (!(dir.y > 0.0)) return std::nullopt;
    glm::dvec3 p = origin + (-origin.y / dir.y) * dir;
    p.y = 0.0;
    return p;
}

Result<Design> design_many_origins(const CompileContext& ctx, const CameraRays& rays) {
    const MirageSettings& st = ctx.settings;
    Design d;
    const Atmosphere& atm = ctx.atmosphere;
    // The exponential profiles' bands hold eta^2 excesses over eta0 (layers/stack.h), real
    // air's over n(0)^2.
    const Profile* closed = atm.exponential_profile();
    if (closed) {
        d.stack.profile = *closed;
        d.stack.excess = {eta_sq_excess(*closed, ctx.eye_y)};
    } else {
        d.stack = air_layers(atm, {});
    }
    if (!st.declared || !atm.has_gradient()) {
        d.mode = "none";
        d.left_out.push_back(
            "every layer: the scene declares no atmosphere, or its index does "
            "not change with height");
        return d;
    }
    const std::string camera = camera_type_name(ctx.camera.type);
    if (st.layers == LayerMode::Adaptive &&
        (ctx.options.layers || ctx.scene.symbols.count("Mirage_Layers") > 0))
        return make_error(ctx.scene.file + ": adaptive layers (the fit to the rays of one eye) " +
                          "do not apply to the " + camera +
                          " camera, whose rays start at different points: leave Mirage_Layers "
                          "out for layers at equal steps of the index, or ask for uniform "
                          "layers (--layers uniform --count N)");
    const bool uniform = st.layers == LayerMode::Uniform;
    if (uniform && st.layer_count < 1)
        return make_error(ctx.scene.file +
                          ": uniform layers need a count: --count N or Mirage_Layer_Count");

    // The heights the rays reach inside the scene.
    std::vector<Reach> reach(rays.size());
    parallel_for(static_cast<long>(rays.size()),
                 [&](long i) { reach[i] = ray_reach(ctx, rays.origin[i], rays.direction[i]); });
    double lo = kInf, hi = -kInf;
    for (const Reach& r : reach) {
        lo = std::min(lo, r.lo);
        hi = std::max(hi, r.hi);
    }
    const HeightFunction f =
        closed ? HeightFunction([&](double y) { return eta_sq_excess(*closed, y); })
               : HeightFunction([&](double y) { return atm.n_sq(y) - atm.n_sq(0.0); });
    // No higher than where the index no longer changes (real air's model top) or is within
    // 1 % of its value aloft (the exponential profiles).
    const double cap = closed ? height_of_excess(*closed, 0.99 * eta_sq_excess(*closed, kInf))
                              : atm.constant_above();
    hi = std::min(hi, cap);
    lo = std::max(lo, 0.0);
    if (!(hi > lo)) {
        d.mode = "none";
        d.left_out.push_back(
            "every layer: the camera's rays meet no change of the index inside "
            "the scene");
        return d;
    }
    d.mode = uniform ? "uniform" : "index steps";
    const double min_thickness = 3.0 * ctx.gap;
    // The half-space above the last boundary: the index aloft (exponential profiles: every
    // sky direction exact), real air's at its model's top or at the highest point reached.
    const double top_excess =
        closed ? eta_sq_excess(*closed, kInf) : f(std::isfinite(cap) ? cap : hi);
    int count = uniform ? st.layer_count : (st.layer_count > 0 ? st.layer_count : 64);
    for (int attempt = 0; attempt < 12; ++attempt) {
        std::vector<double> h;
        if (uniform) {
            for (int j = 0; j <= count; ++j) {
                const double y = lo + (hi - lo) * j / count;
                if (y - (h.empty() ? 0.0 : h.back()) >= min_thickness) h.push_back(y);
            }
        } else {
            h = equal_steps(f, lo, hi, count, min_thickness);
        }
        LayerStack s = d.stack;
        s.heights = h;
        s.excess.clear();
        double below = 0.0;
        for (const double y : h) {
            s.excess.push_back(mean_over(f, std::max(below, lo), std::max(y, lo)));
            below = y;
        }
        s.excess.push_back(top_excess);
        // Layers of one float ior merged, each run keeping the index of the reference layer's
        // side (the reference of the merged stack is found again from it).
        s = merge_invisible_boundaries(s, ctx.reference_y(s));
        d.stack = s;
        d.max_trace_level = deepest_trace_level(ctx, ctx.rendered(d.stack), rays);
        if (uniform || d.max_trace_level <= kMaxTraceLevel || count <= 2) break;
        count = fewer_steps_for_trace_level(d, count, "steps");
    }
    warn_past_trace_level_ceiling(d);
    d.left_out.push_back("layers of the " + camera + " camera's rays between y = " + sig(lo, 4) +
                         " and " + sig(hi, 4) +
                         " only: no ray, from its own origin, reaches lower or higher inside "
                         "the scene, or the index no longer changes");
    return d;
}

double many_origins_reach(const CompileContext& ctx, const LayerStack& rendered,
                          const CameraRays& rays, int* max_crossings) {
    const glm::dvec3& eye = ctx.camera.location;
    const double cap = ctx.layers_box.x1 - eye.x;
    if (max_crossings) *max_crossings = 0;
    if (rendered.boundaries() == 0) return std::min(1.1 * ctx.extent, cap);
    const double camera_y = ctx.reference_y(rendered);
    std::vector<double> reach(rays.size(), 0.0);
    std::vector<int> crossings(rays.size(), 0);
    parallel_for(static_cast<long>(rays.size()), [&](long i) {
        const auto from = entry_into_atmosphere(rays.origin[i], rays.direction[i]);
        if (!from) return;
        const Trace3dOutcome t =
            trace_layers_3d(rendered, *from, rays.direction[i], ctx.scene_box, ctx.layers_box,
                            Trace3dOptions{100000, nullptr, camera_y});
        crossings[i] = t.crossings;
        if (t.cut_off || t.crossings == 0) return;
        reach[i] = std::hypot(from->x - eye.x, from->z - eye.z) + 1.1 * t.last_event;
    });
    if (max_crossings)
        *max_crossings =
            crossings.empty() ? 0 : *std::max_element(crossings.begin(), crossings.end());
    const double r = std::max(1.1 * ctx.extent, *std::max_element(reach.begin(), reach.end()));
    return std::min(r, cap);
}

}  // namespace mirage
