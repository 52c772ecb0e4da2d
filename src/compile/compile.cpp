#include "compile/compile.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "atmosphere/exact_ray.h"
#include "compile/library_paths.h"
#include "compile/pixel_check.h"
#include "image/image_io.h"
#include "layers/band_tracer3d.h"
#include "layers/fit.h"
#include "layers/outcome.h"
#include "pov/emit_layers.h"
#include "scene/camera.h"
#include "scene/ground.h"
#include "scene/parser.h"
#include "trace/scene_accel.h"
#include "trace/scene_extent.h"
#include "util/atomic_file.h"
#include "util/check.h"
#include "util/format.h"

namespace fs = std::filesystem;

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// POV-Ray counts a camera ray and every ray it spawns (refraction, reflection) as one more
// trace level; max_trace_level 256 is its ceiling and a ray that reaches it returns black.
// Staying at 255 or below keeps the statistics' "Max Level" under 256.
constexpr int kMaxLevel = 255;
// How far the layers reach beyond the scene, in scene extents: far enough that the camera's
// rays leave them through the top (towards the sky, with eta(infinity)) or reach the ground.
constexpr double kLayersExtentFactor = 1000.0;
// The reach of the atmosphere when no object bounds the scene (only planes and the like), in
// camera heights above the ground.
constexpr double kUnboundedSceneExtent = 1000.0;

std::string scene_name(const std::string& path) { return fs::path(path).stem().string(); }

struct PixelRay {
    glm::dvec3 direction{0.0};
    double elevation = 0.0;
    double exit_dz = 0.0;
    double pixel_rad = 0.0;
};

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t i = static_cast<size_t>(std::floor(q * (v.size() - 1) + 0.5));
    return v[std::min(i, v.size() - 1)];
}

// The largest trace level POV-Ray reaches for one camera ray: one level per boundary event
// in the layers and per reflection off an object, following every reflection whose weight
// stays above POV-Ray's adc_bailout.
int trace_levels(const LayerStack& stack, const Scene& scene, const ObjectQuery& objects,
                 double camera_y, const glm::dvec3& origin, const glm::dvec3& dir,
                 const HorizontalBox& scene_box, const HorizontalBox& layers_box, int level,
                 double weight) {
    // Followed past the ceiling (to 4 times it) so that a design over it knows by how much.
    const Trace3dOutcome t = trace_layers_3d(stack, origin, dir, scene_box, layers_box,
                                             Trace3dOptions{4 * kMaxLevel, &objects, camera_y});
    level += t.crossings;
    if (t.cut_off) return std::max(level, 4 * kMaxLevel);
    int deepest = level;
    if (t.object) {
        const Primitive& prim = scene.primitives[t.object->id];
        const glm::dvec3 refl = prim.texture.finish.reflection;
        const double r = std::max({refl.x, refl.y, refl.z});
        if (r > 0.0 && weight * r >= 1.0 / 255.0) {
            glm::dvec3 n = t.object->normal;
            if (glm::dot(n, t.object_dir) > 0.0) n = -n;
            const glm::dvec3 rd = glm::reflect(t.object_dir, n);
            glm::dvec3 start = t.object_point + 1e-6 * n;
            start.y = std::max(start.y, 0.0);
            deepest = std::max(deepest, trace_levels(stack, scene, objects, camera_y, start, rd,
                                                     scene_box, layers_box, level + 1, weight * r));
        }
    }
    return deepest;
}

// Objects met along a straight piece of a band path.  Most pieces lie far from every finite
// object: a slab test against their common bounds spares the full query, leaving only the
// unbounded ones (planes) to test.
ObjectQuery object_query(const SceneAccel& accel) {
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

}  // namespace

namespace {

/// The pixels' errors as an image: seen error (px), shift (rows), reflections' error (px).
Image error_map_image(const CompileReport& r) {
    Image im(r.width, r.height);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const size_t i = static_cast<size_t>(y) * r.width + x;
            im.set(x, y,
                   glm::vec3(r.pixel_error_px[i], r.pixel_shift_rows[i],
                             r.pixel_reflection_error_px[i]));
        }
    return im;
}

}  // namespace

