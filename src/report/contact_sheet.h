// A contact sheet: images in a grid, each with a caption under it, drawn with OpenImageIO's
// ImageBufAlgo (text needs a TrueType font; without one the sheet has no captions).
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "util/result.h"

namespace mirage {

struct SheetTile {
    Image image;          // code values / 255, as read_image gives them for an 8-bit PNG
    std::string caption;  // lines separated by '\n'
};

struct ContactSheetSettings {
    int columns = 4;
    int min_tile_width = 256;  // smaller images are enlarged (pixel copies) to at least this
    int font_px = 13;          // caption text height, pixels
};

struct ContactSheet {
    Image image;       // code values / 255
    std::string font;  // the font the captions were drawn in; empty: none found, no captions
};

/// Lays the tiles out row by row (all tiles take the size of the largest), on a dark ground.
/// Fails on an empty list.
Result<ContactSheet> make_contact_sheet(const std::vector<SheetTile>& tiles,
                                        const ContactSheetSettings& settings = {});

/// The font names OpenImageIO is asked for, in order (DejaVu Sans first, as Debian's
/// fonts-dejavu-core installs it).
const std::vector<std::string>& caption_fonts();

}  // namespace mirage
