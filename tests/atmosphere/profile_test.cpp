#include "atmosphere/profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mirage {
namespace {

TEST(Profile, PaperPresetMatchesThePaper) {
    auto p = preset_profile("paper");
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p->kind, ProfileKind::Inferior);
    EXPECT_EQ(p->eta0, 1.000233);
    EXPECT_EQ(p->eta1, 0.4584);
    EXPECT_EQ(p->alpha, 2.303);
    // The paper's index aloft: sqrt(1.000233^2 + 0.4584^2) = 1.1003 (DESIGN.md).
    EXPECT_NEAR(eta_infinity(*p), 1.10027, 1e-5);
}

TEST(Profile, HotRoadIsTheGladstoneDaleFitOfTheReference) {
    // The reference rays use this fit; the values are the reference file's, bit for bit
    // up to the last place of the square root.
    auto p = preset_profile("hot-road");
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p->kind, ProfileKind::Inferior);
    EXPECT_EQ(p->eta0, 1.00026383734375);
    EXPECT_NEAR(p->eta1, 0.005931939247071331, 4e-18);
    EXPECT_EQ(p->alpha, 3.3333333333333335);
}

TEST(Profile, ColdSeaIsSuperior) {
    auto p = preset_profile("cold-sea");
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p->kind, ProfileKind::Superior);
    EXPECT_NEAR(p->eta0, 1.0002981739360763, 1e-16);
    EXPECT_NEAR(p->eta1, 0.004510955280279839, 1e-17);
    EXPECT_EQ(p->alpha, 0.2);
    EXPECT_LT(eta_infinity(*p), p->eta0);
}

TEST(Profile, ExcessIsExactForTinyHeights) {
    Profile p{ProfileKind::Inferior, 1.0003, 1e-6, 2.303};
    // eta^2 - eta0^2 = eta1^2 alpha y to first order: no cancellation at y = 1e-12.
    EXPECT_NEAR(eta_sq_excess(p, 1e-12) / (1e-12 * 2.303e-12), 1.0, 1e-11);
    EXPECT_DOUBLE_EQ(height_of_excess(p, eta_sq_excess(p, 0.37)), 0.37);
    EXPECT_TRUE(std::isinf(height_of_excess(p, 1e-12)));
}

TEST(Profile, SuperiorIndexFallsWithHeight) {
    auto p = preset_profile("paper-superior");
    ASSERT_TRUE(p.ok());
    EXPECT_GT(eta(*p, 0.0), eta(*p, 1.0));
    EXPECT_NEAR(eta_infinity(*p), 1.000233, 1e-15);
}

TEST(Profile, RefusesBadValuesNamingThem) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(make_profile(ProfileKind::Inferior, 1.0, 0.1, 0.0).message(),
              "alpha = 0 must be from 1e-09 to 1e+09 (1/m)");
    EXPECT_EQ(make_profile(ProfileKind::Inferior, 1.0, -0.1, 1.0).message(),
              "eta1 = -0.1 must be 0 or from 1e-10 to 10");
    EXPECT_EQ(make_profile(ProfileKind::Inferior, 0.9, 0.1, 1.0).message(),
              "eta0 = 0.9 must be a refractive index from 1 to 10");
    EXPECT_EQ(make_profile(ProfileKind::Inferior, nan, 0.1, 1.0).message(),
              "eta0 = nan must be a refractive index from 1 to 10");
    EXPECT_EQ(make_profile(ProfileKind::Superior, 1.0, 1.0, 1.0).message(),
              "eta1 = 1: a superior profile needs eta0^2 > eta1^2, and eta0 = 1 (the index "
              "aloft would not be real)");
    // The values that stop the exact rays: each refused with its range.
    EXPECT_EQ(make_profile(ProfileKind::Inferior, 1.0003, 1e200, 1.0).message(),
              "eta1 = 1e+200 must be 0 or from 1e-10 to 10");
    EXPECT_EQ(make_profile(ProfileKind::Inferior, 1e308, 0.1, 1.0).message(),
              "eta0 = 1e+308 must be a refractive index from 1 to 10");
    EXPECT_EQ(make_profile(ProfileKind::Inferior, 1.0003, 0.1, 1e308).message(),
              "alpha = 1e+308 must be from 1e-09 to 1e+09 (1/m)");
    EXPECT_EQ(make_profile(ProfileKind::Inferior, 1.0003, 1e-300, 1.0).message(),
              "eta1 = 1e-300 must be 0 or from 1e-10 to 10");
    EXPECT_TRUE(make_profile(ProfileKind::Inferior, 1.0003, 0.0, 1.0).ok());
    const ProfileNames names{"s.pov:1:10: Mirage_Eta0", "s.pov:2:10: Mirage_Eta1",
                             "s.pov:3:10: Mirage_Alpha"};
    EXPECT_EQ(validate(Profile{ProfileKind::Inferior, 1.0003, 0.1, 1e308}, names).message(),
              "s.pov:3:10: Mirage_Alpha = 1e+308 must be from 1e-09 to 1e+09 (1/m)");
    EXPECT_EQ(preset_profile("desert").message(),
              "unknown preset 'desert' (known: paper, paper-superior, hot-road, cold-sea)");
}

}  // namespace
}  // namespace mirage
