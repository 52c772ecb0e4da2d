// The scene's geometry prepared for ray queries: a bounding volume hierarchy over the
// finite objects (primitives of their own and compound objects) plus a list of the unbounded
// ones (planes and the like), answering the closest hit along a segment and whether any
// shadow-casting primitive lies on one.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "atmosphere/sampler.h"
#include "scene/scene.h"
#include "shapes/bounds.h"
#include "shapes/csg.h"
#include "shapes/shape_intersect.h"
#include "util/result.h"

namespace mirage {

/// Where a ray met a surface.
struct SurfaceHit {
    double t = 0.0;          // distance from the query's origin along its unit direction
    glm::dvec3 point{0.0};   // world point, origin + t direction
    glm::dvec3 normal{0.0};  // unit geometric normal as the shape defines it (outward,
                             // flipped for `inverse`), not turned toward the ray
    int primitive = -1;      // index into Scene::primitives (for a compound object, the
                             // primitive of it that was hit)
};

class SceneAccel {
  public:
    /// Prepares every primitive of the scene; fails with the first one that cannot be
    /// prepared (its message names the place in the scene file).
    static Result<SceneAccel> build(const Scene& scene);

    /// The closest hit with t in the closed interval [t_min, t_max] along origin + t
    /// direction (direction of unit length), or nothing.  Exact ties go to the primitive
    /// that comes first in the scene, whatever the traversal order.  Thread-safe.
    std::optional<SurfaceHit> closest_hit(const glm::dvec3& origin, const glm::dvec3& direction,
                                          double t_min, double t_max) const;

    /// Whether a primitive that casts shadows (not `no_shadow`) is hit for some t in
    /// [t_min, t_max].  Thread-safe.
    bool any_shadow_hit(const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                        double t_max) const;

    /// The closest hit among the unbounded objects only (planes and the like, and unbounded
    /// compounds): what a segment that misses finite_bounds() can meet.
    std::optional<SurfaceHit> closest_unbounded_hit(const glm::dvec3& origin,
                                                    const glm::dvec3& direction, double t_min,
                                                    double t_max) const;

    /// Where a vertical plane crosses the box of a finite primitive: the plane through
    /// `origin` along the unit horizontal `heading` (x, z); dz is measured from origin along
    /// heading, y is the world's.
    struct Crossing {
        double dz_lo, dz_hi;  // where the plane's line is within the box's x and z ranges
        double y_lo, y_hi;    // the box's heights
    };

    /// The crossings of the boxes of the finite primitives at dz >= 0, in no particular order
    /// (appended to `out`).  Thread-safe.
    void plane_crossings(const glm::dvec3& origin, const glm::dvec2& heading,
                         std::vector<Crossing>& out) const;

    /// Whether the box of a finite primitive meets a region of a vertical plane (as
    /// plane_crossings and region_meets_rectangle would say).  Thread-safe.
    bool region_may_meet(const glm::dvec3& origin, const glm::dvec2& heading,
                         const PathRegion& region) const;

    /// Whether the box of a finite primitive, grown by `margin` on every side, meets the
    /// segment from a to b: false only when every point within `margin` of the segment is
    /// outside every finite primitive's box, so no query along it can meet one.  Thread-safe.
    bool segment_may_meet(const glm::dvec3& a, const glm::dvec3& b, double margin) const;

    /// Whether a plane covers the ground, y = 0 (with normal +y or -y).
    bool has_ground_plane() const { return ground_plane_; }
    /// Whether an unbounded primitive other than a ground plane is in the scene (a plane
    /// elsewhere: it may be met anywhere).
    bool unbounded_elsewhere() const { return unbounded_elsewhere_; }

    /// A number no other built SceneAccel has (a copy keeps it: it holds the same scene).
    std::uint64_t id() const { return id_; }
    /// The hierarchy's items (the primitives of their own and the compound objects, CSG and
    /// the like) and item k's box as the hierarchy holds it (padded; unbounded for planes,
    /// empty for an object with no surface).
    int box_count() const { return static_cast<int>(boxes_.size()); }
    const Aabb& item_box(int k) const { return boxes_[k]; }

    int primitive_count() const { return static_cast<int>(shapes_.size()); }
    /// The compound objects (Scene::compounds) and POV-Ray's inside test of one of them.
    int compound_count() const { return static_cast<int>(compounds_.size()); }
    bool inside_compound_object(int compound, const glm::dvec3& point) const {
        return inside_compound(compounds_[compound], shapes_, point);
    }
    const PreparedShape& shape(int primitive) const { return shapes_[primitive]; }
    /// World bounds of the finite objects (empty when there are none).
    const Aabb& finite_bounds() const { return finite_bounds_; }
    /// Primitives of their own kept outside the hierarchy because they are unbounded
    /// (unbounded compound objects are outside it too, but not listed here).
    const std::vector<int>& unbounded() const { return unbounded_; }

  private:
    /// What the hierarchy holds: a primitive of its own or a compound object.
    struct Item {
        int primitive = -1;  // >= 0: a primitive of its own
        int compound = -1;   // >= 0: index into compounds_
    };
    struct Node {
        Aabb box;
        int first = 0;  // leaf: first index into order_; inner: index of the second child
        int count = 0;  // leaf: number of primitives; inner: 0 (first child follows the node)
        int axis = 0;   // inner: the split axis, to visit the nearer child first
    };
    struct Candidate {
        ShapeHit hit;
        int primitive = -1;
    };
    /// The closest hit of one item within [t_min, t_max] (for shadows: of a primitive that
    /// casts one).
    template <bool kAnyShadow>
    bool intersect_item(const Item& item, const glm::dvec3& origin, const glm::dvec3& direction,
                        double t_min, double t_max, Candidate& hit) const;
    /// The surface hit a candidate stands for, with its point and normal.
    SurfaceHit surface_hit(const Candidate& best, const glm::dvec3& origin,
                           const glm::dvec3& direction) const;
    /// Item k's hit, if nearer than `best` (when `found`) or within t_max: then it is `best`.
    template <bool kAnyShadow>
    bool take_nearer(int k, const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                     double t_max, Candidate& best, bool& found) const;

    int build_node(std::vector<int>& items, int begin, int end, int depth,
                   const std::vector<Aabb>& boxes, const std::vector<glm::dvec3>& centres);
    template <bool kAnyShadow>
    bool traverse(const glm::dvec3& origin, const glm::dvec3& direction, double t_min, double t_max,
                  Candidate& best) const;

    std::vector<PreparedShape> shapes_;
    std::vector<std::uint8_t> casts_shadow_;
    std::vector<PreparedCompound> compounds_;
    std::vector<Item> items_;
    std::vector<Node> nodes_;
    std::vector<int> order_;            // finite items in leaf order
    std::vector<int> unbounded_items_;  // indices into items_
    std::vector<int> unbounded_;
    std::vector<Aabb> boxes_;  // per item, as the hierarchy holds it (padded)
    Aabb finite_bounds_;
    bool ground_plane_ = false;
    bool unbounded_elsewhere_ = false;
    std::uint64_t id_ = 0;
};

}  // namespace mirage
