// The tracer's paths sampled near surfaces (PathSampling::NearSurfaces, the default) against
// the reference sampling (every ray to the tolerance all along), on every shipped scene and
// on random cameras.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "load/mirage_scene.h"
#include "scene/camera.h"
#include "scene/parser.h"
#include "trace/curved_propagator.h"
#include "render/render.h"
#include "trace/scene_accel.h"

namespace mirage {
namespace {

/// The shipped scenes (scenes/*.pov).  Fewer than three fails the test that asks: every test
/// here loops over them, and over none it would check nothing.
std::vector<std::string> shipped_scenes() {
    const std::string dir = std::string(MIRAGE_SOURCE_DIR) + "/scenes";
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        if (e.path().extension() == ".pov") names.push_back(e.path().string());
    }
    std::sort(names.begin(), names.end());
    EXPECT_GE(names.size(), 3u) << "scenes in " << dir;
    return names;
}

struct Loaded {
    Scene scene;
    Profile profile;
    double tolerance_px = 0.5;
    MirageSettings settings;
};

Loaded load(const std::string& path, int width, int height) {
    auto loaded = load_mirage_scene(scene_load_options(path, width, height, {}));
    EXPECT_TRUE(loaded.ok()) << loaded.message();
    EXPECT_TRUE(loaded->settings.declared) << path;
    Loaded l{std::move(loaded->scene), profile_in_scene_units(loaded->settings),
             loaded->settings.tolerance_px, loaded->settings};
    return l;
}

CurvedSettings curved(const Loaded& l, int width, int height, PathSampling sampling) {
    CurvedSettings s;
    s.atmosphere = Atmosphere::exponential(l.profile);
    s.tolerance_rad = l.tolerance_px * pixel_angle_rad(l.scene.camera, width, height);
    s.sampling = sampling;
    s.eye = l.scene.camera.location;
    if (l.settings.air) {
        // Real air: the general engine's paths, followed to twice the scene's reach (as
        // `mirage trace` does), with or without the scene at hand.
        auto atmosphere = scene_atmosphere(l.settings, s.tolerance_rad);
        EXPECT_TRUE(atmosphere.ok()) << atmosphere.message();
        if (atmosphere.ok()) s.atmosphere = *atmosphere;
        auto accel = SceneAccel::build(l.scene);
        EXPECT_TRUE(accel.ok()) << accel.message();
        if (accel.ok()) s.max_dz = general_path_reach(*accel, l.scene.camera.location);
    }
    return s;
}

/// A camera near the scene's own: the eye moved about and up or down, turned by up to 30
/// degrees in azimuth and a few fields of view in elevation, the field of view widened up to
/// five times.
Camera random_camera(const Camera& base, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double h = std::max(base.location.y, 0.1);
    CameraState st;
    st.location = base.location;
    st.direction = base.direction;
    st.up = base.up;
    st.right = base.right;
    st.sky = base.sky;
    st.look_at = base.location + base.direction;
    const double field =
        2.0 * std::atan(0.5 * glm::length(base.right) / glm::length(base.direction));  // rad
    CameraModifiers m;
    m.location = base.location + glm::dvec3((unit(rng) - 0.5) * 4.0 * h,
                                            h * (0.5 + 1.5 * unit(rng)) - base.location.y,
                                            (unit(rng) - 0.5) * 4.0 * h);
    const glm::dvec3 d = glm::normalize(base.direction);
    const double yaw = (unit(rng) - 0.5) * 60.0 * M_PI / 180.0;
    const double pitch = std::asin(std::clamp(d.y, -1.0, 1.0)) + (unit(rng) - 0.5) * field;
    const double az = std::atan2(d.x, d.z) + yaw;
    const glm::dvec3 look(std::cos(pitch) * std::sin(az), std::sin(pitch),
                          std::cos(pitch) * std::cos(az));
    m.look_at = *m.location + 100.0 * h * look;
    m.angle_deg = std::min(field * (1.0 + 4.0 * unit(rng)), 1.2) * 180.0 / M_PI;
    auto applied = apply_camera_statement(st, m);
    EXPECT_TRUE(applied.ok()) << applied.message();
    return camera_from_state(*applied);
}

/// Whether every pixel of `a` finds its colour (each channel within `tol`) in `b` within
/// `radius` pixels; the pixels that do not are counted.
int pixels_not_found(const Image& a, const Image& b, int radius, float tol) {
    int missing = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const glm::vec3 c = a.at(x, y);
            bool found = false;
            for (int v = std::max(0, y - radius); v <= std::min(b.height - 1, y + radius) && !found;
                 ++v) {
                for (int u = std::max(0, x - radius); u <= std::min(b.width - 1, x + radius); ++u) {
                    const glm::vec3 d = glm::abs(b.at(u, v) - c);
                    if (d.x <= tol && d.y <= tol && d.z <= tol) {
                        found = true;
                        break;
                    }
                }
            }
            if (!found) {
                ++missing;
            }
        }
    }
    return missing;
}

