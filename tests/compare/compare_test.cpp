#include "compare/compare.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <map>

#include "../trace/povray_runner.h"
#include "image/image_io.h"
#include "util/atomic_file.h"
#include "util/csv.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

const std::string kDesert = std::string(MIRAGE_SOURCE_DIR) + "/scenes/desert.pov";

/// A small sweep of the desert: two uniform counts and one over the budget, one adaptive
/// tolerance, two tracer tolerances.
CompareOptions small_sweep(const fs::path& dir) {
    CompareOptions o;
    o.scene = kDesert;
    o.width = 48;
    o.height = 36;
    o.out_dir = dir.string();
    o.reference_tolerance_px = 0.1;
    o.counts = {64, 8, 256};  // run from coarse to fine; 256 exceeds POV-Ray's budget
    o.tolerances = {1};
    o.trace_tolerances = {0.5, 4};
    o.steps = {16};  // real air's design: not run for the desert's exponential profile
    o.corrected_counts = {12};
    return o;
}

TEST(Compare, SweepsTheDesertAndWritesEveryOutput) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = testing::test_dir("compare", "sweep");
    std::vector<std::string> progress;
    CompareOptions o = small_sweep(dir);
    o.progress = [&progress](const std::string& line) { progress.push_back(line); };
    auto r = run_comparison(o);
    ASSERT_TRUE(r.ok()) << r.message();

    // One row per setting that was rendered, coarse to fine within each model.
    ASSERT_EQ(r->rows.size(), 6u);
    const std::pair<CompareModel, double> expected[] = {{CompareModel::UniformBands, 8},
                                                        {CompareModel::UniformBands, 64},
                                                        {CompareModel::AdaptiveBands, 1},
                                                        {CompareModel::CorrectedBands, 12},
                                                        {CompareModel::Polyline, 4},
                                                        {CompareModel::Polyline, 0.5}};
    for (size_t i = 0; i < r->rows.size(); ++i) {
        EXPECT_EQ(r->rows[i].model, expected[i].first) << i;
        EXPECT_EQ(r->rows[i].setting, expected[i].second) << i;
        EXPECT_GT(r->rows[i].seconds, 0.0) << i;
        EXPECT_TRUE(fs::exists(dir / r->rows[i].image)) << r->rows[i].image;
    }
    EXPECT_EQ(r->rows[0].layers, 8);
    EXPECT_EQ(r->rows[1].layers, 64);
    EXPECT_LE(r->rows[1].max_trace_level, kPovrayMaxTraceLevel);
    // The count over the budget stopped the uniform sweep, and the summary says so.
    ASSERT_FALSE(r->notes.empty());
    EXPECT_NE(r->notes[0].find("uniform-bands: stopped at 256 layers"), std::string::npos)
        << r->notes[0];
    EXPECT_FALSE(fs::exists(dir / "renders" / "uniform-bands-256.png"));
    ASSERT_GE(r->notes.size(), 2u);
    EXPECT_NE(r->notes[1].find("index-step-bands: not run: index steps are the design for real "
                               "air, and this scene's atmosphere is paper"),
              std::string::npos)
        << r->notes[1];

    // More layers, or a finer tracer tolerance, does not make the picture worse.  Eight equal
    // layers slice the spheres' mirage (RMSE 0.084 here); 64 halve the error.
    EXPECT_LT(r->rows[1].rmse, 0.75 * r->rows[0].rmse);
    EXPECT_LT(r->rows[5].rmse, 0.75 * r->rows[4].rmse);
    // The corrected camera through 12 layers comes closer than 64 equal layers.
    EXPECT_LT(r->rows[3].rmse, r->rows[1].rmse);
    // The polyline's max error is its tolerance; the bands' is the compile report's.
    EXPECT_EQ(r->rows[4].max_error_px, 4.0);
    EXPECT_GT(r->rows[0].max_error_px, r->rows[0].p95_error_px);
    // With straight rays POV-Ray and the tracer draw the same picture, near enough.
    ASSERT_TRUE(r->straight_rmse);
    EXPECT_LT(*r->straight_rmse, 0.01);

    // results.csv: the required columns, one row per setting, as the rows say.
    auto csv = read_csv_file(r->csv_path);
    ASSERT_TRUE(csv.ok()) << csv.message();
    for (const char* column : {"model", "setting", "seconds", "rmse", "psnr", "max_error_px",
                               "share_over", "p95_error_px", "layers", "image"})
        EXPECT_GE(csv->column(column), 0) << column;
    ASSERT_EQ(csv->rows.size(), 6u);
    const int model = csv->column("model"), setting = csv->column("setting");
    EXPECT_EQ(csv->rows[0].fields[model], "uniform-bands");
    EXPECT_EQ(csv->rows[0].fields[setting], "8");
    EXPECT_EQ(csv->rows[2].fields[model], "adaptive-bands");
    EXPECT_EQ(csv->rows[2].fields[setting], "1");
    EXPECT_EQ(csv->rows[3].fields[model], "corrected-bands");
    EXPECT_EQ(csv->rows[3].fields[setting], "12");
    EXPECT_EQ(csv->rows[5].fields[model], "polyline");
    EXPECT_EQ(csv->rows[5].fields[setting], "0.5");
    EXPECT_EQ(csv->rows[4].fields[csv->column("layers")], "");
    auto rmse = csv_number(*csv, csv->rows[1], csv->column("rmse"));
    ASSERT_TRUE(rmse.ok());
    // Written to 6 significant digits: within half a unit of the sixth.
    EXPECT_NEAR(*rmse, r->rows[1].rmse, 5e-6 * r->rows[1].rmse);

    // The plot, its script naming the three models, the sheet, the summary, the reference.
    for (const auto& p : {r->plot_script, r->plot_png, r->plot_svg, r->sheet_path, r->summary_path,
                          r->reference_path})
        EXPECT_TRUE(fs::exists(p) && fs::file_size(p) > 0) << p;
    EXPECT_TRUE(r->plotted);
    auto script = read_file(r->plot_script);
    ASSERT_TRUE(script.ok());
    for (const char* name : {"uniform-bands", "adaptive-bands", "polyline", "set logscale xy"})
        EXPECT_NE(script->find(name), std::string::npos) << name;
    auto summary = read_file(r->summary_path);
    ASSERT_TRUE(summary.ok());
    EXPECT_NE(summary->find("**Adaptive against uniform layers:** at RMSE "), std::string::npos);
    EXPECT_NE(summary->find("uniform-bands: stopped at 256 layers"), std::string::npos);
    EXPECT_NE(summary->find(r->command), std::string::npos);
    auto sheet = read_image(r->sheet_path);
    ASSERT_TRUE(sheet.ok()) << sheet.message();
    EXPECT_GT(sheet->width, 4 * 48);
    auto reference = read_image(r->reference_path);
    ASSERT_TRUE(reference.ok());
    EXPECT_EQ(reference->width, 48);

    // Every file went through a temporary name: none is left.
    for (const auto& e : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
    // One progress line per setting, for the reference and the straight rays, and per note.
    EXPECT_EQ(progress.size(), 1u + 1u + 6u + 2u) << ::testing::PrintToString(progress);
    EXPECT_EQ(progress[2].rfind("uniform 8 layers: POV-Ray ", 0), 0u) << progress[2];
    EXPECT_EQ(progress[5].rfind("index-step-bands: not run", 0), 0u) << progress[5];
    EXPECT_EQ(progress[6].rfind("adaptive 1 px: ", 0), 0u) << progress[6];
    EXPECT_EQ(std::count_if(progress.begin(), progress.end(),
                            [](const std::string& l) {
                                return l.rfind("corrected 12 layers: POV-Ray ", 0) == 0;
                            }),
              1)
        << ::testing::PrintToString(progress);
}

