// mirage trace with an atmosphere for cameras whose rays start at different points
// (orthographic, cylinder 3 and 4): every pixel's exact ray from its own origin, sampled to a
// tolerance in the camera's own unit of one pixel (scene/camera.h, PixelFootprint).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "atmosphere/exact_ray.h"
#include "atmosphere/profile.h"
#include "atmosphere/sampler.h"
#include "load/atmosphere_settings.h"
#include "load/mirage_scene.h"
#include "scene/camera.h"
#include "trace/curved_propagator.h"
#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

// The wall's front face, its top, and the stripes of its gradient (red below each half unit,
// green above).
constexpr double kWallZ = 30.0;
constexpr double kWallTop = 8.0;

enum class Shade { Red, Green, Blue, White, Black, Other };

Shade shade_of(float r, float g, float b) {
    auto hi = [](float v) { return v > 0.5f; };
    if (hi(r) && !hi(g) && !hi(b)) return Shade::Red;
    if (!hi(r) && hi(g) && !hi(b)) return Shade::Green;
    if (!hi(r) && !hi(g) && hi(b)) return Shade::Blue;
    if (hi(r) && hi(g) && hi(b)) return Shade::White;
    if (!hi(r) && !hi(g) && !hi(b)) return Shade::Black;
    return Shade::Other;
}

std::string scene_text(const std::string& camera, bool ground) {
    std::string s =
        "#version 3.7;\n"
        "#declare Mirage_Preset = \"paper\";\n"
        "#declare Mirage_Tolerance = 0.5;\n"
        "#include \"mirage.inc\"\n"
        "global_settings { assumed_gamma 1.0 }\n" +
        camera +
        "\n"
        "sky_sphere { pigment { color rgb <0, 0, 1> } }\n"
        "box { <-100, 0, 30>, <100, 8, 31>\n"
        "    pigment { gradient y color_map { [0 color rgb <1, 0, 0>] [0.5 color rgb <1, 0, 0>]\n"
        "                                     [0.5 color rgb <0, 1, 0>] [1 color rgb <0, 1, 0>] } "
        "}\n"
        "    finish { ambient 1 diffuse 0 } }\n";
    if (ground)
        s += "plane { y, 0 pigment { checker color rgb 1, color rgb 0 scale 2 }\n"
             "    finish { ambient 1 diffuse 0 } }\n";
    return s;
}

// What the pixel's exact ray meets, from its own origin: straight while below the ground
// (the ground's index), then along the closed form of the exponential profile.
Shade exact_shade(const Profile& profile, const CameraRay& r, bool ground) {
    glm::dvec3 o = r.origin;
    const glm::dvec3 d = r.direction;
    if (o.y < 0.0) {
        if (d.y <= 0.0) return Shade::Blue;  // below the ground for ever: the sky's colour
        const double t = -o.y / d.y;
        o += t * d;
        o.y = 0.0;
        if (ground) {  // the plane seen from below
            const int parity =
                static_cast<int>(std::floor(o.x / 2.0 + 1e-9) + std::floor(o.z / 2.0 + 1e-9));
            return (parity & 1) ? Shade::Black : Shade::White;
        }
    }
    const double hl = std::hypot(d.x, d.z);
    auto ex = make_exact_ray(profile, o.y, std::atan2(hl, d.y));
    EXPECT_TRUE(ex.ok());
    if (!ex.ok()) return Shade::Other;
    const double hx = d.x / hl, hz = d.z / hl;
    const double dz_wall = hz > 0.0 ? (kWallZ - o.z) / hz : 1e300;
    if (ex->hits_ground && ex->dz_ground < dz_wall) {
        if (!ground) return Shade::Blue;  // on under the missing ground, straight
        const double x = o.x + ex->dz_ground * hx, z = o.z + ex->dz_ground * hz;
        const int parity =
            static_cast<int>(std::floor(x / 2.0 + 1e-9) + std::floor(z / 2.0 + 1e-9));
        return (parity & 1) ? Shade::Black : Shade::White;
    }
    if (!(hz > 0.0)) return Shade::Blue;
    const double y = height_at(*ex, dz_wall);
    if (y > kWallTop || y < 0.0) return Shade::Blue;
    return y - std::floor(y) < 0.5 ? Shade::Red : Shade::Green;
}

struct Case {
    const char* name;
    const char* camera;
    bool ground;
};

class ManyOrigins : public ::testing::TestWithParam<Case> {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_many_origins_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }
};

constexpr int kW = 80, kH = 60;

