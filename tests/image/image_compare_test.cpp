#include "image/image_compare.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mirage {
namespace {

TEST(ImageCompare, IdenticalImagesHaveInfinitePsnr) {
    Image a(4, 3);
    a.set(1, 1, {0.3f, 0.4f, 0.5f});
    auto c = compare_images(a, a, 0.01);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->rmse, 0.0);
    EXPECT_TRUE(std::isinf(c->psnr_db));
    EXPECT_EQ(c->pixels_over, 0);
    EXPECT_EQ(c->pixel_count, 12);
}

TEST(ImageCompare, MatchesTheDefinitions) {
    Image a(4, 4);
    Image b(4, 4);
    b.set(2, 3, {0.5f, 0.0f, 0.25f});   // two channels of one pixel differ
    b.set(0, 0, {0.0f, 0.005f, 0.0f});  // a small difference, under the threshold
    auto c = compare_images(a, b, 0.01);
    ASSERT_TRUE(c.ok()) << c.message();
    const double mse = (0.5 * 0.5 + 0.25 * 0.25 + 0.005 * 0.005) / (16.0 * 3.0);
    EXPECT_NEAR(c->rmse, std::sqrt(mse), 1e-7);
    EXPECT_NEAR(c->psnr_db, 20.0 * std::log10(1.0 / std::sqrt(mse)), 1e-4);
    EXPECT_NEAR(c->max_error, 0.5, 1e-7);
    EXPECT_EQ(c->max_x, 2);
    EXPECT_EQ(c->max_y, 3);
    EXPECT_EQ(c->pixels_over, 1);  // pixels, not channels
}

TEST(ImageCompare, DifferenceImageIsAbsolute) {
    Image a(2, 1);
    Image b(2, 1);
    a.set(0, 0, {0.2f, 0.8f, 0.5f});
    b.set(0, 0, {0.5f, 0.3f, 0.5f});
    auto d = difference_image(a, b);
    ASSERT_TRUE(d.ok());
    EXPECT_NEAR(d->at(0, 0).x, 0.3f, 1e-6);
    EXPECT_NEAR(d->at(0, 0).y, 0.5f, 1e-6);
    EXPECT_EQ(d->at(0, 0).z, 0.0f);
    EXPECT_EQ(d->at(1, 0), glm::vec3(0.0f));
}

TEST(ImageCompare, RefusesDifferentSizes) {
    auto c = compare_images(Image(2, 2), Image(2, 3), 0.1);
    ASSERT_FALSE(c.ok());
    EXPECT_EQ(c.message(), "cannot compare images of different sizes: 2x2 and 2x3");
    EXPECT_FALSE(difference_image(Image(1, 1), Image(2, 1)).ok());
}

}  // namespace
}  // namespace mirage
