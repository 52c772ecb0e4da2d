// Stage "design" of mirage compile (compile/stages.h): the layers and their trace-level
// budget.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "atmosphere/exact_ray.h"
#include "compile/stages.h"
#include "layers/air_bands.h"
#include "layers/fit.h"
#include "layers/outcome.h"
#include "layers/revolution.h"
#include "util/check.h"
#include "util/format.h"
#include "util/parallel.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

int trace_levels(const CompileContext& ctx, const LayerStack& stack, const ObjectQuery& objects,
                 double camera_y, const glm::dvec3& origin, const glm::dvec3& dir, int level,
                 double weight) {
    Trace3dOptions o{4 * kMaxTraceLevel, &objects, camera_y};
    o.below = ctx.layers_below_box;
    const Trace3dOutcome t = trace_layers_3d(stack, origin, dir, ctx.scene_box, ctx.layers_box, o);
    level += t.crossings;
    if (t.cut_off) return std::max(level, 4 * kMaxTraceLevel);
    int deepest = level;
    if (t.object) {
        const Primitive& prim = ctx.scene.primitives[t.object->id];
        const glm::dvec3 refl = prim.texture.finish.reflection;
        const double r = std::max({refl.x, refl.y, refl.z});
        if (r > 0.0 && weight * r >= 1.0 / 255.0) {
            glm::dvec3 n = t.object->normal;
            if (glm::dot(n, t.object_dir) > 0.0) n = -n;
            const glm::dvec3 rd = glm::reflect(t.object_dir, n);
            glm::dvec3 start = t.object_point + 1e-6 * n;
            start.y = std::max(start.y, 0.0);
            deepest = std::max(deepest, trace_levels(ctx, stack, objects, camera_y, start, rd,
                                                     level + 1, weight * r));
        }
    }
    return deepest;
}

// The highest point the camera's exact rays reach inside the scene.
double highest_reached(const CompileContext& ctx, const CameraRays& rays) {
    std::vector<double> top(rays.size(), ctx.eye_y);
    parallel_for(static_cast<long>(rays.size()), [&](long i) {
        auto ex = ExactPath::make(ctx.atmosphere, ctx.eye_y, M_PI / 2 - rays.elevation[i]);
        if (!ex) return;
        top[i] = ex->height_at(std::min(rays.exit_dz[i], ex->dz_ground()));
    });
    return *std::max_element(top.begin(), top.end());
}

// The heights the camera's rays reach inside the scene, for Berger's layers.
double top_reached(const CompileContext& ctx, const Profile& profile, const CameraRays& rays) {
    const double t = highest_reached(ctx, rays);
    return std::min(t, std::max(ctx.eye_y * 1.001,
                                height_of_excess(profile, eta_sq_excess(profile, kInf) * 0.99)));
}

// The top of the corrected camera's layers: the highest point a camera ray reaches inside
// the scene, no higher than where the index excess left to gain, eta^2(infinity) - eta^2(y),
// is below (p / 10)^2 for the finest pixel angle p: a ray at elevation e that rises from
// there turns by at most about sqrt(that) <= p / 10 more, the worst case being a level one
// (e^2 grows by the excess gained).
double corrected_camera_top(const CompileContext& ctx, const Profile& profile,
                            const CameraRays& rays) {
    const double t = highest_reached(ctx, rays);
    double finest = kInf;
    for (double p : rays.pixel_rad) finest = std::min(finest, p);
    const double ex_inf = eta_sq_excess(profile, kInf);
    const double left = std::min(0.5 * std::fabs(ex_inf), 0.01 * finest * finest);
    const double flat = height_of_excess(profile, ex_inf - std::copysign(left, ex_inf));
    return std::max(ctx.eye_y * 1.001, std::min(t, std::isfinite(flat) ? flat : t));
}

