#include "patterns/pigment_eval.h"

#include <gtest/gtest.h>

#include "trace/scene_builders.h"

namespace mirage {
namespace {

using namespace mirage::testing;

TEST(Checker, AlternatesOnUnitCubesWithPovRaysEpsilon) {
    const Pigment p = checker(rgb(1, 1, 1), rgb(0, 0, 0));
    EXPECT_EQ(evaluate_pigment(p, {0.5, 0.5, 0.5}).rgb, glm::dvec3(1.0));   // floor sum 0
    EXPECT_EQ(evaluate_pigment(p, {1.5, 0.5, 0.5}).rgb, glm::dvec3(0.0));   // 1
    EXPECT_EQ(evaluate_pigment(p, {1.5, 0.0, -0.5}).rgb, glm::dvec3(1.0));  // 1 + 0 - 1
    EXPECT_EQ(evaluate_pigment(p, {-0.5, 0.0, 0.5}).rgb, glm::dvec3(0.0));
    // A point a hair below an integer counts as on it (floor(x + 1e-10)): a plane at y = 0
    // computed as -1e-17 takes the colour of y = 0.
    EXPECT_EQ(evaluate_pigment(p, {0.5, -1e-17, 0.5}).rgb, glm::dvec3(1.0));
    EXPECT_EQ(evaluate_pigment(p, {0.5, -1e-9, 0.5}).rgb, glm::dvec3(0.0));
}

TEST(Checker, FollowsItsTransform) {
    const Pigment p = checker(rgb(1, 0, 0), rgb(0, 0, 1), scale({2.0, 2.0, 2.0}));
    EXPECT_EQ(evaluate_pigment(p, {1.5, 0.5, 0.5}).rgb, glm::dvec3(1, 0, 0));  // 2x larger checks
    EXPECT_EQ(evaluate_pigment(p, {2.5, 0.5, 0.5}).rgb, glm::dvec3(0, 0, 1));
    // Colours are held in single precision, as POV-Ray holds them.
    const Pigment q = solid(rgb(0.1, 0.2, 0.3));
    EXPECT_EQ(evaluate_pigment(q, {0, 0, 0}).rgb.x, static_cast<double>(0.1f));
}

TEST(Gradient, DefaultMapIsBlackToWhiteAndWraps) {
    const Pigment p = gradient({0.0, 1.0, 0.0}, {});
    EXPECT_NEAR(evaluate_pigment(p, {0, 0.25, 0}).rgb.x, 0.25, 1e-15);
    EXPECT_NEAR(evaluate_pigment(p, {0, 1.75, 0}).rgb.x, 0.75, 1e-12);   // fmod
    EXPECT_NEAR(evaluate_pigment(p, {0, -0.25, 0}).rgb.x, 0.75, 1e-15);  // negative wraps up
    EXPECT_EQ(evaluate_pigment(p, {0, 1.0, 0}).rgb.x, 1.0);              // 1 stays 1
    EXPECT_EQ(evaluate_pigment(p, {0, -1.0, 0}).rgb.x, 0.0);
}

TEST(Gradient, AxisIsNormalisedAndMapInterpolated) {
    const Pigment p =
        gradient({0.0, 0.0, 4.0}, {{0.2, rgb(1, 0, 0)}, {0.6, rgb(0, 1, 0)}, {0.6, rgb(0, 0, 1)}});
    EXPECT_EQ(evaluate_pigment(p, {0, 0, 0.1}).rgb, glm::dvec3(1, 0, 0));  // below the first
    const glm::dvec3 mid = evaluate_pigment(p, {0, 0, 0.4}).rgb;
    const double f =
        (0.4 - static_cast<double>(0.2f)) / (static_cast<double>(0.6f) - static_cast<double>(0.2f));
    EXPECT_NEAR(mid.x, 1.0 - f, 1e-12);
    EXPECT_NEAR(mid.y, f, 1e-12);
    // At an entry shared by two colours (a sharp step), the later entry wins from there on.
    EXPECT_EQ(evaluate_pigment(p, {0, 0, 0.9}).rgb, glm::dvec3(0, 0, 1));
}

TEST(PatternValue, GradientAlongAnOffAxisVector) {
    Pigment p = gradient({1.0, 1.0, 0.0}, {});
    EXPECT_NEAR(pattern_value(p, {0.5, 0.5, 7.0}), std::sqrt(0.5), 1e-15);
}

TEST(Sky, BackgroundIsPrecomposedOverBlack) {
    // POV-Ray 3.7 renders background { rgbt <0.5, 0.5, 0.5, 0.5> } as code 137 = rgb 0.25:
    // its parser multiplies by 1 - transmit and drops filter.
    Scene s;
    s.background = Colour{glm::dvec3(0.2, 0.4, 0.6), 0.3, 0.5};
    EXPECT_NEAR(glm::length(sky_colour(s, {0, 1, 0}) - glm::dvec3(0.1, 0.2, 0.3)), 0.0, 1e-7);
}

TEST(Sky, TheLastPigmentIsOnTopAndTransmitShowsWhatIsBelow) {
    // As POV-Ray: sky_sphere { pigment { rgb <1,0,0> } pigment { rgbt <0,0,1,0.5> } } shows
    // half blue over half red (measured: codes 188 0 188).
    Scene s;
    SkySphere sky;
    sky.pigments.push_back(solid(rgb(1, 0, 0)));
    sky.pigments.push_back(solid(Colour{glm::dvec3(0, 0, 1), 0.0, 0.5}));
    s.sky_sphere = sky;
    s.background = rgb(0, 1, 0);  // hidden behind the opaque red layer
    EXPECT_NEAR(glm::length(sky_colour(s, {0, 0, 1}) - glm::dvec3(0.5, 0.0, 0.5)), 0.0, 1e-12);
    // A fully transmitting sky shows the background; filter tints it.
    s.sky_sphere->pigments = {solid(Colour{glm::dvec3(1.0, 0.5, 0.0), 1.0, 0.0})};
    EXPECT_NEAR(glm::length(sky_colour(s, {0, 0, 1}) - glm::dvec3(0.0, 0.5, 0.0)), 0.0, 1e-12);
}

TEST(Sky, EmissionScalesTheSkyPigmentsNotTheBackground) {
    Scene s;
    SkySphere sky;
    sky.pigments.push_back(solid(Colour{glm::dvec3(0.5, 0.5, 0.5), 0.0, 0.5}));
    sky.emission = glm::dvec3(2.0, 1.0, 0.0);
    s.sky_sphere = sky;
    s.background = rgb(0.2, 0.2, 0.2);
    // 0.5 opaque share of 0.5 grey times the emission, plus half the background.
    EXPECT_NEAR(glm::length(sky_colour(s, {0, 0, 1}) - glm::dvec3(0.6, 0.35, 0.1)), 0.0, 1e-7);
}

TEST(Sky, EvaluatesTheDirectionInTheSkysSpace) {
    Scene s;
    SkySphere sky;
    sky.pigments.push_back(gradient({0, 1, 0}, {}));
    sky.transform = rotate({0.0, 0.0, 90.0});  // y rotated onto -x
    s.sky_sphere = sky;
    EXPECT_NEAR(sky_colour(s, {-1, 0, 0}).x, 1.0, 1e-12);
    EXPECT_NEAR(sky_colour(s, {0.6, 0.8, 0}).x, 0.4, 1e-12);  // wrapped: -0.6 + 1
}

}  // namespace
}  // namespace mirage
