// Mirage_Ground_Height: the atmosphere's ground (the profile's y = 0) where the scene has its
// floor.  Heights are converted in one place: the parsed scene is lowered by the ground height
// before the compiler or the tracer look at it, so that everything downstream keeps its ground
// at y = 0; the compiled layers are raised back when they are written (LayerEmitSettings).
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace mirage {

/// Moves every spatial part of the scene down by `height` (scene units): the camera, the
/// lights, the primitives with their patterns, the unknown objects' bounds.  Directions (the
/// sky, the background) do not move.  Nothing happens for a height of 0.
void lower_scene(Scene& scene, double height);

/// A horizontal plane of the scene (a plane with a normal along y, on its own or in a CSG).
struct HorizontalPlane {
    double height = 0.0;  // scene units, before lowering
    FileLoc loc;
};

/// The scene's horizontal planes strictly below `below_y`: the highest of them (the floor
/// under the camera) and the lowest, if it has any.
struct PlanesBelow {
    std::optional<HorizontalPlane> highest, lowest;
};
PlanesBelow horizontal_planes_below(const Scene& scene, double below_y);

/// The message for a camera that is not above the atmosphere's ground: where the camera is,
/// where the ground is, and the scene's own horizontal plane under the camera as the likely
/// ground, with the declaration that puts it there (and the lowest plane when it is another
/// one; without any, the lowest point of its objects when the caller knows it).  `scene` is
/// the scene as parsed (not lowered).
std::string camera_below_ground_message(const Scene& scene, double ground_height,
                                        std::optional<double> lowest_object_y);

}  // namespace mirage
