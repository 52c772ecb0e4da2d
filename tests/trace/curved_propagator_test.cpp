#include "trace/curved_propagator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "recording_propagator.h"
#include "scene/camera.h"
#include "scene_builders.h"
#include "shading/shading.h"

namespace mirage {
namespace {

using namespace mirage::testing;

constexpr double kDeg = M_PI / 180.0;

SceneAccel build(const Scene& s) {
    auto accel = SceneAccel::build(s);
    EXPECT_TRUE(accel.ok()) << accel.message();
    return std::move(*accel);
}

Profile paper() { return *preset_profile("paper"); }

CurvedSettings settings(const Profile& p, double tolerance_rad) {
    CurvedSettings s;
    s.atmosphere = Atmosphere::exponential(p);
    s.tolerance_rad = tolerance_rad;
    return s;
}

glm::dvec3 direction(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * kDeg;
    const double a = azimuth_deg * kDeg;
    return glm::dvec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
}

/// The exact ray of a start and direction, as the propagator must follow it.
ExactRay exact(const Profile& p, const glm::dvec3& origin, const glm::dvec3& d) {
    auto r = make_exact_ray(p, origin.y, std::atan2(std::hypot(d.x, d.z), d.y));
    EXPECT_TRUE(r.ok());
    return *r;
}

double horizontal_distance(const glm::dvec3& a, const glm::dvec3& b) {
    return std::hypot(a.x - b.x, a.z - b.z);
}

/// Checks a hit on a vertical screen against the exact path: the hit lies in the ray's
/// vertical plane, and its height is within the sampler's allowance of the exact height at
/// the same horizontal distance.  Returns the error as a fraction of the allowance, and in
/// `straight_error` that of a straight ray (to show the paths do bend).
double screen_error(const Profile& p, double tolerance_rad, const glm::dvec3& origin,
                    const glm::dvec3& d, double travelled, const PathHit& hit,
                    double* straight_error = nullptr) {
    const ExactRay ray = exact(p, origin, d);
    const glm::dvec3& q = hit.surface.point;
    const double dz = horizontal_distance(q, origin);
    // In the vertical plane of the start direction.
    const glm::dvec2 h = glm::normalize(glm::dvec2(d.x, d.z));
    EXPECT_NEAR(h.x * (q.z - origin.z) - h.y * (q.x - origin.x), 0.0, 1e-9 * (1.0 + dz));
    const double y = height_at(ray, dz);
    SampleSettings ss;
    ss.tolerance_rad = tolerance_rad;
    ss.start_distance = travelled;
    const double allowance = allowed_error(ray, ss, dz, y) + 1e-9 * (1.0 + dz);
    if (straight_error) {
        const double straight_y = origin.y + dz * d.y / std::hypot(d.x, d.z);
        *straight_error = std::abs(straight_y - y) / allowance;
    }
    return std::abs(q.y - y) / allowance;
}

TEST(CurvedPropagator, HitsOnAVerticalScreenMatchTheExactPathWithinTheTolerance) {
    const Profile p = paper();
    for (const double tolerance : {1e-2, 1e-3, 1e-4}) {
        const CurvedPropagator curved(settings(p, tolerance));
        for (const double screen_z : {4.0, 25.0, 300.0}) {
            Scene s;
            s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, screen_z}, Texture{}));
            const SceneAccel accel = build(s);
            const glm::dvec3 eye(0.3, 1.5, 0.0);
            double worst = 0.0;
            double most_bent = 0.0;
            int checked = 0;
            for (double e = -23.0; e <= 23.0; e += 0.37) {
                for (const double a : {-35.0, -10.0, 0.0, 20.0}) {
                    const glm::dvec3 d = direction(e, a);
                    const ExactRay ray = exact(p, eye, d);
                    const PathHit hit = curved.propagate(accel, {eye, d});
                    ASSERT_TRUE(hit.hit) << e << " " << a;
                    const double dz = horizontal_distance(hit.surface.point, eye);
                    // Past the exact ground hit the path has left the atmosphere (no ground
                    // object here: it goes on straight below y = 0).
                    if (ray.hits_ground && dz >= ray.dz_ground) continue;
                    double straight = 0.0;
                    const double err = screen_error(p, tolerance, eye, d, 0.0, hit, &straight);
                    EXPECT_LE(err, 1.0) << "tolerance " << tolerance << " screen " << screen_z
                                        << " elevation " << e << " azimuth " << a;
                    worst = std::max(worst, err);
                    most_bent = std::max(most_bent, straight);
                    ++checked;
                }
            }
            EXPECT_GT(checked, 200);
            // The paths do bend, by far more than the tolerance: a straight ray would fail.
            EXPECT_GT(most_bent, 10.0) << tolerance << " " << screen_z;
            std::printf(
                "tolerance %g rad, screen at %g: largest error %.3f of the allowance, "
                "straight rays %.0f\n",
                tolerance, screen_z, worst, most_bent);
        }
    }
}

