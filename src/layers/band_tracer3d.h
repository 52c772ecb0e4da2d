// An independent check of a layer design: traces 3D rays through the layers as POV-Ray will
// see them (horizontal planes, each index relative to the camera's layer, the vector form
// of Snell's law with total internal reflection), without the invariant the fit uses.
#pragma once

#include <glm/vec3.hpp>

#include "layers/stack.h"

namespace mirage {

/// A horizontal box around the scene: the atmosphere's layers span it.
struct HorizontalBox {
    double x0 = -1.0, x1 = 1.0, z0 = -1.0, z1 = 1.0;
    bool contains(double x, double z) const { return x >= x0 && x <= x1 && z >= z0 && z <= z1; }
};

/// Distance along the horizontal direction (hx, hz) (unit) from (x, z) to the box's edge.
double distance_to_box_edge(const HorizontalBox& box, double x, double z, double hx, double hz);

struct Trace3dOutcome {
    bool ground = false;       // hit the ground inside the scene box
    glm::dvec3 scene_point{0.0};  // ground hit, or where it leaves the scene box
    glm::dvec3 scene_dir{0.0};    // direction there
    bool sky = false;          // leaves the layers for good going up
    glm::dvec3 final_dir{0.0};    // its direction then
    int crossings = 0;         // boundary events inside the layers
    bool cut_off = false;
};

/// Traces from `origin` along `dir` (unit).  The scene ends at `scene`; the layers span
/// `layers` (which contains `scene`); outside them the ray is straight.
Trace3dOutcome trace_layers_3d(const LayerStack& stack, const glm::dvec3& origin,
                               const glm::dvec3& dir, const HorizontalBox& scene,
                               const HorizontalBox& layers, int max_events = 100000);

}  // namespace mirage
