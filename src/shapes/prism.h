// Prisms as a ComplexShape (see prism.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_prism(const Prism& prism, const Primitive& p);

}  // namespace mirage
