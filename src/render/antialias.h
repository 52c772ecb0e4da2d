// POV-Ray 3.7's antialiasing (+A, +AM1 and +AM2, +R, +J, +AG): which pixels get more samples,
// where those samples fall and how they are averaged, one render block at a time.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "image/image.h"
#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

/// POV-Ray's sampling methods (its +AM option).
enum class AntialiasMethod {
    None,          // one ray through each pixel's centre (-A)
    NonRecursive,  // +AM1: a pixel whose colour differs from its left or top neighbour's by the
                   // threshold gets depth x depth more rays, on a grid (POV-Ray's default)
    Recursive,     // +AM2: every pixel from its four corners, its square cut in four where the
                   // corners differ, down to depth - 1 levels
};

struct AntialiasSettings {
    AntialiasMethod method = AntialiasMethod::None;
    double threshold = 0.3;         // +A: the colour distance that calls for more samples
    int depth = 3;                  // +R: method 1's rays per side; method 2's levels + 1
    double jitter = 1.0;            // +J amount in [0, 1] of the sub-sample spacing; 0: -J
    std::uint64_t jitter_seed = 0;  // the same seed gives the same offsets, whatever the threads
    double gamma = 2.5;             // +AG: colours are compared after encoding with this gamma
    int block_size = 32;  // POV-Ray's render block (+BS), in pixels: method 1 compares a block's
                          // left column and top row with neighbours traced afresh
    bool enabled() const { return method != AntialiasMethod::None; }
};

/// "method 1 (non-recursive), threshold 0.3, depth 3, jitter 1" and the like; "off".
std::string antialias_label(const AntialiasSettings& settings);

/// Refuses what POV-Ray would clip: a threshold outside [0, 1], a depth outside [1, 9], a
/// jitter outside [0, 1], a gamma or block size that is not positive.  The message names the
/// option (--antialias, --antialias-depth, --jitter).
Status check_antialias(const AntialiasSettings& settings);

/// The power that takes a colour from the scene's working space to the space the threshold
/// is applied in: the scene's assumed_gamma over the antialias gamma (POV-Ray transcodes the
/// working gamma to +AG; a scene before #version 3.7 without assumed_gamma has none).
double antialias_exponent(const GlobalSettings& global, double antialias_gamma);

/// A sample as POV-Ray compares it with the threshold: red, green and blue each clipped at 0
/// and raised to `exponent`, transmit as it is, in single precision as POV-Ray's colours are.
glm::vec4 antialias_encode(const glm::dvec4& sample, double exponent);

/// POV-Ray's distance between two samples for the threshold: the sum of the absolute
/// differences of red, green, blue and transmit after antialias_encode.  The threshold is
/// reached when the distance is at least the threshold, both in single precision.
double antialias_distance(const glm::dvec4& a, const glm::dvec4& b, double exponent);

/// The colour seen at an image position, in pixels from the image's top-left corner (a
/// pixel's centre is at +0.5), in the scene's working space, and its transmit: 1 where the
/// camera gives no ray (POV-Ray marks such a position so; the colour is black), else 0 (a 3.7
/// scene's background is opaque without an alpha channel, and the tracer writes none).
using SampleFunction = std::function<glm::dvec4(double x, double y)>;

/// A block of pixels: columns [x0, x1), rows [y0, y1).
struct PixelBlock {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct AntialiasCounters {
    std::uint64_t pixels = 0;               // pixels rendered
    std::uint64_t pixels_supersampled = 0;  // of them, those given more than their first rays
    std::uint64_t samples = 0;              // every position sampled, the first rays among them
    void add(const AntialiasCounters& other);
    /// The share of pixels supersampled, 0 to 1.
    double supersampled_share() const;
};

/// Renders one block as POV-Ray's trace task renders a block for the settings' method
/// (settings.enabled() must hold), writing its pixels into `image`.  `exponent` is
/// antialias_exponent's.  A block depends on nothing outside it: blocks may go in any order
/// on any thread.
void antialias_block(const AntialiasSettings& settings, double exponent, const PixelBlock& block,
                     const SampleFunction& sample, Image& image, AntialiasCounters& counters);

/// The offset of a jittered sample at (x, y), each coordinate in [-0.5, 0.5): a hash of the
/// seed and the position, so a sample falls where it fell in every other run.
glm::dvec2 jitter_offset(std::uint64_t seed, double x, double y);

}  // namespace mirage
