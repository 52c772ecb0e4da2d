// The refractive index of air from its temperature, pressure and humidity: Gladstone-Dale
// (the design's default) or Ciddor 1996 (wavelength, humidity, CO2), and the constants of the
// hydrostatic equation that gives the pressure when a profile does not.
#pragma once

#include <string_view>

#include "util/result.h"

namespace mirage {

/// Which formula turns temperature, pressure and humidity into an index.
enum class IndexFormula {
    GladstoneDale,  ///< n - 1 = K (p / 1013.25 hPa) (288.15 K / T); dry air, no dispersion
    Ciddor,         ///< Ciddor, Appl. Opt. 35, 1566 (1996): wavelength, humidity, CO2
};

struct IndexSettings {
    IndexFormula formula = IndexFormula::GladstoneDale;
    double gladstone_dale = 2.93e-4;  // Gladstone-Dale: n - 1 at 288.15 K and 1013.25 hPa
    double wavelength_nm = 550.0;     // Ciddor: vacuum wavelength, 300 to 1690 nm
    double co2_ppm = 450.0;           // Ciddor: CO2 mole fraction, ppm
};

/// One parcel of air.
struct AirState {
    double temperature_k = 288.15;
    double pressure_pa = 101325.0;
    double relative_humidity = 0.0;  // 0 to 1 (Gladstone-Dale ignores it)
};

/// n - 1 of the parcel by the chosen formula.  The state must be physical (T > 0, p > 0,
/// humidity in [0, 1]; see validate_air_state).
double refractivity(const IndexSettings& settings, const AirState& air);

/// Ciddor 1996, with the NIST Engineering Metrology Toolbox's saturation vapour pressure
/// (IAPWS-IF97 over water) and enhancement factor; humidity is relative to water at every
/// temperature (the WMO convention).  lambda in nm, T in K, p in Pa, h in [0, 1], CO2 in ppm.
double ciddor_refractivity(double wavelength_nm, double temperature_k, double pressure_pa,
                           double relative_humidity, double co2_ppm);

/// Saturation vapour pressure over water, Pa (IAPWS-IF97, continued below 0 degC).
double saturation_vapour_pressure(double temperature_k);

/// Checks the index settings: Gladstone-Dale constant in (0, 1e-2], wavelength in
/// [300, 1690] nm, CO2 in [0, 2000] ppm (Ciddor's stated range).
Status validate(const IndexSettings& settings);

/// Checks a parcel: finite, T > 0, p > 0, humidity in [0, 1].  `where` prefixes the message.
Status validate_air_state(const AirState& air, std::string_view where);

std::string_view index_formula_name(IndexFormula f);
Result<IndexFormula> parse_index_formula(std::string_view name);

// The hydrostatic equation dp/dy = -p g M / (R T) for dry air (the US Standard Atmosphere's
// constants; humidity's effect on the molar mass is left out, under 1 % of the lapse).
constexpr double kGravity = 9.80665;                                              // m/s^2
constexpr double kMolarMassDryAir = 0.0289644;                                    // kg/mol
constexpr double kGasConstant = 8.314462618;                                      // J/(mol K)
constexpr double kHydrostaticScale = kGravity * kMolarMassDryAir / kGasConstant;  // K/m

}  // namespace mirage
