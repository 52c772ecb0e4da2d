// Pigments evaluated as POV-Ray 3.7 evaluates them (pigment.cpp Compute_Pigment): plain
// colours, patterns through their warp chain with a colour map (POV-Ray's default maps when
// none is given), pigment maps and the colour or pigment lists of checker, brick, hexagon and
// the other list patterns, image maps; and the sky (sky_sphere layers over the background,
// trace.cpp ComputeSky).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "patterns/patterns.h"

namespace mirage {

/// A pigment's colour with POV-Ray's filter and transmit channels.
struct PigmentColour {
    glm::dvec3 rgb{0.0};
    double filter = 0.0;
    double transmit = 0.0;
    /// POV-Ray's rgbTransm: the light the colour lets through, rgb * filter + transmit.
    glm::dvec3 rgb_transmit() const { return rgb * filter + glm::dvec3(transmit); }
    double opacity() const { return 1.0 - filter - transmit; }
};

/// The pattern value in [0, 1] of a pigment at a point of the pattern's own space (after the
/// warp chain), as POV-Ray's Evaluate_TPat.
double pattern_value(const Pigment& pigment, const glm::dvec3& pattern_point);

/// POV-Ray's Compute_Pigment at a point of the pigment's outer space (for an object's
/// pigment: the world point).  Returns false where no colour is found (outside an image map
/// used `once`): `out` is then clear (POV-Ray's (1, 1, 1) with transmit 1 for image maps).
bool compute_pigment(const Pigment& pigment, const glm::dvec3& point, const PatternContext& ctx,
                     PigmentColour& out);

/// The colour of a pigment at a world point, with the default pattern context.  Colours are
/// rounded to single precision as POV-Ray stores them.
PigmentColour evaluate_pigment(const Pigment& pigment, const glm::dvec3& world_point);

/// The colour seen along an escaping ray of unit `direction`: the sky_sphere's pigments,
/// the last declared on top, evaluated at the direction taken as a point in the sky
/// sphere's space and scaled by its emission, with the background behind them (precomposed over
/// black as POV-Ray's parser does without an alpha channel: rgb * (1 - transmit), filter ignored).
glm::dvec3 sky_colour(const Scene& scene, const glm::dvec3& direction,
                      const PatternContext& ctx = default_pattern_context());

}  // namespace mirage