TEST(CurvedPropagator, GroundHitsAreTheExactGroundPoints) {
    for (const char* preset : {"paper", "paper-superior"}) {
        const Profile p = *preset_profile(preset);
        const double tolerance = 5e-4;
        const CurvedPropagator curved(settings(p, tolerance));
        Scene s;
        s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, Texture{}));
        const SceneAccel accel = build(s);
        const glm::dvec3 eye(-1.0, 1.5, 2.0);
        int grounded = 0, escaped = 0;
        for (double e = -60.0; e <= 10.0; e += 0.25) {
            const glm::dvec3 d = direction(e, 33.0);
            const ExactRay ray = exact(p, eye, d);
            const PathHit hit = curved.propagate(accel, {eye, d});
            if (ray.hits_ground) {
                ASSERT_TRUE(hit.hit) << preset << " " << e;
                const double dz = horizontal_distance(hit.surface.point, eye);
                EXPECT_NEAR(dz, ray.dz_ground, 1e-9 * (1.0 + ray.dz_ground)) << preset << " " << e;
                EXPECT_NEAR(hit.surface.point.y, 0.0, 1e-9);
                // The direction of arrival is the last segment's, within the tolerance of
                // the exact tangent (a chord of the path seen from its end).
                const double slope = hit.direction.y / std::hypot(hit.direction.x, hit.direction.z);
                EXPECT_LT(slope, 0.0);
                ++grounded;
            } else {
                // Escapes: the sky is looked up along the exact asymptotic direction.
                ASSERT_FALSE(hit.hit) << preset << " " << e;
                const double slope = hit.direction.y / std::hypot(hit.direction.x, hit.direction.z);
                EXPECT_NEAR(slope, asymptotic_slope(ray), 1e-12 * (1.0 + std::abs(slope)))
                    << preset << " " << e;
                // Nothing but the ground in the scene: the escaping path is its start and the
                // asymptote's straight end, never tested against the scene.
                EXPECT_EQ(hit.segments, 1) << preset << " " << e;
                EXPECT_EQ(hit.queries, 0) << preset << " " << e;
                ++escaped;
            }
        }
        EXPECT_GT(grounded, 20) << preset;
        if (p.kind == ProfileKind::Inferior) {
            EXPECT_GT(escaped, 20);
        }
    }
}

TEST(CurvedPropagator, TrappedSuperiorRaysComeBackToTheGround) {
    const Profile p = *preset_profile("paper-superior");
    const CurvedPropagator curved(settings(p, 1e-3));
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, Texture{}));
    const SceneAccel accel = build(s);
    const glm::dvec3 eye(0.0, 1.0, 0.0);
    int trapped = 0;
    for (double e = 0.5; e <= 30.0; e += 0.5) {
        const glm::dvec3 d = direction(e, -70.0);
        const ExactRay ray = exact(p, eye, d);
        if (ray.ray_class != RayClass::SupTrappedUp) continue;
        const PathHit hit = curved.propagate(accel, {eye, d});
        ASSERT_TRUE(hit.hit) << e;
        EXPECT_NEAR(horizontal_distance(hit.surface.point, eye), ray.dz_ground,
                    1e-9 * (1.0 + ray.dz_ground));
        ++trapped;
    }
    EXPECT_GT(trapped, 5);
}

