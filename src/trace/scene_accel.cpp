#include "trace/scene_accel.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>

#include "util/check.h"

namespace mirage {

namespace {

constexpr int kLeafSize = 2;
constexpr int kBins = 12;
constexpr int kMaxDepth = 64;

/// Whether `a` should replace `b` as the closest hit: nearer, or as near and earlier in the
/// scene (POV-Ray keeps the first of equal depths in its object list).
inline bool better(double t, int primitive, double best_t, int best_primitive) {
    return t < best_t || (t == best_t && primitive < best_primitive);
}

}  // namespace

Result<SceneAccel> SceneAccel::build(const Scene& scene) {
    static std::atomic<std::uint64_t> next_id{1};
    SceneAccel accel;
    accel.id_ = next_id++;
    const int n = static_cast<int>(scene.primitives.size());
    accel.shapes_.reserve(n);
    accel.casts_shadow_.reserve(n);
    for (int i = 0; i < n; ++i) {
        const Primitive& p = scene.primitives[i];
        auto shape = prepare_shape(p);
        if (!shape) return shape.error();
        accel.shapes_.push_back(*shape);
        accel.casts_shadow_.push_back(p.no_shadow ? 0 : 1);
        if (p.compound >= static_cast<int>(scene.compounds.size())) {
            return make_error(scene.file + ": primitive " + std::to_string(i) +
                              " belongs to a compound object the scene does not have");
        }
    }
    // Items: the primitives of their own, then the compounds, in scene order.
    std::vector<Aabb> item_boxes;
    for (int i = 0; i < n; ++i) {
        if (scene.primitives[i].compound >= 0) continue;
        accel.items_.push_back(Item{i, -1});
        item_boxes.push_back(shape_bounds(accel.shapes_[i]));
    }
    for (std::size_t c = 0; c < scene.compounds.size(); ++c) {
        accel.compounds_.push_back(prepare_compound(scene.compounds[c], accel.shapes_));
        accel.items_.push_back(Item{-1, static_cast<int>(c)});
        item_boxes.push_back(accel.compounds_.back().bounds());
    }
    std::vector<Aabb> boxes;
    std::vector<glm::dvec3> centres;
    std::vector<int> finite;
    for (std::size_t k = 0; k < accel.items_.size(); ++k) {
        const Aabb& box = item_boxes[k];
        if (box.empty()) {
            // No surface at all (an intersection of disjoint objects): never hit.
            boxes.push_back(box);
            centres.push_back(glm::dvec3(0.0));
            continue;
        }
        boxes.push_back(box.finite() ? box.padded(1e-9, 1e-12) : box);
        centres.push_back(box.finite() ? box.centre() : glm::dvec3(0.0));
        if (box.finite()) {
            finite.push_back(static_cast<int>(k));
            accel.finite_bounds_.extend(boxes.back());
        } else {
            accel.unbounded_items_.push_back(static_cast<int>(k));
            const int prim = accel.items_[k].primitive;
            if (prim >= 0) accel.unbounded_.push_back(prim);
            const PreparedShape* shape = prim >= 0 ? &accel.shapes_[prim] : nullptr;
            const bool ground = shape && shape->kind == ShapeKind::Plane &&
                                shape->normal.x == 0.0 && shape->normal.z == 0.0 &&
                                shape->pov_distance == 0.0;
            (ground ? accel.ground_plane_ : accel.unbounded_elsewhere_) = true;
        }
    }
    if (!finite.empty()) {
        accel.nodes_.reserve(2 * finite.size());
        accel.build_node(finite, 0, static_cast<int>(finite.size()), 0, boxes, centres);
        accel.order_ = finite;
    }
    accel.boxes_ = std::move(boxes);
    return accel;
}

template <bool kAnyShadow>
bool SceneAccel::intersect_item(const Item& item, const glm::dvec3& origin,
                                const glm::dvec3& direction, double t_min, double t_max,
                                Candidate& hit) const {
    if (item.primitive >= 0) {
        if (kAnyShadow && !casts_shadow_[item.primitive]) return false;
        if (!intersect_shape(shapes_[item.primitive], origin, direction, t_min, t_max, hit.hit)) {
            return false;
        }
        hit.primitive = item.primitive;
        return true;
    }
    const PreparedCompound& c = compounds_[item.compound];
    if (!kAnyShadow) {
        CompoundHit h;
        if (!intersect_compound(c, shapes_, origin, direction, t_min, t_max, h)) return false;
        hit.hit = h.hit;
        hit.primitive = h.primitive;
        return true;
    }
    std::vector<CompoundHit> hits;
    intersect_compound_all(c, shapes_, origin, direction, t_min, t_max, hits);
    for (const CompoundHit& h : hits) {
        if (casts_shadow_[h.primitive]) {
            hit.hit = h.hit;
            hit.primitive = h.primitive;
            return true;
        }
    }
    return false;
}

int SceneAccel::build_node(std::vector<int>& items, int begin, int end, int depth,
                           const std::vector<Aabb>& boxes, const std::vector<glm::dvec3>& centres) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{});
    Aabb box;
    Aabb centre_box;
    for (int i = begin; i < end; ++i) {
        box.extend(boxes[items[i]]);
        centre_box.extend(centres[items[i]]);
    }
    nodes_[index].box = box;
    const int count = end - begin;
    const auto make_leaf = [&] {
        nodes_[index].first = begin;
        nodes_[index].count = count;
        return index;
    };
    if (count <= kLeafSize || depth >= kMaxDepth) {
        return make_leaf();
    }

    // Binned surface area heuristic on the axis where the centres spread most.
    const glm::dvec3 extent = centre_box.hi - centre_box.lo;
    int axis = 0;
    if (extent.y > extent[axis]) axis = 1;
    if (extent.z > extent[axis]) axis = 2;
    if (!(extent[axis] > 0.0)) return make_leaf();  // all centres coincide

    std::array<Aabb, kBins> bin_box;
    std::array<int, kBins> bin_count{};
    const double scale = kBins / extent[axis];
    const auto bin_of = [&](int item) {
        const int b = static_cast<int>((centres[item][axis] - centre_box.lo[axis]) * scale);
        return std::clamp(b, 0, kBins - 1);
    };
    for (int i = begin; i < end; ++i) {
        const int b = bin_of(items[i]);
        bin_box[b].extend(boxes[items[i]]);
        ++bin_count[b];
    }
    std::array<double, kBins> right_cost{};
    Aabb right;
    int right_n = 0;
    for (int b = kBins - 1; b > 0; --b) {
        right.extend(bin_box[b]);
        right_n += bin_count[b];
        right_cost[b] = right.half_area() * right_n;
    }
    Aabb left;
    int left_n = 0;
    int best_split = -1;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int b = 1; b < kBins; ++b) {
        left.extend(bin_box[b - 1]);
        left_n += bin_count[b - 1];
        if (left_n == 0 || left_n == count) continue;
        const double cost = left.half_area() * left_n + right_cost[b];
        if (cost < best_cost) {
            best_cost = cost;
            best_split = b;
        }
    }
    if (best_split < 0) return make_leaf();
    const double leaf_cost = box.half_area() * count;
    if (count <= 4 && best_cost >= leaf_cost) return make_leaf();

    // A stable partition keeps the build independent of anything but the input order.
    const auto middle = std::stable_partition(items.begin() + begin, items.begin() + end,
                                              [&](int item) { return bin_of(item) < best_split; });
    const int mid = static_cast<int>(middle - items.begin());
    MIRAGE_CHECK(mid > begin && mid < end);
    nodes_[index].axis = axis;
    build_node(items, begin, mid, depth + 1, boxes, centres);
    const int second = build_node(items, mid, end, depth + 1, boxes, centres);
    nodes_[index].first = second;
    nodes_[index].count = 0;
    return index;
}

