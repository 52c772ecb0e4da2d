// Comparing two images with OpenImageIO's ImageBufAlgo: RMSE, PSNR, largest difference,
// pixels over a threshold, and a difference image.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "util/result.h"

namespace mirage {

/// How far apart two images of the same size are, over all pixels and channels, in the
/// images' own units (code / 255 for PNGs read by `read_image`).
struct ImageComparison {
    double rmse = 0.0;       // root mean square difference over all samples
    double psnr_db = 0.0;    // 20 log10(1 / rmse); +infinity for identical images
    double max_error = 0.0;  // largest absolute difference of one sample
    int max_x = 0;           // pixel with the largest difference
    int max_y = 0;
    std::int64_t pixels_over = 0;  // pixels with a channel differing by more than threshold
    std::int64_t pixel_count = 0;
};

/// Compares `a` and `b` (which must have the same size).  `threshold` is the difference of
/// one channel above which a pixel counts in `pixels_over`.
Result<ImageComparison> compare_images(const Image& a, const Image& b, double threshold);

/// |a - b| per channel (same size required).
Result<Image> difference_image(const Image& a, const Image& b);

}  // namespace mirage
