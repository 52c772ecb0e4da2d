#include "atmosphere/general_profile.h"

#include <gtest/gtest.h>

#include <cmath>

#include "air_fixtures.h"
#include "atmosphere/exact_path.h"

namespace mirage {
namespace {

TEST(GeneralProfile, TemperatureFormsAddUp) {
    AirColumn c;
    c.ground_temperature_k = 290.0;
    c.lapse_k_per_m = 0.0065;
    c.layers.push_back({10.0, 0.5});
    c.inversions.push_back({50.0, 60.0, 2.0, 0.0});
    EXPECT_DOUBLE_EQ(column_temperature(c, 0.0), 300.0);
    EXPECT_NEAR(column_temperature(c, 1.0), 290.0 - 0.0065 + 10.0 * std::exp(-2.0), 1e-12);
    EXPECT_NEAR(column_temperature(c, 55.0), 290.0 - 0.0065 * 55.0 + 1.0, 1e-9);
    EXPECT_NEAR(column_temperature(c, 80.0), 290.0 - 0.0065 * 80.0 + 2.0, 1e-9);
    // The sharp ramp has corners: its slope jumps at the inversion's ends.
    EXPECT_NEAR(column_temperature_slope(c, 50.0, -1), -0.0065, 1e-9);
    EXPECT_NEAR(column_temperature_slope(c, 50.0, +1), -0.0065 + 0.2, 1e-9);
    // Smoothed by a Gaussian, the ramp keeps its middle, its total and a continuous slope.
    c.inversions[0].smoothing_m = 1.0;
    EXPECT_NEAR(column_temperature(c, 55.0), 290.0 - 0.0065 * 55.0 + 1.0, 1e-9);
    EXPECT_NEAR(column_temperature(c, 90.0), 290.0 - 0.0065 * 90.0 + 2.0, 1e-9);
    EXPECT_NEAR(column_temperature_slope(c, 50.0, -1), column_temperature_slope(c, 50.0, +1),
                1e-15);
    // At the corner the smoothed ramp is sigma phi(0) / w above the sharp one.
    EXPECT_NEAR(column_temperature(c, 50.0) - (290.0 - 0.0065 * 50.0),
                2.0 * 1.0 / std::sqrt(2.0 * M_PI) / 10.0, 1e-12);
}

// The hydrostatic pressure has closed forms for an isothermal column, p0 exp(-g M y / (R T)),
// and for a linear lapse, p0 (1 - L y / T0)^(g M / (R L)); the model's index must follow them.
TEST(GeneralProfile, HydrostaticPressureMatchesItsClosedForms) {
    for (double lapse : {0.0, 0.0065, -0.02}) {
        AirSpec spec;
        spec.column.ground_temperature_k = 288.15;
        spec.column.lapse_k_per_m = lapse;
        spec.top_m = 2000.0;
        auto m = make_air_model(spec);
        ASSERT_TRUE(m.ok()) << m.message();
        for (double y : {0.0, 1.0, 37.0, 500.0, 1999.0}) {
            const double T = 288.15 - lapse * y;
            const double p = lapse == 0.0 ? 101325.0 * std::exp(-kHydrostaticScale * y / T)
                                          : 101325.0 * std::pow(1.0 - lapse * y / 288.15,
                                                                kHydrostaticScale / lapse);
            EXPECT_NEAR(m->pressure_pa(y), p, 1e-10 * p) << lapse << " " << y;
            EXPECT_NEAR(m->refractivity(y), 2.93e-4 * (p / 101325.0) * (288.15 / T), 1e-17) << y;
        }
    }
    AirSpec iso;
    iso.hydrostatic = false;
    iso.ground_pressure_pa = 90000.0;
    auto m = make_air_model(iso);
    ASSERT_TRUE(m.ok());
    EXPECT_DOUBLE_EQ(m->pressure_pa(700.0), 90000.0);
}

// The check: with no gradient, a level ray from 10 m is 41.4 m above the sphere at
// 20 km.  Exactly: a straight line from r0 = R + 10 m tangent to the local level reaches
// r0 / cos(20 km / R) at that arc distance, 41.3924 m above the sphere.
TEST(GeneralProfile, EarthFlatteningBendsALevelRayAwayFromTheSphere) {
    AirSpec spec;
    spec.index.gladstone_dale = 1e-30;  // no refraction at all
    spec.hydrostatic = false;
    spec.earth_radius_m = 6371000.0;
    spec.top_m = 100.0;
    auto q = testing::fit_or_die(spec, 1e-12);
    ASSERT_TRUE(q);
    const Atmosphere atm = Atmosphere::quadratic(q);
    const double R = 6371000.0;
    auto path = ExactPath::make(atm, flattened_height(10.0, R), M_PI / 2);
    ASSERT_TRUE(path.ok());
    for (double d : {5000.0, 20000.0, 60000.0}) {
        const double h = height_above_sphere(path->height_at(d), R);
        const double exact = (R + 10.0) / std::cos(d / R) - R;
        EXPECT_NEAR(h, exact, 1e-6 * (1.0 + exact)) << d;
    }
    EXPECT_NEAR(height_above_sphere(path->height_at(20000.0), R), 41.4, 0.05);
    // The flattened slope is the tangent of the local elevation: a straight line's elevation
    // relative to the local level grows as the arc angle, d / R.
    EXPECT_NEAR(std::atan(path->slope_at(20000.0)), 20000.0 / R, 1e-9);
    EXPECT_DOUBLE_EQ(height_above_sphere(flattened_height(123.4, R), R), 123.4);
}

// Young's inversion, 2 K between 50 and 60 m over the standard atmosphere's lapse (6.5 K/km,
// 15 degC and 1013.25 hPa at the ground), seen on the curved Earth: he gives the duct's bottom
// at 45.3 m for the sharp ("zigzag") profile and 45.7 m with its corners smoothed
// (aty.sdsu.edu, "Mirages Produced by a Zigzag Temperature Profile" and "... by a Smooth
// Temperature Profile").  With Ciddor's index at 550 nm and a Gaussian of 2 m full width at half
// maximum (sigma 0.85 m) for the smoothing, the model's ducts start at 45.35 m and 45.78 m.
TEST(GeneralProfile, YoungsInversionDuctStartsWhereHeSaysItDoes) {
    const double R = 6371000.0;
    const struct {
        double sigma, young;
    } cases[] = {{0.0, 45.3}, {2.0 / (2.0 * std::sqrt(2.0 * std::log(2.0))), 45.7}};
    for (const auto& c : cases) {
        auto q = testing::fit_or_die(testing::young_spec(c.sigma), 1e-12);
        ASSERT_TRUE(q);
        const auto ducts = find_ducts(*q);
        ASSERT_EQ(ducts.size(), 1u);
        const double bottom = height_above_sphere(ducts[0].bottom, R);
        EXPECT_NEAR(bottom, c.young, 0.1) << "sigma " << c.sigma;
        EXPECT_NEAR(height_above_sphere(ducts[0].top, R), 60.0, 0.5);
        // The exact paths agree: a level ray just inside the duct is trapped, one just below
        // escapes.
        const Atmosphere atm = Atmosphere::quadratic(q);
        auto inside = ExactPath::make(atm, ducts[0].bottom + 0.01, M_PI / 2);
        auto below = ExactPath::make(atm, ducts[0].bottom - 0.01, M_PI / 2);
        ASSERT_TRUE(inside.ok() && below.ok());
        EXPECT_EQ(inside->fate(), PathFate::Ducted);
        EXPECT_EQ(below->fate(), PathFate::Escape);
    }
}

TEST(GeneralProfile, BadProfilesAreRefusedByName) {
    AirSpec spec;
    spec.column.inversions.push_back({60.0, 50.0, 2.0, 0.0});
    EXPECT_EQ(make_air_model(spec).message(),
              "inversion: top 50 m must lie above its bottom 60 m and at most 10000 m");
    spec.column.inversions = {{50.0, 1500.0, 2.0, 0.0}};
    spec.top_m = 1000.0;
    EXPECT_EQ(make_air_model(spec).message(),
              "inversion top 1500 m must lie below the profile's top 1000 m");
    spec = {};
    spec.column.layers.push_back({5.0, 0.0});
    EXPECT_EQ(make_air_model(spec).message(),
              "surface layer: scale height 0 m must be from 0.001 to 10000 m");
    spec = {};
    spec.column.lapse_k_per_m = 0.5;
    EXPECT_EQ(make_air_model(spec).message(),
              "the temperature falls to -273.25 degC at 576.5 m: the profile is not physical");
    spec = {};
    spec.earth_radius_m = -1.0;
    EXPECT_EQ(make_air_model(spec).message(),
              "Earth radius -1 m must be finite and >= 0 (0: flat)");
}

// A sounding of n is its own model: the spline of n^2 is fitted exactly, knot for knot.
TEST(GeneralProfile, IndexSoundingIsItsOwnModel) {
    AirSpec spec;
    spec.source = AirSpec::Source::Sounding;
    spec.sounding =
        *parse_sounding("height_m,n\n0,1.000270\n1,1.000280\n2,1.000282\n5,1.000281\n", "n.csv");
    FitReport report;
    auto q = fit_air(spec, {}, &report);
    ASSERT_TRUE(q.ok()) << q.message();
    EXPECT_EQ((*q)->piece_count(), 6);
    EXPECT_EQ(report.max_error_n, 0.0);
    for (double y : {0.0, 1.0, 2.0, 5.0})
        EXPECT_NEAR((*q)->n(y),
                    y == 0   ? 1.000270
                    : y == 1 ? 1.000280
                    : y == 2 ? 1.000282
                             : 1.000281,
                    1e-15);
    EXPECT_NEAR((*q)->n(9.0), 1.000281, 1e-15);  // homogeneous above the top
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

// A smooth sounding of `rows` rows 0.1 m apart, fitted as a scene's is (with the coarse spans).
FitReport fit_smooth_sounding(int rows) {
    AirSpec spec;
    spec.source = AirSpec::Source::Sounding;
    Sounding& s = spec.sounding;
    s.source = "smooth.csv";
    for (int i = 0; i < rows; ++i) {
        const double y = 0.1 * i;
        s.height_m.push_back(y);
        // The standard lapse: a quadratic fits it over long spans (they stay of use).
        s.temperature_k.push_back(288.15 - 0.0065 * y + 1e-3 * std::sin(y));
        s.line.push_back(i + 2);
    }
    FitSettings fit;
    fit.coarse_spans = true;
    FitReport report;
    auto q = fit_air(spec, fit, &report);
    EXPECT_TRUE(q.ok()) << q.message();
    if (q.ok()) EXPECT_TRUE((*q)->has_spans());
    return report;
}

// The fit's work grows as its rows (times the log of the coarse spans' lengths), not as their
// square: from every fine knot every span length was checked at every fine knot inside it,
// and 10^4 rows took more than 300 s.  Four times the rows cost at most six times the checks
// (a quadratic cost would be sixteen times: spans from every fine knot gave 15.7 times).
TEST(GeneralProfile, FittingASoundingCostsAboutItsRows) {
    const FitReport small = fit_smooth_sounding(1500);
    const FitReport large = fit_smooth_sounding(6000);
    ASSERT_GT(small.checks, 0);
    EXPECT_GT(large.pieces, 3 * small.pieces);
    EXPECT_LT(double(large.checks) / small.checks, 6.0) << small.checks << " then " << large.checks;
}

// A fit that fails on a sounding names the file and the rows around the height where it
// stopped.
TEST(GeneralProfile, ASoundingFitFailureNamesItsRows) {
    AirSpec spec;
    spec.source = AirSpec::Source::Sounding;
    spec.sounding.source = "road.csv";
    spec.sounding.height_m = {0.0, 0.5, 10.0};
    spec.sounding.temperature_k = {318.15, 304.15, 301.65};
    spec.sounding.line = {2, 3, 4};
    FitSettings fit;
    fit.tolerance_n = 1e-30;
    auto q = fit_air(spec, fit);
    ASSERT_FALSE(q.ok());
    EXPECT_EQ(q.message().rfind("road.csv:2: the rows at 0 m (line 2) and 0.5 m (line 3): the "
                                "profile changes too fast near ",
                                0),
              0u)
        << q.message();
}

}  // namespace
}  // namespace mirage