// The same in real air, no higher than the model's top (above it n no longer changes).
double air_top_reached(const CompileContext& ctx, const CameraRays& rays) {
    std::vector<double> top(rays.size(), ctx.eye_y);
    parallel_for(static_cast<long>(rays.size()), [&](long i) {
        top[i] = exact_outcome(ctx.atmosphere, ctx.eye_y, rays.elevation[i], rays.exit_dz[i]).y;
    });
    double t = *std::max_element(top.begin(), top.end());
    const Aabb& objects = ctx.accel->finite_bounds();
    if (ctx.atmosphere.earth_radius() > 0.0 && !objects.empty() && objects.finite() &&
        objects.hi.y < t) {
        // On the curved Earth the flattened n* keeps growing with height (the Earth's term,
        // 1/R per unit of height), and a band ray that goes on bending above everything
        // the scene holds only turns its final direction away from the one the sky is seen
        // in (that is dz / R from the flattened one, curved_propagator.h).  So the layers end
        // at the top of the objects, or higher where a camera ray rises above them and comes
        // back down inside the scene (a duct, looming): above, no ray meets anything.
        const double objects_top = objects.hi.y;
        std::vector<double> peak(rays.size(), 0.0);
        parallel_for(static_cast<long>(rays.size()), [&](long i) {
            peak[i] = air_peak_below(ctx.atmosphere, ctx.eye_y, rays.elevation[i], rays.exit_dz[i],
                                     objects_top);
        });
        t = std::min(t, std::max(objects_top, *std::max_element(peak.begin(), peak.end())));
    }
    return std::max(std::min(t, ctx.atmosphere.constant_above()), ctx.eye_y * 1.001);
}

// POV-Ray needs the camera off a boundary.
void move_off_camera(std::vector<double>& heights, double eye_y) {
    for (double& h : heights)
        if (std::fabs(h - eye_y) < 1e-9 * std::max(1.0, eye_y)) h += 1e-6 * std::max(1.0, eye_y);
}

// When the layer under the camera's is one float ulp below it (2^-24, the smallest index step
// POV-Ray's single-precision ior holds there), the rays from level to sqrt(2^-24 x 2) below it
// all turn at the camera layer's floor, wherever their exact paths turn: say which rows
// (those of the image's centre column).  docs/atmospheres.md, "Rays that skim a layer".
std::optional<std::string> turning_under_the_float_step(const CompileContext& ctx,
                                                        const LayerStack& stack,
                                                        const CameraRays& rays) {
    const int k_cam = stack.layer_at(ctx.eye_y);
    if (k_cam == 0 || rays.width < 1) return std::nullopt;
    const float c = pov_relative_ior(stack, k_cam, k_cam - 1);
    if (c != std::nextafter(1.0f, 0.0f)) return std::nullopt;
    const double below_rad = std::acos(static_cast<double>(c));
    int first = -1, last = -1;
    for (int row = 0; row < rays.height; ++row) {
        const double e = rays.elevation[static_cast<size_t>(row) * rays.width + rays.width / 2];
        if (e <= 0.0 && -e < below_rad) {
            if (first < 0) first = row;
            last = row;
        }
    }
    if (first < 0) return std::nullopt;
    return "the turning of the rays from level to " + sig(1e3 * below_rad, 3) +
           " mrad below it (rows " + std::to_string(first) + " to " + std::to_string(last) +
           "): they all turn at the camera layer's floor, y = " + sig(stack.heights[k_cam - 1], 4) +
           ", as POV-Ray's single-precision ior holds no smaller index step under the camera "
           "layer's than 2^-24";
}

