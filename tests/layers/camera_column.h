// Test helper: the pixel rays of one column of a level pinhole camera, as the layer design
// sees them.
#pragma once

#include <cmath>
#include <vector>

#include "layers/band_tracer3d.h"
#include "layers/fit.h"

namespace mirage::testing {

/// Rows of the column at normalised horizontal position x (0 = centre) of a level camera with
/// vertical field vfov_deg and `rows` rows; every ray leaves the scene at exit_dz.
inline std::vector<DesignRay> level_column(double vfov_deg, int rows, double exit_dz,
                                           double x = 0.0) {
    const double dl = 0.5 / std::tan(vfov_deg * M_PI / 360.0);
    auto elevation = [&](double v) { return std::atan2(v, std::hypot(dl, x)); };
    std::vector<DesignRay> out;
    for (int row = 0; row < rows; ++row) {
        DesignRay r;
        r.elevation = elevation(0.5 - (row + 0.5) / rows);
        r.pixel_rad = elevation(0.5 - double(row) / rows) - elevation(0.5 - (row + 1.0) / rows);
        r.exit_dz = exit_dz;
        r.row = row;
        out.push_back(r);
    }
    return out;
}

/// Options for the 3D band trace that keep the design's own indices (no POV-Ray rounding):
/// the geometry of the band model.
inline Trace3dOptions exact_indices() {
    Trace3dOptions o;
    o.pov_precision = false;
    return o;
}

}  // namespace mirage::testing
