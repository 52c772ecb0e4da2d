// Loading a mirage scene: the floor beneath every command that reads one (compile, trace and
// compare).  The image size, the include paths, the parse, the Mirage_ settings, the
// tolerance and the camera's place are checked here, each once and with one message.

#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "load/atmosphere_settings.h"
#include "scene/parser.h"
#include "scene/scene.h"
#include "util/result.h"
#include "util/scene_input.h"

namespace mirage {

/// The largest image side, pixels.
constexpr int kMaxImageSide = 20000;
/// The smallest angle one pixel may span at the image centre, rad: a tolerance of
/// kMinTolerancePx then stays above the finest angle paths are sampled to
/// (atmosphere/sampler.h, kMinToleranceRad).
constexpr double kMinPixelRad = 1e-7;

/// When a scene that never includes mirage.inc is refused.  Without it POV-Ray renders no
/// mirage: the compiled layers reach POV-Ray only through it (pov_includes/mirage.inc).
enum class MirageIncCheck {
    None,        // not checked (tools that read a scene's settings only)
    IfDeclared,  // when the scene declares an atmosphere (trace: it would render a mirage
                 // that POV-Ray never shows)
    Always,      // compile: its layers have no other way into the scene
};

/// SceneInput: the scene, the render's size, the user's include directories (searched first).
struct SceneLoadOptions : SceneInput {
    bool strict = true;                       // every object must be supported (false: skip others)
    std::optional<double> tolerance_px;       // --tolerance: replaces Mirage_Tolerance
    std::optional<LayerMode> layers;          // --layers: replaces Mirage_Layers
    std::optional<int> layer_count;           // --count: replaces Mirage_Layer_Count
    std::optional<AnimationClock> animation;  // this frame's clock (unset: the thread's)
    std::optional<double> clock;              // --clock (POV-Ray's +K): a still at this clock,
                                              // in place of `animation`
    std::map<std::string, double> declares;   // --declare (POV-Ray's Declare=), defined before
                                              // the scene is parsed
    MirageIncCheck mirage_inc = MirageIncCheck::None;
    ParseLimits limits;
    ObjectQueries object_queries;  // trace() and the like (ParseOptions::object_queries)
};

/// A scene with its atmosphere, ready for a command.
struct MirageScene {
    Scene scene;
    MirageSettings settings;     // the scene's Mirage_ settings with the options' replacements
    ParseOptions parse_options;  // as the scene was parsed: every include directory in order
};

/// The options for the input's scene rendered at its size, its include directories searched
/// first; the rest as SceneLoadOptions has them.
SceneLoadOptions scene_load_options(const SceneInput& input);
SceneLoadOptions scene_load_options(const std::string& scene, int width, int height,
                                    const std::vector<std::string>& library_paths);

/// Checks an image size: 1 to kMaxImageSide pixels each way.
Status check_image_size(int width, int height);

/// Checks the user's include directories (-L): each must be a directory.
Status check_library_paths(const std::vector<std::string>& paths);

/// Reads the scene file: checks the size, parses with the user's include directories, then
/// the scene's own directory, the project's pov_includes and POV-Ray's, refuses a scene
/// without a camera, reads and checks the Mirage_ settings, applies the options'
/// replacements, checks the camera and the include of mirage.inc (SceneLoadOptions::
/// mirage_inc).  An error names the file (and its line and column) or the option at fault.
Result<MirageScene> load_mirage_scene(const SceneLoadOptions& options);

/// What load_mirage_scene checks after the parse, for a scene parsed already: the Mirage_
/// settings with the options' replacements, and the camera's place.
Result<MirageSettings> settle_mirage_scene(const Scene& scene, const SceneLoadOptions& options);

/// Whether the scene, or a file it includes, includes mirage.inc (the parser lists every file
/// it read in Scene::files).
bool includes_mirage_inc(const Scene& scene);

/// Checks that the camera is above the atmosphere's ground (y = `ground_height`, from
/// Mirage_Ground_Height), with camera_below_ground_message's message (scene/ground.h): the one
/// check of compile and trace.  `scene` as parsed (not lowered); `lowest_object_y`, asked only
/// when the camera is refused, gives the lowest point of the scene's bounded objects, as
/// parsed, if any (for a scene without a horizontal plane under the camera).
Status check_camera_above_ground(const Scene& scene, double ground_height,
                                 const std::function<std::optional<double>()>& lowest_object_y);

/// Reads `--declare NAME=VALUE` (POV-Ray's Declare=NAME=VALUE): NAME an identifier POV-Ray
/// can declare, VALUE a number (POV-Ray 3.7's Declare= takes numbers only).  An error names
/// the text and the part at fault.
Result<std::pair<std::string, double>> parse_declare(const std::string& text);

}  // namespace mirage
