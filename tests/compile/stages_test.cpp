#include "compile/stages.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "atmosphere/profile.h"
#include "compile/pixel_check.h"
#include "layers/band_aim.h"
#include "layers/fit.h"
#include "layers/outcome.h"
#include "scene/camera.h"
#include "test_temp.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::string temp_dir(const std::string& name) {
    const fs::path d = mirage::testing::test_temp_path("mirage_stages_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d.string();
}

// The paper's desert in small: a level camera 1.5 m up, a sphere 14 m out (reflective), the
// sand at y = 0.
std::string scene_text(const std::string& atmosphere) {
    return "#version 3.7;\n" + atmosphere + R"(
#declare Mirage_Tolerance = 0.5;
#include "mirage.inc"
camera { location <0, 1.5, 0> look_at <0, 1.5, 10> right x * image_width / image_height angle 60 }
light_source { <-30, 60, -20>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <2.5, 1.6, 14>, 1 pigment { color rgb <0.8, 0.2, 0.1> } finish { reflection 0.25 } }
)";
}

CompileOptions options_for(const std::string& name, const std::string& atmosphere, int w, int h) {
    const std::string dir = temp_dir(name);
    CompileOptions o;
    o.scene = dir + "/" + name + ".pov";
    std::ofstream(o.scene) << scene_text(atmosphere);
    o.width = w;
    o.height = h;
    o.out_dir = dir + "/out";
    o.progress = false;
    return o;
}

const char* kPaper = "#declare Mirage_Preset = \"paper\";";

TEST(CompileSettings, ReadsTheCameraTheExtentAndTheLayout) {
    auto ctx = compile_settings(options_for("settings", kPaper, 40, 30));
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    EXPECT_DOUBLE_EQ(ctx->eye_y, 1.5);
    // The sphere's far corner, 1.25 times: sqrt(3.5^2 + 15^2) * 1.25.
    EXPECT_NEAR(ctx->extent, 1.25 * std::hypot(3.5, 15.0), 1e-6);
    EXPECT_FALSE(ctx->gaps);  // the paper's index changes by 0.1: nested planes
    EXPECT_NEAR(ctx->layers_box.x1, kLayersExtentFactor * ctx->extent, 1e-6);
    // The steepest ray of a level camera: at the middle of the image's bottom edge (the
    // corners look down less steeply).
    const glm::dvec3 bottom = camera_ray(ctx->camera, 20.0, 30.0, 40, 30).direction;
    EXPECT_NEAR(ctx->steepest_sine, std::fabs(bottom.y), 1e-12);
    EXPECT_GT(ctx->steepest_sine,
              std::fabs(camera_ray(ctx->camera, 0.5, 29.5, 40, 30).direction.y));

    auto road = compile_settings(
        options_for("settings_road", "#declare Mirage_Preset = \"hot-road\";", 40, 30));
    ASSERT_TRUE(road.ok()) << road.message();
    EXPECT_TRUE(road->gaps);  // real air: index steps too small for float quotients
}

TEST(CompileSettings, RefusesBadSizesAndSampleCounts) {
    CompileOptions o = options_for("bad", kPaper, 0, 30);
    auto r = compile_settings(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), "image size 0x30 must be 1 to 20000 pixels each way");
    o.width = 40;
    o.samples_per_side = 9;
    r = compile_settings(o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), "sub-pixel samples 9 per side: must be 1 to 5");
}

