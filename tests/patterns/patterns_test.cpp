// Pattern values, waves and warps as POV-Ray's Evaluate_TPat and Warp_EPoint compute them,
// checked against the definitions.
#include "patterns/patterns.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/transform.h"
#include "patterns/warps.h"

namespace mirage {
namespace {

const PatternContext& ctx() { return default_pattern_context(); }

Pattern of(PatternKind kind) {
    Pattern p;
    p.kind = kind;
    return p;
}

TEST(Patterns, WavesShapeTheValue) {
    Pattern p = of(PatternKind::Gradient);
    p.gradient_axis = glm::dvec3(1, 0, 0);
    const glm::dvec3 at(0.25, 0, 0);
    EXPECT_DOUBLE_EQ(evaluate_pattern(p, at, ctx()), 0.25);
    p.wave = WaveType::Triangle;
    EXPECT_DOUBLE_EQ(evaluate_pattern(p, at, ctx()), 0.5);
    p.wave = WaveType::Sine;
    EXPECT_NEAR(evaluate_pattern(p, at, ctx()), 1.0, 1e-12);
    p.wave = WaveType::Cubic;
    EXPECT_DOUBLE_EQ(evaluate_pattern(p, at, ctx()), 0.25 * 0.25 * (3 - 0.5));
    p.wave = WaveType::Poly;
    p.exponent = 3;
    EXPECT_DOUBLE_EQ(evaluate_pattern(p, at, ctx()), 0.25 * 0.25 * 0.25);
    // frequency and phase, with POV-Ray's fmod by 1.00001.
    p.wave = WaveType::Ramp;
    p.frequency = 2;
    p.phase = 0.25;
    EXPECT_DOUBLE_EQ(evaluate_pattern(p, glm::dvec3(0.4, 0, 0), ctx()),
                     std::fmod(0.4 * 2 + 0.25, 1.00001));
    p.frequency = -1;  // negative frequencies wrap up into [0, 1)
    p.phase = 0;
    EXPECT_NEAR(evaluate_pattern(p, glm::dvec3(0.3, 0, 0), ctx()), 0.7, 1e-12);
}

TEST(Patterns, ListPatternsGiveTheirEntryIndex) {
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Checker), {0.5, 0.5, 0.5}, ctx()), 0.0);
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Checker), {1.5, 0.5, 0.5}, ctx()), 1.0);
    // Hexagon: the cell around the origin is 0, its neighbours 1 and 2.
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Hexagon), {0.0, 0, 0.01}, ctx()), 0.0);
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Hexagon), {0.0, 0, 1.3}, ctx()), 1.0);
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Hexagon), {0.0, 0, -1.3}, ctx()), 2.0);
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Cubic), {2, 1, 0}, ctx()), 0.0);
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Cubic), {0, -3, 1}, ctx()), 4.0);
    // Brick: mortar at the joints, brick elsewhere.
    Pattern b = of(PatternKind::Brick);
    EXPECT_EQ(raw_pattern_value(b, {4.0, 1.5, 1.0}, ctx()), 1.0);
    EXPECT_EQ(raw_pattern_value(b, {4.0, -0.25, 1.0}, ctx()), 0.0);  // a horizontal joint
    EXPECT_EQ(raw_pattern_value(b, {7.5, 1.5, 1.0}, ctx()), 0.0);    // a vertical joint
}

TEST(Patterns, DensityPatternsFallOffFromTheirCentre) {
    EXPECT_EQ(raw_pattern_value(of(PatternKind::Spherical), {0.6, 0, 0.8}, ctx()), 0.0);
    EXPECT_DOUBLE_EQ(raw_pattern_value(of(PatternKind::Spherical), {0.3, 0, 0.4}, ctx()), 0.5);
    EXPECT_DOUBLE_EQ(raw_pattern_value(of(PatternKind::Cylindrical), {0.3, 7, 0.4}, ctx()), 0.5);
    EXPECT_DOUBLE_EQ(raw_pattern_value(of(PatternKind::Planar), {9, -0.25, 9}, ctx()), 0.75);
    EXPECT_DOUBLE_EQ(raw_pattern_value(of(PatternKind::Boxed), {0.1, -0.3, 0.2}, ctx()), 0.7);
    EXPECT_DOUBLE_EQ(raw_pattern_value(of(PatternKind::Onion), {1.5, 0, 0}, ctx()), 0.5);
    // Radial starts at 0.25 on +z: its raw value runs from 0.25 to 1.25 (the wave folds it).
    EXPECT_DOUBLE_EQ(raw_pattern_value(of(PatternKind::Radial), {0, 0, -1}, ctx()), 1.25);
    EXPECT_DOUBLE_EQ(raw_pattern_value(of(PatternKind::Radial), {-1, 0, 0}, ctx()), 0.5);
}

