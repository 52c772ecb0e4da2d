#include "load/mirage_scene.h"

#include <cmath>
#include <filesystem>

#include "load/library_paths.h"
#include "scene/camera.h"
#include "util/format.h"

namespace mirage {

namespace {

/// The options' own values, before anything is read.
Status check_options(const SceneLoadOptions& o) {
    if (auto s = check_image_size(o.width, o.height); !s) return s;
    if (o.tolerance_px) {
        if (auto s = check_tolerance_px(*o.tolerance_px, "--tolerance"); !s) return s;
    }
    if (o.layer_count) {
        if (auto s = check_layer_count(*o.layer_count, "--count"); !s) return s;
    }
    return check_library_paths(o.library_paths);
}

}  // namespace

SceneLoadOptions scene_load_options(const std::string& scene, int width, int height,
                                    const std::vector<std::string>& library_paths) {
    SceneLoadOptions o;
    o.scene = scene;
    o.width = width;
    o.height = height;
    o.library_paths = library_paths;
    return o;
}

Status check_library_paths(const std::vector<std::string>& paths) {
    namespace fs = std::filesystem;
    for (const std::string& p : paths) {
        std::error_code ec;
        const fs::file_status status = fs::status(p, ec);
        if (fs::is_directory(status)) continue;
        return make_error("-L " + p + ": " +
                          (fs::exists(status) ? "is not a directory" : "no such directory") +
                          ": -L names a directory to look for include files in");
    }
    return Ok{};
}

Status check_image_size(int width, int height) {
    if (width >= 1 && height >= 1 && width <= kMaxImageSide && height <= kMaxImageSide) return Ok{};
    return make_error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                      " must be 1 to " + std::to_string(kMaxImageSide) + " pixels each way");
}

Result<AtmosphereSettings> settle_mirage_scene(const Scene& scene,
                                               const SceneLoadOptions& options) {
    auto settings = read_atmosphere_settings(scene);
    if (!settings) return settings.error();
    if (options.tolerance_px) settings->tolerance_px = *options.tolerance_px;
    if (options.layers) settings->layers = *options.layers;
    if (options.layer_count) settings->layer_count = *options.layer_count;
    // The camera: within reach, its rays defined, its pixels no finer than paths can follow.
    const Camera& camera = scene.camera;
    const std::string at = (camera.loc.file.empty() ? scene.file : to_string(camera.loc)) + ": ";
    for (int i = 0; i < 3; ++i) {
        const double v = camera.location[i];
        if (std::abs(v) <= kMaxCoordinate) continue;
        return make_error(at + "the camera is at " + "xyz"[i] + " = " + shortest(v) +
                          ": mirage follows scenes within " + shortest(kMaxCoordinate) +
                          " units of the origin");
    }
    const int w = options.width, h = options.height;
    for (const auto& [x, y] :
         {std::pair{0, 0}, std::pair{w, 0}, std::pair{0, h}, std::pair{w, h}}) {
        const glm::dvec3 d = camera_ray(camera, x, y, w, h).direction;
        if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)) ||
            std::abs(glm::length(d) - 1.0) > 1e-9)
            return make_error(at +
                              "camera: its vectors give no ray direction (zero or parallel "
                              "direction, right and up?)");
    }
    // (Rays from many points, as an orthographic camera's, span no angle: the commands that
    // follow paths from an eye refuse those cameras themselves.)
    const double pixel_rad = pixel_angle_rad(camera, w, h);
    if (camera_has_one_viewpoint(camera) && !(pixel_rad >= kMinPixelRad))
        return make_error(at + "one pixel of this camera spans " + sig(pixel_rad, 3) + " rad at " +
                          std::to_string(w) + "x" + std::to_string(h) + ", less than the " +
                          shortest(kMinPixelRad) +
                          " rad mirage samples paths for (widen the view)");
    return settings;
}

Result<MirageScene> load_mirage_scene(const SceneLoadOptions& options) {
    if (auto s = check_options(options); !s) return s.error();
    MirageScene loaded;
    ParseOptions& po = loaded.parse_options;
    po.library_paths = options.library_paths;
    for (const auto& p : default_library_paths(options.scene)) po.library_paths.push_back(p);
    po.image_width = options.width;
    po.image_height = options.height;
    po.strict = options.strict;
    po.limits = options.limits;
    po.object_queries = options.object_queries;
    po.animation = options.animation;
    auto parsed = parse_scene_file(options.scene, po);
    if (!parsed) return parsed.error();
    std::error_code ec;
    if (std::filesystem::file_size(options.scene, ec) == 0 && !ec)
        return make_error(options.scene + ": the file is empty: there is no scene to read");
    loaded.scene = std::move(*parsed);
    auto settings = settle_mirage_scene(loaded.scene, options);
    if (!settings) return settings.error();
    loaded.settings = std::move(*settings);
    // A sounding is an input of the scene: listed with its files, so no output replaces it.
    for (const std::string& f : loaded.settings.input_files) loaded.scene.files.push_back(f);
    return loaded;
}

}  // namespace mirage