RenderResult render_with(const Scene& scene, int width, int height, const CurvedSettings& s,
                         int threads = 0) {
    RenderSettings rs;
    rs.width = width;
    rs.height = height;
    rs.progress = false;
    rs.threads = threads;
    auto r = render(scene, rs, CurvedPropagator(s));
    EXPECT_TRUE(r.ok()) << r.message();
    return std::move(*r);
}

// Both samplings keep every path within the tolerance of the exact one, so a pixel's colour
// lies in the other image at most twice the tolerance away, plus one pixel for the grid
// (each channel within 0.1): anything the near-surface sampling missed (a clear stretch that
// was not clear) would show as a colour the reference has nowhere near.  On the shipped
// cameras every pixel finds its colour.  From random cameras an isolated pixel may not: the
// sharp highlights and reflections of the desert's spheres peak between pixel centres.
// Measured at 160x120: up to 2 of 19200 (on the walk), 1 on the desert as for the reference
// against itself at half its tolerance (also within the bound); at 64x48 up to 5 of 3072
// (the reference against itself: 2).  They may be 1 in 2000.
void expect_same_within_the_tolerance(const Scene& scene, const Loaded& l, int width, int height,
                                      bool every_pixel, const std::string& what) {
    const RenderResult near =
        render_with(scene, width, height, curved(l, width, height, PathSampling::NearSurfaces));
    const RenderResult ref =
        render_with(scene, width, height, curved(l, width, height, PathSampling::Reference));
    const int radius = static_cast<int>(std::ceil(2.0 * l.tolerance_px)) + 1;
    const int a = pixels_not_found(near.image, ref.image, radius, 0.1f);
    const int b = pixels_not_found(ref.image, near.image, radius, 0.1f);
    int same = 0;
    for (std::size_t k = 0; k < near.image.pixels.size(); ++k)
        same += near.image.pixels[k] == ref.image.pixels[k];
    std::printf(
        "%s %dx%d: %.2f %% of the channels identical; not found within %d px: %d and %d; "
        "segments tested per ray %.2f (reference %.2f)\n",
        what.c_str(), width, height, 100.0 * same / near.image.pixels.size(), radius, a, b,
        near.stats.queries_per_ray(), ref.stats.queries_per_ray());
    const int allowed = every_pixel ? 0 : width * height / 2000;
    EXPECT_LE(a, allowed) << what;
    EXPECT_LE(b, allowed) << what;
    EXPECT_LE(near.stats.queries_per_ray(), ref.stats.queries_per_ray()) << what;
}

TEST(NearSampling, EveryShippedSceneIsTheReferenceWithinTheTolerance) {
    for (const std::string& path : shipped_scenes()) {
        const int w = 120, h = 90;
        const Loaded l = load(path, w, h);
        expect_same_within_the_tolerance(l.scene, l, w, h, true,
                                         std::filesystem::path(path).stem().string());
    }
}

