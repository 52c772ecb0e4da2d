#include "image/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

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

}  // namespace mirage
