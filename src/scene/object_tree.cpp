// Object tree operations: transforms, texture inheritance and flattening.
#include "scene/object_tree.h"

#include "scene/material_ops.h"
#include "scene/transform.h"

namespace mirage {
namespace {

void flatten(const ObjectNode& object, const Texture* inherited,
             const std::shared_ptr<const Interior>& inherited_interior,
             const Texture* inherited_interior_texture, bool inherited_no_shadow,
             const Texture& default_texture, std::vector<Primitive>& primitives,
             std::vector<PointLight>& lights) {
    const Texture* texture = object.texture ? &*object.texture : inherited;
    const Texture* interior_texture =
        object.interior_texture ? &*object.interior_texture : inherited_interior_texture;
    // An object without an interior shares its union's (one medium, as in POV-Ray).
    const std::shared_ptr<const Interior> interior =
        object.interior ? object.interior : inherited_interior;
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
            p.interior = interior ? interior : std::make_shared<const Interior>();
            if (interior_texture) p.interior_texture = *interior_texture;
            primitives.push_back(std::move(p));
            break;
        }
        case ObjectNode::Kind::Union: {
            // A union always has an interior (POV-Ray gives it one), which its children share.
            const auto shared = interior ? interior : std::make_shared<const Interior>();
            for (const ObjectNode& child : object.children) {
                flatten(child, texture, shared, interior_texture, no_shadow, default_texture,
                        primitives, lights);
            }
            break;
        }
        case ObjectNode::Kind::Light:
            lights.push_back(object.light);
            break;
        case ObjectNode::Kind::Empty:
            break;
    }
}

}  // namespace

void transform_object(ObjectNode& object, const Transform& t) {
    switch (object.kind) {
        case ObjectNode::Kind::Shape:
            object.transform = compose_transforms(object.transform, t);
            break;
        case ObjectNode::Kind::Union:
            for (ObjectNode& child : object.children) transform_object(child, t);
            break;
        case ObjectNode::Kind::Light:
            transform_light(object.light, t);
            break;
        case ObjectNode::Kind::Empty:
            break;
    }
    if (object.texture) transform_texture(*object.texture, t);
    if (object.interior_texture) transform_texture(*object.interior_texture, t);
}

void flatten_object(const ObjectNode& object, const Texture& default_texture,
                    std::vector<Primitive>& primitives, std::vector<PointLight>& lights) {
    flatten(object, nullptr, nullptr, nullptr, false, default_texture, primitives, lights);
}

}  // namespace mirage
