#include "compare/tradeoff.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mirage {
namespace {

TEST(ParetoFront, KeepsOnlyPointsNothingBeatsSortedByTime) {
    const auto front = pareto_front({{4.0, 0.01, "slow good"},
                                     {1.0, 0.10, "fast bad"},
                                     {2.0, 0.20, "dominated"},  // slower and worse than 1 s
                                     {2.5, 0.05, "middle"},
                                     {3.0, 0.05, "no better"},        // slower for the same error
                                     {3.5, 0.0498, "hardly better"},  // 0.4 % less error
                                     {0.0, 0.01, "no time"},
                                     {1.5, NAN, "no error"}});
    ASSERT_EQ(front.size(), 3u);
    EXPECT_EQ(front[0].label, "fast bad");
    EXPECT_EQ(front[1].label, "middle");
    EXPECT_EQ(front[2].label, "slow good");
}

TEST(SecondsAtError, InterpolatesInLogLogBetweenNeighbours) {
    // error = 0.1 * seconds^-1 between the points: the log-log line through them.
    const auto front = pareto_front({{1.0, 0.1, "a"}, {10.0, 0.01, "b"}, {100.0, 0.005, "c"}});
    auto t = seconds_at_error(front, std::sqrt(0.1 * 0.01));
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->seconds, std::sqrt(10.0), 1e-12);
    EXPECT_EQ(t->from, "a");
    EXPECT_EQ(t->to, "b");
    EXPECT_FALSE(t->at_most);
    // At a point, its own time.
    t = seconds_at_error(front, 0.01);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(t->seconds, 10.0);
    EXPECT_EQ(t->from, "b");
    EXPECT_EQ(t->to, "b");
    // Above the fastest point's error: its time, as an upper bound.
    t = seconds_at_error(front, 0.5);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(t->seconds, 1.0);
    EXPECT_TRUE(t->at_most);
    // Below the finest point's error: the curve never gets there.
    EXPECT_FALSE(seconds_at_error(front, 0.001));
}

TEST(SecondsAtError, AFinestPointOfErrorZeroInterpolatesLinearlyInError) {
    const auto front = pareto_front({{1.0, 0.1, "a"}, {4.0, 0.0, "b"}});
    auto t = seconds_at_error(front, 0.05);
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->seconds, 2.0, 1e-12);  // halfway in error, geometric mean in time
}

TEST(CompareAtEqualError, UsesTheLowestErrorBothReach) {
    const auto uniform = pareto_front({{1.0, 0.08, "8"}, {2.0, 0.04, "16"}, {8.0, 0.02, "64"}});
    const auto adaptive = pareto_front({{0.5, 0.04, "4"}, {1.0, 0.01, "1"}});
    auto e = compare_at_equal_error(uniform, adaptive);
    ASSERT_TRUE(e);
    EXPECT_DOUBLE_EQ(e->error, 0.02);
    EXPECT_DOUBLE_EQ(e->a.seconds, 8.0);
    EXPECT_NEAR(e->b.seconds, 0.5 * std::pow(2.0, 0.5), 1e-12);  // halfway in log error
    EXPECT_NEAR(e->speedup(), 8.0 / (0.5 * std::sqrt(2.0)), 1e-12);
    EXPECT_FALSE(compare_at_equal_error(uniform, {}));
}

}  // namespace
}  // namespace mirage
