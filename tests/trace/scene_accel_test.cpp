#include "trace/scene_accel.h"

#include <gtest/gtest.h>

#include <random>

#include "scene_builders.h"

namespace mirage {
namespace {

using namespace mirage::testing;

/// Many random shapes of every kind, some transformed, plus two planes.
Scene random_scene(int count, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Scene s;
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, -3.0}, Texture{}));
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 c(8.0 * u(rng), 2.0 * u(rng), 8.0 * u(rng));
        const double r = 0.2 + 0.3 * (u(rng) + 1.0);
        Shape shape;
        switch (i % 5) {
            case 0:
                shape = Sphere{c, r};
                break;
            case 1:
                shape = Box{c - glm::dvec3(r), c + glm::dvec3(r, 0.5 * r, 1.5 * r)};
                break;
            case 2:
                shape = Cylinder{c, c + glm::dvec3(u(rng), 1.0, u(rng)), 0.5 * r, i % 2 == 0};
                break;
            case 3:
                shape = Disc{c, {u(rng), 1.0, u(rng)}, r, 0.3 * r};
                break;
            default:
                shape = Sphere{c, r};
                break;
        }
        Transform t;
        if (i % 3 == 0) {
            t = then(translate(-c),
                     then(scale({1.0 + 0.5 * (u(rng) + 1.0), 1.0, 0.7}),
                          then(rotate({30.0 * u(rng), 90.0 * u(rng), 0.0}), translate(c))));
        }
        Primitive p = primitive(shape, Texture{}, t);
        p.no_shadow = i % 4 == 1;
        s.primitives.push_back(p);
    }
    s.primitives.push_back(primitive(Plane{{0.3, 0.0, 1.0}, 12.0}, Texture{}));
    return s;
}

/// The closest hit by testing every shape, ties to the lower index.
std::optional<std::pair<double, int>> brute_force(const SceneAccel& accel, const glm::dvec3& o,
                                                  const glm::dvec3& d, double t_min, double t_max,
                                                  bool shadow_only, const Scene& scene) {
    std::optional<std::pair<double, int>> best;
    for (int i = 0; i < accel.primitive_count(); ++i) {
        if (shadow_only && scene.primitives[i].no_shadow) continue;
        ShapeHit h;
        if (intersect_shape(accel.shape(i), o, d, t_min, t_max, h) &&
            (!best || h.t < best->first)) {
            best = std::make_pair(h.t, i);
        }
    }
    return best;
}

TEST(SceneAccel, AgreesWithTestingEveryShape) {
    const Scene scene = random_scene(300, 11);
    auto accel = SceneAccel::build(scene);
    ASSERT_TRUE(accel.ok()) << accel.message();
    EXPECT_EQ(accel->unbounded().size(), 2u);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 o(12.0 * u(rng), 4.0 * u(rng), 12.0 * u(rng));
        const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), 0.5 * u(rng), u(rng)));
        const double t_max = i % 2 ? 1e30 : 6.0;
        const auto expected = brute_force(*accel, o, d, 1e-4, t_max, false, scene);
        const auto got = accel->closest_hit(o, d, 1e-4, t_max);
        ASSERT_EQ(got.has_value(), expected.has_value()) << i;
        if (got) {
            ++hits;
            EXPECT_EQ(got->t, expected->first);
            EXPECT_EQ(got->primitive, expected->second);
            EXPECT_EQ(got->point, o + got->t * d);
        }
        const auto blocker = brute_force(*accel, o, d, 1e-3, t_max, true, scene);
        EXPECT_EQ(accel->any_shadow_hit(o, d, 1e-3, t_max), blocker.has_value()) << i;
    }
    EXPECT_GT(hits, 10000);
}

TEST(SceneAccel, TiesGoToTheFirstPrimitive) {
    Scene s;
    s.primitives.push_back(primitive(Sphere{{0.0, 0.0, 5.0}, 1.0}, Texture{}));
    s.primitives.push_back(primitive(Plane{{0.0, 0.0, 1.0}, 4.0}, Texture{}));  // same point
    s.primitives.push_back(primitive(Sphere{{0.0, 0.0, 5.0}, 1.0}, Texture{}));
    auto accel = SceneAccel::build(s);
    ASSERT_TRUE(accel.ok());
    const auto hit = accel->closest_hit({0, 0, 0}, {0, 0, 1}, 1e-4, 100.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->t, 4.0);
    EXPECT_EQ(hit->primitive, 0);
}

TEST(SceneAccel, ShadowQueriesSkipNoShadow) {
    Scene s;
    Primitive blocker = primitive(Sphere{{0.0, 0.0, 5.0}, 1.0}, Texture{});
    blocker.no_shadow = true;
    s.primitives.push_back(blocker);
    auto accel = SceneAccel::build(s);
    ASSERT_TRUE(accel.ok());
    EXPECT_TRUE(accel->closest_hit({0, 0, 0}, {0, 0, 1}, 1e-4, 100.0).has_value());
    EXPECT_FALSE(accel->any_shadow_hit({0, 0, 0}, {0, 0, 1}, 1e-3, 100.0));
    s.primitives[0].no_shadow = false;
    auto casting = SceneAccel::build(s);
    EXPECT_TRUE(casting->any_shadow_hit({0, 0, 0}, {0, 0, 1}, 1e-3, 100.0));
    EXPECT_FALSE(casting->any_shadow_hit({0, 0, 0}, {0, 0, 1}, 1e-3, 3.9));
}

TEST(SceneAccel, EmptySceneAndBuildErrors) {
    Scene empty;
    auto accel = SceneAccel::build(empty);
    ASSERT_TRUE(accel.ok());
    EXPECT_FALSE(accel->closest_hit({0, 0, 0}, {0, 0, 1}, 0.0, 1e30));
    EXPECT_TRUE(accel->finite_bounds().empty());

    Scene bad;
    bad.primitives.push_back(primitive(Sphere{}, Texture{}));
    Primitive p = primitive(Plane{{0.0, 0.0, 0.0}, 0.0}, Texture{});
    p.loc = FileLoc{"bad.pov", 7, 3};
    bad.primitives.push_back(p);
    auto failed = SceneAccel::build(bad);
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.message(), "bad.pov:7:3: plane: degenerate normal (zero length)");
}

TEST(SceneAccel, ManyCoincidentShapesStillWork) {
    // Identical bounds defeat every split: the hierarchy must stay shallow and correct.
    Scene s;
    for (int i = 0; i < 500; ++i)
        s.primitives.push_back(primitive(Sphere{{0.0, 0.0, 0.0}, 1.0 + 1e-3 * i}, Texture{}));
    auto accel = SceneAccel::build(s);
    ASSERT_TRUE(accel.ok());
    const auto hit = accel->closest_hit({0, 0, -10}, {0, 0, 1}, 1e-4, 100.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 499);
    EXPECT_NEAR(hit->t, 10.0 - 1.499, 1e-12);
}

}  // namespace
}  // namespace mirage
