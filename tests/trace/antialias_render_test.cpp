// The render driver with POV-Ray's antialiasing: the same bytes whatever the threads and
// tiles, every sample a camera ray, the counts in the summary, and the plain path untouched.
#include <gtest/gtest.h>

#include <cstring>

#include "parity_scenes.h"
#include "render/render.h"

namespace mirage {
namespace {

using namespace mirage::testing;

RenderSettings settings(AntialiasMethod method, int threads, int tile) {
    RenderSettings r;
    r.width = 83;  // not a multiple of POV-Ray's blocks of 32
    r.height = 45;
    r.threads = threads;
    r.tile_size = tile;
    r.progress = false;
    r.antialias.method = method;
    return r;
}

bool same_bytes(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(AntialiasRender, SameBytesWhateverTheThreadsAndTiles) {
    const Scene s = showcase_scene();
    for (const auto method : {AntialiasMethod::NonRecursive, AntialiasMethod::Recursive}) {
        auto reference = render(s, settings(method, 1, 32));
        ASSERT_TRUE(reference.ok()) << reference.message();
        for (const auto& [threads, tile] : {std::pair{2, 32}, std::pair{3, 7}, std::pair{0, 1}}) {
            auto other = render(s, settings(method, threads, tile));
            ASSERT_TRUE(other.ok());
            EXPECT_TRUE(same_bytes(other->image, reference->image))
                << threads << " threads, tiles of " << tile;
            EXPECT_EQ(other->stats.antialias.samples, reference->stats.antialias.samples);
        }
    }
}

TEST(AntialiasRender, CountsSamplesAsCameraRaysAndReportsTheShare) {
    const Scene s = showcase_scene();
    auto plain = render(s, settings(AntialiasMethod::None, 2, 32));
    auto aa = render(s, settings(AntialiasMethod::NonRecursive, 2, 32));
    ASSERT_TRUE(plain.ok() && aa.ok());
    EXPECT_FALSE(plain->stats.antialiased);
    EXPECT_EQ(plain->stats.antialias.samples, 0u);
    EXPECT_EQ(format_stats(plain->stats, 83, 45).find("antialiased"), std::string::npos);

    const AntialiasCounters& c = aa->stats.antialias;
    EXPECT_TRUE(aa->stats.antialiased);
    EXPECT_EQ(c.pixels, 83u * 45u);
    EXPECT_GT(c.pixels_supersampled, 0u);
    EXPECT_LT(c.pixels_supersampled, c.pixels);
    // Every pixel's first ray, the frames of the 3 x 2 blocks, and 9 more per supersampled
    // pixel: all through the camera (the showcase camera traces every position).
    EXPECT_EQ(c.samples, 83u * 45u + (2u * 83u + 3u * 45u) + 9u * c.pixels_supersampled);
    EXPECT_EQ(aa->stats.counters.camera_rays, c.samples);
    const std::string line = format_stats(aa->stats, 83, 45);
    EXPECT_NE(line.find("; antialiased: " + std::to_string(c.pixels_supersampled) +
                        " pixels supersampled ("),
              std::string::npos)
        << line;

    // Pixels not supersampled keep their one ray through the centre, as without antialiasing.
    int kept = 0, changed = 0;
    for (std::size_t i = 0; i < plain->image.pixels.size(); i += 3) {
        const bool same =
            std::memcmp(&plain->image.pixels[i], &aa->image.pixels[i], 3 * sizeof(float)) == 0;
        (same ? kept : changed)++;
    }
    EXPECT_GE(kept, static_cast<int>(c.pixels - c.pixels_supersampled));
    EXPECT_GT(changed, 0);
}

TEST(AntialiasRender, BadSettingsAreRefusedBeforeTracing) {
    RenderSettings r = settings(AntialiasMethod::Recursive, 1, 32);
    r.antialias.depth = 12;
    auto failed = render(showcase_scene(), r);
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.message(),
              "--antialias-depth 12: must be 1 to 9 (POV-Ray's +R clips it there)");
}

}  // namespace
}  // namespace mirage
