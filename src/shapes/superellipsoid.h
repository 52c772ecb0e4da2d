// Superellipsoids as a ComplexShape (see superellipsoid.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_superellipsoid(const Superellipsoid& s,
                                                                   const Primitive& p);

}  // namespace mirage