// Layers for real air, from n(y) alone (layers/air_bands.h): equal heights (Mirage_Layers
// "uniform" with a count) or, by default, equal steps of the index (below the eye's index, of
// the elevation of the eye's rays that turn there), the layers kept off skimming pixel rays;
// the designs fitted to the camera's rays need the exponential closed forms and are refused.
Result<Design> design_air_layers(const CompileContext& ctx, const CameraRays& rays) {
    const MirageSettings& st = ctx.settings;
    const Atmosphere& air = ctx.atmosphere;
    Design d;
    d.stack = air_layers(air, {});
    const bool adaptive_asked =
        st.layers == LayerMode::Adaptive &&
        (ctx.options.layers || ctx.scene.symbols.count("Mirage_Layers") > 0);
    if (adaptive_asked)
        return make_error(ctx.scene.file + ": adaptive layers (the fit to the camera's rays) " +
                          "need the exponential profiles' closed forms, and this atmosphere is " +
                          "real air (" + st.profile_label +
                          "): leave Mirage_Layers out for layers at equal steps of the index, or "
                          "ask for uniform layers (--layers uniform --count N)");
    if (!air.has_gradient()) {
        d.mode = "none";
        d.left_out.push_back("every layer: the index does not change with height");
        return d;
    }
    const double top = air_top_reached(ctx, rays);
    const bool uniform = st.layers == LayerMode::Uniform;
    if (uniform && st.layer_count < 1)
        return make_error(ctx.scene.file +
                          ": uniform layers need a count: --count N or Mirage_Layer_Count");
    d.mode = uniform ? "uniform" : "index steps";
    // POV-Ray ignores a hit closer than 1e-4 units to a ray's origin: along the steepest ray,
    // every layer (and gap) must be thicker than that.
    const double min_thickness = ctx.gaps ? 3.0 * ctx.gap : 1.5e-4 * ctx.steepest_sine;
    // The corrected camera aims every ray where its exact ray ends: the layers carry only the
    // paths' smooth part, and its rays' trace levels are measured when they are aimed.
    const bool corrected = ctx.options.camera == CameraModel::Corrected;
    int count =
        uniform ? st.layer_count
                : (st.layer_count > 0 ? st.layer_count : (corrected ? kCorrectedCameraLayers : 64));
    for (int attempt = 0; attempt < 12; ++attempt) {
        std::vector<double> h =
            uniform ? equal_height_boundaries(top, count)
                    : equal_turning_boundaries(air, top, ctx.eye_y, count, min_thickness);
        move_off_camera(h, ctx.eye_y);
        d.stack = merge_invisible_boundaries(air_layers_for_eye(air, h, ctx.eye_y), ctx.eye_y);
        if (corrected) break;
        // No pixel's ray nearly level in a layer it enters (POV-Ray renders the pixel centres).
        d.stack = keep_layers_off_skimming_rays(air, d.stack, ctx.eye_y, rays.elevation);
        d.max_trace_level = deepest_trace_level(ctx, ctx.rendered(d.stack), rays);
        if (uniform || d.max_trace_level <= kMaxTraceLevel || count <= 2) break;
        count = fewer_steps_for_trace_level(d, count, "index steps");
    }
    warn_past_trace_level_ceiling(d);
    d.left_out.push_back("layers above y = " + sig(top, 4) +
                         ": no camera ray reaches higher inside the scene, or the index no "
                         "longer changes");
    // (Aimed rays turn where their exact rays do, float step or not.)
    if (!corrected)
        if (auto l = turning_under_the_float_step(ctx, d.stack, rays)) d.left_out.push_back(*l);
    return d;
}

}  // namespace

LayerStack corrected_camera_layers(const Profile& profile, double eye_y, int count, double top) {
    MIRAGE_CHECK(count >= 1 && eye_y > 0.0);
    const double ex0 = eta_sq_excess(profile, 0.0), ex_eye = eta_sq_excess(profile, eye_y);
    const double ex_top = eta_sq_excess(profile, std::max(top, eye_y));
    // Two thirds of the boundaries below the eye, where the rays turn over hot ground (the
    // inferior mirage), or a third where they turn above it (looming), the rest on the other
    // side; none above `top`.
    const bool turns_below = std::fabs(ex_eye - ex0) >= std::fabs(ex_top - ex_eye);
    const int above = top > eye_y ? std::max(1, turns_below ? count / 3 : count - count / 3) : 0;
    const int below = std::max(1, count - above);
    LayerStack s;
    s.profile = profile;
    // Below: boundaries at excess fractions k / (below + 1/2) from the ground's to the eye's,
    // the eye's layer from the last of them; the ground layer holds eta0, the others the
    // excess midway between their boundaries.
    s.excess.push_back(ex0);
    for (int k = 1; k <= below; ++k) {
        const double f = k / (below + 0.5);
        s.heights.push_back(height_of_excess(profile, ex0 + f * (ex_eye - ex0)));
        if (k < below) s.excess.push_back(ex0 + (k + 0.5) / (below + 0.5) * (ex_eye - ex0));
    }
    s.excess.push_back(ex_eye);
    // Above: from half a step over the eye up to `top`; the half-space over them holds
    // eta(infinity), so that every ray that leaves for the sky leaves in its exact direction.
    for (int k = 1; k <= above; ++k) {
        const double f = (k - 0.5) / (above - 0.5);  // the last one at `top`
        s.heights.push_back(height_of_excess(profile, ex_eye + f * (ex_top - ex_eye)));
        s.excess.push_back(k < above ? ex_eye + k / (above - 0.5) * (ex_top - ex_eye)
                                     : eta_sq_excess(profile, kInf));
    }
    // Heights strictly ascending, off the eye.
    std::vector<double> h;
    std::vector<double> ex = {s.excess.front()};
    for (size_t j = 0; j < s.heights.size(); ++j) {
        const double y = s.heights[j];
        if (!std::isfinite(y) || y <= 0.0 || (!h.empty() && y <= h.back())) continue;
        h.push_back(y);
        ex.push_back(s.excess[j + 1]);
    }
    move_off_camera(h, eye_y);
    s.heights = h;
    s.excess = ex;
    // The eye's layer holds the eye's index exactly.
    s.excess[s.layer_at(eye_y)] = ex_eye;
    return s;
}

