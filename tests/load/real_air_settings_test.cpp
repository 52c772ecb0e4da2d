// Real air in scenes: Mirage_Sounding, the temperature forms and Mirage_Earth_Radius, read
// where the other Mirage_ settings are, each range checked once with its place.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"
#include "load/mirage_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

class RealAirSettings : public ::testing::Test {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_real_air_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_ / "air"); }
    void TearDown() override { fs::remove_all(dir_); }

    std::string scene(const std::string& settings) {
        const fs::path p = dir_ / "s.pov";
        std::ofstream(p) << settings
                         << "\ncamera { location <0, 1.5, 0> look_at <0, 1.5, 10> }\n"
                            "sphere { <0, 1, 10>, 1 }\n";
        return p.string();
    }
    Result<MirageScene> load(const std::string& settings) {
        SceneLoadOptions o;
        o.scene = scene(settings);
        o.width = 64;
        o.height = 48;
        return load_mirage_scene(o);
    }
    std::string error(const std::string& settings) {
        auto r = load(settings);
        EXPECT_FALSE(r.ok()) << settings;
        return r.ok() ? std::string() : r.message();
    }
};

TEST_F(RealAirSettings, ASoundingIsReadBesideTheSceneAndIsOneOfItsInputs) {
    std::ofstream(dir_ / "air" / "road.csv")
        << "height_m,temperature_c\n0,45\n0.1,38\n0.5,31\n2,29\n10,28.5\n";
    auto r = load("#declare Mirage_Sounding = \"air/road.csv\";");
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_TRUE(r->settings.air);
    EXPECT_TRUE(bends_rays(r->settings));
    EXPECT_EQ(r->settings.air->source, AirSpec::Source::Sounding);
    EXPECT_EQ(r->settings.air->sounding.height_m.size(), 5u);
    // Real air defaults to the curved Earth.
    EXPECT_DOUBLE_EQ(r->settings.air->earth_radius_m, kEarthRadiusM);
    const std::string csv = (dir_ / "air" / "road.csv").string();
    EXPECT_EQ(r->scene.files.back(), csv);  // OutputSet keeps every output off it
    EXPECT_NE(r->settings.profile_label.find("sounding air/road.csv (5 rows of temperature)"),
              std::string::npos)
        << r->settings.profile_label;
    // The fitted model: hot at the ground, in scene units (Mirage_Unit = 0.5 m per unit
    // halves the heights of its knots).
    auto m = scene_atmosphere(r->settings, 1e-4);
    ASSERT_TRUE(m.ok()) << m.message();
    ASSERT_TRUE(m->quadratic_profile());
    EXPECT_LT(m->n(0.0), m->n(2.0));  // hot ground: the index grows with height
    auto half = load("#declare Mirage_Sounding = \"air/road.csv\";\n#declare Mirage_Unit = 0.5;");
    ASSERT_TRUE(half.ok()) << half.message();
    auto mh = scene_atmosphere(half->settings, 1e-4);
    ASSERT_TRUE(mh.ok()) << mh.message();
    for (double y : {0.05, 0.3, 1.0, 4.0}) EXPECT_NEAR(mh->n(y / 0.5), m->n(y), 1e-15) << y;
}

