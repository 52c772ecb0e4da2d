// Test helper of the POV-Ray image tests: the built-in tracer's render of a scene, as
// POV-Ray's 8-bit PNG of the same scene would hold it, to compare the two pixel by pixel.
#pragma once

#include <filesystem>
#include <string>

#include "image/image.h"
#include "image/image_io.h"
#include "trace_scene/trace_scene.h"
#include "util/result.h"

namespace mirage::testing {

/// `mirage trace` of `scene` at width x height, its paths within tolerance_px of the exact
/// ones (straight rays when `atmosphere` is false), written to `png` (kept beside POV-Ray's
/// render); the image quantized to 8-bit sRGB codes.
inline Result<Image> trace_png(const std::string& scene, const std::filesystem::path& png,
                               int width, int height, double tolerance_px, bool atmosphere = true) {
    TraceOptions o;
    o.scene = scene;
    o.output = png.string();
    o.width = width;
    o.height = height;
    o.tolerance_px = tolerance_px;
    o.atmosphere = atmosphere;
    o.progress = false;
    auto r = trace_scene(o);
    if (!r) return r.error();
    return quantize_srgb8(r->render.image);
}

}  // namespace mirage::testing
