// Parity with POV-Ray 3.7: the same scene rendered by the tracer and by `povray -D -A`
// must agree to PSNR >= 40 dB on the 8-bit images.  The tracer renders the scene file as
// parsed (and, as a check of how it reads the Scene, the C++ scene the file came from).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "parity_scenes.h"
#include "pov_writer.h"
#include "povray_runner.h"
#include "scene/parser.h"
#include "scene_builders.h"
#include "render/render.h"

namespace mirage {
namespace {

using namespace mirage::testing;

constexpr double kRequiredPsnrDb = 40.0;

struct Parity {
    ImageComparison comparison;              // POV-Ray against the tracer on the parsed file
    ImageComparison constructed_comparison;  // POV-Ray against the tracer on the C++ scene
    std::string message;
};

std::string describe(const std::string& name, const ImageComparison& c) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%s: PSNR %.2f dB, RMSE %.5f, max %.3f at (%d, %d), %lld of %lld pixels over "
                  "2.5/255",
                  name.c_str(), c.psnr_db, c.rmse, c.max_error, c.max_x, c.max_y,
                  static_cast<long long>(c.pixels_over), static_cast<long long>(c.pixel_count));
    return text;
}

/// Renders the tracer's image of `scene` to dir/png_name and compares it with POV-Ray's.
ImageComparison compare_render(const Scene& scene, const Image& pov,
                               const std::filesystem::path& dir, const std::string& png_name,
                               bool write_difference) {
    RenderSettings settings;
    settings.width = pov.width;
    settings.height = pov.height;
    settings.progress = false;
    auto ours = render(scene, settings);
    EXPECT_TRUE(ours.ok()) << ours.message();
    if (!ours.ok()) return {};
    const std::string png = (dir / png_name).string();
    EXPECT_TRUE(write_png(ours->image, png).ok());
    auto ours_read = read_image(png);
    EXPECT_TRUE(ours_read.ok());
    auto cmp = compare_images(pov, *ours_read, 2.5 / 255.0);
    EXPECT_TRUE(cmp.ok());
    if (write_difference) {
        auto diff = difference_image(pov, *ours_read);
        if (diff.ok()) {
            for (float& v : diff->pixels) v = std::min(1.0f, v * 8.0f);
            (void)write_exr(*diff, (dir / "difference_x8.exr").string());
        }
    }
    return *cmp;
}

/// Writes the scene file (`pov_text`, by default `scene` written out), renders it with
/// POV-Ray, parses it and renders the parsed scene with the tracer, and compares the PNGs;
/// the C++ scene the file was written from is rendered and compared too.
Parity render_both(const Scene& scene, const std::string& name, int width, int height,
                   const std::string& pov_text = "") {
    const auto dir = test_dir("pov_parity", name);
    const std::string text = pov_text.empty() ? scene_to_pov(scene) : pov_text;
    auto pov = render_with_povray(text, dir, "povray", width, height);
    EXPECT_TRUE(pov.ok()) << pov.message();
    if (!pov.ok()) return {};
    ParseOptions options;
    options.image_width = width;
    options.image_height = height;
    auto parsed = parse_scene_text(text, (dir / "povray.pov").string(), options);
    EXPECT_TRUE(parsed.ok()) << parsed.message();
    if (!parsed.ok()) return {};
    Parity p;
    p.comparison = compare_render(*parsed, *pov, dir, "mirage.png", true);
    p.constructed_comparison = compare_render(scene, *pov, dir, "mirage_constructed.png", false);
    p.message = describe(name, p.comparison) + "\n" +
                describe(name + " (scene built in C++)", p.constructed_comparison);
    std::printf("%s\n", p.message.c_str());
    return p;
}

void expect_parity(const Parity& p) {
    EXPECT_GE(p.comparison.psnr_db, kRequiredPsnrDb) << p.message;
    EXPECT_GE(p.constructed_comparison.psnr_db, kRequiredPsnrDb) << p.message;
}

TEST(PovParity, Showcase) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Parity p = render_both(showcase_scene(), "showcase", 320, 240);
    expect_parity(p);
}

TEST(PovParity, HandwrittenSceneFile) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Parity p = render_both(handwritten_scene(), "handwritten", 320, 240, kHandwrittenPov);
    expect_parity(p);
}

TEST(PovParity, Transforms) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Parity p = render_both(transforms_scene(), "transforms", 320, 240);
    expect_parity(p);
}

TEST(PovParity, MirrorsAtTraceLevel5) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Parity p = render_both(mirrors_scene(5), "mirrors5", 240, 180);
    expect_parity(p);
}

TEST(PovParity, MirrorsAtTraceLevel20) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Parity p = render_both(mirrors_scene(20), "mirrors20", 240, 180);
    expect_parity(p);
}

TEST(PovParity, CheckerToTheHorizon) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const Parity p = render_both(horizon_scene(), "horizon", 320, 240);
    expect_parity(p);
}

}  // namespace
}  // namespace mirage
