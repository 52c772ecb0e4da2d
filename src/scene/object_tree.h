// Objects as the parser builds them: a tree of shapes, unions and light sources, with
// POV-Ray's rules for transforms and textures, flattened into Scene::primitives at the end.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace mirage {

/// One object of the scene language while it is parsed or held by an identifier.
struct ObjectNode {
    enum class Kind {
        Shape,  ///< a primitive (sphere, plane, box, cylinder, disc)
        Union,  ///< union: the children, transformed together
        Light,  ///< a point light source
        Empty,  ///< a placeholder for an object skipped in lenient mode
    };
    Kind kind = Kind::Empty;
    Shape shape;                     // Shape
    Transform transform;             // Shape: shape space -> world space
    std::optional<Texture> texture;  // the object's own texture, if it has one
    bool no_shadow = false;
    bool inverse = false;
    std::vector<ObjectNode> children;  // Union
    PointLight light;                  // Light
    std::string unknown;               // Empty: what the lenient parser left out, for messages
    FileLoc loc;
};

/// Transforms an object as POV-Ray does: the shape (or every child of a union, or a light's
/// location) and the textures the object already has.  A texture added later is not affected,
/// which is why `texture { ... } translate x` moves the pattern with the object and
/// `translate x texture { ... }` does not.
void transform_object(ObjectNode& object, const Transform& t);

/// Transforms a texture's patterns (the finish has no place in space).
void transform_texture(Texture& texture, const Transform& t);

/// True when nothing of the texture lets light through (no filter or transmit anywhere), so
/// that a texture layered on top of another hides it completely.
bool texture_is_opaque(const Texture& texture);

/// Fills in what POV-Ray fills in after parsing: a gradient without color_map gets the default
/// map (black at 0 to white at 1).
void finish_pigment(Pigment& pigment);

/// Flattens an object into primitives and lights: a child without a texture takes the one of
/// its nearest enclosing union that has one, else `default_texture`; no_shadow on a union
/// applies to its children (POV-Ray's Post_Process).
void flatten_object(const ObjectNode& object, const Texture& default_texture,
                    std::vector<Primitive>& primitives, std::vector<PointLight>& lights);

}  // namespace mirage
