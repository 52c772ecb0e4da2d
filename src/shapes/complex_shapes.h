// The shapes that implement ComplexShape (shapes/shape_intersect.h): one preparation entry
// point, one file per family here in shapes/.
#pragma once

#include <memory>

#include "scene/scene.h"
#include "shapes/shape_intersect.h"
#include "util/result.h"

namespace mirage {

/// Prepares a primitive whose shape is not one of PreparedShape's own kinds.  Fails with the
/// primitive's place for a shape the tracer cannot render or degenerate data.
Result<std::shared_ptr<const ComplexShape>> prepare_complex_shape(const Primitive& primitive);

/// "file:line:column: " of a primitive, for messages.
std::string primitive_place(const Primitive& primitive);

}  // namespace mirage
