#include "scene/camera.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "parse_helpers.h"
#include "scene/parser.h"
#include "scene/transform.h"

namespace mirage {
namespace {

using testing::expect_vec;

CameraState apply(const CameraModifiers& mods) {
    auto result = apply_camera_statement(CameraState{}, mods);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.message());
    return result.ok() ? *result : CameraState{};
}

TEST(Camera, DefaultIsPovRaysDefaultCamera) {
    Camera c = camera_from_state(apply(CameraModifiers{}));
    expect_vec(c.location, glm::dvec3(0, 0, 0));
    expect_vec(c.direction, glm::dvec3(0, 0, 1));
    expect_vec(c.right, glm::dvec3(1.33, 0, 0));
    expect_vec(c.up, glm::dvec3(0, 1, 0));
    expect_vec(c.sky, glm::dvec3(0, 1, 0));
}

TEST(Camera, AngleSetsDirectionLengthFromRight) {
    CameraModifiers m;
    m.angle_deg = 90.0;
    // |direction| = |right| / (2 tan(45 degrees)) = 1.33 / 2.
    expect_vec(apply(m).direction, glm::dvec3(0, 0, 0.665));
    m.right = glm::dvec3(2.0, 0.0, 0.0);
    m.angle_deg = 60.0;
    expect_vec(apply(m).direction, glm::dvec3(0, 0, 1.0 / std::tan(3.14159265358979323846 / 6)),
               1e-12);
}

TEST(Camera, LookAtTurnsVectorsUsingSky) {
    CameraModifiers m;
    m.look_at = glm::dvec3(5, 0, 0);
    CameraState s = apply(m);
    // direction toward +x keeps length 1; right = sky x direction = -z, scaled by 1.33;
    // up = direction x right = +y.
    expect_vec(s.direction, glm::dvec3(1, 0, 0));
    expect_vec(s.right, glm::dvec3(0, 0, -1.33));
    expect_vec(s.up, glm::dvec3(0, 1, 0));
}

TEST(Camera, LookAtKeepsARightHandedCameraRightHanded) {
    CameraModifiers m;
    m.right = glm::dvec3(-1.33, 0, 0);
    m.look_at = glm::dvec3(5, 0, 0);
    expect_vec(apply(m).right, glm::dvec3(0, 0, 1.33));
}

TEST(Camera, ModifiersApplyInPovRaysOrderWhateverTheirOrder) {
    // look_at uses the location even when written before it (POV-Ray 3.5+).
    CameraModifiers m;
    m.look_at = glm::dvec3(0, 0, 0);
    m.location = glm::dvec3(0, 0, -4);
    m.angle_deg = 90.0;
    CameraState s = apply(m);
    expect_vec(s.location, glm::dvec3(0, 0, -4));
    expect_vec(s.direction, glm::dvec3(0, 0, 0.665));
}

TEST(Camera, TransformsMoveLocationAndTurnVectorsButNotSky) {
    CameraModifiers m;
    m.location = glm::dvec3(0, 0, -4);
    m.transform = compose_transforms(make_rotation(glm::dvec3(0, 90, 0)),
                                     make_translation(glm::dvec3(0, 1, 0)));
    CameraState s = apply(m);
    expect_vec(s.location, glm::dvec3(-4, 1, 0));
    expect_vec(s.direction, glm::dvec3(1, 0, 0));
    expect_vec(s.right, glm::dvec3(0, 0, -1.33));
    expect_vec(s.sky, glm::dvec3(0, 1, 0));
}

TEST(Camera, Errors) {
    CameraModifiers same;
    same.look_at = glm::dvec3(0, 0, 0);
    auto r = apply_camera_statement(CameraState{}, same);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), "the camera location and look_at point must be different");
    CameraModifiers wide;
    wide.angle_deg = 180.0;
    EXPECT_FALSE(apply_camera_statement(CameraState{}, wide).ok());
}

TEST(Camera, PerpendicularityCheck) {
    CameraState s;
    EXPECT_TRUE(camera_vectors_perpendicular(s));
    s.up = glm::dvec3(0, 1, 0.1);
    EXPECT_FALSE(camera_vectors_perpendicular(s));
}

