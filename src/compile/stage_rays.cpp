// Stage "rays" of mirage compile (compile/stages.h).
#include <algorithm>
#include <cmath>

#include "compile/stages.h"
#include "scene/camera.h"
#include "util/parallel.h"

namespace mirage {

size_t CameraRays::centre(int col, int row) const {
    const int k = per_side / 2;
    return static_cast<size_t>(row * per_side + k) * grid_width() + (col * per_side + k);
}

void CameraRays::resize(size_t n) {
    origin.resize(n);
    direction.resize(n);
    elevation.resize(n);
    exit_dz.resize(n);
    pixel_rad.resize(n);
}

CameraRays CameraRays::centres() const {
    if (per_side == 1) return *this;
    CameraRays c;
    c.width = width;
    c.height = height;
    c.per_side = 1;
    c.resize(static_cast<size_t>(width) * height);
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            const size_t i = static_cast<size_t>(row) * width + col, j = centre(col, row);
            c.origin[i] = origin[j];
            c.direction[i] = direction[j];
            c.elevation[i] = elevation[j];
            c.exit_dz[i] = exit_dz[j];
            c.pixel_rad[i] = pixel_rad[j];
        }
    return c;
}

CameraRays camera_rays(const CompileContext& ctx, int per_side) {
    CameraRays r;
    r.width = ctx.options.width;
    r.height = ctx.options.height;
    r.per_side = per_side;
    const int GW = r.grid_width(), GH = r.grid_height();
    r.resize(static_cast<size_t>(GW) * GH);
    const Camera& cam = ctx.camera;
    const int W = r.width, H = r.height;
    parallel_for(
        GH,
        [&](long gy) {
            const double y = (gy + 0.5) / per_side;
            for (int gx = 0; gx < GW; ++gx) {
                const double x = (gx + 0.5) / per_side;
                const size_t i = static_cast<size_t>(gy) * GW + gx;
                const CameraRay ray = camera_ray(cam, x, y, W, H);
                const glm::dvec3 d = ray.direction;
                // A camera with one eye point: every ray from its location exactly.
                const glm::dvec3 o = ctx.many_origins ? ray.origin : cam.location;
                r.origin[i] = o;
                r.direction[i] = d;
                r.elevation[i] = std::asin(std::clamp(d.y, -1.0, 1.0));
                const double hl = std::hypot(d.x, d.z);
                r.exit_dz[i] =
                    hl > 0.0 ? distance_to_box_edge(ctx.scene_box, o.x, o.z, d.x / hl, d.z / hl)
                             : ctx.extent;
                r.pixel_rad[i] = angle_between(camera_ray(cam, x, y - 0.5, W, H).direction,
                                               camera_ray(cam, x, y + 0.5, W, H).direction);
            }
        },
        0, 1);
    return r;
}

}  // namespace mirage
