// Value helpers.
#include "scene/value.h"

namespace mirage {

Numeric Numeric::scalar(double x) {
    Numeric n;
    n.size = 1;
    n.v[0] = x;
    return n;
}

Numeric Numeric::vector3(const glm::dvec3& p) {
    Numeric n;
    n.size = 3;
    n.v = {p.x, p.y, p.z, 0.0, 0.0};
    return n;
}

Numeric Numeric::colour(const Colour& c) {
    Numeric n;
    n.size = 5;
    n.v = {c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit};
    return n;
}

Numeric promote(const Numeric& n, int size) {
    if (n.size >= size) return n;
    Numeric out = n;
    for (int i = n.size; i < size; ++i) out.v[i] = n.size == 1 ? n.v[0] : 0.0;
    out.size = size;
    return out;
}

Colour numeric_to_colour(const Numeric& n) {
    Colour c;
    c.rgb = glm::dvec3(n.v[0], n.v[1], n.v[2]);
    c.filter = n.v[3];
    c.transmit = n.v[4];
    return c;
}

std::string numeric_type_name(int size) {
    switch (size) {
        case 1:
            return "float";
        case 2:
            return "2-component vector";
        case 3:
            return "vector";
        case 4:
            return "4-component vector";
        default:
            return "colour";
    }
}

Value deep_copy(const Value& value) {
    if (const auto* array = value.get_if<ArrayValue>()) {
        ArrayValue copy;
        copy.sizes = array->sizes;
        copy.elements.reserve(array->elements.size());
        for (const auto& e : array->elements) {
            copy.elements.push_back(e ? std::make_shared<Value>(deep_copy(*e)) : nullptr);
        }
        return Value{copy};
    }
    return value;
}

std::string value_type_name(const Value& value) {
    struct Namer {
        std::string operator()(const Numeric& n) const { return numeric_type_name(n.size); }
        std::string operator()(const std::string&) const { return "string"; }
        std::string operator()(const Boxed<ObjectNode>& b) const {
            const ObjectNode& o = *b;
            return o.kind == ObjectNode::Kind::Light ? "light source" : "object";
        }
        std::string operator()(const Boxed<Texture>&) const { return "texture"; }
        std::string operator()(const Boxed<Pigment>&) const { return "pigment"; }
        std::string operator()(const Finish&) const { return "finish"; }
        std::string operator()(const Transform&) const { return "transform"; }
        std::string operator()(const ColourMapValue&) const { return "color_map"; }
        std::string operator()(const CameraState&) const { return "camera"; }
        std::string operator()(const ArrayValue&) const { return "array"; }
        std::string operator()(const std::shared_ptr<const MacroDef>&) const { return "macro"; }
        std::string operator()(const OpaqueValue& u) const { return u.what; }
        std::string operator()(const Boxed<SkySphere>&) const { return "sky_sphere"; }
        std::string operator()(const std::shared_ptr<const FunctionCode>&) const {
            return "function";
        }
        std::string operator()(const Boxed<MaterialValue>& m) const { return (*m).type_name(); }
    };
    return std::visit(Namer{}, value.data);
}

}  // namespace mirage
