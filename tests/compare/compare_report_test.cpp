#include "compare/compare_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace mirage {
namespace {

CompareRow row(CompareModel model, double setting, double seconds, double rmse) {
    CompareRow r;
    r.model = model;
    r.setting = setting;
    r.seconds = seconds;
    r.render_seconds = 0.5 * seconds;
    r.process_cpu_seconds = 0.25 * seconds;
    r.rmse = rmse;
    r.psnr_db = -20.0 * std::log10(rmse);
    r.threads = 2;
    if (model != CompareModel::Polyline && model != CompareModel::Scanline) {
        r.layers = model == CompareModel::AdaptiveBands ? 40 : static_cast<int>(setting);
        r.compile_seconds = 0.1;
        r.max_error_px = 12.5;
        r.p95_error_px = 2.0;
        r.p95_shift_rows = 3.0;
        r.max_trace_level = 100;
    } else {
        r.max_error_px = setting;
        r.segments_per_ray = 3.5;
    }
    r.image = "renders/" + model_name(model) + "-" + setting_text(r) + ".png";
    return r;
}

CompareResult result() {
    CompareResult r;
    r.scene = "scenes/desert.pov";
    r.name = "desert";
    r.width = 320;
    r.height = 240;
    r.threshold = 0.05;
    r.reference_tolerance_px = 0.02;
    r.rows = {row(CompareModel::UniformBands, 8, 1.0, 0.08),
              row(CompareModel::UniformBands, 16, 2.0, 0.04),
              row(CompareModel::UniformBands, 64, 8.0, 0.02),
              row(CompareModel::AdaptiveBands, 4, 0.5, 0.04),
              row(CompareModel::AdaptiveBands, 1, 1.0, 0.01),
              row(CompareModel::Polyline, 4, 0.1, 0.03),
              row(CompareModel::Polyline, 0.5, 0.2, 0.005),
              row(CompareModel::Polyline, 0.1, 0.4, 0.006)};
    r.command = "mirage compare scenes/desert.pov";
    return r;
}

TEST(ResultsCsv, OneRowPerSettingWithEmptyFieldsWhereAColumnDoesNotApply) {
    const std::string csv = results_csv(result());
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "model,setting,layers,seconds,render_seconds,cpu_seconds,threads,compile_seconds,"
              "rmse,psnr,share_over,max_error_px,p95_error_px,p95_shift_rows,max_trace_level,"
              "segments_per_ray,image,process_cpu_seconds");
    EXPECT_NE(csv.find("\nuniform-bands,16,16,2,1,0,2,0.1,0.04,27.959,0,12.5,2,3,100,,"
                       "renders/uniform-bands-16.png,0.5\n"),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find("\npolyline,0.5,,0.2,0.1,0,2,,0.005,46.021,0,0.5,,,,3.5,"
                       "renders/polyline-0.5.png,0.05\n"),
              std::string::npos)
        << csv;
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
}

TEST(Headlines, AdaptiveAgainstUniformAtTheLowestCommonError) {
    const Headlines h = compute_headlines(result().rows);
    ASSERT_TRUE(h.adaptive_vs_uniform);
    // Uniform reaches 0.02 at best (8 s); adaptive gets there between 4 px and 1 px.
    EXPECT_DOUBLE_EQ(h.adaptive_vs_uniform->error, 0.02);
    EXPECT_DOUBLE_EQ(h.adaptive_vs_uniform->a.seconds, 8.0);
    EXPECT_NEAR(h.adaptive_vs_uniform->b.seconds, 0.5 * std::sqrt(2.0), 1e-12);
    ASSERT_TRUE(h.tracer_vs_adaptive);
    EXPECT_DOUBLE_EQ(h.tracer_vs_adaptive->error, 0.01);
    // On render time every figure halves here, and the ratios stay.
    const Headlines hr = compute_headlines(result().rows, TimeBasis::Render);
    ASSERT_TRUE(hr.adaptive_vs_uniform);
    EXPECT_NEAR(hr.adaptive_vs_uniform->speedup(), h.adaptive_vs_uniform->speedup(), 1e-12);
    // On processor time (a quarter of the wall clock here) the same.
    const Headlines hp = compute_headlines(result().rows, TimeBasis::Processor);
    ASSERT_TRUE(hp.adaptive_vs_uniform);
    EXPECT_DOUBLE_EQ(hp.adaptive_vs_uniform->a.seconds, 2.0);
    EXPECT_NEAR(hp.adaptive_vs_uniform->speedup(), h.adaptive_vs_uniform->speedup(), 1e-12);
}

TEST(ErrorRises, NamesTheSettingWhereAFinerOneGotWorse) {
    const auto rises = error_rises(result().rows);
    ASSERT_EQ(rises.size(), 1u);
    EXPECT_EQ(rises[0], "polyline: RMSE 0.006 at 0.1 px against 0.005 at 0.5 px");
}

