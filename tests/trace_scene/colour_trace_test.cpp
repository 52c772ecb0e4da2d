// mirage trace in colour, and the curved Earth's sky followed to the top of the air.
//
// The sky of these scenes is a gradient of the direction's height y (grey 0 straight down to
// 1 straight up), so that a pixel's value says where its ray went: the elevation of its sky
// direction is asin(2 v - 1).  A level camera's centre pixel looks along the horizon; the
// refraction is how far below it the sky it shows lies.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "atmosphere/astronomical_refraction.h"
#include "load/atmosphere_settings.h"
#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

constexpr double kArcsec = M_PI / 180.0 / 3600.0;
constexpr double kEyeM = 10.0;

class ColourTrace : public ::testing::Test {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_colour_trace_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }

    /// The standard atmosphere from 15 degC and 1013.25 hPa as real air: the troposphere's
    /// lapse to 10 km, then (with `upper`) the standard atmosphere above; `extra` settings.
    fs::path horizon_scene(bool upper, const std::string& extra) {
        const fs::path p = dir_ / "horizon.pov";
        std::ofstream(p)
            << "#version 3.7;\n"
               "#declare Mirage_Air_Temperature = 288.15;\n"
               "#declare Mirage_Lapse = 6.5;\n"
               "#declare Mirage_Pressure = 1013.25;\n"
               "#declare Mirage_Index = \"ciddor\";\n"
               "#declare Mirage_Top = 10000;\n"
            << (upper ? "#declare Mirage_Upper_Air = \"standard\";\n" : "") << extra
            << "#include \"mirage.inc\"\n"
               "global_settings { assumed_gamma 1.0 }\n"
               "camera { location <0, "
            << kEyeM << ", 0> look_at <0, " << kEyeM
            << ", 1000> right x angle 0.01 }\n"
               "sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } scale 2 "
               "translate -y } }\n";
        return p;
    }

    Result<TraceReport> trace(const fs::path& scene, std::vector<double> nm = {}) {
        TraceOptions o;
        o.scene = scene.string();
        o.width = 3;
        o.height = 3;
        o.progress = false;
        o.wavelengths_nm = std::move(nm);
        return trace_scene(o);
    }
};

// The elevation of the sky the centre pixel shows in channel c, rad.
double horizon_sky(const TraceReport& r, int c) {
    return std::asin(2.0 * r.render.image.at(1, 1)[c] - 1.0);
}

// The standard atmosphere's refraction at the horizon from the eye, by the classical integral
// over its own index (astronomical_refraction.h), rad.
double table_refraction(double nm) {
    StandardAirSettings s;
    s.ground_temperature_k = kPulkovoTemperatureK;
    s.ground_pressure_pa = kPulkovoPressurePa;
    s.wavelength_nm = nm;
    auto air = StandardAir::make(s);
    EXPECT_TRUE(air.ok()) << air.message();
    return refraction_by_integral(*air, kEyeM, 0.0);
}

TEST_F(ColourTrace, TheSkyAtTheHorizonIsRefractedThroughTheWholeAtmosphere) {
    const double table = table_refraction(590.0);
    auto whole = trace(horizon_scene(true, "#declare Mirage_Wavelength = 590;\n"));
    ASSERT_TRUE(whole.ok()) << whole.message();
    const double seen = -horizon_sky(*whole, 1);
    std::printf("horizon refraction from %g m: traced %.2f\", integral %.2f\"\n", kEyeM,
                seen / kArcsec, table / kArcsec);
    // The scene's air is the standard atmosphere at geometric heights with constant gravity,
    // the table's at geopotential heights: 0.5" apart at the horizon.  Within 0.1 %.
    EXPECT_NEAR(seen, table, 1e-3 * table);
    // Looked up where the paths stop (10 km away, in the air's lowest 20 m), the sky is
    // refracted by the first 10 km of the path only: 55", not 33'.
    auto cut = trace(horizon_scene(false, "#declare Mirage_Wavelength = 590;\n"));
    ASSERT_TRUE(cut.ok()) << cut.message();
    EXPECT_LT(-horizon_sky(*cut, 1), 0.1 * table);
}