TEST(CameraRays, SamplesAGridInEveryPixelWithTheCentreAmongThem) {
    auto ctx = compile_settings(options_for("rays", kPaper, 8, 6));
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    const CameraRays rays = camera_rays(*ctx, 3);
    EXPECT_EQ(rays.grid_width(), 24);
    EXPECT_EQ(rays.grid_height(), 18);
    ASSERT_EQ(rays.size(), 24u * 18u);
    for (int row = 0; row < 6; ++row)
        for (int col = 0; col < 8; ++col) {
            const glm::dvec3 want = camera_ray(ctx->camera, col + 0.5, row + 0.5, 8, 6).direction;
            EXPECT_EQ(rays.direction[rays.centre(col, row)], want) << col << "," << row;
        }
    // A sample a third of a pixel left of and above the centre of pixel (2, 3).
    const size_t s = rays.centre(2, 3) - rays.grid_width() - 1;
    EXPECT_EQ(rays.direction[s], camera_ray(ctx->camera, 2 + 1.0 / 6, 3 + 1.0 / 6, 8, 6).direction);
    const CameraRays c = rays.centres();
    ASSERT_EQ(c.size(), 48u);
    EXPECT_EQ(c.direction[3 * 8 + 2], rays.direction[rays.centre(2, 3)]);
    EXPECT_EQ(c.elevation[3 * 8 + 2], rays.elevation[rays.centre(2, 3)]);
    // Rows near the horizon of a level camera look up and down alike.
    EXPECT_GT(c.elevation[0], 0.0);
    EXPECT_LT(c.elevation[47], 0.0);
    EXPECT_NEAR(c.elevation[0], -c.elevation[47], 1e-12);
}

TEST(DesignLayers, NoAtmosphereNoLayersAndNoBendNoLayers) {
    auto plain = compile_settings(options_for("design_plain", "", 16, 12));
    ASSERT_TRUE(plain.ok()) << plain.message();
    auto d = design_layers(*plain, camera_rays(*plain, 1));
    ASSERT_TRUE(d.ok()) << d.message();
    EXPECT_EQ(d->mode, "none");
    EXPECT_EQ(d->stack.boundaries(), 0);

    auto flat = compile_settings(
        options_for("design_flat",
                    "#declare Mirage_Profile = \"inferior\"; #declare Mirage_Eta0 = 1.0003; "
                    "#declare Mirage_Eta1 = 1e-9; #declare Mirage_Alpha = 2.3;",
                    16, 12));
    ASSERT_TRUE(flat.ok()) << flat.message();
    d = design_layers(*flat, camera_rays(*flat, 1));
    ASSERT_TRUE(d.ok()) << d.message();
    EXPECT_EQ(d->mode, "adaptive");
    EXPECT_EQ(d->stack.boundaries(), 0);
    ASSERT_FALSE(d->left_out.empty());
    EXPECT_NE(d->left_out.front().find("no camera ray bends"), std::string::npos);
}

TEST(DesignLayers, FitsWithinTheTraceLevelCeiling) {
    CompileOptions o = options_for("design_fit", kPaper, 40, 30);
    o.camera = CameraModel::Perspective;  // the fit to the scene's own camera
    auto ctx = compile_settings(o);
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    const CameraRays rays = camera_rays(*ctx, 1);
    auto d = design_layers(*ctx, rays);
    ASSERT_TRUE(d.ok()) << d.message();
    EXPECT_EQ(d->mode, "adaptive");
    EXPECT_GT(d->stack.boundaries(), 5);
    EXPECT_TRUE(well_formed(d->stack));
    EXPECT_LE(d->max_trace_level, kMaxTraceLevel);
    EXPECT_EQ(d->max_trace_level, deepest_trace_level(*ctx, ctx->rendered(d->stack), rays));
    // Better than no layers at all where the rays bend.
    LayerStack none;
    none.profile = *ctx->atmosphere.exponential_profile();
    none.excess = {eta_sq_excess(none.profile, ctx->eye_y)};
    const auto with = design_errors(*ctx, ctx->rendered(d->stack), rays);
    const auto without = design_errors(*ctx, none, rays);
    double sum_with = 0.0, sum_without = 0.0;
    for (size_t i = 0; i < rays.size(); ++i) sum_with += with[i], sum_without += without[i];
    EXPECT_LT(sum_with, 0.2 * sum_without);
}

