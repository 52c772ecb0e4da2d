// Colour and the upper air in a scene: Mirage_Wavelengths (the red, green and blue channels'
// wavelengths) and Mirage_Upper_Air, read and refused with their place; the wavelength a
// command puts in place of the scene's (SceneInput::wavelength_nm).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "atmosphere/general_profile.h"
#include "load/mirage_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRealAir =
    "#declare Mirage_Air_Temperature = 288.15;\n"
    "#declare Mirage_Lapse = 6.5;\n"
    "#declare Mirage_Index = \"ciddor\";\n";

class ColourSettingsLoad : public ::testing::Test {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_colour_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }

    Result<MirageScene> load(const std::string& settings, std::optional<double> nm = {}) {
        const fs::path p = dir_ / "s.pov";
        std::ofstream(p) << settings
                         << "\ncamera { location <0, 10, 0> look_at <0, 10, 1000> }\n"
                            "sphere { <0, 1, 1000>, 1 }\n";
        SceneLoadOptions o;
        o.scene = p.string();
        o.wavelength_nm = nm;
        return load_mirage_scene(o);
    }
    std::string error(const std::string& settings, std::optional<double> nm = {}) {
        auto r = load(settings, nm);
        EXPECT_FALSE(r.ok()) << settings;
        return r.ok() ? std::string() : r.message();
    }
    std::string at(int line, int column = 10) {
        return (dir_ / "s.pov").string() + ":" + std::to_string(line) + ":" +
               std::to_string(column) + ": ";
    }
};

TEST_F(ColourSettingsLoad, ReadsTheChannelsAndGivesTheAirTheGreenOne) {
    auto r = load(std::string(kRealAir) + "#declare Mirage_Wavelengths = <620, 540, 450>;\n");
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_TRUE(r->settings.channel_wavelengths_nm.has_value());
    EXPECT_EQ(*r->settings.channel_wavelengths_nm, (ChannelWavelengths{620.0, 540.0, 450.0}));
    ASSERT_TRUE(r->settings.air);
    EXPECT_EQ(r->settings.air->index.wavelength_nm, 540.0);
    EXPECT_NE(r->settings.profile_label.find("Ciddor 540 nm"), std::string::npos)
        << r->settings.profile_label;
    // Without it: monochrome.
    auto mono = load(kRealAir);
    ASSERT_TRUE(mono.ok()) << mono.message();
    EXPECT_FALSE(mono->settings.channel_wavelengths_nm.has_value());
}

TEST_F(ColourSettingsLoad, AWavelengthOutOfRangeIsRefusedWithItsPlaceAndChannel) {
    EXPECT_EQ(error(std::string(kRealAir) + "#declare Mirage_Wavelengths = <610, 550, 250>;\n"),
              at(4) +
                  "Mirage_Wavelengths = <610, 550, 250>: the blue channel's wavelength 250 "
                  "nm must be from 300 to 1690 nm (Ciddor's range)");
    EXPECT_EQ(error(std::string(kRealAir) + "#declare Mirage_Wavelengths = <2000, 550, 465>;\n"),
              at(4) +
                  "Mirage_Wavelengths = <2000, 550, 465>: the red channel's wavelength "
                  "2000 nm must be from 300 to 1690 nm (Ciddor's range)");
    EXPECT_EQ(error(std::string(kRealAir) + "#declare Mirage_Wavelengths = 550;\n"),
              at(4) +
                  "Mirage_Wavelengths must be a vector, e.g. <610, 550, 465> (red, green, "
                  "blue; nm)");
}

TEST_F(ColourSettingsLoad, AirWithoutAWavelengthIsRefused) {
    // An exponential profile (the paper's), Gladstone-Dale's index, and both settings at once.
    const std::string paper = error(
        "#declare Mirage_Preset = \"paper\";\n#declare Mirage_Wavelengths = <610, 550, 465>;\n");
    EXPECT_EQ(
        paper.rfind(at(2) + "Mirage_Wavelengths = <610, 550, 465>: an exponential profile", 0), 0u)
        << paper;
    const std::string gd =
        error("#declare Mirage_Lapse = 6.5;\n#declare Mirage_Wavelengths = <610, 550, 465>;\n");
    EXPECT_EQ(gd, at(2) +
                      "Mirage_Wavelengths = <610, 550, 465>: Gladstone-Dale's index has no "
                      "wavelength: declare Mirage_Index = \"ciddor\"");
    const std::string both = error(std::string(kRealAir) +
                                   "#declare Mirage_Wavelength = 590;\n"
                                   "#declare Mirage_Wavelengths = <610, 550, 465>;\n");
    EXPECT_EQ(both.rfind(at(4) + "declare one: Mirage_Wavelength", 0), 0u) << both;
}

TEST_F(ColourSettingsLoad, ACommandsWavelengthReplacesTheScenes) {
    auto r =
        load(std::string(kRealAir) + "#declare Mirage_Wavelengths = <610, 550, 465>;\n", 465.0);
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->settings.air->index.wavelength_nm, 465.0);
    EXPECT_FALSE(r->settings.channel_wavelengths_nm.has_value());  // one channel's design
    const std::string paper = error("#declare Mirage_Preset = \"paper\";\n", 610.0);
    EXPECT_NE(paper.find("s.pov: the wavelength 610 nm: an exponential profile"), std::string::npos)
        << paper;
}

TEST_F(ColourSettingsLoad, TheUpperAirIsReadAndRefusedWhereItCannotBe) {
    auto r = load(std::string(kRealAir) + "#declare Mirage_Upper_Air = \"standard\";\n");
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_TRUE(r->settings.air->upper_air);
    auto none = load(std::string(kRealAir) + "#declare Mirage_Upper_Air = \"none\";\n");
    ASSERT_TRUE(none.ok()) << none.message();
    EXPECT_FALSE(none->settings.air->upper_air);
    EXPECT_EQ(error(std::string(kRealAir) + "#declare Mirage_Upper_Air = \"standrad\";\n"),
              at(4) +
                  "Mirage_Upper_Air \"standrad\": expected \"standard\" (the standard "
                  "atmosphere above Mirage_Top, to 47 km) or \"none\" (homogeneous air "
                  "above)");
    EXPECT_EQ(error(std::string(kRealAir) +
                    "#declare Mirage_Earth_Radius = 0;\n#declare Mirage_Upper_Air = "
                    "\"standard\";\n"),
              at(5) +
                  "Mirage_Upper_Air \"standard\": the upper air is the curved Earth's; on "
                  "flat ground (Mirage_Earth_Radius = 0) rays never leave the air");
}

}  // namespace
}  // namespace mirage