Result<CompileReport> compile_scene(const CompileOptions& opt) {
    const auto t0 = std::chrono::steady_clock::now();
    if (opt.width < 1 || opt.height < 1 || opt.width > 20000 || opt.height > 20000)
        return make_error("image size " + std::to_string(opt.width) + "x" +
                          std::to_string(opt.height) + " must be 1 to 20000 pixels each way");
    CompileReport rep;
    rep.scene = opt.scene;
    rep.name = scene_name(opt.scene);
    rep.width = opt.width;
    rep.height = opt.height;

    ParseOptions po;
    po.library_paths = opt.library_paths;
    for (const auto& p : default_library_paths(opt.scene)) po.library_paths.push_back(p);
    po.image_width = opt.width;
    po.image_height = opt.height;
    po.strict = false;  // the compiler needs the camera, the atmosphere and the extent only
    auto parsed = parse_scene_file(opt.scene, po);
    if (!parsed) return parsed.error();
    auto settings_r = read_atmosphere_settings(*parsed);
    if (!settings_r) return settings_r.error();
    AtmosphereSettings settings = *settings_r;
    // Heights above the atmosphere's ground from here on (scene/ground.h).
    const Scene as_parsed = settings.ground_height != 0.0 ? *parsed : Scene{};
    lower_scene(*parsed, settings.ground_height);
    const Scene& scene = *parsed;
    if (opt.tolerance_px) {
        if (!(*opt.tolerance_px > 0.0))
            return make_error("--tolerance " + shortest(*opt.tolerance_px) +
                              ": must be > 0 pixels");
        settings.tolerance_px = *opt.tolerance_px;
    }
    if (opt.profile) {
        settings.profile = *opt.profile;
        settings.profile_label = opt.profile_label.empty() ? "replaced" : opt.profile_label;
        settings.declared = true;
    }
    if (!opt.error_map.empty() && fs::path(opt.error_map).extension() != ".exr")
        return make_error("--error-map " + opt.error_map +
                          ": the error map is written as OpenEXR, name it .exr");
    if (opt.layers) settings.layers = *opt.layers;
    if (opt.layer_count) settings.layer_count = *opt.layer_count;
    rep.tolerance_px = settings.tolerance_px;
    rep.atmosphere = settings.declared ? settings.profile_label : "none declared";

    const Camera& cam = scene.camera;
    const double eye_y = cam.location.y;
    const std::string cam_at = cam.loc.file.empty()
                                   ? scene.file + ": "
                                   : cam.loc.file + ":" + std::to_string(cam.loc.line) + ":" +
                                         std::to_string(cam.loc.column) + ": ";
    if (!camera_has_one_viewpoint(cam))
        return make_error(cam_at + "the " + camera_type_name(cam.type) +
                          " camera's rays start at different points: mirage compile fits the "
                          "layers to the rays of one eye point");
    auto accel_r = SceneAccel::build(scene);
    if (!accel_r) return accel_r.error();
    const SceneAccel& accel = *accel_r;
    if (!(eye_y > 0.0)) {
        std::optional<double> lowest;
        if (!accel.finite_bounds().empty())
            lowest = accel.finite_bounds().lo.y + settings.ground_height;
        return make_error(camera_below_ground_message(
            settings.ground_height != 0.0 ? as_parsed : scene, settings.ground_height, lowest));
    }

    // The scene's horizontal extent around the camera: declared, or the objects' with a margin.
    double extent = 0.0;
    if (settings.extent) {
        extent = *settings.extent;
        rep.left_out.push_back("the atmosphere reaches " + sig(extent, 4) +
                               " units from the camera (Mirage_Extent)");
    } else {
        const SceneExtent objects = scene_extent(scene, accel);
        for (const auto& note : objects.bounded) rep.left_out.push_back(note);
        for (const auto& note : objects.unbounded) rep.warnings.push_back(note);
        const Aabb& b = objects.finite;
        if (b.empty() || !b.finite()) {
            // Nothing bounds the scene (planes, objects taken as unbounded): the atmosphere
            // reaches far, and the report says how far.
            extent = kUnboundedSceneExtent * eye_y;
            if (settings.declared)
                rep.warnings.push_back(
                    "no object bounds the scene: the atmosphere reaches " + sig(extent, 4) +
                    " units (" + sig(kUnboundedSceneExtent, 4) +
                    " camera heights) from the camera; declare Mirage_Extent to choose");
        } else {
            for (int i = 0; i < 4; ++i) {
                const double x = (i & 1) ? b.hi.x : b.lo.x, z = (i & 2) ? b.hi.z : b.lo.z;
                extent = std::max(extent, std::hypot(x - cam.location.x, z - cam.location.z));
            }
            extent *= 1.25;
        }
    }
    if (extent <= 0.0) extent = 100.0 * eye_y;
    rep.extent = extent;
    const HorizontalBox scene_box{cam.location.x - extent, cam.location.x + extent,
                                  cam.location.z - extent, cam.location.z + extent};
    const double layers_reach = kLayersExtentFactor * extent;
    const HorizontalBox layers_box{cam.location.x - layers_reach, cam.location.x + layers_reach,
                                   cam.location.z - layers_reach, cam.location.z + layers_reach};

    // Every pixel centre's ray.
    const int W = opt.width, H = opt.height;
    std::vector<PixelRay> rays(static_cast<size_t>(W) * H);
    for (int row = 0; row < H; ++row) {
        for (int col = 0; col < W; ++col) {
            PixelRay& r = rays[static_cast<size_t>(row) * W + col];
            r.direction = camera_ray(cam, col + 0.5, row + 0.5, W, H).direction;
            r.elevation = std::asin(std::clamp(r.direction.y, -1.0, 1.0));
            const double hl = std::hypot(r.direction.x, r.direction.z);
            r.exit_dz = hl > 0.0 ? distance_to_box_edge(scene_box, cam.location.x, cam.location.z,
                                                        r.direction.x / hl, r.direction.z / hl)
                                 : extent;
            r.pixel_rad = angle_between(camera_ray(cam, col + 0.5, row, W, H).direction,
                                        camera_ray(cam, col + 0.5, row + 1.0, W, H).direction);
        }
    }

    const Profile profile = profile_in_scene_units(settings);
    // The layout: nested planes, or slabs with gaps where the index steps are so small that
    // POV-Ray's single-precision ior quotients would swamp them (see pov/emit_layers.h).
    bool gaps = false;
    if (opt.layout == "gaps") {
        gaps = true;
    } else if (opt.layout == "auto") {
        gaps = std::fabs(eta_infinity(profile) - profile.eta0) < 1e-3 * profile.eta0;
    } else if (opt.layout != "nested") {
        return make_error("--layout " + opt.layout + ": expected nested, gaps or auto");
    }
    rep.layout = gaps ? "gaps" : "nested";
    // Gaps thick enough that POV-Ray sees both of their faces along the steepest camera ray
    // (it ignores hits closer than MIN_ISECT_DEPTH = 1e-4 units to a ray's origin).
    double max_sin = 0.0;
    for (const auto& r : rays) max_sin = std::max(max_sin, std::fabs(r.direction.y));
    const double gap = std::max(1.5e-4 * max_sin, 1e-7 * eye_y);
    rep.gap = gaps ? gap : 0.0;
    auto as_rendered = [&](const LayerStack& s) { return gaps ? with_gaps(s, eye_y, gap) : s; };
    LayerStack stack;
    stack.profile = profile;
    stack.excess = {eta_sq_excess(profile, eye_y)};
    rep.mode = settings.declared ? (settings.layers == LayerMode::Uniform ? "uniform" : "adaptive")
                                 : "none";
    // Errors of the homogeneous model: when no ray bends by the tolerance, no layers at all.
    auto pixel_errors = [&](const LayerStack& s, std::vector<double>& err, int& max_cross) {
        err.assign(rays.size(), 0.0);
        max_cross = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            const PixelRay& r = rays[i];
            Trace3dOptions to;
            to.camera_y = eye_y;
            const Trace3dOutcome t =
                trace_layers_3d(s, cam.location, r.direction, scene_box, layers_box, to);
            BandOutcome b;
            b.ground = t.ground;
            const double hl = std::hypot(r.direction.x, r.direction.z);
            b.dz = glm::length(
                glm::dvec2(t.scene_point.x - cam.location.x, t.scene_point.z - cam.location.z));
            if (!t.ground && hl > 0.0) b.dz = r.exit_dz;
            b.y = t.scene_point.y;
            const double sh = std::hypot(t.scene_dir.x, t.scene_dir.z);
            b.slope = sh > 0.0 ? t.scene_dir.y / sh : 0.0;
            b.sky = t.sky;
            const double fh = std::hypot(t.final_dir.x, t.final_dir.z);
            b.final_slope = fh > 0.0 ? t.final_dir.y / fh : 0.0;
            const BandOutcome e = exact_outcome(profile, eye_y, r.elevation, r.exit_dz);
            err[i] = t.cut_off ? kInf : outcome_error_rad(eye_y, e, b) / r.pixel_rad;
            max_cross = std::max(max_cross, t.crossings);
        }
    };
    std::vector<double> err;
    int max_cross = 0;
    if (settings.declared && profile.kind != ProfileKind::None) {
        pixel_errors(stack, err, max_cross);
        const double straight_max = *std::max_element(err.begin(), err.end());
        if (straight_max <= settings.tolerance_px && settings.layers == LayerMode::Adaptive) {
            rep.left_out.push_back("every layer: no camera ray bends by " +
                                   sig(settings.tolerance_px, 3) + " px (largest bend " +
                                   sig(straight_max, 3) + " px)");
        } else if (settings.layers == LayerMode::Uniform) {
            if (settings.layer_count < 1)
                return make_error(scene.file +
                                  ": uniform layers need a count: --count N or "
                                  "Mirage_Layer_Count");
            // Over the heights the camera's rays reach inside the scene.
            double top = eye_y;
            for (const auto& r : rays) {
                auto ex = make_exact_ray(profile, eye_y, M_PI / 2 - r.elevation);
                if (!ex) continue;
                top = std::max(
                    top,
                    height_at(*ex, std::min(r.exit_dz, ex->hits_ground ? ex->dz_ground : kInf)));
            }
            top = std::min(
                top, std::max(eye_y * 1.001,
                              height_of_excess(profile, eta_sq_excess(profile, kInf) * 0.99)));
            stack = uniform_layers(profile, eye_y, settings.layer_count, top);
            // Berger's layers do not care where the camera is; POV-Ray needs it off a boundary.
            for (double& h : stack.heights)
                if (std::fabs(h - eye_y) < 1e-9 * std::max(1.0, eye_y))
                    h += 1e-6 * std::max(1.0, eye_y);
            rep.left_out.push_back("layers above y = " + sig(top, 4) +
                                   ": no camera ray reaches higher inside the scene");
        } else {
            // Fit to the rays of a few columns spread from the image's centre to its edge
            // (their rows have other elevations), measure on every pixel.
            std::vector<DesignRay> design;
            const int n_cols = std::max(1, std::min(opt.fit_columns, (W + 1) / 2));
            for (int k = 0; k < n_cols; ++k) {
                const int col = n_cols == 1 ? W / 2 : W / 2 + (W - 1 - W / 2) * k / (n_cols - 1);
                for (int row = 0; row < H; ++row) {
                    const PixelRay& r = rays[static_cast<size_t>(row) * W + col];
                    design.push_back({r.elevation, r.exit_dz, r.pixel_rad, col, row});
                }
            }
            FitSettings fs;
            fs.tolerance_px = settings.tolerance_px;
            fs.layers_extent_factor = kLayersExtentFactor;
            // The budget of one pass through the layers: a camera ray may meet a reflective
            // object and pass through them again; measured below and tightened if needed.
            fs.max_crossings = gaps ? (kMaxLevel - 1) / 2 : kMaxLevel - 1;
            // POV-Ray ignores a hit closer than 1e-4 units to a ray's origin: along the
            // steepest ray, every layer (and gap) must be thicker than that.
            fs.min_thickness = gaps ? 3.0 * gap : 1.5e-4 * max_sin;
            const ObjectQuery objects = object_query(accel);
            for (int attempt = 0; attempt < 12; ++attempt) {
                FitResult f = fit_layers(profile, eye_y, design, fs);
                rep.max_error_px_fitted = f.quality.max_error_px;
                // The deepest trace level of any camera ray with its reflections.
                int level = 0;
                const LayerStack rendered = as_rendered(f.stack);
                for (size_t i = 0; i < rays.size(); ++i)
                    level = std::max(
                        level, trace_levels(rendered, scene, objects, eye_y, cam.location,
                                            rays[i].direction, scene_box, layers_box, 1, 1.0));
                stack = f.stack;
                rep.max_trace_level = level;
                if (level <= kMaxLevel) break;
                // Over the ceiling: fewer crossings per pass, in proportion.
                const int per_pass =
                    std::min(f.quality.max_crossings, fs.max_crossings) * (gaps ? 2 : 1);
                fs.max_crossings = std::max(
                    4, std::min(per_pass - 1,
                                static_cast<int>(per_pass * double(kMaxLevel - 1) / level)) /
                           (gaps ? 2 : 1));
                rep.warnings.push_back("a camera ray with its reflections reached trace level " +
                                       std::to_string(level) + "; refitted within " +
                                       std::to_string(fs.max_crossings) + " crossings per pass");
            }
        }
        pixel_errors(as_rendered(stack), err, max_cross);
    } else {
        err.assign(rays.size(), 0.0);
        rep.left_out.push_back("every layer: the scene declares no atmosphere");
    }
    rep.max_crossings = max_cross;
    rep.layers = stack.boundaries();
    // The layers reach as far as the camera's rays still meet a boundary before they leave
    // through the top or reach the ground, and at least past the scene: no farther.
    double emitted_reach = 1.1 * extent;
    if (stack.boundaries() > 0) {
        const LayerStack rendered = as_rendered(stack);
        Trace3dOptions to;
        to.camera_y = eye_y;
        for (const auto& r : rays) {
            const Trace3dOutcome t =
                trace_layers_3d(rendered, cam.location, r.direction, scene_box, layers_box, to);
            if (!t.cut_off) emitted_reach = std::max(emitted_reach, 1.1 * t.last_event);
        }
        emitted_reach = std::min(emitted_reach, layers_reach);
    }
    rep.layers_extent = emitted_reach;
    const HorizontalBox emitted_box{cam.location.x - emitted_reach, cam.location.x + emitted_reach,
                                    cam.location.z - emitted_reach, cam.location.z + emitted_reach};
    const int k_cam = stack.layer_at(eye_y);
    rep.below_camera = k_cam;
    rep.above_camera = stack.boundaries() - k_cam;
    if (rep.layers > 0) {
        rep.lowest = stack.heights.front();
        rep.highest = stack.heights.back();
        if (profile.kind == ProfileKind::Inferior)
            rep.left_out.push_back("layers below y = " + sig(rep.lowest, 4) +
                                   ": no camera ray turns lower");
        rep.left_out.push_back("layers above y = " + sig(rep.highest, 4) +
                               ": the index is within 1% of eta(infinity), or no camera ray "
                               "reaches higher");
        rep.left_out.push_back("the layers beyond " + sig(emitted_reach, 4) +
                               " units from the camera: every camera ray has left them by then");
    }
    rep.pixels = static_cast<int>(err.size());
    // What every pixel shows: its ray through the rendered layers against the exact ray, to
    // the surfaces they meet (the design's errors above are taken at the scene's edge).
    rep.pixel_error_px.assign(err.size(), 0.0f);
    rep.pixel_shift_rows.assign(err.size(), 0.0f);
    rep.pixel_reflection_error_px.assign(err.size(), 0.0f);
    if (stack.boundaries() > 0) {
        std::vector<glm::dvec3> directions(rays.size());
        std::vector<double> pixel_rad(rays.size());
        std::vector<bool> cut_off(rays.size());
        double finest = kInf;
        for (size_t i = 0; i < rays.size(); ++i) {
            directions[i] = rays[i].direction;
            pixel_rad[i] = rays[i].pixel_rad;
            cut_off[i] = err[i] == kInf;
            finest = std::min(finest, rays[i].pixel_rad);
        }
        PixelCheckSettings ps;
        ps.width = W;
        ps.height = H;
        ps.eye = cam.location;
        ps.camera_y = eye_y;
        ps.layers = emitted_box;
        ps.exact_tolerance_rad = 0.02 * finest;
        PixelCheck pc = check_pixels(as_rendered(stack), profile, scene, accel, object_query(accel),
                                     directions, pixel_rad, cut_off, ps);
        rep.pixel_error_px = std::move(pc.seen_error_px);
        rep.pixel_shift_rows = std::move(pc.shift_rows);
        rep.pixel_reflection_error_px = std::move(pc.reflection_error_px);
        std::vector<double> seen(rep.pixel_error_px.begin(), rep.pixel_error_px.end());
        std::vector<double> shift;
        for (float v : rep.pixel_shift_rows) {
            if (std::isfinite(v))
                shift.push_back(v);
            else
                ++rep.pixels_not_shown;
        }
        rep.p95_seen_error_px = percentile(seen, 0.95);
        rep.max_seen_error_px = *std::max_element(seen.begin(), seen.end());
        rep.p95_shift_rows = percentile(shift, 0.95);
        rep.max_shift_rows = shift.empty() ? 0.0 : *std::max_element(shift.begin(), shift.end());
    }
    rep.p50_error_px = percentile(err, 0.50);
    rep.p95_error_px = percentile(err, 0.95);
    rep.p99_error_px = percentile(err, 0.99);
    rep.max_error_px = err.empty() ? 0.0 : *std::max_element(err.begin(), err.end());
    std::vector<RowExcess> rows(H);
    for (int row = 0; row < H; ++row) {
        rows[row].row = row;
        for (int col = 0; col < W; ++col) {
            const double e = err[static_cast<size_t>(row) * W + col];
            rows[row].max_error_px = std::max(rows[row].max_error_px, e);
            if (e > settings.tolerance_px) ++rows[row].pixels_over;
        }
        rep.pixels_over += rows[row].pixels_over;
        if (rows[row].pixels_over > 0) rep.rows_over.push_back(rows[row]);
    }
    rep.within_tolerance = rep.pixels_over == 0;
    if (rep.max_trace_level == 0 && rep.layers > 0) {
        // Uniform designs: measure the trace levels too.
        const ObjectQuery objects = object_query(accel);
        const LayerStack rendered = as_rendered(stack);
        for (size_t i = 0; i < rays.size(); ++i)
            rep.max_trace_level =
                std::max(rep.max_trace_level,
                         trace_levels(rendered, scene, objects, eye_y, cam.location,
                                      rays[i].direction, scene_box, layers_box, 1, 1.0));
        if (rep.max_trace_level > kMaxLevel)
            rep.warnings.push_back(
                "some camera rays reach POV-Ray's trace-level ceiling with these "
                "layers: they will render black");
    }

    // Outputs, each to a temporary name first.
    const fs::path dir =
        opt.out_dir.empty() ? fs::path("build/render") / rep.name : fs::path(opt.out_dir);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return make_error(dir.string() + ": cannot create: " + ec.message());
    const fs::path abs_dir = fs::absolute(dir);
    rep.include_path = (abs_dir / "mirage_layers.inc").string();
    rep.csv_path = (abs_dir / "layers.csv").string();
    rep.ini_path = (abs_dir / (rep.name + ".ini")).string();
    rep.report_path = (abs_dir / "report.json").string();
    rep.image_path = opt.image.empty() ? (abs_dir.parent_path() / (rep.name + ".png")).string()
                                       : fs::absolute(opt.image).string();
    const std::string scene_abs = fs::absolute(opt.scene).string();
    if (fs::equivalent(scene_abs, rep.include_path, ec) ||
        fs::equivalent(scene_abs, rep.ini_path, ec))
        return make_error(opt.scene + ": the outputs would overwrite the template");

    LayerEmitSettings es;
    es.camera_y = eye_y;
    es.extent = emitted_box;
    es.ground_height = settings.ground_height;
    es.layout = gaps ? LayerLayout::Gaps : LayerLayout::Nested;
    es.gap = gap;
    es.header = {"mirage_layers.inc: the banded atmosphere of " + rep.name + " at " +
                     std::to_string(W) + "x" + std::to_string(H) + ", written by mirage compile.",
                 "Atmosphere: " + rep.atmosphere + "; " + rep.mode + " layers.",
                 "Error over the " + std::to_string(rep.pixels) + " pixel centres: p50 " +
                     sig(rep.p50_error_px, 3) + " px, p95 " + sig(rep.p95_error_px, 3) +
                     " px, max " + sig(rep.max_error_px, 3) + " px (tolerance " +
                     sig(rep.tolerance_px, 3) + " px).",
                 "Do not edit: run mirage compile again."};
    IniSettings ini;
    ini.scene = scene_abs;
    ini.output_image = rep.image_path;
    ini.width = W;
    ini.height = H;
    ini.library_paths.push_back(abs_dir.string());
    for (const auto& p : po.library_paths) ini.library_paths.push_back(fs::absolute(p).string());
    ini.antialias = opt.antialias;
    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::pair<std::string, std::string> files[] = {
        {rep.include_path, layers_include(stack, es)},
        {rep.csv_path, layers_csv(stack, eye_y)},
        {rep.ini_path, render_ini(ini)},
        {rep.report_path, report_json(rep)},
    };
    for (const auto& [path, text] : files)
        if (auto s = write_file_atomic(path, text); !s) return s.error();
    if (!opt.error_map.empty()) {
        if (auto s = write_exr(error_map_image(rep), opt.error_map); !s) return s.error();
    }
    return rep;
}

