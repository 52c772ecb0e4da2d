#include "shapes/shape_intersect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "trace/scene_builders.h"

namespace mirage {
namespace {

using namespace mirage::testing;

PreparedShape prepared(const Shape& shape, const Transform& t = {}, bool inverse = false) {
    Primitive p = primitive(shape, Texture{}, t);
    p.inverse = inverse;
    auto s = prepare_shape(p);
    EXPECT_TRUE(s.ok()) << s.message();
    return *s;
}

/// The closest hit over [1e-4, 2e10] (the tracer's interval), or -1.
double hit_t(const PreparedShape& s, const glm::dvec3& o, const glm::dvec3& d,
             int* part = nullptr) {
    ShapeHit h;
    if (!intersect_shape(s, o, glm::normalize(d), 1e-4, kPovBoundHuge, h)) return -1.0;
    if (part) *part = h.part;
    return h.t;
}

TEST(Sphere, HitsAtTheAnalyticDepthsWithOutwardNormal) {
    const auto s = prepared(Sphere{{1.0, 2.0, 3.0}, 2.0});
    EXPECT_EQ(s.kind, ShapeKind::Sphere);
    EXPECT_DOUBLE_EQ(hit_t(s, {1.0, 2.0, -7.0}, {0, 0, 1}), 8.0);
    // From inside, the far side.
    EXPECT_DOUBLE_EQ(hit_t(s, {1.0, 2.0, 3.0}, {0, 0, 1}), 2.0);
    // Behind the origin: no hit.
    EXPECT_EQ(hit_t(s, {1.0, 2.0, 7.0}, {0, 0, 1}), -1.0);
    const glm::dvec3 n = shape_normal(s, {1.0, 2.0, 1.0}, 0);
    EXPECT_EQ(n, glm::dvec3(0.0, 0.0, -1.0));
}

TEST(Sphere, GrazingRaysMissAsInPovRay) {
    // POV-Ray misses when the half chord squared is <= EPSILON (1e-10).
    const auto s = prepared(Sphere{{0.0, 0.0, 0.0}, 1.0});
    const double inside = 1.0 - 1e-9;    // half chord^2 = 2e-9: a hit
    const double tangent = 1.0 - 1e-11;  // half chord^2 = 2e-11: a miss
    EXPECT_GT(hit_t(s, {inside, 0.0, -5.0}, {0, 0, 1}), 0.0);
    EXPECT_EQ(hit_t(s, {tangent, 0.0, -5.0}, {0, 0, 1}), -1.0);
    EXPECT_EQ(hit_t(s, {1.0, 0.0, -5.0}, {0, 0, 1}), -1.0);
}

TEST(Sphere, SimilarityStaysASphereAndGeneralMapsMakeEllipsoids) {
    const auto rotated = prepared(Sphere{{1.0, 0.0, 0.0}, 1.0},
                                  then(rotate({0.0, 0.0, 90.0}), scale({2.0, 2.0, 2.0})));
    EXPECT_EQ(rotated.kind, ShapeKind::Sphere);
    EXPECT_NEAR(rotated.centre.x, 0.0, 1e-12);
    EXPECT_NEAR(rotated.centre.y, 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(rotated.radius, 2.0);

    const auto e = prepared(Sphere{{0.0, 0.0, 0.0}, 1.0}, scale({3.0, 1.0, 1.0}));
    EXPECT_EQ(e.kind, ShapeKind::Ellipsoid);
    EXPECT_NEAR(hit_t(e, {-10.0, 0.0, 0.0}, {1, 0, 0}), 7.0, 1e-12);
    EXPECT_NEAR(hit_t(e, {0.0, -10.0, 0.0}, {0, 1, 0}), 9.0, 1e-12);
    // The normal of x^2/9 + y^2 = 1 at (3 cos a, sin a) is along (cos a / 3, sin a).
    const double a = 0.7;
    const glm::dvec3 p(3.0 * std::cos(a), std::sin(a), 0.0);
    const glm::dvec3 n = shape_normal(e, p, 0);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(std::cos(a) / 3.0, std::sin(a), 0.0));
    EXPECT_NEAR(glm::length(n - expected), 0.0, 1e-12);
    const Aabb b = shape_bounds(e);
    EXPECT_NEAR(b.hi.x, 3.0, 1e-12);
    EXPECT_NEAR(b.hi.y, 1.0, 1e-12);
}

TEST(Plane, DepthParallelAndMaxDistance) {
    const auto s = prepared(Plane{{0.0, 1.0, 0.0}, 1.0});
    EXPECT_DOUBLE_EQ(hit_t(s, {0.0, 3.0, 0.0}, {0, -1, 0}), 2.0);
    EXPECT_DOUBLE_EQ(hit_t(s, {0.0, -3.0, 0.0}, {0, 1, 0}), 4.0);  // from below too
    EXPECT_EQ(hit_t(s, {0.0, 3.0, 0.0}, {1, 0, 0}), -1.0);         // parallel
    EXPECT_EQ(hit_t(s, {0.0, 3.0, 0.0}, {1, 1e-11, 0}), -1.0);     // |n.d| < EPSILON
    // POV-Ray ignores plane hits beyond MAX_DISTANCE = 1e7: the far ground is sky.
    EXPECT_GT(hit_t(s, {0.0, 2.0, 0.0}, {1.0, -1.0 / 9.0e6, 0.0}), 0.0);
    EXPECT_EQ(hit_t(s, {0.0, 2.0, 0.0}, {1.0, -1.0 / 1.1e7, 0.0}), -1.0);
    EXPECT_TRUE(std::isinf(shape_bounds(s).hi.x));
}

TEST(Plane, TransformsMoveTheRightWay) {
    const auto up = prepared(Plane{{0.0, 1.0, 0.0}, 1.0}, translate({5.0, 2.0, 0.0}));
    EXPECT_DOUBLE_EQ(hit_t(up, {0.0, 10.0, 0.0}, {0, -1, 0}), 7.0);  // now at y = 3
    const auto tilted = prepared(Plane{{0.0, 1.0, 0.0}, 0.0}, rotate({0.0, 0.0, 90.0}));
    EXPECT_NEAR(std::abs(tilted.normal.x), 1.0, 1e-15);  // y rotated onto -x
    EXPECT_NEAR(hit_t(tilted, {4.0, 0.0, 0.0}, {-1, 0, 0}), 4.0, 1e-12);
    const auto squashed = prepared(Plane{{0.0, 1.0, 0.0}, 1.0}, scale({1.0, 0.5, 1.0}));
    EXPECT_NEAR(hit_t(squashed, {0.0, 10.0, 0.0}, {0, -1, 0}), 9.5, 1e-12);
}

TEST(Box, EntryExitAndSides) {
    const auto b = prepared(Box{{1.0, 1.0, 1.0}, {-1.0, -1.0, -1.0}});
    EXPECT_EQ(b.kind, ShapeKind::Box);
    int part = 0;
    EXPECT_DOUBLE_EQ(hit_t(b, {0.2, 0.3, -5.0}, {0, 0, 1}, &part), 4.0);
    EXPECT_EQ(shape_normal(b, {0.2, 0.3, -1.0}, part), glm::dvec3(0, 0, -1));
    EXPECT_DOUBLE_EQ(hit_t(b, {0.0, 0.0, 0.0}, {1, 0, 0}, &part), 1.0);  // from inside
    EXPECT_EQ(shape_normal(b, {1.0, 0.0, 0.0}, part), glm::dvec3(1, 0, 0));
    EXPECT_EQ(hit_t(b, {0.0, 2.0, -5.0}, {0, 0, 1}), -1.0);
    // Along a face plane, parallel to it: POV-Ray counts the face's points as inside.
    EXPECT_DOUBLE_EQ(hit_t(b, {0.0, 1.0, -5.0}, {0, 0, 1}), 4.0);
}

TEST(Box, EdgeHitsPickTheSideTheRayRunsAlong) {
    // A ray through the edge x = 1, z = -1 (within CLOSE_TOLERANCE) coming mostly along +z
    // takes the z side, coming mostly along -x the x side (POV-Ray's [DB 9/94] rule).
    const auto b = prepared(Box{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}});
    int part = 0;
    const glm::dvec3 edge(1.0, 0.0, -1.0);
    const glm::dvec3 along_z = glm::normalize(glm::dvec3(-0.3, 0.0, 1.0));
    ASSERT_GT(hit_t(b, edge - 4.0 * along_z, along_z, &part), 0.0);
    EXPECT_EQ(shape_normal(b, edge, part), glm::dvec3(0, 0, -1));
    const glm::dvec3 along_x = glm::normalize(glm::dvec3(-1.0, 0.0, 0.3));
    ASSERT_GT(hit_t(b, edge - 4.0 * along_x, along_x, &part), 0.0);
    EXPECT_EQ(shape_normal(b, edge, part), glm::dvec3(1, 0, 0));
}

TEST(Box, RotatedBoxHasRotatedNormals) {
    const auto b = prepared(Box{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}, rotate({0.0, 45.0, 0.0}));
    EXPECT_EQ(b.kind, ShapeKind::TransformedBox);
    int part = 0;
    // The edge now points at -z: a ray along +z meets it at z = -sqrt 2.
    const double t = hit_t(b, {0.0, 0.0, -5.0}, {0, 0, 1}, &part);
    EXPECT_NEAR(t, 5.0 - std::sqrt(2.0), 1e-9);
    const double off = 0.3;
    const double t2 = hit_t(b, {off, 0.0, -5.0}, {0, 0, 1}, &part);
    EXPECT_NEAR(t2, 5.0 - std::sqrt(2.0) + off, 1e-9);
    const glm::dvec3 n = shape_normal(b, {off, 0.0, -std::sqrt(2.0) + off}, part);
    EXPECT_NEAR(glm::length(n - glm::normalize(glm::dvec3(1.0, 0.0, -1.0))), 0.0, 1e-12);
    const Aabb box = shape_bounds(b);
    EXPECT_NEAR(box.hi.x, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(box.lo.z, -std::sqrt(2.0), 1e-12);
}

TEST(Cylinder, SideCapsAndOpen) {
    const Cylinder c{{0.0, 1.0, 0.0}, {0.0, 3.0, 0.0}, 0.5, false};
    const auto closed = prepared(c);
    int part = 0;
    EXPECT_NEAR(hit_t(closed, {-5.0, 2.0, 0.0}, {1, 0, 0}, &part), 4.5, 1e-12);
    EXPECT_NEAR(glm::length(shape_normal(closed, {-0.5, 2.0, 0.0}, part) - glm::dvec3(-1, 0, 0)),
                0.0, 1e-12);
    EXPECT_NEAR(hit_t(closed, {0.1, 10.0, 0.2}, {0, -1, 0}, &part), 7.0, 1e-12);
    EXPECT_NEAR(glm::length(shape_normal(closed, {0.1, 3.0, 0.2}, part) - glm::dvec3(0, 1, 0)), 0.0,
                1e-12);
    EXPECT_NEAR(hit_t(closed, {0.1, -10.0, 0.2}, {0, 1, 0}, &part), 11.0, 1e-12);
    EXPECT_NEAR(glm::length(shape_normal(closed, {0.1, 1.0, 0.2}, part) - glm::dvec3(0, -1, 0)),
                0.0, 1e-12);
    // Open: down the axis, no caps to hit.
    Cylinder o = c;
    o.open = true;
    EXPECT_EQ(hit_t(prepared(o), {0.1, 10.0, 0.2}, {0, -1, 0}), -1.0);
    // Past the ends of the side.
    EXPECT_EQ(hit_t(prepared(o), {-5.0, 3.5, 0.0}, {1, 0, 0}), -1.0);
}

TEST(Cylinder, TransformedAndDegenerate) {
    // Along z, then rotated onto x and scaled 2x along x: from x = 0 to x = 4.
    const auto c = prepared(Cylinder{{0.0, 0.0, 0.0}, {0.0, 0.0, 2.0}, 1.0, false},
                            then(rotate({0.0, 90.0, 0.0}), scale({2.0, 1.0, 1.0})));
    EXPECT_NEAR(hit_t(c, {10.0, 0.2, 0.1}, {-1, 0, 0}), 6.0, 1e-12);
    EXPECT_NEAR(hit_t(c, {2.0, 5.0, 0.0}, {0, -1, 0}), 4.0, 1e-12);
    const Aabb b = shape_bounds(c);
    EXPECT_NEAR(b.lo.x, 0.0, 1e-12);
    EXPECT_NEAR(b.hi.x, 4.0, 1e-12);

    Primitive bad = primitive(Cylinder{{1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, 1.0, false}, Texture{});
    bad.loc = FileLoc{"s.pov", 4, 2};
    auto r = prepare_shape(bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(), "s.pov:4:2: cylinder: degenerate, base point = cap point");
}

TEST(Disc, RingAndNormal) {
    const auto d = prepared(Disc{{0.0, 1.0, 0.0}, {0.0, 2.0, 0.0}, 2.0, 0.5});
    EXPECT_NEAR(hit_t(d, {1.0, 5.0, 0.0}, {0, -1, 0}), 4.0, 1e-12);
    EXPECT_NEAR(hit_t(d, {1.0, -5.0, 0.0}, {0, 1, 0}), 6.0, 1e-12);  // both faces
    EXPECT_EQ(hit_t(d, {0.2, 5.0, 0.0}, {0, -1, 0}), -1.0);          // through the hole
    EXPECT_EQ(hit_t(d, {2.1, 5.0, 0.0}, {0, -1, 0}), -1.0);          // outside
    EXPECT_EQ(hit_t(d, {0.0, 1.0, -5.0}, {0, 0, 1}), -1.0);          // edge-on
    EXPECT_EQ(shape_normal(d, {1.0, 1.0, 0.0}, 0), glm::dvec3(0, 1, 0));
    // Scaled non-uniformly: the normal follows as a normal, not as a vector.
    const auto tilted =
        prepared(Disc{{0.0, 0.0, 0.0}, glm::normalize(glm::dvec3(1, 1, 0)), 1.0, 0.0},
                 scale({2.0, 1.0, 1.0}));
    EXPECT_NEAR(glm::length(tilted.normal - glm::normalize(glm::dvec3(0.5, 1.0, 0.0))), 0.0, 1e-12);
}

TEST(Shapes, InverseFlipsTheNormal) {
    const auto s = prepared(Sphere{{0.0, 0.0, 0.0}, 1.0}, {}, /*inverse=*/true);
    EXPECT_EQ(shape_normal(s, {1.0, 0.0, 0.0}, 0), glm::dvec3(-1, 0, 0));
}

TEST(Shapes, IntervalIsClosedAndRespected) {
    const auto s = prepared(Plane{{0.0, 1.0, 0.0}, 0.0});
    ShapeHit h;
    EXPECT_TRUE(intersect_shape(s, {0, 2, 0}, {0, -1, 0}, 0.0, 2.0, h));
    EXPECT_EQ(h.t, 2.0);
    EXPECT_TRUE(intersect_shape(s, {0, 2, 0}, {0, -1, 0}, 2.0, 3.0, h));
    EXPECT_FALSE(intersect_shape(s, {0, 2, 0}, {0, -1, 0}, 0.0, 1.999, h));
    // Negative t_min finds a surface just behind the origin (polyline joints need it).
    const auto sphere = prepared(Sphere{{0.0, 0.0, 0.0}, 1.0});
    EXPECT_TRUE(intersect_shape(sphere, {0, 0, 1.0 + 1e-12}, {0, 0, 1}, -1e-9, 10.0, h));
    EXPECT_NEAR(h.t, -1e-12, 1e-15);
    const auto box = prepared(Box{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}});
    EXPECT_TRUE(intersect_shape(box, {0, 0, -1.0 + 1e-12}, {0, 0, 1}, -1e-9, 0.5, h));
    EXPECT_NEAR(h.t, -1e-12, 1e-15);
}

TEST(Shapes, BoundsContainTheSurface) {
    // Random rays at random transformed shapes: every hit point lies in the bounds.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Transform t = then(scale({1.5, 0.7, 1.2}),
                             then(rotate({20.0, 35.0, -10.0}), translate({0.5, 1.0, -0.3})));
    const Shape shapes[] = {Sphere{{0.2, 0.1, 0.0}, 0.8}, Box{{-0.5, -0.2, -0.4}, {0.6, 0.9, 0.3}},
                            Cylinder{{0.0, -0.5, 0.2}, {0.3, 0.7, -0.1}, 0.4, false},
                            Disc{{0.1, 0.2, 0.3}, {0.2, 1.0, 0.4}, 0.9, 0.2}};
    for (const Shape& shape : shapes) {
        const auto s = prepared(shape, t);
        const Aabb b = shape_bounds(s);
        int hits = 0;
        for (int i = 0; i < 4000; ++i) {
            const glm::dvec3 o(5.0 * u(rng), 5.0 * u(rng), 5.0 * u(rng));
            const glm::dvec3 target(u(rng), 1.0 + u(rng), u(rng));
            const glm::dvec3 d = glm::normalize(target - o);
            ShapeHit h;
            if (!intersect_shape(s, o, d, 1e-4, 1e10, h)) continue;
            ++hits;
            const glm::dvec3 p = o + h.t * d;
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(p[a], b.lo[a] - 1e-9);
                EXPECT_LE(p[a], b.hi[a] + 1e-9);
            }
            const glm::dvec3 n = shape_normal(s, p, h.part);
            EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
        }
        EXPECT_GT(hits, 200);
    }
}

TEST(Shapes, RefusesWhatPovRayRefuses) {
    auto plane = prepare_shape(primitive(Plane{{0.0, 0.0, 0.0}, 1.0}, Texture{}));
    ASSERT_FALSE(plane.ok());
    EXPECT_EQ(plane.message(), "plane: degenerate normal (zero length)");
    auto disc =
        prepare_shape(primitive(Disc{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0, 0.0}, Texture{}));
    EXPECT_FALSE(disc.ok());
    auto flat =
        prepare_shape(primitive(Sphere{}, Texture{}, Transform{glm::dmat4(0.0), glm::dmat4(0.0)}));
    ASSERT_FALSE(flat.ok());
    EXPECT_NE(flat.message().find("cannot be inverted"), std::string::npos);
    Transform wrong = scale({2.0, 2.0, 2.0});
    wrong.inverse = glm::dmat4(1.0);
    auto mismatched = prepare_shape(primitive(Sphere{}, Texture{}, wrong));
    ASSERT_FALSE(mismatched.ok());
    EXPECT_NE(mismatched.message().find("inverse do not match"), std::string::npos);
}

}  // namespace
}  // namespace mirage
