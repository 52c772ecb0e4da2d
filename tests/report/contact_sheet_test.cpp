#include "report/contact_sheet.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

Image flat(int w, int h, float v) {
    Image im(w, h);
    for (float& p : im.pixels) p = v;
    return im;
}

TEST(ContactSheet, LaysOutEnlargedTilesWithCaptionsUnder) {
    ContactSheetSettings st;
    st.columns = 2;
    st.min_tile_width = 40;  // 10-pixel images become 4 x 4 blocks
    std::vector<SheetTile> tiles = {{flat(10, 5, 1.0f), "white\nfirst"},
                                    {flat(10, 5, 0.0f), "black"},
                                    {flat(10, 5, 0.5f), "grey"}};
    auto sheet = make_contact_sheet(tiles, st);
    ASSERT_TRUE(sheet.ok()) << sheet.message();
    const int pad = 6, cell_w = 40 + 2 * pad;
    EXPECT_EQ(sheet->image.width, 2 * cell_w);
    const int caption_h = 2 * (st.font_px + 4) + pad;  // two lines: the longest caption
    const int cell_h = 20 + pad + caption_h;
    EXPECT_EQ(sheet->image.height, 2 * cell_h);
    // Every pixel of an enlarged tile is its image's pixel.
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 40; ++x) {
            EXPECT_EQ(sheet->image.at(pad + x, pad + y).x, 1.0f);
            EXPECT_EQ(sheet->image.at(cell_w + pad + x, pad + y).x, 0.0f);
            EXPECT_EQ(sheet->image.at(pad + x, cell_h + pad + y).x, 0.5f);
        }
    if (sheet->font.empty()) GTEST_SKIP() << "no font for captions on this machine";
    // Some ink in the first caption's strip, under the first tile.
    float brightest = 0.0f;
    for (int y = pad + 20; y < cell_h; ++y)
        for (int x = pad; x < cell_w; ++x) brightest = std::max(brightest, sheet->image.at(x, y).x);
    EXPECT_GT(brightest, 0.5f);
}

TEST(ContactSheet, NothingToShowIsAnError) {
    auto sheet = make_contact_sheet({});
    ASSERT_FALSE(sheet.ok());
    EXPECT_EQ(sheet.message(), "contact sheet: no images");
}

}  // namespace
}  // namespace mirage
