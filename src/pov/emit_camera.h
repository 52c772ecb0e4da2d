// Writing a corrected camera for POV-Ray 3.7: a `mesh_camera` whose faces give every pixel
// (and, antialiased, every sample of it) its own direction from the eye, and the scene that
// renders the template through it.
//
// The recipe (POV-Ray 3.7.0.10's mesh camera, measured and read in its source): distribution
// 0, face y * W + x for pixel (x, y), one mesh per sample averaged by POV-Ray; a face's ray
// starts at its centroid and leaves along its flat normal.  Each face has the origin as its
// first vertex and carries its direction's float components with the largest one +-1
// (layers/band_aim.h, mesh_face), so that the normal POV-Ray computes is exactly the intended
// direction before it is stored as a float; the mesh is scaled by 2^-40 and moved to the eye,
// which puts every ray's origin within about 1e-12 of it.  POV-Ray 3.7 gives image row r the
// faces of row max(r - 1, 0) (rows 0 and 1 alike, fixed only in 3.8): the scene is rendered
// one row taller and the top row dropped (crop_mesh_camera_render).
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "util/result.h"

namespace mirage {

struct MeshCameraSettings {
    int width = 0, height = 0;  // the image, pixels
    glm::dvec3 eye{0.0};        // where every ray starts, POV-Ray's coordinates
    // One mesh per sample of a pixel: its width x height directions, row-major from the top
    // row (unit; carried to float precision as mesh_camera_direction says).
    std::vector<std::vector<glm::dvec3>> samples;
    std::vector<std::string> header;  // comment lines at the top
};

/// The text of mirage_camera.inc: the meshes and `#declare Mirage_Camera = camera {...}`.
std::string mesh_camera_include(const MeshCameraSettings& settings);

/// The paths must be ones POV-Ray can take (pov/povray_path.h, check_povray_path).
struct RenderSceneSettings {
    std::string scene;                // the template, absolute
    std::string camera_include;       // file name of the mesh camera's include (found on the path)
    int width = 0, height = 0;        // the image the camera was solved for
    std::string settings_check;       // SDL run after the template (pov/emit_stamp.h)
    std::vector<std::string> header;  // comment lines at the top
};

/// The text of the scene POV-Ray renders: the template, then its camera replaced by
/// Mirage_Camera.  It stops POV-Ray with an #error when the template never includes
/// mirage.inc or when the render's size is not the one the camera was solved for (that size
/// with the extra top row).
std::string render_scene(const RenderSceneSettings& settings);

/// Drops the top row of a PNG POV-Ray rendered through a mesh camera (see above), in place,
/// through a temporary name.
Status crop_mesh_camera_render(const std::string& png);

}  // namespace mirage
