#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_tool.h"
#include "util/csv.h"

namespace mirage {
namespace {

using testing::run_tool;

TEST(PathCli, PrintsClassTurningPointAndSamples) {
    auto r = run_tool("path --preset paper --eye-height 1.5 --elevation-deg -10");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("class       inf_turn"), std::string::npos) << r.out;
    EXPECT_NE(
        r.out.find("turning     lowest point y = 0.6894575529 m at dz = 7.179101315 m (ahead)"),
        std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("ground      not reached"), std::string::npos);
}

TEST(PathCli, JsonCarriesTheSamples) {
    auto r = run_tool("path --preset hot-road --eye-height 1.5 --elevation-deg -0.2 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["ray_class"], "inf_turn");
    EXPECT_GT(j["samples"].size(), 3u);
    EXPECT_EQ(j["samples"][0][0], 0.0);
    EXPECT_EQ(j["samples"][0][1], 1.5);
    EXPECT_EQ(j["end"], "straight");
}

TEST(PathCli, BatchReproducesTheReferenceFile) {
    auto r = run_tool("path --batch " + std::string(MIRAGE_REFERENCE_DIR) + "/path_public.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto got = parse_csv(r.out, "stdout");
    ASSERT_TRUE(got.ok()) << got.message();
    auto ref = read_csv_file(std::string(MIRAGE_REFERENCE_DIR) + "/path_public.csv");
    ASSERT_TRUE(ref.ok());
    ASSERT_EQ(got->rows.size(), ref->rows.size());
    const std::vector<std::string> cols = {
        "case_id", "k2",   "k",       "y_turn",  "dz_turn", "turn_kind",   "ray_class", "y_d1",
        "y_d2",    "y_d3", "dydz_d1", "dydz_d2", "dydz_d3", "hits_ground", "dz_ground"};
    ASSERT_EQ(got->header, cols);
    for (size_t i = 0; i < ref->rows.size(); ++i) {
        const auto& g = got->rows[i];
        const auto& f = ref->rows[i];
        const double tol = std::stod(f.fields[ref->column("tol_rel")]);
        const double y0 = std::stod(f.fields[ref->column("y0")]);
        for (const auto& c : cols) {
            const std::string a = g.fields[got->column(c)], b = f.fields[ref->column(c)];
            if (c == "case_id" || c == "turn_kind" || c == "ray_class" || c == "hits_ground" ||
                b == "nan") {
                EXPECT_EQ(a, b) << f.fields[0] << " " << c;
                continue;
            }
            const double x = std::stod(a), y = std::stod(b);
            const bool height = c == "y_turn" || c.rfind("y_d", 0) == 0;
            const double scale = height ? std::max(y0, std::fabs(y)) : std::fabs(y);
            EXPECT_LE(std::fabs(x - y) / scale, tol) << f.fields[0] << " " << c;
        }
        // 17 significant digits, as the reference.
        std::string digits;
        for (char ch : g.fields[got->column("k2")]) {
            if (ch == 'e') break;
            if (std::isdigit(static_cast<unsigned char>(ch)) && !(digits.empty() && ch == '0'))
                digits += ch;
        }
        EXPECT_EQ(digits.size(), 17u) << g.fields[got->column("k2")];
    }
}

TEST(PathCli, BadCsvRowNamesTheRowAndColumn) {
    const std::string path = std::string(::testing::TempDir()) + "bad_rays.csv";
    std::ofstream(path) << "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n"
                           "A,inferior,1.000233,0.4584,2.303,1.0,1.9,1,2,3\n"
                           "B,inferior,1.000233,0.4584,2.3x,1.0,1.9,1,2,3\n";
    auto r = run_tool("path --batch " + path);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err,
              "mirage path: " + path + ":3:28: column 'alpha': '2.3x' is not a decimal number\n");

    std::ofstream(path) << "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n"
                           "A,superior,1.0,1.5,2.303,1.0,1.9,1,2,3\n";
    r = run_tool("path --batch " + path);
    EXPECT_EQ(r.err, "mirage path: " + path +
                         ":2:16: eta1 = 1.5: a superior profile needs eta0^2 > eta1^2, and eta0 "
                         "= 1 (the index aloft would not be real)\n");

    std::ofstream(path) << "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2\n"
                           "A,inferior,1.0,1.5,2.303,1.0,1.9,1,2\n";
    r = run_tool("path --batch " + path);
    EXPECT_EQ(r.err, "mirage path: " + path + ":1: missing column 'd3'\n");

    std::ofstream(path) << "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n"
                           "A,inferior,1.000233,0.4584,2.303,1.0,3.5,1,2,3\n";
    r = run_tool("path --batch " + path);
    EXPECT_EQ(r.err, "mirage path: " + path +
                         ":2:38: i_rad: angle from the vertical i = 3.5 rad must lie strictly "
                         "between 0 and pi (a vertical ray has no horizontal distance)\n");
}

TEST(PathCli, BadFlagsAndValuesAreNamed) {
    auto r = run_tool("path --preset paper --eye-height abc --elevation-deg 1");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("Could not convert: --eye-height = abc"), std::string::npos) << r.err;

    r = run_tool("path --preset paper --eye-hieght 1 --elevation-deg 1");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--eye-hieght"), std::string::npos) << r.err;

    r = run_tool("path --preset paper --eye-height 0 --elevation-deg 1");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --eye-height 0: the eye must be above the ground (> 0 m) and at most "
              "1e+09 m\n");

    r = run_tool("path --preset sahara --eye-height 1 --elevation-deg 1");
    EXPECT_EQ(r.err,
              "mirage path: --preset: unknown preset 'sahara' (known: paper, paper-superior, "
              "hot-road, cold-sea)\n");

    r = run_tool(
        "path --profile inferior --eta0 1.0003 --eta1 0.01 --alpha -2 --eye-height 1 "
        "--elevation-deg 1");
    EXPECT_EQ(r.err, "mirage path: --alpha = -2 must be from 1e-09 to 1e+09 (1/m)\n");

    r = run_tool("path --preset paper --eye-height 1");
    EXPECT_EQ(r.err,
              "mirage path: give the ray's direction with --elevation-deg DEG (or --i-rad RAD)\n");
}

TEST(PathCli, SvgDiagramIsWrittenWithTheFan) {
    const std::string svg = std::string(::testing::TempDir()) + "fan.svg";
    std::remove(svg.c_str());
    auto r = run_tool(
        "path --preset paper --eye-height 1.5 --elevation-deg -10 --fan-count 7 --svg " + svg);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(svg);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.rfind("<svg", 0), 0u);
    size_t curves = 0;
    for (size_t p = 0; (p = text.find("<polyline", p)) != std::string::npos; ++p) ++curves;
    EXPECT_EQ(curves, 7u);
    EXPECT_NE(text.find("height (m)"), std::string::npos);
}

}  // namespace
}  // namespace mirage
