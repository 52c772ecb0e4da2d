#include "util/stats.h"

#include <gtest/gtest.h>

#include "util/file_name.h"

namespace mirage {
namespace {

TEST(Percentile, TakesTheValueOfTheRoundedRank) {
    const std::vector<double> v = {5, 1, 4, 2, 3, 9, 8, 7, 6, 10, 11};  // 1..11 shuffled
    EXPECT_EQ(percentile(v, 0.0), 1.0);
    EXPECT_EQ(percentile(v, 0.5), 6.0);    // rank 5 of 0..10
    EXPECT_EQ(percentile(v, 0.95), 11.0);  // rank round(9.5) = 10
    EXPECT_EQ(percentile(v, 0.94), 10.0);  // rank round(9.4) = 9
    EXPECT_EQ(percentile(v, 1.0), 11.0);
    EXPECT_EQ(percentile({}, 0.5), 0.0);
    EXPECT_EQ(percentile({3.5}, 0.95), 3.5);
}

TEST(LowerExtension, IsTheLastComponentsExtensionInLowerCase) {
    EXPECT_EQ(lower_extension("out/Render.PNG"), ".png");
    EXPECT_EQ(lower_extension("a.tar.GZ"), ".gz");
    EXPECT_EQ(lower_extension("dir.d/file"), "");
    EXPECT_EQ(lower_extension("noext"), "");
}

}  // namespace
}  // namespace mirage
