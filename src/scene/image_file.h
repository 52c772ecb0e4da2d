// The image file of an image_map or bump_map, read while the scene is parsed (POV-Ray reads
// it there too, so that a missing or broken file is an error at its place in the scene).
#pragma once

#include <cstdint>
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

/// The most pixels an image map's or a height field's image may have: its pixels are held as
/// floats (16 bytes a pixel and as much again while the file is decoded).
constexpr long long kMaxImagePixels = 4096LL * 4096;

/// An error naming the file when width x height is more than kMaxImagePixels.
Status check_image_pixels(const std::string& path, long long width, long long height);

/// Reads an image for an image map: its colour (grey spread to rgb) and alpha (1 without).
Result<RgbaImage> read_image_rgba(const std::string& path);

/// An image as a height field's heights, POV-Ray's HF_VAL (0..65535), top row first.
struct HeightImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> heights;
};

/// Reads a height field's image as POV-Ray 3.7's image_height_at (imageutil.cpp) turns pixels
/// into heights: a palette image's index * 256, a grey image's value scaled to 0..65535, a
/// colour image of more than 8 bits its grey, one of 8 bits red * 256 + green (the tga/pot
/// convention).  PNG files are read by libpng, which keeps palette indices; other files by
/// OpenImageIO, which does not (their palettes count as colour).
Result<HeightImage> read_height_image(const std::string& path);

}  // namespace mirage