TEST(Warps, TransformsComeFirstAndRepeatFolds) {
    Pattern p = of(PatternKind::Bozo);
    p.transform = make_scaling(glm::dvec3(2.0));
    EXPECT_EQ(warp_point(p, {4, 2, 0}), glm::dvec3(2, 1, 0));
    Warp repeat;
    repeat.kind = Warp::Kind::Repeat;
    repeat.axis = 0;
    repeat.width = 1.0;
    repeat.offset = glm::dvec3(0, 10, 0);
    p.warps.push_back(repeat);
    // 4 / 2 = 2 -> block 2 at 0: x 0, y moved by 2 offsets.
    const glm::dvec3 w = warp_point(p, {4.5, 2, 0});
    EXPECT_DOUBLE_EQ(w.x, 0.25);
    EXPECT_DOUBLE_EQ(w.y, 1.0 + 20.0);
}

TEST(Warps, BlackHolePullsPointsTowardItsCentre) {
    Pattern p = of(PatternKind::Bozo);
    Warp hole;
    hole.kind = Warp::Kind::BlackHole;
    hole.centre = glm::dvec3(0.0);
    hole.radius = 1.0;
    hole.strength = 1.0;
    hole.power = 2.0;
    p.warps.push_back(hole);
    // Inside: moved by (1 - r)^2 of its offset from the centre, outward from the point.
    const glm::dvec3 q = warp_point(p, {0.5, 0, 0});
    EXPECT_DOUBLE_EQ(q.x, 0.5 + 0.25 * 0.5);
    EXPECT_EQ(warp_point(p, {1.5, 0, 0}), glm::dvec3(1.5, 0, 0));  // outside: untouched
}

TEST(Warps, CubicUnfoldsTheCubesFacesIntoACross) {
    Pattern p = of(PatternKind::Bozo);
    Warp cubic;
    cubic.kind = Warp::Kind::Cubic;
    p.warps.push_back(cubic);
    // Each face's centre lands at the centre of its square of the cross (quarters across,
    // thirds up), with the distance along that face's axis as z.
    const auto near = [](const glm::dvec3& a, const glm::dvec3& b) {
        EXPECT_NEAR(glm::length(a - b), 0.0, 1e-12) << a.x << " " << a.y << " " << a.z;
    };
    near(warp_point(p, {2, 0, 0}), {0.625, 0.5, 2});         // +x
    near(warp_point(p, {-3, 0, 0}), {0.125, 0.5, 3});        // -x
    near(warp_point(p, {0, 0, 1}), {0.375, 0.5, 1});         // +z
    near(warp_point(p, {0, 0, -1}), {0.875, 0.5, 1});        // -z
    near(warp_point(p, {0, 1, 0}), {0.375, 5.0 / 6.0, 1});   // +y, above +z
    near(warp_point(p, {0, -1, 0}), {0.375, 1.0 / 6.0, 1});  // -y, below
    // Across a face: the other coordinates over the face's one.
    near(warp_point(p, {2, 1, -1}), {0.75 - 0.25 * 0.25, 1.0 / 3.0 + 0.25, 2});
}

TEST(Warps, NormalsGoThroughTheTransformsAndBack) {
    Pattern p = of(PatternKind::Bozo);
    p.transform = make_scaling(glm::dvec3(1, 4, 1));
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 1, 0));
    const glm::dvec3 there = warp_normal(p, n, false);
    EXPECT_NEAR(glm::length(there), 1.0, 1e-12);
    const glm::dvec3 back = unwarp_normal(p, there, false);
    EXPECT_NEAR(glm::length(back - n), 0.0, 1e-12);
}

}  // namespace
}  // namespace mirage
