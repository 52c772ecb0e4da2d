// Text (TrueType glyphs) as a ComplexShape (see text.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_text(const Text& text, const Primitive& p);

}  // namespace mirage
