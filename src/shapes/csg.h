// Compound objects (scene/shapes.h: CSG, clipped_by, bounded_by) intersected as POV-Ray 3.7's
// csg.cpp and objects.cpp do: every hit of every child, kept when the other children's inside
// tests say so (intersection: inside all of them; merge: inside none), then when inside every
// clipping object; a node with bounded_by objects is tested only by rays that meet one or
// start inside (Ray_In_Bound).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "scene/shapes.h"
#include "shapes/bounds.h"
#include "shapes/shape_intersect.h"

namespace mirage {

/// A compound object ready for ray queries: its nodes and, per node, where its hits and its
/// inside can lie.
struct PreparedCompound {
    std::vector<CsgNode> nodes;
    std::vector<Aabb> surface_bounds;  // per node: every hit lies in it
    std::vector<Aabb> inside_bounds;   // per node: every inside point lies in it
    int root = 0;
    Aabb bounds() const { return surface_bounds[root]; }
};

/// A hit of a compound: on which primitive, where along the ray.
struct CompoundHit {
    ShapeHit hit;
    int primitive = -1;
};

/// Prepares a compound whose primitives are prepared in `shapes` (indexed like
/// Scene::primitives).
PreparedCompound prepare_compound(const CompoundObject& compound,
                                  const std::vector<PreparedShape>& shapes);

/// Every hit of the compound with t in [t_min, t_max] (unit direction).
void intersect_compound_all(const PreparedCompound& compound,
                            const std::vector<PreparedShape>& shapes, const glm::dvec3& origin,
                            const glm::dvec3& direction, double t_min, double t_max,
                            std::vector<CompoundHit>& hits);

/// The closest of them (ties to the primitive first in the scene); false when there is none.
bool intersect_compound(const PreparedCompound& compound, const std::vector<PreparedShape>& shapes,
                        const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                        double t_max, CompoundHit& hit);

/// POV-Ray's Inside_Object for the compound: its clipping objects' insides and its own.
bool inside_compound(const PreparedCompound& compound, const std::vector<PreparedShape>& shapes,
                     const glm::dvec3& point);

}  // namespace mirage