TEST(GnuplotScript, OneCurvePerModelLabelledBySetting) {
    const std::string gp = gnuplot_script(result());
    for (const char* s : {"$uniform_bands << EOD", "$adaptive_bands << EOD", "$polyline << EOD",
                          "title \"uniform-bands", "title \"adaptive-bands", "title \"polyline",
                          "with labels", "set logscale xy", "set output png_out",
                          "set output svg_out", "pngcairo", "\n1 0.08 \"8\"\n"})
        EXPECT_NE(gp.find(s), std::string::npos) << s;
    EXPECT_EQ(gp.find("scanline"), std::string::npos);
}

TEST(Summary, LeadsWithTheTableAndTheFiguresAtEqualError) {
    const std::string md = summary_markdown(result());
    EXPECT_NE(md.find("| uniform-bands | 64 layers | 64 | 8 | 0.02 | 34 | 0 % | 12.5 | 2 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("**Adaptive against uniform layers:** at RMSE 0.02, uniform layers take "
                      "8 s (at 64 layers) and adaptive layers 0.707 s (interpolated between "
                      "4 px and 1 px): adaptive layers are 11.3 times faster."),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("On processor time (the whole process, parse included, without the wall "
                      "clock's idle waits), at RMSE 0.02: 2 s (at 64 layers) against 0.177 s "
                      "(interpolated between 4 px and 1 px), adaptive layers 11.3 times faster."),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("polyline: RMSE 0.006 at 0.1 px against 0.005 at 0.5 px"), std::string::npos);
    EXPECT_NE(md.find("```\nmirage compare scenes/desert.pov\n```"), std::string::npos);
}

// Real air's index steps: a counted setting ("64 steps", finer with more), a band model in the
// CSV, its own curve, and its figures at equal error in the summary.
CompareResult real_air_result() {
    CompareResult r = result();
    r.scene = "scenes/hot_road.pov";
    r.name = "hot_road";
    r.rows = {row(CompareModel::UniformBands, 8, 1.0, 0.16),
              row(CompareModel::UniformBands, 64, 1.2, 0.07),
              row(CompareModel::IndexStepBands, 8, 1.0, 0.08),
              row(CompareModel::IndexStepBands, 16, 1.05, 0.09),
              row(CompareModel::IndexStepBands, 64, 1.1, 0.04),
              row(CompareModel::Polyline, 1, 0.01, 0.02)};
    r.command = "mirage compare scenes/hot_road.pov";
    return r;
}

TEST(IndexSteps, ACountedBandModelWithItsOwnCurveAndFiguresAtEqualError) {
    const CompareResult r = real_air_result();
    EXPECT_EQ(setting_label(r.rows[4]), "64 steps");
    const std::string csv = results_csv(r);
    EXPECT_NE(csv.find("\nindex-step-bands,64,64,1.1,0.55,0,2,0.1,0.04,27.959,0,12.5,2,3,100,,"
                       "renders/index-step-bands-64.png,0.275\n"),
              std::string::npos)
        << csv;
    // 16 steps worse than 8: a finer setting that got worse, in the count's order.
    const auto rises = error_rises(r.rows);
    ASSERT_EQ(rises.size(), 1u);
    EXPECT_EQ(rises[0], "index-step-bands: RMSE 0.09 at 16 steps against 0.08 at 8 steps");
    const Headlines h = compute_headlines(r.rows);
    ASSERT_TRUE(h.steps_vs_uniform);
    // Uniform layers reach 0.07 at best (1.2 s); index steps between 16 and 64 steps.
    EXPECT_DOUBLE_EQ(h.steps_vs_uniform->error, 0.07);
    EXPECT_DOUBLE_EQ(h.steps_vs_uniform->a.seconds, 1.2);
    EXPECT_GT(h.steps_vs_uniform->b.seconds, 1.0);
    EXPECT_LT(h.steps_vs_uniform->b.seconds, 1.1);
    ASSERT_TRUE(h.tracer_vs_steps);
    EXPECT_DOUBLE_EQ(h.tracer_vs_steps->error, 0.04);
    const std::string gp = gnuplot_script(r);
    EXPECT_NE(gp.find("$index_step_bands << EOD"), std::string::npos) << gp;
    EXPECT_NE(gp.find("title \"index-step-bands"), std::string::npos) << gp;
    const std::string md = summary_markdown(r);
    EXPECT_NE(md.find("| index-step-bands | 64 steps | 64 | 1.1 | 0.04 |"), std::string::npos)
        << md;
    EXPECT_NE(md.find("**Index steps against uniform layers:** at RMSE 0.07, uniform layers take "
                      "1.2 s (at 64 layers) and equal index steps "),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("**The tracer against POV-Ray with index steps:** at RMSE 0.04"),
              std::string::npos)
        << md;
}

}  // namespace
}  // namespace mirage