// Real air's own design in the sweep: equal index steps rendered by POV-Ray beside the uniform
// layers and the tracer.  The hot road's mirage needs the fine steps near the hot asphalt:
// eight index steps beat eight equal layers, and 64 steps beat eight.
TEST(Compare, RealAirSweepsItsIndexSteps) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = testing::test_dir("compare", "real_air");
    const fs::path scenes = fs::path(MIRAGE_SOURCE_DIR) / "scenes";
    CompareOptions o;
    o.scene = (scenes / "hot_road.pov").string();
    o.width = 64;
    o.height = 48;
    o.out_dir = dir.string();
    o.reference_tolerance_px = 0.1;
    o.counts = {8};
    o.steps = {64, 8};
    o.tolerances = {1, 0.5};
    o.corrected_counts = {};
    o.trace_tolerances = {1};
    auto r = run_comparison(o);
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_EQ(r->rows.size(), 4u);
    // The fit to the camera's rays is not for real air: one note for both tolerances.
    int adaptive_notes = 0;
    for (const auto& n : r->notes) adaptive_notes += n.rfind("adaptive-bands: not run", 0) == 0;
    EXPECT_EQ(adaptive_notes, 1) << ::testing::PrintToString(r->notes);
    const CompareRow& uniform8 = r->rows[0];
    const CompareRow& steps8 = r->rows[1];
    const CompareRow& steps64 = r->rows[2];
    EXPECT_EQ(uniform8.model, CompareModel::UniformBands);
    EXPECT_EQ(steps8.model, CompareModel::IndexStepBands);
    EXPECT_EQ(steps8.setting, 8);
    EXPECT_EQ(steps64.model, CompareModel::IndexStepBands);
    EXPECT_EQ(steps64.setting, 64);
    EXPECT_EQ(r->rows[3].model, CompareModel::Polyline);
    std::printf("hot road 64x48: uniform 8 RMSE %.4f, index steps 8 / 64: %.4f / %.4f (%d / %d "
                "layers), tracer 1 px %.4f\n",
                uniform8.rmse, steps8.rmse, steps64.rmse, steps8.layers, steps64.layers,
                r->rows[3].rmse);
    EXPECT_GT(steps8.layers, 1);
    EXPECT_GT(steps64.layers, 4 * steps8.layers);
    EXPECT_LE(steps64.max_trace_level, kPovrayMaxTraceLevel);
    EXPECT_LT(steps8.rmse, 0.75 * uniform8.rmse);
    EXPECT_LT(steps64.rmse, 0.9 * steps8.rmse);
    EXPECT_TRUE(fs::exists(dir / "renders" / "index-step-bands-64.png"));
    auto csv = read_csv_file(r->csv_path);
    ASSERT_TRUE(csv.ok()) << csv.message();
    EXPECT_EQ(csv->rows[2].fields[csv->column("model")], "index-step-bands");
    auto summary = read_file(r->summary_path);
    ASSERT_TRUE(summary.ok());
    EXPECT_NE(summary->find("**Index steps against uniform layers:**"), std::string::npos);
    EXPECT_NE(summary->find("--steps 64,8"), std::string::npos);
}

