// The render driver: every pixel's camera ray traced and shaded, tile by tile on all cores,
// the same bytes whatever the thread count, with a progress bar on a terminal.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "image/image.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "render/antialias.h"
#include "trace/propagator.h"
#include "shading/shading.h"
#include "util/result.h"

namespace mirage {

struct RenderSettings {
    int width = 320;       // image width, in pixels
    int height = 240;      // image height, in pixels
    int threads = 0;       // worker threads; 0 = all cores
    bool progress = true;  // progress bar on stderr, shown only when stderr is a terminal
    int tile_size = 32;    // side of the square tiles handed to the threads, in pixels
    // POV-Ray's antialiasing; when on, the tiles are its render blocks (antialias.block_size)
    AntialiasSettings antialias;
};

/// What a render did and how fast.
struct RenderStats {
    TraceCounters counters;
    int threads = 0;           // threads used
    double seconds = 0.0;      // wall-clock time of the tracing
    double cpu_seconds = 0.0;  // processor time of the tracing threads, summed (a measure that
                               // other jobs on the machine disturb less than the wall clock)
    // Whether POV-Ray's antialiasing was on, and its pixels supersampled and positions sampled.
    bool antialiased = false;
    AntialiasCounters antialias;
    /// Camera and reflected rays: the rays that went through the propagator.
    std::uint64_t rays() const { return counters.camera_rays + counters.reflected_rays; }
    /// Propagated rays plus shadow rays.
    std::uint64_t all_rays() const { return rays() + counters.shadow_rays; }
    /// Straight segments per propagated ray (1 for straight rays).
    double segments_per_ray() const;
    /// Of them, those tested against the scene, per propagated ray.
    double queries_per_ray() const;
    /// Millions of rays (propagated and shadow) per second of wall-clock time.
    double mrays_per_second() const;
};

struct RenderResult {
    Image image;  // linear colour (write it with write_png to get POV-Ray's encoding)
    RenderStats stats;
};

/// The camera ray through an image position, in pixels from the image's top-left corner
/// (pixel centres at +0.5): the scene module's camera_ray unless a test needs another.
using PixelRayFunction =
    std::function<CameraRay(const Camera& camera, double x, double y, int width, int height)>;

/// Renders the scene as POV-Ray renders it: without antialiasing one ray through each
/// pixel's centre, shaded by Shader; with it, POV-Ray's sampling method (render/antialias.h).
/// Fails (with the message of check_supported or of the geometry) for scenes outside the
/// supported subset, for non-positive sizes and for antialias settings POV-Ray would clip.
Result<RenderResult> render(const Scene& scene, const RenderSettings& settings,
                            const Propagator& propagator,
                            const PixelRayFunction& pixel_ray = camera_ray);

/// Renders with straight rays.
Result<RenderResult> render(const Scene& scene, const RenderSettings& settings);

/// A one-line summary: size, rays, segments per ray (and tested per ray), seconds (wall and
/// processor), Mrays/s, threads; when antialiased, the share of pixels supersampled.
std::string format_stats(const RenderStats& stats, int width, int height);

}  // namespace mirage
