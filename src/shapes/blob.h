// Blobs as a ComplexShape (see blob.cpp).
#pragma once

#include <vector>

#include "shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_blob(const Blob& blob, const Primitive& p);

/// The blob's density at a point of its own space (before the primitive's transform): the sum
/// over its components of strength (1 - r^2 / radius^2)^2 inside each, POV-Ray's
/// calculate_field_value.  For tests and for the component texture weights.
double blob_field(const Blob& blob, const glm::dvec3& point);

/// Each component's density at a point of the blob's own space, in component order
/// (POV-Ray's Determine_Blob_Textures weighs component textures by these).
std::vector<double> blob_component_fields(const Blob& blob, const glm::dvec3& point);

}  // namespace mirage