TEST(CurvedPropagator, WithoutAGroundObjectARayGoesOnAlongTheExactTangent) {
    const Profile p = paper();
    const CurvedPropagator curved(settings(p, 1e-3));
    Scene s;  // nothing to hit
    const SceneAccel accel = build(s);
    const glm::dvec3 eye(0.0, 1.5, 0.0);
    const glm::dvec3 d = direction(-40.0, 0.0);
    const ExactRay ray = exact(p, eye, d);
    ASSERT_TRUE(ray.hits_ground);
    const PathHit hit = curved.propagate(accel, {eye, d});
    EXPECT_FALSE(hit.hit);
    const glm::dvec3 tangent = glm::normalize(glm::dvec3(0.0, slope_at(ray, ray.dz_ground), 1.0));
    EXPECT_NEAR(glm::length(hit.direction - tangent), 0.0, 1e-15);
}

TEST(CurvedPropagator, ReflectedRaysFollowTheirOwnPathsFromTheEyesDistance) {
    // A ray starting at a reflection point, travelled metres from the eye: its path is the
    // exact ray from that point and direction, within an allowance that grows with the
    // distance already travelled (an angle seen from the eye), so it needs fewer segments.
    const Profile p = paper();
    const double tolerance = 2e-4;
    const CurvedPropagator curved(settings(p, tolerance));
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, -30.0}, Texture{}));
    const SceneAccel accel = build(s);
    const glm::dvec3 start(1.0, 0.8, 12.0);
    int fewer = 0;
    for (double e = -8.0; e <= 20.0; e += 0.5) {
        const glm::dvec3 d = direction(e, 175.0);
        const PathHit near = curved.propagate(accel, {start, d, 0.0});
        const PathHit far = curved.propagate(accel, {start, d, 40.0});
        ASSERT_TRUE(near.hit && far.hit);
        EXPECT_LE(screen_error(p, tolerance, start, d, 0.0, near), 1.0) << e;
        EXPECT_LE(screen_error(p, tolerance, start, d, 40.0, far), 1.0) << e;
        EXPECT_LE(far.segments, near.segments);
        fewer += far.segments < near.segments;
    }
    EXPECT_GT(fewer, 10);
}

/// Arc length of the exact path from its start to horizontal distance dz (Simpson).
double arc_length(const ExactRay& ray, double dz) {
    const int n = 20000;
    const double h = dz / n;
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        sum += w * std::hypot(1.0, slope_at(ray, k * h));
    }
    return sum * h / 3.0;
}

TEST(CurvedPropagator, TheShaderStartsAReflectedRayWhereTheCameraRayEndsWithItsLength) {
    // A vertical mirror in front of the eye and a screen behind it.
    const Profile p = paper();
    const double tolerance = 1e-4;
    const RecordingPropagator recording(settings(p, tolerance));
    Scene s;
    Finish mirror;
    mirror.ambient = glm::dvec3(0.0);
    mirror.diffuse = 0.0;
    mirror.reflection = glm::dvec3(1.0);
    s.primitives.push_back(
        primitive(Plane{{0.0, 0.0, 1.0}, 15.0}, texture(solid(rgb(1, 1, 1)), mirror)));
    s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, -20.0}, Texture{}));
    const SceneAccel accel = build(s);
    const Shader shader(s, accel, recording);
    const glm::dvec3 eye(0.0, 1.5, 0.0);
    for (double e = -10.0; e <= 10.0; e += 2.5) {
        recording.starts.clear();
        recording.hits.clear();
        TraceCounters counters;
        shader.trace_camera_ray(eye, direction(e, 12.0), counters);
        ASSERT_EQ(recording.starts.size(), 2u) << e;
        const RayStart& camera = recording.starts[0];
        const PathHit& to_mirror = recording.hits[0];
        const RayStart& bounce = recording.starts[1];
        ASSERT_TRUE(to_mirror.hit);
        EXPECT_EQ(bounce.origin, to_mirror.surface.point);
        EXPECT_FALSE(bounce.image_position.has_value());
        // The path length to the mirror: the polyline's, a chord-wise approximation of the
        // exact arc.
        const ExactRay ray = exact(p, eye, camera.direction);
        const double arc = arc_length(ray, horizontal_distance(to_mirror.surface.point, eye));
        EXPECT_DOUBLE_EQ(bounce.travelled, to_mirror.length);
        EXPECT_NEAR(bounce.travelled, arc, 1e-4 * arc) << e;
        // The mirror turns the arrival direction about its normal (z).
        EXPECT_NEAR(bounce.direction.z, -to_mirror.direction.z, 1e-12);
        // The reflected ray follows the exact path from the mirror, allowance from the eye.
        ASSERT_TRUE(recording.hits[1].hit);
        EXPECT_EQ(recording.hits[1].surface.primitive, 1);
        EXPECT_LE(screen_error(p, tolerance, bounce.origin, bounce.direction, bounce.travelled,
                               recording.hits[1]),
                  1.0)
            << e;
    }
}

