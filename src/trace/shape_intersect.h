// Ray-shape intersection for the primitives of the scene subset (sphere, plane, box,
// cylinder, disc) under affine transforms, with POV-Ray 3.7's own tests and tolerances
// (backend/shape/*.cpp), their surface normals and world-space bounds.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "scene/scene.h"
#include "trace/bounds.h"
#include "util/result.h"

namespace mirage {

/// POV-Ray's EPSILON (configbackend.h): below it a direction component counts as parallel.
inline constexpr double kPovEpsilon = 1.0e-10;
/// POV-Ray's MAX_DISTANCE: spheres, planes, cylinders and discs ignore hits this far away.
inline constexpr double kPovMaxDistance = 1.0e7;
/// POV-Ray's BOUND_HUGE: no hit is farther (the box's initial far limit, an empty hit's depth).
inline constexpr double kPovBoundHuge = 2.0e10;

enum class ShapeKind : std::uint8_t {
    Sphere,     ///< world-space sphere (no transform, or a similarity)
    Ellipsoid,  ///< sphere under a general affine map: intersected in its own space
    Plane,      ///< world-space plane
    Box,        ///< world-space axis-aligned box
    TransformedBox,
    Cylinder,  ///< canonical: radius 1, z from 0 to 1
    Disc,      ///< canonical: in z = 0, normal +z, centre at the origin
};

/// A primitive's shape prepared for intersection.  POV-Ray keeps spheres, planes and
/// axis-aligned boxes in world space under the transforms that allow it, and the others in a
/// canonical space with a matrix; so do we, which keeps its arithmetic where it matters.
struct PreparedShape {
    ShapeKind kind = ShapeKind::Sphere;
    bool inverse = false;              // the normal is flipped (POV-Ray's `inverse`)
    bool open = false;                 // Cylinder: no caps
    glm::dvec3 centre{0.0};            // Sphere, Ellipsoid (own space)
    double radius = 1.0;               // Sphere, Ellipsoid
    double radius_sq = 1.0;            // Sphere, Ellipsoid
    glm::dvec3 normal{0.0, 1.0, 0.0};  // Plane: unit normal; Disc: unit world normal
    double pov_distance = 0.0;         // Plane: POV-Ray's Distance, -dot(normal, point on plane)
    glm::dvec3 lo{-1.0};               // Box, TransformedBox: corners, lo <= hi
    glm::dvec3 hi{1.0};
    double inner_sq = 0.0;            // Disc: hole radius squared
    double outer_sq = 1.0;            // Disc: radius squared
    glm::dmat4 world_to_local{1.0};   // Ellipsoid, TransformedBox, Cylinder, Disc
    glm::dmat4 local_to_world{1.0};   // its inverse (for bounds)
    glm::dmat3 normal_to_world{1.0};  // transpose of world_to_local's linear part
};

/// Where a ray met a shape: distance along the (unit) ray and, for boxes and cylinders,
/// which part was hit.
struct ShapeHit {
    double t = 0.0;
    int part = 0;
};

/// Prepares a primitive's shape.  Fails (naming the primitive's place) for what POV-Ray also
/// refuses or cannot render: a zero plane or disc normal, a cylinder whose ends coincide, a
/// transform that cannot be inverted.
Result<PreparedShape> prepare_shape(const Primitive& primitive);

/// The closest hit with t in [t_min, t_max] of the ray origin + t direction (unit direction),
/// with POV-Ray's tests: grazing rays that POV-Ray misses are missed.  POV-Ray's tiny lower
/// depth tolerances (1e-6) are left to t_min, which the tracer sets to its 1e-4 minimum.
bool intersect_shape(const PreparedShape& shape, const glm::dvec3& origin,
                     const glm::dvec3& direction, double t_min, double t_max, ShapeHit& hit);

/// The unit surface normal at a hit point, as POV-Ray computes it: outward, flipped for
/// `inverse`, not yet turned toward the viewer.
glm::dvec3 shape_normal(const PreparedShape& shape, const glm::dvec3& point, int part);

/// Bounds in world space; unbounded (infinite) for planes.
Aabb shape_bounds(const PreparedShape& shape);

}  // namespace mirage
