// The shapes of a scene, in their own space as written in the scene file (POV-Ray 3.7's
// conventions), and the compound objects (CSG, clipped_by, bounded_by) built from them.
// Plain data: the parser fills it, the tracer (shapes/shape_intersect.h) prepares it.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace mirage {

struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 1.0;
};
struct Plane {  // points p with dot(normal, p) = distance; normal normalised by the parser
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double distance = 0.0;
};
struct Box {
    glm::dvec3 corner1{-1.0};
    glm::dvec3 corner2{1.0};
};
struct Cylinder {
    glm::dvec3 base{0.0};
    glm::dvec3 cap{0.0, 1.0, 0.0};
    double radius = 1.0;
    bool open = false;
};
struct Disc {
    glm::dvec3 center{0.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double radius = 1.0;
    double hole_radius = 0.0;
};
struct Cone {
    glm::dvec3 base{0.0};
    double base_radius = 1.0;
    glm::dvec3 cap{0.0, 1.0, 0.0};  // POV-Ray's apex
    double cap_radius = 0.0;
    bool open = false;
};
struct Torus {  // in the xz plane, around the y axis
    double major = 1.0;
    double minor = 0.25;
    bool sturm = false;
};
/// A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0, as POV-Ray's
/// quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }; inside where the left side is <= 0.
struct Quadric {
    glm::dvec3 square{0.0};  // A, B, C
    glm::dvec3 mixed{0.0};   // D (xy), E (xz), F (yz)
    glm::dvec3 linear{0.0};  // G, H, I
    double constant = 0.0;   // J
};
/// poly, cubic and quartic: a polynomial in x, y, z of order 2 to 15 (POV-Ray's term order,
/// descending powers of x, then y, then z); inside where it is < 0.
struct Polynomial {
    int order = 2;
    std::vector<double> coefficients;  // (order + 1)(order + 2)(order + 3) / 6 of them
    bool sturm = false;
};
struct Superellipsoid {
    double e = 1.0;  // east-west exponent
    double n = 1.0;  // north-south exponent
};
/// A triangle mesh (mesh, mesh2, and a single triangle or smooth_triangle).  A mesh with
/// textures on its triangles is parsed into one Mesh per texture.
struct MeshData {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::dvec3> normals;  // unit vertex normals of smooth faces
    struct Face {
        int v[3] = {0, 0, 0};
        int n[3] = {-1, -1, -1};  // indices into normals; -1: flat
    };
    std::vector<Face> faces;
    glm::dvec3 inside_vector{0.0};  // zero: the mesh has no inside
    bool single_precision = true;   // POV-Ray holds meshes in floats, single triangles not
};
struct Mesh {
    std::shared_ptr<const MeshData> data;
};
/// A polygon in the xy plane of its own space (POV-Ray's Compute_Polygon puts it there).
struct Polygon {
    std::vector<glm::dvec2> points;  // the outline(s), closed sub-polygons one after another
    glm::dmat4 plane_to_shape{1.0};  // from its plane to the points as written
    bool degenerate = false;         // collinear or not coplanar points: POV-Ray ignores it
};
enum class SplineKind : std::uint8_t { Linear, Quadratic, Cubic, Bezier };
struct Prism {  // the profile in the xz plane, swept along y from height1 to height2
    SplineKind spline = SplineKind::Linear;
    bool conic = false;  // conic_sweep
    double height1 = 0.0, height2 = 1.0;
    std::vector<glm::dvec2> points;
    bool open = false;
    bool sturm = false;
};
struct Lathe {  // (radius, height) points turned around the y axis
    SplineKind spline = SplineKind::Linear;
    std::vector<glm::dvec2> points;
    bool sturm = false;
};
struct Sor {  // surface of revolution: a cubic r^2(y) through (radius, height) points
    std::vector<glm::dvec2> points;
    bool open = false;
    bool sturm = false;
};
/// A blob: spherical and cylindrical components of a density field, the surface where the
/// field equals the threshold.
struct BlobComponent {
    bool cylinder = false;
    glm::dvec3 centre{0.0};  // sphere; cylinder: the first end
    glm::dvec3 end{0.0};     // cylinder: the second end
    double radius = 1.0;
    double strength = 1.0;
    glm::dmat4 to_world{1.0};  // the component's own transform (shape space)
    glm::dmat4 from_world{1.0};
};
struct Blob {
    double threshold = 1.0;
    std::vector<BlobComponent> components;
    bool sturm = false;
};
/// A height field: heights in [0, 1] on a grid over x, z in [0, 1] (image rows along z).
struct HeightFieldData {
    int width = 0, depth = 0;    // grid points along x and z
    std::vector<float> heights;  // width * depth, row-major along x, z = 0 first
    bool smooth = false;
    double water_level = 0.0;
};
struct HeightField {
    std::shared_ptr<const HeightFieldData> data;
};
struct FunctionCode;  // scene/function.h
/// An isosurface: where the function equals the threshold, inside a box or sphere container.
struct Isosurface {
    std::shared_ptr<const FunctionCode> function;
    bool sphere_container = false;
    glm::dvec3 corner1{-1.0}, corner2{1.0};  // box container
    glm::dvec3 centre{0.0};                  // sphere container
    double radius = 1.0;
    double threshold = 0.0;
    double accuracy = 0.001;
    double max_gradient = 1.1;
    int max_trace = 1;  // 1 to 10 (all_intersections: 10, POV-Ray's ISOSURFACE_MAXTRACE)
    bool all_intersections = false;
    bool open = false;
    bool evaluate = false;  // `evaluate P0, P1, P2`: the gradient adapted along each ray
    glm::dvec3 eval_params{0.0};
    int noise_generator = 2;  // the scene's (global_settings), for f_noise3d; set after parsing
};
/// A TrueType glyph as POV-Ray's truetype.cpp holds it: its contours in em units (font units
/// over unitsPerEm), each with its first point repeated at the end, and the glyph header's
/// extent in font units.
struct GlyphData {
    struct Contour {
        std::vector<double> x, y;           // count + 1 points
        std::vector<unsigned char> on_curve;
    };
    std::vector<Contour> contours;
    int x_min = 0, y_min = 0, x_max = 0, y_max = 0;  // font units
    int units_per_em = 2048;
};
/// Text: glyphs extruded along z from 0 to thickness, each moved to its place in the string
/// (POV-Ray's ProcessNewTTF: advances, left side bearings, kerning, the offset vector).
struct Text {
    struct Placed {
        std::shared_ptr<const GlyphData> glyph;
        glm::dvec3 offset{0.0};
    };
    std::vector<Placed> glyphs;
    double thickness = 1.0;
};

using Shape = std::variant<Sphere, Plane, Box, Cylinder, Disc, Cone, Torus, Quadric, Polynomial,
                           Superellipsoid, Mesh, Polygon, Prism, Lathe, Sor, Blob, HeightField,
                           Isosurface, Text>;

/// The shape's keyword, for messages.
const char* shape_keyword(const Shape& shape);

/// One node of a compound object: a primitive, or a combination of nodes as POV-Ray's
/// csg.cpp evaluates them.  A difference is an intersection whose later children were
/// inverted when it was parsed (POV-Ray does the same), so only three kinds remain.
enum class CsgKind : std::uint8_t {
    Primitive,     ///< one primitive of Scene::primitives
    Union,         ///< every child's surface (a union with clipped_by, bounded_by or inverse)
    Merge,         ///< the children's surfaces outside the other children
    Intersection,  ///< the children's surfaces inside every other child
};

struct CsgNode {
    CsgKind kind = CsgKind::Primitive;
    int primitive = -1;         // Primitive: index into Scene::primitives
    std::vector<int> children;  // Union, Merge, Intersection: indices into CompoundObject::nodes
    std::vector<int> clip;      // clipped_by: a hit counts only inside every one of these
    std::vector<int> bound;     // bounded_by: a ray that meets none of them and starts
                                // outside skips the node (POV-Ray's Ray_In_Bound)
    bool inverted = false;      // POV-Ray's INVERTED flag of a combination: inverted nodes do
                                // not bound an intersection
};

/// An object that is more than one primitive to intersect: CSG, or an object with clipped_by
/// or bounded_by.  Its primitives (Primitive::compound) are intersected only through it.
struct CompoundObject {
    std::vector<CsgNode> nodes;
    int root = 0;
};

}  // namespace mirage