ObjectQuery object_query(const SceneAccel& accel) {
    // Most pieces of a band path lie far from every finite object: a slab test against their
    // common bounds spares the full query, leaving only the unbounded ones (planes) to test.
    return [&accel](const glm::dvec3& o, const glm::dvec3& d,
                    double t_max) -> std::optional<ObjectHit> {
        const Aabb& b = accel.finite_bounds();
        const bool near_finite = !b.empty() && slab_test(b, SlabRay(o, d), 1e-6, t_max);
        if (near_finite) {
            auto h = accel.closest_hit(o, d, 1e-6, t_max);
            if (!h) return std::nullopt;
            return ObjectHit{h->t, h->normal, h->primitive};
        }
        auto h = accel.closest_unbounded_hit(o, d, 1e-6, t_max);
        if (!h) return std::nullopt;
        return ObjectHit{h->t, h->normal, h->primitive};
    };
}

int fewer_steps_for_trace_level(Design& d, int count, const std::string& steps) {
    const int fewer = std::max(
        2, std::min(count - 1,
                    static_cast<int>(count * double(kMaxTraceLevel - 1) / d.max_trace_level)));
    d.warnings.push_back("a camera ray with its reflections reached trace level " +
                         std::to_string(d.max_trace_level) + " with " + std::to_string(count) +
                         " " + steps + "; redesigned with " + std::to_string(fewer));
    return fewer;
}

void warn_past_trace_level_ceiling(Design& d) {
    if (d.max_trace_level > kMaxTraceLevel)
        d.warnings.push_back(
            "some camera rays reach POV-Ray's trace-level ceiling with these layers: they "
            "will render black");
}

int deepest_trace_level(const CompileContext& ctx, const LayerStack& rendered,
                        const CameraRays& rays) {
    const ObjectQuery objects = object_query(*ctx.accel);
    const double camera_y = ctx.reference_y(rendered);
    std::vector<int> level(rays.size(), 0);
    parallel_for(static_cast<long>(rays.size()), [&](long i) {
        // A ray from below the ground enters the layers where it rises to it, if ever (the
        // straight stretch below, in the bottom layer, costs no level).
        const glm::dvec3 o = rays.origin.empty() ? ctx.camera.location : rays.origin[i];
        const auto from = entry_into_atmosphere(o, rays.direction[i]);
        level[i] =
            from ? trace_levels(ctx, rendered, objects, camera_y, *from, rays.direction[i], 1, 1.0)
                 : 1;
    });
    return rays.size() ? *std::max_element(level.begin(), level.end()) : 0;
}

namespace {

// A camera ray through a horizontal stack is one ray of the 2D problem of its elevation: its
// path in the half-plane of its azimuth, out to where the layers end, with POV-Ray's ior
// quotients (layers/revolution.h).
MeridianPath camera_path(const CompileContext& ctx, const RevolutionStack& s, double elevation) {
    return trace_meridian(s, elevation, ctx.layers_box.x1 - ctx.camera.location.x, 100000, true);
}

// The slope of a path at radius r (its final direction beyond its last point).
double slope_at_radius(const MeridianPath& p, double r) {
    for (size_t i = 1; i < p.points.size(); ++i)
        if (p.points[i].x >= r && p.points[i - 1].x <= r && p.points[i].x > p.points[i - 1].x)
            return (p.points[i].y - p.points[i - 1].y) / (p.points[i].x - p.points[i - 1].x);
    return p.direction.y / p.direction.x;
}

}  // namespace