TEST(DesignErrors, TheHalfPlaneTraceAgreesWithTheIndependent3dTracer) {
    // design_errors follows each camera ray in the half-plane of its azimuth; the 3D band
    // tracer follows the same ray as POV-Ray does, in vectors, without the symmetry.
    for (const char* atmosphere : {kPaper, "#declare Mirage_Preset = \"hot-road\";"}) {
        auto ctx = compile_settings(options_for("errors2d", atmosphere, 24, 18));
        ASSERT_TRUE(ctx.ok()) << ctx.message();
        const CameraRays rays = camera_rays(*ctx, 1);
        auto d = design_layers(*ctx, rays);
        ASSERT_TRUE(d.ok()) << d.message();
        const LayerStack rendered = ctx->rendered(d->stack);
        const std::vector<double> err = design_errors(*ctx, rendered, rays);
        for (size_t i = 0; i < rays.size(); ++i) {
            Trace3dOptions to;
            to.camera_y = ctx->eye_y;
            const Trace3dOutcome t =
                trace_layers_3d(rendered, ctx->camera.location, rays.direction[i], ctx->scene_box,
                                ctx->layers_box, to);
            const glm::dvec3& eye = ctx->camera.location;
            const glm::dvec3& dir = rays.direction[i];
            BandOutcome b;
            b.ground = t.ground;
            b.dz = t.ground ? std::hypot(t.scene_point.x - eye.x, t.scene_point.z - eye.z)
                            : rays.exit_dz[i];
            b.y = t.scene_point.y;
            b.slope = t.scene_dir.y / std::hypot(t.scene_dir.x, t.scene_dir.z);
            b.sky = t.sky;
            b.final_slope = t.final_dir.y / std::hypot(t.final_dir.x, t.final_dir.z);
            const BandOutcome e =
                exact_outcome(ctx->atmosphere, ctx->eye_y, rays.elevation[i], rays.exit_dz[i]);
            const double want = outcome_error_rad(ctx->eye_y, e, b) / rays.pixel_rad[i];
            EXPECT_NEAR(err[i], want, 1e-6 * (1.0 + want))
                << atmosphere << " ray " << i << " elevation " << dir.y;
        }
    }
}

TEST(DesignLayers, UniformLayersAreBergersAndMeasured) {
    CompileOptions o = options_for("design_uniform", kPaper, 16, 12);
    o.layers = LayerMode::Uniform;
    o.layer_count = 12;
    auto ctx = compile_settings(o);
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    const CameraRays rays = camera_rays(*ctx, 1);
    auto d = design_layers(*ctx, rays);
    ASSERT_TRUE(d.ok()) << d.message();
    EXPECT_EQ(d->mode, "uniform");
    ASSERT_EQ(d->stack.boundaries(), 12);
    for (int k = 1; k < 12; ++k)
        EXPECT_NEAR(d->stack.heights[k] - d->stack.heights[k - 1],
                    d->stack.heights[1] - d->stack.heights[0], 1e-9);
    EXPECT_EQ(d->max_trace_level, deepest_trace_level(*ctx, d->stack, rays));
    // No count anywhere: the settings stand, the uniform design has nothing to divide by.
    o.layer_count.reset();
    ctx = compile_settings(o);
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    EXPECT_FALSE(design_layers(*ctx, rays).ok());
    // A count out of range is refused where it is read, with its name and limit.
    o.layer_count = 0;
    ctx = compile_settings(o);
    ASSERT_FALSE(ctx.ok());
    EXPECT_EQ(ctx.message(), "--count 0: the layer count must be a whole number from 1 to 4096");
}

TEST(DeepestTraceLevel, CountsBoundaryEventsAndReflections) {
    // Two planes below the eye of a straight atmosphere-less stack: a ray down to the ground
    // crosses both (2 events) on level 1; the ground is no mirror.
    auto ctx = compile_settings(options_for("levels", kPaper, 8, 6));
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    LayerStack s;
    s.profile = *ctx->atmosphere.exponential_profile();
    s.heights = {0.5, 1.0};
    s.excess = {0.0, 0.01, eta_sq_excess(s.profile, ctx->eye_y)};
    CameraRays down;
    down.width = down.height = 1;
    down.direction = {glm::normalize(glm::dvec3(0.0, -1.0, 0.2))};
    down.elevation = {std::asin(down.direction[0].y)};
    down.exit_dz = {ctx->extent};
    down.pixel_rad = {1e-3};
    EXPECT_EQ(deepest_trace_level(*ctx, s, down), 1 + 2);
    // Near the top of the reflective sphere, above both planes: one more level for the
    // reflection, and the reflected ray leaves upwards through no boundary.
    CameraRays at_sphere = down;
    at_sphere.direction = {glm::normalize(glm::dvec3(2.5, 1.05, 14.0))};
    EXPECT_EQ(deepest_trace_level(*ctx, s, at_sphere), 2);
}