std::string report_json(const CompileReport& r) {
    nlohmann::json j;
    j["scene"] = r.scene;
    j["width"] = r.width;
    j["height"] = r.height;
    j["atmosphere"] = r.atmosphere;
    j["mode"] = r.mode;
    j["layout"] = r.layout;
    j["gap"] = r.gap;
    j["tolerance_px"] = r.tolerance_px;
    j["layers"] = r.layers;
    j["layers_below_camera"] = r.below_camera;
    j["layers_above_camera"] = r.above_camera;
    j["p50_error_px"] = r.p50_error_px;
    j["p95_error_px"] = r.p95_error_px;
    j["p95_seen_error_px"] = r.p95_seen_error_px;
    j["max_seen_error_px"] = r.max_seen_error_px;
    j["p95_shift_rows"] = r.p95_shift_rows;
    j["max_shift_rows"] = r.max_shift_rows;
    j["pixels_not_shown"] = r.pixels_not_shown;
    j["p99_error_px"] = r.p99_error_px;
    j["max_error_px"] =
        std::isfinite(r.max_error_px) ? nlohmann::json(r.max_error_px) : nlohmann::json("inf");
    j["max_error_px_fitted_column"] = r.max_error_px_fitted;
    j["pixels"] = r.pixels;
    j["pixels_over_tolerance"] = r.pixels_over;
    j["within_tolerance"] = r.within_tolerance;
    j["max_crossings"] = r.max_crossings;
    j["max_trace_level"] = r.max_trace_level;
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : r.rows_over)
        rows.push_back(
            {{"row", row.row},
             {"max_error_px", std::isfinite(row.max_error_px) ? nlohmann::json(row.max_error_px)
                                                              : nlohmann::json("inf")},
             {"pixels_over", row.pixels_over}});
    j["rows_over_tolerance"] = rows;
    j["left_out"] = r.left_out;
    j["warnings"] = r.warnings;
    j["extent"] = r.extent;
    j["layers_extent"] = r.layers_extent;
    j["seconds"] = r.seconds;
    j["include"] = r.include_path;
    j["ini"] = r.ini_path;
    j["csv"] = r.csv_path;
    j["image"] = r.image_path;
    return j.dump(2) + "\n";
}

