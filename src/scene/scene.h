// The parsed scene: what `mirage compile` and `mirage trace` read from a .pov file.
// Plain data; the parser (scene/parser.h) fills it, the tracer and the compiler read it.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <map>
#include <memory>
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

/// POV-Ray's greyscale of a colour (GREY_SCALE in base/colour.h: 0.297, 0.589, 0.114).
inline double greyscale(const glm::dvec3& rgb) {
    return 0.297 * rgb.x + 0.589 * rgb.y + 0.114 * rgb.z;
}

/// An affine map from an object's (or a pattern's) own space to world space.
struct Transform {
    glm::dmat4 matrix{1.0};
    glm::dmat4 inverse{1.0};
};

struct ColourMapEntry {
    double position = 0.0;
    Colour colour;
};

/// POV-Ray's pattern types (pattern.h), the ones the tracer evaluates.  `Solid` is a pigment
/// without a pattern (a plain colour) and a texture or normal without one.
enum class PatternKind : std::uint8_t {
    Solid,
    Checker,
    Gradient,
    Agate,
    Average,
    Boxed,
    Bozo,
    Brick,
    Bumps,
    Cells,
    Crackle,
    Cubic,
    Cylindrical,
    Dents,
    Facets,
    Granite,
    Hexagon,
    ImageMap,  // pigment image_map / normal bump_map (POV-Ray's BITMAP_PATTERN)
    Leopard,
    Mandel,
    Marble,
    Onion,
    PigmentPattern,
    Planar,
    Quilted,
    Radial,
    Ripples,
    Slope,
    Spherical,
    Spiral1,
    Spiral2,
    Spotted,
    Square,
    Triangular,
    Waves,
    Wood,
    Wrinkles,
};
using PigmentKind = PatternKind;

/// How a pattern value is shaped before the map lookup (Evaluate_TPat).
enum class WaveType : std::uint8_t { Ramp, Sine, Triangle, Scallop, Cubic, Poly };

/// Fractal Brownian motion parameters: POV-Ray's TURB (`turbulence`, `octaves`, `omega`,
/// `lambda`), with its defaults.
struct Turbulence {
    glm::dvec3 amount{0.0};
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};

/// One entry of a pattern's warp chain (warps.h): `warp { ... }` blocks and the transforms
/// between them, applied in chain order to the evaluation point.
struct Warp {
    enum class Kind : std::uint8_t {
        Transform,   // a pattern transform (inverse applied to the point)
        Turbulence,  // warp { turbulence ... }
        Repeat,
        BlackHole,
        Cylindrical,
        Spherical,
        Toroidal,
        Planar,
        Cubic,
    };
    Kind kind = Kind::Transform;
    Transform transform;                    // Transform
    Turbulence turbulence;                  // Turbulence
    int axis = 0;                           // Repeat: 0, 1, 2 for x, y, z
    double width = 0.0;                     // Repeat
    glm::dvec3 offset{0.0};                 // Repeat
    glm::dvec3 flip{1.0};                   // Repeat: -1 on the flipped axes
    glm::dvec3 centre{0.0};                 // BlackHole
    double radius = 1.0;                    // BlackHole
    double strength = 1.0;                  // BlackHole
    double power = 2.0;                     // BlackHole: falloff
    bool inverse = false;                   // BlackHole
    bool repeat = false;                    // BlackHole
    glm::dvec3 repeat_vector{0.0};          // BlackHole
    bool uncertain = false;                 // BlackHole
    glm::dvec3 uncertainty{0.0};            // BlackHole: turbulence
    glm::dvec3 orientation{0.0, 0.0, 1.0};  // Cylindrical, Spherical, Toroidal, Planar
    double dist_exp = 0.0;                  // Cylindrical, Spherical, Toroidal
    double major_radius = 1.0;              // Toroidal
    double planar_offset = 0.0;             // Planar
};

/// A decoded image for image_map and bump_map: rgb, filter and transmit per pixel, top row
/// first, as POV-Ray holds it after reading the file.
struct ImageData {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;  // 5 floats per pixel: r, g, b, filter, transmit
    bool has_alpha = false;     // the file had an alpha channel
    bool is_indexed = false;    // a palette image (filter/transmit by index apply)
    std::vector<int> indices;   // palette index per pixel, when indexed
    std::string file;
};

struct Pigment;

