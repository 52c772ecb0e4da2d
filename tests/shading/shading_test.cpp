#include "shading/shading.h"

#include <gtest/gtest.h>

#include <cmath>

#include "trace/recording_propagator.h"
#include "trace/scene_builders.h"
#include "trace/curved_propagator.h"
#include "patterns/single_precision.h"

namespace mirage {
namespace {

using namespace mirage::testing;

/// A scene with its accel and a shader over straight rays.
struct Rig {
    Scene scene;
    SceneAccel accel;
    StraightPropagator straight;
    std::unique_ptr<Shader> shader;
    explicit Rig(Scene s) : scene(std::move(s)), accel(*SceneAccel::build(scene)) {
        shader = std::make_unique<Shader>(scene, accel, straight);
    }
    glm::dvec3 trace(const glm::dvec3& o, const glm::dvec3& d, TraceCounters* c = nullptr) {
        TraceCounters local;
        return shader->trace_camera_ray(o, glm::normalize(d), c ? *c : local);
    }
};

Scene lit_sphere(const Finish& finish) {
    Scene s;
    s.lights.push_back(light({0.0, 0.0, -10.0}, glm::dvec3(1.0, 0.9, 0.8)));
    s.primitives.push_back(
        primitive(Sphere{{0.0, 0.0, 0.0}, 1.0}, texture(solid(rgb(0.5, 0.6, 0.7)), finish)));
    return s;
}

TEST(Shading, LitSphereMatchesPovRaysFormula) {
    Finish f;
    f.ambient = glm::dvec3(0.1);
    f.diffuse = 0.6;
    f.brilliance = 2.0;
    f.specular = 0.5;
    f.roughness = 0.05;
    f.phong = 0.7;
    f.phong_size = 40.0;
    Rig rig(lit_sphere(f));
    const glm::dvec3 pigment = to_single(glm::dvec3(0.5, 0.6, 0.7));
    const glm::dvec3 light_colour = to_single(glm::dvec3(1.0, 0.9, 0.8));
    for (const double x0 : {0.0, 0.3, 0.6, 0.9}) {
        const glm::dvec3 origin(x0, 0.0, -5.0);
        const glm::dvec3 d(0.0, 0.0, 1.0);
        const glm::dvec3 p(x0, 0.0, -std::sqrt(1.0 - x0 * x0));
        const glm::dvec3 n = p;  // unit sphere
        const glm::dvec3 l = glm::normalize(glm::dvec3(0.0, 0.0, -10.0) - p);
        const double cos_in = glm::dot(n, l);
        glm::dvec3 expected = pigment * to_single(glm::dvec3(0.1));
        // POV-Ray holds the finish's values in single precision.
        expected += std::pow(cos_in, 2.0) * to_single(0.6) * pigment * light_colour;
        const glm::dvec3 r = d - 2.0 * glm::dot(d, n) * n;
        // Phong only where the mirror direction leans toward the light (pow of an even
        // exponent would hide the sign).
        if (glm::dot(r, l) > 0.0) {
            expected += to_single(0.7) * std::pow(glm::dot(r, l), 40.0) * light_colour;
        }
        const glm::dvec3 h = glm::normalize(-d + l);
        expected += 0.5 * std::pow(glm::dot(h, n), to_single(1.0 / 0.05)) * light_colour;
        const glm::dvec3 got = rig.trace(origin, d);
        EXPECT_NEAR(glm::length(got - expected), 0.0, 1e-9) << "x0 = " << x0;
    }
}

TEST(Shading, UnlitSideGetsAmbientAndEmissionOnly) {
    Finish f;
    f.ambient = glm::dvec3(0.2, 0.1, 0.05);
    f.emission = glm::dvec3(0.3);
    Scene s = lit_sphere(f);
    s.global.ambient_light = glm::dvec3(0.5);
    s.lights[0].location = glm::dvec3(0.0, 0.0, 10.0);  // behind the sphere
    Rig rig(s);
    const glm::dvec3 pigment = to_single(glm::dvec3(0.5, 0.6, 0.7));
    const glm::dvec3 expected =
        pigment * to_single(f.ambient) * 0.5 + pigment * to_single(f.emission);
    EXPECT_NEAR(glm::length(rig.trace({0, 0, -5}, {0, 0, 1}) - expected), 0.0, 1e-9);
}

TEST(Shading, NormalFacesTheViewerFromInside) {
    Finish f;
    f.ambient = glm::dvec3(0.0);
    f.diffuse = 1.0;
    Scene s = lit_sphere(f);
    s.lights[0].location = glm::dvec3(0.0, 0.0, 0.0);  // inside, with the camera
    Rig rig(s);
    // From the centre the light falls square on the inside: diffuse = pigment * light.
    const glm::dvec3 got = rig.trace({0.0, 0.0, 0.0}, {0, 0, 1});
    EXPECT_NEAR(glm::length(got - to_single(glm::dvec3(0.5, 0.6, 0.7)) *
                                      to_single(glm::dvec3(1.0, 0.9, 0.8))),
                0.0, 1e-9);
}

Scene ball_over_ground(bool no_shadow, bool shadowless) {
    Scene s;
    PointLight l = light({0.0, 10.0, 0.0});
    l.shadowless = shadowless;
    s.lights.push_back(l);
    Finish ground;
    ground.ambient = glm::dvec3(0.1);
    ground.diffuse = 0.6;
    ground.specular = 0.8;  // a highlight a shadowless light must not make
    s.primitives.push_back(
        primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, texture(solid(rgb(1, 1, 1)), ground)));
    Primitive ball = primitive(Sphere{{0.0, 2.0, 0.0}, 1.0}, texture(solid(rgb(1, 0, 0))));
    ball.no_shadow = no_shadow;
    s.primitives.push_back(ball);
    return s;
}

TEST(Shading, ShadowsAreCastAndSkippedAsPovRayDoes) {
    const glm::dvec3 eye(0.0, 5.0, -10.0);
    const glm::dvec3 under(0.0, 0.0, 0.0);   // right under the ball
    const glm::dvec3 aside(3.0, 0.0, -1.0);  // in the open
    const auto at = [&](Rig& rig, const glm::dvec3& p, TraceCounters* c = nullptr) {
        return rig.trace(eye, p - eye, c);
    };
    Rig shadowed(ball_over_ground(false, false));
    TraceCounters counters;
    EXPECT_NEAR(at(shadowed, under, &counters).x, static_cast<double>(0.1f), 1e-9);  // ambient only
    EXPECT_EQ(counters.shadow_rays, 1u);
    EXPECT_GT(at(shadowed, aside).x, 0.5);

    Rig no_shadow(ball_over_ground(true, false));
    const double lit = at(no_shadow, under).x;
    EXPECT_GT(lit, 0.5);

    // A shadowless light: no shadow ray, diffuse yes, highlights no.
    Rig fill(ball_over_ground(false, true));
    TraceCounters fill_counters;
    const glm::dvec3 p = at(fill, under, &fill_counters);
    EXPECT_EQ(fill_counters.shadow_rays, 0u);
    const glm::dvec3 l = glm::normalize(glm::dvec3(0.0, 10.0, 0.0) - under);
    const double diffuse = to_single(0.6) * glm::dot(glm::dvec3(0, 1, 0), l);
    EXPECT_NEAR(p.x, static_cast<double>(0.1f) + diffuse, 1e-9);
    EXPECT_LT(p.x, lit);  // the lit, non-shadowless case had a highlight on top
}

Scene mirror_floor(double reflection, int max_trace_level) {
    Scene s;
    s.global.max_trace_level = max_trace_level;
    s.background = rgb(0.2, 0.4, 0.6);
    Finish mirror;
    mirror.ambient = glm::dvec3(0.0);
    mirror.diffuse = 0.0;
    mirror.reflection = glm::dvec3(reflection);
    s.primitives.push_back(
        primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, texture(solid(rgb(1, 1, 1)), mirror)));
    return s;
}