TEST_F(RealAirSettings, TheFormsMakeOneColumnOfAir) {
    auto r = load(
        "#declare Mirage_Air_Temperature = 288.15;\n#declare Mirage_Lapse = 6.5;\n"
        "#declare Mirage_Inversion = <50, 60, 2>;\n#declare Mirage_Inversion_Smoothing = 0.85;\n"
        "#declare Mirage_Inversion_2 = <100, 120, 1>;\n#declare Mirage_Index = \"ciddor\";\n"
        "#declare Mirage_Earth_Radius = 6371000;");
    ASSERT_TRUE(r.ok()) << r.message();
    const AirSpec& a = *r->settings.air;
    EXPECT_EQ(a.source, AirSpec::Source::Column);
    EXPECT_DOUBLE_EQ(a.column.ground_temperature_k, 288.15);
    EXPECT_DOUBLE_EQ(a.column.lapse_k_per_m, 6.5e-3);
    ASSERT_EQ(a.column.inversions.size(), 2u);
    EXPECT_DOUBLE_EQ(a.column.inversions[0].smoothing_m, 0.85);
    EXPECT_DOUBLE_EQ(a.column.inversions[1].bottom_m, 100.0);
    EXPECT_DOUBLE_EQ(a.column.inversions[1].smoothing_m, 0.0);
    EXPECT_EQ(a.index.formula, IndexFormula::Ciddor);
    // Young's duct, as `mirage path ... --ducts` finds it, from the scene's settings.
    auto m = scene_atmosphere(r->settings, 1e-5);
    ASSERT_TRUE(m.ok()) << m.message();
    const auto ducts = find_ducts(*m->quadratic_profile());
    ASSERT_FALSE(ducts.empty());
    EXPECT_NEAR(height_above_sphere(ducts.front().bottom, 6371000.0), 45.78, 0.05);

    // The exponential fit alone stays the closed forms; an Earth radius sends a preset
    // through the general engine, 0 keeps it flat and closed.
    auto old = load(
        "#declare Mirage_Air_Temperature = 275;\n#declare Mirage_Ground_Temperature = 260;\n"
        "#declare Mirage_Scale_Height = 3;");
    ASSERT_TRUE(old.ok()) << old.message();
    EXPECT_FALSE(old->settings.air);
    EXPECT_EQ(old->settings.profile.kind, ProfileKind::Superior);
    auto curved =
        load("#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Earth_Radius = 6371000;");
    ASSERT_TRUE(curved.ok()) << curved.message();
    ASSERT_TRUE(curved->settings.air);
    EXPECT_EQ(curved->settings.air->source, AirSpec::Source::Exponential);
    auto flat = load("#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Earth_Radius = 0;");
    ASSERT_TRUE(flat.ok()) << flat.message();
    EXPECT_FALSE(flat->settings.air);
    // With a form, the same three values describe the column exactly.
    auto exact = load(
        "#declare Mirage_Air_Temperature = 275;\n#declare Mirage_Ground_Temperature = 260;\n"
        "#declare Mirage_Scale_Height = 3;\n#declare Mirage_Lapse = 0;\n"
        "#declare Mirage_Earth_Radius = 0;");
    ASSERT_TRUE(exact.ok()) << exact.message();
    ASSERT_TRUE(exact->settings.air);
    ASSERT_EQ(exact->settings.air->column.layers.size(), 1u);
    EXPECT_DOUBLE_EQ(exact->settings.air->column.layers[0].delta_k, -15.0);
    EXPECT_DOUBLE_EQ(exact->settings.air->earth_radius_m, 0.0);
}

