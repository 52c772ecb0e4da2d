// POV-Ray 3.7's antialiasing on images whose answer is known: an edge at a known place seen
// through sample functions, the threshold on POV-Ray's colour distance, method 1's blocks
// and neighbours, method 2's subdivision, and the jitter.
#include "render/antialias.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mirage {
namespace {

constexpr double kEdgeX = 10.3;  // white left of it, black right of it

/// A grey sample the camera traced (transmit 0).
glm::dvec4 grey(double v) { return {v, v, v, 0.0}; }

glm::dvec4 edge(double x, double /*y*/) { return grey(x < kEdgeX ? 1.0 : 0.0); }

AntialiasSettings settings(AntialiasMethod method, int depth) {
    AntialiasSettings s;
    s.method = method;
    s.depth = depth;
    s.jitter = 0.0;
    return s;
}

struct Rendered {
    Image image;
    AntialiasCounters counters;
};

Rendered render_block(const AntialiasSettings& s, const PixelBlock& b, const SampleFunction& f,
                      double exponent = 1.0 / 2.5) {
    Rendered r;
    r.image = Image(b.x1, b.y1);
    antialias_block(s, exponent, b, f, r.image, r.counters);
    return r;
}

TEST(Antialias, NonRecursiveLeavesAUniformImageAlone) {
    const auto s = settings(AntialiasMethod::NonRecursive, 3);
    const auto r = render_block(s, {0, 0, 20, 6}, [](double, double) { return grey(0.4); });
    EXPECT_EQ(r.counters.pixels, 120u);
    EXPECT_EQ(r.counters.pixels_supersampled, 0u);
    // Each pixel's centre, and the row above and the column left of the block.
    EXPECT_EQ(r.counters.samples, 120u + 20u + 6u);
    for (float v : r.image.pixels) EXPECT_FLOAT_EQ(v, 0.4f);
}

TEST(Antialias, NonRecursiveAveragesTheFirstRayWithAGridOfDepthSquared) {
    // Pixel 10 (centre 10.5, black): its 3 x 3 grid at x = 10 1/6, 10.5, 10 5/6 has one
    // white column, so (0 + 3) / (9 + 1) = 0.3.  Its left neighbour is all white, pixel 11
    // all black.  At depth 4: x = 10.125 white, the rest black: (0 + 4) / 17.
    for (const auto& [depth, expected] : {std::pair{3, 0.3}, std::pair{4, 4.0 / 17.0}}) {
        const auto r =
            render_block(settings(AntialiasMethod::NonRecursive, depth), {0, 0, 20, 6}, edge);
        for (int y = 0; y < 6; ++y) {
            for (int x = 0; x < 20; ++x) {
                const double want = x < 10 ? 1.0 : x == 10 ? expected : 0.0;
                EXPECT_NEAR(r.image.at(x, y).x, want, 1e-6) << "depth " << depth << " at " << x;
            }
        }
        EXPECT_EQ(r.counters.samples, 120u + 26u + r.counters.pixels_supersampled * depth * depth);
    }
}

TEST(Antialias, NonRecursiveComparesWithTheNeighbourAsItStands) {
    // Pixels 9 and 10 differ, so both are supersampled; pixel 10 is then 0.3, which differs
    // from pixel 11's black: 11 is supersampled too, though the first rays of 10 and 11 are
    // the same colour.  Three pixels a row, as POV-Ray does.
    const auto r = render_block(settings(AntialiasMethod::NonRecursive, 3), {0, 0, 20, 6}, edge);
    EXPECT_EQ(r.counters.pixels_supersampled, 3u * 6u);
}

TEST(Antialias, NonRecursiveNeverSupersamplesAcrossABlockEdge) {
    // The edge at 31.7: pixel 31 (white centre) is the last of the first block and pixel 32
    // (black) the first of the next, compared with a pixel 31 traced afresh and never
    // supersampled (POV-Ray's blocks are independent).  So pixel 31 stays white and pixel 32
    // is supersampled to black; with one block of 64, pixel 31 gets (1 + 6) / 10.
    const auto at_31_7 = [](double x, double) { return grey(x < 31.7 ? 1.0 : 0.0); };
    AntialiasSettings s = settings(AntialiasMethod::NonRecursive, 3);
    Image image(64, 2);
    AntialiasCounters counters;
    antialias_block(s, 0.4, {0, 0, 32, 2}, at_31_7, image, counters);
    antialias_block(s, 0.4, {32, 0, 64, 2}, at_31_7, image, counters);
    EXPECT_FLOAT_EQ(image.at(31, 1).x, 1.0f);
    EXPECT_FLOAT_EQ(image.at(32, 1).x, 0.0f);
    EXPECT_EQ(counters.pixels_supersampled, 2u);  // pixel 32 of each row
    Image whole(64, 2);
    AntialiasCounters one;
    antialias_block(s, 0.4, {0, 0, 64, 2}, at_31_7, whole, one);
    EXPECT_NEAR(whole.at(31, 1).x, 0.7, 1e-6);
}

TEST(Antialias, ThresholdIsTheSumOfTheGammaEncodedChannelDifferences) {
    // Grey v against black: 3 v^(1/2.5) >= 0.3 from v = 0.1^2.5 = 0.0031623.  The largest
    // channel (0.1) or the Euclidean distance (0.17) would not reach 0.3, nor would the
    // linear difference (0.0095).
    const auto step = [](double v) {
        return [v](double x, double) { return grey(x < 5.0 ? 0.0 : v); };
    };
    const auto s = settings(AntialiasMethod::NonRecursive, 3);
    EXPECT_GT(render_block(s, {0, 0, 10, 2}, step(0.00320)).counters.pixels_supersampled, 0u);
    EXPECT_EQ(render_block(s, {0, 0, 10, 2}, step(0.00312)).counters.pixels_supersampled, 0u);
    EXPECT_NEAR(antialias_distance(grey(0.0), grey(std::pow(0.1, 2.5)), 0.4), 0.3,
                1e-6);  // single precision, as POV-Ray's
    EXPECT_NEAR(antialias_distance({0.2, 0.5, 0.9, 0.0}, {0.1, 0.7, 0.4, 1.0}, 1.0),
                0.1 + 0.2 + 0.5 + 1.0, 1e-6);
    // Negative channels are clipped at 0 before encoding.
    EXPECT_DOUBLE_EQ(antialias_distance({-1.0, 0.0, 0.0, 0.0}, grey(0.0), 0.4), 0.0);
}

TEST(Antialias, WhereTheCameraGivesNoRayTransmitCounts) {
    // Black traced pixels beside positions with no camera ray (a fisheye's corners): POV-Ray
    // marks those with transmit 1, so they differ by 1 from black and are supersampled.
    const auto corner = [](double x, double) {
        return x < 5.0 ? glm::dvec4(0.0, 0.0, 0.0, 1.0) : grey(0.0);
    };
    const auto r = render_block(settings(AntialiasMethod::NonRecursive, 3), {0, 0, 10, 2}, corner);
    EXPECT_EQ(r.counters.pixels_supersampled, 2u * 2u);  // pixels 4 and 5 of each row
    for (float v : r.image.pixels) EXPECT_EQ(v, 0.0f);   // black all the same
}

TEST(Antialias, ExponentTranscodesTheWorkingGammaToTheAntialiasGamma) {
    GlobalSettings g;  // #version 3.7, assumed_gamma 1
    EXPECT_DOUBLE_EQ(antialias_exponent(g, 2.5), 0.4);
    g.assumed_gamma = 2.2;
    g.assumed_gamma_given = true;
    EXPECT_DOUBLE_EQ(antialias_exponent(g, 2.5), 0.88);
    EXPECT_DOUBLE_EQ(antialias_exponent(g, 2.2), 1.0);
    g.assumed_gamma_given = false;
    g.language_version = 3.6;  // no gamma handling: the values count as linear
    EXPECT_DOUBLE_EQ(antialias_exponent(g, 2.5), 0.4);
}

TEST(Antialias, RecursiveSubdividesWhereCornersDiffer) {
    // Pixel 10 spans [10, 11]: corners white at 10, black at 11.  Depth 1: the mean of the
    // corners, 0.5.  Depth 2: one cut, the left quarters' corners at 10 and 10.5 differ but
    // may be cut no further: (0.5 + 0) / 2.  Depth 3: the left quarters cut again at 10.25,
    // whose left eighths are white and right eighths half: ((1 + 0.5) / 2 + 0) / 2 = 0.375.
    for (const auto& [depth, expected] :
         {std::pair{1, 0.5}, std::pair{2, 0.25}, std::pair{3, 0.375}}) {
        const auto r =
            render_block(settings(AntialiasMethod::Recursive, depth), {0, 0, 20, 3}, edge);
        for (int y = 0; y < 3; ++y) {
            for (int x = 0; x < 20; ++x) {
                const double want = x < 10 ? 1.0 : x == 10 ? expected : 0.0;
                EXPECT_NEAR(r.image.at(x, y).x, want, 1e-12) << "depth " << depth << " at " << x;
            }
        }
        EXPECT_EQ(r.counters.pixels_supersampled, depth > 1 ? 3u : 0u) << depth;
    }
    // A uniform block: every pixel the mean of its corners, only the corners traced.
    const auto uniform = render_block(settings(AntialiasMethod::Recursive, 3), {0, 0, 8, 4},
                                      [](double, double) { return grey(0.25); });
    EXPECT_EQ(uniform.counters.samples, 9u * 5u);
    for (float v : uniform.image.pixels) EXPECT_FLOAT_EQ(v, 0.25f);
}

TEST(Antialias, RecursiveSamplesAtCornersNotCentres) {
    // A colour that changes within a pixel but equals at its corners: method 2 never sees it.
    const auto stripes = [](double x, double) {
        return grey(std::abs(x - std::round(x)) < 0.25 ? 1.0 : 0.0);
    };
    const auto r = render_block(settings(AntialiasMethod::Recursive, 3), {0, 0, 6, 2}, stripes);
    EXPECT_EQ(r.counters.pixels_supersampled, 0u);
    for (float v : r.image.pixels) EXPECT_FLOAT_EQ(v, 1.0f);
    const auto m1 = render_block(settings(AntialiasMethod::NonRecursive, 3), {0, 0, 6, 2}, stripes);
    for (float v : m1.image.pixels) EXPECT_FLOAT_EQ(v, 0.0f);  // centres black, none differ
}

TEST(Antialias, JitterMovesSubSamplesWithinHalfACellReproducibly) {
    std::vector<glm::dvec2> seen;
    const auto recording = [&seen](double x, double y) {
        seen.emplace_back(x, y);
        return edge(x, y);
    };
    AntialiasSettings s = settings(AntialiasMethod::NonRecursive, 3);
    s.jitter = 1.0;
    render_block(s, {0, 0, 20, 2}, recording);
    // The sub-samples of pixel 10 in row 0: within half a cell of their grid points, and
    // moved.
    int moved = 0, found = 0;
    for (const auto& p : seen) {
        if (p.x < 10.0 || p.x >= 11.0 || p.y < 0.0 || p.y >= 1.0 || p == glm::dvec2(10.5, 0.5))
            continue;
        ++found;
        const glm::dvec2 cell = (p - glm::dvec2(10.0, 0.0)) * 3.0;
        const glm::dvec2 grid = glm::floor(cell) + 0.5;
        EXPECT_LE(std::abs(cell.x - grid.x), 0.5) << p.x << ", " << p.y;
        EXPECT_LE(std::abs(cell.y - grid.y), 0.5) << p.x << ", " << p.y;
        moved += glm::distance(cell, grid) > 1e-6;
    }
    EXPECT_EQ(found, 9);
    EXPECT_GE(moved, 8);
    // The same seed gives the same image; another seed another (a colour that changes
    // everywhere, so that every moved sample shows).
    const auto ramp = [](double x, double y) { return edge(x, y) + grey(1e-3 * x * y); };
    const auto b = render_block(s, {0, 0, 20, 2}, ramp);
    EXPECT_EQ(b.image.pixels, render_block(s, {0, 0, 20, 2}, ramp).image.pixels);
    s.jitter_seed = 7;
    EXPECT_NE(b.image.pixels, render_block(s, {0, 0, 20, 2}, ramp).image.pixels);
    // Offsets over [-0.5, 0.5), centred.
    double sum = 0.0;
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec2 o = jitter_offset(3, 0.1 * i, 0.7 * i);
        EXPECT_GE(o.x, -0.5);
        EXPECT_LT(o.x, 0.5);
        EXPECT_GE(o.y, -0.5);
        EXPECT_LT(o.y, 0.5);
        sum += o.x + o.y;
    }
    EXPECT_LT(std::abs(sum / 2000.0), 0.03);
}

