#include "load/mirage_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "load/library_paths.h"
#include "scene/camera.h"
#include "scene/ground.h"
#include "scene/keywords.h"
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
    if (o.clock && !(std::abs(*o.clock) <= std::numeric_limits<float>::max()))
        return make_error("--clock " + shortest(*o.clock) +
                          ": beyond the range of POV-Ray's clock (a float, at most 3.4e+38)");
    return check_library_paths(o.library_paths);
}

/// POV-Ray's still at `clock` (+K): the clock as the float POV-Ray holds, clock_on set, the
/// six frame identifiers 0 (vfe/vfe.cpp; src/animate/frame_plan.cpp plans the same).
AnimationClock still_at(double clock) {
    AnimationClock still;
    still.clock = static_cast<float>(clock);
    still.clock_on = true;
    return still;
}

/// A Mirage_ setting the scene declares (the first by name), with its place, for the message
/// of a scene that never includes mirage.inc.
std::string first_setting(const Scene& scene) {
    for (const auto& [name, d] : scene.symbols)
        if (name.rfind("Mirage_", 0) == 0) return name + " at " + to_string(d.loc);
    return "";
}

/// A scene that never includes mirage.inc, refused as `check` asks.
Status check_mirage_inc(const Scene& scene, const MirageSettings& settings, MirageIncCheck check) {
    if (check == MirageIncCheck::None || includes_mirage_inc(scene)) return Ok{};
    const std::string add =
        "add #include \"mirage.inc\" after its #version line (plain POV-Ray finds it with "
        "+Lpov_includes)";
    if (settings.declared) {
        const std::string setting = first_setting(scene);
        return make_error(scene.file +
                          ": the scene never includes mirage.inc, so POV-Ray renders it without "
                          "the atmosphere it declares" +
                          (setting.empty() ? "" : " (" + setting + ")") + ": " + add);
    }
    if (check == MirageIncCheck::IfDeclared) return Ok{};
    return make_error(scene.file +
                      ": the scene never includes mirage.inc and declares no atmosphere: there is "
                      "nothing to compile; " +
                      add +
                      ", after a Mirage_ setting such as #declare Mirage_Preset = "
                      "\"hot-road\"; (pov_includes/mirage.inc lists them)");
}

}  // namespace

SceneLoadOptions scene_load_options(const SceneInput& input) {
    SceneLoadOptions o;
    o.input() = input;
    return o;
}

SceneLoadOptions scene_load_options(const std::string& scene, int width, int height,
                                    const std::vector<std::string>& library_paths) {
    return scene_load_options(SceneInput{scene, width, height, library_paths});
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

Result<MirageSettings> settle_mirage_scene(const Scene& scene, const SceneLoadOptions& options) {
    auto settings = read_atmosphere_settings(scene);
    if (!settings) return settings.error();
    if (options.tolerance_px) settings->tolerance_px = *options.tolerance_px;
    if (options.layers) settings->layers = *options.layers;
    if (options.layer_count) settings->layer_count = *options.layer_count;
    if (options.wavelength_nm) {
        // One channel of a colour render: the air at that wavelength, one colour throughout.
        if (auto s = set_wavelength(*settings, *options.wavelength_nm,
                                    options.scene + ": the wavelength " +
                                        shortest(*options.wavelength_nm) + " nm");
            !s)
            return s.error();
        settings->channel_wavelengths_nm.reset();
    }
    // The camera: within reach, its rays defined, its pixels no finer than paths can follow.
    const Camera& camera = scene.camera;
    const std::string at = place_prefix(camera.loc, scene.file);
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
    po.animation = options.clock ? std::optional(still_at(*options.clock)) : options.animation;
    po.declares = options.declares;
    auto parsed = parse_scene_file(options.scene, po);
    if (!parsed) return parsed.error();
    std::error_code ec;
    if (std::filesystem::file_size(options.scene, ec) == 0 && !ec)
        return make_error(options.scene + ": the file is empty: there is no scene to read");
    loaded.scene = std::move(*parsed);
    // Without a camera POV-Ray renders from its default one, at the origin: on the ground.
    if (!loaded.scene.has_camera)
        return make_error(options.scene +
                          ": the scene has no camera: POV-Ray would render it from its default "
                          "camera at the origin, on the ground; add one, such as camera { "
                          "location <0, 1.7, -10> look_at <0, 1.7, 0> }");
    auto settings = settle_mirage_scene(loaded.scene, options);
    if (!settings) return settings.error();
    if (auto s = check_mirage_inc(loaded.scene, *settings, options.mirage_inc); !s)
        return s.error();
    loaded.settings = std::move(*settings);
    // A sounding is an input of the scene: listed with its files, so no output replaces it.
    for (const std::string& f : loaded.settings.input_files) loaded.scene.files.push_back(f);
    return loaded;
}

bool includes_mirage_inc(const Scene& scene) {
    for (std::size_t i = 1; i < scene.files.size(); ++i)
        if (std::filesystem::path(scene.files[i]).filename() == "mirage.inc") return true;
    return false;
}

Status check_camera_above_ground(const Scene& scene, double ground_height,
                                 const std::function<std::optional<double>()>& lowest_object_y) {
    if (scene.camera.location.y - ground_height > 0.0) return Ok{};
    return make_error(camera_below_ground_message(scene, ground_height, lowest_object_y()));
}

Result<std::pair<std::string, double>> parse_declare(const std::string& text) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos)
        return make_error(text + ": give NAME=VALUE, as POV-Ray's Declare=NAME=VALUE");
    const std::string name = text.substr(0, eq), value = text.substr(eq + 1);
    const bool identifier =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
        std::all_of(name.begin(), name.end(),
                    [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (!identifier)
        return make_error(text + ": '" + name +
                          "' is not a name POV-Ray can declare (letters, digits and '_', not "
                          "beginning with a digit)");
    if (is_reserved_word(name))
        return make_error(text + ": '" + name + "' is a word of POV-Ray's language");
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || std::isspace(static_cast<unsigned char>(value[0])) ||
        end != value.c_str() + value.size() || !std::isfinite(v))
        return make_error(text + ": '" + value +
                          "' is not a number (POV-Ray 3.7's Declare= takes numbers only)");
    return std::pair{name, v};
}

}  // namespace mirage
