// The path command's air: which model each description gets, the legend it is shown with, and
// the ducts found in it.
#include "paths/path_air.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/format.h"

namespace mirage {
namespace {

TEST(PathAir, AnExponentialProfileKeepsItsClosedFormsOnFlatGroundOnly) {
    PathAirOptions o;
    o.preset = "cold-sea";
    auto reference = resolve_reference_air(o);
    ASSERT_TRUE(reference.ok()) << reference.message();
    EXPECT_EQ(reference->form, AirForm::Reference);
    ASSERT_NE(reference->atmosphere.exponential_profile(), nullptr);
    EXPECT_EQ(reference->atmosphere.exponential_profile()->kind, ProfileKind::Superior);
    EXPECT_TRUE(reference->legend.empty());

    auto closed = resolve_air(o);
    ASSERT_TRUE(closed.ok()) << closed.message();
    EXPECT_EQ(closed->form, AirForm::General);
    EXPECT_NE(closed->atmosphere.exponential_profile(), nullptr);
    EXPECT_EQ(closed->legend.back(), "closed forms");

    for (bool general : {true, false}) {
        PathAirOptions fitted = o;
        fitted.general = general;
        if (!general) fitted.earth_radius = 6371000.0;
        auto air = resolve_air(fitted);
        ASSERT_TRUE(air.ok()) << air.message();
        ASSERT_NE(air->atmosphere.quadratic_profile(), nullptr) << general;
        EXPECT_EQ(air->atmosphere.earth_radius(), general ? 0.0 : 6371000.0);
        EXPECT_EQ(air->legend.back(),
                  "fitted: " + std::to_string(air->fit.pieces) + " pieces, |dn| <= 1e-10");
    }
}

TEST(PathAir, YoungsInversionHasItsDuctWhereTheDocumentationSays) {
    // docs/commands.md: the duct's bottom at 45.35 m (Young: 45.3 m) on the curved Earth.
    PathAirOptions o;
    o.air_temperature_c = 15.0;
    o.lapse_k_per_km = 6.5;
    o.inversions = {"50,60,2"};
    o.earth_radius = 6371000.0;
    o.index = "ciddor";
    auto air = resolve_air(o);
    ASSERT_TRUE(air.ok()) << air.message();
    const auto ducts = duct_heights(*air);
    ASSERT_EQ(ducts.size(), 1u);
    EXPECT_NEAR(ducts[0].first, 45.35, 0.005);
    EXPECT_NEAR(ducts[0].second, 60.0, 0.5);
    std::ostringstream text;
    write_air_text(*air, text);
    EXPECT_EQ(text.str(),
              "profile     air at 15 degC\n"
              "            lapse 6.5 K/km\n"
              "            inversion 2 K, 50 to 60 m\n"
              "            index: Ciddor, 550 nm\n"
              "            pressure 1013.25 hPa, hydrostatic\n"
              "            fitted: " +
                  std::to_string(air->fit.pieces) +
                  " pieces, |dn| <= 1e-10\n"
                  "            Earth radius 6371000 m: heights above the sphere, distances "
                  "along it\n"
                  "ducts       level rays trapped from " +
                  sig(ducts[0].first, 10) + " m to " + sig(ducts[0].second, 10) + " m\n");
    const nlohmann::json j = air_json(*air);
    EXPECT_EQ(j["ducts"][0]["bottom"].get<double>(), ducts[0].first);
    EXPECT_EQ(j["pieces"].get<int>(), air->fit.pieces);
}

TEST(PathAir, BadDescriptionsAreNamed) {
    auto error_of = [](const PathAirOptions& o) {
        auto air = resolve_air(o);
        return air.ok() ? std::string("(no error)") : air.message();
    };
    PathAirOptions o;
    o.surface_layers = {"20,x"};
    EXPECT_EQ(error_of(o), "--surface-layer 20,x: 'x' is not a number (expected DT_K,SCALE_M)");
    o.surface_layers = {"1e308,1"};
    EXPECT_EQ(error_of(o),
              "--surface-layer 1e308,1: temperature excess 1e+308 K must be from -100 to 100 K");
    o.surface_layers.clear();
    o.preset = "paper";
    o.inversions = {"50,60,2"};
    EXPECT_EQ(error_of(o).rfind("--preset/--profile give an exponential profile and ", 0), 0u);
    o.inversions.clear();
    o.preset.clear();
    o.profile = "inferior";
    o.eta0 = 1.0003;
    EXPECT_EQ(error_of(o), "--profile inferior needs --eta0, --eta1 and --alpha");
    o.profile.clear();
    o.index = "edlen";
    EXPECT_EQ(error_of(o),
              "--index: unknown index formula 'edlen' (expected gladstone-dale or ciddor)");
    o.index.clear();
    o.eta0 = kNotGiven;
    o.sounding = "any.csv";
    o.sounding_max_gap = 0.0;
    EXPECT_EQ(error_of(o), "--sounding-max-gap 0: must be more than 0 and at most 10000 m");
}

TEST(PathAir, TheDefaultAirIsNotGiven) {
    PathAirOptions o;
    EXPECT_FALSE(air_given(o));
    auto air = resolve_air(o);
    ASSERT_TRUE(air.ok());
    EXPECT_EQ(air->label, "air at 15 degC");
    o.isobaric = true;
    EXPECT_TRUE(air_given(o));
}

}  // namespace
}  // namespace mirage
