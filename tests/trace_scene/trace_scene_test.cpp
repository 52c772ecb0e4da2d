#include "trace_scene/trace_scene.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "../trace/povray_runner.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "load/library_paths.h"
#include "scene/parser.h"

namespace mirage {
namespace {

using namespace mirage::testing;

std::string scene_path(const std::string& name) {
    return std::string(MIRAGE_SOURCE_DIR) + "/scenes/" + name + ".pov";
}

TraceOptions options(const std::string& scene, int width, int height) {
    TraceOptions o;
    o.scene = scene;
    o.width = width;
    o.height = height;
    o.progress = false;
    return o;
}

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
}

/// A copy of a shipped scene with one line replaced, in the test's directory.
std::filesystem::path edited_scene(const std::filesystem::path& dir, const std::string& name,
                                   const std::string& from, const std::string& to) {
    std::string text = read_bytes(scene_path(name));
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    const auto path = dir / (name + ".pov");
    write_text(path, text);
    return path;
}

TEST(TraceScene, WithoutTheAtmosphereItIsTheStraightTracerByteForByte) {
    for (const std::string name : {"desert", "road", "looming"}) {
        TraceOptions o = options(scene_path(name), 96, 72);
        o.atmosphere = false;
        auto traced = trace_scene(o);
        ASSERT_TRUE(traced.ok()) << traced.message();
        EXPECT_EQ(traced->mode, PathMode::Straight);
        EXPECT_EQ(traced->atmosphere, "off (--no-atmosphere)");
        EXPECT_DOUBLE_EQ(traced->render.stats.segments_per_ray(), 1.0);

        ParseOptions po;
        po.library_paths = default_library_paths(o.scene);
        po.image_width = 96;
        po.image_height = 72;
        auto scene = parse_scene_file(o.scene, po);
        ASSERT_TRUE(scene.ok()) << scene.message();
        RenderSettings rs;
        rs.width = 96;
        rs.height = 72;
        rs.progress = false;
        auto straight = render(*scene, rs);  // StraightPropagator, the tracer's own pixel rays
        ASSERT_TRUE(straight.ok());
        ASSERT_EQ(traced->render.image.pixels.size(), straight->image.pixels.size());
        EXPECT_EQ(std::memcmp(traced->render.image.pixels.data(), straight->image.pixels.data(),
                              straight->image.pixels.size() * sizeof(float)),
                  0)
            << name;
    }
}

TEST(TraceScene, AnAtmosphereBendsTheRaysAndItsToleranceIsTheScenes) {
    auto traced = trace_scene(options(scene_path("desert"), 64, 48));
    ASSERT_TRUE(traced.ok()) << traced.message();
    EXPECT_EQ(traced->mode, PathMode::PerRay);
    EXPECT_EQ(traced->atmosphere, "paper (inferior)");
    EXPECT_DOUBLE_EQ(traced->tolerance_px, 0.5);  // Mirage_Tolerance
    // Straight rays are one segment each; curved ones that pass near the spheres or reach the
    // sand take several (a sky ray with nothing near it is one: its asymptote).
    EXPECT_GT(traced->render.stats.segments_per_ray(), 1.2);
    TraceOptions o = options(scene_path("desert"), 64, 48);
    o.tolerance_px = 0.1;
    auto tight = trace_scene(o);
    ASSERT_TRUE(tight.ok());
    EXPECT_DOUBLE_EQ(tight->tolerance_px, 0.1);
    EXPECT_GT(tight->render.stats.segments_per_ray(), traced->render.stats.segments_per_ray());
    // A tighter tolerance moves no pixel far: the pictures agree closely.
    auto cmp = compare_images(quantize_srgb8(traced->render.image),
                              quantize_srgb8(tight->render.image), 0.1);
    ASSERT_TRUE(cmp.ok());
    EXPECT_GT(cmp->psnr_db, 30.0);
    const std::string summary = trace_summary(*traced);
    EXPECT_NE(summary.find("atmosphere paper (inferior), per-ray paths within 0.5 px"),
              std::string::npos)
        << summary;
    EXPECT_NE(summary.find("segments/ray"), std::string::npos);
    EXPECT_NE(summary.find("Mrays/s"), std::string::npos);
}

/// The desert with its camera made level (it looks 12 degrees down, at the sand): scanline
/// paths need a level camera.
std::filesystem::path level_desert(const std::filesystem::path& dir) {
    return edited_scene(dir, "desert", "look_at  <0, 0, 7>", "look_at  <0, 1.5, 10>");
}

TEST(TraceScene, SameBytesWithOneAndTwoThreads) {
    const auto dir = test_dir("trace_scene", "threads");
    const std::string level = level_desert(dir).string();
    for (const bool scanline : {false, true}) {
        std::string bytes[2];
        for (const int threads : {1, 2}) {
            TraceOptions o = options(scanline ? level : scene_path("desert"), 120, 90);
            o.threads = threads;
            o.scanline_paths = scanline;
            o.output = (dir / ("desert_" + std::to_string(threads) + ".png")).string();
            auto traced = trace_scene(o);
            ASSERT_TRUE(traced.ok()) << traced.message();
            EXPECT_EQ(traced->render.stats.threads, threads);
            EXPECT_GT(traced->render.stats.segments_per_ray(), 1.2);  // curved, not straight
            bytes[threads - 1] = read_bytes(o.output);
        }
        EXPECT_GT(bytes[0].size(), 1000u);
        EXPECT_TRUE(bytes[0] == bytes[1]) << (scanline ? "scanline" : "per ray");
    }
}

TEST(TraceScene, ScanlinePathsAgainstPerRayPaths) {
    // The paper's scheme gives every pixel of a row the central column's elevation: exact on
    // that column, off by the perspective elsewhere.  Measured on the desert made level (60
    // degrees across) and the road (2 degrees across).  An odd width puts a pixel column on
    // the centre.
    const auto dir = test_dir("trace_scene", "scanline");
    const std::string level = level_desert(dir).string();
    for (const std::string name : {"desert", "road"}) {
        const int w = 161, h = 120;
        TraceOptions o = options(name == "desert" ? level : scene_path(name), w, h);
        auto per_ray = trace_scene(o);
        o.scanline_paths = true;
        auto scanline = trace_scene(o);
        ASSERT_TRUE(per_ray.ok() && scanline.ok());
        EXPECT_EQ(scanline->mode, PathMode::Scanline);
        const Image a = quantize_srgb8(per_ray->render.image);
        const Image b = quantize_srgb8(scanline->render.image);
        for (int y = 0; y < h; ++y) {
            ASSERT_EQ(per_ray->render.image.at(w / 2, y), scanline->render.image.at(w / 2, y))
                << name << " row " << y;
        }
        auto cmp = compare_images(a, b, 2.5 / 255.0);
        ASSERT_TRUE(cmp.ok());
        const RenderStats& sp = per_ray->render.stats;
        const RenderStats& ss = scanline->render.stats;
        std::printf(
            "%s %dx%d: scanline vs per-ray PSNR %.2f dB, RMSE %.5f, max %.3f, %lld of "
            "%lld pixels over 2.5/255; per ray %.3f s (%.2f segments/ray), scanline "
            "%.3f s (%.2f segments/ray)\n",
            name.c_str(), w, h, cmp->psnr_db, cmp->rmse, cmp->max_error,
            static_cast<long long>(cmp->pixels_over), static_cast<long long>(cmp->pixel_count),
            sp.seconds, sp.segments_per_ray(), ss.seconds, ss.segments_per_ray());
        if (name == "desert") {
            // A wide field: the rows' error shows.
            EXPECT_GT(cmp->rmse, 0.005);
            EXPECT_GT(cmp->pixels_over, w * h / 20);
        } else {
            EXPECT_GT(cmp->rmse, 0.0);
        }
    }
}

TEST(TraceScene, ScanlinePathsRefuseATiltedCamera) {
    // The desert looks down at the sand: atan(1.5 / 7) = 12.1 degrees.
    const std::string path = scene_path("desert");
    TraceOptions o = options(path, 32, 24);
    o.scanline_paths = true;
    auto r = trace_scene(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), path +
                               ":26:1: scanline paths need a level camera (one path per image "
                               "row is rotated about the vertical): the camera looks 12.1 "
                               "degrees down");
    o.scanline_paths = false;
    EXPECT_TRUE(trace_scene(o).ok());  // per-ray paths take any camera
}