std::vector<double> design_errors(const CompileContext& ctx, const LayerStack& rendered,
                                  const CameraRays& rays, int* max_crossings) {
    const RevolutionStack s = revolution_of(rendered, ctx.eye_y);
    std::vector<double> err(rays.size(), 0.0);
    std::vector<int> cross(rays.size(), 0);
    parallel_for(static_cast<long>(rays.size()), [&](long i) {
        const MeridianPath p = camera_path(ctx, s, rays.elevation[i]);
        cross[i] = p.crossings;
        if (p.cut_off) {
            err[i] = kInf;
            return;
        }
        const double exit = rays.exit_dz[i];
        BandOutcome b;
        b.ground = p.ground && p.points.back().x <= exit;
        if (b.ground) {
            b.dz = p.points.back().x;
        } else {
            b.dz = exit;
            b.y = path_height(p, exit);
            b.slope = slope_at_radius(p, exit);
            b.sky = !p.ground && p.direction.y > 0.0;
            b.final_slope = p.direction.y / p.direction.x;
        }
        const BandOutcome e = exact_outcome(ctx.atmosphere, ctx.eye_y, rays.elevation[i], exit);
        err[i] = outcome_error_rad(ctx.eye_y, e, b) / rays.pixel_rad[i];
    });
    if (max_crossings)
        *max_crossings = cross.empty() ? 0 : *std::max_element(cross.begin(), cross.end());
    return err;
}

double layers_reach(const CompileContext& ctx, const LayerStack& rendered, const CameraRays& rays) {
    if (ctx.many_origins) return many_origins_reach(ctx, rendered, rays);
    const double cap = ctx.layers_box.x1 - ctx.camera.location.x;
    if (rendered.boundaries() == 0) return 1.1 * ctx.extent;
    const RevolutionStack s = revolution_of(rendered, ctx.eye_y);
    std::vector<double> reach(rays.size(), 0.0);
    parallel_for(static_cast<long>(rays.size()), [&](long i) {
        const MeridianPath p = camera_path(ctx, s, rays.elevation[i]);
        if (p.cut_off || p.crossings == 0) return;
        // The last boundary event: the point before the path's end (the ground or the reach).
        reach[i] = 1.1 * p.points[p.points.size() - 2].x;
    });
    const double r = std::max(1.1 * ctx.extent, *std::max_element(reach.begin(), reach.end()));
    return std::min(r, cap);
}

std::optional<double> layers_reach_below(const CompileContext& ctx, const LayerStack& rendered,
                                         const CameraRays& rays, double reach) {
    if (!ctx.layers_below_box || rendered.boundaries() == 0) return std::nullopt;
    const double cap = ctx.layers_below_box->x1 - ctx.camera.location.x;
    const ObjectQuery objects = object_query(*ctx.accel);
    const double camera_y = ctx.reference_y(rendered);
    std::vector<double> last(rays.size(), 0.0);
    parallel_for(static_cast<long>(rays.size()), [&](long i) {
        Trace3dOptions o{100000, &objects, camera_y};
        o.below = ctx.layers_below_box;
        const Trace3dOutcome t = trace_layers_3d(rendered, ctx.camera.location, rays.direction[i],
                                                 ctx.scene_box, ctx.layers_box, o);
        if (!t.cut_off) last[i] = 1.1 * t.last_event;
    });
    const double r = std::max(reach, *std::max_element(last.begin(), last.end()));
    return std::min(r, cap);
}

