// `mirage trace`: a scene file rendered by the built-in tracer along the curved light paths
// of the atmosphere it declares, the continuous model every POV-Ray band render is checked
// against.  Parses the scene strictly, reads its Mirage_ declarations, chooses the
// propagator (straight, per-ray paths or the paper's per-scanline paths), renders on all
// cores and writes the image through a temporary name.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "render/render.h"
#include "util/result.h"
#include "util/scene_input.h"

namespace mirage {

/// How the rays of a trace travel.
enum class PathMode {
    Straight,  // no atmosphere (none declared, or switched off)
    PerRay,    // every ray along its own exact path
    Scanline,  // camera rays along their row's path (Khote & Howard); reflections per ray
};

struct TraceOptions : SceneInput {
    std::string output;                      // .png or .exr; empty: nothing written
    std::optional<double> tolerance_px;      // overrides Mirage_Tolerance (default 0.5), pixels
    int threads = 0;                         // worker threads; 0 = all cores
    bool scanline_paths = false;             // one path per image row (level camera only)
    bool atmosphere = true;                  // false: straight rays whatever the scene declares
    bool reference_sampling = false;         // per-ray paths sampled to the tolerance all along
    bool progress = true;                    // progress bar on stderr when it is a terminal
    std::optional<double> clock;             // --clock (POV-Ray's +K): a still at this clock
    std::map<std::string, double> declares;  // --declare (POV-Ray's Declare=)
    AntialiasSettings antialias;             // POV-Ray's +A, +AM, +R, +J; off by default
    // Colour (docs/colour.md): the red, green and blue channels traced at these wavelengths
    // (--wavelengths, nm), replacing the scene's Mirage_Wavelengths; empty: the scene's, else
    // one wavelength for the three.
    std::vector<double> wavelengths_nm;
    // The scene's Mirage_Wavelengths ignored: one render through the air at the green
    // channel's wavelength (what the band designs of compare and study see).
    bool monochrome = false;
};

struct TraceReport {
    std::string scene;
    int width = 0, height = 0;
    std::string atmosphere;  // what the scene declares, or why there is none
    PathMode mode = PathMode::Straight;
    double tolerance_px = 0.0;  // the paths' largest error, pixels
    double pixel_rad = 0.0;     // one pixel's angle at the image centre, rad
    PixelFootprint footprint;   // one pixel along a camera ray (scene/camera.h)
    bool many_origins = false;  // the camera's rays start at different points
    int model_pieces = 0;       // real air: the fitted model's pieces (0: closed forms)
    RenderResult render;        // the image (linear) and the render's statistics (a colour
                                // render's summed over its channels)
    // Colour: the channels' wavelengths, nm (red, green, blue), each channel traced through its
    // own atmosphere; empty: monochrome.
    std::vector<double> wavelengths_nm;
    std::string output;         // the file written, if any
    // The files the scene was read from.
    std::vector<std::string> files;
};

/// POV-Ray's output gamma: the rendered values are in the scene's working gamma
/// (assumed_gamma), which the file's sRGB encoding undoes; a scene of #version 3.6 or older
/// without assumed_gamma gets no gamma handling at all (the file holds the values as they
/// are).  Turns `image` into the linear values that write_png encodes to those codes.
void apply_output_gamma(Image& image, const GlobalSettings& global);

/// Traces the scene.  On failure nothing was written and the message names the place at
/// fault (file:line:column for the scene, the option for a bad value).
Result<TraceReport> trace_scene(const TraceOptions& options);

/// Two lines for people: what was traced and how, then the statistics (rays, segments per
/// ray, seconds, Mrays/s).
std::string trace_summary(const TraceReport& report);

std::string path_mode_name(PathMode mode);

}  // namespace mirage