TEST(TraceScene, RefusesBadOptionsBeforeTracing) {
    TraceOptions o = options(scene_path("desert"), 32, 24);
    o.output = "/nonexistent-dir/desert.jpg";
    EXPECT_EQ(trace_scene(o).message(),
              "/nonexistent-dir/desert.jpg: unknown image type '.jpg' (use .png or .exr)");
    o.output.clear();
    o.tolerance_px = 0.0;
    EXPECT_EQ(trace_scene(o).message(),
              "--tolerance 0: the tolerance must be from 0.001 to 1000 pixels");
    o.tolerance_px.reset();
    o.threads = -1;
    EXPECT_EQ(trace_scene(o).message(), "--threads -1: must be 0 (all cores) or more");
    o.threads = 0;
    o.width = 0;
    EXPECT_EQ(trace_scene(o).message(), "image size 0x24 must be 1 to 20000 pixels each way");
}

TEST(TraceScene, AFailedWriteLeavesTheOldImage) {
    const auto dir = test_dir("trace_scene", "write");
    const auto image = dir / "out.png";
    write_text(image, "old");
    TraceOptions o = options((dir / "missing.pov").string(), 32, 24);
    o.output = image.string();
    EXPECT_FALSE(trace_scene(o).ok());
    EXPECT_EQ(read_bytes(image), "old");
    o.scene = scene_path("desert");
    ASSERT_TRUE(trace_scene(o).ok());
    auto back = read_image(image.string());
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->width, 32);
}

