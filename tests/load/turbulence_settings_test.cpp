// The scene's turbulent air: Mirage_Turbulence_Cn2, _Inner, _Outer, _Seed, _Aperture and
// Mirage_Wind, read with their defaults and refused out of range with their place.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "load/mirage_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

class TurbulenceSettingsLoad : public ::testing::Test {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_turbulence_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
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
        return load_mirage_scene(o);
    }
    std::string error(const std::string& settings) {
        auto r = load(settings);
        EXPECT_FALSE(r.ok()) << settings;
        return r.ok() ? std::string() : r.message();
    }
    std::string at(int line) {
        return (dir_ / "s.pov").string() + ":" + std::to_string(line) + ":10: ";
    }
};

TEST_F(TurbulenceSettingsLoad, ReadsTheValuesAndTheDefaults) {
    auto r = load(
        "#declare Mirage_Turbulence_Cn2 = 5e-13;\n"
        "#declare Mirage_Turbulence_Inner = 0.004;\n"
        "#declare Mirage_Turbulence_Outer = 2;\n"
        "#declare Mirage_Wind = <1.5, 0, -0.5>;\n"
        "#declare Mirage_Turbulence_Seed = 42;\n"
        "#declare Mirage_Turbulence_Aperture = 0.05;");
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_TRUE(r->settings.turbulence.has_value());
    const TurbulenceSettings& t = *r->settings.turbulence;
    EXPECT_EQ(t.cn2, 5e-13);
    EXPECT_EQ(t.inner_scale_m, 0.004);
    EXPECT_EQ(t.outer_scale_m, 2.0);
    EXPECT_EQ(t.wind, glm::dvec3(1.5, 0.0, -0.5));
    EXPECT_EQ(t.seed, 42u);
    EXPECT_EQ(r->settings.turbulence_aperture_m, 0.05);
    // Off by default, and with C_n^2 = 0 (whatever goes with it).
    auto none = load("");
    ASSERT_TRUE(none.ok()) << none.message();
    EXPECT_FALSE(none->settings.turbulence.has_value());
    auto zero = load("#declare Mirage_Turbulence_Cn2 = 0;\n#declare Mirage_Wind = <1, 0, 0>;");
    ASSERT_TRUE(zero.ok()) << zero.message();
    EXPECT_FALSE(zero->settings.turbulence.has_value());
    auto defaults = load("#declare Mirage_Turbulence_Cn2 = 1e-13;");
    ASSERT_TRUE(defaults.ok()) << defaults.message();
    EXPECT_EQ(defaults->settings.turbulence->inner_scale_m, TurbulenceSettings{}.inner_scale_m);
    EXPECT_EQ(defaults->settings.turbulence->seed, 1u);
}

TEST_F(TurbulenceSettingsLoad, EachValueOutOfRangeIsRefusedWithItsPlace) {
    const std::string cn2 = "#declare Mirage_Turbulence_Cn2 = 1e-13;\n";
    EXPECT_EQ(error("#declare Mirage_Turbulence_Cn2 = -1e-14;"),
              at(1) + "Mirage_Turbulence_Cn2 = -1e-14 must be from 0 to 1e-08 (m^-2/3)");
    EXPECT_EQ(error("#declare Mirage_Turbulence_Cn2 = 1;"),
              at(1) + "Mirage_Turbulence_Cn2 = 1 must be from 0 to 1e-08 (m^-2/3)");
    EXPECT_EQ(error("#declare Mirage_Turbulence_Cn2 = \"strong\";"),
              at(1) + "Mirage_Turbulence_Cn2 must be a number");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Turbulence_Inner = 0;"),
              at(2) + "Mirage_Turbulence_Inner = 0 must be from 1e-05 to 1e+05 (m)");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Turbulence_Outer = 1e6;"),
              at(2) + "Mirage_Turbulence_Outer = 1e+06 must be from 1e-05 to 1e+05 (m)");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Turbulence_Inner = 3;"),
              at(2) +
                  "the inner scale 3 m (Mirage_Turbulence_Inner) must be below the outer "
                  "scale 1 m (Mirage_Turbulence_Outer)");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Turbulence_Outer = 0.001;"),
              at(2) +
                  "the inner scale 0.005 m (Mirage_Turbulence_Inner) must be below the outer "
                  "scale 0.001 m (Mirage_Turbulence_Outer)");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Wind = <2000, 0, 0>;"),
              at(2) + "Mirage_Wind = <2000, 0, 0>: its speed 2000 m/s must be at most 1000 m/s");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Wind = 3;"),
              at(2) + "Mirage_Wind must be a vector, e.g. <1.5, 0, 0> (m/s)");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Turbulence_Seed = 1.5;"),
              at(2) + "Mirage_Turbulence_Seed = 1.5 must be a whole number from 0 to 4294967295");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Turbulence_Seed = -1;"),
              at(2) + "Mirage_Turbulence_Seed = -1 must be from 0 to 4294967295 (a whole number)");
    EXPECT_EQ(error(cn2 + "#declare Mirage_Turbulence_Aperture = 20;"),
              at(2) + "Mirage_Turbulence_Aperture = 20 must be from 0 to 10 (m)");
    // A setting of the turbulence without its strength is a mistake, not ignored.
    EXPECT_EQ(error("#declare Mirage_Wind = <1, 0, 0>;"),
              at(1) + "Mirage_Wind without Mirage_Turbulence_Cn2 (the turbulence's strength)");
    // And a misspelt name is named as every Mirage_ name is.
    EXPECT_EQ(error("#declare Mirage_Turbulence_Cn = 1e-13;"),
              at(1) + "unknown setting Mirage_Turbulence_Cn (did you mean Mirage_Turbulence_Cn2?)");
}

}  // namespace
}  // namespace mirage
