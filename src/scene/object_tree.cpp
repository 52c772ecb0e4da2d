// Object tree operations: transforms, texture inheritance and flattening.
#include "scene/object_tree.h"

#include "scene/transform.h"

namespace mirage {
namespace {

bool colour_is_opaque(const Colour& c) { return c.filter == 0.0 && c.transmit == 0.0; }

void flatten(const ObjectNode& object, const Texture* inherited, bool inherited_no_shadow,
             const Texture& default_texture, std::vector<Primitive>& primitives,
             std::vector<PointLight>& lights) {
    const Texture* texture = object.texture ? &*object.texture : inherited;
    bool no_shadow = object.no_shadow || inherited_no_shadow;
    switch (object.kind) {
        case ObjectNode::Kind::Shape: {
            Primitive p;
            p.shape = object.shape;
            p.transform = object.transform;
            p.texture = texture ? *texture : default_texture;
            finish_pigment(p.texture.pigment);
            p.no_shadow = no_shadow;
            p.inverse = object.inverse;
            p.loc = object.loc;
            primitives.push_back(std::move(p));
            break;
        }
        case ObjectNode::Kind::Union:
            for (const ObjectNode& child : object.children) {
                flatten(child, texture, no_shadow, default_texture, primitives, lights);
            }
            break;
        case ObjectNode::Kind::Light:
            lights.push_back(object.light);
            break;
        case ObjectNode::Kind::Empty:
            break;
    }
}

}  // namespace

void transform_texture(Texture& texture, const Transform& t) {
    texture.pigment.transform = compose_transforms(texture.pigment.transform, t);
}

void transform_object(ObjectNode& object, const Transform& t) {
    switch (object.kind) {
        case ObjectNode::Kind::Shape:
            object.transform = compose_transforms(object.transform, t);
            break;
        case ObjectNode::Kind::Union:
            for (ObjectNode& child : object.children) transform_object(child, t);
            break;
        case ObjectNode::Kind::Light:
            object.light.location = transform_point(t, object.light.location);
            break;
        case ObjectNode::Kind::Empty:
            break;
    }
    if (object.texture) transform_texture(*object.texture, t);
}

bool texture_is_opaque(const Texture& texture) {
    const Pigment& p = texture.pigment;
    switch (p.kind) {
        case PigmentKind::Solid:
            return colour_is_opaque(p.colour);
        case PigmentKind::Checker:
            return colour_is_opaque(p.checker[0]) && colour_is_opaque(p.checker[1]);
        case PigmentKind::Gradient:
            for (const ColourMapEntry& e : p.colour_map) {
                if (!colour_is_opaque(e.colour)) return false;
            }
            return true;
    }
    return false;
}

void finish_pigment(Pigment& pigment) {
    if (pigment.kind == PigmentKind::Gradient && pigment.colour_map.empty()) {
        // POV-Ray's Gray_Default_Map (texture/pigment.cpp).
        ColourMapEntry black, white;
        black.position = 0.0;
        white.position = 1.0;
        white.colour.rgb = glm::dvec3(1.0);
        pigment.colour_map = {black, white};
    }
}

void flatten_object(const ObjectNode& object, const Texture& default_texture,
                    std::vector<Primitive>& primitives, std::vector<PointLight>& lights) {
    flatten(object, nullptr, false, default_texture, primitives, lights);
}

}  // namespace mirage
