// The parser of POV-Ray 3.7's scene language, shared by every mirage command: reads a .pov
// file (with its #include files, macros, loops and declarations) into a Scene.
//
// Supported: the whole directive language (#declare, #local, #undef, #include, #if,
// #ifdef, #ifndef, #elseif, #else, #switch, #case, #range, #break, #while, #for, #macro,
// #version, #debug, #warning, #error, #default), float, vector, colour and string
// expressions with POV-Ray's functions, arrays, and the scene subset mirage renders:
// perspective camera, point lights, background, sky_sphere, global_settings (assumed_gamma,
// max_trace_level, ambient_light), sphere, plane, box, cylinder, disc, union and object with
// transforms, textures (solid, checker and gradient pigments with color_map; finish).
// Anything else is an error naming it in strict mode and is skipped and recorded in
// Scene::skipped in lenient mode.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/animation_clock.h"
#include "scene/object_queries.h"
#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

/// What one parse may take at most.  Past a limit the parse ends with an error naming the
/// place and the limit: a hostile or broken scene never crashes the parser, hangs it or fills
/// the memory (docs/robustness.md gives the reasons for the numbers).
struct ParseLimits {
    std::uintmax_t max_source_bytes = 16u << 20;  // the scene and its include files, bytes
    int max_nesting = 256;  // parentheses, objects, directives, conditionals inside each other
    std::int64_t max_loop_passes = 1'000'000;    // passes of all #while and #for loops together
    std::int64_t max_tokens = 100'000'000;       // tokens read, each time they are read
    std::size_t max_array_elements = 1'000'000;  // elements of one array
    std::size_t max_total_array_elements = 20'000'000;  // array elements made or copied in all
    std::size_t max_objects = 1'000'000;                // objects parsed or copied in all
    std::size_t max_string_bytes = 1u << 20;            // one string value, bytes
};

struct ParseOptions {
    std::vector<std::string>
        library_paths;  // searched after the including file's directory, like +L
    std::map<std::string, double> declares;     // Declare=NAME=VALUE from the command line or .ini
    int image_width = 320, image_height = 240;  // for the image_width / image_height identifiers
    // clock, clock_on, frame_number, ...: this frame's; unset, the thread's (a still unless a
    // ScopedAnimationClock is in force: scene/animation_clock.h).
    std::optional<AnimationClock> animation;
    // strict: anything outside the supported subset is an error naming it and its place.
    // lenient: unknown object kinds (and unsupported modifiers inside objects) are skipped
    // (brace-matched) and recorded in Scene::skipped; camera, lights, declarations still parsed.
    bool strict = true;
    ParseLimits limits;
    // trace(), inside(), min_extent(), max_extent(): answered by the tracer
    // (tracer_object_queries() of trace/object_query.h); unset, a scene using them is refused.
    ObjectQueries object_queries;
};

/// Parses the scene file at `path` (shown in messages as given).  The file must be a regular
/// file (with its includes at most ParseLimits::max_source_bytes); a directory, a device or a pipe
/// is refused with a message saying so.
Result<Scene> parse_scene_file(const std::string& path, const ParseOptions& options);

/// Parses scene text; `name` is the file name shown in messages, and its directory is where
/// #include looks first.
Result<Scene> parse_scene_text(std::string_view text, const std::string& name,
                               const ParseOptions& options);

}  // namespace mirage