TEST_F(RealAirSettings, EachValueOutOfRangeIsNamedWithItsPlaceAndLimit) {
    const std::string s = (dir_ / "s.pov").string();
    EXPECT_EQ(error("#declare Mirage_Lapse = 500;"),
              s + ":1:10: Mirage_Lapse = 500 must be from -100 to 100 (K per km)");
    EXPECT_EQ(error("\n#declare Mirage_Earth_Radius = 1000;"),
              s + ":2:10: Mirage_Earth_Radius = 1000 must be 0 (flat ground) or from 1e+05 to "
                  "1e+09 (m)");
    EXPECT_EQ(error("#declare Mirage_Inversion = <60, 50, 2>;"),
              s + ":1:10: Mirage_Inversion = <60, 50, 2>: its bottom must be at least 0 and its "
                  "top above the bottom and at most 10000 m");
    EXPECT_EQ(error("#declare Mirage_Inversion = 3;"),
              s + ":1:10: Mirage_Inversion must be a vector, e.g. <50, 60, 2> (bottom m, top m, "
                  "rise K)");
    EXPECT_EQ(error("#declare Mirage_Inversion_Smoothing = 1;"),
              s + ":1:10: Mirage_Inversion_Smoothing without Mirage_Inversion");
    EXPECT_EQ(error("#declare Mirage_Inversion = <50, 60, 2>;\n#declare Mirage_Inversion_3 = <1, "
                    "2, 1>;"),
              s + ":2:10: Mirage_Inversion_3 without Mirage_Inversion_2 (number them without "
                  "gaps)");
    EXPECT_EQ(error("#declare Mirage_Humidity = 120;"),
              s + ":1:10: Mirage_Humidity = 120 must be from 0 to 100 (%)");
    EXPECT_EQ(error("#declare Mirage_Index = \"edlen\";"),
              s + ":1:10: Mirage_Index: unknown index formula 'edlen' (expected gladstone-dale or "
                  "ciddor)");
    // Misspellings are caught like the others'.
    EXPECT_EQ(error("#declare Mirage_Invresion = <50, 60, 2>;"),
              s + ":1:10: unknown setting Mirage_Invresion (did you mean Mirage_Inversion?)");
    EXPECT_EQ(error("#declare Mirage_Earth_Radios = 0;"),
              s + ":1:10: unknown setting Mirage_Earth_Radios (did you mean Mirage_Earth_Radius?)");
    // One way to say the air.
    EXPECT_EQ(error("#declare Mirage_Preset = \"paper\";\n#declare Mirage_Lapse = 6.5;"),
              s + ":1:10: declare the atmosphere one way: an exponential profile (Mirage_Preset, "
                  "Mirage_Profile) or real air (Mirage_Sounding, Mirage_Lapse, Mirage_Inversion, "
                  "...)");
    std::ofstream(dir_ / "t.csv") << "height_m,temperature_c\n0,20\n1,19\n";
    EXPECT_EQ(error("#declare Mirage_Sounding = \"t.csv\";\n#declare Mirage_Lapse = 6.5;"),
              s + ":1:10: Mirage_Sounding gives the whole profile: leave out Mirage_Lapse, "
                  "Mirage_Inversion and the Mirage_..._Temperature values");
    // What the whole column breaks is named at the setting that describes it.
    EXPECT_EQ(error("#declare Mirage_Inversion = <50, 60, 2>;\n#declare Mirage_Top = 55;"),
              s + ":2:10: inversion top 60 m must lie below the profile's top 55 m");
}

TEST_F(RealAirSettings, ABadSoundingIsRefusedWithItsFileLineAndColumn) {
    const std::string s = (dir_ / "s.pov").string();
    std::ofstream(dir_ / "bad.csv") << "height_m,temperature_c\n0,20\n0.5,nan\n";
    EXPECT_EQ(error("#declare Mirage_Sounding = \"bad.csv\";"),
              s + ":1:10: Mirage_Sounding: " + (dir_ / "bad.csv").string() +
                  ":3:5: column 'temperature_c': 'nan' is not a finite number");
    const std::string missing = error("#declare Mirage_Sounding = \"none.csv\";");
    EXPECT_EQ(missing.rfind(s + ":1:10: Mirage_Sounding: " + (dir_ / "none.csv").string() +
                                ": cannot be opened",
                            0),
              0u)
        << missing;
    // A device or a directory is no sounding (reading /dev/zero would never end).
    EXPECT_EQ(error("#declare Mirage_Sounding = \"/dev/zero\";"),
              s + ":1:10: Mirage_Sounding: /dev/zero: is not a regular file (a device, a pipe or "
                  "a socket?): soundings are read from files");
    EXPECT_EQ(error("#declare Mirage_Sounding = \"air\";"),
              s + ":1:10: Mirage_Sounding: " + (dir_ / "air").string() +
                  ": is a directory, not a sounding");
}

TEST_F(RealAirSettings, IndexStepsAreAskedForByNameAndAMisspellingListsTheDesigns) {
    std::ofstream(dir_ / "air" / "road.csv") << "height_m,temperature_c\n0,45\n0.5,31\n10,28.5\n";
    auto r = load("#declare Mirage_Sounding = \"air/road.csv\";\n"
             "#declare Mirage_Layers = \"index-steps\";\n#declare Mirage_Layer_Count = 32;");
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->settings.layers, LayerMode::IndexSteps);
    EXPECT_EQ(r->settings.layer_count, 32);
    const std::string e = error("#declare Mirage_Layers = \"index_steps\";");
    EXPECT_NE(e.find("s.pov:1:"), std::string::npos) << e;
    EXPECT_NE(e.find("Mirage_Layers \"index_steps\": expected \"adaptive\", \"uniform\" or "
                     "\"index-steps\""),
              std::string::npos)
        << e;
}

}  // namespace
}  // namespace mirage
