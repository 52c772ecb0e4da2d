#include "layers/graded.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "atmosphere/exact_ray.h"

namespace mirage {
namespace {

TEST(GradingFactor, RisesFromOneAndLevelsOffSmoothly) {
    GradedSettings st;
    st.grading = 0.1;
    st.saturation = 10.0;
    st.softness = 0.2;
    EXPECT_DOUBLE_EQ(grading_factor(st, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(grading_factor(st, 5.0), 1.05);
    EXPECT_DOUBLE_EQ(grading_factor(st, 12.0), 1.1);
    EXPECT_DOUBLE_EQ(grading_factor(st, 100.0), 1.1);
    // A continuous slope through the eased corner (8 to 12).
    for (double t : {8.0, 9.0, 10.0, 11.0, 12.0}) {
        const double a = (grading_factor(st, t) - grading_factor(st, t - 1e-6)) / 1e-6;
        const double b = (grading_factor(st, t + 1e-6) - grading_factor(st, t)) / 1e-6;
        EXPECT_NEAR(a, b, 1e-4) << t;
    }
    st.grading = 0.0;
    EXPECT_DOUBLE_EQ(grading_factor(st, 5.0), 1.0);
}

std::vector<double> levels_between(double lo, double hi, double step) {
    std::vector<double> v;
    for (double c = lo + 0.5 * step; c < hi; c += step) v.push_back(c);
    return v;
}

TEST(GradedStack, WithoutGradingTheLevelsAreHorizontal) {
    const Profile p = *preset_profile("paper");
    GradedSettings st;
    st.radial_nodes = 60;
    st.family_rays = 600;
    st.column_samples = 6000;
    const std::vector<double> lv = levels_between(eta(p, 0.05), eta(p, 3.0), 0.004);
    auto s = graded_stack(p, 1.5, -0.4, 0.4, 60.0, 4.0, st, lv);
    ASSERT_TRUE(s.ok()) << s.message();
    ASSERT_EQ(s->boundaries(), static_cast<int>(lv.size()));
    for (int k = 0; k < s->boundaries(); ++k) {
        const double want = height_of_excess(p, lv[k] * lv[k] - p.eta0 * p.eta0);
        for (size_t j = 0; j < s->radii.size(); ++j)
            EXPECT_NEAR(s->heights[k][j], want, 2e-3) << k << " " << j;  // the column's grid
    }
}

TEST(GradedStack, GradedLevelsKeepALevelRayCrossingBoundaries) {
    // A level camera ray 1.5 m up in the paper's air runs along its own turning point: in
    // horizontal layers it meets no boundary at all (the skim); with the grading it keeps
    // crossing them, none farther apart than the grading's spacing allows.
    const Profile p = *preset_profile("paper");
    GradedSettings st;
    st.radial_nodes = 400;
    st.family_rays = 1500;
    const double step = 0.002;
    st.saturation = 30.0;
    st.grading = 12 * step / eta(p, 1.5);  // twelve levels over 30 m of optical path
    const IndexRange ir = graded_index_range(p, 1.5, 4.0, st);
    const double ne = eta(p, 1.5);
    std::vector<double> lv;
    for (double c = ne + 0.5 * step - step * std::ceil((ne - ir.lo) / step); c < ir.hi; c += step)
        if (c > ir.lo) lv.push_back(c);
    auto graded = graded_stack(p, 1.5, -0.4, 0.4, 60.0, 4.0, st, lv);
    ASSERT_TRUE(graded.ok()) << graded.message();
    GradedSettings flat = st;
    flat.grading = 0.0;
    auto horizontal = graded_stack(p, 1.5, -0.4, 0.4, 60.0, 4.0, flat, lv);
    ASSERT_TRUE(horizontal.ok()) << horizontal.message();
    const MeridianPath skim = trace_meridian(*horizontal, 0.0, 25.0);
    EXPECT_EQ(skim.crossings, 0);
    const MeridianPath level = trace_meridian(*graded, 0.0, 25.0);
    EXPECT_GE(level.crossings, 6);
    double widest = 0.0;
    for (size_t i = 1; i + 1 < level.points.size(); ++i)
        widest = std::max(widest, level.points[i + 1].x - level.points[i].x);
    EXPECT_LT(widest, 5.0);
    // And it follows the exact path, which rises half a metre by 14 m, to within a few
    // centimetres, where the skimming ray stays at the eye's height.
    auto ex = make_exact_ray(p, 1.5, M_PI / 2);
    ASSERT_TRUE(ex.ok());
    EXPECT_NEAR(path_height(level, 14.0), height_at(*ex, 14.0), 0.05);
    EXPECT_GT(height_at(*ex, 14.0) - path_height(skim, 14.0), 0.4);
}

TEST(GradedStack, RefusesLevelsOutOfOrder) {
    const Profile p = *preset_profile("paper");
    GradedSettings st;
    EXPECT_FALSE(graded_stack(p, 1.5, -0.4, 0.4, 60.0, 4.0, st, {1.05, 1.04}).ok());
}

}  // namespace
}  // namespace mirage
