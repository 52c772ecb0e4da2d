// A bounding volume hierarchy over the parts of one shape (a mesh's triangles, a blob's
// components), in the shape's own space: median splits on the widest axis of the centres.
#pragma once

#include <algorithm>
#include <array>
#include <glm/glm.hpp>
#include <numeric>
#include <vector>

#include "shapes/bounds.h"

namespace mirage {

class LocalBvh {
  public:
    LocalBvh() = default;

    /// Builds over parts with these boxes (the parts are referred to by their index).
    explicit LocalBvh(const std::vector<Aabb>& boxes) {
        order_.resize(boxes.size());
        std::iota(order_.begin(), order_.end(), 0);
        if (boxes.empty()) return;
        nodes_.reserve(2 * boxes.size());
        build(boxes, 0, static_cast<int>(boxes.size()), 0);
    }

    /// Calls visit(part) for every part whose box the ray origin + t direction meets for
    /// some t in [t_min, t_max()]; `t_max` is read again after each visit, so a caller that
    /// keeps only the closest hit can shrink it.
    template <class Visit, class Limit>
    void traverse(const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                  Limit&& t_max, Visit&& visit) const {
        if (nodes_.empty()) return;
        const SlabRay ray(origin, direction);
        std::array<int, 2 * kMaxDepth + 4> stack;
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = nodes_[stack[--top]];
            if (!slab_test(n.box, ray, t_min, t_max())) continue;
            if (n.count > 0) {
                for (int k = n.first; k < n.first + n.count; ++k) visit(order_[k]);
                continue;
            }
            const int self = static_cast<int>(&n - nodes_.data());
            stack[top++] = n.first;
            stack[top++] = self + 1;
        }
    }

    /// Calls visit(part) for every part whose box contains the point (within the box).
    bool empty() const { return nodes_.empty(); }
    Aabb bounds() const { return nodes_.empty() ? Aabb{} : nodes_[0].box; }

  private:
    static constexpr int kLeafSize = 4;
    static constexpr int kMaxDepth = 48;
    struct Node {
        Aabb box;
        int first = 0;  // leaf: first index into order_; inner: the second child
        int count = 0;  // leaf: parts; inner: 0 (the first child follows the node)
    };

    int build(const std::vector<Aabb>& boxes, int begin, int end, int depth) {
        const int index = static_cast<int>(nodes_.size());
        nodes_.push_back(Node{});
        Aabb box, centres;
        for (int i = begin; i < end; ++i) {
            box.extend(boxes[order_[i]]);
            centres.extend(boxes[order_[i]].centre());
        }
        nodes_[index].box = box;
        if (end - begin <= kLeafSize || depth >= kMaxDepth) {
            nodes_[index].first = begin;
            nodes_[index].count = end - begin;
            return index;
        }
        const glm::dvec3 e = centres.hi - centres.lo;
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        const int mid = (begin + end) / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                         [&](int a, int b) {
                             const double ca = boxes[a].lo[axis] + boxes[a].hi[axis];
                             const double cb = boxes[b].lo[axis] + boxes[b].hi[axis];
                             return ca < cb || (ca == cb && a < b);
                         });
        build(boxes, begin, mid, depth + 1);
        const int second = build(boxes, mid, end, depth + 1);
        nodes_[index].first = second;
        nodes_[index].count = 0;
        return index;
    }

    std::vector<Node> nodes_;
    std::vector<int> order_;
};

}  // namespace mirage
