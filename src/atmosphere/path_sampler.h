// The paper's sampled ray path for any exact path (exact_path.h): the sampler of sampler.h
// generalised from the exponential profiles' one turning point to paths with any number of
// them (ducted rays turn for ever), with the same tolerance and the same proof.
//
// The polyline's height differs from the exact path's by at most
//   tolerance_m + tolerance_rad * (start_distance + |exact point - start|)
// at every horizontal distance.  Every chord lies within one monotone run of the path (runs are
// split at the turning points), so the heights it spans are those of its two ends, and the
// chord's error is at most max|y''| L^2 / 8 with the maximum taken over those heights: y'' of a
// ray depends on its height only.  ExactPath::curvature_bound gives that maximum for any
// profile (for the exponential ones it is the value at the lower end, as in sampler.cpp).
#pragma once

#include "atmosphere/exact_path.h"
#include "atmosphere/sampler.h"

namespace mirage {

/// Samples the exact path to the tolerance (SampleSettings and SampledPath as in sampler.h; the
/// path's `turns`/`dz_turn` name its first turning point).  At least one of tolerance_m and
/// tolerance_rad must be positive.
SampledPath sample_exact_path(const ExactPath& path, const SampleSettings& settings);

/// The allowance at horizontal distance dz where the exact height is y.
double allowed_error(const ExactPath& path, const SampleSettings& settings, double dz, double y);

}  // namespace mirage