TEST(NearSampling, RandomCamerasAreTheReferenceWithinTheTolerance) {
    std::mt19937_64 rng(11);
    for (const std::string& path : shipped_scenes()) {
        const int w = 160, h = 120;
        Loaded l = load(path, w, h);
        const Camera base = l.scene.camera;
        for (int k = 0; k < 3; ++k) {
            l.scene.camera = random_camera(base, rng);
            expect_same_within_the_tolerance(
                l.scene, l, w, h, false,
                std::filesystem::path(path).stem().string() + " camera " + std::to_string(k));
        }
    }
}

// The near-surface sampling finds the first hit of the same sampler told nothing of the
// scene: the stretches it leaves coarse hold nothing.  Camera rays through the eye's index
// and rays from other points (reflections) through the hierarchy, on every scene from random
// eyes in random directions.
TEST(NearSampling, HitsAreThoseOfTheSamePathsSampledToTheToleranceAllAlong) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0, rays = 0;
    for (const std::string& path : shipped_scenes()) {
        const int w = 64, h = 48;
        Loaded l = load(path, w, h);
        auto accel = SceneAccel::build(l.scene);
        ASSERT_TRUE(accel.ok()) << accel.message();
        for (int k = 0; k < 4; ++k) {
            const Camera cam = random_camera(l.scene.camera, rng);
            l.scene.camera = cam;
            CurvedSettings s = curved(l, w, h, PathSampling::NearSurfaces);
            for (const bool from_eye : {true, false}) {
                s.eye = from_eye ? std::optional(cam.location) : std::nullopt;
                const CurvedPropagator near(s);
                for (int j = 0; j < 400; ++j) {
                    const CameraRay cr = camera_ray(cam, w * unit(rng), h * unit(rng), w, h);
                    RayStart start;
                    start.origin = cr.origin;
                    start.direction = cr.direction;
                    const PathHit got = near.propagate(*accel, start);
                    const auto full = curved_path(s, cr.origin, cr.direction, 0.0);
                    const PathHit want = full ? march_curved_path(*accel, cr.origin, *full)
                                              : StraightPropagator().propagate(*accel, start);
                    const std::string what = path + " camera " + std::to_string(k) + " ray " +
                                             std::to_string(j) + (from_eye ? " (eye)" : "");
                    ASSERT_EQ(got.hit, want.hit) << what;
                    ++rays;
                    if (!want.hit) {
                        EXPECT_NEAR(glm::length(got.direction - want.direction), 0.0, 1e-12)
                            << what;
                        continue;
                    }
                    ++hits;
                    EXPECT_EQ(got.surface.primitive, want.surface.primitive) << what;
                    EXPECT_NEAR(glm::length(got.surface.point - want.surface.point), 0.0,
                                1e-9 * (1.0 + want.length))
                        << what;
                    // The path length (which sets a reflection's allowance, an angle seen from
                    // the eye): the clear stretches' arcs estimated, the others' chords.
                    EXPECT_NEAR(got.length, want.length, 1e-3 * want.length) << what;
                    EXPECT_LE(got.queries, want.queries) << what;
                }
            }
        }
    }
    EXPECT_EQ(rays, static_cast<int>(shipped_scenes().size()) * 4 * 2 * 400);
    EXPECT_GT(hits, rays / 4);
}

TEST(NearSampling, SameBytesAtAnyThreadCount) {
    for (const std::string& path : shipped_scenes()) {
        const int w = 80, h = 60;
        const Loaded l = load(path, w, h);
        for (const PathSampling sampling : {PathSampling::NearSurfaces, PathSampling::Reference}) {
            const CurvedSettings s = curved(l, w, h, sampling);
            const RenderResult one = render_with(l.scene, w, h, s, 1);
            for (const int threads : {2, 3}) {
                const RenderResult many = render_with(l.scene, w, h, s, threads);
                EXPECT_TRUE(one.image.pixels == many.image.pixels)
                    << path << " with " << threads << " threads";
                EXPECT_EQ(one.stats.counters.segments, many.stats.counters.segments) << path;
            }
        }
    }
}

}  // namespace
}  // namespace mirage
