#include "shapes/csg.h"

#include <algorithm>
#include <limits>

#include "util/check.h"

namespace mirage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Aabb infinite() {
    Aabb b;
    b.lo = glm::dvec3(-kInf);
    b.hi = glm::dvec3(kInf);
    return b;
}

Aabb intersect_boxes(const Aabb& a, const Aabb& b) {
    Aabb out;
    out.lo = glm::max(a.lo, b.lo);
    out.hi = glm::min(a.hi, b.hi);
    return out;
}

double volume(const Aabb& b) {
    if (b.empty()) return 0.0;
    const glm::dvec3 e = b.hi - b.lo;
    return e.x * e.y * e.z;
}

struct Query {
    const PreparedCompound& c;
    const std::vector<PreparedShape>& shapes;
    glm::dvec3 origin;
    glm::dvec3 direction;
    SlabRay slab;
};

bool inside_node(const PreparedCompound& c, const std::vector<PreparedShape>& shapes, int index,
                 const glm::dvec3& p);

// POV-Ray's Point_In_Clip.
bool in_clip(const PreparedCompound& c, const std::vector<PreparedShape>& shapes,
             const CsgNode& node, const glm::dvec3& p) {
    for (const int k : node.clip) {
        if (!inside_node(c, shapes, k, p)) return false;
    }
    return true;
}

bool inside_node(const PreparedCompound& c, const std::vector<PreparedShape>& shapes, int index,
                 const glm::dvec3& p) {
    const CsgNode& node = c.nodes[index];
    if (!in_clip(c, shapes, node, p)) return false;  // POV-Ray's Inside_Object
    if (!c.inside_bounds[index].empty() && c.inside_bounds[index].finite()) {
        const Aabb& b = c.inside_bounds[index];
        if (p.x < b.lo.x || p.y < b.lo.y || p.z < b.lo.z || p.x > b.hi.x || p.y > b.hi.y ||
            p.z > b.hi.z) {
            // Not inside: a cheap answer where the bounds allow it (the tests below would say
            // the same, up to their tolerances, which reach at most 1e-10 past the surface).
            const double pad =
                1e-9 * (1.0 + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
            if (p.x < b.lo.x - pad || p.y < b.lo.y - pad || p.z < b.lo.z - pad ||
                p.x > b.hi.x + pad || p.y > b.hi.y + pad || p.z > b.hi.z + pad) {
                return false;
            }
        }
    }
    switch (node.kind) {
        case CsgKind::Primitive:
            return inside_shape(shapes[node.primitive], p);
        case CsgKind::Union:
        case CsgKind::Merge:
            for (const int k : node.children) {
                if (inside_node(c, shapes, k, p)) return true;
            }
            return false;
        case CsgKind::Intersection:
            for (const int k : node.children) {
                if (!inside_node(c, shapes, k, p)) return false;
            }
            return true;
    }
    return false;
}

void node_hits(const Query& q, int index, double t_min, double t_max,
               std::vector<CompoundHit>& out);

// POV-Ray's Ray_In_Bound: the ray meets every bounding object somewhere ahead or starts in it.
bool ray_in_bound(const Query& q, const CsgNode& node, double t_min) {
    std::vector<CompoundHit> tmp;
    for (const int k : node.bound) {
        tmp.clear();
        node_hits(q, k, t_min, kPovBoundHuge, tmp);
        if (tmp.empty() && !inside_node(q.c, q.shapes, k, q.origin)) return false;
    }
    return true;
}

void node_hits(const Query& q, int index, double t_min, double t_max,
               std::vector<CompoundHit>& out) {
    const PreparedCompound& c = q.c;
    const CsgNode& node = c.nodes[index];
    const Aabb& box = c.surface_bounds[index];
    if (box.empty() || !slab_test(box, q.slab, t_min, t_max)) return;
    if (!node.bound.empty() && !ray_in_bound(q, node, t_min)) return;
    const std::size_t first = out.size();
    switch (node.kind) {
        case CsgKind::Primitive: {
            std::vector<ShapeHit> hits;
            intersect_shape_all(q.shapes[node.primitive], q.origin, q.direction, t_min, t_max,
                                hits);
            for (const ShapeHit& h : hits) out.push_back(CompoundHit{h, node.primitive});
            break;
        }
        case CsgKind::Union:
            for (const int k : node.children) node_hits(q, k, t_min, t_max, out);
            break;
        case CsgKind::Intersection:
        case CsgKind::Merge: {
            const bool intersection = node.kind == CsgKind::Intersection;
            std::vector<CompoundHit> local;
            for (const int k : node.children) {
                local.clear();
                node_hits(q, k, t_min, t_max, local);
                for (const CompoundHit& h : local) {
                    const glm::dvec3 p = q.origin + h.hit.t * q.direction;
                    bool keep = true;
                    for (const int other : node.children) {
                        if (other == k) continue;
                        const bool in = inside_node(c, q.shapes, other, p);
                        if (intersection ? !in : in) {
                            keep = false;
                            break;
                        }
                    }
                    if (keep) out.push_back(h);
                }
            }
            break;
        }
    }
    if (node.clip.empty()) return;
    // Keep only the hits inside every clipping object.
    std::size_t kept = first;
    for (std::size_t i = first; i < out.size(); ++i) {
        const glm::dvec3 p = q.origin + out[i].hit.t * q.direction;
        if (in_clip(c, q.shapes, node, p)) out[kept++] = out[i];
    }
    out.resize(kept);
}

}  // namespace