TEST_P(ManyOrigins, EveryPixelShowsWhatItsOwnExactRayMeets) {
    const Case& c = GetParam();
    const fs::path scene = dir_ / (std::string(c.name) + ".pov");
    std::ofstream(scene) << scene_text(c.camera, c.ground);
    TraceOptions o;
    o.scene = scene.string();
    o.width = kW;
    o.height = kH;
    o.progress = false;
    o.tolerance_px = 0.1;
    auto curved = trace_scene(o);
    ASSERT_TRUE(curved.ok()) << curved.message();
    EXPECT_EQ(curved->mode, PathMode::PerRay);
    EXPECT_TRUE(curved->many_origins);
    o.atmosphere = false;
    auto straight = trace_scene(o);
    ASSERT_TRUE(straight.ok()) << straight.message();

    auto loaded = load_mirage_scene(scene_load_options(scene.string(), kW, kH, {}));
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    const Profile profile = profile_in_scene_units(loaded->settings);
    // A pixel is explained when its colour is what its own exact ray meets, or what the exact
    // ray half a pixel up, down, left or right meets: the tracer keeps 0.1 px, and a pixel
    // centre that close to an edge may fall on either side of it.
    int curved_differ = 0, straight_differ = 0;
    for (int row = 0; row < kH; ++row)
        for (int col = 0; col < kW; ++col) {
            std::vector<Shade> want;
            for (const auto& [dx, dy] :
                 {std::pair{0.0, 0.0}, std::pair{0.0, -0.5}, std::pair{0.0, 0.5},
                  std::pair{-0.5, 0.0}, std::pair{0.5, 0.0}}) {
                const CameraRay r =
                    camera_ray(loaded->scene.camera, col + 0.5 + dx, row + 0.5 + dy, kW, kH);
                want.push_back(exact_shade(profile, r, c.ground));
            }
            auto explained = [&](const std::vector<float>& px) {
                const size_t p = 3 * (static_cast<size_t>(row) * kW + col);
                const Shade got = shade_of(px[p], px[p + 1], px[p + 2]);
                return std::find(want.begin(), want.end(), got) != want.end();
            };
            curved_differ += !explained(curved->render.image.pixels);
            straight_differ += !explained(straight->render.image.pixels);
        }
    const double share = static_cast<double>(curved_differ) / (kW * kH);
    const double straight_share = static_cast<double>(straight_differ) / (kW * kH);
    std::printf(
        "%s: %.2f %% of pixels show what no exact ray within half a pixel meets (straight rays "
        "%.1f %%)\n",
        c.name, 100.0 * share, 100.0 * straight_share);
    EXPECT_LT(share, 0.002);
    EXPECT_GT(straight_share, 0.08);  // the atmosphere changes much of the picture
}

