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

// A vertical edge pattern: rows above `edge` dark, from `edge` down bright.
Image edge_image(int width, int height, int edge) {
    Image im(width, height);
    for (int y = edge; y < height; ++y)
        for (int x = 0; x < width; ++x) im.set(x, y, glm::vec3(0.8f));
    return im;
}

TEST(ImageCompare, RowShiftToleratesShiftsWithinTheRadius) {
    const Image a = edge_image(5, 10, 4);
    const Image b = edge_image(5, 10, 6);  // the edge two rows lower
    auto plain = compare_images(a, b, 0.05);
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ(plain->pixels_over, 10);  // two rows of five
    auto r1 = compare_within_rows(a, b, 1, 0.05);
    ASSERT_TRUE(r1.ok()) << r1.message();
    // Row 4 of a is bright and b's nearest bright row is 6, two rows away; row 5 of b is
    // dark and a's rows 4 to 6 are all bright.  Rows 4 and 5 differ, one from each side.
    EXPECT_EQ(r1->pixels_differing, 10);
    EXPECT_EQ(r1->pixel_count, 50);
    EXPECT_DOUBLE_EQ(r1->share(), 0.2);
    EXPECT_EQ(r1->mask.at(2, 3), glm::vec3(0.0f));
    EXPECT_EQ(r1->mask.at(2, 4), glm::vec3(1.0f));
    EXPECT_EQ(r1->mask.at(2, 5), glm::vec3(1.0f));
    EXPECT_EQ(r1->mask.at(2, 6), glm::vec3(0.0f));
    auto r2 = compare_within_rows(a, b, 2, 0.05);
    ASSERT_TRUE(r2.ok());
    EXPECT_EQ(r2->pixels_differing, 0);
}

TEST(ImageCompare, RowShiftIsSymmetricAndColumnwise) {
    Image a(3, 6), b(3, 6);
    a.set(1, 2, {1.0f, 0.0f, 0.0f});  // a red pixel that b has in another column only
    b.set(2, 2, {1.0f, 0.0f, 0.0f});
    auto ab = compare_within_rows(a, b, 3, 0.1);
    auto ba = compare_within_rows(b, a, 3, 0.1);
    ASSERT_TRUE(ab.ok() && ba.ok());
    EXPECT_EQ(ab->pixels_differing, 2);  // (1, 2) unmatched in a, (2, 2) unmatched in b
    EXPECT_EQ(ba->pixels_differing, 2);
    // Within the threshold counts as matched.
    Image c(3, 6);
    c.set(1, 2, {0.97f, 0.04f, 0.0f});
    auto ac = compare_within_rows(a, c, 0, 0.05);
    ASSERT_TRUE(ac.ok());
    EXPECT_EQ(ac->pixels_differing, 0);
    EXPECT_FALSE(compare_within_rows(a, Image(3, 5), 1, 0.1).ok());
    EXPECT_FALSE(compare_within_rows(a, b, -1, 0.1).ok());
}

TEST(ImageCompare, RowShiftRadiusPerPixel) {
    // The edge moves two rows in columns 0 to 2 and not at all in columns 3 and 4: a radius
    // of 2 where it moved and 0 elsewhere accepts it, a radius of 1 in column 1 does not.
    Image a = edge_image(5, 10, 4), b = edge_image(5, 10, 4);
    for (int x = 0; x < 3; ++x)
        for (int y = 4; y < 6; ++y) b.set(x, y, glm::vec3(0.0f));
    std::vector<int> radius(50, 0);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 3; ++x) radius[y * 5 + x] = 2;
    auto ok = compare_within_rows(a, b, radius, 0.05);
    ASSERT_TRUE(ok.ok()) << ok.message();
    EXPECT_EQ(ok->pixels_differing, 0);
    for (int y = 0; y < 10; ++y) radius[y * 5 + 1] = 1;
    auto short_radius = compare_within_rows(a, b, radius, 0.05);
    ASSERT_TRUE(short_radius.ok());
    EXPECT_EQ(short_radius->pixels_differing, 2);  // rows 4 and 5 of column 1
    EXPECT_EQ(short_radius->mask.at(1, 4), glm::vec3(1.0f));
    EXPECT_EQ(short_radius->mask.at(1, 5), glm::vec3(1.0f));
    EXPECT_FALSE(compare_within_rows(a, b, std::vector<int>(49, 0), 0.05).ok());
    radius[7] = -1;
    EXPECT_FALSE(compare_within_rows(a, b, radius, 0.05).ok());
}

}  // namespace
}  // namespace mirage
