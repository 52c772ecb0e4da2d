// An independent check of a layer design: traces 3D rays through the layers as POV-Ray will
// see them (horizontal planes, each index relative to the camera's layer, the vector form
// of Snell's law with total internal reflection), without the invariant the fit uses.
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <limits>
#include <optional>

#include "layers/stack.h"

namespace mirage {

/// A horizontal box around the scene: the atmosphere's layers span it.
struct HorizontalBox {
    double x0 = -1.0, x1 = 1.0, z0 = -1.0, z1 = 1.0;
    bool contains(double x, double z) const { return x >= x0 && x <= x1 && z >= z0 && z <= z1; }
};

/// Distance along the horizontal direction (hx, hz) (unit) from (x, z) to the box's edge.
double distance_to_box_edge(const HorizontalBox& box, double x, double z, double hx, double hz);

/// An opaque object met along a straight piece of the path.
struct ObjectHit {
    double t = 0.0;          // distance along the (unit) direction
    glm::dvec3 normal{0.0};  // surface normal there
    int id = -1;             // which object
};

/// Finds the closest object hit within (0, t_max] along origin + t direction.
using ObjectQuery = std::function<std::optional<ObjectHit>(const glm::dvec3& origin,
                                                           const glm::dvec3& dir, double t_max)>;

struct Trace3dOutcome {
    bool ground = false;          // hit the ground inside the scene box
    glm::dvec3 scene_point{0.0};  // ground hit, or where it leaves the scene box
    glm::dvec3 scene_dir{0.0};    // direction there
    bool sky = false;             // leaves the layers for good going up
    glm::dvec3 final_dir{0.0};    // its direction then
    int crossings = 0;            // boundary events inside the layers
    double last_event = 0.0;      // horizontal distance from the origin of the last event
    bool cut_off = false;
    std::optional<ObjectHit> object;  // the object that stopped the ray, if any
    glm::dvec3 object_point{0.0};     // where
    glm::dvec3 object_dir{0.0};       // the ray's direction there
};

/// Traces from `origin` along `dir` (unit).  The scene ends at `scene`; the layers span
/// `layers` (which contains `scene`; those below the camera's layer options.below, if given);
/// outside them the ray is straight, and meets the objects there as POV-Ray's ray does.
struct Trace3dOptions {
    int max_events = 100000;
    const ObjectQuery* objects = nullptr;  // stops the ray at the first opaque object
    double camera_y = std::numeric_limits<double>::quiet_NaN();  // NaN: the ray starts there
    bool pov_precision = true;  // POV-Ray's single-precision iors; false: exact indices
    // How far the boundaries below the camera's layer reach, when farther than `layers` (which
    // then bounds the camera's ceiling and the boundaries above it); outside a boundary's box
    // a ray is in POV-Ray's atmosphere, the camera's layer.
    std::optional<HorizontalBox> below = std::nullopt;
};

/// A ray may start on the ground (y = 0, going up) or anywhere above it; the camera's layer
/// (at camera_y) is POV-Ray's atmosphere.
Trace3dOutcome trace_layers_3d(const LayerStack& stack, const glm::dvec3& origin,
                               const glm::dvec3& dir, const HorizontalBox& scene,
                               const HorizontalBox& layers, const Trace3dOptions& options = {});

/// The layer of the camera (POV-Ray's atmosphere, outside every plane).
int pov_camera_layer(const LayerStack& stack, double y, double camera_y);

/// The ior POV-Ray holds for layer k's plane: its index over the camera layer's, in single
/// precision (POV-Ray 3.7 keeps Interior::IOR as a float).
float pov_ior(const LayerStack& stack, int k_cam, int k);

/// The index ratio POV-Ray refracts with from layer `from` into layer `to`.
double pov_ior_ratio(const LayerStack& stack, int k_cam, int from, int to);

}  // namespace mirage
