#include "trace/pixel_ray.h"

namespace mirage {

PixelRay pov_pixel_ray(const Camera& camera, double x, double y, int width, int height) {
    const double w = width;
    const double h = height;
    // POV-Ray is handed the pixel's integer row j and computes ((h - 1) - (j - 0.5)) / h - 0.5;
    // y - 1 = j - 0.5 exactly for a pixel centre, so the same expression gives the same bits.
    const double x0 = x / w - 0.5;
    const double y0 = ((h - 1.0) - (y - 1.0)) / h - 0.5;
    glm::dvec3 d;
    for (int i = 0; i < 3; ++i) {
        d[i] = 1.0 * camera.direction[i] + x0 * camera.right[i] + y0 * camera.up[i];
    }
    PixelRay ray;
    ray.origin = camera.location;
    ray.direction = d * (1.0 / glm::length(d));
    return ray;
}

}  // namespace mirage
