// poly, cubic and quartic as a ComplexShape (see poly.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

/// How many coefficients a polynomial of this order has: (n + 1)(n + 2)(n + 3) / 6.
int polynomial_term_count(int order);

Result<std::shared_ptr<const ComplexShape>> prepare_poly(const Polynomial& poly,
                                                         const Primitive& p);

}  // namespace mirage
