// Colour through POV-Ray (docs/colour.md): one compiled design per wavelength (the scene's air
// at the red, green and blue channels' wavelengths), each rendered by POV-Ray, and the image
// made of the red channel of the red design's render, the green of the green's and the blue of
// the blue's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/povray_render.h"
#include "compile/compile.h"
#include "image/image.h"
#include "load/atmosphere_settings.h"
#include "util/result.h"

namespace mirage {

/// The channels' wavelengths a compile renders at: `asked` (--wavelengths, named by `option`
/// in a message), else the scene's Mirage_Wavelengths; nothing for a monochrome scene or one
/// that does not load (its compile then says why).  An error names the option.
Result<std::optional<ChannelWavelengths>> compile_colour_wavelengths(
    const CompileOptions& options, const std::vector<double>& asked, const std::string& option);

struct ColourChannel {
    double wavelength_nm = 0.0;
    CompileReport report;                // the design at this wavelength
    std::optional<PovrayRender> render;  // POV-Ray's render of it, when rendered
    std::string log;                     // POV-Ray's console output
};

struct ColourCompileReport {
    std::vector<ColourChannel> channels;  // red, green, blue
    std::string image;                    // the combined image, when rendered
};

/// Compiles the scene once per wavelength, into OUT/NAME-<nm>nm/ (OUT: options.out_dir, else
/// build/render/NAME); with `render`, renders each with POV-Ray and combines the channels into
/// options.image (else OUT/NAME.png), written through a temporary name.  A POV-Ray failure is
/// an error naming the .ini and the end of its log.
Result<ColourCompileReport> compile_colour(const CompileOptions& options,
                                           const ChannelWavelengths& wavelengths_nm, bool render);

/// The image of the three channels: red from `red`, green from `green`, blue from `blue`.
/// Errors when their sizes differ.
Result<Image> combine_channels(const Image& red, const Image& green, const Image& blue);

/// A few lines for people: each channel's design and render, and the combined image.
std::string colour_compile_summary(const ColourCompileReport& report);

}  // namespace mirage
