// Image files through OpenImageIO: 8-bit PNG encoded as POV-Ray 3.7 encodes it, linear
// float OpenEXR, and reading any format OpenImageIO knows.
#pragma once

#include <cstdint>
#include <string>

#include "image/image.h"
#include "util/output_set.h"
#include "util/result.h"

namespace mirage {

/// POV-Ray 3.7's 8-bit code for a linear value, as it writes PNG with assumed_gamma 1.0
/// and the default File_Gamma (sRGB): the sRGB transfer function in single precision,
/// clipped to [0, 1], rounded half up, no dithering (base/image/colourspace.cpp,
/// encoding.h IntEncode).
std::uint8_t encode_srgb8(float linear);

/// Inverse of the sRGB transfer function for an 8-bit code (exact to float precision).
float decode_srgb8(std::uint8_t code);

/// Inverse of the sRGB transfer function for a value in [0, 1].
float decode_srgb_value(float encoded);

/// The image POV-Ray's PNG would hold, as code values / 255: what `read_image` returns for
/// that PNG.  For comparing a linear render with a PNG without writing a file.
Image quantize_srgb8(const Image& linear);

/// Writes linear pixels as an 8-bit RGB PNG encoded by `encode_srgb8`, tagged sRGB.  Writes
/// to a temporary name beside `path` and renames it, so a failure leaves `path` untouched;
/// with `outputs`, to the set's temporary name, renamed when the set is committed.  The
/// writers below do the same.
Status write_png(const Image& linear, const std::string& path, OutputSet* outputs = nullptr);

/// Writes code values / 255 (what `read_image` gives for an 8-bit PNG, or `quantize_srgb8`)
/// back as an 8-bit RGB PNG, each value rounded to its code with no encoding, through a
/// temporary name.  For pictures made of such images (a contact sheet).
Status write_png_codes(const Image& codes, const std::string& path, OutputSet* outputs = nullptr);

/// Writes linear pixels as a float RGB OpenEXR (no encoding), through a temporary name.
Status write_exr(const Image& linear, const std::string& path, OutputSet* outputs = nullptr);

/// Whether write_image takes `path`: .png, .exr, or a device or a FIFO without an extension
/// (written as PNG).  An error names it.
Status check_image_name(const std::string& path);

/// Writes by extension: .png as `write_png`, .exr as `write_exr`, a device or a FIFO without
/// an extension as PNG; anything else is refused (check_image_name).
Status write_image(const Image& linear, const std::string& path, OutputSet* outputs = nullptr);

/// Reads the first three channels of an image as stored: an 8-bit PNG gives code / 255
/// (no linearisation), an EXR its linear floats.  A grey image is spread to RGB.
Result<Image> read_image(const std::string& path);

}  // namespace mirage
