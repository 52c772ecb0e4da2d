// Image-diff test of colour through POV-Ray: `mirage compile` in colour writes one design per
// wavelength, POV-Ray renders each, and the channels are combined (compare/colour_render.h);
// `mirage trace` in colour traces each channel through the air at its wavelength.  The two
// images must agree as the monochrome ones do (scene_image_diff_test.cpp's colour threshold).
//
// The scene is the hot road (scenes/hot_road.pov) through a lens of 1 degree, on flat ground
// through Ciddor's index, its air exaggerated 16 times (not air) and its channels at 1600, 550
// and 350 nm, the ends of Ciddor's range, so that at 160x120 the colours part by pixels at
// the mirage's edges (at 610/550/465 nm and the true air they part by a fraction of a pixel
// there).  The check can fail: against the tracer's image with the red and blue wavelengths
// swapped, the same POV-Ray image differs by more than kSameColour in 351 pixels (1.8 %,
// measured), against 52 (0.27 %) for the right one.
//
// Images are kept under build/test_output/colour_image_diff/.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../trace/povray_runner.h"
#include "compare/colour_render.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "trace_scene/trace_scene.h"
#include "util/format.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::povray_available;
using testing::test_dir;

constexpr int kW = 160, kH = 120;
constexpr double kSameColour = 0.1;  // as scene_image_diff_test.cpp
// Pixels POV-Ray's bands and the exact paths may show differently: an edge between two
// pixel centres.  Measured: 0.27 %.
constexpr double kDifferingShare = 0.01;

/// scenes/hot_road.pov in `dir` with its sounding, on flat ground, in exaggerated colour.
std::string colour_road_in(const fs::path& dir) {
    fs::create_directories(dir);
    const fs::path scenes = fs::path(MIRAGE_SOURCE_DIR) / "scenes";
    fs::copy_file(scenes / "hot_road.csv", dir / "hot_road.csv",
                  fs::copy_options::overwrite_existing);
    std::ifstream in(scenes / "hot_road.pov");
    std::ofstream out(dir / "colour_road.pov");
    for (std::string line; std::getline(in, line);) {
        // A lens twice as long: a pixel of 23", the colours apart by more of them.
        if (line.rfind("    angle", 0) == 0) line = "    angle 1";
        out << line << "\n";
        if (line.rfind("#declare Mirage_Sounding", 0) == 0)
            out << "#declare Mirage_Earth_Radius = 0;\n"
                   "#declare Mirage_Index = \"ciddor\";\n"
                   "#declare Mirage_Wavelengths = <1600, 550, 350>;\n"
                   "#declare Mirage_Exaggeration = 16;\n";
    }
    return (dir / "colour_road.pov").string();
}

Result<Image> trace_colour(const std::string& scene, const fs::path& png, std::vector<double> nm) {
    TraceOptions o;
    o.scene = scene;
    o.output = png.string();
    o.width = kW;
    o.height = kH;
    o.tolerance_px = 0.1;
    o.progress = false;
    o.wavelengths_nm = std::move(nm);
    auto r = trace_scene(o);
    if (!r) return r.error();
    return quantize_srgb8(r->render.image);
}

TEST(ColourImageDiff, PovRaysChannelsMatchTheColourTracer) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = test_dir("colour_image_diff", "road");
    const std::string scene = colour_road_in(dir);
    CompileOptions o;
    o.scene = scene;
    o.width = kW;
    o.height = kH;
    o.out_dir = (dir / "compiled").string();
    o.samples_per_side = 1;
    o.progress = false;
    auto nm = compile_colour_wavelengths(o, {}, "--wavelengths");
    ASSERT_TRUE(nm.ok()) << nm.message();
    ASSERT_TRUE(nm->has_value());  // the scene's Mirage_Wavelengths
    auto compiled = compile_colour(o, **nm, true);
    ASSERT_TRUE(compiled.ok()) << compiled.message();
    ASSERT_EQ(compiled->channels.size(), 3u);
    for (const ColourChannel& ch : compiled->channels) {
        EXPECT_TRUE(fs::exists(ch.report.ini_path)) << ch.report.ini_path;
        EXPECT_NE(ch.report.ini_path.find("colour_road-" + shortest(ch.wavelength_nm) + "nm"),
                  std::string::npos);
    }
    EXPECT_EQ(compiled->image, (dir / "compiled" / "colour_road.png").string());
    auto pov = read_image(compiled->image);
    ASSERT_TRUE(pov.ok()) << pov.message();

    auto traced = trace_colour(scene, dir / "trace.png", {});
    ASSERT_TRUE(traced.ok()) << traced.message();
    auto same = compare_images(*pov, *traced, kSameColour);
    ASSERT_TRUE(same.ok()) << same.message();
    // The red and blue channels' wavelengths swapped: the colours part the other way.
    auto swapped = trace_colour(scene, dir / "trace_swapped.png", {350.0, 550.0, 1600.0});
    ASSERT_TRUE(swapped.ok()) << swapped.message();
    auto wrong = compare_images(*pov, *swapped, kSameColour);
    ASSERT_TRUE(wrong.ok()) << wrong.message();
    std::printf(
        "colour road: POV-Ray against the tracer: %lld px over %.2f (PSNR %.2f dB); "
        "against the swapped channels: %lld px (PSNR %.2f dB)\n",
        static_cast<long long>(same->pixels_over), kSameColour, same->psnr_db,
        static_cast<long long>(wrong->pixels_over), wrong->psnr_db);
    EXPECT_LE(same->pixels_over, kDifferingShare * kW * kH) << "images in " << dir;
    EXPECT_GE(wrong->pixels_over, 4 * std::max<std::int64_t>(same->pixels_over, 1))
        << "images in " << dir;
}

TEST(ColourImageDiff, EachChannelIsItsWavelengthsRender) {
    // combine_channels takes red from the first image, green from the second, blue from the
    // third.
    Image a(2, 1), b(2, 1), c(2, 1);
    a.set(0, 0, {0.1f, 0.2f, 0.3f});
    b.set(0, 0, {0.4f, 0.5f, 0.6f});
    c.set(0, 0, {0.7f, 0.8f, 0.9f});
    auto m = combine_channels(a, b, c);
    ASSERT_TRUE(m.ok()) << m.message();
    EXPECT_EQ(m->at(0, 0), glm::vec3(0.1f, 0.5f, 0.9f));
    Image small(1, 1);
    auto bad = combine_channels(a, b, small);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.message(), "the channels' images differ in size: 2x1, 2x1, 1x1");
}

}  // namespace
}  // namespace mirage
