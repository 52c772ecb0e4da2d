// Graded layers: boundaries of revolution about the eye's vertical axis that are the level
// sets of
//
//     n_eff(r, y) = eta(y) h(tau(r, y)),
//
// tau the optical path length from the eye along the exact camera ray through (r, y) and h
// a function rising from 1 and levelling off at 1 + grading.
//
// Why: rays from one point of a medium n_eff are the same curves for every n_eff = eta(y)
// Psi'(tau) (the eikonal: their wavefronts are the level sets of tau, and only the spacing
// of the wavefronts changes), so in the limit of fine levels these layers bend every camera
// ray exactly as the atmosphere does.  Horizontal layers (h = 1) bend rays exactly too, but a
// ray parallel to a layer never meets its boundaries: the skim of rays near their turning
// point, the cause of slices in a band render.  With h rising along the rays, n_eff grows
// along every ray even where it runs level, so every ray keeps crossing boundaries at a
// bounded spacing: no skim.  Where two sheets of camera rays cross (after the fold of the
// inverted image), one medium can bend both only if it is physical there; h levels off
// before, and the layers become horizontal.
#pragma once

#include <vector>

#include "atmosphere/profile.h"
#include "layers/revolution.h"
#include "util/result.h"

namespace mirage {

struct GradedSettings {
    double grading = 0.0;       // h rises from 1 to 1 + grading (0: horizontal layers)
    double saturation = 1.0;    // optical path (m from the eye) at which h levels off
    double softness = 0.2;      // share of `saturation` over which h eases into its maximum
    int radial_nodes = 800;     // nodes of every boundary, geometric in r up to the reach
    int family_rays = 4000;     // exact rays spanning the camera's elevations for tau
    int column_samples = 4000;  // heights per node at which n_eff is evaluated
};

/// h at optical path tau >= 0: 1 + grading min(tau / saturation, 1), the corner eased over
/// softness * saturation on either side so that h' is continuous.
double grading_factor(const GradedSettings& settings, double tau);

/// The level sets of n_eff at `levels` (ascending) as boundaries of revolution from the axis
/// out to `reach`, for the camera rays from the eye at eye_y with elevations in
/// [elevation_lo, elevation_hi] (rad); the layer between two levels gets the index at their
/// middle.  n_eff is evaluated up to `top` (m) and, above it and in the shadows no camera ray
/// reaches, continued from the nearest height a camera ray reaches.
Result<RevolutionStack> graded_stack(const Profile& profile, double eye_y, double elevation_lo,
                                     double elevation_hi, double reach, double top,
                                     const GradedSettings& settings,
                                     const std::vector<double>& levels);

/// The range of n_eff over r in [0, reach], y in [0, top], for choosing levels.
struct IndexRange {
    double lo = 0.0, hi = 0.0;
};
IndexRange graded_index_range(const Profile& profile, double eye_y, double top,
                              const GradedSettings& settings);

}  // namespace mirage