std::string report_text(const CompileReport& r) {
    std::ostringstream s;
    s << r.name << " at " << r.width << "x" << r.height << ": " << r.atmosphere << ", " << r.mode
      << " layers, " << r.layout << " layout";
    if (r.layout == "gaps") s << " (gaps of " << sig(r.gap, 3) << " units)";
    s << "\n";
    s << "  layers      " << r.layers << " boundaries (" << r.below_camera << " below the camera, "
      << r.above_camera << " above)";
    if (r.layers > 0) s << " from y = " << sig(r.lowest, 6) << " to " << sig(r.highest, 6);
    s << "\n";
    s << "  error       p50 " << sig(r.p50_error_px, 3) << " px, p95 " << sig(r.p95_error_px, 3)
      << " px, max " << sig(r.max_error_px, 3) << " px over " << r.pixels
      << " pixel centres (tolerance " << sig(r.tolerance_px, 3) << " px)\n";
    if (r.layers > 0) {
        s << "  seen        p95 " << sig(r.p95_seen_error_px, 3) << " px, max "
          << sig(r.max_seen_error_px, 3)
          << " px: where the pixels' rays meet the objects, reflections included\n";
        s << "  shift       p95 " << sig(r.p95_shift_rows, 3) << " rows, max "
          << sig(r.max_shift_rows, 3) << " rows to where the exact image shows the same; "
          << r.pixels_not_shown << " pixels show what no row of their column shows\n";
    }
    if (!r.rows_over.empty()) {
        s << "  over        " << r.pixels_over << " pixels in " << r.rows_over.size()
          << " rows exceed the tolerance; worst rows:";
        auto rows = r.rows_over;
        std::sort(rows.begin(), rows.end(), [](const RowExcess& a, const RowExcess& b) {
            return a.max_error_px > b.max_error_px;
        });
        for (size_t i = 0; i < std::min<size_t>(5, rows.size()); ++i)
            s << " row " << rows[i].row << " (" << sig(rows[i].max_error_px, 3) << " px, "
              << rows[i].pixels_over << " px over)"
              << (i + 1 < std::min<size_t>(5, rows.size()) ? "," : "");
        s << "\n";
    }
    s << "  budget      " << r.max_crossings << " boundary crossings per camera ray, trace level "
      << r.max_trace_level << " of 256 with reflections\n";
    for (const auto& l : r.left_out) s << "  left out    " << l << "\n";
    for (const auto& w : r.warnings) s << "  warning     " << w << "\n";
    s << "  wrote       " << r.include_path << "\n              " << r.ini_path
      << "\n              " << r.csv_path << "\n";
    s << "  time        " << sig(r.seconds, 3) << " s\n";
    return s.str();
}

}  // namespace mirage
