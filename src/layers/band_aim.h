// Aiming camera rays through horizontal layers: the direction, from the eye, whose band path
// goes where an exact path goes.
//
// In a stack of horizontal layers a camera ray stays in the vertical plane of its azimuth,
// and its path there is decided by its elevation alone: inside a layer it is straight, at a
// boundary the cosine of its elevation is multiplied by the index ratio POV-Ray refracts
// with (the vector form of Snell's law keeps the component along a horizontal boundary
// times the ratio), and where that product would pass 1 the ray is totally reflected.  So a
// band path is a closed-form walk over the layers it meets, and its height at a given
// horizontal distance, on one sheet of rays (those that turned the same number of times
// before it), is continuous and monotone in the elevation.  A corrected camera chooses for
// every pixel the elevation whose band path passes through the point where the exact ray
// ends, instead of the elevation of the exact ray, whose band path may skim along a layer
// without bound (docs/band_designs.md).
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "layers/revolution.h"

namespace mirage {

/// A horizontal stack (a stack of revolution with one radial node) as the 2D walks of camera
/// rays from its eye, with POV-Ray's index ratios (layers/revolution.h, pov_iors).
class BandWalk {
  public:
    explicit BandWalk(const RevolutionStack& stack);

    /// The height of the band path leaving the eye at `elevation` (rad, > 0 up) at horizontal
    /// distance r >= 0 from the eye.  Past the ground the path's last straight piece is
    /// continued below it (so that the height stays continuous in the elevation); past the
    /// top boundary it is straight.  NaN for a path cut off after max_events boundary events
    /// (one skimming along a layer) before r.
    double height_at(double elevation, double r, int max_events = 1024) const;

    /// How many times the band path leaving at `elevation` turns (totally reflects) before
    /// the horizontal distance r.
    int turns_before(double elevation, double r, int max_events = 1024) const;

    /// The elevation at the eye whose band path, once above the top boundary, rises at
    /// `final_elevation` (rad, > 0): POV-Ray's ratios carry cos(elevation) to the half-space
    /// over the layers multiplied by a fixed factor.  Nothing when no elevation does.
    std::optional<double> elevation_leaving_at(double final_elevation) const;

    double eye_y() const { return eye_y_; }

  private:
    double eye_y_ = 0.0;
    int k_cam_ = 0;
    std::vector<double> bottom_, top_;  // per layer, bottom 0 and top +inf at the ends
    // Per layer, the factor POV-Ray's ratios multiply the camera layer's cos(elevation) by
    // there, reached from the camera's layer through the layers between.
    std::vector<double> cos_factor_;
    // Per layer, POV-Ray's ratio into the layer below and into the one above (1 where it
    // passes freely): a path multiplies its cosine by each as it crosses, as POV-Ray does
    // (float quotients are not reciprocal: after a turn the way back differs in the last
    // bits).
    std::vector<double> ratio_down_, ratio_up_;
    struct Walk {
        double height = 0.0;
        int turns = 0;
        bool cut_off = false;
    };
    Walk walk(double elevation, double r, int max_events) const;
};

/// The elevation nearest `guess` (rad) whose band path passes through (r, y): r the
/// horizontal distance from the eye, y the height; `step` (rad, > 0) is the scale of the
/// search (a pixel's angle).  Searches outward from the guess for the nearest change of sign
/// of the height difference across which the height is continuous, to `tolerance_m` in
/// height.  Nothing when none lies within max_offset (rad) of the guess.
std::optional<double> elevation_through(const BandWalk& walk, double r, double y, double guess,
                                        double step, double tolerance_m, double max_offset);

/// The unit direction at `elevation` (rad, > 0 up) in the vertical plane of `d`, whose
/// horizontal part must not vanish: the one degree of freedom an aim through horizontal layers
/// has.
glm::dvec3 direction_at_elevation(const glm::dvec3& d, double elevation);

/// The float components a mesh camera's face carries for `direction`: the largest (index
/// `pivot`) is +-1, the others rounded to float.
struct MeshDirection {
    int pivot = 2;     // 0, 1, 2: x, y, z
    float value[3]{};  // value[pivot] is +1 or -1
};
MeshDirection mesh_direction(const glm::dvec3& direction);

/// The face that carries m, with its first vertex at the origin: its other two vertices, in
/// the order whose normal, as POV-Ray 3.7's mesh2 computes it (cross(P3 - P1, P2 - P1)),
/// points along m.  With (u, v, w) the axes in cyclic order from the pivot's successor, the
/// vertices are (0, p, -b) and (p, 0, -a) in (u, v, w), swapped when p = -1: their cross
/// product is exactly p^2 (a, b, p).
struct MeshFace {
    glm::vec3 p2{0.0f}, p3{0.0f};
};
MeshFace mesh_face(const MeshDirection& m);

/// The direction POV-Ray 3.7 traces for that face: the cross product of its float vertices in
/// double (exact), normalised, stored as float32 (mesh2's normal), normalised again in double.
glm::dvec3 mesh_camera_direction(const glm::dvec3& direction);

}  // namespace mirage
