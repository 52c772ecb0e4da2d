#include "image/image_io.h"

#include <OpenImageIO/fmath.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "util/check.h"
#include "util/file_name.h"
#include "util/output_path.h"

namespace mirage {

namespace {

namespace OIIO = OIIO_NAMESPACE;

/// OpenImageIO's message about the temporary file, told of the output it stands for, with the
/// system's reason when there is one.
std::string write_message(const std::string& path, const std::string& tmp, std::string said,
                          int err) {
    for (std::size_t at = said.find(tmp); at != std::string::npos; at = said.find(tmp, at))
        said.replace(at, tmp.size(), path);
    std::string m = path + ": cannot write";
    if (err != 0) m += std::string(": ") + std::strerror(err);
    if (!said.empty()) m += " (" + said + ")";
    return m;
}

// Writes to `outputs`' temporary name for `path` (renamed, or written into a device or a
// FIFO, when the set is committed), or without a set through a set of its own, committed at
// once.
// `kind` is OpenImageIO's name of the format ("png", "openexr"): a device or a FIFO named
// without an extension still gets one.
Status write_through_temporary(const std::string& path, const char* kind,
                               const OIIO::ImageSpec& spec, const OIIO::TypeDesc& format,
                               const void* data, OutputSet* outputs) {
    if (!outputs) {
        OutputSet own;
        if (auto s = write_through_temporary(path, kind, spec, format, data, &own); !s) return s;
        return own.commit();
    }
    auto staged = outputs->stage(path);
    if (!staged) return staged.error();
    const std::string tmp = *staged;
    auto out = OIIO::ImageOutput::create(kind);
    if (!out) return make_error(path + ": cannot write images of this type: " + OIIO::geterror());
    errno = 0;
    if (!out->open(tmp, spec)) return make_error(write_message(path, tmp, out->geterror(), errno));
    if (!out->write_image(format, data)) {
        const int err = errno;
        std::string message = write_message(path, tmp, out->geterror(), err);
        out->close();
        std::remove(tmp.c_str());
        return make_error(message);
    }
    if (!out->close()) {
        std::string message = write_message(path, tmp, out->geterror(), errno);
        std::remove(tmp.c_str());
        return make_error(message);
    }
    return Ok{};
}

Status check_image(const Image& image, const std::string& path) {
    if (image.empty()) return make_error(path + ": refusing to write an empty image");
    MIRAGE_CHECK(image.pixels.size() == static_cast<std::size_t>(image.width) *
                                            static_cast<std::size_t>(image.height) * 3);
    return Ok{};
}

}  // namespace

std::uint8_t encode_srgb8(float linear) {
    // Single precision throughout, as POV-Ray (its pow is the float overload): this decides
    // the rounding of a few values per thousand.
    float encoded;
    if (linear <= 0.0031308f) {
        encoded = linear * 12.92f;
    } else {
        encoded = 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    }
    if (!(encoded > 0.0f)) encoded = 0.0f;  // also NaN, which POV-Ray never produces
    if (encoded > 1.0f) encoded = 1.0f;
    return static_cast<std::uint8_t>(std::floor(encoded * 255.0f + 0.5f));
}

float decode_srgb8(std::uint8_t code) {
    return decode_srgb_value(static_cast<float>(code) / 255.0f);
}

float decode_srgb_value(float x) {
    if (x < 0.04045f) return x / 12.92f;
    return std::pow((x + 0.055f) / 1.055f, 2.4f);
}

Image quantize_srgb8(const Image& linear) {
    Image out(linear.width, linear.height);
    for (std::size_t i = 0; i < linear.pixels.size(); ++i) {
        // OpenImageIO's own conversion, so the values equal what read_image gives for the PNG.
        out.pixels[i] = OIIO::convert_type<std::uint8_t, float>(encode_srgb8(linear.pixels[i]));
    }
    return out;
}

namespace {

/// An 8-bit sRGB PNG of the image, each value turned into its byte by `encode`.
template <class Encode>
Status write_png_bytes(const Image& image, const std::string& path, OutputSet* outputs,
                       Encode encode) {
    if (auto s = check_image(image, path); !s) return s;
    std::vector<std::uint8_t> bytes(image.pixels.size());
    for (std::size_t i = 0; i < image.pixels.size(); ++i) bytes[i] = encode(image.pixels[i]);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("Software", "mirage");
    return write_through_temporary(path, "png", spec, OIIO::TypeDesc::UINT8, bytes.data(), outputs);
}

}  // namespace

Status write_png(const Image& linear, const std::string& path, OutputSet* outputs) {
    return write_png_bytes(linear, path, outputs, [](float v) { return encode_srgb8(v); });
}

Status write_png_codes(const Image& codes, const std::string& path, OutputSet* outputs) {
    return write_png_bytes(codes, path, outputs,
                           [](float v) { return OIIO::convert_type<float, std::uint8_t>(v); });
}

Status write_exr(const Image& linear, const std::string& path, OutputSet* outputs) {
    if (auto s = check_image(linear, path); !s) return s;
    OIIO::ImageSpec spec(linear.width, linear.height, 3, OIIO::TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("compression", "zip");
    return write_through_temporary(path, "openexr", spec, OIIO::TypeDesc::FLOAT,
                                   linear.pixels.data(), outputs);
}

Status check_image_name(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".png" || ext == ".exr") return Ok{};
    if (ext.empty()) {
        auto out = resolve_output_path(path);
        if (!out) return out.error();
        if (out->stream && out->target != "-") return Ok{};  // a device or a FIFO: PNG
    }
    return make_error(path + ": unknown image type '" + ext + "' (use .png or .exr)");
}

Status write_image(const Image& linear, const std::string& path, OutputSet* outputs) {
    if (auto s = check_image_name(path); !s) return s;
    if (lower_extension(path) == ".exr") return write_exr(linear, path, outputs);
    return write_png(linear, path, outputs);
}

Result<Image> read_image(const std::string& path) {
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
    in->close();
    Image image(spec.width, spec.height);
    for (std::size_t p = 0, n = static_cast<std::size_t>(spec.width) * spec.height; p < n; ++p) {
        for (int c = 0; c < 3; ++c) {
            const int source = channels >= 3 ? c : 0;
            image.pixels[p * 3 + c] = data[p * channels + source];
        }
    }
    return image;
}

}  // namespace mirage