PreparedCompound prepare_compound(const CompoundObject& compound,
                                  const std::vector<PreparedShape>& shapes) {
    PreparedCompound c;
    c.nodes = compound.nodes;
    c.root = compound.root;
    const std::size_t n = c.nodes.size();
    c.surface_bounds.resize(n);
    c.inside_bounds.resize(n);
    // Children, clipping and bounding objects come before the nodes that use them.
    for (std::size_t i = 0; i < n; ++i) {
        const CsgNode& node = c.nodes[i];
        const auto check_order = [&](const std::vector<int>& list) {
            for (const int k : list) MIRAGE_CHECK(k >= 0 && static_cast<std::size_t>(k) < i);
        };
        check_order(node.children);
        check_order(node.clip);
        check_order(node.bound);
        Aabb surface, inside;
        switch (node.kind) {
            case CsgKind::Primitive:
                surface = shape_bounds(shapes[node.primitive]);
                inside = shape_inside_bounds(shapes[node.primitive]);
                break;
            case CsgKind::Union:
            case CsgKind::Merge:
                for (const int k : node.children) {
                    surface.extend(c.surface_bounds[k]);
                    inside.extend(c.inside_bounds[k]);
                }
                break;
            case CsgKind::Intersection: {
                // POV-Ray's CSG::Compute_BBox: the children's boxes intersected, inverted ones
                // left out (their inside is unbounded).
                Aabb region = infinite();
                for (const int k : node.children)
                    region = intersect_boxes(region, c.inside_bounds[k]);
                for (const int k : node.children) surface.extend(c.surface_bounds[k]);
                surface = intersect_boxes(surface, region);
                inside = region;
                break;
            }
        }
        if (node.inverted) inside = infinite();
        for (const int k : node.clip) {
            surface = intersect_boxes(surface, c.inside_bounds[k]);
            inside = intersect_boxes(inside, c.inside_bounds[k]);
        }
        if (!node.bound.empty()) {
            // POV-Ray's Parse_Object_Mods: the bounding objects' box when it is the smaller.
            Aabb region = infinite();
            for (const int k : node.bound) region = intersect_boxes(region, c.inside_bounds[k]);
            if (!region.empty() &&
                (!surface.finite() || (region.finite() && volume(region) < volume(surface)))) {
                if (region.finite()) surface = region;
            }
        }
        c.surface_bounds[i] = surface;
        c.inside_bounds[i] = inside;
    }
    return c;
}

void intersect_compound_all(const PreparedCompound& compound,
                            const std::vector<PreparedShape>& shapes, const glm::dvec3& origin,
                            const glm::dvec3& direction, double t_min, double t_max,
                            std::vector<CompoundHit>& hits) {
    const Query q{compound, shapes, origin, direction, SlabRay(origin, direction)};
    node_hits(q, compound.root, t_min, t_max, hits);
}

bool intersect_compound(const PreparedCompound& compound, const std::vector<PreparedShape>& shapes,
                        const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                        double t_max, CompoundHit& hit) {
    std::vector<CompoundHit> hits;
    intersect_compound_all(compound, shapes, origin, direction, t_min, t_max, hits);
    if (hits.empty()) return false;
    const CompoundHit* best = &hits[0];
    for (const CompoundHit& h : hits) {
        if (h.hit.t < best->hit.t || (h.hit.t == best->hit.t && h.primitive < best->primitive)) {
            best = &h;
        }
    }
    hit = *best;
    return true;
}

bool inside_compound(const PreparedCompound& compound, const std::vector<PreparedShape>& shapes,
                     const glm::dvec3& point) {
    return inside_node(compound, shapes, compound.root, point);
}

}  // namespace mirage
