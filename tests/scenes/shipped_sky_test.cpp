// The skies of the shipped scenes (scenes/*.pov) have no edge: their colour changes smoothly
// with the direction, below the horizontal too.  POV-Ray's `gradient y` wraps at y = 0: just
// below the horizontal its value is just under 1, the colour map's far end, so a sky whose
// map runs from haze at 0 to deep blue at 1 shows a hard-edged blue band wherever an
// escaping ray points below the eye's horizontal (on the curved Earth, every ray that leaves
// the atmosphere far away, turned back to the eye's frame).  Each scene's sky is evaluated
// as the tracer evaluates it (sky_colour) along columns of directions from the nadir to the
// zenith, under a pixel apart; where neighbours differ by more than a few 8-bit codes (a
// cloud's edge, or a jump) the step is halved towards its steepest part until the two
// directions are 2e-14 rad apart, and what is left must be a few codes at most: the sky's
// colour is continuous.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "load/library_paths.h"
#include "scene/parser.h"
#include "test_temp.h"
#include "patterns/pigment_eval.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_scenes() {
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(fs::path(MIRAGE_SOURCE_DIR) / "scenes"))
        if (e.path().extension() == ".pov") paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    return paths;
}

// Neighbouring directions of a column are this far apart: under one pixel of every shipped
// scene at the size its header renders it (the narrowest, fata_morgana.pov at 900 pixels for
// 1.2 degrees, has 2.3e-5 rad pixels).
constexpr double kStepRad = 2e-5;
// A change of a channel's 8-bit code by more than this between neighbours is looked at
// closer.  Clouds change faster (a cloud's edge spans a few pixels), the wrap of `gradient y`
// by 60 to 150 codes.
constexpr int kMaxCodeStep = 3;
// Halvings of a step that changes more: a smooth sky's change shrinks with its interval
// (after 30 halvings the directions are 2e-14 rad apart, and a continuous colour changes by
// far less than a code); a jump (a wrap, or two colour map entries at one place) stays.
constexpr int kHalvings = 30;

struct Jump {
    int codes = 0;  // the change between the two directions, 8-bit codes (largest channel)
    double azimuth_deg = 0.0, elevation_deg = 0.0;
};

/// The scene as the tracer reads it.
Result<Scene> parse(const fs::path& path) {
    ParseOptions po;
    po.library_paths = default_library_paths(path.string());
    po.image_width = 320;
    po.image_height = 240;
    return parse_scene_file(path.string(), po);
}

/// The sky's 8-bit codes (POV-Ray's PNG) at azimuth a and elevation e, rad.
glm::ivec3 sky_codes(const Scene& scene, double a, double e) {
    const glm::dvec3 dir(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    const glm::dvec3 c = sky_colour(scene, dir);
    return {encode_srgb8(static_cast<float>(c.x)), encode_srgb8(static_cast<float>(c.y)),
            encode_srgb8(static_cast<float>(c.z))};
}

int largest_channel(const glm::ivec3& a, const glm::ivec3& b) {
    const glm::ivec3 d = glm::abs(a - b);
    return std::max(d.x, std::max(d.y, d.z));
}

struct SkySteps {
    Jump largest_step;  // between neighbours kStepRad apart
    Jump largest_jump;  // what is left of a step after kHalvings halvings
};

/// The columns at eight azimuths round the camera's heading, from straight down to straight
/// up: the largest step between neighbours, and the largest change left after halving every
/// step over kMaxCodeStep towards its steepest part.
SkySteps sky_steps(const Scene& scene) {
    const glm::dvec3 d = scene.camera.direction;
    const double heading = std::atan2(d.x, d.z);
    const int steps = static_cast<int>(std::ceil(M_PI / kStepRad));
    SkySteps r;
    for (int k = 0; k < 8; ++k) {
        const double a = heading + k * M_PI / 4.0;
        double e0 = -M_PI / 2.0;
        glm::ivec3 c0 = sky_codes(scene, a, e0);
        for (int i = 1; i <= steps; ++i) {
            const double e1 = -M_PI / 2.0 + M_PI * i / steps;
            const glm::ivec3 c1 = sky_codes(scene, a, e1);
            const int step = largest_channel(c0, c1);
            if (step > r.largest_step.codes) r.largest_step = {step, a, e0};
            if (step > kMaxCodeStep) {
                double lo = e0, hi = e1;
                glm::ivec3 clo = c0, chi = c1;
                for (int h = 0; h < kHalvings; ++h) {
                    const double mid = 0.5 * (lo + hi);
                    const glm::ivec3 cmid = sky_codes(scene, a, mid);
                    if (largest_channel(clo, cmid) >= largest_channel(cmid, chi)) {
                        hi = mid;
                        chi = cmid;
                    } else {
                        lo = mid;
                        clo = cmid;
                    }
                }
                const int left = largest_channel(clo, chi);
                if (left > r.largest_jump.codes) r.largest_jump = {left, a, lo};
            }
            e0 = e1;
            c0 = c1;
        }
    }
    for (Jump* j : {&r.largest_step, &r.largest_jump}) {
        j->azimuth_deg *= 180.0 / M_PI;
        j->elevation_deg *= 180.0 / M_PI;
    }
    return r;
}

TEST(ShippedSkies, NoColourJumpsBetweenNeighbouringDirections) {
    const auto scenes = shipped_scenes();
    ASSERT_GE(scenes.size(), 7u);
    for (const fs::path& path : scenes) {
        auto scene = parse(path);
        ASSERT_TRUE(scene.ok()) << scene.message();
        ASSERT_TRUE(scene->sky_sphere.has_value()) << path << " has no sky_sphere";
        const SkySteps s = sky_steps(*scene);
        std::printf(
            "%s: largest step %d codes (azimuth %.2f, elevation %.5f degrees), %d codes "
            "left after %d halvings\n",
            path.filename().c_str(), s.largest_step.codes, s.largest_step.azimuth_deg,
            s.largest_step.elevation_deg, s.largest_jump.codes, kHalvings);
        EXPECT_LE(s.largest_jump.codes, kMaxCodeStep)
            << path << ": the sky's colour jumps at azimuth " << s.largest_jump.azimuth_deg
            << " degrees, elevation " << s.largest_jump.elevation_deg << " degrees";
    }
}

// The check sees the wrap it is there for: the shipped skies' old form, a gradient y from
// haze to blue, jumps just below the horizontal.
TEST(ShippedSkies, TheCheckFindsTheWrapOfAGradientSky) {
    const fs::path path = testing::test_temp_path("wrapped_sky.pov");
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs(
            "#version 3.7;\n"
            "camera { location <0, 1, 0> look_at <0, 1, 10> }\n"
            "sky_sphere { pigment { gradient y color_map {\n"
            "  [0.000 color rgb <0.86, 0.88, 0.92>] [0.004 color rgb <0.66, 0.76, 0.90>]\n"
            "  [1.000 color rgb <0.25, 0.40, 0.75>] } } }\n",
            f);
        std::fclose(f);
    }
    auto scene = parse(path);
    ASSERT_TRUE(scene.ok()) << scene.message();
    const SkySteps s = sky_steps(*scene);
    EXPECT_GT(s.largest_jump.codes, 20 * kMaxCodeStep);
    EXPECT_NEAR(s.largest_jump.elevation_deg, 0.0, 1e-9);
}

}  // namespace
}  // namespace mirage
