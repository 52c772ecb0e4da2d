// Triangle meshes and polygons as ComplexShapes (see mesh.cpp).
#pragma once

#include "shapes/complex_shapes.h"

namespace mirage {

Result<std::shared_ptr<const ComplexShape>> prepare_mesh(const Mesh& mesh, const Primitive& p);
Result<std::shared_ptr<const ComplexShape>> prepare_polygon(const Polygon& polygon,
                                                            const Primitive& p);

}  // namespace mirage