/// The fields every POV-Ray pattern carries (TPATTERN): the type, the wave applied to the
/// value, the pattern's own parameters and its warp chain.  Pigments, normals and patterned
/// textures are patterns.
struct Pattern {
    PatternKind kind = PatternKind::Solid;
    WaveType wave = WaveType::Ramp;
    double frequency = 1.0;
    double phase = 0.0;
    double exponent = 1.0;                    // poly_wave
    int noise_generator = 0;                  // 1 to 3; 0: the scene's (global_settings)
    glm::dvec3 gradient_axis{0.0, 1.0, 0.0};  // Gradient: the vector given after `gradient`
                                              // (normalised by the parser, as POV-Ray does)
    double agate_turb = 1.0;                  // Agate
    int arms = 0;                             // Spiral1, Spiral2
    glm::dvec3 brick_size{8.0, 3.0, 4.5};     // Brick
    double mortar = 0.5 - 2.0e-10;            // Brick: POV-Ray stores mortar - 2 EPSILON
    double crackle_metric = 2.0;              // Crackle
    double crackle_offset = 0.0;              // Crackle
    glm::dvec3 crackle_form{-1.0, 1.0, 0.0};  // Crackle
    bool crackle_solid = false;               // Crackle
    int iterations = 0;                       // Mandel
    int fractal_exponent = 2;                 // Mandel
    int interior_type = 0;                    // Mandel
    int exterior_type = 1;                    // Mandel
    double interior_factor = 1.0;             // Mandel
    double exterior_factor = 1.0;             // Mandel
    double control0 = 1.0;                    // Quilted
    double control1 = 1.0;                    // Quilted
    double facets_size = 0.1;                 // Facets
    double facets_coords = 0.0;               // Facets
    double facets_metric = 2.0;               // Facets
    // Slope: the direction (unit) and altitude, their weights and ranges (POV-Ray keeps the
    // range as low end and width).
    glm::dvec3 slope_vector{0.0, 1.0, 0.0};
    glm::dvec3 altitude_vector{0.0};
    double slope_len = 1.0, altitude_len = 0.0;
    glm::dvec2 slope_mod{0.0}, altitude_mod{0.0};
    bool slope_point_at = false;
    // PigmentPattern: the pigment whose greyscale is the value.
    std::shared_ptr<const Pigment> pattern_pigment;
    // ImageMap: the image and how it is mapped (image_map, bump_map).
    std::shared_ptr<const ImageData> image;
    int map_type = 0;     // 0 planar, 1 spherical, 2 cylindrical, 5 torus
    int interpolate = 0;  // 0 none, 2 bilinear, 4 normalised distance
    bool once = false;
    double filter_all = 0.0, transmit_all = 0.0;
    bool filter_all_set = false, transmit_all_set = false;
    bool use_index = true;                      // bump_map: use_index (default) or use_colour
    glm::dvec3 image_gradient{1.0, -1.0, 0.0};  // the map's axes (x to u, y to v by default)
    glm::dvec2 image_repeat{1.0};
    glm::dvec2 image_offset{0.0};
    // The warp chain, first applied first: `transform` is the chain's first entry (identity
    // when the first entry is another warp), `warps` the rest, and `turbulence` POV-Ray's
    // classic turbulence, which always comes last.  Every transform given since the last
    // warp composes into `transform`, as POV-Ray composes into its leading transform warp.
    Transform transform;
    std::vector<Warp> warps;
    std::optional<Turbulence> turbulence;
};

struct Pigment;
struct PigmentMapEntry {
    double position = 0.0;
    std::shared_ptr<const Pigment> pigment;
};

/// A pigment: a plain colour or a pattern with a colour map, a pigment map, or the colours
/// of a list pattern (checker, brick, hexagon...).  Patterns are evaluated at the point
/// taken through the warp chain (the parser composes the transforms that apply).
struct Pigment : Pattern {
    Colour colour;                             // Solid
    Colour checker[2];                         // Checker: the two colours, in POV-Ray's order
    std::vector<ColourMapEntry> colour_map;    // also the colours of brick, hexagon... (at 0, 1, 2)
    std::vector<PigmentMapEntry> pigment_map;  // pigment_map, or the pigments of a list pattern
};

struct Normal;
struct NormalMapEntry {
    double position = 0.0;
    std::shared_ptr<const Normal> normal;
};
struct SlopeMapEntry {
    double position = 0.0;
    glm::dvec2 point_slope{0.0};  // height and slope
};

/// A normal perturbation (TNORMAL): a pattern with its bump size, the finite-difference
/// step (accuracy), and a normal map or slope map.
struct Normal : Pattern {
    double amount = 0.5;  // bump_size
    double delta = 0.02;  // accuracy
    bool no_bump_scale = false;
    std::vector<NormalMapEntry> normal_map;
    std::vector<SlopeMapEntry> slope_map;
};

/// POV-Ray 3.7's finish, with POV-Ray's defaults.
struct Finish {
    glm::dvec3 ambient{0.1};
    glm::dvec3 emission{0.0};
    double diffuse = 0.6;
    double diffuse_back = 0.0;
    double brilliance = 1.0;
    double specular = 0.0;
    double roughness = 0.05;  // as written (POV-Ray keeps its inverse)
    double phong = 0.0;
    double phong_size = 40.0;
    double metallic = 0.0;
    double crand = 0.0;
    glm::dvec3 reflection{0.0};                // POV-Ray's reflection_max
    std::optional<glm::dvec3> reflection_min;  // reflection { min, max }: at normal incidence;
                                               // empty: the same as the maximum
    bool reflection_fresnel = false;
    double reflection_falloff = 1.0;
    double reflection_exponent = 1.0;  // 1 / exponent, as POV-Ray stores it
    double reflection_metallic = 0.0;
    bool conserve_energy = false;
    double irid = 0.0;
    double irid_thickness = 0.0;
    double irid_turbulence = 0.0;
    // The old finish-level interior items, promoted to the object's interior (Post_Process).
    double ior = -1.0;  // -1: not given
    double caustics = -1.0;
    double refraction = 1.0;
};

