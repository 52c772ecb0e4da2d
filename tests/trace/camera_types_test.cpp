// POV-Ray's projections other than the perspective one: their rays against closed forms and
// their images against POV-Ray's.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera.h"
#include "scene/parser.h"
#include "shapes_parity_test.h"

namespace mirage {
namespace {

Camera parse_camera(const std::string& text) {
    auto s = parse_scene_text(text, "scene.pov", ParseOptions{});
    EXPECT_TRUE(s.ok()) << s.message();
    return s.ok() ? s->camera : Camera{};
}

TEST(CameraTypes, OrthographicRaysAreParallelFromTheImagePlane) {
    // Without up and right, POV-Ray scales them to the area a perspective camera sees at the
    // look_at distance: here 5 units away, angle 90 -> right 10 wide (|right| 1.33 * 5 / 0.665).
    const Camera c =
        parse_camera("camera { orthographic location <0, 0, -5> look_at <0, 0, 0> angle 90 }");
    EXPECT_EQ(c.type, CameraType::Orthographic);
    const CameraRay centre = camera_ray(c, 80.0, 60.0, 160, 120);
    EXPECT_NEAR(glm::length(centre.direction - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
    const CameraRay corner = camera_ray(c, 0.0, 0.0, 160, 120);
    EXPECT_NEAR(glm::length(corner.direction - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
    // The left edge lies half the width to the left: |right| / 2 = 5 (tan 45 = 1).
    EXPECT_NEAR(corner.origin.x, -5.0, 1e-9);
    EXPECT_FALSE(camera_has_one_viewpoint(c));
}

TEST(CameraTypes, FisheyeHasNoRayOutsideItsCircleAndLooksSidewaysAtItsRim) {
    const Camera c = parse_camera(
        "camera { fisheye location 0 look_at z angle 180 right x up y }");  // a square frame
    EXPECT_FALSE(camera_ray(c, 0.5, 0.5, 100, 100).traced);
    const CameraRay rim = camera_ray(c, 100.0, 50.0, 100, 100);  // right edge, on the axis
    EXPECT_TRUE(rim.traced);
    EXPECT_NEAR(rim.direction.x, 1.0, 1e-9);  // 90 degrees off the axis
    EXPECT_TRUE(camera_has_one_viewpoint(c));
}

TEST(CameraTypes, PanoramicSpansHalfATurnAcross) {
    const Camera c = parse_camera("camera { panoramic location 0 look_at z }");
    // The left edge looks along -right, the right edge along +right (x from 0 to 1 maps to an
    // angle from pi to 0).
    EXPECT_NEAR(camera_ray(c, 0.0, 60.0, 160, 120).direction.x, -1.0, 1e-9);
    EXPECT_NEAR(camera_ray(c, 160.0, 60.0, 160, 120).direction.x, 1.0, 1e-9);
    EXPECT_NEAR(camera_ray(c, 80.0, 60.0, 160, 120).direction.z, 1.0, 1e-9);
}

TEST(CameraTypes, CylinderThreeMovesTheOriginUpTheAxis) {
    const Camera c =
        parse_camera("camera { cylinder 3 location <0, 1, 0> look_at <0, 1, 1> angle 90 }");
    const CameraRay top = camera_ray(c, 80.0, 1.0, 160, 120);
    const CameraRay bottom = camera_ray(c, 80.0, 121.0, 160, 120);
    EXPECT_NEAR(top.direction.y, 0.0, 1e-12);
    EXPECT_GT(top.origin.y, bottom.origin.y);
}

TEST(CameraTypes, AnUnknownCylinderTypeIsRefused) {
    auto s = parse_scene_text("camera { cylinder 5 }", "scene.pov", ParseOptions{});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message().rfind("scene.pov:1:19: cylinder camera type 5", 0), 0u) << s.message();
}

class CameraParity : public ::testing::TestWithParam<const char*> {};

TEST_P(CameraParity, MatchesPovRay) {
    if (!testing::povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const std::string projection = GetParam();
    std::string name = projection;
    for (char& ch : name) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    }
    const std::string text = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\ncamera { " +
                             projection + R"( location <0, 2, -5> look_at <0, 1, 0> }
light_source { <-5, 10, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.2, 0.1> } finish { phong 0.5 } }
box { <-3, 0, 1>, <-2, 2, 2> pigment { rgb <0.1, 0.8, 0.3> } }
cylinder { <2, 0, -1>, <2, 3, -1>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } }
)";
    EXPECT_GE(testing::parity_psnr("camera_parity", name, text, 160, 120), 40.0);
}

INSTANTIATE_TEST_SUITE_P(Projections, CameraParity,
                         ::testing::Values("orthographic", "fisheye angle 180",
                                           "ultra_wide_angle angle 120", "panoramic",
                                           "cylinder 1 angle 120", "cylinder 4 angle 90",
                                           "spherical angle 270, 120", "omnimax angle 180"));

}  // namespace
}  // namespace mirage
