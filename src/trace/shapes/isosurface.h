// Isosurfaces as a ComplexShape (see isosurface.cpp).
#pragma once

#include "trace/shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_isosurface(const Isosurface& iso,
                                                               const Primitive& p);

}  // namespace mirage
