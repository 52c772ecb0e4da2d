// POV-Ray 3.7's perspective camera ray for an image position (render/tracepixel.cpp,
// CreateCameraRay).  The tracer's own copy until the scene module's camera_ray lands; the
// renderer takes the function as a parameter, so switching is a one-line change.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace mirage {

struct PixelRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};  // unit
};

/// The camera ray through image position (x, y), in pixels from the top-left corner of the
/// image: pixel (i, j) spans [i, i + 1] x [j, j + 1] and its centre is (i + 0.5, j + 0.5).
/// direction = normalize(camera.direction + x0 right + y0 up) with x0 = x / width - 0.5 and
/// y0 = 0.5 - y / height, computed in POV-Ray's order of operations, so a pixel centre gives
/// the very bits POV-Ray gives.
PixelRay pov_pixel_ray(const Camera& camera, double x, double y, int width, int height);

}  // namespace mirage
