// POV-Ray 3.7's image mapping (support/imageutil.cpp): the image coordinates of a point
// for the planar, spherical, cylindrical and torus maps, the pixel lookup without
// interpolation or with bilinear or normalised-distance interpolation, image_map pigments
// and bump_map normals.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "patterns/pigment_eval.h"

namespace mirage {

/// POV-Ray's image_map: the colour of an image_map pigment at a point of its space.  False
/// (and POV-Ray's clear colour) outside an image used `once`.
bool image_map_colour(const Pattern& pattern, const glm::dvec3& p, PigmentColour& out);

/// POV-Ray's bump_map: perturbs `normal` by the image's heights around the point.
void bump_map_normal(const Normal& normal, const glm::dvec3& p, glm::dvec3& out_normal);

}  // namespace mirage
