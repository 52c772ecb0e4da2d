// What every pixel of a band render shows, against the exact model: each pixel centre's ray
// followed through the layers as POV-Ray follows it and along its exact path, each to the
// surface it meets and on through the reflections both make.  Two measures per pixel: the
// angle between where the two rays end, seen from the eye, and how many rows away the exact
// image shows what the band ray ends on (in a mirage the exact image is stretched, so a
// small angle can be many rows).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "atmosphere/exact_path.h"
#include "atmosphere/phase_screens.h"
#include "layers/band_tracer3d.h"
#include "layers/stack.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "trace/scene_accel.h"

namespace mirage {


/// Where an exact camera ray ends: on a surface (hit) or leaving in `direction`.
struct ExactEnd {
    bool hit = false;
    glm::dvec3 point{0.0};
    glm::dvec3 direction{0.0};
};

/// A corrected camera: the band directions to try for ray `i`, whose exact ray leaves along
/// `exact_direction`.  The check follows each through the layers and keeps the one whose
/// end lies nearest the exact end (the camera ray's first, then its reflections').
struct BandAim {
    /// The first directions to try, given where the exact ray ends, the likeliest first (the
    /// check stops at one that ends within a hundredth of a pixel of the exact end).
    std::function<void(size_t i, const glm::dvec3& exact_direction, const ExactEnd& end,
                       std::vector<glm::dvec3>& candidates)>
        candidates;
    /// The direction whose band path passes where the exact path is at horizontal distance
    /// r from the eye: tried when the best so far meets something at r that the exact ray
    /// passes by (a band path a little off the exact one near an object's edge).
    std::function<std::optional<glm::dvec3>(size_t i, const glm::dvec3& exact_direction, double r)>
        through;
    explicit operator bool() const { return static_cast<bool>(candidates); }
};

struct PixelCheckSettings {
    int width = 0, height = 0;  // the image; rays are row-major from the top row
    glm::dvec3 eye{0.0};        // where every camera ray starts
    double camera_y = 0.0;      // the camera's height, for POV-Ray's ior quotients
    HorizontalBox layers{};     // horizontal extent of the rendered layers
    // Of those below the camera's layer, when they reach farther (Trace3dOptions::below).
    std::optional<HorizontalBox> layers_below = std::nullopt;
    double exact_tolerance_rad = 1e-5;  // sampling tolerance of the exact paths
    int max_bounces = 4;                // reflections followed, while their weight shows
    bool progress = false;              // a progress bar on stderr (on a terminal)
    // The atmosphere the exact rays follow, as the tracer's do (CurvedSettings::atmosphere,
    // ::max_dz).
    Atmosphere atmosphere;
    double max_dz = 0.0;
    // Turbulent air: the exact rays walked through these screens at that time, as the
    // tracer's are (CurvedSettings::turbulence); unit_m metres per scene unit.
    std::shared_ptr<const PhaseScreens> turbulence;
    double turbulence_time_s = 0.0;
    double unit_m = 1.0;
    // A camera whose rays start at different points: ray i leaves (*origins)[i] (not `eye`),
    // `camera_y` is the height of the layer POV-Ray's atmosphere stands for, and the errors are
    // distances across the rays in the camera's unit of a pixel, footprint.distance +
    // footprint.angle_rad * (path length from the ray's origin), with the exact paths sampled
    // to a twentieth of it (exact_tolerance_rad is then not used).  A ray that leaves the scene
    // is taken at `far` along its final direction from its origin.
    const std::vector<glm::dvec3>* origins = nullptr;
    PixelFootprint footprint;
    double far = 0.0;
    // A corrected camera (one eye only): every band ray leaves along the best of the
    // directions `aim` offers, instead of along the exact ray's direction.
    BandAim aim;
};

struct PixelCheck {
    // Angle between the band ray's end and the exact ray's, seen from the eye, in pixels;
    // the larger of the camera ray's and its reflections' (a reflection's angle at the mirror
    // shrunk by the distances, as seen from the eye).  +inf where a band ray was cut off.
    std::vector<float> seen_error_px;
    // Rows between the pixel and the nearest one in its column whose exact ray ends on what
    // the band ray ends on (within the exact rays' spacing there); +inf when no row of the
    // column shows it: the band render shows something the exact image does not.
    std::vector<float> shift_rows;
    // The reflections' part of seen_error_px (0 without reflections), pixels.
    std::vector<float> reflection_error_px;
    // With an aim: the direction each band ray left along (one of the aim's candidates).
    std::vector<glm::dvec3> band_direction;
    // With an aim: the camera ray's part of seen_error_px, pixels.
    std::vector<float> camera_error_px;
    // With an aim, along each chosen band ray: the boundaries it crosses, POV-Ray's trace
    // level with its reflections, and the horizontal distance from the eye to its last
    // crossing (0 where cut off).
    std::vector<int> crossings, trace_level;
    std::vector<double> last_event;
};

/// Checks every ray of a width x height grid (with settings.origins, from their own origins:
/// the angles below are then distances across the rays, in the camera's pixels, and
/// `pixel_rad` is not read) (pixel centres, or sub-pixel samples):
/// `directions[i]` and `pixel_rad[i]` (the angle of one pixel at ray i), `cut_off[i]` for
/// rays known to be cut off (a band ray the tracer cuts off is found so anyway).
/// `objects` stops band rays at the scene's surfaces (as POV-Ray does); `accel` holds the
/// same surfaces for the exact rays.  Runs on all cores; the result does not depend on how
/// many.
PixelCheck check_pixels(const LayerStack& rendered, const Scene& scene,
                        const SceneAccel& accel, const ObjectQuery& objects,
                        const std::vector<glm::dvec3>& directions,
                        const std::vector<double>& pixel_rad, const std::vector<bool>& cut_off,
                        const PixelCheckSettings& settings);

}  // namespace mirage
