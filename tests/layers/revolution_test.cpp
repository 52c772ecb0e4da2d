#include "layers/revolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "atmosphere/profile.h"
#include "layers/stack.h"

namespace mirage {
namespace {

LayerStack paper_stack() {
    LayerStack s;
    s.profile = *preset_profile("paper");
    s.heights = {0.2, 0.5, 0.9, 1.2, 1.45, 1.8, 2.5};
    for (double y : {0.1, 0.35, 0.7, 1.05, 1.33, 1.5, 2.1, 4.0})
        s.excess.push_back(eta_sq_excess(s.profile, y));
    return s;
}

TEST(TraceMeridian, FlatBoundariesAreHorizontalLayers) {
    // The vector form with boundary normals and the invariant form of trace_band must agree on
    // every ray of a horizontal stack.
    const LayerStack s = paper_stack();
    const RevolutionStack r = revolution_of(s, 1.5);
    ASSERT_TRUE(well_formed(r));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> e(-0.4, 0.4);
    for (int i = 0; i < 200; ++i) {
        const double el = e(rng);
        const BandOutcome b = trace_band(s, 1.5, el, 40.0, 40.0);
        const MeridianPath p = trace_meridian(r, el, 40.0);
        EXPECT_EQ(p.ground, b.ground) << el;
        if (b.ground) {
            EXPECT_NEAR(p.points.back().x, b.dz, 1e-9 * b.dz) << el;
        } else {
            EXPECT_NEAR(p.points.back().y, b.y, 1e-9) << el;
            EXPECT_NEAR(p.direction.y / p.direction.x, b.slope, 1e-9) << el;
        }
        EXPECT_EQ(p.crossings, b.crossings) << el;
    }
}

TEST(TraceMeridian, ATiltedBoundaryRefractsAboutItsOwnNormal) {
    // One boundary rising at slope 0.1 below the eye (level at the axis, as a smooth surface
    // of revolution must be), index 1.0 beneath, 1.1 above: a ray at -20 degrees meets it at
    // 20 + atan(0.1) degrees from its plane and leaves by Snell's law.
    RevolutionStack s;
    s.eye_y = 2.0;
    s.heights = {{}};
    for (int j = 0; j <= 20; ++j) {
        s.radii.push_back(j);
        s.heights[0].push_back(1.0 + 0.1 * j);  // y = 1 + 0.1 r
    }
    s.index = {1.0, 1.1};
    ASSERT_TRUE(well_formed(s));
    const double el = -20.0 * M_PI / 180.0;
    const MeridianPath p = trace_meridian(s, el, 9.0);
    ASSERT_GE(p.points.size(), 3u);
    // Where it meets y = 1 + 0.1 r: 2 + r tan(el) = 1 + 0.1 r.
    const double r_hit = 1.0 / (0.1 - std::tan(el));
    EXPECT_NEAR(p.points[1].x, r_hit, 1e-12);
    const double tilt = std::atan(0.1);
    const double in = -el + tilt;  // angle below the boundary's plane
    const double out = std::acos(1.1 * std::cos(in) / 1.0);
    EXPECT_NEAR(std::atan2(-p.direction.y, p.direction.x), out - tilt, 1e-12);
    EXPECT_EQ(p.crossings, 1);
}

TEST(TraceMeridian, GrazingRaysReflectTotally) {
    RevolutionStack s;
    s.eye_y = 2.0;
    s.radii = {0.0};
    s.heights = {{1.0}};
    s.index = {1.0, 1.01};
    const MeridianPath p = trace_meridian(s, -0.05, 100.0);
    ASSERT_GE(p.points.size(), 3u);
    EXPECT_NEAR(p.points[1].y, 1.0, 1e-12);
    EXPECT_NEAR(p.direction.y / p.direction.x, std::tan(0.05), 1e-12);  // mirrored
    EXPECT_FALSE(p.ground);
}

TEST(RevolutionStack, WellFormedNeedsOrderedBoundariesAndNodes) {
    RevolutionStack s;
    s.eye_y = 1.0;
    s.radii = {0.0, 1.0};
    s.heights = {{0.2, 0.3}, {0.5, 0.25}};  // the second dips under the first at r = 1
    s.index = {1.0, 1.01, 1.02};
    EXPECT_FALSE(well_formed(s));
    s.heights[1][1] = 0.6;
    EXPECT_TRUE(well_formed(s));
    s.radii = {0.5, 1.0};
    EXPECT_FALSE(well_formed(s));  // nodes start on the axis
    s.radii = {0.0, 1.0};
    s.index.pop_back();
    EXPECT_FALSE(well_formed(s));
}

TEST(PathHeight, InterpolatesAlongThePath) {
    MeridianPath p;
    p.points = {{0.0, 1.0}, {2.0, 0.0}, {4.0, 2.0}};
    EXPECT_DOUBLE_EQ(path_height(p, 1.0), 0.5);
    EXPECT_DOUBLE_EQ(path_height(p, 3.0), 1.0);
    EXPECT_TRUE(std::isnan(path_height(p, 5.0)));
}

}  // namespace
}  // namespace mirage
