// POV-Ray's noise: its tables and the properties its patterns rely on.  That the values are
// POV-Ray's own is checked image by image in pov_material_parity_test.cpp.
#include "patterns/noise.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

namespace mirage {
namespace {

TEST(Noise, HashTableIsAPermutation) {
    std::set<int> seen;
    for (int a = 0; a < 4096; ++a) seen.insert(hash3d(a, 0, 0));
    EXPECT_EQ(seen.size(), 4096u);
    EXPECT_EQ(*seen.begin(), 0);
    EXPECT_EQ(*seen.rbegin(), 4095);
    // Only the low 12 bits of each coordinate count.
    EXPECT_EQ(hash3d(5, 7, 9), hash3d(5 + 4096, 7 - 4096, 9 + 8192));
}

TEST(Noise, PatternRandsAreTheDefaultMersenneTwistersDraws) {
    // boost's uniform_real over mt19937 seeded 5489: draw / 2^32; the 10000th draw of the
    // generator is the C++ standard's check value 4123659995.
    EXPECT_EQ(pattern_rand(0), 3499211612.0 / 4294967296.0);
    EXPECT_EQ(pattern_rand(9999), 4123659995.0 / 4294967296.0);
    EXPECT_EQ(pattern_rand(32768 + 3), pattern_rand(3));  // the sequence repeats
}

TEST(Noise, GeneratorsStayInRangeAndTwoRescalesOne) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-50.0, 50.0);
    int inside = 0;
    double lo3 = 1, hi3 = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        const double g1 = noise(p, 1), g2 = noise(p, 2), g3 = noise(p, 3);
        for (double v : {g1, g2, g3}) {
            ASSERT_GE(v, 0.0);
            ASSERT_LE(v, 1.0);
        }
        lo3 = std::min(lo3, g3);
        hi3 = std::max(hi3, g3);
        // Generators 1 and 2 share the lattice sum: 1 adds 0.5, 2 stretches POV-Ray's measured
        // range -1.05242 to 0.988997 onto [0, 1].
        if (g1 > 0.0 && g1 < 1.0) {
            ++inside;
            EXPECT_NEAR(g2, std::clamp((g1 - 0.5 + 1.05242) * 0.48985582, 0.0, 1.0), 1e-12);
        }
    }
    EXPECT_GT(inside, 15000);
    EXPECT_GT(hi3 - lo3, 0.7);
}

TEST(Noise, IsContinuousAcrossCellsAndDNoiseToo) {
    for (double x : {-3.0, -1.0, 0.0, 1.0, 7.0}) {
        for (int g = 1; g <= 3; ++g) {
            const double a = noise(glm::dvec3(x - 1e-9, 0.3, 0.6), g);
            const double b = noise(glm::dvec3(x + 1e-9, 0.3, 0.6), g);
            EXPECT_NEAR(a, b, 1e-6) << "x = " << x << ", generator " << g;
        }
        const glm::dvec3 a = dnoise(glm::dvec3(x - 1e-9, 0.3, 0.6));
        const glm::dvec3 b = dnoise(glm::dvec3(x + 1e-9, 0.3, 0.6));
        EXPECT_NEAR(glm::length(a - b), 0.0, 1e-6) << "x = " << x;
    }
}

TEST(Noise, TurbulenceAddsOctaves) {
    Turbulence one;
    one.octaves = 1;
    const glm::dvec3 p(0.3, 1.7, -2.2);
    // One octave is the clipped noise itself.
    EXPECT_EQ(turbulence(p, one, 1), noise(p, 1));
    EXPECT_EQ(turbulence(p, one, 2), std::clamp(2.0 * noise(p, 2) - 0.5, 0.0, 1.0));
    Turbulence two = one;
    two.octaves = 2;
    two.lambda = 2.0;
    two.omega = 0.5;
    EXPECT_DOUBLE_EQ(turbulence(p, two, 1), noise(p, 1) + 0.5 * noise(2.0 * p, 1));
    EXPECT_EQ(dturbulence(p, one), dnoise(p));
}

TEST(Noise, WavesAndCycloidal) {
    EXPECT_NEAR(cycloidal(0.25), 1.0, 1e-12);
    EXPECT_NEAR(cycloidal(-0.25), -1.0, 1e-12);
    EXPECT_NEAR(cycloidal(1.25), 1.0, 1e-12);  // period 1
    EXPECT_EQ(triangle_wave(0.25), 0.5);
    EXPECT_EQ(triangle_wave(0.5), 1.0);
    EXPECT_EQ(triangle_wave(-0.25), 0.5);
    EXPECT_EQ(pov_floor(-2.0), -3.0);  // POV-Ray's FLOOR is one lower at negative integers
    EXPECT_EQ(pov_floor(-2.5), -3.0);
    EXPECT_EQ(pov_floor(2.0), 2.0);
    const WaveSources w = make_wave_sources(10);
    ASSERT_EQ(w.sources.size(), 10u);
    for (std::size_t i = 0; i < 10; ++i) {
        EXPECT_NEAR(glm::length(w.sources[i]), 1.0, 1e-12);
        EXPECT_GT(w.frequencies[i], 0.01);
        EXPECT_LT(w.frequencies[i], 1.02);
    }
}

}  // namespace
}  // namespace mirage
