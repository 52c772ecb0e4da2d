#include "util/edit_distance.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
    EXPECT_EQ(edit_distance("", ""), 0u);
    EXPECT_EQ(edit_distance("width", "width"), 0u);
    EXPECT_EQ(edit_distance("widht", "width"), 2u);  // a swap is two substitutions
    EXPECT_EQ(edit_distance("--with", "--width"), 1u);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
    EXPECT_EQ(edit_distance("abc", ""), 3u);
}

TEST(EditDistance, TheClosestNameBelowTheLimit) {
    const std::vector<std::string> names = {"--width", "--height", "--output", "--threads"};
    EXPECT_EQ(closest_name("--widht", names, 4), "--width");
    EXPECT_EQ(closest_name("--hieght", names, 4), "--height");
    EXPECT_EQ(closest_name("--thread", names, 4), "--threads");
    EXPECT_EQ(closest_name("--colour-map", names, 4), "");  // nothing near
    EXPECT_EQ(closest_name("--widht", names, 2), "");       // the limit is strict
}

}  // namespace
}  // namespace mirage
