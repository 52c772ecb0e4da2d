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

/// Samples the exact path to the tolerance wherever it may meet something, and coarsely where
/// nothing can lie near it (sample_path_near of sampler.h, for any exact path).  Every monotone
/// run (from the start or a turning point to the next turning point, the ground or the cut at
/// max_dz) is cut in halves on a grid of powers of two from the run's start; a half is kept whole
/// once its chord is within the tolerance (the chord bound with the path's curvature bound over the
/// heights the half spans), or, with obstacles, once the band about its chord that holds the half
/// and everything within the allowance of it (the chord +- max|y''| L^2 / 8 and the allowance,
/// within the heights of its ends) meets nothing: marked in clear_length.  A half that ends on a
/// surface at the ground always keeps the tolerance.  An escaping path ends with its asymptotic
/// slope (the direction it leaves the profile's top with, or its slope at the cut).  With
/// obstacles a path that does not end on the ground stops at the first node beyond which nothing
/// lies (at once at the node of the grid that covers the obstacles' reach, when they know it):
/// an escaping one is then straight and clear in its end direction (its far end's height is
/// computed only where a test needs it), one cut at max_dz reaches the cut by one clear stretch
/// and goes on from there as before.  Without obstacles every segment keeps the tolerance, and
/// with them the segments that do are the same ones.  `path`'s storage is reused.
void sample_exact_path_near(const ExactPath& path, const SampleSettings& settings,
                            const PathObstacles* obstacles, SampledPath& out);

/// The tracer's sampler for any exact path: the closed-form sampler of sampler.h
/// (sample_path, sample_path_near) for an exponential profile's ray, whose economy is tuned to
/// its one turning point, and the general sampler above for every other path.  Both keep the
/// same tolerance.
SampledPath sample_path(const ExactPath& path, const SampleSettings& settings);
void sample_path_near(const ExactPath& path, const SampleSettings& settings,
                      const PathObstacles* obstacles, SampledPath& out);

}  // namespace mirage
