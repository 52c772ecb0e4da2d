// Stage "camera" of mirage compile (compile/stages.h): the corrected camera, every band ray
// aimed through the point where its exact ray ends (layers/band_aim.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "compile/stages.h"
#include "layers/band_aim.h"
#include "layers/outcome.h"
#include "layers/revolution.h"

namespace mirage {

BandAim corrected_camera_aim(const CompileContext& ctx, const LayerStack& rendered,
                             const CameraRays& rays) {
    auto walk = std::make_shared<const BandWalk>(revolution_of(rendered, ctx.eye_y));
    const glm::dvec3 eye = ctx.camera.location;
    // The direction in d's vertical plane whose band path passes through (r, y), if any near
    // ray i's own elevation.
    auto through = [&rays, walk](size_t i, const glm::dvec3& d, double r,
                                 double y) -> std::optional<glm::dvec3> {
        const double hl = std::hypot(d.x, d.z);
        if (!(hl > 0.0) || !(r > 0.0) || !std::isfinite(y)) return std::nullopt;
        const double pixel = rays.pixel_rad[i];
        // A thousandth of a pixel, as a height at r.
        const double tolerance = std::max(1e-3 * pixel * r, 1e-12 * (1.0 + std::fabs(y)));
        const auto e = elevation_through(*walk, r, y, rays.elevation[i], pixel, tolerance,
                                         std::min(0.5, 2000.0 * pixel));
        if (!e) return std::nullopt;
        const glm::dvec3 aimed(std::cos(*e) * d.x / hl, std::sin(*e), std::cos(*e) * d.z / hl);
        return mesh_camera_direction(aimed);
    };
    // The exact path's height at horizontal distance r (NaN past its ground).
    auto exact_height = [&ctx, &rays](size_t i, double r) {
        const BandOutcome o = ctx.air
                                  ? exact_outcome(*ctx.air, ctx.eye_y, rays.elevation[i], r)
                                  : exact_outcome(ctx.profile, ctx.eye_y, rays.elevation[i], r);
        return o.ground ? std::numeric_limits<double>::quiet_NaN() : o.y;
    };
    BandAim aim;
    aim.candidates = [&rays, eye, through, exact_height](size_t i, const glm::dvec3& d,
                                                         const ExactEnd& end,
                                                         std::vector<glm::dvec3>& out) {
        // As the camera has it, carried to the mesh's float precision.
        out.push_back(mesh_camera_direction(d));
        // Through where the exact ray ends: the surface it meets, or where it leaves the
        // scene for the sky (its height at the scene's edge).
        std::optional<glm::dvec3> c;
        if (end.hit) {
            c = through(i, d, std::hypot(end.point.x - eye.x, end.point.z - eye.z), end.point.y);
        } else {
            const double r = rays.exit_dz[i];
            c = through(i, d, r, exact_height(i, r));
        }
        if (c) out.push_back(*c);
    };
    aim.through = [through, exact_height](size_t i, const glm::dvec3& d, double r) {
        return through(i, d, r, exact_height(i, r));
    };
    return aim;
}

}  // namespace mirage