INSTANTIATE_TEST_SUITE_P(
    Cameras, ManyOrigins,
    ::testing::Values(
        // Parallel rays tilted 1.7 degrees down from heights 0.5 to 2.5: the wall's
        // stripes and the ground's mirage.
        Case{"orthographic_down",
             "camera { orthographic location <0, 1.5, 0> up <0, 2, 0> right <2.4, 0, 0> "
             "look_at <0, 1.2, 10> }",
             true},
        // Rays tilted up from heights -0.4 to 1.6 over no ground: the lowest rows start
        // below the ground and bend only once they have risen to it.
        Case{"orthographic_below_ground",
             "camera { orthographic location <0, 0.6, 0> up <0, 2, 0> right <2.4, 0, 0> "
             "look_at <0, 1.0, 10> }",
             false},
        // Level rays fanned through 60 degrees from heights 0.5 to 2.5.
        Case{"cylinder3",
             "camera { cylinder 3 location <0, 1.5, 0> up y * 2 look_at <0, 1.5, 10> "
             "angle 60 }",
             true},
        // Rays fanned through 40 degrees of elevation from a level line 3 units wide.
        Case{"cylinder4",
             "camera { cylinder 4 location <0, 1.5, 0> right x * 3 look_at <0, 1.5, 10> "
             "angle 40 }",
             true}),
    [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

Camera parsed_camera(const std::string& text) {
    const fs::path p = fs::path(::testing::TempDir()) /
                       ("mirage_many_origins_cam_" + std::to_string(::getpid()) + ".pov");
    std::ofstream(p) << text << "\n";
    auto loaded = load_mirage_scene(scene_load_options(p.string(), kW, kH, {}));
    fs::remove(p);
    EXPECT_TRUE(loaded.ok()) << loaded.message();
    return loaded.ok() ? loaded->scene.camera : Camera{};
}

TEST(PixelFootprint, IsTheCamerasOwnUnitOfOnePixel) {
    // Orthographic: rows 2 / 60 and columns 2.4 / 80 apart, perpendicular to the rays.
    const Camera ortho = parsed_camera(
        "camera { orthographic location <0, 1.5, 0> up <0, 2, 0> right <2.4, 0, 0> "
        "look_at <0, 1.2, 10> }");
    auto f = pixel_footprint(ortho, kW, kH);
    ASSERT_TRUE(f.ok()) << f.message();
    EXPECT_NEAR(f->distance, 2.4 / kW, 1e-12);
    EXPECT_EQ(f->angle_rad, 0.0);
    // Cylinder 3: rows |up| / height apart.
    const Camera cyl3 =
        parsed_camera("camera { cylinder 3 location <0, 1.5, 0> up y * 2 look_at <0, 1.5, 10> }");
    f = pixel_footprint(cyl3, kW, kH);
    ASSERT_TRUE(f.ok()) << f.message();
    EXPECT_NEAR(f->distance, 2.0 / kH, 1e-12);
    EXPECT_EQ(f->angle_rad, 0.0);
    // Cylinder 4: rows the angle / height apart, from each ray's origin.
    const Camera cyl4 = parsed_camera(
        "camera { cylinder 4 location <0, 1.5, 0> right x * 3 look_at <0, 1.5, 10> angle 40 }");
    f = pixel_footprint(cyl4, kW, kH);
    ASSERT_TRUE(f.ok()) << f.message();
    EXPECT_EQ(f->distance, 0.0);
    EXPECT_NEAR(f->angle_rad, 40.0 * M_PI / 180.0 / kH, 1e-15);
    // One eye: the angle of a pixel seen from it.
    const Camera persp = parsed_camera("camera { location <0, 1.5, 0> look_at <0, 1.5, 10> }");
    f = pixel_footprint(persp, kW, kH);
    ASSERT_TRUE(f.ok()) << f.message();
    EXPECT_EQ(f->angle_rad, pixel_angle_rad(persp, kW, kH));
    // A cylinder 3 camera looking down mixes rows and columns in a ray's vertical plane.
    const Camera tilted =
        parsed_camera("camera { cylinder 3 location <0, 1.5, 0> up y * 2 look_at <0, 0.5, 10> }");
    f = pixel_footprint(tilted, kW, kH);
    ASSERT_FALSE(f.ok());
    EXPECT_NE(f.message().find("cylinder 3"), std::string::npos) << f.message();
}

TEST(PixelFootprint, TheSampledPathKeepsADistanceAcrossParallelRays) {
    // An orthographic camera's rays over the paper's desert, sampled to half a pixel of
    // 0.03 units: the polyline's height stays within 0.015 of the exact path from each
    // ray's own origin at every distance (a height error bounds the displacement
    // perpendicular to the ray), and comes near it (sampled to the tolerance, not finer).
    auto paper = preset_profile("paper");
    ASSERT_TRUE(paper.ok());
    const Camera ortho = parsed_camera(
        "camera { orthographic location <0, 1.5, 0> up <0, 2, 0> right <2.4, 0, 0> "
        "look_at <0, 1.2, 10> }");
    auto f = pixel_footprint(ortho, kW, kH);
    ASSERT_TRUE(f.ok());
    CurvedSettings cs;
    cs.atmosphere = Atmosphere::exponential(*paper);
    cs.tolerance_m = 0.5 * f->distance;
    double worst_share = 0.0;
    int sampled = 0;
    for (int row = 0; row < kH; row += 7)
        for (int col : {0, kW / 2, kW - 1}) {
            const CameraRay r = camera_ray(ortho, col + 0.5, row + 0.5, kW, kH);
            const auto cp = curved_path(cs, r.origin, r.direction, 0.0);
            ASSERT_TRUE(cp.has_value()) << row;
            ++sampled;
            const double end = cp->exact->hits_ground() ? cp->exact->dz_ground() : 200.0;
            for (int k = 0; k <= 4000; ++k) {
                const double dz = end * k / 4000.0;
                const double err = std::abs(polyline_height(cp->path, dz) - cp->exact->height_at(dz));
                EXPECT_LE(err, cs.tolerance_m * (1.0 + 1e-9)) << "row " << row << " dz " << dz;
                worst_share = std::max(worst_share, err / cs.tolerance_m);
            }
        }
    EXPECT_GT(sampled, 10);
    EXPECT_GT(worst_share, 0.1);
}

}  // namespace
}  // namespace mirage
