#include "util/stats.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mirage {

double percentile(std::vector<double> values, double q) {
    if (values.empty()) return 0.0;
    const size_t n = values.size();
    const size_t i = std::min(static_cast<size_t>(std::floor(q * (n - 1) + 0.5)), n - 1);
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(i), values.end());
    return values[i];
}

}  // namespace mirage