/// Two sky_sphere pigments: POV-Ray 3.7 puts the last on top.  Parsed, traced and compared
/// with POV-Ray in both orders.
TEST(TraceScene, TheLastSkySpherePigmentIsOnTopAsInPovRay) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const auto dir = test_dir("trace_scene", "sky_layers");
    const std::string head = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0, 0, 1> }
background { rgb <0, 1, 0> }
)";
    const std::string red = "pigment { rgb <1, 0, 0> }";
    const std::string blue =
        "pigment { gradient y color_map { [0 rgbt <0, 0, 1, 0.5>] "
        "[1 rgbt <0, 0, 1, 0.9>] } }";
    struct Case {
        std::string name, sky;
        glm::vec3 centre;  // the centre's code values, POV-Ray's
    };
    for (const Case& c : {Case{"red_then_blue", red + " " + blue, {188, 0, 188}},
                          Case{"blue_then_red", blue + " " + red, {255, 0, 0}}}) {
        const std::string text = head + "sky_sphere { " + c.sky + " }\n";
        // An odd size puts a pixel's centre on the view direction (the gradient's 0).
        auto pov = render_with_povray(text, dir, c.name, 41, 31);
        ASSERT_TRUE(pov.ok()) << pov.message();
        TraceOptions o = options((dir / (c.name + ".pov")).string(), 41, 31);
        o.output = (dir / (c.name + "_mirage.png")).string();
        auto traced = trace_scene(o);
        ASSERT_TRUE(traced.ok()) << traced.message();
        auto ours = read_image(o.output);
        ASSERT_TRUE(ours.ok());
        auto cmp = compare_images(*pov, *ours, 1.5 / 255.0);
        ASSERT_TRUE(cmp.ok());
        EXPECT_EQ(cmp->pixels_over, 0) << c.name << ": PSNR " << cmp->psnr_db;
        const glm::vec3 centre = pov->at(20, 15) * 255.0f;
        EXPECT_NEAR(centre.x, c.centre.x, 0.01) << c.name;
        EXPECT_NEAR(centre.y, c.centre.y, 0.01) << c.name;
        EXPECT_NEAR(centre.z, c.centre.z, 0.01) << c.name;
    }
}

}  // namespace
}  // namespace mirage