TEST(LayersReach, AtLeastPastTheSceneAtMostTheLayersBox) {
    auto ctx = compile_settings(options_for("reach", kPaper, 16, 12));
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    const CameraRays rays = camera_rays(*ctx, 1);
    auto d = design_layers(*ctx, rays);
    ASSERT_TRUE(d.ok()) << d.message();
    const double reach = layers_reach(*ctx, ctx->rendered(d->stack), rays);
    EXPECT_GE(reach, 1.1 * ctx->extent);
    EXPECT_LE(reach, ctx->layers_box.x1 - ctx->camera.location.x);
}

TEST(EmitFiles, TheIniFindsTheLayersFirstAndTheIncludeSplitsAtTheCamera) {
    auto ctx = compile_settings(options_for("emit", kPaper, 16, 12));
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    auto d = design_layers(*ctx, camera_rays(*ctx, 1));
    ASSERT_TRUE(d.ok()) << d.message();
    const EmittedFiles f =
        emit_files(*ctx, d->stack, 100.0, std::nullopt, "/out/dir", "/out/x.png", {"hello"}, false);
    const size_t out = f.ini.find("Library_Path=\"/out/dir\"");
    ASSERT_NE(out, std::string::npos) << f.ini;
    EXPECT_LT(out, f.ini.find("Library_Path=", out + 1));
    EXPECT_NE(f.ini.find("Output_File_Name=\"/out/x.png\""), std::string::npos);
    EXPECT_EQ(f.include.rfind("// hello\n", 0), 0u);
    EXPECT_NE(f.include.find("plane { y, "), std::string::npos);   // below the camera
    EXPECT_NE(f.include.find("plane { -y, "), std::string::npos);  // above it
    EXPECT_NE(f.include.find("<-100, "), std::string::npos);       // clipped to the reach
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

// For a ray leaving for the sky the aim's first candidates leave the layers in the exact
// final direction on both sheets (a ray and its mirror image have one cosine), the exact
// ray's own sheet first: a downward camera ray's turned one, a rising ray's direct one.
TEST(CorrectedCameraAim, SkyRaysTryTheExactRaysSheetFirst) {
    auto ctx = compile_settings(options_for("aim_sheet", kPaper, 40, 30));
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    const CameraRays rays = camera_rays(*ctx, 1);
    auto d = design_layers(*ctx, rays);
    ASSERT_TRUE(d.ok()) << d.message();
    ASSERT_GT(d->stack.boundaries(), 0);
    const BandAim aim = corrected_camera_aim(*ctx, ctx->rendered(d->stack), rays);
    ASSERT_TRUE(aim);
    int down = 0, up = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const glm::dvec3 dir = rays.direction[i];
        ExactEnd end;
        end.hit = false;  // leaving upward, a little steeper than the ray set out
        const double final_sine = std::min(0.9, std::fabs(dir.y) + 0.02);
        const double hl = std::hypot(dir.x, dir.z);
        end.direction = glm::dvec3(dir.x / hl * std::sqrt(1 - final_sine * final_sine), final_sine,
                                   dir.z / hl * std::sqrt(1 - final_sine * final_sine));
        std::vector<glm::dvec3> c;
        aim.candidates(i, dir, end, c);
        if (c.size() < 3) continue;  // no elevation leaves that way
        // The two sheets: one cosine, opposite sines, the horizontal direction the camera's.
        EXPECT_NEAR(c[0].y, -c[1].y, 1e-6) << i;
        EXPECT_NEAR(c[0].x * dir.z - c[0].z * dir.x, 0.0, 1e-6) << i;
        if (rays.elevation[i] < 0.0) {
            EXPECT_LT(c[0].y, 0.0) << i;
            ++down;
        } else {
            EXPECT_GT(c[0].y, 0.0) << i;
            ++up;
        }
    }
    EXPECT_GT(down, 100);
    EXPECT_GT(up, 100);
}