TEST_F(ColourTrace, TheChannelsSeparateAtTheHorizonAsCiddorsIndexSays) {
    const ChannelWavelengths nm = kDefaultChannelWavelengthsNm;
    auto r = trace(horizon_scene(true, ""), {nm[0], nm[1], nm[2]});
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_EQ(r->wavelengths_nm, std::vector<double>(nm.begin(), nm.end()));
    double seen[3], table[3];
    for (int c = 0; c < 3; ++c) {
        seen[c] = -horizon_sky(*r, c);
        table[c] = table_refraction(nm[c]);
        EXPECT_NEAR(seen[c], table[c], 1e-3 * table[c]) << nm[c] << " nm";
    }
    // Blue lifted more than green, green more than red: the separation (about 30") as the
    // table's within 1 %, far finer than the 0.1 % of the whole refraction above.
    const double separation = seen[2] - seen[0], expected = table[2] - table[0];
    std::printf("blue - red at the horizon: traced %.3f\", integral %.3f\"\n", separation / kArcsec,
                expected / kArcsec);
    EXPECT_GT(seen[1], seen[0]);
    EXPECT_GT(seen[2], seen[1]);
    EXPECT_NEAR(separation, expected, 0.01 * expected);
}

TEST_F(ColourTrace, EachChannelIsTheMonochromeRenderAtItsWavelength) {
    const fs::path scene = horizon_scene(true, "");
    auto colour = trace(scene, {610.0, 550.0, 465.0});
    ASSERT_TRUE(colour.ok()) << colour.message();
    const double nm[3] = {610.0, 550.0, 465.0};
    for (int c = 0; c < 3; ++c) {
        // A scene at one wavelength: its render's channel c is the colour render's, bit for bit.
        auto mono = trace(
            horizon_scene(true, "#declare Mirage_Wavelength = " + std::to_string(nm[c]) + ";\n"));
        ASSERT_TRUE(mono.ok()) << mono.message();
        EXPECT_TRUE(mono->wavelengths_nm.empty());
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x)
                EXPECT_EQ(colour->render.image.at(x, y)[c], mono->render.image.at(x, y)[c])
                    << nm[c] << " nm, pixel " << x << ", " << y;
    }
}

TEST_F(ColourTrace, AMonochromeRenderOfAColourSceneIsTheGreenChannelsAir) {
    auto green = trace(horizon_scene(true, "#declare Mirage_Wavelength = 550;\n"));
    ASSERT_TRUE(green.ok()) << green.message();
    TraceOptions o;
    o.scene = horizon_scene(true, "#declare Mirage_Wavelengths = <610, 550, 465>;\n").string();
    o.width = 3;
    o.height = 3;
    o.progress = false;
    o.monochrome = true;
    auto mono = trace_scene(o);
    ASSERT_TRUE(mono.ok()) << mono.message();
    EXPECT_TRUE(mono->wavelengths_nm.empty());
    EXPECT_EQ(mono->render.image.pixels, green->render.image.pixels);
    o.monochrome = false;
    auto colour = trace_scene(o);
    ASSERT_TRUE(colour.ok()) << colour.message();
    EXPECT_NE(colour->render.image.pixels, green->render.image.pixels);
}

TEST_F(ColourTrace, BadWavelengthsAreRefusedByTheOption) {
    auto few = trace(horizon_scene(true, ""), {610.0, 550.0});
    ASSERT_FALSE(few.ok());
    EXPECT_EQ(few.message(),
              "--wavelengths 610,550: give three wavelengths, the red, green and blue channels' "
              "(nm), e.g. 610,550,465");
    auto far = trace(horizon_scene(true, ""), {610.0, 550.0, 2000.0});
    ASSERT_FALSE(far.ok());
    EXPECT_EQ(far.message(),
              "--wavelengths 610,550,2000: the blue channel's wavelength 2000 nm must be from 300 "
              "to 1690 nm (Ciddor's range)");
    // The paper's exponential profile has no wavelength.
    auto road = trace(fs::path(MIRAGE_SOURCE_DIR) / "scenes" / "road.pov", {610, 550, 465});
    ASSERT_FALSE(road.ok());
    EXPECT_NE(road.message().find("--wavelengths 610,550,465: an exponential profile"),
              std::string::npos)
        << road.message();
}

}  // namespace
}  // namespace mirage
