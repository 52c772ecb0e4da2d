#include "scene/image_file.h"

#include <OpenImageIO/imageio.h>

namespace mirage {

Result<RgbaImage> read_image_rgba(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return make_error(path + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1) {
        return make_error(path + ": not a 2D image with pixels");
    }
    const int channels = spec.nchannels;
    std::vector<float> data(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
        return make_error(path + ": cannot read pixels: " + in->geterror());
    }
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
    in->close();
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

}  // namespace mirage
