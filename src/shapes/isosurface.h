// Isosurfaces as a ComplexShape (see isosurface.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

/// The most intervals the root search of one ray through one isosurface halves (all its
/// max_trace roots together).  A usual isosurface needs a few hundred; `accuracy 1e-300` with
/// `max_gradient 1e300` drops none and would halve without end.  A ray that reaches the bound
/// misses the surface there.
constexpr long kMaxRootSearchSteps = 1L << 16;

/// The intervals halved by the root searches this thread has made (for the tests of the bound).
long root_search_steps_on_this_thread();

Result<std::shared_ptr<const ComplexShape>> prepare_isosurface(const Isosurface& iso,
                                                               const Primitive& p);

}  // namespace mirage
