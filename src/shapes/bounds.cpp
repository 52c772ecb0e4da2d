#include "shapes/bounds.h"

#include <algorithm>
#include <cmath>

namespace mirage {

bool Aabb::finite() const {
    return !empty() && std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) &&
           std::isfinite(hi.x) && std::isfinite(hi.y) && std::isfinite(hi.z);
}

double Aabb::half_area() const {
    if (empty()) return 0.0;
    const glm::dvec3 e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

Aabb Aabb::padded(double relative, double absolute) const {
    if (empty()) return *this;
    const glm::dvec3 e = hi - lo;
    const glm::dvec3 m = glm::max(glm::abs(lo), glm::abs(hi));
    const double scale = std::max({e.x, e.y, e.z, m.x, m.y, m.z});
    const double pad = relative * scale + absolute;
    Aabb out = *this;
    out.lo -= glm::dvec3(pad);
    out.hi += glm::dvec3(pad);
    return out;
}

}  // namespace mirage
