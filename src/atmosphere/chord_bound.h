// The chord test both samplers share (sampler.cpp for the exponential rays, path_sampler.cpp
// for any exact path).
#pragma once

#include <algorithm>

#include "atmosphere/sampler.h"

namespace mirage {

/// Paths are followed at most this far (m); beyond, they continue straight.  Far larger than
/// any scene, and small enough that no coordinate overflows.
inline constexpr double kMaxSampleDistance = 1e9;

/// Whether the chord over the dz interval [p, q] keeps the tolerance when |y''| <= m there.
/// Linear interpolation errs by at most m (x - p)(q - x) / 2 at x; the allowance is at least
/// allow_p (it grows away from the start) and at least tol_m + tol_rad (start_distance + x)
/// (the distance from the start is at least the horizontal one).  Either bound suffices; the
/// second matters next to the start, where an angular allowance vanishes.
inline bool chord_within(double m, double p, double q, double allow_p, const SampleSettings& st) {
    if (q <= p) return true;
    if (m * (q - p) * (q - p) <= 8.0 * allow_p) return true;
    if (st.tolerance_rad <= 0.0) return false;
    // max over x in [p, q] of m (x - p)(q - x)/2 - tol_rad x, a downward parabola.
    const double x = std::clamp(0.5 * (p + q) - st.tolerance_rad / m, p, q);
    const double excess = 0.5 * m * (x - p) * (q - x) - st.tolerance_rad * x;
    return excess <= st.tolerance_m + st.tolerance_rad * st.start_distance;
}

}  // namespace mirage
