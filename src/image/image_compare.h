// Comparing two images with OpenImageIO's ImageBufAlgo: RMSE, PSNR, largest difference,
// pixels over a threshold, and a difference image.
#pragma once

#include <cstdint>
#include <vector>

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

/// Pixels that differ beyond a vertical shift of up to `radius_rows` rows.  A pixel of one
/// image is matched when some pixel of the other image in the same column, at most
/// `radius_rows` rows above or below, has every channel within `threshold` of it; a pixel
/// differs when it is unmatched in either direction (a against b, or b against a).
///
/// Why vertical: the atmosphere depends on height only, so a ray stays in the vertical plane
/// of its first direction, and a level camera images every vertical plane through the eye as
/// one column.  A model whose rays end a pixel or two away from the exact ones moves the
/// picture along the columns; plain per-pixel differences count every such edge as an
/// error, this comparison only what a shift of `radius_rows` cannot explain.
struct RowShiftComparison {
    std::int64_t pixels_differing = 0;
    std::int64_t pixel_count = 0;
    Image mask;  // 1 where a pixel differs, 0 elsewhere (grey)
    double share() const {
        return pixel_count > 0 ? static_cast<double>(pixels_differing) / pixel_count : 0.0;
    }
};

Result<RowShiftComparison> compare_within_rows(const Image& a, const Image& b, int radius_rows,
                                               double threshold);

/// The same with a radius for every pixel (row-major, width * height): pixel (x, y) of
/// either image looks `radius_rows[y * width + x]` rows up and down, as far as the path
/// error at that pixel can move the picture.
Result<RowShiftComparison> compare_within_rows(const Image& a, const Image& b,
                                               const std::vector<int>& radius_rows,
                                               double threshold);

}  // namespace mirage
