#include "layers/stack.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "camera_column.h"
#include "layers/band_tracer3d.h"
#include "layers/fit.h"

namespace mirage {
namespace {

using testing::exact_indices;

LayerStack two_layers(double n_below, double n_above, double h) {
    LayerStack s;
    s.profile = Profile{ProfileKind::Inferior, 1.0, 0.5, 1.0};
    s.heights = {h};
    s.excess = {n_below * n_below - 1.0, n_above * n_above - 1.0};
    return s;
}

TEST(BandTrace, RefractsBySnellsLawAtABoundary) {
    const LayerStack s = two_layers(1.1, 1.2, 1.0);
    const double e = 0.3;  // from 0.5 m, upward
    const BandOutcome b = trace_band(s, 0.5, e, 100.0, 100.0);
    // n cos e is conserved: 1.1 cos 0.3 = 1.2 cos e1.
    const double e1 = std::acos(1.1 * std::cos(e) / 1.2);
    EXPECT_NEAR(b.final_slope, std::tan(e1), 1e-14);
    EXPECT_TRUE(b.sky);
    EXPECT_EQ(b.crossings, 1);
    const double z1 = 0.5 / std::tan(e);
    EXPECT_NEAR(b.y, 1.0 + (100.0 - z1) * std::tan(e1), 1e-11);
}

TEST(BandTrace, ReflectsTotallyBelowTheCriticalAngle) {
    const LayerStack s = two_layers(1.0, 1.1, 1.0);  // ground layer has the lower index
    const double e = -0.2;                           // from 2 m, downward
    const double crit = std::acos(1.0 / 1.1);
    ASSERT_LT(std::fabs(e), crit);
    const BandOutcome b = trace_band(s, 2.0, e, 50.0, 50.0);
    EXPECT_FALSE(b.ground);
    EXPECT_EQ(b.crossings, 1);
    // Mirror path: back at 2 m after 2 / tan 0.2 m, then rising at the same angle.
    EXPECT_NEAR(b.y, 2.0 + (50.0 - 2.0 * 1.0 / std::tan(0.2)) * std::tan(0.2), 1e-11);
    const BandOutcome steep = trace_band(s, 2.0, -0.6, 50.0, 50.0);
    EXPECT_TRUE(steep.ground);
    EXPECT_EQ(steep.crossings, 1);
}

// The 2D invariant trace the fit uses and the 3D vector trace POV-Ray's geometry implies
// agree on a fitted stack, ray by ray.
TEST(BandTrace, InvariantTraceAgreesWithTheVectorTrace) {
    const Profile p = *preset_profile("paper");
    std::vector<DesignRay> rays;
    for (int i = 0; i < 60; ++i) {
        DesignRay r;
        r.elevation = -0.4 + 0.5 * i / 59.0;
        r.exit_dz = 60.0;
        r.pixel_rad = 0.0034;
        rays.push_back(r);
    }
    LayerFitSettings st;
    const FitResult f = fit_layers(p, 1.5, rays, st);
    ASSERT_GT(f.stack.boundaries(), 10);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-0.45, 0.3);
    const HorizontalBox scene{-60, 60, -60, 60}, layers{-6000, 6000, -6000, 6000};
    for (int i = 0; i < 500; ++i) {
        const double e = u(rng);
        const BandOutcome b = trace_band(f.stack, 1.5, e, 60.0, 6000.0);
        const Trace3dOutcome t = trace_layers_3d(f.stack, glm::dvec3(0.0, 1.5, 0.0),
                                                 glm::dvec3(0.0, std::sin(e), std::cos(e)), scene,
                                                 layers, exact_indices());
        ASSERT_EQ(b.ground, t.ground) << e;
        EXPECT_EQ(b.crossings, t.crossings) << e;
        EXPECT_NEAR(b.y, t.scene_point.y, 1e-9) << e;
        EXPECT_NEAR(b.dz, t.scene_point.z, 1e-9 * b.dz) << e;
        EXPECT_EQ(b.sky, t.sky) << e;
        if (b.sky) {
            EXPECT_NEAR(std::atan(b.final_slope), std::asin(t.final_dir.y), 1e-10) << e;
        }
    }
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

// Real air near the eye: neighbouring layers whose indices differ by less than POV-Ray's
// float can tell, over the camera's.
LayerStack air_stack() {
    LayerStack s;
    s.profile = *preset_profile("hot-road");
    s.heights = {0.1, 0.5, 1.0, 1.45, 1.55, 2.0};
    const double u_cam = eta_sq_excess(s.profile, 1.5);
    s.excess = {eta_sq_excess(s.profile, 0.05),
                eta_sq_excess(s.profile, 0.3),
                eta_sq_excess(s.profile, 0.7),
                u_cam + 1e-13,  // as the camera's, to a float
                u_cam,
                u_cam - 2e-13,  // likewise
                eta_sq_excess(s.profile, 3.0)};
    return s;
}

TEST(MergeInvisibleBoundaries, JoinsLayersOfOneFloatIor) {
    const LayerStack s = air_stack();
    const int k_cam = s.layer_at(1.5);
    ASSERT_EQ(k_cam, 4);
    ASSERT_EQ(pov_relative_ior(s, k_cam, 3), 1.0f);
    ASSERT_EQ(pov_relative_ior(s, k_cam, 5), 1.0f);
    const LayerStack m = merge_invisible_boundaries(s, 1.5);
    ASSERT_TRUE(well_formed(m));
    // The camera's layer now runs from 1.0 to 2.0, with the camera's own index.
    ASSERT_EQ(m.boundaries(), 4);
    EXPECT_EQ(m.heights, (std::vector<double>{0.1, 0.5, 1.0, 2.0}));
    EXPECT_EQ(m.excess[m.layer_at(1.5)], s.excess[k_cam]);
    // No boundary left that POV-Ray would pass as a free continued ray.
    const int m_cam = m.layer_at(1.5);
    for (int j = 0; j < m.boundaries(); ++j)
        EXPECT_NE(pov_relative_ior(m, m_cam, j), pov_relative_ior(m, m_cam, j + 1)) << j;
    // The medium is the same to the index steps the merge dropped (du <= 2e-13): every ray's
    // outcome is the same in both, event for event, its final slope within du / (2 |slope|)
    // and its height within that times the 300 m it may run.  (With POV-Ray's precision the two
    // differ by the rounding of its divisions: from the camera's layer it divides in double,
    // between two others in single precision.)
    const HorizontalBox scene{-300, 300, -300, 300}, layers{-3e5, 3e5, -3e5, 3e5};
    for (double e : {-0.006, -0.004, -0.002, -0.0005, 0.0, 0.001, 0.004}) {
        const glm::dvec3 dir(0.0, std::sin(e), std::cos(e));
        Trace3dOptions to = exact_indices();
        to.camera_y = 1.5;
        const auto a = trace_layers_3d(s, glm::dvec3(0, 1.5, 0), dir, scene, layers, to);
        const auto b = trace_layers_3d(m, glm::dvec3(0, 1.5, 0), dir, scene, layers, to);
        EXPECT_EQ(a.ground, b.ground) << e;
        EXPECT_EQ(a.crossings, b.crossings) << e;
        const double slope_tol = 1.01 * 2e-13 / (2.0 * std::fabs(a.final_dir.y)) + 1e-15;
        EXPECT_NEAR(a.final_dir.y, b.final_dir.y, slope_tol) << e;
        EXPECT_NEAR(a.scene_point.y, b.scene_point.y, 300.0 * slope_tol) << e;
    }
}

TEST(MergeInvisibleBoundaries, KeepsAStackPovRaySeesWhole) {
    LayerStack s;
    s.profile = *preset_profile("paper");
    s.heights = {0.5, 1.0, 2.0};
    s.excess = {0.01, 0.05, 0.1, 0.2};
    const LayerStack m = merge_invisible_boundaries(s, 1.5);
    EXPECT_EQ(m.heights, s.heights);
    EXPECT_EQ(m.excess, s.excess);
}

}  // namespace
}  // namespace mirage
