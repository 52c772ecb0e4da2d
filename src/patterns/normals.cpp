#include "patterns/normals.h"

#include <cmath>

#include "patterns/image_map.h"
#include "patterns/noise.h"
#include "patterns/single_precision.h"
#include "patterns/warps.h"

namespace mirage {

namespace {

// The tetrahedron of the finite difference (POV-Ray's Pyramid_Vect).
constexpr glm::dvec3 kPyramid[4] = {{0.942809041, -0.333333333, 0.0},
                                    {-0.471404521, -0.333333333, 0.816496581},
                                    {-0.471404521, -0.333333333, -0.816496581},
                                    {0.0, 1.0, 0.0}};

const WaveSources& waves_of(const PatternContext& ctx) {
    static const WaveSources kDefault = make_wave_sources(10);
    return ctx.waves ? *ctx.waves : kDefault;
}

void ripples(const glm::dvec3& p, const Normal& n, glm::dvec3& normal, const PatternContext& ctx) {
    const WaveSources& w = waves_of(ctx);
    const double count = static_cast<double>(w.sources.size());
    for (std::size_t i = 0; i < w.sources.size(); ++i) {
        const glm::dvec3 d = p - w.sources[i];
        double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (length == 0.0) length = 1.0;
        const double scalar =
            cycloidal(length * to_single(n.frequency) + to_single(n.phase)) * to_single(n.amount);
        normal += (scalar / (length * count)) * d;
    }
}

void waves(const glm::dvec3& p, const Normal& n, glm::dvec3& normal, const PatternContext& ctx) {
    const WaveSources& w = waves_of(ctx);
    const double count = static_cast<double>(w.sources.size());
    for (std::size_t i = 0; i < w.sources.size(); ++i) {
        const glm::dvec3 d = p - w.sources[i];
        double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (length == 0.0) length = 1.0;
        const double index =
            length * to_single(n.frequency) * w.frequencies[i] + to_single(n.phase);
        const double scalar = cycloidal(index) * to_single(n.amount) / w.frequencies[i];
        normal += (scalar / (length * count)) * d;
    }
}

void wrinkles(const glm::dvec3& p, const Normal& n, glm::dvec3& normal) {
    glm::dvec3 result(0.0);
    double scale = 1.0;
    for (int i = 0; i < 10; scale *= 2.0, ++i) {
        const glm::dvec3 v = dnoise(glm::dvec3(p.x * scale, p.y * scale, p.z * scale));
        result.x += std::fabs(v.x / scale);
        result.y += std::fabs(v.y / scale);
        result.z += std::fabs(v.z / scale);
    }
    normal += to_single(n.amount) * result;
}

void quilted(const glm::dvec3& p, const Normal& n, glm::dvec3& normal) {
    glm::dvec3 v(p.x - pov_floor(p.x) - 0.5, p.y - pov_floor(p.y) - 0.5,
                 p.z - pov_floor(p.z) - 0.5);
    const double t = quilt_cubic(std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z),
                                 to_single(n.control0), to_single(n.control1));
    v *= t;
    normal += to_single(n.amount) * v;
}

/// POV-Ray's Do_Slope_Map and Hermite_Cubic.
double slope_map(const std::vector<SlopeMapEntry>& map, double value) {
    if (map.empty()) return value;
    const std::size_t last = map.size() - 1;
    std::size_t prev = 0, cur = 0;
    if (value >= to_single(map[last].position)) {
        prev = cur = last;
    } else {
        while (value > to_single(map[cur].position)) prev = cur++;
    }
    if (value == to_single(map[cur].position)) prev = cur;
    if (prev == cur) return map[cur].point_slope.x;
    const double t = (value - to_single(map[prev].position)) /
                     (to_single(map[cur].position) - to_single(map[prev].position));
    const glm::dvec2& a = map[prev].point_slope;
    const glm::dvec2& b = map[cur].point_slope;
    const double tt = t * t, ttt = tt * t;
    double rv = ttt * (a[1] + b[1] + 2.0 * (a[0] - b[0]));
    rv += -tt * (2.0 * a[1] + b[1] + 3.0 * (a[0] - b[0]));
    rv += t * a[1] + a[0];
    return rv;
}

}  // namespace

