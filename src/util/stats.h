// Order statistics over a set of figures (errors per pixel, per ray).
#pragma once

#include <vector>

namespace mirage {

/// The value of rank round(q (n - 1)) among `values` (q in [0, 1]: 0.5 the median, 0.95 the
/// 95th percentile), found without sorting the rest; 0 for none.
double percentile(std::vector<double> values, double q);

}  // namespace mirage
