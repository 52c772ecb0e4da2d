#include "scene/image_file.h"

#include <OpenImageIO/imageio.h>
#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "scene/scene.h"

namespace mirage {
namespace {

// A file's pixels as floats, every channel, with the file's own description.
struct FloatPixels {
    OIIO::ImageSpec spec;
    std::vector<float> data;  // width * height * spec.nchannels, top row first
};

}  // namespace

Status check_image_pixels(const std::string& path, long long width, long long height) {
    if (width <= kMaxImagePixels / std::max(height, 1LL)) return Ok{};
    return make_error(path + ": the image is " + std::to_string(width) + "x" +
                      std::to_string(height) + " pixels, more than the " +
                      std::to_string(kMaxImagePixels) +
                      " pixels (4096x4096) mirage reads for an image map or a height field");
}

namespace {

Result<FloatPixels> read_float_pixels(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return make_error(path + ": cannot read image: " + OIIO::geterror());
    FloatPixels f{in->spec(), {}};
    const OIIO::ImageSpec& spec = f.spec;
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1) {
        return make_error(path + ": not a 2D image with pixels");
    }
    // The size the header gives, before any pixel is decoded.
    if (auto s = check_image_pixels(path, spec.width, spec.height); !s) return s.error();
    if (spec.nchannels > 64) return make_error(path + ": an image of more than 64 channels");
    f.data.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, f.data.data())) {
        return make_error(path + ": cannot read pixels: " + in->geterror());
    }
    in->close();
    return f;
}

}  // namespace

Result<RgbaImage> read_image_rgba(const std::string& path) {
    auto pixels = read_float_pixels(path);
    if (!pixels) return make_error(pixels.message());
    const OIIO::ImageSpec& spec = pixels->spec;
    const std::vector<float>& data = pixels->data;
    const int channels = spec.nchannels;
    RgbaImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.has_alpha = spec.alpha_channel >= 0 || channels == 4 || channels == 2;
    const int alpha = spec.alpha_channel >= 0 ? spec.alpha_channel
                      : channels == 4         ? 3
                      : channels == 2         ? 1
                                              : -1;
    // A file's own gamma (a PNG's gAMA chunk), else sRGB; float formats are linear.
    const std::string colour_space = spec.get_string_attribute("oiio:ColorSpace");
    if (spec.format.basetype == OIIO::TypeDesc::FLOAT ||
        spec.format.basetype == OIIO::TypeDesc::HALF || colour_space == "Linear") {
        image.file_gamma = 1.0;
    } else if (colour_space.rfind("GammaCorrected", 0) == 0) {
        image.file_gamma = spec.get_float_attribute("oiio:Gamma", 0.0f);
    }
    image.pixels.resize(static_cast<std::size_t>(spec.width) * spec.height * 4);
    for (std::size_t p = 0, n = static_cast<std::size_t>(spec.width) * spec.height; p < n; ++p) {
        const int colour_channels = channels - (alpha >= 0 ? 1 : 0);
        for (int c = 0; c < 3; ++c) {
            const int source = colour_channels >= 3 ? c : 0;
            image.pixels[p * 4 + c] = data[p * channels + source];
        }
        image.pixels[p * 4 + 3] = alpha >= 0 ? data[p * channels + alpha] : 1.0f;
    }
    return image;
}

namespace {

// image_height_at's three kinds of pixel, from values as POV-Ray's image classes hold them.
std::uint16_t grey_height(float grey) { return static_cast<std::uint16_t>(grey * 65535.0f); }
std::uint16_t colour_height(float r, float g, float b, bool deep) {
    if (deep) {
        return static_cast<std::uint16_t>(static_cast<float>(greyscale(glm::dvec3(r, g, b))) *
                                          65535.0f);
    }
    return static_cast<std::uint16_t>((r * 256.0 + g) * 255.0);
}

struct PngFile {
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngFile() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
        if (file) std::fclose(file);
    }
};

void png_failure(png_structp png, png_const_charp message) {
    auto* text = static_cast<std::string*>(png_get_error_ptr(png));
    *text = message;
    png_longjmp(png, 1);
}
void png_warning_ignored(png_structp, png_const_charp) {}

