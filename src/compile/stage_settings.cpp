// Stage "settings" of mirage compile (compile/stages.h).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "compile/stages.h"
#include "trace/scene_screens.h"
#include "load/mirage_scene.h"
#include "pov/povray_path.h"
#include "scene/camera.h"
#include "scene/ground.h"
#include "trace/curved_propagator.h"
#include "trace/object_query.h"
#include "trace/scene_extent.h"
#include "util/format.h"
#include "util/output_set.h"

namespace fs = std::filesystem;

namespace mirage {

namespace {

// The reach of the atmosphere when no object bounds the scene (only planes and the like), in
// camera heights above the ground.
constexpr double kUnboundedSceneExtent = 1000.0;

// The |sin(elevation)| of the steepest ray POV-Ray may shoot through the image (antialiasing
// samples reach the pixels' edges): over the image's edges and a grid inside, which holds
// the steepest ray unless the camera looks nearly straight up or down.
double steepest_sine(const Camera& cam, int W, int H) {
    double s = 0.0;
    auto take = [&](double x, double y) {
        s = std::max(s, std::fabs(camera_ray(cam, x, y, W, H).direction.y));
    };
    constexpr int kSteps = 256;
    for (int i = 0; i <= kSteps; ++i) {
        const double x = W * double(i) / kSteps, y = H * double(i) / kSteps;
        take(x, 0.0), take(x, H), take(0.0, y), take(W, y);
        for (int j = 1; j < 32; ++j) take(x, H * j / 32.0);
    }
    return s;
}

/// The output folder and the image, and what the .ini names for POV-Ray
/// (pov/emit_layers.h): the scene, the image, the include folders, the output folder among
/// them; refused before any work if POV-Ray cannot take one.
Status place_outputs(const CompileOptions& opt, CompileContext& ctx) {
    const fs::path out_dir = fs::absolute(opt.out_dir.empty() ? fs::path("build/render") / ctx.name
                                                              : fs::path(opt.out_dir));
    ctx.out_dir = out_dir.string();
    ctx.image = opt.image.empty() ? (out_dir / (ctx.name + ".png")).string()
                                  : fs::absolute(opt.image).string();
    if (auto s = check_povray_path(fs::absolute(opt.scene).string(), "the scene"); !s) return s;
    if (auto s = check_povray_path(ctx.out_dir, "the output folder (-o)"); !s) return s;
    if (auto s = check_povray_path(ctx.image, opt.image.empty() ? "the image" : "--image"); !s)
        return s;
    for (const auto& l : opt.library_paths)
        if (auto s = check_povray_path(fs::absolute(l).string(), "-L"); !s) return s;
    return Ok{};
}

/// The camera's pixel footprint, and what the options ask of the camera that it cannot give:
/// a corrected camera past the meshes' limit, nested layers for rays from many origins.
Status check_camera(const CompileOptions& opt, CompileContext& ctx) {
    auto footprint = pixel_footprint(ctx.camera, opt.width, opt.height);
    if (!footprint)
        return make_error(place_prefix(ctx.camera.loc, ctx.scene.file) + footprint.message());
    ctx.footprint = *footprint;
    // The corrected camera's meshes, about 60 bytes of text and 215 bytes of POV-Ray's memory a
    // face (../studies/mesh-camera): refused past the limit before any work, with the figure.
    if (opt.camera == CameraModel::Corrected && !ctx.many_origins && ctx.settings.declared) {
        const size_t samples = shot_samples(opt.samples_per_side, opt.antialias).size();
        const double faces = static_cast<double>(opt.width) * opt.height * samples;
        if (faces > kMaxMeshCameraFaces)
            return make_error(
                "--width " + std::to_string(opt.width) + " --height " + std::to_string(opt.height) +
                (samples > 1 ? " antialiased" : std::string()) +
                ": the corrected camera would need " + sig(faces, 3) + " mesh faces (about " +
                sig(faces * 215.0 / (1 << 30), 3) +
                " GiB of POV-Ray's memory), more than the limit of " + sig(kMaxMeshCameraFaces, 3) +
                ": render smaller, or use --camera perspective");
    }
    if (ctx.many_origins && opt.layout == LayerLayout::Nested)
        return make_error(place_prefix(ctx.camera.loc, ctx.scene.file) + "the " +
                          camera_type_name(ctx.camera.type) +
                          " camera's rays start at different points, inside different layers: "
                          "--layout nested needs them all in one (use gaps or auto)");
    return Ok{};
}

/// The scene's horizontal extent around the camera: declared, or the objects' with a margin
/// (what bounds it, or does not, noted in the context); with many origins, their spread added.
double scene_extent_around_camera(const CompileOptions& opt, CompileContext& ctx) {
    const Scene& scene = ctx.scene;
    const glm::dvec3& eye = ctx.camera.location;
    double extent = 0.0;
    if (ctx.settings.extent) {
        extent = *ctx.settings.extent;
        ctx.left_out.push_back("the atmosphere reaches " + sig(extent, 4) +
                               " units from the camera (Mirage_Extent)");
    } else {
        const SceneExtent objects = scene_extent(scene, *ctx.accel);
        for (const auto& note : objects.bounded) ctx.left_out.push_back(note);
        for (const auto& note : objects.unbounded) ctx.warnings.push_back(note);
        const Aabb& b = objects.finite;
        if (b.empty() || !b.finite()) {
            // Nothing bounds the scene (planes, objects taken as unbounded): the atmosphere
            // reaches far, and the report says how far.
            extent = kUnboundedSceneExtent * ctx.eye_y;
            if (ctx.settings.declared)
                ctx.warnings.push_back(
                    "no object bounds the scene: the atmosphere reaches " + sig(extent, 4) +
                    " units (" + sig(kUnboundedSceneExtent, 4) +
                    " camera heights) from the camera; declare Mirage_Extent to choose");
        } else {
            for (int i = 0; i < 4; ++i) {
                const double x = (i & 1) ? b.hi.x : b.lo.x, z = (i & 2) ? b.hi.z : b.lo.z;
                extent = std::max(extent, std::hypot(x - eye.x, z - eye.z));
            }
            extent *= 1.25;
        }
    }
    if (extent <= 0.0) extent = 100.0 * ctx.eye_y;
    if (ctx.many_origins) {
        // Every ray's origin lies inside the scene's box: the image's corners and edges'
        // midpoints bound how far the origins spread from the location.
        double spread = 0.0;
        for (const double fx : {0.0, 0.5, 1.0})
            for (const double fy : {0.0, 0.5, 1.0}) {
                const glm::dvec3 o =
                    camera_ray(ctx.camera, fx * opt.width, fy * opt.height, opt.width, opt.height)
                        .origin;
                spread = std::max(spread, std::hypot(o.x - eye.x, o.z - eye.z));
            }
        extent += spread;
    }
    return extent;
}

/// Real air: the tracer's model, fitted for exact paths a twentieth of a pixel from the
/// truth (the pixel check's), followed as far as the tracer follows them; on the curved Earth
/// the layers' reach as POV-Ray's sky allows.
Status fit_real_air(const CompileOptions& opt, CompileContext& ctx) {
    const glm::dvec3& eye = ctx.camera.location;
    const double extent = ctx.extent;
    const double reach_dz =
        ctx.settings.extent ? *ctx.settings.extent : general_path_reach(*ctx.accel, eye);
    auto air = scene_atmosphere(
        ctx.settings, fit_angle_rad(ctx.footprint, 0.05 * ctx.settings.tolerance_px, reach_dz));
    if (!air) return make_error(opt.scene + ": " + air.message());
    if (air->earth_radius() > 0.0) {
        // On the curved Earth a band ray's final direction is its direction in the
        // flattened frame where it stops bending, which is dz / R from the eye's
        // (curved_propagator.h): POV-Ray looks the sky up with it unturned.  The layers
        // reach just past the scene, so that angle stays below 1.1 extent / R.
        const double near = 1.1 * extent;
        // The layers below the camera's may reach as far as on flat ground: a camera ray
        // that turns in them beyond the scene (one that skims a layer just under its
        // index) would otherwise leave them still going down, and POV-Ray's straight ray
        // meet the ground there instead of turning up to the sky; it stops bending where
        // it rises past the camera's layer.
        ctx.layers_below_box = ctx.layers_box;
        ctx.layers_box = {eye.x - near, eye.x + near, eye.z - near, eye.z + near};
        const double R = air->earth_radius();
        if (near > kMaxCurvedSkyRad * R) {
            const double km = ctx.settings.unit_m / 1000.0;
            return make_error(
                opt.scene + ": on the curved Earth POV-Ray sees the sky up to " +
                "the layers' reach over the Earth's radius off (" + sig(near * km, 3) + " km / " +
                shortest(R * km) + " km = " + sig(1e3 * near / R, 3) + " mrad), more than the " +
                shortest(1e3 * kMaxCurvedSkyRad) +
                " mrad bands allow: render it with mirage trace, or declare Mirage_Extent "
                "of at most " +
                shortest(std::floor(kMaxCurvedSkyRad * R / 1.1)) +
                " (scene units), or Mirage_Earth_Radius = 0 for flat ground");
        }
    }
    ctx.atmosphere = std::move(*air);
    ctx.max_dz = reach_dz;
    return Ok{};
}

/// The layout: nested planes, or slabs with gaps where the index steps are so small that
/// POV-Ray's single-precision ior quotients would swamp them (see pov/emit_layers.h).
bool uses_gaps(const CompileOptions& opt, const CompileContext& ctx) {
    // Rays from many origins start inside different layers: POV-Ray builds each one's list of
    // interiors in its bounding tree's order, which only the gap layout's disjoint slabs (one
    // interior at any point) make right.
    if (opt.layout == LayerLayout::Gaps || ctx.many_origins) return true;
    if (opt.layout) return false;
    // Real air: its index changes by a few 1e-4 at most over the heights a scene sees (the
    // flattened profile's n* grows by 1.6e-4 per km on the curved Earth).
    const Profile* p = ctx.atmosphere.exponential_profile();
    if (!p) return true;
    return std::fabs(eta_infinity(*p) - p->eta0) < 1e-3 * p->eta0;
}

}  // namespace

LayerStack CompileContext::rendered(const LayerStack& stack) const {
    return gaps && stack.boundaries() > 0 ? with_gaps(stack, reference_y(stack), gap) : stack;
}

double CompileContext::reference_y(const LayerStack& stack) const {
    const int n = stack.boundaries();
    if (!many_origins || n == 0) return eye_y;
    int best = -1;
    for (int k = 0; k <= n; ++k) {
        if (!stack.air.empty() && stack.air[k]) continue;
        if (best < 0 || stack.excess[k] >= stack.excess[best]) best = k;
    }
    const auto& h = stack.heights;
    if (best == n) return h[n - 1] + std::max(1.0, h[n - 1]);
    if (best == 0) return 0.5 * h[0];
    return 0.5 * (h[best - 1] + h[best]);
}

Result<CompileContext> compile_settings(const CompileOptions& opt) {
    if (opt.samples_per_side < 1 || opt.samples_per_side > 5)
        return make_error("sub-pixel samples " + std::to_string(opt.samples_per_side) +
                          " per side: must be 1 to 5");
    if (!opt.error_map.empty() && fs::path(opt.error_map).extension() != ".exr")
        return make_error("--error-map " + opt.error_map +
                          ": the error map is written as OpenEXR, name it .exr");
    CompileContext ctx;
    ctx.options = opt;
    ctx.name = fs::path(opt.scene).stem().string();
    if (auto s = place_outputs(opt, ctx); !s) return s.error();

    // The image size, the include paths, the parse, the Mirage_ settings with the options'
    // replacements and the camera's place: load/mirage_scene.h.
    SceneLoadOptions lo = scene_load_options(opt);
    lo.strict = false;  // the compiler needs the camera, the atmosphere and the extent only
    lo.object_queries = tracer_object_queries();
    lo.tolerance_px = opt.tolerance_px;
    lo.layers = opt.layers;
    lo.layer_count = opt.layer_count;
    lo.clock = opt.clock;
    lo.declares = opt.declares;
    lo.mirage_inc = MirageIncCheck::Always;  // the layers reach POV-Ray through mirage.inc only
    auto loaded = load_mirage_scene(lo);
    if (!loaded) return loaded.error();
    ctx.scene = std::move(loaded->scene);
    // The outputs the options name may not replace a file the scene was read from: refused
    // here, before any work (compile_scene writes them through an OutputSet of its own).
    {
        const OutputSet inputs(ctx.scene.files);
        for (const std::string& named : {opt.error_map, opt.image})
            if (!named.empty())
                if (auto s = inputs.check(named); !s) return s.error();
    }
    for (const auto& p : loaded->parse_options.library_paths) {
        ctx.library_paths.push_back(fs::absolute(p).string());
        if (auto s = check_povray_path(ctx.library_paths.back(), "the include folder"); !s)
            return s.error();
    }
    ctx.settings = loaded->settings;
    // Heights above the atmosphere's ground from here on (scene/ground.h).
    const double ground = ctx.settings.ground_height;
    const Scene as_parsed = ground != 0.0 ? ctx.scene : Scene{};
    lower_scene(ctx.scene, ground);
    if (opt.profile) {
        ctx.settings.profile = *opt.profile;
        ctx.settings.profile_label = opt.profile_label.empty() ? "replaced" : opt.profile_label;
        ctx.settings.declared = true;
    }

    if (opt.profile) ctx.settings.air.reset();  // the replacement is exponential
    const Scene& scene = ctx.scene;
    ctx.camera = scene.camera;
    ctx.eye_y = ctx.camera.location.y;
    ctx.many_origins = !camera_has_one_viewpoint(ctx.camera);
    if (auto s = check_camera(opt, ctx); !s) return s.error();
    auto accel = SceneAccel::build(scene);
    if (!accel) return accel.error();
    ctx.accel = std::make_shared<const SceneAccel>(std::move(*accel));
    // (Heights above the atmosphere's ground: the camera's against the scene as parsed.)
    if (auto s = check_camera_above_ground(ground != 0.0 ? as_parsed : scene, ground,
                                           [&]() -> std::optional<double> {
                                               const Aabb& b = ctx.accel->finite_bounds();
                                               if (b.empty()) return std::nullopt;
                                               return b.lo.y + ground;
                                           });
        !s)
        return s.error();

    const glm::dvec3& eye = ctx.camera.location;
    const double extent = scene_extent_around_camera(opt, ctx);
    ctx.extent = extent;
    ctx.scene_box = {eye.x - extent, eye.x + extent, eye.z - extent, eye.z + extent};
    const double reach = kLayersExtentFactor * extent;
    ctx.layers_box = {eye.x - reach, eye.x + reach, eye.z - reach, eye.z + reach};

    ctx.atmosphere = Atmosphere::exponential(profile_in_scene_units(ctx.settings));
    if (auto s = ctx.settings.air ? fit_real_air(opt, ctx) : Status(Ok{}); !s) return s.error();
    // Turbulent air: the exact rays the corrected camera aims at are walked through it, at the
    // clock the scene was parsed at (a frame of an animation shimmers).
    if (ctx.settings.turbulence) {
        auto screens = scene_screens(ctx.scene, ctx.settings);
        if (!screens) return screens.error();
        ctx.turbulence = std::move(*screens);
        ctx.turbulence_time_s = turbulence_time_s(loaded->parse_options);
    }
    ctx.gaps = uses_gaps(opt, ctx);
    // Gaps thick enough that POV-Ray sees both of their faces along the steepest camera ray
    // (it ignores hits closer than MIN_ISECT_DEPTH = 1e-4 units to a ray's origin).
    ctx.steepest_sine = steepest_sine(ctx.camera, opt.width, opt.height);
    ctx.gap = std::max(1.5e-4 * ctx.steepest_sine, 1e-7 * ctx.eye_y);
    return ctx;
}

}  // namespace mirage
