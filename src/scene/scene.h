// The parsed scene: what `mirage compile` and `mirage trace` read from a .pov file.
// Plain data; the parser (scene/parser.h) fills it, the tracer and the compiler read it.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene/shapes.h"
#include "util/file_loc.h"

namespace mirage {

/// A POV-Ray colour: linear rgb plus filter and transmit.
struct Colour {
    glm::dvec3 rgb{0.0};
    double filter = 0.0;
    double transmit = 0.0;
};

/// An affine map from an object's (or a pattern's) own space to world space.
struct Transform {
    glm::dmat4 matrix{1.0};
    glm::dmat4 inverse{1.0};
};

struct ColourMapEntry {
    double position = 0.0;
    Colour colour;
};

enum class PigmentKind { Solid, Checker, Gradient };

/// A pigment of the supported subset.  Patterns are evaluated at
/// `transform.inverse * world_point` (the parser composes the transforms that apply).
struct Pigment {
    PigmentKind kind = PigmentKind::Solid;
    Colour colour;                            // Solid
    Colour checker[2];                        // Checker: the two colours, in POV-Ray's order
    glm::dvec3 gradient_axis{0.0, 1.0, 0.0};  // Gradient: the vector given after `gradient`
                                              // (normalised by the parser, as POV-Ray does)
    std::vector<ColourMapEntry> colour_map;   // Gradient: POV-Ray's default map when absent
    Transform transform;
};

/// POV-Ray 3.7's finish subset, with POV-Ray's defaults.
struct Finish {
    glm::dvec3 ambient{0.1};
    glm::dvec3 emission{0.0};
    double diffuse = 0.6;
    double brilliance = 1.0;
    double specular = 0.0;
    double roughness = 0.05;
    double phong = 0.0;
    double phong_size = 40.0;
    glm::dvec3 reflection{0.0};  // reflection colour (POV-Ray's reflection_max)
};

struct Texture {
    Pigment pigment;
    Finish finish;
};

/// One primitive of the scene: `union`s and `object`s are flattened by the parser, every
/// primitive carries its world transform and its resolved texture (its own, the one it
/// inherits from an enclosing union, or POV-Ray's default).
struct Primitive {
    Shape shape;
    Transform transform;  // shape space -> world space
    Texture texture;
    bool no_shadow = false;
    bool inverse = false;
    FileLoc loc;
    int compound = -1;  // the compound object (Scene::compounds) it is part of; -1: its own
};

/// An object the lenient parser could not represent (an unsupported kind, or one that uses
/// an opaque value).  Its extent is what its bounded_by or clipped_by objects bound; without
/// them it is unbounded.
struct UnknownObject {
    std::string what;
    FileLoc loc;
    std::vector<std::vector<Primitive>> bounds;  // per bounded_by or clipped_by object, its
                                                 // primitives in world space
};

struct PointLight {
    glm::dvec3 location{0.0};
    glm::dvec3 colour{1.0};
    bool shadowless = false;
    FileLoc loc;
};

/// POV-Ray 3.7's camera projections (render/tracepixel.cpp).
enum class CameraType : std::uint8_t {
    Perspective,
    Orthographic,
    Fisheye,
    UltraWideAngle,
    Omnimax,
    Panoramic,
    Cylinder1,  ///< cylinder 1: vertical cylinder, fixed viewpoint
    Cylinder2,  ///< cylinder 2: horizontal cylinder, fixed viewpoint
    Cylinder3,  ///< cylinder 3: vertical cylinder, viewpoint moving along the axis
    Cylinder4,  ///< cylinder 4: horizontal cylinder, viewpoint moving along the axis
    Spherical,
};

/// A camera, held as POV-Ray holds it after parsing: the final location, direction, right,
/// up and sky vectors with look_at, angle and transforms applied.
struct Camera {
    CameraType type = CameraType::Perspective;
    double angle_deg = 90.0;   // the angle as given (fisheye, ultra_wide_angle, panoramic,
                               // cylinder, omnimax and spherical use it; 0 when not given)
    double v_angle_deg = 0.0;  // spherical: the vertical angle (0: half the horizontal)
    glm::dvec3 location{0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};
    glm::dvec3 right{1.33, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dvec3 sky{0.0, 1.0, 0.0};
    FileLoc loc;
};

struct SkySphere {
    std::vector<Pigment> pigments;  // in file order; POV-Ray 3.7 layers the LAST on top (a
                                    // transparent later pigment shows the earlier ones through)
    Transform transform;
    FileLoc loc;
    glm::dvec3 emission{1.0};  // POV-Ray 3.7's sky_sphere `emission`: scales the sky colour
};

struct GlobalSettings {
    double assumed_gamma = 1.0;
    int max_trace_level = 5;
    glm::dvec3 ambient_light{1.0};
};

/// A value declared at the top level (#declare), kept for tools that read settings from
/// the scene, such as the Mirage_... atmosphere declarations.
struct Declared {
    std::variant<double, glm::dvec3, std::string> value;
    FileLoc loc;
};

/// Something the parser skipped in lenient mode (an object kind outside the subset).
struct Skipped {
    std::string what;
    FileLoc loc;
};

struct Scene {
    std::string file;
    std::vector<std::string> files;  // every file read: the scene, then its includes in order
    Camera camera;                   // POV-Ray's default camera when the file has none
    bool has_camera = false;
    std::vector<PointLight> lights;
    std::vector<Primitive> primitives;
    Colour background;  // as written; POV-Ray 3.7 without alpha output shows rgb * (1 - transmit)
    std::optional<SkySphere> sky_sphere;
    GlobalSettings global;
    std::map<std::string, Declared> symbols;
    std::vector<std::string> messages;  // #warning and #debug output, with their place
    std::vector<Skipped> skipped;
    std::vector<CompoundObject> compounds;
    std::vector<UnknownObject> unknown_objects;  // lenient mode only
};

}  // namespace mirage
