#include "atmosphere/air.h"

#include <cmath>
#include <string>

#include "util/format.h"

namespace mirage {

namespace {

// Ciddor's compressibility of moist air (his eq. 12, constants of his table; t in degC).
double compressibility(double temperature_k, double pressure_pa, double xv) {
    constexpr double a0 = 1.58123e-6, a1 = -2.9331e-8, a2 = 1.1043e-10;
    constexpr double b0 = 5.707e-6, b1 = -2.051e-8;
    constexpr double c0 = 1.9898e-4, c1 = -2.376e-6;
    constexpr double d = 1.83e-11, e = -0.765e-8;
    const double t = temperature_k - 273.15;
    const double pt = pressure_pa / temperature_k;
    return 1.0 - pt * (a0 + a1 * t + a2 * t * t + (b0 + b1 * t) * xv + (c0 + c1 * t) * xv * xv) +
           pt * pt * (d + e * xv * xv);
}

}  // namespace

double saturation_vapour_pressure(double temperature_k) {
    // IAPWS-IF97 saturation pressure (region 4), as the NIST toolbox uses it above 0 degC, and
    // below 0 degC too: relative humidity is taken over water at every temperature (the WMO
    // convention), which keeps the index smooth through 0 degC (the curve continued below it
    // follows supercooled water: 286.4 Pa at -10 degC, 125.5 Pa at -20, 19.0 Pa at -40).
    constexpr double K1 = 1.16705214528e3, K2 = -7.24213167032e5, K3 = -1.70738469401e1,
                     K4 = 1.20208247025e4, K5 = -3.23255503223e6, K6 = 1.49151086135e1,
                     K7 = -4.82326573616e3, K8 = 4.05113405421e5, K9 = -2.38555575678e-1,
                     K10 = 6.50175348448e2;
    const double T = temperature_k;
    const double omega = T + K9 / (T - K10);
    const double A = omega * omega + K1 * omega + K2;
    const double B = K3 * omega * omega + K4 * omega + K5;
    const double C = K6 * omega * omega + K7 * omega + K8;
    const double X = -B + std::sqrt(B * B - 4.0 * A * C);
    const double r = 2.0 * C / X;
    return 1e6 * r * r * r * r;
}

double ciddor_refractivity(double wavelength_nm, double temperature_k, double pressure_pa,
                           double relative_humidity, double co2_ppm) {
    const double lambda_um = wavelength_nm * 1e-3;
    const double S = 1.0 / (lambda_um * lambda_um);  // um^-2
    // Standard dry air (15 degC, 101325 Pa, 450 ppm CO2) and standard water vapour (20 degC,
    // 1333 Pa): Ciddor's eqs. 1 to 3.
    constexpr double k0 = 238.0185, k1 = 5792105.0, k2 = 57.362, k3 = 167917.0;
    constexpr double w0 = 295.235, w1 = 2.6422, w2 = -0.032380, w3 = 0.004028;
    const double r_as = 1e-8 * (k1 / (k0 - S) + k3 / (k2 - S));
    const double r_vs = 1.022e-8 * (w0 + w1 * S + w2 * S * S + w3 * S * S * S);
    const double r_axs = r_as * (1.0 + 0.534e-6 * (co2_ppm - 450.0));
    // Mole fraction of water vapour from the relative humidity (enhancement factor f).
    const double t = temperature_k - 273.15;
    const double f = 1.00062 + 3.14e-8 * pressure_pa + 5.6e-7 * t * t;
    const double xv =
        f * relative_humidity * saturation_vapour_pressure(temperature_k) / pressure_pa;
    // Densities relative to the standard ones, rho = p M / (Z R T) (eqs. 4, 9): the molar
    // masses and the gas constant cancel in the ratios.
    constexpr double p_a = 101325.0, T_a = 288.15, p_w = 1333.0, T_w = 293.15;
    const double Z_a = compressibility(T_a, p_a, 0.0);
    const double Z_w = compressibility(T_w, p_w, 1.0);
    const double Z_m = compressibility(temperature_k, pressure_pa, xv);
    const double dry = (1.0 - xv) * pressure_pa * T_a * Z_a / (p_a * temperature_k * Z_m);
    const double vapour = xv * pressure_pa * T_w * Z_w / (p_w * temperature_k * Z_m);
    return dry * r_axs + vapour * r_vs;
}

double refractivity(const IndexSettings& s, const AirState& air) {
    if (s.formula == IndexFormula::Ciddor)
        return ciddor_refractivity(s.wavelength_nm, air.temperature_k, air.pressure_pa,
                                   air.relative_humidity, s.co2_ppm);
    return s.gladstone_dale * (air.pressure_pa / 101325.0) * (288.15 / air.temperature_k);
}

Status validate(const IndexSettings& s) {
    if (!(s.gladstone_dale > 0.0 && s.gladstone_dale <= 1e-2))
        return make_error("Gladstone-Dale constant " + shortest(s.gladstone_dale) +
                          " must lie in (0, 0.01] (n - 1 at 288.15 K and 1013.25 hPa)");
    if (!(s.wavelength_nm >= 300.0 && s.wavelength_nm <= 1690.0))
        return make_error("wavelength " + shortest(s.wavelength_nm) +
                          " nm is outside Ciddor's range, 300 to 1690 nm");
    if (!(s.co2_ppm >= 0.0 && s.co2_ppm <= 2000.0))
        return make_error("CO2 " + shortest(s.co2_ppm) + " ppm must lie in [0, 2000] ppm");
    return Ok{};
}

Status validate_air_state(const AirState& air, std::string_view where) {
    const std::string at = where.empty() ? "" : std::string(where) + ": ";
    if (!(std::isfinite(air.temperature_k) && air.temperature_k > 0.0))
        return make_error(at + "temperature " + shortest(air.temperature_k - 273.15) +
                          " degC is below absolute zero or not a number");
    if (!(std::isfinite(air.pressure_pa) && air.pressure_pa > 0.0))
        return make_error(at + "pressure " + shortest(air.pressure_pa / 100.0) +
                          " hPa must be finite and > 0");
    if (!(air.relative_humidity >= 0.0 && air.relative_humidity <= 1.0))
        return make_error(at + "relative humidity " + shortest(100.0 * air.relative_humidity) +
                          " % must lie in [0, 100] %");
    return Ok{};
}

std::string_view index_formula_name(IndexFormula f) {
    return f == IndexFormula::Ciddor ? "ciddor" : "gladstone-dale";
}

Result<IndexFormula> parse_index_formula(std::string_view name) {
    if (name == "gladstone-dale") return IndexFormula::GladstoneDale;
    if (name == "ciddor") return IndexFormula::Ciddor;
    return make_error("unknown index formula '" + std::string(name) +
                      "' (expected gladstone-dale or ciddor)");
}

}  // namespace mirage
