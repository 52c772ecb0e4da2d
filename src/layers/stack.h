// A stack of horizontal layers of constant refractive index (the band model), and the 2D
// trace of a ray through it: straight inside a layer, Snell's law or total internal
// reflection at each boundary, via the invariant eta cos(elevation).
#pragma once

#include <vector>

#include "atmosphere/profile.h"

namespace mirage {

/// Horizontal layers over the ground.  Layer k spans (heights[k-1], heights[k]) with
/// heights[-1] = 0 (the ground) and heights[N] = +infinity.  Indices are held as the excess
/// eta^2 - eta0^2 of the profile, which keeps the tiny index steps of real air exact.
struct LayerStack {
    Profile profile;              // eta0 of `excess`; the profile the stack approximates
    std::vector<double> heights;  // N boundary heights, strictly ascending, > 0, m
    std::vector<double> excess;   // N + 1 layer values of eta^2 - eta0^2
    // Layers POV-Ray sees as its atmosphere (index 1 relative to the camera's layer) besides
    // the camera's own: the gaps of the gap layout (see pov/emit_layers.h).  Empty: none.
    std::vector<char> air;

    int boundaries() const { return static_cast<int>(heights.size()); }
    /// The layer containing height y (a height on a boundary belongs to the layer above).
    int layer_at(double y) const;
    /// Absolute index of layer k.
    double index(int k) const;
};

/// True when heights ascend strictly, are positive and finite, and excess has N + 1 values.
bool well_formed(const LayerStack& stack);

/// The ior POV-Ray holds for layer k: its index over the camera layer's, in single precision
/// (POV-Ray 3.7 keeps Interior::IOR as a float).
float pov_relative_ior(const LayerStack& stack, int k_cam, int k);

/// The stack with every boundary between two layers of the same float ior removed: POV-Ray's
/// ratio there is exactly 1 and it passes the boundary without bending, as a free continued
/// ray that still costs a recursive call (deep chains of them overflow its render threads'
/// stacks).  Each run of such layers becomes one, with the index of the one nearest the
/// camera (the camera's own in its run).
LayerStack merge_invisible_boundaries(const LayerStack& stack, double camera_y);

/// The stack as POV-Ray renders it in the gap layout: every boundary that does not touch the
/// camera's layer becomes a gap of thickness `gap` filled with the camera layer's index (POV-
/// Ray's atmosphere), so that every refraction divides by POV-Ray's double-precision
/// atmosphere index instead of one single-precision ior by another.
LayerStack with_gaps(const LayerStack& stack, double camera_y, double gap);

/// What a ray does: where it ends inside the scene, and where it goes after.
struct BandOutcome {
    bool ground = false;       // reached the ground inside the scene (before scene_dz)
    double dz = 0.0;           // horizontal distance of the end point in the scene, m
    double y = 0.0;            // height of the end point, m
    double slope = 0.0;        // dy/dz where it leaves the scene (0 on the ground)
    bool sky = false;          // after the scene it rises for good, never reaching the ground
    double final_slope = 0.0;  // dy/dz in the end, for a ray that goes to the sky
    int crossings = 0;         // boundary events (refractions and reflections) in the layers
    bool cut_off = false;      // stopped after max_events (a ray skimming along a layer)
};

/// Traces the ray leaving height y0 at `elevation` (rad, > 0 up).  The scene ends at the
/// horizontal distance scene_dz; the layers reach to layers_dz >= scene_dz, beyond which the
/// ray is straight.
BandOutcome trace_band(const LayerStack& stack, double y0, double elevation, double scene_dz,
                       double layers_dz, int max_events = 100000);

}  // namespace mirage
