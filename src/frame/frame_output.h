// What `mirage frame` writes: the reading as text and as JSON, and the teaching overlay, an
// image of the scene with the true horizon, the apparent horizon, the mirage band and each
// object's vanishing mark drawn over it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "frame/frame.h"
#include "image/image.h"

namespace mirage {

/// The reading as text: the horizons, the band, each object, the options tried and the
/// advice; figures in metres, degrees and rows.
std::string frame_text(const FrameReading& reading);

/// The same as JSON (distances in metres, angles in degrees, rows as image row coordinates).
nlohmann::json frame_json(const FrameReading& reading);

/// The overlay's colours, for the legend.
struct OverlayKey {
    static constexpr float kTrueHorizon[3] = {0.1f, 0.9f, 0.1f};      // green
    static constexpr float kApparentHorizon[3] = {1.0f, 0.1f, 0.1f};  // red
    static constexpr float kBand[3] = {0.0f, 0.9f, 1.0f};             // cyan, blended
    static constexpr float kBandInReach[3] = {0.1f, 0.3f, 1.0f};      // blue, blended
    static constexpr float kVanishing[3] = {1.0f, 0.1f, 1.0f};        // magenta
    static constexpr float kMirrored[3] = {1.0f, 0.9f, 0.1f};         // yellow
};

/// The legend of the overlay, one line a colour.
std::string overlay_legend();

/// Draws the reading over `background` (linear colour, the frame's size; a grey ground and sky
/// when empty).
Image frame_overlay(const FrameReading& reading, const Image& background);

}  // namespace mirage
