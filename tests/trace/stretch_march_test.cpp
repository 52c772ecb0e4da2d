#include "trace/stretch_march.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "scene_builders.h"

namespace mirage {
namespace {

using namespace mirage::testing;

// Small spheres and boxes above a ground plane at y = 0 (and, with `elsewhere`, a wall).
Scene kinked_scene(bool elsewhere) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0}, Texture{}));
    for (int i = 0; i < 60; ++i) {
        const glm::dvec3 c(-6.0 + 12.0 * u(rng), 0.5 + 3.0 * u(rng), 5.0 + 90.0 * u(rng));
        const double r = 0.05 + 0.25 * u(rng);
        if (i % 2 == 0) {
            s.primitives.push_back(primitive(Sphere{c, r}, Texture{}));
        } else {
            s.primitives.push_back(primitive(Box{c - glm::dvec3(r), c + glm::dvec3(r)}, Texture{}));
        }
    }
    if (elsewhere) s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, 200.0}, Texture{}));
    return s;
}

// A kinked polyline from `from`: a chord with `kinks` points along it, each moved across it at
// random by up to `amplitude`, some polylines going down to the ground at the end.
std::vector<glm::dvec3> kinked_path(std::mt19937_64& rng, const glm::dvec3& from, int kinks,
                                    double amplitude) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dvec3 to(8.0 * u(rng), 2.0 + 2.0 * u(rng), 100.0 + 20.0 * u(rng));
    std::vector<glm::dvec3> points;
    for (int k = 1; k <= kinks; ++k) {
        const double f = static_cast<double>(k) / (kinks + 1);
        points.push_back(from + f * (to - from) + amplitude * glm::dvec3(u(rng), u(rng), 0.0));
    }
    points.push_back(u(rng) > 0.6 ? glm::dvec3(to.x, 0.0, to.z) : to);
    return points;
}

// Marching a stretch at once gives what querying each of its segments gives, with fewer
// queries; kinks that leave the chord are found where the chord alone would miss.
TEST(StretchMarch, EndsAsQueryingEverySegmentDoes) {
    const Scene scene = kinked_scene(false);
    auto accel = SceneAccel::build(scene);
    ASSERT_TRUE(accel.ok()) << accel.message();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int hits = 0, kink_hits = 0, ground_hits = 0, fewer = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 eye(0.5 * u(rng), 1.5 + 0.5 * u(rng), 0.0);
        const double amplitude = i % 3 == 0 ? 0.0 : (i % 3 == 1 ? 0.01 : 0.6);
        const std::vector<glm::dvec3> points = kinked_path(rng, eye, 15, amplitude);
        PolylineMarch each(*accel, eye), stretch(*accel, eye), chord(*accel, eye);
        bool expected = false;
        for (const glm::dvec3& p : points)
            if ((expected = each.segment_to(p))) break;
        ASSERT_EQ(march_stretch(stretch, *accel, points), expected) << i;
        const PathHit &a = each.result(), &b = stretch.result();
        ASSERT_EQ(b.hit, a.hit) << i;
        EXPECT_EQ(stretch.path_length(), each.path_length()) << i;
        EXPECT_EQ(stretch.point(), each.point()) << i;
        EXPECT_EQ(b.segments, a.segments) << i;
        EXPECT_LE(b.queries, a.queries) << i;
        if (b.queries < a.queries) ++fewer;
        if (a.hit) {
            ++hits;
            EXPECT_EQ(b.surface.t, a.surface.t) << i;
            EXPECT_EQ(b.surface.point, a.surface.point) << i;
            EXPECT_EQ(b.surface.primitive, a.surface.primitive) << i;
            if (a.surface.primitive == 0) ++ground_hits;
            // The straight chord from the eye to the end misses what the kinks met.
            if (a.surface.primitive != 0 && !chord.segment_to(points.back())) ++kink_hits;
        }
    }
    std::printf(
        "  %d hits (%d on the ground, %d only through the kinks), %d of 4000 with "
        "fewer queries\n",
        hits, ground_hits, kink_hits, fewer);
    EXPECT_GT(hits, 400);
    EXPECT_GT(ground_hits, 100);
    EXPECT_GT(kink_hits, 20);
    EXPECT_GT(fewer, 2000);
}

// A plane that is not the ground may be met anywhere: every segment is queried.
TEST(StretchMarch, APlaneElsewhereIsQueriedAllAlong) {
    const Scene scene = kinked_scene(true);
    auto accel = SceneAccel::build(scene);
    ASSERT_TRUE(accel.ok()) << accel.message();
    std::mt19937_64 rng(4);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 eye(0.0, 1.5, 0.0);
        const std::vector<glm::dvec3> points = kinked_path(rng, eye, 7, 0.01);
        PolylineMarch each(*accel, eye), stretch(*accel, eye);
        for (const glm::dvec3& p : points)
            if (each.segment_to(p)) break;
        march_stretch(stretch, *accel, points);
        EXPECT_EQ(stretch.result().queries, each.result().queries) << i;
        EXPECT_EQ(stretch.result().hit, each.result().hit) << i;
    }
}

// Whether a segment comes within a margin of a finite object's box, against every box.
TEST(SceneAccel, SegmentMayMeetAgreesWithEveryBox) {
    const Scene scene = kinked_scene(false);
    auto accel = SceneAccel::build(scene);
    ASSERT_TRUE(accel.ok()) << accel.message();
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int met = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 a(8.0 * u(rng), 2.0 + 2.0 * u(rng), 50.0 + 50.0 * u(rng));
        const glm::dvec3 b = i % 10 == 0 ? a : a + glm::dvec3(4.0 * u(rng), u(rng), 20.0 * u(rng));
        const double margin = 0.3 * (u(rng) + 1.0);
        // The segment's points on a fine grid against every finite box grown by the margin,
        // and by the margin and the grid's step.
        const double step = glm::length(b - a) / 500.0;
        auto grid_meets = [&](double grow) {
            for (int k = 0; k < accel->box_count(); ++k) {
                const Aabb& box = accel->item_box(k);
                if (!box.finite()) continue;
                for (int j = 0; j <= 500; ++j) {
                    const glm::dvec3 p = a + (j / 500.0) * (b - a);
                    if (glm::all(glm::greaterThanEqual(p, box.lo - grow)) &&
                        glm::all(glm::lessThanEqual(p, box.hi + grow)))
                        return true;
                }
            }
            return false;
        };
        const bool got = accel->segment_may_meet(a, b, margin);
        if (grid_meets(margin)) {
            ++met;
            EXPECT_TRUE(got) << i;
        } else if (got) {
            EXPECT_TRUE(grid_meets(margin + step)) << i;  // a graze between grid points
        }
    }
    EXPECT_GT(met, 200);
}

}  // namespace
}  // namespace mirage
