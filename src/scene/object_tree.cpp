// Object tree operations: transforms, inversion, texture inheritance and flattening.
#include "scene/object_tree.h"

#include "scene/transform.h"

namespace mirage {
namespace {

bool colour_is_opaque(const Colour& c) { return c.filter == 0.0 && c.transmit == 0.0; }

/// Whether the object and everything in it can be flattened into primitives of their own.
bool splits_into_primitives(const ObjectNode& n) {
    if (!n.clip.empty() || !n.bound.empty()) return false;
    switch (n.kind) {
        case ObjectNode::Kind::Shape:
        case ObjectNode::Kind::Light:
            return true;
        case ObjectNode::Kind::Union:
            return true;  // its children are objects of their own, whatever they are
        case ObjectNode::Kind::Csg:
        case ObjectNode::Kind::Empty:
            return false;
    }
    return false;
}

class Flattener {
  public:
    Flattener(const Texture& default_texture, Scene& scene)
        : default_texture_(default_texture), scene_(scene) {}

    void object(const ObjectNode& n, const Texture* inherited, bool inherited_no_shadow) {
        const Texture* texture = n.texture ? &*n.texture : inherited;
        const bool no_shadow = n.no_shadow || inherited_no_shadow;
        if (n.kind == ObjectNode::Kind::Empty) {
            unknown(n);
            return;
        }
        if (!splits_into_primitives(n)) {
            const int index = static_cast<int>(scene_.compounds.size());
            scene_.compounds.emplace_back();
            CompoundObject compound;
            const int root = node(n, texture, no_shadow, index, compound);
            if (root < 0) {
                scene_.compounds.pop_back();
                return;
            }
            compound.root = root;
            scene_.compounds[index] = std::move(compound);
            return;
        }
        switch (n.kind) {
            case ObjectNode::Kind::Shape:
                scene_.primitives.push_back(primitive(n, texture, no_shadow, -1));
                break;
            case ObjectNode::Kind::Union:
                for (const ObjectNode& child : n.children) object(child, texture, no_shadow);
                break;
            case ObjectNode::Kind::Light:
                scene_.lights.push_back(n.light);
                break;
            default:
                break;
        }
    }

  private:
    Primitive primitive(const ObjectNode& n, const Texture* texture, bool no_shadow,
                        int compound) const {
        Primitive p;
        p.shape = n.shape;
        p.transform = n.transform;
        p.texture = texture ? *texture : default_texture_;
        finish_pigment(p.texture.pigment);
        p.no_shadow = no_shadow;
        p.inverse = n.inverse;
        p.loc = n.loc;
        p.compound = compound;
        return p;
    }

    /// Adds the node and what is under it to `c`; returns its index, or -1 when nothing of it
    /// is a surface (a light, an unknown object).
    int node(const ObjectNode& n, const Texture* inherited, bool inherited_no_shadow, int index,
             CompoundObject& c) {
        const Texture* texture = n.texture ? &*n.texture : inherited;
        const bool no_shadow = n.no_shadow || inherited_no_shadow;
        CsgNode out;
        switch (n.kind) {
            case ObjectNode::Kind::Light:
                scene_.lights.push_back(n.light);
                return -1;
            case ObjectNode::Kind::Empty:
                unknown(n);
                return -1;
            case ObjectNode::Kind::Shape:
                out.kind = CsgKind::Primitive;
                out.primitive = static_cast<int>(scene_.primitives.size());
                scene_.primitives.push_back(primitive(n, texture, no_shadow, index));
                break;
            case ObjectNode::Kind::Union:
            case ObjectNode::Kind::Csg:
                out.kind = n.kind == ObjectNode::Kind::Union ? CsgKind::Union : n.csg;
                out.inverted = n.inverted;
                for (const ObjectNode& child : n.children) {
                    const int k = node(child, texture, no_shadow, index, c);
                    if (k >= 0) out.children.push_back(k);
                }
                break;
        }
        // Clipping and bounding objects are never seen: their textures do not matter.
        for (const ObjectNode& clip : n.clip) {
            const int k = node(clip, nullptr, true, index, c);
            if (k >= 0) out.clip.push_back(k);
        }
        for (const ObjectNode& bound : n.bound) {
            const int k = node(bound, nullptr, true, index, c);
            if (k >= 0) out.bound.push_back(k);
        }
        c.nodes.push_back(std::move(out));
        return static_cast<int>(c.nodes.size()) - 1;
    }

    void unknown(const ObjectNode& n) {
        UnknownObject u;
        u.what = n.unknown.empty() ? "an object mirage does not know" : n.unknown;
        u.loc = n.loc;
        // Each bounded_by or clipped_by object bounds it: their primitives, wherever they are.
        for (const auto* list : {&n.bound, &n.clip}) {
            for (const ObjectNode& b : *list) {
                Scene scratch;
                Flattener(default_texture_, scratch).object(b, nullptr, true);
                u.bounds.push_back(std::move(scratch.primitives));
            }
        }
        scene_.unknown_objects.push_back(std::move(u));
    }

    const Texture& default_texture_;
    Scene& scene_;
};

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
        case ObjectNode::Kind::Csg:
            for (ObjectNode& child : object.children) transform_object(child, t);
            break;
        case ObjectNode::Kind::Light:
            object.light.location = transform_point(t, object.light.location);
            break;
        case ObjectNode::Kind::Empty:
            break;
    }
    for (ObjectNode& c : object.clip) transform_object(c, t);
    for (ObjectNode& b : object.bound) transform_object(b, t);
    if (object.texture) transform_texture(*object.texture, t);
}

void invert_object(ObjectNode& object) {
    switch (object.kind) {
        case ObjectNode::Kind::Shape:
            object.inverse = !object.inverse;
            break;
        case ObjectNode::Kind::Union:
        case ObjectNode::Kind::Csg:
            for (ObjectNode& child : object.children) invert_object(child);
            // POV-Ray's Morph: a union or a merge becomes an intersection, an intersection a
            // merge.
            object.csg = object.kind == ObjectNode::Kind::Csg && object.csg == CsgKind::Intersection
                             ? CsgKind::Merge
                             : CsgKind::Intersection;
            object.kind = ObjectNode::Kind::Csg;
            object.inverted = !object.inverted;
            break;
        case ObjectNode::Kind::Light:
        case ObjectNode::Kind::Empty:
            break;
    }
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

void flatten_object(const ObjectNode& object, const Texture& default_texture, Scene& scene) {
    Flattener(default_texture, scene).object(object, nullptr, false);
}

void flatten_object(const ObjectNode& object, const Texture& default_texture,
                    std::vector<Primitive>& primitives, std::vector<PointLight>& lights) {
    Scene scene;
    scene.primitives = std::move(primitives);
    scene.lights = std::move(lights);
    Flattener(default_texture, scene).object(object, nullptr, false);
    primitives = std::move(scene.primitives);
    lights = std::move(scene.lights);
}

}  // namespace mirage