// At an object's edge the exact ray passes close by one surface and meets another, and no band
// ray may do both: the aim still finds, along the pixel's sheet of directions, the band ray
// that ends nearest the exact end.  Checked against a fan of band rays a twentieth of a pixel
// apart, from three pixels under to three over the chosen one, offered on top of the aim's
// own candidates wherever the chosen ray ends off the exact end: none ends nearer.
TEST(CorrectedCameraAim, AtAnEdgeNoBandRayOnTheSheetEndsNearer) {
    const std::string dir = temp_dir("aim_edge");
    CompileOptions o;
    o.scene = dir + "/edge.pov";
    // Eight layers (a coarse smooth part), a long low bar 8 m out whose top the rays turning
    // over the sand graze, a wall 30 m out behind it.
    std::ofstream(o.scene) << R"(#version 3.7;
#declare Mirage_Preset = "paper";
#declare Mirage_Layer_Count = 8;
#include "mirage.inc"
camera { location <0, 1.5, 0> look_at <0, 1.3, 10> right x * image_width / image_height angle 16 }
light_source { <-30, 60, -20>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
box { <-30, 0, 8>, <30, 0.35, 8.3> pigment { color rgb <0.2, 0.3, 0.8> } }
box { <-40, 0, 30>, <40, 6, 31> pigment { color rgb <0.8, 0.7, 0.2> } }
)";
    o.width = 48;
    o.height = 72;
    o.out_dir = dir + "/out";
    o.progress = false;
    auto ctx = compile_settings(o);
    ASSERT_TRUE(ctx.ok()) << ctx.message();
    const CameraRays rays = camera_rays(*ctx, 1);
    auto d = design_layers(*ctx, rays);
    ASSERT_TRUE(d.ok()) << d.message();
    const LayerStack rendered = ctx->rendered(d->stack);
    PixelCheckSettings ps;
    ps.atmosphere = ctx->atmosphere;
    ps.width = rays.grid_width();
    ps.height = rays.grid_height();
    ps.eye = ctx->camera.location;
    ps.camera_y = ctx->reference_y(rendered);
    const double reach = ctx->layers_box.x1 - ps.eye.x;
    ps.layers = {ps.eye.x - reach, ps.eye.x + reach, ps.eye.z - reach, ps.eye.z + reach};
    ps.exact_tolerance_rad = 0.05 * rays.pixel_rad[0];
    ps.aim = corrected_camera_aim(*ctx, rendered, rays);
    const std::vector<bool> cut(rays.size(), false);
    const ObjectQuery objects = object_query(*ctx->accel);
    const PixelCheck chosen = check_pixels(rendered, ctx->scene, *ctx->accel, objects,
                                           rays.direction, rays.pixel_rad, cut, ps);
    // The same check offered the fan too, where the chosen ray ends a tenth of a pixel off.
    std::vector<size_t> off;
    for (size_t i = 0; i < rays.size(); ++i)
        if (chosen.camera_error_px[i] > 0.1f) off.push_back(i);
    ASSERT_GE(off.size(), 5u) << "no edges to test";
    PixelCheckSettings fan = ps;
    const BandAim own = ps.aim;
    fan.aim.candidates = [&](size_t i, const glm::dvec3& d, const ExactEnd& end,
                             std::vector<glm::dvec3>& out) {
        own.candidates(i, d, end, out);
        if (chosen.camera_error_px[i] <= 0.1f) return;
        const glm::dvec3 c = chosen.band_direction[i];
        const double e = std::asin(c.y);
        for (int k = -60; k <= 60; ++k)
            out.push_back(mesh_camera_direction(
                direction_at_elevation(c, e + k * 0.05 * rays.pixel_rad[i])));
    };
    const PixelCheck fanned = check_pixels(rendered, ctx->scene, *ctx->accel,
                                           objects, rays.direction, rays.pixel_rad, cut, fan);
    for (size_t i : off)
        EXPECT_LE(chosen.camera_error_px[i], fanned.camera_error_px[i] + 0.05f)
            << "pixel " << i % rays.grid_width() << ", " << i / rays.grid_width();
}

}  // namespace
}  // namespace mirage
