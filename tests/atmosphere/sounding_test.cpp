#include "atmosphere/sounding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

namespace mirage {
namespace {

TEST(Sounding, ReadsTemperaturePressureAndHumidity) {
    auto s = parse_sounding(
        "height_m,temperature_c,pressure_hpa,relative_humidity\n"
        "0,24.5,1012.0,60\n"
        "0.5, 21.0 ,1011.94,62\n"
        "2,18.9,1011.76,64\n",
        "s.csv");
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(s->kind, Sounding::Kind::Temperature);
    ASSERT_EQ(s->height_m.size(), 3u);
    EXPECT_DOUBLE_EQ(s->height_m[1], 0.5);
    EXPECT_DOUBLE_EQ(s->temperature_k[1], 21.0 + 273.15);
    EXPECT_DOUBLE_EQ(s->pressure_pa[2], 101176.0);
    EXPECT_DOUBLE_EQ(s->relative_humidity[0], 0.6);
}

TEST(Sounding, ReadsAnIndexSoundingWithAByteOrderMarkAndCrlf) {
    auto s = parse_sounding("\xEF\xBB\xBFheight_m,n\r\n0,1.000281\r\n1,1.000279\r\n", "n.csv");
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(s->kind, Sounding::Kind::Index);
    EXPECT_DOUBLE_EQ(s->index[1], 1.000279);
}

// Every refusal names the file, the line and the column where the bad value starts.
TEST(Sounding, BadSoundingsAreRefusedWithFileLineAndColumn) {
    auto err = [](const std::string& text, SoundingRules rules = {}) {
        auto s = parse_sounding(text, "s.csv", rules);
        EXPECT_FALSE(s.ok());
        return s.ok() ? std::string() : s.message();
    };
    EXPECT_EQ(
        err("height_m,temperature_c\n0,20\n1,19\n1,18\n"),
        "s.csv:4:1: column 'height_m': height 1 m is not above the previous row's 1 m (line 3)");
    EXPECT_EQ(
        err("height_m,temperature_c\n0,20\n2,19\n1,18\n"),
        "s.csv:4:1: column 'height_m': height 1 m is not above the previous row's 2 m (line 3)");
    EXPECT_EQ(err("height_m,temperature_c\n0,20\n1,nan\n"),
              "s.csv:3:3: column 'temperature_c': 'nan' is not a finite number");
    EXPECT_EQ(err("height_m,temperature_c\n0,20\n1,19.x\n"),
              "s.csv:3:3: column 'temperature_c': '19.x' is not a number");
    EXPECT_EQ(err("height_m,temperature_c\n0,20\n1,\n"),
              "s.csv:3:3: column 'temperature_c': missing number");
    SoundingRules tight;
    tight.max_gap_m = 100.0;
    EXPECT_EQ(
        err("height_m,temperature_c\n0,20\n50,19\n200,18\n", tight),
        "s.csv:4:1: column 'height_m': gap of 150 m from the previous row (line 3, 50 m) exceeds "
        "the limit of 100 m");
    EXPECT_EQ(err("height_m,temperature_c\n0,20\n"),
              "s.csv: a sounding needs at least 2 rows, this one has 1");
    EXPECT_EQ(
        err("height_m,temperature_c,wind_m_s\n0,20,3\n1,19,4\n"),
        "s.csv:1:24: unknown column 'wind_m_s' (a sounding has height_m with temperature_c [, "
        "pressure_hpa] [, relative_humidity], or height_m with n)");
    EXPECT_EQ(err("\xEF\xBB\xBFheight,temperature_c\n0,20\n1,19\n"),
              "s.csv:1:1: unknown column 'height' (a sounding has height_m with temperature_c [, "
              "pressure_hpa] [, relative_humidity], or height_m with n)");
    EXPECT_EQ(err("height_m,pressure_hpa\n0,1000\n1,999\n"),
              "s.csv:1: missing column 'temperature_c' or 'n' (a sounding has height_m with "
              "temperature_c [, pressure_hpa] [, relative_humidity], or height_m with n)");
    EXPECT_EQ(err("height_m,temperature_c,n\n0,20,1.0003\n1,19,1.0003\n"),
              "s.csv:1:24: column 'n' with 'temperature_c': give one (a sounding has height_m with "
              "temperature_c [, pressure_hpa] [, relative_humidity], or height_m with n)");
    EXPECT_EQ(err("height_m,temperature_c\n2,20\n3,19\n"),
              "s.csv:2:1: column 'height_m': the first row must be at the ground, 0 m (got 2 m)");
    EXPECT_EQ(
        err("height_m,temperature_c\n0,20\n1,-300\n"),
        "s.csv:3:3: column 'temperature_c': temperature -300 degC is at or below absolute zero");
    // A temperature of 3.7e6 degC (found by the fuzz target) made the fit take a million pieces.
    EXPECT_EQ(err("height_m,temperature_c\n0,20\n0.1,3700030.0\n10,29.9\n"),
              "s.csv:3:5: column 'temperature_c': temperature 3700030 degC must be from -173.15 "
              "to 126.85 degC");
    EXPECT_EQ(err("height_m,temperature_c,pressure_hpa\n0,20,1013\n1,19,1e9\n"),
              "s.csv:3:6: column 'pressure_hpa': pressure 1e+09 hPa must be from 1 to 2000 hPa");
    EXPECT_EQ(
        err("height_m,temperature_c,relative_humidity\n0,20,50\n1,19,120\n"),
        "s.csv:3:6: column 'relative_humidity': relative humidity 120 % must lie in [0, 100]");
    EXPECT_EQ(err("height_m,n\n0,1.0003\n1,0.9\n"),
              "s.csv:3:3: column 'n': index 0.9 must lie in [1, 2)");
    EXPECT_EQ(err("height_m,temperature_c\n0,20\n1,19,4\n"),
              "s.csv:3: row has 3 fields, the header has 2");
}

TEST(Sounding, MissingFileIsNamed) {
    auto s = read_sounding("/nonexistent/sounding.csv");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message(),
              "/nonexistent/sounding.csv: cannot be opened: No such file or directory");
}

// The spline passes through every row, has one slope at every knot, and keeps monotone data
// monotone (no overshoot between rows, unlike a cubic spline).
TEST(Sounding, SplineInterpolatesWithAContinuousSlopeAndNoOvershoot) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<double> x{0.0}, f{unit(rng)};
        const bool monotone = trial % 2 == 0;
        for (int k = 1; k < 12; ++k) {
            x.push_back(x.back() + 0.01 + 3.0 * unit(rng) * unit(rng));
            f.push_back(monotone ? f.back() + unit(rng) * unit(rng) : unit(rng));
        }
        const QuadraticSpline sp = make_shape_preserving_spline(x, f);
        for (size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(sp.value(x[k]), f[k], 1e-14);
        for (size_t j = 1; j + 1 < sp.knots.size(); ++j) {
            const double h = sp.knots[j] - sp.knots[j - 1];
            const double left_value =
                sp.values[j - 1] + (sp.slopes[j - 1] + sp.curvatures[j - 1] * h) * h;
            const double left_slope = sp.slopes[j - 1] + 2.0 * sp.curvatures[j - 1] * h;
            EXPECT_NEAR(left_value, sp.values[j], 1e-13);
            EXPECT_NEAR(left_slope, sp.slopes[j], 1e-11 * (1.0 + std::fabs(sp.slopes[j])));
        }
        for (size_t k = 0; k + 1 < x.size(); ++k) {
            const double lo = std::min(f[k], f[k + 1]), hi = std::max(f[k], f[k + 1]);
            for (int q = 1; q < 50; ++q) {
                const double v = sp.value(x[k] + (x[k + 1] - x[k]) * q / 50.0);
                EXPECT_GE(v, lo - 1e-14) << "trial " << trial << " interval " << k;
                EXPECT_LE(v, hi + 1e-14) << "trial " << trial << " interval " << k;
            }
        }
    }
}

// Linear data stay linear: every secant is the same, so is every slope, and every curvature
// is 0.
TEST(Sounding, SplineReproducesLinearDataExactly) {
    std::vector<double> x{0.0, 0.3, 1.0, 2.5, 2.6, 7.0}, f;
    for (double v : x) f.push_back(2.0 - 0.4 * v);
    const QuadraticSpline sp = make_shape_preserving_spline(x, f);
    for (double y = 0.0; y <= 7.0; y += 0.013) EXPECT_NEAR(sp.value(y), 2.0 - 0.4 * y, 1e-14);
    for (double c : sp.curvatures) EXPECT_NEAR(c, 0.0, 1e-13);
}

}  // namespace
}  // namespace mirage
