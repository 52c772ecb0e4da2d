// The atmosphere a scene declares with Mirage_... values (see pov_includes/mirage.inc).
#pragma once

#include <optional>
#include <string>

#include "atmosphere/profile.h"
#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

enum class LayerMode { Adaptive, Uniform };

struct AtmosphereSettings {
    Profile profile;               // in metres; ProfileKind::None when the scene declares none
    std::string profile_label;     // "paper (inferior)", "explicit inferior", ...
    bool declared = false;         // the scene declares an atmosphere at all
    double tolerance_px = 0.5;     // largest path error, pixels
    std::optional<double> extent;  // horizontal reach from the camera, scene units
    double unit_m = 1.0;           // metres per scene unit
    double ground_height = 0.0;    // the profile's y = 0 in the scene, scene units
    LayerMode layers = LayerMode::Adaptive;
    int layer_count = 0;  // uniform mode
};

/// Reads the Mirage_... declarations of a parsed scene.  An error names the declaration's
/// file, line and column and the bad value; unknown Mirage_ names are errors too (a typo
/// would otherwise be ignored silently).
Result<AtmosphereSettings> read_atmosphere_settings(const Scene& scene);

/// The profile in scene units: heights in units of unit_m metres.
Profile profile_in_scene_units(const AtmosphereSettings& settings);

}  // namespace mirage
