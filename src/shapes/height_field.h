// Height fields as a ComplexShape (see height_field.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_height_field(const HeightField& hf,
                                                                 const Primitive& p);

}  // namespace mirage
