// Test helper: a scene file rendered by POV-Ray and by the tracer (straight rays), compared.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "povray_runner.h"
#include "scene/parser.h"
#include "render/render.h"

namespace mirage::testing {

/// PSNR (dB) between POV-Ray's render of `pov_text` and the tracer's, both 8-bit PNGs of
/// width x height; -1 when either fails (the test is failed then).  Files stay in
/// build/test_output/<group>/<name>/.
inline double parity_psnr(const std::string& group, const std::string& name,
                          const std::string& pov_text, int width, int height) {
    const auto dir = test_dir(group, name);
    auto pov = render_with_povray(pov_text, dir, "povray", width, height);
    EXPECT_TRUE(pov.ok()) << pov.message();
    if (!pov.ok()) return -1.0;
    ParseOptions options;
    options.image_width = width;
    options.image_height = height;
    options.library_paths = {"/usr/share/povray-3.7/include"};
    auto parsed = parse_scene_text(pov_text, (dir / "povray.pov").string(), options);
    EXPECT_TRUE(parsed.ok()) << parsed.message();
    if (!parsed.ok()) return -1.0;
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.progress = false;
    auto ours = render(*parsed, settings);
    EXPECT_TRUE(ours.ok()) << ours.message();
    if (!ours.ok()) return -1.0;
    const std::string png = (dir / "mirage.png").string();
    EXPECT_TRUE(write_png(ours->image, png).ok());
    auto ours_read = read_image(png);
    EXPECT_TRUE(ours_read.ok());
    if (!ours_read.ok()) return -1.0;
    auto cmp = compare_images(*pov, *ours_read, 2.5 / 255.0);
    EXPECT_TRUE(cmp.ok());
    if (!cmp.ok()) return -1.0;
    std::printf("%s: PSNR %.2f dB, %lld of %lld pixels over 2.5/255 (%s)\n", name.c_str(),
                cmp->psnr_db, static_cast<long long>(cmp->pixels_over),
                static_cast<long long>(cmp->pixel_count), dir.string().c_str());
    return cmp->psnr_db;
}

}  // namespace mirage::testing
