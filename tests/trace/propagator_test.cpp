#include "trace/propagator.h"

#include <gtest/gtest.h>

#include <random>

#include "scene_builders.h"

namespace mirage {
namespace {

using namespace mirage::testing;

SceneAccel build(const Scene& s) {
    auto accel = SceneAccel::build(s);
    EXPECT_TRUE(accel.ok()) << accel.message();
    return std::move(*accel);
}

Scene ground_and_ball() {
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, Texture{}));
    s.primitives.push_back(primitive(Sphere{{0.0, 1.0, 6.0}, 1.0}, Texture{}));
    s.primitives.push_back(primitive(Box{{2.0, 0.0, 2.0}, {3.0, 1.0, 3.0}}, Texture{}));
    return s;
}

TEST(StraightPropagator, OneSegmentAndPovRaysMinimumDepth) {
    const Scene s = ground_and_ball();
    const SceneAccel accel = build(s);
    const StraightPropagator straight;
    PathHit p = straight.propagate(accel, {{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}});
    EXPECT_TRUE(p.hit);
    EXPECT_EQ(p.segments, 1);
    EXPECT_EQ(p.surface.primitive, 1);
    EXPECT_DOUBLE_EQ(p.surface.t, 5.0);
    EXPECT_DOUBLE_EQ(p.length, 5.0);
    EXPECT_EQ(p.direction, glm::dvec3(0.0, 0.0, 1.0));
    // A surface closer than 1e-4 is ignored (POV-Ray's MIN_ISECT_DEPTH): here the ground
    // 5e-5 below the origin; the ray goes on to the sky.
    p = straight.propagate(accel, {{0.0, 5e-5, 0.0}, {0.0, -1.0, 0.0}});
    EXPECT_FALSE(p.hit);
    EXPECT_EQ(p.direction, glm::dvec3(0.0, -1.0, 0.0));
    p = straight.propagate(accel, {{0.0, 2e-4, 0.0}, {0.0, -1.0, 0.0}});
    EXPECT_TRUE(p.hit);
}

TEST(PolylineMarch, SplitStraightLinesFindWhatOneRayFinds) {
    const Scene s = ground_and_ball();
    const SceneAccel accel = build(s);
    const StraightPropagator straight;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 5000; ++i) {
        const glm::dvec3 o(2.0 * u(rng), 1.0 + u(rng), -2.0 + u(rng));
        const glm::dvec3 d = glm::normalize(glm::dvec3(0.3 * u(rng), 0.4 * u(rng) - 0.1, 1.0));
        const PathHit one = straight.propagate(accel, {o, d});
        PolylineMarch march(accel, o);
        double s_done = 0.0;
        for (int k = 0; k < 12 && !march.done(); ++k) {
            s_done += 0.05 + (u(rng) + 1.0);
            march.segment_to(o + s_done * d);
        }
        if (!march.done()) march.ray(d);
        const PathHit& many = march.result();
        ASSERT_EQ(many.hit, one.hit) << i;
        if (one.hit) {
            EXPECT_EQ(many.surface.primitive, one.surface.primitive);
            EXPECT_NEAR(many.length, one.length, 1e-9);
            EXPECT_NEAR(glm::length(many.surface.point - one.surface.point), 0.0, 1e-9);
        }
    }
}

TEST(PolylineMarch, AHitExactlyAtAJointIsFoundOnce) {
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, Texture{}));
    const SceneAccel accel = build(s);
    // A path that runs down to the ground, its vertex exactly on the plane, then climbs:
    // the hit is at the joint and must be reported there, as the end of the first segment.
    PolylineMarch march(accel, {0.0, 1.0, 0.0});
    EXPECT_TRUE(march.segment_to({1.0, 0.0, 0.0}));
    EXPECT_TRUE(march.done());
    const PathHit& p = march.result();
    EXPECT_TRUE(p.hit);
    EXPECT_EQ(p.segments, 1);
    EXPECT_NEAR(glm::length(p.surface.point - glm::dvec3(1.0, 0.0, 0.0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(p.direction - glm::normalize(glm::dvec3(1.0, -1.0, 0.0))), 0.0, 1e-15);
}

TEST(PolylineMarch, JointsOnACurvedSurfaceAreNeverLost) {
    // Paths whose vertex lies on a sphere (to rounding) and then turn away from it: the hit
    // at the vertex computes to just past the first segment's end or just before the
    // second's start; the overlap of the queries must catch every one.
    Scene s;
    s.primitives.push_back(primitive(Sphere{{0.3, -0.2, 0.1}, 1.7}, Texture{}));
    const SceneAccel accel = build(s);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
        const glm::dvec3 vertex = glm::dvec3(0.3, -0.2, 0.1) + 1.7 * n;
        const glm::dvec3 start =
            vertex + 3.0 * glm::normalize(n + 0.5 * glm::dvec3(u(rng), u(rng), u(rng)));
        PolylineMarch march(accel, start);
        if (!march.segment_to(vertex)) march.segment_to(vertex + 2.0 * n);
        ASSERT_TRUE(march.result().hit) << i;
        EXPECT_NEAR(glm::length(march.result().surface.point - vertex), 0.0, 1e-8);
    }
}

TEST(PolylineMarch, ASurfaceThroughAJointIsNotLostWhenTheSegmentSkims) {
    // The first segment runs along the plane's surface (parallel: it cannot see the plane),
    // the second leaves it downward from the very joint: the hit is at the joint, t ~ 0 of
    // the second segment, and must not fall between the two.
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, Texture{}));
    const SceneAccel accel = build(s);
    PolylineMarch march(accel, {-1.0, 0.0, 0.0});
    EXPECT_FALSE(march.segment_to({0.0, 0.0, 0.0}));
    EXPECT_TRUE(march.segment_to({1.0, -1.0, 0.0}));
    EXPECT_EQ(march.result().segments, 2);
    EXPECT_NEAR(glm::length(march.result().surface.point), 0.0, 1e-12);
}

TEST(PolylineMarch, IgnoresOnlyTheFirstStretchOfPath) {
    Scene s;
    s.primitives.push_back(primitive(Sphere{{0.0, 0.0, 0.0}, 1.0}, Texture{}));
    const SceneAccel accel = build(s);
    // Leaving the sphere's surface: the surface at the start is ignored ...
    PolylineMarch leave(accel, {0.0, 0.0, 1.0});
    EXPECT_FALSE(leave.segment_to({0.0, 0.0, 2.0}));
    // ... but coming back to it after a turn, the same surface is hit.
    EXPECT_TRUE(leave.segment_to({0.0, 0.0, 0.0}));
    EXPECT_NEAR(leave.result().surface.point.z, 1.0, 1e-12);
    EXPECT_NEAR(leave.path_length(), 1.0, 0.0);
    // Zero-length segments are skipped and not counted.
    PolylineMarch idle(accel, {0.0, 0.0, 3.0});
    EXPECT_FALSE(idle.segment_to({0.0, 0.0, 3.0}));
    EXPECT_EQ(idle.result().segments, 0);
    EXPECT_FALSE(idle.ray({0.0, 1.0, 0.0}));
    EXPECT_TRUE(idle.done());
    EXPECT_EQ(idle.result().direction, glm::dvec3(0.0, 1.0, 0.0));
}

}  // namespace
}  // namespace mirage