TEST(Compare, TheReferenceMustBeFinerThanEverySetting) {
    CompareOptions o;
    o.scene = kDesert;
    o.reference_tolerance_px = 0.25;
    auto s = validate_compare_options(o);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message(),
              "--reference-tolerance 0.25 px is not finer than 0.25 px in --tolerances: the "
              "reference must be finer than every setting it judges");
    o.reference_tolerance_px = 0.05;
    o.trace_tolerances = {1, 0.01};
    s = validate_compare_options(o);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message(),
              "--reference-tolerance 0.05 px is not finer than 0.01 px in --trace-tolerances: "
              "the reference must be finer than every setting it judges");
    o.trace_tolerances = {1, 0.06};
    EXPECT_TRUE(validate_compare_options(o).ok());
}

TEST(Compare, BadValuesNameTheOptionAndTheValue) {
    auto message = [](auto change) {
        CompareOptions o;
        o.scene = kDesert;
        change(o);
        auto s = validate_compare_options(o);
        return s.ok() ? std::string("ok") : s.message();
    };
    EXPECT_EQ(message([](CompareOptions& o) {
                  o.counts = {8, 0};
              }),
              "--counts 0: the layer count must be a whole number from 1 to 4096");
    EXPECT_EQ(message([](CompareOptions& o) {
                  o.tolerances = {1, -0.5};
              }),
              "--tolerances -0.5: the tolerance must be from 0.001 to 1000 pixels");
    EXPECT_EQ(message([](CompareOptions& o) { o.reference_tolerance_px = 0; }),
              "--reference-tolerance 0: the tolerance must be from 0.001 to 1000 pixels");
    EXPECT_EQ(message([](CompareOptions& o) { o.threshold = 1.5; }),
              "--threshold 1.5: must be between 0 and 1 (a difference of 8-bit codes / 255)");
    EXPECT_EQ(message([](CompareOptions& o) { o.width = 0; }),
              "image size 0x240 must be 1 to 20000 pixels each way");
    EXPECT_EQ(message([](CompareOptions& o) { o.threads = -1; }),
              "--threads -1: must be 0 (all cores) or more");
}

TEST(Compare, RefusesWithoutPovrayBeforeWritingAnything) {
    const fs::path dir = testing::test_dir("compare", "no_povray");
    CompareOptions o = small_sweep(dir / "out");
    o.povray = "mirage-no-such-povray";
    auto r = run_comparison(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(),
              "mirage-no-such-povray: not found on PATH; the band models are rendered by "
              "POV-Ray 3.7 (Debian: apt-get install povray)");
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Compare, RefusesASceneWithoutAtmosphere) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = testing::test_dir("compare", "no_atmosphere");
    const fs::path scene = dir / "plain.pov";
    std::ofstream(scene) << "#version 3.7;\ncamera { location <0, 1, -3> look_at 0 }\n"
                            "sphere { 0, 1 pigment { rgb 1 } }\n";
    CompareOptions o = small_sweep(dir / "out");
    o.scene = scene.string();
    auto r = run_comparison(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), scene.string() +
                               ": the scene declares no atmosphere (none declared): there is "
                               "nothing to compare; declare one as mirage.inc describes");
    EXPECT_FALSE(fs::exists(dir / "out" / "reference.png"));
}

}  // namespace
}  // namespace mirage