void perturb_normal(glm::dvec3& normal, const Normal& n, const glm::dvec3& point,
                    const PatternContext& ctx) {
    const bool dont_scale = n.no_bump_scale;
    if (!n.normal_map.empty() && n.kind != PatternKind::Average) {
        const glm::dvec3 tp = warp_point(n, point);
        const double value = evaluate_pattern(n, tp, ctx);
        const std::size_t last = n.normal_map.size() - 1;
        std::size_t prev = 0, cur = 0;
        if (value >= to_single(n.normal_map[last].position)) {
            prev = cur = last;
        } else {
            while (value > to_single(n.normal_map[cur].position)) prev = cur++;
        }
        if (value == to_single(n.normal_map[cur].position)) prev = cur;
        normal = warp_normal(n, normal, dont_scale);
        glm::dvec3 below = normal;
        perturb_normal(normal, *n.normal_map[cur].normal, tp, ctx);
        if (prev != cur) {
            perturb_normal(below, *n.normal_map[prev].normal, tp, ctx);
            const double p0 = to_single(n.normal_map[prev].position);
            const double p1 = to_single(n.normal_map[cur].position);
            const double w = (value - p0) / (p1 - p0);
            normal = (1.0 - w) * below + w * normal;
        }
        normal = glm::normalize(unwarp_normal(n, normal, dont_scale));
        return;
    }
    if (is_normal_only_pattern(n.kind)) {
        normal = warp_normal(n, normal, dont_scale);
        const glm::dvec3 tp = warp_point(n, point);
        switch (n.kind) {
            case PatternKind::ImageMap:
                bump_map_normal(n, tp, normal);
                break;
            case PatternKind::Bumps:
                normal += to_single(n.amount) * dnoise(tp);
                break;
            case PatternKind::Dents: {
                double v = noise(tp, pattern_noise_generator(n, ctx));
                v = v * v * v * to_single(n.amount);
                normal += v * dnoise(tp);
                break;
            }
            case PatternKind::Ripples:
                ripples(tp, n, normal, ctx);
                break;
            case PatternKind::Waves:
                waves(tp, n, normal, ctx);
                break;
            case PatternKind::Wrinkles:
                wrinkles(tp, n, normal);
                break;
            case PatternKind::Quilted:
                quilted(tp, n, normal);
                break;
            case PatternKind::Average: {
                glm::dvec3 sum(0.0);
                float total = 0.0f;
                for (const NormalMapEntry& e : n.normal_map) {
                    glm::dvec3 v = normal;
                    perturb_normal(v, *e.normal, tp, ctx);
                    const double w = to_single(e.position);
                    sum += w * v;
                    total += static_cast<float>(w);
                }
                if (total != 0.0f) normal = sum / static_cast<double>(total);
                break;
            }
            default:
                break;  // facets: refused by the parser
        }
        normal = unwarp_normal(n, normal, dont_scale);
        return;
    }
    normal = warp_normal(n, normal, dont_scale);
    // POV-Ray's fudge factor, and its bump size and accuracy in single precision.
    const double amount = to_single(n.amount) * -5.0 * (0.02 / to_single(n.delta));
    const glm::dvec3 tp = warp_point(n, point);
    const double delta = to_single(n.delta);
    for (int i = 0; i <= 3; ++i) {
        const glm::dvec3 p1 = tp + delta * kPyramid[i];
        const double value = slope_map(n.slope_map, evaluate_pattern(n, p1, ctx));
        normal += (value * amount) * kPyramid[i];
    }
    normal = unwarp_normal(n, normal, dont_scale);
}

}  // namespace mirage