Result<HeightImage> read_png_heights(const std::string& path) {
    PngFile f;
    f.file = std::fopen(path.c_str(), "rb");
    if (!f.file) return make_error(path + ": cannot open the height field's image");
    std::string error;
    f.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, png_failure, png_warning_ignored);
    if (f.png) f.info = png_create_info_struct(f.png);
    if (!f.png || !f.info) return make_error(path + ": cannot read PNG");
    HeightImage image;
    std::vector<png_byte> pixels;
    std::vector<png_bytep> rows;
    int colour_type = 0, depth = 0, channels = 0;
    if (setjmp(png_jmpbuf(f.png))) return make_error(path + ": not a readable PNG file: " + error);
    png_init_io(f.png, f.file);
    png_read_info(f.png, f.info);
    // The size the header gives, before any pixel is decoded.
    if (auto s = check_image_pixels(path, png_get_image_width(f.png, f.info),
                                    png_get_image_height(f.png, f.info));
        !s)
        return s.error();
    colour_type = png_get_color_type(f.png, f.info);
    depth = png_get_bit_depth(f.png, f.info);
    if (colour_type == PNG_COLOR_TYPE_PALETTE) {
        png_set_packing(f.png);  // one index a byte
    } else if (colour_type == PNG_COLOR_TYPE_GRAY && depth < 8) {
        png_set_expand_gray_1_2_4_to_8(f.png);
    }
    if (depth == 16) png_set_swap(f.png);  // host order (little-endian)
    png_set_interlace_handling(f.png);
    png_read_update_info(f.png, f.info);
    image.width = static_cast<int>(png_get_image_width(f.png, f.info));
    image.height = static_cast<int>(png_get_image_height(f.png, f.info));
    channels = png_get_channels(f.png, f.info);
    depth = png_get_bit_depth(f.png, f.info);
    const std::size_t row_bytes = png_get_rowbytes(f.png, f.info);
    pixels.resize(row_bytes * static_cast<std::size_t>(image.height));
    rows.resize(static_cast<std::size_t>(image.height));
    for (int y = 0; y < image.height; ++y)
        rows[static_cast<std::size_t>(y)] = &pixels[row_bytes * y];
    png_read_image(f.png, rows.data());
    png_read_end(f.png, nullptr);
    image.heights.resize(static_cast<std::size_t>(image.width) * image.height);
    const bool grey = (colour_type & PNG_COLOR_MASK_COLOR) == 0;
    for (int y = 0; y < image.height; ++y) {
        const png_byte* row = rows[static_cast<std::size_t>(y)];
        for (int x = 0; x < image.width; ++x) {
            const auto sample = [&](int c) -> float {
                if (depth == 16) {
                    std::uint16_t v;
                    std::memcpy(&v, row + 2 * (x * channels + c), 2);
                    return static_cast<float>(v) / 65535.0f;
                }
                return static_cast<float>(row[x * channels + c]) / 255.0f;
            };
            std::uint16_t h;
            if (colour_type == PNG_COLOR_TYPE_PALETTE) {
                h = static_cast<std::uint16_t>(row[x] * 256);
            } else if (grey) {
                h = grey_height(sample(0));
            } else {
                h = colour_height(sample(0), sample(1), sample(2), depth > 8);
            }
            image.heights[static_cast<std::size_t>(y) * image.width + x] = h;
        }
    }
    return image;
}

}  // namespace

Result<HeightImage> read_height_image(const std::string& path) {
    std::FILE* probe = std::fopen(path.c_str(), "rb");
    if (!probe) return make_error(path + ": cannot open the height field's image");
    unsigned char signature[8] = {};
    const std::size_t n = std::fread(signature, 1, 8, probe);
    std::fclose(probe);
    if (n == 8 && png_sig_cmp(signature, 0, 8) == 0) return read_png_heights(path);
    auto pixels = read_float_pixels(path);
    if (!pixels) return make_error(pixels.message());
    const OIIO::ImageSpec& spec = pixels->spec;
    const std::vector<float>& data = pixels->data;
    const int channels = spec.nchannels;
    const bool deep = spec.format.size() > 1;
    const int colour_channels =
        channels - (spec.alpha_channel >= 0 || channels == 2 || channels == 4 ? 1 : 0);
    HeightImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.heights.resize(static_cast<std::size_t>(spec.width) * spec.height);
    for (std::size_t p = 0; p < image.heights.size(); ++p) {
        const float* v = &data[p * channels];
        image.heights[p] =
            colour_channels >= 3 ? colour_height(v[0], v[1], v[2], deep) : grey_height(v[0]);
    }
    return image;
}

}  // namespace mirage
