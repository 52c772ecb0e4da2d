// Pigments of the scene subset evaluated as POV-Ray 3.7 evaluates them (pigment.cpp,
// pattern.cpp): solid colours, checker, gradient with a colour map (POV-Ray's black-to-white
// map when none is given), each under its own transform; and the sky (sky_sphere layers
// over the background, tracepixel/trace.cpp ComputeSky).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace mirage {

/// A pigment's colour with POV-Ray's filter and transmit channels.
struct PigmentColour {
    glm::dvec3 rgb{0.0};
    double filter = 0.0;
    double transmit = 0.0;
};

/// The pattern value in [0, 1] of a checker (0 or 1) or gradient pigment at a point of the
/// pattern's own space (after the pigment's transform), as POV-Ray's Evaluate_TPat.
double pattern_value(const Pigment& pigment, const glm::dvec3& pattern_point);

/// The colour of a pigment at a world point: the pattern is evaluated at
/// `pigment.transform.inverse * point`.  Colours are rounded to single precision as POV-Ray
/// stores them.
PigmentColour evaluate_pigment(const Pigment& pigment, const glm::dvec3& world_point);

/// The colour seen along an escaping ray of unit `direction`: the sky_sphere's pigments,
/// the last declared on top, evaluated at the direction taken as a point in the sky
/// sphere's space and scaled by its emission, with the background behind them (precomposed over
/// black as POV-Ray's parser does without an alpha channel: rgb * (1 - transmit), filter ignored).
glm::dvec3 sky_colour(const Scene& scene, const glm::dvec3& direction);

}  // namespace mirage
