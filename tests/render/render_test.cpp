#include "render/render.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>

#include "image/image_io.h"
#include "trace/scene_builders.h"

namespace mirage {
namespace {

using namespace mirage::testing;

Scene small_scene() {
    Scene s;
    s.camera = look_at_camera({0.0, 1.5, -5.0}, {0.0, 0.8, 0.0});
    s.lights.push_back(light({-3.0, 6.0, -4.0}));
    s.lights.push_back(light({4.0, 3.0, -2.0}, glm::dvec3(0.4)));
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0},
                                     texture(checker(rgb(0.9, 0.9, 0.9), rgb(0.2, 0.3, 0.5)))));
    Finish shiny;
    shiny.reflection = glm::dvec3(0.4);
    shiny.specular = 0.5;
    s.primitives.push_back(
        primitive(Sphere{{0.0, 1.0, 0.0}, 1.0}, texture(solid(rgb(0.8, 0.2, 0.1)), shiny)));
    s.primitives.push_back(
        primitive(Box{{1.2, 0.0, -0.5}, {2.0, 0.8, 0.5}}, texture(solid(rgb(0.1, 0.7, 0.2)))));
    SkySphere sky;
    sky.pigments.push_back(
        gradient({0, 1, 0}, {{0.0, rgb(0.9, 0.9, 1.0)}, {1.0, rgb(0.2, 0.3, 0.8)}}));
    s.sky_sphere = sky;
    return s;
}

RenderSettings settings(int threads, int tile) {
    RenderSettings r;
    r.width = 97;  // not a multiple of the tiles
    r.height = 61;
    r.threads = threads;
    r.tile_size = tile;
    r.progress = false;
    return r;
}

TEST(Render, SameBytesWhateverTheThreadsAndTiles) {
    const Scene s = small_scene();
    auto reference = render(s, settings(1, 32));
    ASSERT_TRUE(reference.ok()) << reference.message();
    for (const auto& [threads, tile] :
         {std::pair{2, 32}, std::pair{3, 7}, std::pair{8, 1}, std::pair{0, 16}}) {
        auto other = render(s, settings(threads, tile));
        ASSERT_TRUE(other.ok());
        ASSERT_EQ(other->image.pixels.size(), reference->image.pixels.size());
        EXPECT_EQ(std::memcmp(other->image.pixels.data(), reference->image.pixels.data(),
                              reference->image.pixels.size() * sizeof(float)),
                  0)
            << threads << " threads, tiles of " << tile;
        EXPECT_EQ(other->stats.counters.reflected_rays, reference->stats.counters.reflected_rays);
        EXPECT_EQ(other->stats.counters.shadow_rays, reference->stats.counters.shadow_rays);
    }
}

TEST(Render, CountsRaysAndSegments) {
    auto r = render(small_scene(), settings(2, 16));
    ASSERT_TRUE(r.ok());
    const RenderStats& st = r->stats;
    EXPECT_EQ(st.counters.camera_rays, 97u * 61u);
    EXPECT_GT(st.counters.reflected_rays, 0u);
    EXPECT_GT(st.counters.shadow_rays, 0u);
    EXPECT_EQ(st.counters.segments, st.rays());  // straight rays: one segment each
    EXPECT_DOUBLE_EQ(st.segments_per_ray(), 1.0);
    EXPECT_EQ(st.threads, 2);
    EXPECT_GT(st.seconds, 0.0);
    EXPECT_GT(st.mrays_per_second(), 0.0);
    const std::string line = format_stats(st, 97, 61);
    EXPECT_NE(line.find("97x61: "), std::string::npos);
    EXPECT_NE(line.find("Mrays/s on 2 threads"), std::string::npos);
}

/// A propagator that records how many rays it followed and delegates to straight rays.
class CountingPropagator final : public Propagator {
  public:
    PathHit propagate(const SceneAccel& accel, const RayStart& start) const override {
        ++calls;
        PathHit p = straight_.propagate(accel, start);
        p.segments = 3;  // pretend to bend
        return p;
    }
    mutable std::atomic<long> calls{0};

  private:
    StraightPropagator straight_;
};

TEST(Render, CameraAndReflectedRaysGoThroughThePropagatorShadowRaysDoNot) {
    CountingPropagator counting;
    auto r = render(small_scene(), settings(2, 16), counting);
    ASSERT_TRUE(r.ok());
    const auto& c = r->stats.counters;
    EXPECT_EQ(counting.calls.load(), static_cast<long>(c.camera_rays + c.reflected_rays));
    EXPECT_EQ(c.segments, 3u * (c.camera_rays + c.reflected_rays));
    EXPECT_DOUBLE_EQ(r->stats.segments_per_ray(), 3.0);
    // Same paths, so the same picture as straight rays.
    auto straight = render(small_scene(), settings(2, 16));
    EXPECT_EQ(r->image.pixels, straight->image.pixels);
}

TEST(Render, UsesThePixelRayFunctionGiven) {
    // A camera function that looks straight up from everywhere: the image is the sky's zenith.
    const Scene s = small_scene();
    const StraightPropagator straight;
    auto r = render(s, settings(1, 32), straight, [](const Camera&, double, double, int, int) {
        return CameraRay{glm::dvec3(0.0, 5.0, 0.0), glm::dvec3(0.0, 1.0, 0.0)};
    });
    ASSERT_TRUE(r.ok());
    const glm::vec3 zenith = r->image.at(0, 0);
    EXPECT_NEAR(zenith.x, static_cast<float>(0.2f), 1e-6);
    EXPECT_EQ(r->image.at(96, 60), zenith);
}

TEST(Render, RefusesBadSizes) {
    RenderSettings bad = settings(1, 32);
    bad.width = 0;
    auto r = render(small_scene(), bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), "image size must be positive, got 0x61");
}

TEST(Render, RefusesADegenerateCamera) {
    Scene s = small_scene();
    s.camera.direction = glm::dvec3(0.0);
    s.camera.right = glm::dvec3(0.0);
    s.camera.up = glm::dvec3(0.0);
    s.camera.loc = FileLoc{"cam.pov", 2, 1};
    auto r = render(s, settings(1, 32));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message().rfind("cam.pov:2:1: camera: its vectors give no ray direction", 0), 0u);
}

TEST(Render, NoProgressBarWhenStderrIsNotATerminal) {
    RenderSettings s = settings(2, 8);
    s.progress = true;
    ::testing::internal::CaptureStderr();
    auto r = render(small_scene(), s);
    const std::string err = ::testing::internal::GetCapturedStderr();
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(err, "");
}

}  // namespace
}  // namespace mirage