TEST(Antialias, RecursiveJitterSparesTheCorners) {
    std::vector<glm::dvec2> seen;
    AntialiasSettings s = settings(AntialiasMethod::Recursive, 3);
    s.jitter = 1.0;
    render_block(s, {0, 0, 20, 1}, [&seen](double x, double y) {
        seen.emplace_back(x, y);
        return edge(x, y);
    });
    int off_grid = 0;
    for (const auto& p : seen) {
        const glm::dvec2 quarter = p * 4.0;
        const double off = glm::distance(quarter, glm::round(quarter)) / 4.0;
        // POV-Ray's jitter for depth 3 is at most half of 1 / (2^3 + 1) pixel.
        EXPECT_LE(off, 0.5 / 9.0 * std::sqrt(2.0) + 1e-12);
        off_grid += off > 1e-9;
    }
    EXPECT_EQ(seen.size() - off_grid, 21u * 2u);  // the corners, on the grid
    EXPECT_GT(off_grid, 0);
}

TEST(Antialias, SettingsOutsidePovRaysRangesAreRefusedByOption) {
    AntialiasSettings s;
    s.method = AntialiasMethod::NonRecursive;
    EXPECT_TRUE(check_antialias(s).ok());
    s.threshold = 1.5;
    EXPECT_EQ(check_antialias(s).message(),
              "--antialias 1.5: the threshold must be in [0, 1] (POV-Ray's +A clips it there)");
    s.threshold = 0.3;
    s.depth = 10;
    EXPECT_EQ(check_antialias(s).message(),
              "--antialias-depth 10: must be 1 to 9 (POV-Ray's +R clips it there)");
    s.depth = 0;
    EXPECT_FALSE(check_antialias(s).ok());
    s.depth = 3;
    s.jitter = -0.1;
    EXPECT_EQ(check_antialias(s).message(),
              "--jitter -0.1: the amount must be in [0, 1] (POV-Ray's +J clips it there)");
    s.jitter = NAN;
    EXPECT_FALSE(check_antialias(s).ok());
    s.method = AntialiasMethod::None;  // off: nothing to check
    EXPECT_TRUE(check_antialias(s).ok());
}

TEST(Antialias, Label) {
    AntialiasSettings s;
    EXPECT_EQ(antialias_label(s), "off");
    s.method = AntialiasMethod::Recursive;
    s.jitter = 0.0;
    EXPECT_EQ(antialias_label(s), "method 2 (recursive), threshold 0.3, depth 3, jitter off");
}

}  // namespace
}  // namespace mirage
