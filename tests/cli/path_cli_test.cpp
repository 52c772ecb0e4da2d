#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_tool.h"
#include "test_temp.h"
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
    const std::string path = mirage::testing::test_temp_path("bad_rays.csv").string();
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
    const std::string svg = mirage::testing::test_temp_path("fan.svg").string();
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

// ---- Real air: any profile through the general engine ----------------------------------------

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"

namespace mirage {
namespace {

std::string temp_path(const std::string& name) {
    return mirage::testing::test_temp_path(name).string();
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The flags build the profile the library builds from the same numbers: the ray the tool prints
// is the library's ray, to the last bit.
TEST(PathCli, RealAirFromTemperatureFormsIsTheLibrarysRay) {
    auto r = run_tool(
        "path --air-temperature-c 27 --surface-layer 20,0.3 --inversion 2,4,1.5,0.3 --top 100 "
        "--eye-height 1.5 --elevation-deg -0.2 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    AirSpec spec;
    spec.column.ground_temperature_k = 27.0 + 273.15;
    spec.column.layers.push_back({20.0, 0.3});
    spec.column.inversions.push_back({2.0, 4.0, 1.5, 0.3});
    spec.top_m = 100.0;
    FitSettings fs;
    fs.tolerance_n = 1e-10;
    auto q = fit_air(spec, fs);
    ASSERT_TRUE(q.ok());
    const Atmosphere atm = Atmosphere::quadratic(*q);
    const double i = M_PI / 2 - (-0.2) * M_PI / 180.0;
    auto path = ExactPath::make(atm, 1.5, i);
    ASSERT_TRUE(path.ok());
    EXPECT_EQ(j["engine"], "general");
    EXPECT_EQ(j["ray_class"], path->class_name());
    EXPECT_EQ(j["beta"].get<double>(), path->beta());
    ASSERT_EQ(j["turning_points"].size(), 1u);
    EXPECT_EQ(j["turning_points"][0]["kind"], "lowest");
    EXPECT_EQ(j["turning_points"][0]["dz"].get<double>(), path->turning_point(0).dz);
    EXPECT_EQ(j["turning_points"][0]["y"].get<double>(), path->turning_point(0).y);
    EXPECT_EQ(j["profile"]["pieces"].get<int>(), (*q)->piece_count());
    EXPECT_EQ(j["samples"][0][1].get<double>(), 1.5);
}

TEST(PathCli, SoundingIsReadAndABadOneIsNamedWithItsPlace) {
    const std::string good = temp_path("sounding_good.csv");
    write_text(
        good,
        "height_m,temperature_c,pressure_hpa,relative_humidity\n0,24.5,1012.0,60\n0.5,21.0,"
        "1011.94,62\n1,19.8,1011.88,63\n2,18.9,1011.76,64\n4,18.4,1011.53,65\n7,18.6,1011.18,"
        "66\n12,19.6,1010.59,67\n20,20.1,1009.65,68\n");
    auto r = run_tool("path --sounding " + good +
                      " --index ciddor --eye-height 1.2 --elevation-deg -0.3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("profile     sounding " + good), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("8 rows of temperature, 0 to 20 m"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("index: Ciddor, 550 nm"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("class       "), std::string::npos);

    const std::string bad = temp_path("sounding_bad.csv");
    write_text(bad, "height_m,temperature_c\n0,24.5\n0.5,21.0\n0.5,20.0\n");
    r = run_tool("path --sounding " + bad + " --eye-height 1.2 --elevation-deg -0.3");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "mirage path: " + bad +
                         ":4:1: column 'height_m': height 0.5 m is not above the previous row's "
                         "0.5 m (line 3)\n");
    write_text(bad, "height_m,temperature_c\n0,24.5\n1500,21.0\n");
    r = run_tool("path --sounding " + bad +
                 " --sounding-max-gap 500 --eye-height 1.2 --elevation-deg -0.3");
    EXPECT_EQ(r.err, "mirage path: " + bad +
                         ":3:1: column 'height_m': gap of 1500 m from the previous row (line 2, 0 "
                         "m) exceeds the limit of 500 m\n");
}

// With an atmosphere on the command line every row of the batch is traced in it: its profile
// columns may be empty, the output has today's columns with nan where a value is not defined.
// (On flat ground the pressure's fall with height bends nearly level rays back down, so only a
// ray climbing at more than about 0.12 degrees escapes this 100 m profile.)
TEST(PathCli, BatchIsTracedInTheGivenAtmosphere) {
    const std::string rays = temp_path("rays_general.csv");
    write_text(rays,
               "case_id,profile,eta0,eta1,alpha,y0,i_rad,d1,d2,d3\n"
               "up,,,,,1.5,1.5664330,10,100,400\n"
               "turn,,,,,1.5,1.5742869852988852,100,450,900\n"
               "ground,,,,,1.5,1.62,5,20,1000\n");
    auto r =
        run_tool("path --air-temperature-c 27 --surface-layer 20,0.3 --top 100 --batch " + rays);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto got = parse_csv(r.out, "stdout");
    ASSERT_TRUE(got.ok()) << got.message();
    ASSERT_EQ(got->rows.size(), 3u);
    auto field = [&](int row, const char* c) { return got->rows[row].fields[got->column(c)]; };
    EXPECT_EQ(field(0, "k2"), "nan");
    EXPECT_EQ(field(0, "ray_class"), "escape");
    EXPECT_EQ(field(0, "turn_kind"), "behind");  // a rising ray's lowest point lies behind it
    EXPECT_LT(std::stod(field(0, "dz_turn")), 0.0);
    EXPECT_EQ(field(1, "turn_kind"), "ahead");
    EXPECT_EQ(field(2, "ray_class"), "ground");
    EXPECT_EQ(field(2, "hits_ground"), "1");
    EXPECT_EQ(field(2, "y_d3"), "nan");  // beyond the ground hit
    // The library's numbers, printed to 17 digits.
    AirSpec spec;
    spec.column.ground_temperature_k = 300.15;
    spec.column.layers.push_back({20.0, 0.3});
    spec.top_m = 100.0;
    auto q = fit_air(spec, {});
    ASSERT_TRUE(q.ok());
    auto path = ExactPath::make(Atmosphere::quadratic(*q), 1.5, 1.5742869852988852);
    ASSERT_TRUE(path.ok());
    EXPECT_EQ(std::stod(field(1, "y_d2")), path->height_at(450.0));
    EXPECT_EQ(std::stod(field(1, "dz_turn")), path->turning_point(0).dz);
}

TEST(PathCli, DuctsOfYoungsInversionAreFound) {
    auto r = run_tool(
        "path --air-temperature-c 15 --lapse-k-per-km 6.5 --inversion 50,60,2 --earth-radius "
        "6371000 --index ciddor --ducts");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("ducts       level rays trapped from 45.3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" m to 60 m"), std::string::npos) << r.out;
}

TEST(PathCli, TransferCurveShowsSeveralImagesAndIsDrawnAsSvgAndPng) {
    const std::string svg = temp_path("transfer.svg"), png = temp_path("transfer.png");
    std::remove(svg.c_str());
    std::remove(png.c_str());
    auto r = run_tool(
        "path --air-temperature-c 13 --lapse-k-per-km 6.5 --inversion 50,60,2,0.85 --earth-radius "
        "6371000 --index ciddor --eye-height 54 --transfer 40000 --transfer-from-deg -0.15 "
        "--transfer-to-deg 0.1 --transfer-count 801 --svg " +
        svg + " --png " + png);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto images = r.out.find("images      up to ");
    ASSERT_NE(images, std::string::npos) << r.out;
    EXPECT_GE(std::stoi(r.out.substr(images + 18)), 3) << r.out;  // a Fata Morgana's images
    std::ifstream s(svg), p(png, std::ios::binary);
    std::string svg_text((std::istreambuf_iterator<char>(s)), std::istreambuf_iterator<char>());
    std::string png_head(8, '\0');
    p.read(png_head.data(), 8);
    EXPECT_NE(svg_text.find("<svg"), std::string::npos);
    EXPECT_NE(svg_text.find("apparent elevation (arcmin)"), std::string::npos);
    EXPECT_EQ(png_head, "\x89PNG\r\n\x1a\n");
}

// The transfer diagram's outputs are written all or none, never over an input: an SVG named
// like the sounding it was drawn from is refused before gnuplot runs, and neither file appears.
TEST(PathCli, TransferDiagramNeverReplacesItsSounding) {
    const std::string snd = temp_path("transfer_sounding.csv"), png = temp_path("transfer_x.png");
    const std::string text = "height_m,temperature_c\n0,10\n20,12\n40,11.5\n100,11\n";
    write_text(snd, text);
    std::remove(png.c_str());
    auto r = run_tool("path --sounding " + snd +
                      " --eye-height 20 --transfer 5000 --transfer-count 51 --png " + png +
                      " --svg " + snd);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(snd), std::string::npos) << r.err;
    std::ifstream in(snd);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()),
              text);
    EXPECT_FALSE(std::ifstream(png).good());
}

// The general engine keeps the exponential path's limits on the eye, the tolerances and a
// batch's distances.
TEST(PathCli, RealAirRaysKeepTheLimitsOfTheExponentialPath) {
    auto r = run_tool("path --air-temperature-c 20 --eye-height 2e9 --elevation-deg 0");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --eye-height 2000000000: the eye must be above the ground (> 0 m) and "
              "at most 1e+09 m\n");
    r = run_tool("path --air-temperature-c 20 --eye-height 2 --elevation-deg 0 --tolerance 1e-12");
    EXPECT_EQ(r.err, "mirage path: --tolerance 1e-12: must be 0 or from 1e-10 to 1 rad\n");
    const std::string rays = temp_path("rays_general_bad.csv");
    write_text(rays, "case_id,y0,i_rad,d1,d2,d3\nA,1.5,1.57,10,-5,20\n");
    r = run_tool("path --air-temperature-c 20 --batch " + rays);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err,
              "mirage path: " + rays + ":2:15: d2 = -5: a distance must be finite and >= 0 (m)\n");
}

