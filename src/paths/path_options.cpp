#include "paths/path_options.h"

#include <cmath>

namespace mirage {

std::vector<std::string> path_input_files(const PathOptions& o) {
    std::vector<std::string> in;
    for (const auto& f : {o.air.sounding, o.batch})
        if (!f.empty()) in.push_back(f);
    return in;
}

bool general_requested(const PathOptions& o) {
    const PathAirOptions& a = o.air;
    return a.general || !std::isnan(a.air_temperature_c) || !std::isnan(a.lapse_k_per_km) ||
           !a.surface_layers.empty() || !a.inversions.empty() || !a.sounding.empty() ||
           !std::isnan(a.pressure_hpa) || a.isobaric || !std::isnan(a.humidity_pct) ||
           !a.index.empty() || !std::isnan(a.gladstone_dale) || !std::isnan(a.wavelength_nm) ||
           !std::isnan(a.co2_ppm) || !std::isnan(a.earth_radius) || !std::isnan(a.top) ||
           !std::isnan(o.transfer) || o.ducts;
}

}  // namespace mirage