TEST(CurvedPropagator, StraightWhereNothingBends) {
    Scene s;
    s.primitives.push_back(primitive(Sphere{{0.0, 5.0, 0.0}, 1.0}, Texture{}));
    s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, 50.0}, Texture{}));
    const SceneAccel accel = build(s);
    const CurvedPropagator curved(settings(paper(), 1e-3));
    const StraightPropagator straight;
    auto same = [&](const RayStart& r) {
        const PathHit a = curved.propagate(accel, r);
        const PathHit b = straight.propagate(accel, r);
        EXPECT_EQ(a.segments, 1);
        EXPECT_EQ(a.hit, b.hit);
        EXPECT_EQ(a.surface.point, b.surface.point);
        EXPECT_EQ(a.direction, b.direction);
    };
    same({{0.0, 1.0, 0.0}, {0.0, 1.0, 0.0}});  // vertical: hits the sphere's bottom
    same({{0.0, 1.0, 0.0}, {0.0, -1.0, 0.0}});
    same({{0.0, -2.0, 0.0}, {0.0, 0.0, 1.0}});                            // below the ground
    same({{0.0, 0.0, 0.0}, glm::normalize(glm::dvec3(0.0, -1.0, 1.0))});  // into the ground
    // Steep enough that the direction turns by less than half the tolerance anywhere.
    same({{0.0, 1.0, 0.0}, glm::normalize(glm::dvec3(1e-4, 1.0, 0.0))});
    // No index gradient at all.
    const CurvedPropagator none(settings(Profile{}, 1e-3));
    for (double e = -20.0; e <= 20.0; e += 5.0) {
        const PathHit a = none.propagate(accel, {{0.0, 1.5, 0.0}, direction(e, 3.0)});
        const PathHit b = straight.propagate(accel, {{0.0, 1.5, 0.0}, direction(e, 3.0)});
        EXPECT_EQ(a.segments, 1);
        EXPECT_EQ(a.surface.point, b.surface.point);
    }
    // A grazing ray bends: many segments.
    EXPECT_GT(curved.propagate(accel, {{0.0, 1.5, 0.0}, direction(-5.0, 0.0)}).segments, 3);
}

Camera level_camera(int width, int height) {
    Camera c;
    c.location = glm::dvec3(0.0, 1.5, 0.0);
    c.direction = glm::dvec3(0.0, 0.0, 1.0);
    c.right = glm::dvec3(1.0 * width / height, 0.0, 0.0);
    c.up = glm::dvec3(0.0, 1.0, 0.0);
    c.loc = FileLoc{"scene.pov", 4, 1};
    return c;
}