template <bool kAnyShadow>
bool SceneAccel::take_nearer(int k, const glm::dvec3& origin, const glm::dvec3& direction,
                             double t_min, double t_max, Candidate& best, bool& found) const {
    Candidate c;
    const double limit = found ? best.hit.t : t_max;
    if (intersect_item<kAnyShadow>(items_[k], origin, direction, t_min, limit, c) &&
        (!found || better(c.hit.t, c.primitive, best.hit.t, best.primitive))) {
        best = c;
        found = true;
    }
    return found;
}

template <bool kAnyShadow>
bool SceneAccel::traverse(const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                          double t_max, Candidate& best) const {
    bool found = false;
    const auto test = [&](int k) {
        return take_nearer<kAnyShadow>(k, origin, direction, t_min, t_max, best, found);
    };
    // Unbounded items first: a near plane tightens the interval for the hierarchy.
    for (const int k : unbounded_items_) {
        if (test(k) && kAnyShadow) return true;
    }
    if (nodes_.empty()) return found;

    const SlabRay ray(origin, direction);
    std::array<int, kMaxDepth + 8> stack;  // a node at depth k leaves at most k + 2 entries
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        const double limit = found ? best.hit.t : t_max;
        if (!slab_test(node.box, ray, t_min, limit)) continue;
        if (node.count > 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                if (test(order_[k]) && kAnyShadow) return true;
            }
            continue;
        }
        const int first_child = static_cast<int>(&node - nodes_.data()) + 1;
        const int second_child = node.first;
        MIRAGE_CHECK(top + 2 <= static_cast<int>(stack.size()));
        // Visit the child on the ray's side of the split first (pushed last).
        if (direction[node.axis] < 0.0) {
            stack[top++] = first_child;
            stack[top++] = second_child;
        } else {
            stack[top++] = second_child;
            stack[top++] = first_child;
        }
    }
    return found;
}

