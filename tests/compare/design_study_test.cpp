#include "compare/design_study.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "test_temp.h"
#include "util/atomic_file.h"
#include "util/csv.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

TEST(DesignStudy, ComparesDesignsOnTheContinuumOfCameraRays) {
    const fs::path dir = mirage::testing::test_temp_path("mirage_design_study");
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene = (dir / "desert.pov").string();
    std::ofstream(scene) << R"(#version 3.7;
#declare Mirage_Preset = "paper";
#include "mirage.inc"
camera { location <0, 1.5, 0> look_at <0, 1.5, 10> right x * image_width / image_height angle 60 }
light_source { <-30, 60, -20>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <2.5, 1.6, 14>, 1 pigment { color rgb <0.8, 0.2, 0.1> } }
)";
    StudyOptions o;
    o.scene = scene;
    o.width = 48;
    o.height = 36;
    o.out_dir = (dir / "out").string();
    o.uniform_counts = {4, 64};
    o.graded_levels = {32};
    o.graded_steps = {0.0, 8.0};
    o.rays_per_row = 4;
    o.render = false;
    const auto before = std::chrono::steady_clock::now();
    auto r = run_design_study(o);
    const double study_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->rays, 4 * 36);
    EXPECT_LT(r->elevation_lo, 0.0);
    EXPECT_GT(r->elevation_hi, 0.0);
    // The sphere's near side, 14 m out less its radius, to the scene's edge.
    EXPECT_NEAR(r->zone_lo, std::hypot(1.5, 13.0), 1e-3);
    ASSERT_EQ(r->rows.size(), 2u + 2u + 2u);
    const StudyRow& few = r->rows[0];
    const StudyRow& many = r->rows[1];
    EXPECT_EQ(few.design, "uniform 4");
    EXPECT_EQ(few.boundaries, 4);
    // More equal layers: more crossings, a smaller error.
    EXPECT_GT(many.mean_crossings, few.mean_crossings);
    EXPECT_LT(many.p95_px, few.p95_px);
    double compile_seconds = 0.0;  // of the plane designs, together
    for (const auto& row : r->rows) {
        EXPECT_LE(row.p50_px, row.p95_px) << row.design;
        EXPECT_LE(row.p95_px, row.max_px) << row.design;
        EXPECT_TRUE(fs::exists(fs::path(r->out_dir) / row.curve)) << row.design;
        if (row.geometry == "planes") {
            EXPECT_GE(row.seen_p95_px, 0.0) << row.design;  // checked pixel by pixel
            // Compile's time is the one its own report gives (in the design's work folder,
            // named as its curve), a part of the study's.
            const fs::path report =
                fs::path(r->out_dir) / "work" / fs::path(row.curve).stem() / "report.json";
            auto text = read_file(report.string());
            ASSERT_TRUE(text.ok()) << text.message();
            const auto json = nlohmann::json::parse(*text);
            EXPECT_EQ(row.compile_seconds, json.at("seconds").get<double>()) << row.design;
            EXPECT_GT(row.compile_seconds, 0.0) << row.design;
            compile_seconds += row.compile_seconds;
        } else {
            EXPECT_EQ(row.seen_p95_px, -1.0) << row.design;  // 2D only
        }
    }
    EXPECT_LE(compile_seconds, study_seconds);
    auto csv = read_csv_file(r->csv_path);
    ASSERT_TRUE(csv.ok()) << csv.message();
    EXPECT_EQ(csv->rows.size(), r->rows.size());
    auto md = read_file(r->summary_path);
    ASSERT_TRUE(md.ok());
    EXPECT_NE(md->find("| uniform 64 | 64 |"), std::string::npos) << *md;
    // Nothing of the staging left behind.
    for (const auto& e : fs::directory_iterator(r->out_dir))
        EXPECT_NE(e.path().filename().string().rfind(".staging", 0), 0u) << e.path();

    // All or none: a directory where the summary goes fails the study, and none of its other
    // results is put in place.
    const fs::path out2 = dir / "out2";
    fs::create_directories(out2 / "summary.md");
    o.out_dir = out2.string();
    o.uniform_counts = {4};
    o.graded_levels = {};
    auto bad = run_design_study(o);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.message().find("summary.md"), std::string::npos) << bad.message();
    EXPECT_FALSE(fs::exists(out2 / "study.csv"));
    EXPECT_FALSE(fs::exists(out2 / "study.gp"));
    EXPECT_FALSE(fs::exists(out2 / "curves" / "uniform_4.csv"));
    for (const auto& e : fs::directory_iterator(out2))
        EXPECT_NE(e.path().filename().string().rfind(".staging", 0), 0u) << e.path();
}

// The study's results may not replace any file the scene was read from: the scene, and each
// file it includes (here one named as the summary is, in the output folder).
TEST(DesignStudy, RefusesToReplaceAFileTheSceneIncludes) {
    const fs::path dir = mirage::testing::test_temp_path("mirage_design_study_include");
    fs::remove_all(dir);
    fs::create_directories(dir / "out");
    const std::string included = (dir / "out" / "summary.md").string();
    const std::string content = "#declare Sphere_Colour = rgb <0.8, 0.2, 0.1>;\n";
    std::ofstream(included) << content;
    const std::string scene = (dir / "desert.pov").string();
    std::ofstream(scene) << R"(#version 3.7;
#declare Mirage_Preset = "paper";
#include "mirage.inc"
#include "out/summary.md"
camera { location <0, 1.5, 0> look_at <0, 1.5, 10> right x * image_width / image_height angle 60 }
light_source { <-30, 60, -20>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <2.5, 1.6, 14>, 1 pigment { color Sphere_Colour } }
)";
    StudyOptions o;
    o.scene = scene;
    o.width = 48;
    o.height = 36;
    o.out_dir = (dir / "out").string();
    o.uniform_counts = {4};
    o.graded_levels = {};
    o.rays_per_row = 2;
    o.render = false;
    auto r = run_design_study(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find("would overwrite"), std::string::npos) << r.message();
    EXPECT_NE(r.message().find("summary.md"), std::string::npos) << r.message();
    auto after = read_file(included);
    ASSERT_TRUE(after.ok());
    EXPECT_EQ(*after, content);
    // None of the other results is put in place either.
    EXPECT_FALSE(fs::exists(dir / "out" / "study.csv"));
    for (const auto& e : fs::directory_iterator(dir / "out"))
        EXPECT_NE(e.path().filename().string().rfind(".staging", 0), 0u) << e.path();
}

}  // namespace
}  // namespace mirage
