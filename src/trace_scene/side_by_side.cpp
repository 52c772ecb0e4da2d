#include "trace_scene/side_by_side.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "image/image_io.h"
#include "report/contact_sheet.h"
#include "util/check.h"
#include "util/output_set.h"

namespace mirage {

namespace {

namespace OIIO = OIIO_NAMESPACE;

constexpr float kGround = 0.12f;  // the background round the pictures, code / 255
constexpr float kInk = 0.93f;     // the labels

/// The first of the caption fonts OpenImageIO can draw with; empty when none.
std::string find_label_font(int font_px) {
    for (const auto& name : caption_fonts()) {
        // The probe holds the glyph whole: OpenImageIO 2.4 asserts on text outside the image.
        OIIO::ImageBuf probe(OIIO::ImageSpec(2 * font_px, 2 * font_px, 3, OIIO::TypeDesc::FLOAT));
        if (OIIO::ImageBufAlgo::render_text(probe, 0, font_px, "x", font_px, name)) return name;
    }
    return "";
}

void paste_codes(OIIO::ImageBuf& buf, const Image& codes, int x0, int y0) {
    for (int y = 0; y < codes.height; ++y) {
        for (int x = 0; x < codes.width; ++x) {
            const glm::vec3 c = codes.at(x, y);
            const float rgb[3] = {c.x, c.y, c.z};
            buf.setpixel(x0 + x, y0 + y, rgb, 3);
        }
    }
}

/// A label centred in a strip `width` x `height`, drawn on the strip alone so that it cannot
/// run into the other half, and only when it fits (OpenImageIO 2.4 asserts on text that
/// reaches past the image).
void draw_label(OIIO::ImageBuf& buf, const std::string& text, const std::string& font, int font_px,
                int x0, int y0, int width, int height) {
    OIIO::ImageBuf strip(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::fill(strip, {kGround, kGround, kGround});
    const OIIO::ROI extent = OIIO::ImageBufAlgo::text_size(text, font_px, font);
    if (extent.defined() && extent.width() <= width && extent.height() <= height) {
        const int x = (width - extent.width()) / 2 - extent.xbegin;
        const int y = (height - extent.height()) / 2 - extent.ybegin;
        OIIO::ImageBufAlgo::render_text(strip, x, y, text, font_px, font, {kInk, kInk, kInk});
    }
    OIIO::ImageBufAlgo::paste(buf, x0, y0, 0, 0, strip);
}

/// The largest size up to `font_px` at which every label fits `width` x `height`.
int fitting_font_px(const std::string& font, int font_px, int width, int height) {
    for (; font_px > 6; --font_px) {
        bool fits = true;
        for (const char* label : {kWithoutMirageLabel, kWithMirageLabel}) {
            const OIIO::ROI e = OIIO::ImageBufAlgo::text_size(label, font_px, font);
            fits = fits && e.defined() && e.width() <= width && e.height() <= height;
        }
        if (fits) break;
    }
    return font_px;
}

}  // namespace

Result<SideBySideReport> trace_side_by_side(const TraceOptions& options) {
    if (auto s = check_image_name(options.output); !s) return s.error();
    const std::string ext = std::filesystem::path(options.output).extension().string();
    if (ext == ".exr" || ext == ".EXR")
        return make_error(options.output +
                          ": --side-by-side writes an 8-bit PNG with its labels; name a .png");
    TraceOptions o = options;
    o.output.clear();
    SideBySideReport r;
    o.atmosphere = true;
    auto with = trace_scene(o);
    if (!with) return with.error();
    if (with->mode == PathMode::Straight)
        return make_error(options.scene + ": the atmosphere (" + with->atmosphere +
                          ") bends no ray, so both halves of --side-by-side would be the same");
    // The image may replace no file the scene was read from; refused before the second render.
    OutputSet outputs(with->files);
    if (auto s = outputs.check(options.output); !s) return s.error();
    o.atmosphere = false;
    auto without = trace_scene(o);
    if (!without) return without.error();
    r.with = std::move(*with);
    r.without = std::move(*without);
    r.without.atmosphere = "off (the left half)";

    const Image left = quantize_srgb8(r.without.render.image);
    const Image right = quantize_srgb8(r.with.render.image);
    MIRAGE_CHECK(left.width == right.width && left.height == right.height);
    const int w = left.width, h = left.height;
    const int font_px = std::clamp(h / 16, 12, 48);
    const int pad = std::max(4, font_px / 2);
    r.font = find_label_font(font_px);
    const int strip_h = r.font.empty() ? 0 : font_px + pad;
    r.left_x = pad;
    r.right_x = 2 * pad + w;
    r.top_y = pad;
    OIIO::ImageBuf buf(
        OIIO::ImageSpec(2 * w + 3 * pad, h + 2 * pad + strip_h, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::fill(buf, {kGround, kGround, kGround});
    paste_codes(buf, left, r.left_x, r.top_y);
    paste_codes(buf, right, r.right_x, r.top_y);
    if (!r.font.empty()) {
        const int px = fitting_font_px(r.font, font_px, w, strip_h);
        draw_label(buf, kWithoutMirageLabel, r.font, px, r.left_x, r.top_y + h + pad / 2, w,
                   strip_h);
        draw_label(buf, kWithMirageLabel, r.font, px, r.right_x, r.top_y + h + pad / 2, w, strip_h);
    }
    const OIIO::ImageSpec& spec = buf.spec();
    Image codes(spec.width, spec.height);
    const bool got = buf.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, 3),
                                    OIIO::TypeDesc::FLOAT, codes.pixels.data());
    MIRAGE_CHECK(got);
    if (auto s = write_png_codes(codes, options.output, &outputs); !s) return s.error();
    if (auto s = outputs.commit(); !s) return s.error();
    r.output = options.output;
    return r;
}

std::string side_by_side_summary(const SideBySideReport& r) {
    std::ostringstream out;
    out << "left, " << kWithoutMirageLabel << ": " << trace_summary(r.without);
    out << "right, " << kWithMirageLabel << ": " << trace_summary(r.with);
    out << "wrote " << r.output << " (without the atmosphere left, with it right)\n";
    if (r.font.empty())
        out << "note: no font found for the labels (" << caption_fonts().front()
            << ", Debian's fonts-dejavu-core): the halves are unlabelled\n";
    return out.str();
}

}  // namespace mirage
