// Loading a mirage scene: the floor beneath every command that reads one (compile, trace and
// compare).  The image size, the include paths, the parse, the Mirage_ settings, the
// tolerance and the camera's place are checked here, each once and with one message.
//
// The modules of src/, lowest first; each includes only from those before it (checked by
// tests/layout/module_order_test.cpp):
//   util, atmosphere, scene, load, image, layers, pov, report, trace, compile, trace_scene,
//   compare, animate, frame, cli
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "load/atmosphere_settings.h"
#include "scene/parser.h"
#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

/// The largest image side, pixels.
constexpr int kMaxImageSide = 20000;
/// The smallest angle one pixel may span at the image centre, rad: a tolerance of
/// kMinTolerancePx then stays above the finest angle paths are sampled to
/// (atmosphere/sampler.h, kMinToleranceRad).
constexpr double kMinPixelRad = 1e-7;

struct SceneLoadOptions {
    std::string scene;                        // the .pov file
    int width = 320, height = 240;            // the render's size, pixels
    std::vector<std::string> library_paths;   // the user's include directories, searched first
    bool strict = true;                       // every object must be supported (false: skip others)
    std::optional<double> tolerance_px;       // --tolerance: replaces Mirage_Tolerance
    std::optional<LayerMode> layers;          // --layers: replaces Mirage_Layers
    std::optional<int> layer_count;           // --count: replaces Mirage_Layer_Count
    std::optional<AnimationClock> animation;  // this frame's clock (unset: the thread's)
    ParseLimits limits;
    ObjectQueries object_queries;  // trace() and the like (ParseOptions::object_queries)
};

/// A scene with its atmosphere, ready for a command.
struct MirageScene {
    Scene scene;
    AtmosphereSettings settings;  // the scene's Mirage_ settings with the options' replacements
    ParseOptions parse_options;   // as the scene was parsed: every include directory in order
};

/// The options for `scene` rendered at width x height, the user's include directories
/// searched first; the rest as SceneLoadOptions has them.
SceneLoadOptions scene_load_options(const std::string& scene, int width, int height,
                                    const std::vector<std::string>& library_paths);

/// Checks an image size: 1 to kMaxImageSide pixels each way.
Status check_image_size(int width, int height);

/// Checks the user's include directories (-L): each must be a directory.
Status check_library_paths(const std::vector<std::string>& paths);

/// Reads the scene file: checks the size, parses with the user's include directories, then
/// the scene's own directory, the project's pov_includes and POV-Ray's, reads and checks the
/// Mirage_ settings, applies the options' replacements and checks the camera.  An error
/// names the file (and its line and column) or the option at fault.
Result<MirageScene> load_mirage_scene(const SceneLoadOptions& options);

/// What load_mirage_scene checks after the parse, for a scene parsed already: the Mirage_
/// settings with the options' replacements, and the camera's place.
Result<AtmosphereSettings> settle_mirage_scene(const Scene& scene, const SceneLoadOptions& options);

}  // namespace mirage