// The check through the tool: no gradient, a level ray from 10 m is 41.4 m above the
// sphere 20 km away.
TEST(PathCli, EarthCurvatureLiftsALevelRay) {
    auto r = run_tool(
        "path --gladstone-dale 1e-30 --isobaric --earth-radius 6371000 --eye-height 10 "
        "--elevation-deg 0 --max-distance 20000 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["end"], "cut");
    const auto last = j["samples"].back();
    EXPECT_DOUBLE_EQ(last[0].get<double>(), 20000.0);
    EXPECT_NEAR(last[1].get<double>(), 41.4, 0.05);
}

TEST(PathCli, BadRealAirFlagsAreNamed) {
    auto r = run_tool("path --inversion 50,60 --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "mirage path: --inversion 50,60: expected BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M]\n");
    r = run_tool("path --surface-layer 20,x --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.err,
              "mirage path: --surface-layer 20,x: 'x' is not a number (expected DT_K,SCALE_M)\n");
    r = run_tool("path --preset paper --inversion 50,60,2 --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(
        r.err,
        "mirage path: --preset/--profile give an exponential profile and --air-temperature-c, "
        "--lapse-k-per-km, --surface-layer, --inversion and --sounding another: give one\n");
    r = run_tool("path --preset paper --eye-height 1 --elevation-deg 0 --png x.png");
    EXPECT_EQ(r.err, "mirage path: --png draws the transfer diagram: give --transfer DIST\n");
    r = run_tool("path --index edlen --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.err,
              "mirage path: --index: unknown index formula 'edlen' (expected gladstone-dale or "
              "ciddor)\n");
    r = run_tool("path --inversion 50,2000,2 --top 1000 --eye-height 1 --elevation-deg 0");
    EXPECT_EQ(r.err, "mirage path: inversion top 2000 m must lie below the profile's top 1000 m\n");
}

TEST(PathCli, FanDiagramForAnyProfileShadesItsDucts) {
    const std::string svg = temp_path("fan_duct.svg");
    std::remove(svg.c_str());
    auto r = run_tool(
        "path --air-temperature-c 15 --lapse-k-per-km 6.5 --inversion 50,60,2 --earth-radius "
        "6371000 --index ciddor --eye-height 54 --elevation-deg -0.05 --fan-from-deg -0.1 "
        "--fan-to-deg 0.1 --fan-count 9 --max-distance 60000 --svg " +
        svg);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(svg);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t curves = 0;
    for (size_t p = 0; (p = text.find("<polyline", p)) != std::string::npos; ++p) ++curves;
    EXPECT_EQ(curves, 9u);
    EXPECT_NE(text.find("shaded: ducts (level rays trapped)"), std::string::npos);
    EXPECT_NE(text.find("height above the sphere (m)"), std::string::npos);
}

}  // namespace
}  // namespace mirage