Result<Design> design_layers(const CompileContext& ctx, const CameraRays& rays) {
    if (ctx.many_origins) return design_many_origins(ctx, rays);
    // The designs fitted with the exponential profiles' closed forms, else those built from
    // n(y) alone.
    const Profile* closed = ctx.atmosphere.exponential_profile();
    if (!closed) return design_air_layers(ctx, rays);
    const Profile& profile = *closed;
    Design d;
    const MirageSettings& st = ctx.settings;
    d.stack.profile = profile;
    d.stack.excess = {eta_sq_excess(profile, ctx.eye_y)};
    if (!st.declared || profile.kind == ProfileKind::None) {
        d.mode = "none";
        d.left_out.push_back("every layer: the scene declares no atmosphere");
        return d;
    }
    if (st.layers == LayerMode::IndexSteps)
        return make_error(ctx.scene.file + ": index steps (layers at equal steps of the index) " +
                          "are the design for real air and for cameras whose rays start at " +
                          "many points, and this scene's atmosphere is the exponential profile " +
                          st.profile_label +
                          ": leave Mirage_Layers out for layers fitted to the camera's rays, or "
                          "ask for uniform layers (--layers uniform --count N)");
    d.mode = st.layers == LayerMode::Uniform ? "uniform" : "adaptive";
    if (st.layers == LayerMode::Uniform) {
        if (st.layer_count < 1)
            return make_error(ctx.scene.file +
                              ": uniform layers need a count: --count N or Mirage_Layer_Count");
        const double top = top_reached(ctx, profile, rays);
        d.stack = merge_invisible_boundaries(
            uniform_layers(profile, ctx.eye_y, st.layer_count, top), ctx.eye_y);
        // Berger's layers do not care where the camera is; POV-Ray needs it off a boundary.
        for (double& h : d.stack.heights)
            if (std::fabs(h - ctx.eye_y) < 1e-9 * std::max(1.0, ctx.eye_y))
                h += 1e-6 * std::max(1.0, ctx.eye_y);
        d.left_out.push_back("layers above y = " + sig(top, 4) +
                             ": no camera ray reaches higher inside the scene");
        d.max_trace_level = deepest_trace_level(ctx, ctx.rendered(d.stack), rays);
        warn_past_trace_level_ceiling(d);
        return d;
    }
    // Errors of the homogeneous model: when no ray bends by the tolerance, no layers at all.
    const std::vector<double> straight = design_errors(ctx, d.stack, rays);
    const double straight_max = *std::max_element(straight.begin(), straight.end());
    if (straight_max <= st.tolerance_px) {
        d.left_out.push_back("every layer: no camera ray bends by " + sig(st.tolerance_px, 3) +
                             " px (largest bend " + sig(straight_max, 3) + " px)");
        return d;
    }
    if (ctx.options.camera == CameraModel::Corrected) {
        // The corrected camera aims every ray through where its exact ray ends: the layers
        // only carry the paths' smooth bending, at equal steps of eta^2.
        d.mode = "index steps";
        const double top = corrected_camera_top(ctx, profile, rays);
        // (The trace levels are those of the aimed rays, measured when they are aimed.)
        const int count = st.layer_count > 0 ? st.layer_count : kCorrectedCameraLayers;
        d.stack = merge_invisible_boundaries(
            corrected_camera_layers(profile, ctx.eye_y, count, top), ctx.eye_y);
        d.left_out.push_back("layers above y = " + sig(top, 4) +
                             ": no camera ray reaches higher inside the scene, or a ray rising "
                             "from there turns by less than a tenth of a pixel more");
        return d;
    }
    // Fit to the rays of a few columns spread from the image's centre to its edge (their rows
    // have other elevations), measure on every pixel.
    const int W = rays.width, H = rays.height;
    std::vector<DesignRay> design;
    const int n_cols = std::max(1, std::min(ctx.options.fit_columns, (W + 1) / 2));
    for (int k = 0; k < n_cols; ++k) {
        const int col = n_cols == 1 ? W / 2 : W / 2 + (W - 1 - W / 2) * k / (n_cols - 1);
        for (int row = 0; row < H; ++row) {
            const size_t i = static_cast<size_t>(row) * W + col;
            design.push_back({rays.elevation[i], rays.exit_dz[i], rays.pixel_rad[i], col, row});
        }
    }
    LayerFitSettings fs;
    fs.tolerance_px = st.tolerance_px;
    fs.layers_extent_factor = kLayersExtentFactor;
    // The budget of one pass through the layers: a camera ray may meet a reflective object
    // and pass through them again; measured below and tightened if needed.
    fs.max_crossings = ctx.gaps ? (kMaxTraceLevel - 1) / 2 : kMaxTraceLevel - 1;
    // POV-Ray ignores a hit closer than 1e-4 units to a ray's origin: along the steepest ray,
    // every layer (and gap) must be thicker than that.
    fs.min_thickness = ctx.gaps ? 3.0 * ctx.gap : 1.5e-4 * ctx.steepest_sine;
    for (int attempt = 0; attempt < 12; ++attempt) {
        FitResult f = fit_layers(profile, ctx.eye_y, design, fs);
        d.max_error_px_fitted = f.quality.max_error_px;
        d.stack = merge_invisible_boundaries(f.stack, ctx.eye_y);
        const int level = deepest_trace_level(ctx, ctx.rendered(d.stack), rays);
        d.max_trace_level = level;
        if (level <= kMaxTraceLevel) break;
        // Over the ceiling: fewer crossings per pass, in proportion.
        const int per_pass =
            std::min(f.quality.max_crossings, fs.max_crossings) * (ctx.gaps ? 2 : 1);
        fs.max_crossings =
            std::max(4, std::min(per_pass - 1,
                                 static_cast<int>(per_pass * double(kMaxTraceLevel - 1) / level)) /
                            (ctx.gaps ? 2 : 1));
        d.warnings.push_back("a camera ray with its reflections reached trace level " +
                             std::to_string(level) + "; refitted within " +
                             std::to_string(fs.max_crossings) + " crossings per pass");
    }
    return d;
}

}  // namespace mirage
