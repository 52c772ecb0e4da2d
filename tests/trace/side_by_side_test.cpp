// `mirage trace --side-by-side`: the left half is the scene traced without its atmosphere and
// the right half with it, pixel for pixel as `mirage trace` writes each, labelled under them.
#include "trace_scene/side_by_side.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../cli/run_tool.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "povray_runner.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::test_dir;

constexpr int kW = 96, kH = 72;

std::string scene_path(const std::string& name) {
    return (fs::path(MIRAGE_SOURCE_DIR) / "scenes" / (name + ".pov")).string();
}

TraceOptions options(const std::string& scene, const fs::path& output) {
    TraceOptions o;
    o.scene = scene;
    o.output = output.string();
    o.width = kW;
    o.height = kH;
    o.progress = false;
    return o;
}

/// The w x h region of `image` at (x0, y0).
Image crop(const Image& image, int x0, int y0, int w, int h) {
    Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) out.set(x, y, image.at(x0 + x, y0 + y));
    return out;
}

bool same(const Image& a, const Image& b) {
    auto c = compare_images(a, b, 0.0);
    return c.ok() && c->max_error == 0.0;
}

TEST(SideBySide, TheHalvesAreTheTracesWithoutAndWithTheAtmosphere) {
    const auto dir = test_dir("side_by_side", "halves");
    TraceOptions plain = options(scene_path("desert"), dir / "without.png");
    plain.atmosphere = false;
    ASSERT_TRUE(trace_scene(plain).ok());
    ASSERT_TRUE(trace_scene(options(scene_path("desert"), dir / "with.png")).ok());
    auto both = trace_side_by_side(options(scene_path("desert"), dir / "both.png"));
    ASSERT_TRUE(both.ok()) << both.message();
    EXPECT_EQ(both->output, (dir / "both.png").string());

    auto image = read_image((dir / "both.png").string());
    auto without = read_image((dir / "without.png").string());
    auto with = read_image((dir / "with.png").string());
    ASSERT_TRUE(image.ok() && without.ok() && with.ok());
    ASSERT_GE(image->width, 2 * kW);
    ASSERT_GE(image->height, kH);
    const Image left = crop(*image, both->left_x, both->top_y, kW, kH);
    const Image right = crop(*image, both->right_x, both->top_y, kW, kH);
    EXPECT_TRUE(same(left, *without));
    EXPECT_TRUE(same(right, *with));
    // The two traces differ (the paper's air hides the sand), so the halves cannot be swapped.
    EXPECT_FALSE(same(*without, *with));
    EXPECT_FALSE(same(left, *with));

    // The labels: light text on the dark strip under each half, when a font was found.
    if (both->font.empty()) GTEST_SKIP() << "no font for the labels; the halves are unlabelled";
    for (const int x0 : {both->left_x, both->right_x}) {
        int ink = 0;
        for (int y = both->top_y + kH + 1; y < image->height; ++y)
            for (int x = x0; x < x0 + kW; ++x) ink += image->at(x, y).x > 0.5f;
        EXPECT_GT(ink, 20) << "no label under the half at x = " << x0;
    }
}

TEST(SideBySide, AntialiasingAppliesToBothHalves) {
    const auto dir = test_dir("side_by_side", "antialiased");
    TraceOptions o = options(scene_path("road"), dir / "both.png");
    o.antialias.method = AntialiasMethod::NonRecursive;
    auto both = trace_side_by_side(o);
    ASSERT_TRUE(both.ok()) << both.message();
    EXPECT_TRUE(both->without.render.stats.antialiased);
    EXPECT_TRUE(both->with.render.stats.antialiased);
    EXPECT_EQ(both->without.mode, PathMode::Straight);
    EXPECT_EQ(both->with.mode, PathMode::PerRay);
}

TEST(SideBySide, TallImagesGetLargerLabels) {
    // 400 rows ask for 25-pixel labels, larger than the probe for a font once was (OpenImageIO
    // aborted on text outside it); 60 columns hold them only when made smaller.
    const auto dir = test_dir("side_by_side", "tall");
    TraceOptions o = options(scene_path("desert"), dir / "tall.png");
    o.width = 60;
    o.height = 400;
    auto both = trace_side_by_side(o);
    ASSERT_TRUE(both.ok()) << both.message();
    auto image = read_image((dir / "tall.png").string());
    ASSERT_TRUE(image.ok());
    EXPECT_GT(image->height, 400);
}

TEST(SideBySide, RefusesWhatWouldNotShowTheMirage) {
    const auto dir = test_dir("side_by_side", "refused");
    // A scene without an atmosphere: both halves would be the same.
    const fs::path plain = dir / "plain.pov";
    std::ofstream(plain)
        << "#version 3.7;\ncamera { location <0, 1, -3> look_at 0 }\n"
           "light_source { <2, 4, -3>, rgb 1 }\nsphere { 0, 1 pigment { rgb 1 } }\n";
    auto r = trace_side_by_side(options(plain.string(), dir / "plain.png"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), plain.string() +
                               ": the atmosphere (none declared) bends no ray, so both halves of "
                               "--side-by-side would be the same");
    EXPECT_FALSE(fs::exists(dir / "plain.png"));
    // An EXR could not hold the labels as drawn.
    auto exr = trace_side_by_side(options(scene_path("desert"), dir / "both.exr"));
    ASSERT_FALSE(exr.ok());
    EXPECT_NE(exr.message().find("--side-by-side writes an 8-bit PNG"), std::string::npos);
    // The output may not replace the scene.
    const fs::path copy = dir / "desert.pov";
    fs::copy_file(scene_path("desert"), copy);
    auto over = trace_side_by_side(options(copy.string(), copy));
    EXPECT_FALSE(over.ok());
}

TEST(SideBySide, WithoutAFontTheSummarySaysTheHalvesAreUnlabelled) {
    SideBySideReport r;
    r.output = "both.png";
    r.font = "DejaVuSans";
    EXPECT_EQ(side_by_side_summary(r).find("note:"), std::string::npos);
    r.font.clear();
    EXPECT_NE(side_by_side_summary(r).find("note: no font found for the labels (DejaVuSans, "
                                           "Debian's fonts-dejavu-core): the halves are "
                                           "unlabelled\n"),
              std::string::npos)
        << side_by_side_summary(r);
}

TEST(SideBySide, FromTheCommandLine) {
    const auto dir = test_dir("side_by_side", "cli");
    const auto out = dir / "both.png";
    auto r =
        run_tool("trace " + scene_path("desert") + " -W 64 -H 48 --before-after -o " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("left, without mirage: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("right, with mirage: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("wrote " + out.string() + " (without the atmosphere left, with it right)"),
              std::string::npos)
        << r.out;
    auto image = read_image(out.string());
    ASSERT_TRUE(image.ok());
    EXPECT_GT(image->width, 128);

    auto refused = run_tool("trace " + scene_path("desert") +
                            " --side-by-side --no-atmosphere -o " + quoted(dir / "x.png"));
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_EQ(refused.err,
              "mirage trace: --side-by-side renders the scene without and with the atmosphere; "
              "drop --no-atmosphere\n");
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace mirage
