#include "trace/shapes/complex_shapes.h"

#include <sstream>

namespace mirage {

std::string primitive_place(const Primitive& p) {
    std::ostringstream out;
    if (!p.loc.file.empty()) out << p.loc.file << ":" << p.loc.line << ":" << p.loc.column << ": ";
    return out.str();
}

Result<std::shared_ptr<const ComplexShape>> prepare_complex_shape(const Primitive& primitive) {
    return make_error(primitive_place(primitive) + "the tracer cannot render a " +
                      shape_keyword(primitive.shape) + " yet");
}

}  // namespace mirage