struct Texture;
struct TextureMapEntry {
    double position = 0.0;
    std::shared_ptr<const Texture> texture;
};

/// A texture: a plain one (pigment, normal, finish), possibly with layers below it, or a
/// patterned one (texture_map, tiles), whose pattern chooses and blends textures.
struct Texture {
    Pigment pigment;                    // plain: the top layer's
    Finish finish;                      // plain: the top layer's
    std::optional<Normal> normal;       // plain: the top layer's
    std::vector<Texture> layers_below;  // plain layered texture: the layers under the top one,
                                        // each plain, from the top down
    Pattern pattern;                    // patterned texture: kind != Solid
    std::vector<TextureMapEntry> map;   // patterned texture: its texture_map
    bool no_bump_scale = false;
};

/// What an object is filled with (interior.h): refraction and attenuation of the light
/// that passes through it.
struct Interior {
    double ior = 0.0;  // 0: the atmosphere's (1), as POV-Ray fills it in
    double dispersion = 1.0;
    int dispersion_samples = 7;
    double caustics = 0.0;
    glm::dvec3 fade_colour{0.0};
    double fade_distance = 0.0;
    double fade_power = 0.0;
    double refraction = 1.0;  // the old `refraction` factor (Old_Refract)
    bool hollow = false;
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
    std::shared_ptr<const Interior> interior;  // never null after parsing; children of a union
                                               // share its interior (one medium, as in POV-Ray)
    std::optional<Texture> interior_texture;   // seen where a ray meets the surface from inside
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

/// A light source (POV-Ray's LightSource): a point light, a spotlight or a cylinder light,
/// possibly parallel, possibly an area light, with POV-Ray's defaults.
struct PointLight {
    enum class Kind : std::uint8_t { Point, Spot, Cylinder };
    glm::dvec3 location{0.0};
    glm::dvec3 colour{1.0};
    bool shadowless = false;  // POV-Ray's fill light
    FileLoc loc;
    Kind kind = Kind::Point;
    glm::dvec3 point_at{0.0, 0.0, 1.0};
    double radius = 0.0;     // Spot: cos of the radius angle; Cylinder: the radius
    double falloff = 0.0;    // Spot: cos of the falloff angle; Cylinder: the falloff radius
    double tightness = 0.0;  // POV-Ray's Coeff
    bool parallel = false;
    double fade_distance = 0.0;
    double fade_power = 0.0;
    bool area_light = false;
    glm::dvec3 axis1{0.0, 0.0, 1.0};
    glm::dvec3 axis2{0.0, 1.0, 0.0};
    int size1 = 0, size2 = 0;  // samples along the axes
    int adaptive = 100;        // POV-Ray's Adaptive_Level (100: every sample)
    bool jitter = false;       // parsed; the tracer samples without jitter (deterministic)
    bool circular = false;
    bool orient = false;
    bool area_illumination = false;
    bool media_attenuation = false;  // fog (and media) dim the light on its way
    bool media_interaction = true;
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
    bool assumed_gamma_given = false;  // without it a scene of #version < 3.7 gets no gamma
                                       // handling at all (POV-Ray's legacy gamma mode)
    double language_version = 3.7;     // the last #version
    int max_trace_level = 5;
    glm::dvec3 ambient_light{1.0};
    int noise_generator = 2;  // POV-Ray: 2 from #version 3.5 on, 1 before
    int number_of_waves = 10;
    double adc_bailout = 1.0 / 255.0;
    glm::dvec3 irid_wavelength{0.70, 0.52, 0.48};
};

/// A fog (POV-Ray's FOG): constant (type 1) or ground fog (type 2).
struct Fog {
    int type = 1;
    double distance = 0.0;
    Colour colour;
    double alt = 0.0;     // ground fog: fog_alt
    double offset = 0.0;  // ground fog: fog_offset
    glm::dvec3 up{0.0, 1.0, 0.0};
    std::optional<Turbulence> turbulence;
    double turb_depth = 0.5;
    glm::dvec3 lowered_by{0.0};  // how far the scene was moved down (Mirage_Ground_Height):
                                 // the turbulence is evaluated where POV-Ray's point is
    FileLoc loc;
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
    std::vector<Fog> fogs;  // in file order
    GlobalSettings global;
    std::map<std::string, Declared> symbols;
    // The materials declared at the top level (and in include files): name -> what it is
    // ("texture", "pigment", "finish", "normal", "interior", "material", "colour",
    // "color_map", "pigment_map", "normal_map", "texture_map", "sky_sphere", "fog"), for tools
    // and tests that look at a library of materials.
    std::map<std::string, std::string> material_symbols;
    std::vector<std::string> messages;  // #warning and #debug output, with their place
    std::vector<Skipped> skipped;
    std::vector<CompoundObject> compounds;
    std::vector<UnknownObject> unknown_objects;  // lenient mode only
};

}  // namespace mirage