TEST(ScanlinePropagator, EveryPixelOfARowGetsTheRowsElevation) {
    const Profile p = paper();
    const int w = 81, h = 60;
    const Camera cam = level_camera(w, h);
    auto scan = ScanlinePropagator::make(settings(p, 1e-3), cam, w, h);
    ASSERT_TRUE(scan.ok()) << scan.message();
    const CurvedPropagator per_ray(settings(p, 1e-3));
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, 30.0}, Texture{}));
    const SceneAccel accel = build(s);
    for (const int row : {5, 31, 44}) {
        const CameraRay centre = camera_ray(cam, 0.5 * w, row + 0.5, w, h);
        const auto row_path = curved_path(settings(p, 1e-3), centre.origin, centre.direction, 0.0);
        ASSERT_TRUE(row_path.has_value());
        for (const int col : {0, 20, 40, 80}) {
            const CameraRay r = camera_ray(cam, col + 0.5, row + 0.5, w, h);
            RayStart start{r.origin, r.direction};
            start.image_position = glm::dvec2(col + 0.5, row + 0.5);
            const PathHit a = scan->propagate(accel, start);
            const PathHit b = per_ray.propagate(accel, start);
            ASSERT_TRUE(a.hit && b.hit);
            // Rotated about the vertical: in the pixel's vertical plane, at the row path's
            // height for the same horizontal distance.
            const glm::dvec3 q = a.surface.point - cam.location;
            EXPECT_NEAR(q.x * r.direction.z - q.z * r.direction.x, 0.0, 1e-9);
            const double dz = horizontal_distance(a.surface.point, cam.location);
            EXPECT_NEAR(a.surface.point.y, polyline_height(row_path->path, dz), 1e-9)
                << row << " " << col;
            if (col == 40) {
                EXPECT_EQ(a.surface.point, b.surface.point);  // the central column is exact
            } else if (row != 31) {
                // Off the centre the pixel's own elevation is flatter than the row's.
                EXPECT_GT(std::abs(a.surface.point.y - b.surface.point.y), 1e-3)
                    << row << " " << col;
            }
        }
    }
    // Rays without an image position (reflections) follow their own paths.
    const glm::dvec3 d = direction(-7.0, 25.0);
    EXPECT_EQ(scan->propagate(accel, {cam.location, d}).surface.point,
              per_ray.propagate(accel, {cam.location, d}).surface.point);
}

TEST(ScanlinePropagator, RefusesACameraThatIsNotLevel) {
    Camera tilted = level_camera(80, 60);
    tilted.direction = glm::normalize(glm::dvec3(0.0, -0.2, 1.0));
    tilted.up = glm::normalize(glm::dvec3(0.0, 1.0, 0.2));
    auto r = ScanlinePropagator::make(settings(paper(), 1e-3), tilted, 80, 60);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(),
              "scene.pov:4:1: scanline paths need a level camera (one path per image row is "
              "rotated about the vertical): the camera looks 11.3 degrees down");
    Camera rolled = level_camera(80, 60);
    rolled.right = glm::dvec3(1.3, 0.1, 0.0);
    rolled.up = glm::dvec3(-0.1, 1.3, 0.0);
    auto q = ScanlinePropagator::make(settings(paper(), 1e-3), rolled, 80, 60);
    ASSERT_FALSE(q.ok());
    EXPECT_NE(q.message().find("the camera is rolled 4.4 degrees"), std::string::npos)
        << q.message();
    EXPECT_TRUE(camera_is_level(level_camera(80, 60)));
    EXPECT_FALSE(camera_is_level(tilted));
}

TEST(PixelAngle, IsOnePixelOfTheVerticalFieldAtTheCentre) {
    // 60 degrees across at 4:3: the vertical field is 2 atan(0.75 tan 30 deg).
    Camera c = level_camera(640, 480);
    c.direction = glm::dvec3(0.0, 0.0, 0.5 * c.right.x / std::tan(30.0 * kDeg));
    const double per_pixel = pixel_angle_rad(c, 640, 480);
    const double half_pixel_offset = 0.5 / 480.0 * glm::length(c.up) / glm::length(c.direction);
    EXPECT_NEAR(per_pixel, 2.0 * std::atan(half_pixel_offset), 1e-15);
    // Perspective: the centre's pixels subtend more than the field's average.
    const double field = 2.0 * std::atan(0.75 * std::tan(30.0 * kDeg));
    EXPECT_GT(per_pixel, field / 480.0);
    EXPECT_LT(per_pixel, 1.1 * field / 480.0);
}

}  // namespace
}  // namespace mirage
