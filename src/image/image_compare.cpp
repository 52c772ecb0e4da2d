#include "image/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mirage {

namespace {

namespace OIIO = OIIO_NAMESPACE;

/// An ImageBuf wrapping the image's pixels without copying (ImageBufAlgo only reads it).
OIIO::ImageBuf wrap(const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
    return OIIO::ImageBuf(spec, const_cast<float*>(image.pixels.data()));
}

Status check_same_size(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) {
        return make_error("cannot compare images of different sizes: " + std::to_string(a.width) +
                          "x" + std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                          std::to_string(b.height));
    }
    if (a.empty()) return make_error("cannot compare empty images");
    return Ok{};
}

}  // namespace

Result<ImageComparison> compare_images(const Image& a, const Image& b, double threshold) {
    if (auto s = check_same_size(a, b); !s) return s.error();
    const OIIO::ImageBuf A = wrap(a);
    const OIIO::ImageBuf B = wrap(b);
    const auto r = OIIO::ImageBufAlgo::compare(A, B, static_cast<float>(threshold),
                                               static_cast<float>(threshold));
    // r.error only says that some pixel exceeded failthresh: not an error here.
    ImageComparison c;
    c.rmse = r.rms_error;
    c.psnr_db = r.rms_error > 0.0 ? r.PSNR : std::numeric_limits<double>::infinity();
    c.max_error = r.maxerror;
    c.max_x = r.maxx;
    c.max_y = r.maxy;
    c.pixels_over = static_cast<std::int64_t>(r.nfail);
    c.pixel_count = static_cast<std::int64_t>(a.width) * a.height;
    return c;
}

Result<Image> difference_image(const Image& a, const Image& b) {
    if (auto s = check_same_size(a, b); !s) return s.error();
    const OIIO::ImageBuf A = wrap(a);
    const OIIO::ImageBuf B = wrap(b);
    Image out(a.width, a.height);
    OIIO::ImageSpec spec(a.width, a.height, 3, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf D(spec, out.pixels.data());
    if (!OIIO::ImageBufAlgo::absdiff(D, A, B)) {
        return make_error("difference image failed: " + D.geterror());
    }
    return out;
}

namespace {

/// Whether pixel (x, y) of `a` has a pixel of `b` within `radius` rows in its column whose
/// channels are all within `threshold` of its own.
bool matched_in_column(const Image& a, const Image& b, int x, int y, int radius, float threshold) {
    const glm::vec3 c = a.at(x, y);
    const int y0 = std::max(0, y - radius), y1 = std::min(b.height - 1, y + radius);
    for (int yy = y0; yy <= y1; ++yy) {
        const glm::vec3 d = glm::abs(b.at(x, yy) - c);
        if (std::max({d.x, d.y, d.z}) <= threshold) return true;
    }
    return false;
}

}  // namespace

Result<RowShiftComparison> compare_within_rows(const Image& a, const Image& b,
                                               const std::vector<int>& radius_rows,
                                               double threshold) {
    if (auto s = check_same_size(a, b); !s) return s.error();
    const std::size_t n = static_cast<std::size_t>(a.width) * a.height;
    if (radius_rows.size() != n)
        return make_error("row radii: " + std::to_string(radius_rows.size()) + " for " +
                          std::to_string(n) + " pixels");
    if (!(threshold >= 0.0)) return make_error("threshold must be >= 0");
    RowShiftComparison c;
    c.pixel_count = static_cast<std::int64_t>(n);
    c.mask = Image(a.width, a.height);
    const float t = static_cast<float>(threshold);
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const int r = radius_rows[static_cast<std::size_t>(y) * a.width + x];
            if (r < 0) return make_error("row radius " + std::to_string(r) + " < 0");
            if (matched_in_column(a, b, x, y, r, t) && matched_in_column(b, a, x, y, r, t))
                continue;
            ++c.pixels_differing;
            c.mask.set(x, y, glm::vec3(1.0f));
        }
    }
    return c;
}

Result<RowShiftComparison> compare_within_rows(const Image& a, const Image& b, int radius_rows,
                                               double threshold) {
    if (radius_rows < 0) return make_error("row radius " + std::to_string(radius_rows) + " < 0");
    if (auto s = check_same_size(a, b); !s) return s.error();
    return compare_within_rows(
        a, b, std::vector<int>(static_cast<std::size_t>(a.width) * a.height, radius_rows),
        threshold);
}

}  // namespace mirage
