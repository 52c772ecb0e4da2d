// Lathes and surfaces of revolution as ComplexShapes (see lathe_sor.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_lathe(const Lathe& lathe, const Primitive& p);
Result<std::shared_ptr<const ComplexShape>> prepare_sor(const Sor& sor, const Primitive& p);

}  // namespace mirage