TEST(Shading, ReflectionShowsWhatTheMirrorSees) {
    Rig rig(mirror_floor(0.5, 5));
    TraceCounters c;
    const glm::dvec3 got = rig.trace({0, 1, 0}, {0.3, -1, 0.2}, &c);
    EXPECT_NEAR(
        glm::length(got - to_single(glm::dvec3(0.5)) * to_single(glm::dvec3(0.2, 0.4, 0.6))), 0.0,
        1e-12);
    EXPECT_EQ(c.camera_rays, 1u);
    EXPECT_EQ(c.reflected_rays, 1u);
    EXPECT_EQ(c.segments, 2u);
}

TEST(Shading, ReflectionStopsAtMaxTraceLevelAndAdcBailout) {
    // max_trace_level 1: the reflected ray is at level 1 and returns black, not the sky.
    Rig level1(mirror_floor(0.5, 1));
    TraceCounters c;
    EXPECT_EQ(level1.trace({0, 1, 0}, {0.3, -1, 0.2}, &c), glm::dvec3(0.0));
    EXPECT_EQ(c.reflected_rays, 0u);
    EXPECT_EQ(c.trace_level_cutoffs, 1u);
    // A reflection weaker than adc_bailout (1/255) is not traced.
    Rig faint(mirror_floor(0.003, 5));
    TraceCounters f;
    EXPECT_EQ(faint.trace({0, 1, 0}, {0.3, -1, 0.2}, &f), glm::dvec3(0.0));
    EXPECT_EQ(f.reflected_rays, 0u);
}

