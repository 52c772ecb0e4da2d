#include "report/contact_sheet.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <sstream>

#include "util/check.h"

namespace mirage {

namespace {

namespace OIIO = OIIO_NAMESPACE;

constexpr float kGround = 0.12f;  // the sheet's background, code / 255
constexpr float kInk = 0.93f;     // caption text

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

/// The first of `caption_fonts` that OpenImageIO can draw with; empty when none.
std::string find_font(int font_px) {
    for (const auto& name : caption_fonts()) {
        OIIO::ImageBuf probe(OIIO::ImageSpec(8, 8, 3, OIIO::TypeDesc::FLOAT));
        if (OIIO::ImageBufAlgo::render_text(probe, 0, font_px, "x", font_px, name)) return name;
    }
    return "";
}

}  // namespace

const std::vector<std::string>& caption_fonts() {
    static const std::vector<std::string> fonts = {"DejaVuSans", "LiberationSans-Regular",
                                                   "NotoSans-Regular", "FreeSans"};
    return fonts;
}

Result<ContactSheet> make_contact_sheet(const std::vector<SheetTile>& tiles,
                                        const ContactSheetSettings& st) {
    if (tiles.empty()) return make_error("contact sheet: no images");
    int tile_w = 0, tile_h = 0;
    size_t caption_lines = 1;
    for (const auto& t : tiles) {
        if (t.image.empty()) return make_error("contact sheet: an empty image");
        tile_w = std::max(tile_w, t.image.width);
        tile_h = std::max(tile_h, t.image.height);
        caption_lines = std::max(caption_lines, split_lines(t.caption).size());
    }
    const int scale = std::max(1, (st.min_tile_width + tile_w - 1) / tile_w);
    const int pad = 6;
    const int line_h = st.font_px + 4;
    const int cell_w = tile_w * scale + 2 * pad;
    const int caption_h = static_cast<int>(caption_lines) * line_h + pad;
    const int cell_h = tile_h * scale + pad + caption_h;
    const int columns = std::max(1, std::min<int>(st.columns, static_cast<int>(tiles.size())));
    const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;

    ContactSheet sheet;
    sheet.font = find_font(st.font_px);
    OIIO::ImageBuf buf(OIIO::ImageSpec(columns * cell_w, rows * cell_h, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::fill(buf, {kGround, kGround, kGround});
    for (size_t i = 0; i < tiles.size(); ++i) {
        const int x0 = static_cast<int>(i % columns) * cell_w;
        const int y0 = static_cast<int>(i / columns) * cell_h;
        const Image& im = tiles[i].image;
        // Each image pixel becomes a scale x scale block, so small renders stay readable.
        for (int y = 0; y < im.height * scale; ++y)
            for (int x = 0; x < im.width * scale; ++x) {
                const glm::vec3 c = im.at(x / scale, y / scale);
                const float rgb[3] = {c.x, c.y, c.z};
                buf.setpixel(x0 + pad + x, y0 + pad + y, rgb, 3);
            }
        if (sheet.font.empty()) continue;
        // The caption is drawn on its own strip, so a long line is cut at the cell's edge
        // rather than running into the next picture.
        OIIO::ImageBuf strip(OIIO::ImageSpec(cell_w - pad, caption_h, 3, OIIO::TypeDesc::FLOAT));
        OIIO::ImageBufAlgo::fill(strip, {kGround, kGround, kGround});
        const auto lines = split_lines(tiles[i].caption);
        for (size_t k = 0; k < lines.size(); ++k)
            OIIO::ImageBufAlgo::render_text(strip, 0, static_cast<int>(k + 1) * line_h - 4,
                                            lines[k], st.font_px, sheet.font, {kInk, kInk, kInk});
        OIIO::ImageBufAlgo::paste(buf, x0 + pad, y0 + pad + tile_h * scale + pad / 2, 0, 0, strip);
    }
    const OIIO::ImageSpec& spec = buf.spec();
    sheet.image = Image(spec.width, spec.height);
    const bool got = buf.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, 3),
                                    OIIO::TypeDesc::FLOAT, sheet.image.pixels.data());
    MIRAGE_CHECK(got);
    return sheet;
}

}  // namespace mirage
