#include "atmosphere/air.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mirage {
namespace {

TEST(Air, GladstoneDaleScalesWithDensity) {
    IndexSettings gd;
    EXPECT_DOUBLE_EQ(refractivity(gd, {288.15, 101325.0, 0.0}), 2.93e-4);
    EXPECT_NEAR(refractivity(gd, {300.0, 101325.0, 0.5}), 2.93e-4 * 288.15 / 300.0, 1e-19);
    EXPECT_NEAR(refractivity(gd, {288.15, 90000.0, 0.0}), 2.93e-4 * 90000.0 / 101325.0, 1e-19);
    gd.gladstone_dale = 2.78e-4;
    EXPECT_DOUBLE_EQ(refractivity(gd, {288.15, 101325.0, 0.0}), 2.78e-4);
}

// Ciddor's standard dry air (15 degC, 101325 Pa, 450 ppm CO2) is his dispersion formula itself:
// n - 1 = 0.05792105 / (238.0185 - s^2) + 0.00167917 / (57.362 - s^2), s = 1 / lambda in 1/um.
TEST(Air, CiddorStandardAirIsItsDispersionFormula) {
    for (double nm : {400.0, 550.0, 633.0, 1000.0}) {
        const double s2 = 1.0 / (nm * 1e-3 * nm * 1e-3);
        const double ref = 0.05792105 / (238.0185 - s2) + 0.00167917 / (57.362 - s2);
        EXPECT_NEAR(ciddor_refractivity(nm, 288.15, 101325.0, 0.0, 450.0), ref, 1e-19) << nm;
    }
}

// The NIST Engineering Metrology Toolbox's table of Ciddor values ("Refractive Index of Air
// Calculator", Stone and Zimmerman, section VII: t in degC, relative humidity in %, p in kPa,
// wavelength in nm, n to 9 decimals; CO2 450 ppm).  Agreement within 1e-9, the table's last digit.
TEST(Air, CiddorMatchesTheNistToolboxTable) {
    struct Row {
        double t_c, rh, p_kpa, nm, n;
    };
    const Row rows[] = {
        {20, 0, 101.325, 633, 1.000271800},  {20, 0, 60, 633, 1.000160924},
        {20, 0, 120, 633, 1.000321916},      {50, 0, 100, 633, 1.000243285},
        {5, 0, 100, 633, 1.000282756},       {-40, 0, 100, 633, 1.000337580},
        {50, 100, 120, 633, 1.000287924},    {40, 75, 120, 633, 1.000299418},
        {20, 100, 100, 633, 1.000267394},    {40, 100, 110, 1700, 1.000270247},
        {20, 0, 101.325, 1700, 1.000268479}, {40, 100, 110, 300, 1.000289000},
        {20, 0, 101.325, 300, 1.000286581},  {-40, 0, 120, 300, 1.000427233},
    };
    for (const auto& r : rows) {
        const double n =
            1.0 + ciddor_refractivity(r.nm, r.t_c + 273.15, 1000.0 * r.p_kpa, 0.01 * r.rh, 450.0);
        EXPECT_NEAR(n, r.n, 1.0e-9)
            << r.t_c << " degC, " << r.rh << " %, " << r.p_kpa << " kPa, " << r.nm << " nm";
    }
}

// IAPWS saturation pressures over water: 2.3393 kPa at 20 degC, 101.418 kPa at 100 degC, the
// triple point 611.657 Pa at 0.01 degC; below 0 degC over supercooled water (Murphy and Koop
// 2005: 286.5 Pa at -10 degC, 125.5 Pa at -20 degC), continuous through 0 degC.
TEST(Air, SaturationVapourPressureFollowsIapwsOverWater) {
    EXPECT_NEAR(saturation_vapour_pressure(293.15), 2339.3, 0.2);
    EXPECT_NEAR(saturation_vapour_pressure(373.15), 101418.0, 2.0);
    EXPECT_NEAR(saturation_vapour_pressure(273.16), 611.657, 2e-3);
    EXPECT_NEAR(saturation_vapour_pressure(263.15), 286.5, 0.3);
    EXPECT_NEAR(saturation_vapour_pressure(253.15), 125.5, 0.2);
    const double below = saturation_vapour_pressure(273.15 - 1e-9);
    const double above = saturation_vapour_pressure(273.15 + 1e-9);
    EXPECT_NEAR(above - below, 2e-9 * 44.4, 1e-9);  // dp/dT = 44.4 Pa/K there
}

TEST(Air, BadSettingsAndStatesAreNamed) {
    IndexSettings s;
    s.wavelength_nm = 200.0;
    auto st = validate(s);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.message(), "wavelength 200 nm is outside Ciddor's range, 300 to 1690 nm");
    s = {};
    s.gladstone_dale = -1.0;
    EXPECT_EQ(
        validate(s).message(),
        "Gladstone-Dale constant -1 must lie in (0, 0.01] (n - 1 at 288.15 K and 1013.25 hPa)");
    EXPECT_EQ(validate_air_state({-10.0, 101325.0, 0.0}, "row 3").message(),
              "row 3: temperature -283.15 degC is below absolute zero or not a number");
    EXPECT_EQ(validate_air_state({288.0, 101325.0, 1.5}, "").message(),
              "relative humidity 150 % must lie in [0, 100] %");
    EXPECT_EQ(parse_index_formula("edlen").message(),
              "unknown index formula 'edlen' (expected gladstone-dale or ciddor)");
}

}  // namespace
}  // namespace mirage
