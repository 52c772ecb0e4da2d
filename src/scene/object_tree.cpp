// Object tree operations: transforms, inversion, texture inheritance and flattening.
#include "scene/object_tree.h"

#include "scene/material_ops.h"
#include "scene/transform.h"

namespace mirage {
namespace {

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

/// What an object passes down to the objects in it (POV-Ray's Post_Process): its texture,
/// interior and interior_texture, for children that have none, and no_shadow.
struct Inherited {
    const Texture* texture = nullptr;
    std::shared_ptr<const Interior> interior;
    const Texture* interior_texture = nullptr;
    bool no_shadow = false;
};

/// The object's own items over what it inherits.  A union or CSG always has an interior
/// (POV-Ray gives it one), which its children without one share: one medium.
Inherited inherit(const ObjectNode& n, const Inherited& from) {
    Inherited out;
    out.texture = n.texture ? &*n.texture : from.texture;
    out.interior = n.interior ? n.interior : from.interior;
    out.interior_texture = n.interior_texture ? &*n.interior_texture : from.interior_texture;
    out.no_shadow = n.no_shadow || from.no_shadow;
    const bool compound = n.kind == ObjectNode::Kind::Union || n.kind == ObjectNode::Kind::Csg;
    if (compound && !out.interior) out.interior = std::make_shared<const Interior>();
    return out;
}

class Flattener {
  public:
    Flattener(const Texture& default_texture, Scene& scene)
        : default_texture_(default_texture), scene_(scene) {}

    void object(const ObjectNode& n, const Inherited& from) {
        if (n.kind == ObjectNode::Kind::Empty) {
            unknown(n);
            return;
        }
        if (!splits_into_primitives(n)) {
            const int index = static_cast<int>(scene_.compounds.size());
            scene_.compounds.emplace_back();
            CompoundObject compound;
            const int root = node(n, from, index, compound);
            if (root < 0) {
                scene_.compounds.pop_back();
                return;
            }
            compound.root = root;
            scene_.compounds[index] = std::move(compound);
            return;
        }
        const Inherited here = inherit(n, from);
        switch (n.kind) {
            case ObjectNode::Kind::Shape:
                scene_.primitives.push_back(primitive(n, here, -1));
                break;
            case ObjectNode::Kind::Union:
                for (const ObjectNode& child : n.children) object(child, here);
                break;
            case ObjectNode::Kind::Light:
                scene_.lights.push_back(n.light);
                break;
            default:
                break;
        }
    }

  private:
    Primitive primitive(const ObjectNode& n, const Inherited& here, int compound) const {
        Primitive p;
        p.shape = n.shape;
        p.transform = n.transform;
        p.texture = here.texture ? *here.texture : default_texture_;
        finish_pigment(p.texture.pigment);
        p.no_shadow = here.no_shadow;
        p.inverse = n.inverse;
        p.loc = n.loc;
        p.interior = here.interior ? here.interior : std::make_shared<const Interior>();
        if (here.interior_texture) p.interior_texture = *here.interior_texture;
        p.compound = compound;
        return p;
    }

    /// Adds the node and what is under it to `c`; returns its index, or -1 when nothing of it
    /// is a surface (a light, an unknown object).
    int node(const ObjectNode& n, const Inherited& from, int index, CompoundObject& c) {
        const Inherited here = inherit(n, from);
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
                scene_.primitives.push_back(primitive(n, here, index));
                break;
            case ObjectNode::Kind::Union:
            case ObjectNode::Kind::Csg:
                out.kind = n.kind == ObjectNode::Kind::Union ? CsgKind::Union : n.csg;
                out.inverted = n.inverted;
                for (const ObjectNode& child : n.children) {
                    const int k = node(child, here, index, c);
                    if (k >= 0) out.children.push_back(k);
                }
                break;
        }
        // Clipping and bounding objects are never seen: their textures and interiors do not
        // matter.
        const Inherited unseen{nullptr, nullptr, nullptr, true};
        for (const ObjectNode& clip : n.clip) {
            const int k = node(clip, unseen, index, c);
            if (k >= 0) out.clip.push_back(k);
        }
        for (const ObjectNode& bound : n.bound) {
            const int k = node(bound, unseen, index, c);
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
                Flattener(default_texture_, scratch)
                    .object(b, Inherited{nullptr, nullptr, nullptr, true});
                u.bounds.push_back(std::move(scratch.primitives));
            }
        }
        scene_.unknown_objects.push_back(std::move(u));
    }

    const Texture& default_texture_;
    Scene& scene_;
};

}  // namespace

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
            transform_light(object.light, t);
            break;
        case ObjectNode::Kind::Empty:
            break;
    }
    for (ObjectNode& c : object.clip) transform_object(c, t);
    for (ObjectNode& b : object.bound) transform_object(b, t);
    if (object.texture) transform_texture(*object.texture, t);
    if (object.interior_texture) transform_texture(*object.interior_texture, t);
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

void flatten_object(const ObjectNode& object, const Texture& default_texture, Scene& scene) {
    Flattener(default_texture, scene).object(object, Inherited{});
}

void flatten_object(const ObjectNode& object, const Texture& default_texture,
                    std::vector<Primitive>& primitives, std::vector<PointLight>& lights) {
    Scene scene;
    scene.primitives = std::move(primitives);
    scene.lights = std::move(lights);
    Flattener(default_texture, scene).object(object, Inherited{});
    primitives = std::move(scene.primitives);
    lights = std::move(scene.lights);
}

}  // namespace mirage
