// `mirage refraction`: the astronomical refraction of the standard atmosphere
// (atmosphere/astronomical_refraction.h) at a list of apparent elevations and wavelengths, beside
// the published tables, as text, JSON and a gnuplot plot.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "atmosphere/astronomical_refraction.h"
#include "util/output_set.h"
#include "util/result.h"

namespace mirage {

struct RefractionTableOptions {
    double temperature_c = 15.0;           // at the ground
    double pressure_hpa = 1013.25;         // at the ground
    std::vector<double> wavelengths_nm = {590.0};
    double observer_height_m = 0.0;        // above the ground
    std::vector<double> elevations_deg = {0, 0.25, 0.5, 1, 2, 3, 5, 10, 20, 45};
};

/// One wavelength's air and its fitted curved-Earth model.
struct RefractionModel {
    StandardAir air;
    Atmosphere atmosphere;
};

struct RefractionTable {
    RefractionTableOptions options;
    std::vector<RefractionModel> models;              // per wavelength
    std::vector<std::vector<double>> refraction_rad;  // [wavelength][elevation], by the path
    // The tables for the same air, when there are any: the Pulkovo tables' fit at their own
    // conditions (15 degC, 1013.25 hPa, 590 nm, sea level) and the wavelength they are for;
    // else empty.
    std::vector<double> tables_rad;
    std::string tables_name;
    size_t tables_wavelength = 0;  // the index of the wavelength the tables are for
};

/// The options checked (each value named when refused) and every ray followed.
Result<RefractionTable> refraction_table(const RefractionTableOptions& options);

std::string refraction_text(const RefractionTable& t);
nlohmann::json refraction_json(const RefractionTable& t);

/// The plot of the refraction against the apparent elevation (from the horizon to the largest
/// elevation asked, up to 10 degrees), one curve per wavelength and the tables', as PNG, written
/// through `outputs` (renamed into place by its commit()).
Status draw_refraction_plot(const RefractionTable& t, OutputSet& outputs, const std::string& png,
                            const std::string& gnuplot = "gnuplot");

}  // namespace mirage
