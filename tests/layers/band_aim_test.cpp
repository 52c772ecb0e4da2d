#include "layers/band_aim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "atmosphere/profile.h"
#include "layers/revolution.h"
#include "layers/stack.h"

namespace mirage {
namespace {

// Layers of the paper's hot-sand profile around an eye at 1.5 m, and of a cold-ground one
// (looming) around an eye at 2 m: rays turn below the eye in the first, above it in the
// second.
LayerStack paper_stack() {
    LayerStack s;
    s.profile = *preset_profile("paper");
    s.heights = {0.05, 0.2, 0.5, 0.9, 1.2, 1.45, 1.8, 2.5};
    for (double y : {0.0, 0.1, 0.35, 0.7, 1.05, 1.33, 1.5, 2.1, 10.0})
        s.excess.push_back(eta_sq_excess(s.profile, y));
    return s;
}

LayerStack superior_stack() {
    LayerStack s;
    s.profile = *preset_profile("paper-superior");
    s.heights = {0.5, 1.2, 1.9, 2.3, 3.0, 4.0, 6.0};
    for (double y : {0.2, 0.8, 1.5, 2.0, 2.6, 3.5, 5.0, 30.0})
        s.excess.push_back(eta_sq_excess(s.profile, y));
    return s;
}

// The walk's closed form against the vector tracer (POV-Ray's ratios), on both stacks: the
// same height at every distance, turns included.
TEST(BandWalk, HeightsAreTheVectorTracersOnEverySheet) {
    for (const auto& [stack, eye] :
         {std::pair{paper_stack(), 1.5}, std::pair{superior_stack(), 2.0}}) {
        const RevolutionStack r = revolution_of(stack, eye);
        const BandWalk walk(r);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> el(-0.25, 0.25), dist(0.5, 80.0);
        int turned = 0;
        for (int i = 0; i < 2000; ++i) {
            const double e = el(rng), at = dist(rng);
            const MeridianPath p = trace_meridian(r, e, at, 100000, true);
            if (p.cut_off || p.ground) continue;    // the walk continues below the ground
            const double want = p.points.back().y;  // traced to `at`
            EXPECT_NEAR(walk.height_at(e, at), want, 1e-9 * (1.0 + at)) << e << " at " << at;
            if (walk.turns_before(e, at) > 0) ++turned;
        }
        EXPECT_GT(turned, 50);  // the comparison covers turned paths
    }
}

// Aimed through a point of a band path, from a guess a few pixels off, the search finds that
// path's elevation, and the vector tracer's path from it passes through the point.
TEST(BandWalk, ElevationThroughAPointIsFoundNearTheGuess) {
    const RevolutionStack r = revolution_of(paper_stack(), 1.5);
    const BandWalk walk(r);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> el(-0.45, 0.1), dist(1.0, 60.0), off(-3.0, 3.0);
    const double pixel = 1e-3;
    int found = 0;
    for (int i = 0; i < 300; ++i) {
        const double e = el(rng), at = dist(rng);
        const double y = walk.height_at(e, at);
        if (!(y > 0.0)) continue;
        const double tol = 1e-6 * at;
        const auto got = elevation_through(walk, at, y, e + off(rng) * pixel, pixel, tol, 0.1);
        ASSERT_TRUE(got.has_value()) << e << " at " << at;
        ++found;
        const MeridianPath p = trace_meridian(r, *got, at, 100000, true);
        EXPECT_NEAR(p.points.back().y, y, 2.0 * tol) << e << " at " << at;
    }
    EXPECT_GT(found, 200);
}

// Two sheets pass through a point below the horizon beyond the fold (the upright image from
// above, the inverted one from below): the search keeps the one nearest its guess.
TEST(BandWalk, ElevationThroughKeepsTheSheetOfItsGuess) {
    const RevolutionStack r = revolution_of(paper_stack(), 1.5);
    const BandWalk walk(r);
    const double at = 30.0;
    // A path that has turned before 30 m, and where the untouched sheet (still falling there)
    // passes the same height.
    double turned = 0.0, direct = 0.0, y = 0.0;
    for (double e = -0.3; e < 0.0 && direct == 0.0; e += 1e-3) {
        if (walk.turns_before(e, at) != 1) continue;
        y = walk.height_at(e, at);
        if (!(y > 0.1 && y < 1.4)) continue;
        for (double d = -0.2; d < 0.0; d += 1e-5)
            if (walk.turns_before(d, at) == 0 && walk.turns_before(d + 1e-5, at) == 0 &&
                walk.height_at(d, at) <= y && walk.height_at(d + 1e-5, at) > y) {
                turned = e;
                direct = d;
                break;
            }
    }
    ASSERT_NE(direct, 0.0);
    ASSERT_GT(std::fabs(direct - turned), 1e-3);
    const double tol = 1e-7;
    const auto a = elevation_through(walk, at, y, turned + 3e-5, 1e-4, tol, 0.1);
    const auto b = elevation_through(walk, at, y, direct, 1e-4, tol, 0.1);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(walk.turns_before(*a, at), 1);
    EXPECT_EQ(walk.turns_before(*b, at), 0);
    EXPECT_NEAR(walk.height_at(*a, at), y, tol);
    EXPECT_NEAR(walk.height_at(*b, at), y, tol);
    EXPECT_NEAR(*a, turned, 1e-4);
    EXPECT_NEAR(*b, direct, 2e-5);
}

// A ray leaving the eye at elevation_leaving_at(f) rises above the layers at exactly f, float
// iors and all.
TEST(BandWalk, LeavesForTheSkyAtTheAskedElevation) {
    for (const auto& [stack, eye] :
         {std::pair{paper_stack(), 1.5}, std::pair{superior_stack(), 2.0}}) {
        const RevolutionStack r = revolution_of(stack, eye);
        const BandWalk walk(r);
        for (double f : {0.01, 0.05, 0.2, 0.6}) {
            const auto e = walk.elevation_leaving_at(f);
            if (!e) continue;
            const MeridianPath p = trace_meridian(r, *e, 1e4, 100000, true);
            ASSERT_FALSE(p.ground) << f;
            EXPECT_NEAR(std::atan2(p.direction.y, p.direction.x), f, 1e-12) << f;
        }
    }
}

// A mesh camera's face carries its direction with the largest component +-1 and the others
// as floats; the cross product POV-Ray takes of its float vertices is exactly that vector
// (positive multiple), for every pivot and sign.
TEST(MeshCamera, FaceNormalIsTheCarriedDirectionExactly) {
    std::mt19937 rng(5);
    std::normal_distribution<double> g;
    int pivots[3] = {0, 0, 0};
    for (int i = 0; i < 3000; ++i) {
        glm::dvec3 d(g(rng), g(rng), g(rng));
        d /= std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        const MeshDirection m = mesh_direction(d);
        ++pivots[m.pivot];
        EXPECT_EQ(std::fabs(m.value[m.pivot]), 1.0f);
        const MeshFace f = mesh_face(m);
        const glm::dvec3 v1(f.p2), v2(f.p3);
        const glm::dvec3 n(v2.y * v1.z - v2.z * v1.y, v2.z * v1.x - v2.x * v1.z,
                           v2.x * v1.y - v2.y * v1.x);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(n[k], static_cast<double>(m.value[k])) << i;
        // What POV-Ray traces is the direction to float precision.
        const glm::dvec3 t = mesh_camera_direction(d);
        EXPECT_LT(std::acos(std::min(1.0, t.x * d.x + t.y * d.y + t.z * d.z)), 2e-7) << i;
    }
    for (int k = 0; k < 3; ++k) EXPECT_GT(pivots[k], 500);
}

}  // namespace
}  // namespace mirage
