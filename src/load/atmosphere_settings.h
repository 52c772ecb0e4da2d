// The atmosphere a scene declares with Mirage_... values (see pov_includes/mirage.inc).
#pragma once

#include <optional>
#include <string>

#include "atmosphere/profile.h"
#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

enum class LayerMode { Adaptive, Uniform };

// The ranges of the settings (docs/robustness.md).  A tolerance below a thousandth of a pixel
// is finer than anything a render shows and costs ever more samples per path; Berger's
// equal layers beyond 4096 are far past the 255 boundaries a POV-Ray ray may cross.
constexpr double kMinTolerancePx = 1e-3;
constexpr double kMaxTolerancePx = 1e3;
constexpr int kMaxLayerCount = 4096;
constexpr double kMinUnitM = 1e-3;  // Mirage_Unit: a millimetre per unit at least
constexpr double kMaxUnitM = 1e3;   // and a kilometre at most
// The camera and Mirage_Extent lie within this many scene units of the origin: paths are
// followed no farther (atmosphere/sampler.cpp), and no coordinate overflows on the way.
constexpr double kMaxCoordinate = 1e9;

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

/// Checks a tolerance in pixels against its range; `name` says where it was given, with its
/// place: "--tolerance", "scene.pov:3:10: Mirage_Tolerance =".  The one message of every
/// command for a tolerance out of range.
Status check_tolerance_px(double px, const std::string& name);

/// Checks a count of equal layers (a whole number from 1 to kMaxLayerCount), named as above.
Status check_layer_count(double count, const std::string& name);

/// The profile in scene units: heights in units of unit_m metres.
Profile profile_in_scene_units(const AtmosphereSettings& settings);

}  // namespace mirage
