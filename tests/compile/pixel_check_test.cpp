#include "compile/pixel_check.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../trace/scene_builders.h"
#include "atmosphere/exact_ray.h"

namespace mirage {
namespace {

// One image column looking level at a wall D metres away, through the paper's air, with no
// layers at all: the band rays go straight, the exact ones bend.  Heights on the wall from
// the closed forms (exact_ray.h) give what the check must find.
constexpr double kEye = 1.5, kWall = 12.0, kStep = 0.004;  // m, m, rad per row
constexpr int kRows = 40;

struct Column {
    Scene scene;
    std::vector<glm::dvec3> directions;
    std::vector<double> pixel_rad;
    std::vector<double> elevation;
};

Column wall_column() {
    Column c;
    c.scene.primitives.push_back(
        testing::primitive(Box{glm::dvec3(-50.0, 0.0, kWall), glm::dvec3(50.0, 50.0, kWall + 1.0)},
                           testing::texture(testing::solid(testing::rgb(1, 1, 1)))));
    for (int row = 0; row < kRows; ++row) {
        const double e = (kRows / 2 - row - 0.5) * kStep;  // top row looks up
        c.elevation.push_back(e);
        c.directions.push_back(glm::dvec3(0.0, std::sin(e), std::cos(e)));
        c.pixel_rad.push_back(kStep);
    }
    return c;
}

ObjectQuery query(const SceneAccel& accel) {
    return [&accel](const glm::dvec3& o, const glm::dvec3& d,
                    double t_max) -> std::optional<ObjectHit> {
        auto h = accel.closest_hit(o, d, 1e-6, t_max);
        if (!h) return std::nullopt;
        return ObjectHit{h->t, h->normal, h->primitive};
    };
}

PixelCheckSettings settings() {
    PixelCheckSettings s;
    s.width = 1;
    s.height = kRows;
    s.eye = glm::dvec3(0.0, kEye, 0.0);
    s.camera_y = kEye;
    s.layers = HorizontalBox{-1e4, 1e4, -1e4, 1e4};
    s.exact_tolerance_rad = 1e-4 * kStep;
    return s;
}

TEST(PixelCheck, NoLayersAgainstTheExactRays) {
    const Profile p = *preset_profile("paper");
    Column c = wall_column();
    auto accel = SceneAccel::build(c.scene);
    ASSERT_TRUE(accel.ok()) << accel.message();
    LayerStack none;
    none.profile = p;
    none.excess = {eta_sq_excess(p, kEye)};
    PixelCheckSettings ps = settings();
    ps.atmosphere = Atmosphere::exponential(p);
    const PixelCheck pc = check_pixels(none, c.scene, *accel, query(*accel), c.directions,
                                       c.pixel_rad, std::vector<bool>(kRows, false), ps);
    // Where each model's ray meets the wall, as an angle above the level line from the eye.
    std::vector<double> straight(kRows), exact(kRows);
    for (int row = 0; row < kRows; ++row) {
        straight[row] = c.elevation[row];
        auto ray = make_exact_ray(p, kEye, M_PI / 2 - c.elevation[row]);
        ASSERT_TRUE(ray.ok());
        ASSERT_FALSE(ray->hits_ground && ray->dz_ground < kWall) << row;
        exact[row] = std::atan2(height_at(*ray, kWall) - kEye, kWall);
    }
    int shifted = 0;
    for (int row = 0; row < kRows; ++row) {
        // The angle between the two hits (the wall is flat: seen from the eye, their angles
        // differ by the difference of their elevations).
        EXPECT_NEAR(pc.seen_error_px[row], std::fabs(straight[row] - exact[row]) / kStep, 1e-3)
            << row;
        EXPECT_EQ(pc.reflection_error_px[row], 0.0f);
        // The shift: the nearest row whose exact hit is within its spacing of the straight
        // hit, found here by brute force over the closed forms.
        int want = -1;
        for (int d = 0; d < kRows && want < 0; ++d)
            for (int q : {row - d, row + d}) {
                if (q < 0 || q >= kRows) continue;
                double reach = 0.01 * kStep;
                if (q > 0) reach = std::max(reach, std::fabs(exact[q] - exact[q - 1]));
                if (q + 1 < kRows) reach = std::max(reach, std::fabs(exact[q] - exact[q + 1]));
                if (std::fabs(exact[q] - straight[row]) <= reach * (1.0 + 1e-6)) {
                    want = d;
                    break;
                }
            }
        if (want < 0) {
            EXPECT_TRUE(std::isinf(pc.shift_rows[row])) << row;
        } else {
            EXPECT_EQ(pc.shift_rows[row], static_cast<float>(want)) << row;
        }
        if (want > 0) ++shifted;
    }
    // The paper's air bends these rays by whole rows: the check is not trivially zero.
    EXPECT_GT(shifted, kRows / 4);
}

TEST(PixelCheck, StraightAirLeavesNothingToFind) {
    const Profile none_profile{};  // ProfileKind::None: the exact rays are straight too
    Column c = wall_column();
    auto accel = SceneAccel::build(c.scene);
    ASSERT_TRUE(accel.ok());
    LayerStack none;
    none.profile = none_profile;
    none.excess = {0.0};
    std::vector<bool> cut(kRows, false);
    cut[3] = true;
    const PixelCheck pc = check_pixels(none, c.scene, *accel, query(*accel), c.directions,
                                       c.pixel_rad, cut, settings());
    for (int row = 0; row < kRows; ++row) {
        if (row == 3) {
            EXPECT_TRUE(std::isinf(pc.seen_error_px[row]));
            EXPECT_TRUE(std::isinf(pc.shift_rows[row]));
            continue;
        }
        EXPECT_LT(pc.seen_error_px[row], 1e-6) << row;
        EXPECT_EQ(pc.shift_rows[row], 0.0f) << row;
    }
}

}  // namespace
}  // namespace mirage
