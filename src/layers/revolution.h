// Boundaries of revolution about the eye's vertical axis, and the 2D trace of a camera ray
// through them.
//
// Every camera ray stays in the vertical plane through the eye that contains it, so in a
// medium symmetric about the eye's vertical axis every camera ray, in any column, at any
// sub-pixel offset and under any camera tilt, is one ray of one 2D problem: its elevation
// decides its path in the (r, y) half-plane, r the horizontal distance from the axis.
// Horizontal planes are the special case of boundaries of constant height.
//
// A boundary here is a graph y = Y(r) given at shared radial nodes, piecewise linear between
// them, with a normal interpolated linearly from the nodes' normals (the way a smooth mesh
// of revolution refracts), so that the refraction varies continuously along a boundary.
// Boundaries may run below the ground (y = 0), which ends every ray that reaches it.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "atmosphere/profile.h"
#include "layers/stack.h"

namespace mirage {

struct RevolutionStack {
    double eye_y = 0.0;                        // the eye, on the axis (r = 0)
    std::vector<double> radii;                 // radial nodes, ascending, radii[0] = 0
    std::vector<std::vector<double>> heights;  // heights[k][j]: boundary k at radii[j]
    std::vector<double> index;                 // N + 1 absolute indices, lowest layer first
    // Layers POV-Ray sees as its atmosphere besides the eye's (the gaps of the gap layout, see
    // pov/emit_layers.h); empty: none.
    std::vector<char> air;

    int boundaries() const { return static_cast<int>(heights.size()); }
    /// Height of boundary k at radius r (flat beyond the last node).
    double height(int k, double r) const;
    /// The layer containing (r, y): the number of boundaries below it there.
    int layer_at(double r, double y) const;
};

/// True when the nodes ascend from 0, every boundary has a height at every node, the
/// boundaries are ordered (strictly) at every node and there are N + 1 positive indices.
bool well_formed(const RevolutionStack& s);

/// A horizontal stack as a stack of revolution (one radial node, constant heights), its gaps
/// included.
RevolutionStack revolution_of(const LayerStack& stack, double eye_y);

/// A camera ray's path through a stack of revolution, in the (r, y) half-plane.
struct MeridianPath {
    std::vector<glm::dvec2> points;  // (r, y) from the eye: at every boundary event, and the end
    glm::dvec2 direction{1.0, 0.0};  // unit, after the last point
    int crossings = 0;               // refractions and total internal reflections
    bool ground = false;             // ended on the ground (y = 0)
    bool cut_off = false;            // stopped after max_events
    bool back = false;               // turned back towards the axis (r decreasing)
};

/// Traces the ray leaving the eye at `elevation` (rad, > 0 up) out to radius `reach`: straight
/// within a layer, Snell's law or total internal reflection at a boundary (the vector form,
/// with the boundary's interpolated normal), the ground at y = 0.  With pov_iors, each ratio
/// is taken as POV-Ray takes it between nested layers: the layers' indices over the eye
/// layer's held as floats, quotients of floats.
MeridianPath trace_meridian(const RevolutionStack& stack, double elevation, double reach,
                            int max_events = 100000, bool pov_iors = false);

/// The height of a meridian path at radius r (NaN where the path does not reach r).
double path_height(const MeridianPath& path, double r);

}  // namespace mirage
