#include "image/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace mirage {
namespace {

std::filesystem::path temp_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    auto dir = std::filesystem::path(MIRAGE_BINARY_DIR) / "test_output" / "image_io" / info->name();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(EncodeSrgb8, MatchesPovRayCodes) {
    // Codes POV-Ray 3.7.0.10 writes for `background { rgb v }` with assumed_gamma 1.0.
    EXPECT_EQ(encode_srgb8(0.5f), 188);
    EXPECT_EQ(encode_srgb8(0.2f), 124);
    EXPECT_EQ(encode_srgb8(0.002f), 7);
    // Values where single and double precision round differently; POV-Ray gives these.
    EXPECT_EQ(encode_srgb8(0.128782958f), 100);
    EXPECT_EQ(encode_srgb8(0.182815254f), 118);
    EXPECT_EQ(encode_srgb8(0.192905337f), 122);
}

TEST(EncodeSrgb8, ClipsAndIsMonotonic) {
    EXPECT_EQ(encode_srgb8(-1.0f), 0);
    EXPECT_EQ(encode_srgb8(0.0f), 0);
    EXPECT_EQ(encode_srgb8(1.0f), 255);
    EXPECT_EQ(encode_srgb8(7.5f), 255);
    EXPECT_EQ(encode_srgb8(std::nanf("")), 0);
    int previous = 0;
    for (int i = 0; i <= 10000; ++i) {
        const int code = encode_srgb8(static_cast<float>(i) / 10000.0f);
        EXPECT_GE(code, previous);
        previous = code;
    }
}

TEST(EncodeSrgb8, DecodeRoundTrips) {
    for (int code = 0; code < 256; ++code) {
        EXPECT_EQ(encode_srgb8(decode_srgb8(static_cast<std::uint8_t>(code))), code) << code;
    }
}

TEST(ImageIo, PngHoldsTheEncodedCodes) {
    const auto dir = temp_dir();
    Image image(3, 2);
    image.set(0, 0, {0.5f, 0.2f, 0.002f});
    image.set(2, 1, {1.0f, 0.0f, 2.0f});
    const std::string path = (dir / "out.png").string();
    ASSERT_TRUE(write_png(image, path).ok());
    auto back = read_image(path);
    ASSERT_TRUE(back.ok()) << back.message();
    ASSERT_EQ(back->width, 3);
    ASSERT_EQ(back->height, 2);
    EXPECT_FLOAT_EQ(back->at(0, 0).x, 188.0f / 255.0f);
    EXPECT_FLOAT_EQ(back->at(0, 0).y, 124.0f / 255.0f);
    EXPECT_FLOAT_EQ(back->at(0, 0).z, 7.0f / 255.0f);
    EXPECT_FLOAT_EQ(back->at(2, 1).x, 1.0f);
    EXPECT_FLOAT_EQ(back->at(2, 1).y, 0.0f);
    EXPECT_FLOAT_EQ(back->at(2, 1).z, 1.0f);
    // In memory, quantize_srgb8 gives the same values.
    const Image q = quantize_srgb8(image);
    EXPECT_EQ(q.pixels, back->pixels);
    // No temporary file is left behind.
    int files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1);
}

TEST(ImageIo, ExrIsLinearFloat) {
    const auto dir = temp_dir();
    Image image(2, 2);
    image.set(1, 0, {0.123456f, 3.5f, 1e-4f});
    const std::string path = (dir / "out.exr").string();
    ASSERT_TRUE(write_image(image, path).ok());
    auto back = read_image(path);
    ASSERT_TRUE(back.ok()) << back.message();
    EXPECT_EQ(back->pixels, image.pixels);
}

TEST(ImageIo, FailedWriteLeavesTheOldFile) {
    const auto dir = temp_dir();
    const std::string path = (dir / "keep.png").string();
    { std::ofstream(path) << "old"; }
    const auto status = write_png(Image(), path);
    EXPECT_FALSE(status.ok());
    EXPECT_NE(status.message().find("empty"), std::string::npos);
    std::ifstream in(path);
    std::string text;
    in >> text;
    EXPECT_EQ(text, "old");
}

TEST(ImageIo, RefusesUnknownTypesAndMissingFiles) {
    const auto dir = temp_dir();
    Image image(1, 1);
    auto s = write_image(image, (dir / "x.bmpx").string());
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message().find("unknown image type"), std::string::npos);
    auto r = read_image((dir / "missing.png").string());
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.message().find("missing.png"), std::string::npos);
}

}  // namespace
}  // namespace mirage