SurfaceHit SceneAccel::surface_hit(const Candidate& best, const glm::dvec3& origin,
                                   const glm::dvec3& direction) const {
    SurfaceHit hit;
    hit.t = best.hit.t;
    hit.primitive = best.primitive;
    hit.point = origin + best.hit.t * direction;
    hit.normal = shape_normal(shapes_[best.primitive], hit.point, best.hit);
    return hit;
}

std::optional<SurfaceHit> SceneAccel::closest_hit(const glm::dvec3& origin,
                                                  const glm::dvec3& direction, double t_min,
                                                  double t_max) const {
    Candidate best;
    if (!traverse<false>(origin, direction, t_min, t_max, best)) return std::nullopt;
    return surface_hit(best, origin, direction);
}

std::optional<SurfaceHit> SceneAccel::closest_unbounded_hit(const glm::dvec3& origin,
                                                            const glm::dvec3& direction,
                                                            double t_min, double t_max) const {
    Candidate best;
    bool found = false;
    for (const int k : unbounded_items_)
        take_nearer<false>(k, origin, direction, t_min, t_max, best, found);
    if (!found) return std::nullopt;
    return surface_hit(best, origin, direction);
}

namespace {

/// Where the line origin + dz heading (x and z) lies within the box's x and z ranges: [p, q],
/// empty when p > q.  A line in a face's plane (0 * infinity = NaN) counts as inside.
inline void footprint(const Aabb& box, double ox, double oz, double inv_x, double inv_z, double& p,
                      double& q) {
    p = -std::numeric_limits<double>::infinity();
    q = std::numeric_limits<double>::infinity();
    const double x0 = (box.lo.x - ox) * inv_x, x1 = (box.hi.x - ox) * inv_x;
    const double z0 = (box.lo.z - oz) * inv_z, z1 = (box.hi.z - oz) * inv_z;
    for (auto [t0, t1] : {std::pair{x0, x1}, std::pair{z0, z1}}) {
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > p) p = t0;
        if (t1 < q) q = t1;
    }
}

}  // namespace

void SceneAccel::plane_crossings(const glm::dvec3& origin, const glm::dvec2& heading,
                                 std::vector<Crossing>& out) const {
    if (nodes_.empty()) return;
    const double inv_x = 1.0 / heading.x, inv_z = 1.0 / heading.y;
    auto crossing = [&](const Aabb& box, double& p, double& q) {
        footprint(box, origin.x, origin.z, inv_x, inv_z, p, q);
        p = std::max(p, 0.0);
        return p <= q;
    };
    std::array<int, kMaxDepth + 8> stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        double p = 0.0, q = 0.0;
        if (!crossing(node.box, p, q)) continue;
        if (node.count > 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                const Aabb& box = boxes_[order_[k]];
                if (crossing(box, p, q)) out.push_back({p, q, box.lo.y, box.hi.y});
            }
            continue;
        }
        MIRAGE_CHECK(top + 2 <= static_cast<int>(stack.size()));
        stack[top++] = node.first;
        stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
    }
}

bool SceneAccel::region_may_meet(const glm::dvec3& origin, const glm::dvec2& heading,
                                 const PathRegion& region) const {
    if (nodes_.empty()) return false;
    const double inv_x = 1.0 / heading.x, inv_z = 1.0 / heading.y;
    const RegionTest test(region);
    auto meets = [&](const Aabb& box) {
        double p = 0.0, q = 0.0;
        footprint(box, origin.x, origin.z, inv_x, inv_z, p, q);
        return p <= q && test.meets(p, q, box.lo.y, box.hi.y);
    };
    std::array<int, kMaxDepth + 8> stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!meets(node.box)) continue;
        if (node.count > 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                if (meets(boxes_[order_[k]])) return true;
            }
            continue;
        }
        MIRAGE_CHECK(top + 2 <= static_cast<int>(stack.size()));
        stack[top++] = node.first;
        stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
    }
    return false;
}

bool SceneAccel::segment_may_meet(const glm::dvec3& a, const glm::dvec3& b, double margin) const {
    MIRAGE_CHECK(margin >= 0.0);
    if (nodes_.empty()) return false;
    // The segment a + t (b - a), t in [0, 1], against each box grown by the margin (a
    // point, b == a, is tested as a ray in every face's plane: inside where it lies).
    const SlabRay ray(a, b - a);
    const glm::dvec3 grow(margin);
    auto meets = [&](const Aabb& box) {
        Aabb grown;
        grown.lo = box.lo - grow;
        grown.hi = box.hi + grow;
        return slab_test(grown, ray, 0.0, 1.0);
    };
    std::array<int, kMaxDepth + 8> stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!meets(node.box)) continue;
        if (node.count > 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                if (meets(boxes_[order_[k]])) return true;
            }
            continue;
        }
        MIRAGE_CHECK(top + 2 <= static_cast<int>(stack.size()));
        stack[top++] = node.first;
        stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
    }
    return false;
}

bool SceneAccel::any_shadow_hit(const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                                double t_max) const {
    Candidate best;
    return traverse<true>(origin, direction, t_min, t_max, best);
}

}  // namespace mirage
