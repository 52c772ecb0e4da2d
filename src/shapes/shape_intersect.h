// Ray-shape intersection for the scene's primitives under affine transforms, with POV-Ray
// 3.7's own tests and tolerances (backend/shape/*.cpp): every hit along a ray (CSG needs them
// all), the closest one, inside tests (POV-Ray's Inside, for CSG and clipped_by), surface
// normals and world-space bounds.  Simple shapes live in PreparedShape itself; meshes,
// prisms, lathes, blobs and the like implement ComplexShape (src/shapes/).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "scene/scene.h"
#include "shapes/bounds.h"
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
    Cone,      ///< canonical: x^2 + y^2 = z^2, z from cone_dist to 1
    Torus,     ///< in its own space
    Quadric,   ///< in its own space
    Complex,   ///< a ComplexShape
};

/// Where a ray met a shape: distance along the (unit) ray and what the normal needs (which
/// part was hit; for complex shapes an index and two parameters of their own).
struct ShapeHit {
    double t = 0.0;
    int part = 0;
    int index = 0;
    glm::dvec2 uv{0.0};
};

/// Receives a shape's hits along a query: keeps those with t in [t_min, t_max], either all of
/// them (into a list) or only the closest.
class HitSink {
  public:
    HitSink(double t_min, double t_max, std::vector<ShapeHit>* all = nullptr)
        : t_min_(t_min), t_max_(t_max), all_(all) {}
    void add(double t, int part = 0, int index = 0, glm::dvec2 uv = glm::dvec2(0.0)) {
        if (!(t >= t_min_ && t <= t_max_)) return;
        if (all_) {
            all_->push_back(ShapeHit{t, part, index, uv});
            found_ = true;
        } else if (!found_ || t < closest_.t) {
            closest_ = ShapeHit{t, part, index, uv};
            found_ = true;
        }
    }
    double t_min() const { return t_min_; }
    /// The farthest hit still wanted: the closest so far when only that is kept.
    double t_max() const { return !all_ && found_ ? closest_.t : t_max_; }
    bool found() const { return found_; }
    const ShapeHit& closest() const { return closest_; }

  private:
    double t_min_, t_max_;
    std::vector<ShapeHit>* all_;
    bool found_ = false;
    ShapeHit closest_;
};

/// A shape whose data does not fit PreparedShape.  World space in and out; thread-safe.
class ComplexShape {
  public:
    virtual ~ComplexShape() = default;
    /// Every hit of the ray origin + t direction (unit direction) within the sink's range.
    virtual void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                           HitSink& sink) const = 0;
    /// POV-Ray's Inside, without `inverse`.
    virtual bool inside(const glm::dvec3& point) const = 0;
    /// The unit normal at a hit, outward, without `inverse`.
    virtual glm::dvec3 normal(const glm::dvec3& point, const ShapeHit& hit) const = 0;
    /// Where its surface lies (infinite sides for unbounded shapes).
    virtual Aabb bounds() const = 0;
};

/// A primitive's shape prepared for intersection.  POV-Ray keeps spheres, planes and
/// axis-aligned boxes in world space under the transforms that allow it, and the others in a
/// canonical space with a matrix; so do we, which keeps its arithmetic where it matters.
struct PreparedShape {
    ShapeKind kind = ShapeKind::Sphere;
    bool inverse = false;              // POV-Ray's `inverse`: the normal and the inside flip
    bool open = false;                 // Cylinder, Cone: no caps
    glm::dvec3 centre{0.0};            // Sphere, Ellipsoid (own space)
    double radius = 1.0;               // Sphere, Ellipsoid
    double radius_sq = 1.0;            // Sphere, Ellipsoid
    glm::dvec3 normal{0.0, 1.0, 0.0};  // Plane: unit normal; Disc: unit world normal
    double pov_distance = 0.0;         // Plane: POV-Ray's Distance, -dot(normal, point on plane)
    glm::dvec3 lo{-1.0};               // Box, TransformedBox: corners, lo <= hi
    glm::dvec3 hi{1.0};
    double inner_sq = 0.0;                        // Disc: hole radius squared
    double outer_sq = 1.0;                        // Disc: radius squared
    double cone_dist = 0.0;                       // Cone: the small end's z (and radius)
    double major = 1.0, minor = 0.25;             // Torus
    bool sturm = false;                           // Torus
    double q[10] = {};                            // Quadric: A B C D E F G H I J in its own space
    glm::dmat4 world_to_local{1.0};               // the kinds with an own or canonical space
    glm::dmat4 local_to_world{1.0};               // its inverse (for bounds)
    glm::dmat3 normal_to_world{1.0};              // transpose of world_to_local's linear part
    std::shared_ptr<const ComplexShape> complex;  // Complex
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

/// Every hit with t in [t_min, t_max], appended to `hits` in no particular order (POV-Ray's
/// All_Intersections, for CSG).
void intersect_shape_all(const PreparedShape& shape, const glm::dvec3& origin,
                         const glm::dvec3& direction, double t_min, double t_max,
                         std::vector<ShapeHit>& hits);

/// POV-Ray's Inside test, `inverse` included: for planes the half-space below, for discs the
/// half-space behind, for open cylinders and cones their closed inside.
bool inside_shape(const PreparedShape& shape, const glm::dvec3& point);

/// The unit surface normal at a hit point, as POV-Ray computes it: outward, flipped for
/// `inverse`, not yet turned toward the viewer.
glm::dvec3 shape_normal(const PreparedShape& shape, const glm::dvec3& point, const ShapeHit& hit);
glm::dvec3 shape_normal(const PreparedShape& shape, const glm::dvec3& point, int part);

/// POV-Ray's Sphere::Intersect: the two depths along a unit direction, or false for a miss
/// (including rays that only graze, half chord^2 <= EPSILON; with `allow_behind` false also
/// a ray outside the sphere moving away from it).
bool sphere_roots(const glm::dvec3& centre, double radius_sq, const glm::dvec3& origin,
                  const glm::dvec3& direction, bool allow_behind, double& t1, double& t2);

/// POV-Ray's Box::Intersect (boxes.cpp) in the box's own space, unnormalised direction: the
/// entry and exit depths with the sides hit (POV-Ray's numbers: 2 axis + 1 low, 2 axis + 2
/// high), the sides disambiguated where the ray passes within CLOSE_TOLERANCE of an edge.
/// `t_start` is where the entry depth starts (POV-Ray: 0).
bool box_roots(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& p, const glm::dvec3& d,
               double t_start, double& t_near, int& s_near, double& t_far, int& s_far);

/// Bounds of the surface in world space; unbounded (infinite) for planes and the like.
Aabb shape_bounds(const PreparedShape& shape);

/// Bounds of the inside (what an intersection with the shape can reach): the surface's bounds
/// for closed finite shapes, the half-space for axis-aligned planes, unbounded for inverted
/// and open shapes.  POV-Ray's CSG intersection bounds (csg.cpp, Compute_BBox).
Aabb shape_inside_bounds(const PreparedShape& shape);

}  // namespace mirage
