// Test helper: a scene file's text rendered by POV-Ray (`povray -D -A`) and by the tracer
// (parsed with POV-Ray's include directory, gamma applied as mirage trace applies it,
// written and read back as an 8-bit PNG), for comparisons of the two images.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "povray_runner.h"
#include "scene/parser.h"
#include "render/render.h"
#include "trace_scene/trace_scene.h"

namespace mirage::testing {

inline const char* kPovIncludeDir = "/usr/share/povray-3.7/include";

struct TextRenders {
    Image povray;  // code / 255
    Image tracer;  // code / 255
    bool ok = false;
    std::string message;
};

/// Renders `text` both ways into test_output/<group>/<name>/.
inline TextRenders render_text_both(const std::string& text, const std::string& group,
                                    const std::string& name, int width, int height) {
    TextRenders r;
    const auto dir = test_dir(group, name);
    auto pov = render_with_povray(text, dir, "povray", width, height);
    if (!pov.ok()) {
        r.message = pov.message();
        return r;
    }
    ParseOptions options;
    options.image_width = width;
    options.image_height = height;
    options.library_paths = {kPovIncludeDir};
    auto scene = parse_scene_text(text, (dir / "povray.pov").string(), options);
    if (!scene.ok()) {
        r.message = scene.message();
        return r;
    }
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.progress = false;
    auto rendered = render(*scene, settings);
    if (!rendered.ok()) {
        r.message = rendered.message();
        return r;
    }
    apply_output_gamma(rendered->image, scene->global);
    const std::string png = (dir / "mirage.png").string();
    if (auto s = write_png(rendered->image, png); !s.ok()) {
        r.message = s.message();
        return r;
    }
    auto ours = read_image(png);
    if (!ours.ok()) {
        r.message = ours.message();
        return r;
    }
    r.povray = std::move(*pov);
    r.tracer = std::move(*ours);
    r.ok = true;
    return r;
}

/// PSNR (dB) of a rectangle of two images of the same size (+infinity where identical).
inline double region_psnr(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    long n = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const glm::vec3 d = a.at(x, y) - b.at(x, y);
            sum += static_cast<double>(d.x) * d.x + static_cast<double>(d.y) * d.y +
                   static_cast<double>(d.z) * d.z;
            n += 3;
        }
    }
    if (sum == 0.0 || n == 0) return INFINITY;
    return 20.0 * std::log10(1.0 / std::sqrt(sum / n));
}

inline double image_psnr(const Image& a, const Image& b) {
    return region_psnr(a, b, 0, 0, a.width, a.height);
}

}  // namespace mirage::testing
