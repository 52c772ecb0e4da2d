#include "shapes/complex_shapes.h"

#include <sstream>

#include "shapes/blob.h"
#include "shapes/height_field.h"
#include "shapes/isosurface.h"
#include "shapes/lathe_sor.h"
#include "shapes/mesh.h"
#include "shapes/poly.h"
#include "shapes/prism.h"
#include "shapes/superellipsoid.h"
#include "shapes/text.h"

namespace mirage {

std::string primitive_place(const Primitive& p) { return place_prefix(p.loc); }

Result<std::shared_ptr<const ComplexShape>> prepare_complex_shape(const Primitive& primitive) {
    if (const auto* m = std::get_if<Mesh>(&primitive.shape)) return prepare_mesh(*m, primitive);
    if (const auto* q = std::get_if<Polynomial>(&primitive.shape))
        return prepare_poly(*q, primitive);
    if (const auto* t = std::get_if<Text>(&primitive.shape)) return prepare_text(*t, primitive);
    if (const auto* r = std::get_if<Prism>(&primitive.shape)) return prepare_prism(*r, primitive);
    if (const auto* l = std::get_if<Lathe>(&primitive.shape)) return prepare_lathe(*l, primitive);
    if (const auto* h = std::get_if<HeightField>(&primitive.shape)) {
        return prepare_height_field(*h, primitive);
    }
    if (const auto* o = std::get_if<Sor>(&primitive.shape)) return prepare_sor(*o, primitive);
    if (const auto* b = std::get_if<Blob>(&primitive.shape)) return prepare_blob(*b, primitive);
    if (const auto* e = std::get_if<Superellipsoid>(&primitive.shape)) {
        return prepare_superellipsoid(*e, primitive);
    }
    if (const auto* i = std::get_if<Isosurface>(&primitive.shape)) {
        return prepare_isosurface(*i, primitive);
    }
    if (const auto* p = std::get_if<Polygon>(&primitive.shape)) {
        return prepare_polygon(*p, primitive);
    }
    return make_error(primitive_place(primitive) + "the tracer cannot render a " +
                      shape_keyword(primitive.shape) + " yet");
}

}  // namespace mirage
