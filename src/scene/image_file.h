// The image file of an image_map or bump_map, read while the scene is parsed (POV-Ray reads
// it there too, so that a missing or broken file is an error at its place in the scene).
#pragma once

#include <string>
#include <vector>

#include "util/result.h"

namespace mirage {

/// An image as stored, with its alpha: 4 floats per pixel (code / 255 for 8-bit files, no
/// linearisation), top row first.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;
    bool has_alpha = false;
    double file_gamma = 0.0;  // the file's own decoding gamma; 0: none given (sRGB)
};

/// Reads an image for an image map: its colour (grey spread to rgb) and alpha (1 without).
Result<RgbaImage> read_image_rgba(const std::string& path);

}  // namespace mirage
