#include "trace/propagator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/check.h"

namespace mirage {

PathHit StraightPropagator::propagate(const SceneAccel& accel, const RayStart& start) const {
    PathHit path;
    path.direction = start.direction;
    path.segments = 1;
    path.queries = 1;
    if (auto hit =
            accel.closest_hit(start.origin, start.direction, kMinIsectDepth, kPovBoundHuge)) {
        path.hit = true;
        path.surface = *hit;
        path.length = hit->t;
    }
    return path;
}

namespace {

double joint_tolerance(const glm::dvec3& p) {
    const double m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return PolylineMarch::kJointTolerance * (1.0 + m);
}

}  // namespace

PolylineMarch::PolylineMarch(const SceneAccel& accel, const glm::dvec3& origin, double min_depth)
    : accel_(&accel), point_(origin), min_depth_(min_depth) {
    MIRAGE_CHECK(std::isfinite(origin.x) && std::isfinite(origin.y) && std::isfinite(origin.z));
}

bool PolylineMarch::query(const glm::dvec3& direction, double length) {
    ++result_.segments;
    ++result_.queries;
    // Start a little before the joint (but never inside the ignored first stretch of path)
    // and end a little after the next one.
    const double before = length_ == 0.0 ? 0.0 : joint_tolerance(point_);
    const double t_min = std::max(-before, min_depth_ - length_);
    const double t_max =
        std::isinf(length) ? kPovBoundHuge : length + joint_tolerance(point_ + length * direction);
    if (t_min <= t_max) {
        if (auto hit = accel_->closest_hit(point_, direction, t_min, t_max)) {
            result_.hit = true;
            result_.surface = *hit;
            result_.direction = direction;
            result_.length = length_ + hit->t;
            done_ = true;
            return true;
        }
    }
    result_.direction = direction;
    return false;
}

bool PolylineMarch::segment_to(const glm::dvec3& to) {
    MIRAGE_CHECK(!done_);
    MIRAGE_CHECK(std::isfinite(to.x) && std::isfinite(to.y) && std::isfinite(to.z));
    const glm::dvec3 d = to - point_;
    const double length = glm::length(d);
    if (length == 0.0) return false;
    const bool hit = query(d / length, length);
    if (!hit) {
        point_ = to;
        length_ += length;
    }
    return hit;
}

void PolylineMarch::skip_to(const glm::dvec3& to, double length) {
    MIRAGE_CHECK(!done_);
    MIRAGE_CHECK(std::isfinite(to.x) && std::isfinite(to.y) && std::isfinite(to.z));
    MIRAGE_CHECK(length >= 0.0);
    ++result_.segments;
    point_ = to;
    length_ += length;
}

void PolylineMarch::skip_ray(const glm::dvec3& direction) {
    MIRAGE_CHECK(!done_);
    MIRAGE_CHECK(std::abs(glm::length(direction) - 1.0) < 1e-9);
    ++result_.segments;
    result_.direction = direction;
    done_ = true;
}

bool PolylineMarch::ray(const glm::dvec3& direction) {
    MIRAGE_CHECK(!done_);
    MIRAGE_CHECK(std::abs(glm::length(direction) - 1.0) < 1e-9);
    const bool hit = query(direction, std::numeric_limits<double>::infinity());
    done_ = true;
    return hit;
}

}  // namespace mirage