TEST(Shading, MirrorsFacingEachOtherStopAfterMaxTraceLevel) {
    Scene s;
    s.global.max_trace_level = 4;
    Finish mirror;
    mirror.ambient = glm::dvec3(1.0);
    mirror.diffuse = 0.0;
    mirror.reflection = glm::dvec3(0.5);
    s.primitives.push_back(
        primitive(Plane{{0.0, 0.0, 1.0}, 1.0}, texture(solid(rgb(1, 1, 1)), mirror)));
    s.primitives.push_back(
        primitive(Plane{{0.0, 0.0, 1.0}, -1.0}, texture(solid(rgb(1, 1, 1)), mirror)));
    Rig rig(s);
    TraceCounters c;
    // Levels 1..4 each add ambient 1 weighted by 0.5^k: 1 + 0.5 + 0.25 + 0.125.
    const glm::dvec3 got = rig.trace({0, 0, 0}, {0, 0, 1}, &c);
    EXPECT_NEAR(got.x, 1.875, 1e-12);
    EXPECT_EQ(c.reflected_rays, 3u);
    EXPECT_EQ(c.trace_level_cutoffs, 1u);
}

TEST(Shading, ZeroRoughnessIsPovRaysExponentZero) {
    // POV-Ray keeps an exponent of 0 for `roughness 0`: the highlight is flat wherever the
    // halfway vector faces the surface.
    Finish f;
    f.ambient = glm::dvec3(0.0);
    f.diffuse = 0.0;
    f.specular = 0.25;
    f.roughness = 0.0;
    Rig rig(lit_sphere(f));
    const glm::dvec3 light_colour = to_single(glm::dvec3(1.0, 0.9, 0.8));
    EXPECT_NEAR(glm::length(rig.trace({0.5, 0.0, -5.0}, {0, 0, 1}) - 0.25 * light_colour), 0.0,
                1e-12);
}

TEST(Shading, RaysThroughGlassGoStraightInsideAndCurvedOutside) {
    CurvedSettings curved;
    curved.atmosphere = Atmosphere::exponential(*preset_profile("paper"));
    curved.tolerance_rad = 1e-4;
    const RecordingPropagator recording(curved);
    Scene s;
    Finish clear;
    clear.ambient = glm::dvec3(0.0);
    clear.diffuse = 0.0;
    Primitive slab = primitive(Box{{-50.0, -5.0, 8.0}, {50.0, 20.0, 9.0}},
                               texture(solid(Colour{glm::dvec3(1.0), 1.0, 0.0}), clear));
    Interior glass;
    glass.ior = 1.5;
    slab.interior = std::make_shared<const Interior>(glass);
    s.primitives.push_back(slab);
    s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, 20.0}, Texture{}));
    const SceneAccel accel = *SceneAccel::build(s);
    const Shader shader(s, accel, recording);
    TraceCounters counters;
    const glm::dvec3 eye(0.0, 1.5, 0.0);
    shader.trace_camera_ray(eye, glm::normalize(glm::dvec3(0.1, -0.08, 1.0)), counters);
    // The camera ray, then the ray leaving the slab: the one inside went straight.
    ASSERT_EQ(recording.starts.size(), 2u);
    const PathHit& entry = recording.hits[0];
    const RayStart& out = recording.starts[1];
    ASSERT_TRUE(entry.hit);
    EXPECT_NEAR(entry.surface.point.z, 8.0, 1e-9);
    EXPECT_NEAR(out.origin.z, 9.0, 1e-9);
    // Inside, the ray is the straight refracted ray from the entry point (Snell's law with
    // 1 / 1.5 about the slab's normal facing the ray, -z).
    const glm::dvec3 d = entry.direction;
    const double eta = 1.0 / 1.5, cosi = d.z;
    const glm::dvec3 inside =
        glm::normalize(eta * d + (eta * cosi - std::sqrt(1.0 - eta * eta * (1.0 - cosi * cosi))) *
                                     glm::dvec3(0.0, 0.0, -1.0));
    const glm::dvec3 expected_exit = entry.surface.point + (1.0 / inside.z) * inside;
    EXPECT_NEAR(glm::length(out.origin - expected_exit), 0.0, 1e-9);
    // Out of the slab the ray regains the incoming direction, and its allowance counts the
    // path from the eye.
    EXPECT_NEAR(glm::length(out.direction - d), 0.0, 1e-9);
    EXPECT_NEAR(out.travelled, entry.length + glm::length(expected_exit - entry.surface.point),
                1e-9);
    ASSERT_TRUE(recording.hits[1].hit);
    EXPECT_EQ(recording.hits[1].surface.primitive, 1);
}

}  // namespace
}  // namespace mirage
