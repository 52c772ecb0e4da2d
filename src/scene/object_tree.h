// Objects as the parser builds them: a tree of shapes, unions, CSG combinations and light
// sources, with POV-Ray's rules for transforms, textures and inversion, flattened into the
// scene's primitives and compound objects at the end.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace mirage {

/// One object of the scene language while it is parsed or held by an identifier.
struct ObjectNode {
    enum class Kind {
        Shape,  ///< a primitive
        Union,  ///< union: the children, transformed together
        Csg,    ///< merge or intersection (a difference is parsed into an intersection)
        Light,  ///< a point light source
        Empty,  ///< an object the lenient parser could not represent (see `unknown`)
    };
    Kind kind = Kind::Empty;
    Shape shape;                               // Shape
    Transform transform;                       // Shape: shape space -> world space
    std::optional<Texture> texture;            // the object's own texture, if it has one
    std::shared_ptr<const Interior> interior;  // the object's own interior, if it has one
    std::optional<Texture> interior_texture;   // the object's own interior_texture, if any
    bool no_shadow = false;
    bool inverse = false;              // Shape: POV-Ray's inverse
    CsgKind csg = CsgKind::Merge;      // Csg: Merge or Intersection
    bool inverted = false;             // Csg: POV-Ray's INVERTED flag (see CsgNode)
    std::vector<ObjectNode> children;  // Union, Csg
    std::vector<ObjectNode> clip;      // clipped_by objects
    std::vector<ObjectNode> bound;     // bounded_by objects
    PointLight light;                  // Light
    std::string unknown;               // Empty: what the lenient parser left out, for messages
    FileLoc loc;
};

/// Transforms an object as POV-Ray does: the shape (or every child of a union or CSG, or a
/// light's location), its clipped_by and bounded_by objects, and the textures the object
/// already has.  A texture added later is not affected, which is why `texture { ... }
/// translate x` moves the pattern with the object and `translate x texture { ... }` does not.
void transform_object(ObjectNode& object, const Transform& t);

/// Inverts an object as POV-Ray's Invert_Object and Invert_CSG_Object do: a shape's inside
/// becomes its outside; a union or merge becomes the intersection of its inverted children
/// and an intersection the merge of them (De Morgan), with the INVERTED flag toggled.
void invert_object(ObjectNode& object);

/// Transforms a texture's patterns (the finish has no place in space).
void transform_texture(Texture& texture, const Transform& t);

/// True when nothing of the texture lets light through (no filter or transmit anywhere), so
/// that a texture layered on top of another hides it completely.
bool texture_is_opaque(const Texture& texture);

/// Fills in what POV-Ray fills in after parsing: a gradient without color_map gets the default
/// map (black at 0 to white at 1).
void finish_pigment(Pigment& pigment);

/// Flattens a top-level object into the scene: a child without a texture takes the one of its
/// nearest enclosing union or CSG that has one, else `default_texture`; no_shadow applies to
/// the children (POV-Ray's Post_Process).  Shapes and unions of them become primitives of
/// their own (POV-Ray splits unions); CSG and objects with clipped_by or bounded_by become
/// compound objects over their primitives; objects the parser could not represent become
/// unknown objects.
void flatten_object(const ObjectNode& object, const Texture& default_texture, Scene& scene);

/// The same for objects that need no compound (shapes, unions, lights): their primitives and
/// lights.
void flatten_object(const ObjectNode& object, const Texture& default_texture,
                    std::vector<Primitive>& primitives, std::vector<PointLight>& lights);

}  // namespace mirage
