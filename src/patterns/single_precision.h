// Rounding to single precision, where POV-Ray holds a value as a float (colours, colour map
// positions) and the tracer must round the same way.
#pragma once

#include <glm/glm.hpp>

namespace mirage {

/// `v` rounded to the nearest float.  The empty asm makes the float opaque to the
/// optimiser: GCC 12's SLP vectoriser otherwise drops a double -> float -> double round
/// trip done on two lanes at once, and the rounding silently vanishes.
inline double to_single(double v) {
    float f = static_cast<float>(v);
#if defined(__GNUC__)
    __asm__("" : "+m"(f));
#endif
    return static_cast<double>(f);
}

inline glm::dvec3 to_single(const glm::dvec3& v) {
    return glm::dvec3(to_single(v.x), to_single(v.y), to_single(v.z));
}

}  // namespace mirage