TEST(CameraRay, PixelCentresOfATwoByTwoImage) {
    Camera c;  // the default camera
    // Top-left pixel centre (0.5, 0.5): x0 = -1/4, y0 = +1/4.
    CameraRay r = camera_ray(c, 0.5, 0.5, 2, 2);
    expect_vec(r.origin, glm::dvec3(0, 0, 0));
    expect_vec(r.direction, glm::normalize(glm::dvec3(-0.25 * 1.33, 0.25, 1.0)));
    // Bottom-right pixel centre: the mirror image.
    expect_vec(camera_ray(c, 1.5, 1.5, 2, 2).direction,
               glm::normalize(glm::dvec3(0.25 * 1.33, -0.25, 1.0)));
    // The image centre looks along direction; the corner along direction +- right/2 +- up/2.
    expect_vec(camera_ray(c, 1.0, 1.0, 2, 2).direction, glm::dvec3(0, 0, 1));
    expect_vec(camera_ray(c, 0.0, 2.0, 2, 2).direction,
               glm::normalize(glm::dvec3(-0.665, -0.5, 1.0)));
}

// ---------------------------------------------------------------------------------------
// Against POV-Ray itself.  Each camera_rays_*.pov scene puts a unit sphere around the eye whose
// colour is 1/4 + d/4 for the ray direction d that meets it (direction_sphere.inc); POV-Ray
// 3.7.0.10 rendered it into the 16-bit linear PNG next to it (the command is in the .pov).
// The scene is parsed here (leniently: its pigment uses average and function patterns) and
// every pixel's ray compared with what POV-Ray traced.

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
};

Image read_image(const std::string& path) {
    Image image;
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        ADD_FAILURE() << "cannot open " << path;
        return image;
    }
    const OIIO::ImageSpec& spec = in->spec();
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    image.pixels.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data());
    return image;
}

// The largest difference between POV-Ray's encoded directions and ours, with our rays taken
// at (col + 0.5 + shift, row + 0.5 + shift).
double max_direction_error(const std::string& name, double shift = 0.0) {
    Image image = read_image(testing::data_dir() + "/" + name + ".png");
    ParseOptions options;
    options.strict = false;
    options.image_width = image.width;
    options.image_height = image.height;
    auto scene = parse_scene_file(testing::data_dir() + "/" + name + ".pov", options);
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.message());
    if (!scene.ok() || image.pixels.empty()) return 1e9;
    double worst = 0.0;
    for (int row = 0; row < image.height; ++row) {
        for (int col = 0; col < image.width; ++col) {
            CameraRay ray = camera_ray(scene->camera, col + 0.5 + shift, row + 0.5 + shift,
                                       image.width, image.height);
            const float* px =
                &image.pixels[(static_cast<std::size_t>(row) * image.width + col) * image.channels];
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(px[c] - (0.25 + ray.direction[c] / 4.0)));
            }
        }
    }
    return worst;
}

// Half a 16-bit step is 7.6e-6; a half-pixel error is 2.7e-3 or more in these images.
constexpr double kDirectionTolerance = 2e-5;

TEST(CameraAgainstPovRay, LookAtAngleAndAspectRight) {
    EXPECT_LT(max_direction_error("camera_rays_look_at"), kDirectionTolerance);
    EXPECT_GT(max_direction_error("camera_rays_look_at", 0.5), 20 * kDirectionTolerance);
}

TEST(CameraAgainstPovRay, TiltedSkyRightHandedDirectionAndRotation) {
    EXPECT_LT(max_direction_error("camera_rays_tilted"), kDirectionTolerance);
    EXPECT_GT(max_direction_error("camera_rays_tilted", 0.5), 20 * kDirectionTolerance);
}

TEST(CameraAgainstPovRay, DefaultCameraOnASquareImage) {
    EXPECT_LT(max_direction_error("camera_rays_default"), kDirectionTolerance);
    EXPECT_GT(max_direction_error("camera_rays_default", -0.5), 20 * kDirectionTolerance);
}

}  // namespace
}  // namespace mirage
