#include "atmosphere/sky_exit.h"

#include <algorithm>
#include <cmath>

#include "atmosphere/quadratic_path.h"
#include "atmosphere/quadratic_profile.h"

namespace mirage {

std::optional<SkyExit> sky_exit(const ExactPath& path) {
    const QuadraticPath* q = path.quadratic();
    if (!q || q->fate() != PathFate::Escape) return std::nullopt;
    const QuadraticProfile& model = q->profile();
    const double R = model.earth_radius();
    if (!model.sky_at_top() || !(R > 0.0)) return std::nullopt;
    // Beyond dz_straight the path is straight in the flattened frame: above the model's top.
    const double dz = q->dz_straight();
    const double slope = q->asymptotic_slope();
    if (!std::isfinite(dz) || !std::isfinite(slope)) return std::nullopt;
    // The flattened index is n* = n exp(y / R): the air's own index at the top.
    const double n_top = std::sqrt(model.n_sq(model.top())) * std::exp(-model.top() / R);
    const double local = std::atan(slope);
    const double vacuum = std::acos(std::min(1.0, n_top * std::cos(local)));
    return SkyExit{local >= 0.0 ? vacuum : -vacuum, dz};
}

}  // namespace mirage
