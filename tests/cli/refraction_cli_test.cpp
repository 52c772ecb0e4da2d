// mirage refraction: the standard atmosphere's astronomical refraction beside the tables.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "atmosphere/astronomical_refraction.h"
#include "run_tool.h"
#include "test_temp.h"

namespace mirage {
namespace {

using testing::run_tool;

// At the Pulkovo tables' own conditions the table carries their column, and every row is the
// library's exact path for the same air (not the tables' numbers copied).
TEST(RefractionCli, PrintsThePathsRefractionBesideTheTables) {
    const auto r = run_tool("refraction --elevations 0,2,10 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    auto air = StandardAir::make({288.15, 101325.0, 590.0, 6371000.0});
    ASSERT_TRUE(air.ok());
    auto model = standard_air_model(*air);
    ASSERT_TRUE(model.ok());
    const auto& rows = j["refraction_arcsec"][0];
    const auto& tables = j["tables_arcsec"];
    ASSERT_EQ(rows.size(), 3u);
    ASSERT_EQ(tables.size(), 3u);
    int k = 0;
    for (double e : {0.0, 2.0, 10.0}) {
        const double want = *refraction_by_path(*air, *model, 0.0, e * M_PI / 180.0);
        EXPECT_DOUBLE_EQ(rows[k].get<double>(), want / (M_PI / 180.0 / 3600.0)) << e;
        EXPECT_NEAR(rows[k].get<double>() / tables[k].get<double>(), 1.0, 2e-3) << e;
        ++k;
    }
    // Other air: no tables column, and a colder day bends more.
    const auto cold = run_tool("refraction --temperature -20 --elevations 0 --json");
    ASSERT_EQ(cold.exit_code, 0) << cold.err;
    const auto jc = nlohmann::json::parse(cold.out);
    EXPECT_FALSE(jc.contains("tables_arcsec"));
    EXPECT_GT(jc["refraction_arcsec"][0][0].get<double>(), rows[0].get<double>() * 1.05);
}

TEST(RefractionCli, SeveralWavelengthsGiveTheColoursSeparationAndAPlot) {
    const std::string dir = mirage::testing::test_temp_path("mirage_refraction_cli");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto r = run_tool("refraction --wavelength 450,650 --elevations 0,5 --plot " + dir +
                            "/r.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("450-650 nm"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir + "/r.png"));
    EXPECT_GT(std::filesystem::file_size(dir + "/r.png"), 10000u);
}

// A plot named with a line break, quotes and a backslash is written under that very name
// (gnuplot reads the name back from its script: report/gnuplot_run.h, gnuplot_quoted).
TEST(RefractionCli, APlotNameWithALineBreakAndQuotesIsKept) {
    const std::string dir = mirage::testing::test_temp_path("mirage_refraction_names");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const std::string name : {"new\nline.png", "it's \"q\" \\b.png"}) {
        const std::string path = dir + "/" + name;
        const auto r = run_tool("refraction --elevations 0 --plot " + testing::quoted(path));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(std::filesystem::exists(path)) << name;
    }
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                            std::filesystem::directory_iterator()),
              2);
}

TEST(RefractionCli, RefusesAirAndAnglesOutsideTheirRangesNamingTheValue) {
    const struct {
        const char* args;
        const char* says;
    } cases[] = {
        {"refraction --temperature 500", "temperature 500 degC must be from -53.15 to 56.85 degC"},
        {"refraction --pressure 20", "pressure 20 hPa must be from 500 to 1100 hPa"},
        {"refraction --wavelength 200", "wavelength 200 nm must be from 300 to 1690 nm"},
        {"refraction --elevations 0,95", "elevation 95 degrees must be from 0 to 90"},
        {"refraction --observer-height -3", "observer height -3 m must be from 0 to 10000 m"},
    };
    for (const auto& c : cases) {
        const auto r = run_tool(c.args);
        EXPECT_EQ(r.exit_code, 1) << c.args;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    }
}

}  // namespace
}  // namespace mirage
