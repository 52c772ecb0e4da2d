// Axis-aligned bounding boxes in world space and the ray-box slab test the BVH uses.
#pragma once

#include <glm/glm.hpp>
#include <limits>

namespace mirage {

/// A box [lo, hi]; empty when lo > hi on some axis (the default), unbounded when a side is
/// infinite.
struct Aabb {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool finite() const;
    void extend(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    glm::dvec3 centre() const { return 0.5 * (lo + hi); }
    /// Half the surface area (the SAH cost needs only ratios); 0 when empty.
    double half_area() const;
    /// The box grown on every side by `relative` times the larger of its largest extent and its
    /// largest coordinate, plus `absolute`.
    Aabb padded(double relative, double absolute) const;
};

/// A ray prepared for slab tests: origin and the reciprocal of its direction (infinite for
/// a zero component).
struct SlabRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 inv_direction{0.0};
    SlabRay() = default;
    SlabRay(const glm::dvec3& o, const glm::dvec3& d) : origin(o), inv_direction(1.0 / d) {}
};

/// Whether the ray meets the box for some t in [t_min, t_max].  A ray lying in a face's plane
/// (0 * infinity = NaN) counts as inside that slab: the comparisons ignore NaN.
inline bool slab_test(const Aabb& box, const SlabRay& ray, double t_min, double t_max) {
    for (int axis = 0; axis < 3; ++axis) {
        double t0 = (box.lo[axis] - ray.origin[axis]) * ray.inv_direction[axis];
        double t1 = (box.hi[axis] - ray.origin[axis]) * ray.inv_direction[axis];
        if (t0 > t1) {
            const double t = t0;
            t0 = t1;
            t1 = t;
        }
        t_min = t0 > t_min ? t0 : t_min;
        t_max = t1 < t_max ? t1 : t_max;
        if (t_min > t_max) return false;
    }
    return true;
}

}  // namespace mirage
