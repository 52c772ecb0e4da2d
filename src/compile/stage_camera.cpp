// Stage "camera" of mirage compile (compile/stages.h): the corrected camera, every band ray
// aimed through the point where its exact ray ends (layers/band_aim.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "compile/stages.h"
#include "layers/band_aim.h"
#include "layers/outcome.h"
#include "layers/revolution.h"
#include "util/parallel.h"

namespace mirage {

BandAim corrected_camera_aim(const CompileContext& ctx, const LayerStack& rendered,
                             const CameraRays& rays) {
    auto walk = std::make_shared<const BandWalk>(revolution_of(rendered, ctx.eye_y));
    const glm::dvec3 eye = ctx.camera.location;
    // The direction in d's vertical plane whose band path passes through (r, y), if any near
    // ray i's own elevation.
    // Each ray's aim as an offset from its own elevation, for its right-hand neighbour's
    // search to start from (a row is aimed by one thread, left to right).
    const int grid_width = rays.grid_width();
    auto offsets = std::make_shared<std::vector<double>>(rays.size(), 0.0);
    auto through = [&rays, walk, offsets, grid_width](size_t i, const glm::dvec3& d, double r,
                                                      double y) -> std::optional<glm::dvec3> {
        const double hl = std::hypot(d.x, d.z);
        if (!(hl > 0.0) || !(r > 0.0) || !std::isfinite(y)) return std::nullopt;
        const double pixel = rays.pixel_rad[i];
        // A thousandth of a pixel, as a height at r.
        const double tolerance = std::max(1e-3 * pixel * r, 1e-12 * (1.0 + std::fabs(y)));
        const double guess = rays.elevation[i] + (i % grid_width != 0 ? (*offsets)[i - 1] : 0.0);
        auto e =
            elevation_through(*walk, r, y, guess, pixel, tolerance, std::min(0.5, 2000.0 * pixel));
        if (!e && guess != rays.elevation[i])
            e = elevation_through(*walk, r, y, rays.elevation[i], pixel, tolerance,
                                  std::min(0.5, 2000.0 * pixel));
        if (!e) return std::nullopt;
        (*offsets)[i] = *e - rays.elevation[i];
        return mesh_camera_direction(direction_at_elevation(d, *e));
    };
    // The exact path's height at horizontal distance r (NaN past its ground).
    auto exact_height = [&ctx, &rays](size_t i, double r) {
        const BandOutcome o = exact_outcome(ctx.atmosphere, ctx.eye_y, rays.elevation[i], r);
        return o.ground ? std::numeric_limits<double>::quiet_NaN() : o.y;
    };
    BandAim aim;
    // In still air an exact ray stays in its vertical plane; through turbulent air it leaves
    // it, and the band ray is aimed in the vertical plane of where the exact one ends.
    const bool turbulent = ctx.turbulence != nullptr;
    aim.candidates = [&rays, eye, walk, through, exact_height, turbulent](
                         size_t i, const glm::dvec3& camera_d, const ExactEnd& end,
                         std::vector<glm::dvec3>& out) {
        glm::dvec3 d = camera_d;
        if (turbulent) {
            const glm::dvec3 v = end.hit ? end.point - eye : end.direction;
            if (std::hypot(v.x, v.z) > 0.0) d = v;
        }
        const double hl = std::hypot(d.x, d.z);
        if (end.hit) {
            // Through the surface the exact ray meets.
            if (auto c = through(i, d, std::hypot(end.point.x - eye.x, end.point.z - eye.z),
                                 end.point.y))
                out.push_back(*c);
        } else {
            // Leaving for the sky in the exact ray's final direction: exact above the layers,
            // whatever the float iors make of the index over the top.
            // Leaving downward, a ray with the same cosine turns and leaves as the rising one
            // does: the sheet of the exact ray first.
            const double final_elevation = std::asin(std::clamp(end.direction.y, -1.0, 1.0));
            if (const auto e = walk->elevation_leaving_at(final_elevation); e && hl > 0.0)
                for (double sign :
                     rays.elevation[i] < 0.0 ? std::array{-1.0, 1.0} : std::array{1.0, -1.0})
                    out.push_back(mesh_camera_direction(direction_at_elevation(d, sign * *e)));
            // Through the exact path's point at the scene's edge.
            const double r = rays.exit_dz[i];
            if (auto c = through(i, d, r, exact_height(i, r))) out.push_back(*c);
        }
        // As the camera has it, carried to the mesh's float precision.
        out.push_back(mesh_camera_direction(camera_d));
    };
    aim.through = [through, exact_height](size_t i, const glm::dvec3& d, double r) {
        return through(i, d, r, exact_height(i, r));
    };
    return aim;
}

std::vector<std::pair<int, int>> shot_samples(int per_side, bool antialias) {
    const int c = per_side / 2;
    std::vector<std::pair<int, int>> s = {{c, c}};
    if (antialias && per_side >= 3)
        for (int dy : {0, per_side - 1})
            for (int dx : {0, per_side - 1}) s.emplace_back(dx, dy);
    return s;
}

}  // namespace mirage
