// mirage compile for cameras whose rays start at different points (orthographic, cylinder 3
// and 4): the layers at equal steps of the index over the heights the rays reach, rendered by
// POV-Ray in the gap layout, against `mirage trace` along each pixel's own exact ray.  As in
// SceneImageDiff: every pixel must find its colour in the other image within the rows the
// compile report's check says its band ray is off (plus the tracer's tolerance and one row of
// point sampling).  What that cannot explain is a defect of the layers, of POV-Ray's handling
// of rays that start inside them, or of the check.
//
// Images are kept under build/test_output/many_origins_band/<case>/.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../trace/povray_runner.h"
#include "compile/compile.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "trace_png.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::povray_available;
using testing::test_dir;
using testing::trace_png;

constexpr int kW = 96, kH = 72;
constexpr double kTraceTolerancePx = 0.1;
constexpr double kSameColour = 0.1;

std::string scene_text(const std::string& camera) {
    return "#version 3.7;\n"
           "#declare Mirage_Preset = \"paper\";\n"
           "#declare Mirage_Tolerance = 0.5;\n"
           "#include \"mirage.inc\"\n"
           "global_settings { assumed_gamma 1.0 }\n" +
           camera +
           "\n"
           "sky_sphere { pigment { gradient y color_map { [0 color rgb <0.8, 0.9, 1>]\n"
           "                                             [1 color rgb <0.1, 0.2, 0.8>] } } }\n"
           "box { <-100, 0, 30>, <100, 8, 31>\n"
           "    pigment { gradient y color_map { [0 color rgb <1, 0, 0>] [0.5 color rgb <1, 0, "
           "0>]\n"
           "                                     [0.5 color rgb <0, 1, 0>] [1 color rgb <0, 1, "
           "0>] } }\n"
           "    finish { ambient 1 diffuse 0 } }\n"
           "sphere { <1, 1, 12>, 0.7 pigment { color rgb <1, 1, 0> } finish { ambient 1 diffuse 0 "
           "} }\n"
           "plane { y, 0 pigment { checker color rgb 1, color rgb 0.2 scale 2 }\n"
           "    finish { ambient 1 diffuse 0 } }\n";
}

std::string shell_quoted(const fs::path& p) { return "'" + p.string() + "'"; }

struct Case {
    const char* name;
    const char* camera;
    // Rays that start above the gradient: the report's shifts explain every pixel but the
    // odd edge.  Rays that start inside it (and turn within a few layers of their origin):
    // POV-Ray's render was measured 2.4 % (cylinder 4) and 5.6 % (below the ground) off
    // beyond those shifts, on the edges of the sphere, which the check does not yet explain;
    // the layers must still explain far more than straight rays do.
    bool above_gradient;
};

class ManyOriginsBands : public ::testing::TestWithParam<Case> {};

TEST_P(ManyOriginsBands, PovRaysRenderMatchesTheTracerWithinTheReportedError) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Case& c = GetParam();
    const fs::path dir = test_dir("many_origins_band", c.name);
    const fs::path scene = dir / "scene.pov";
    std::ofstream(scene) << scene_text(c.camera);

    CompileOptions o;
    o.scene = scene.string();
    o.width = kW;
    o.height = kH;
    o.out_dir = (dir / "bands").string();
    o.image = (dir / "bands.png").string();
    o.progress = false;
    auto report = compile_scene(o);
    ASSERT_TRUE(report.ok()) << report.message();
    EXPECT_EQ(report->layout, "gaps");
    EXPECT_GT(report->layers, 4);
    EXPECT_LE(report->max_trace_level, 255);
    const std::string command = "cd " + shell_quoted(dir) + " && povray " +
                                shell_quoted(fs::path(report->ini_path)) + " > " +
                                shell_quoted(dir / "bands.log") + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << "see " << dir;
    auto pov = read_image(o.image);
    ASSERT_TRUE(pov.ok()) << pov.message();
    auto exact = trace_png(scene.string(), dir / "trace.png", kW, kH, kTraceTolerancePx);
    ASSERT_TRUE(exact.ok()) << exact.message();
    auto straight =
        trace_png(scene.string(), dir / "straight.png", kW, kH, kTraceTolerancePx, false);
    ASSERT_TRUE(straight.ok()) << straight.message();

    std::vector<int> radius(report->pixel_shift_rows.size());
    for (size_t i = 0; i < radius.size(); ++i) {
        const double e = report->pixel_shift_rows[i] + report->pixel_reflection_error_px[i];
        radius[i] = std::isfinite(e) ? static_cast<int>(std::ceil(e + kTraceTolerancePx)) + 1 : kH;
    }
    auto plain = compare_images(*pov, *exact, kSameColour);
    auto shift = compare_within_rows(*pov, *exact, radius, kSameColour);
    auto none = compare_within_rows(*straight, *exact, radius, kSameColour);
    ASSERT_TRUE(plain.ok() && shift.ok() && none.ok());
    (void)write_png(shift->mask, (dir / "unexplained.png").string());
    std::printf(
        "%s: %d layers, seen p95 %.3g max %.3g px, shift p95 %.3g max %.3g rows; %.2f %% of "
        "pixels differ from the tracer's (PSNR %.2f dB), %.3f %% unexplained by the report "
        "(straight rays: %.1f %%)\n",
        c.name, report->layers, report->p95_seen_error_px, report->max_seen_error_px,
        report->p95_shift_rows, report->max_shift_rows,
        100.0 * static_cast<double>(plain->pixels_over) / (kW * kH), plain->psnr_db,
        100.0 * shift->share(), 100.0 * none->share());
    if (c.above_gradient) {
        EXPECT_LE(shift->share(), 0.01) << "images and masks in " << dir;
    } else {
        EXPECT_LE(shift->share(), 0.15 * none->share()) << "images and masks in " << dir;
    }
    // The scene's mirage is no small part of the picture: without the layers most of what
    // the report's shifts allow is not enough.
    EXPECT_GT(none->share(), 0.05) << "images in " << dir;
}

INSTANTIATE_TEST_SUITE_P(
    Cameras, ManyOriginsBands,
    ::testing::Values(
        // From 3 to 9 units up, 31 degrees down onto the desert: the rays start above the
        // gradient and cross the layers once before they meet the ground or the objects.
        Case{"orthographic_from_above",
             "camera { orthographic location <0, 6, -6> up <0, 6, 0> right <8, 0, 0> "
             "look_at <0, 0, 14> }",
             true},
        // From heights -0.4 to 1.6, tilted up: the lowest rows start below the ground (and
        // meet the ground plane from below, in POV-Ray inside the bottom layer), the others
        // inside the gradient.
        Case{"orthographic_below_ground",
             "camera { orthographic location <0, 0.6, 0> up <0, 2, 0> right <2.667, 0, 0> "
             "look_at <0, 1.0, 10> }",
             false},
        // Rays fanned through 40 degrees of elevation from a level line at 1.5 units.
        Case{"cylinder4",
             "camera { cylinder 4 location <0, 1.5, 0> right x * 3 look_at <0, 1.5, 10> "
             "angle 40 }",
             false}),
    [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace mirage
