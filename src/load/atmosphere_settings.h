// The atmosphere a scene declares with Mirage_... values (see pov_includes/mirage.inc).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atmosphere/profile.h"
#include "atmosphere/turbulence.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

class Atmosphere;  // atmosphere/exact_path.h
struct AirSpec;    // atmosphere/general_profile.h

// Adaptive: fitted to the camera's rays (the exponential profiles; for real air and cameras
// whose rays start at many points, index steps unless asked for by name).  Uniform: Berger's
// equal heights.  IndexSteps: boundaries at equal steps of the index (real air's design, and
// that of many-origin cameras), asked for by name.
enum class LayerMode { Adaptive, Uniform, IndexSteps };

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
// Real air (Mirage_Sounding, the temperature forms, Mirage_Earth_Radius): the ranges of the
// settings, checked where each is read.
constexpr double kEarthRadiusM = 6371000.0;  // the default of real-air scenes
constexpr double kMinEarthRadiusM = 1e5;     // Mirage_Earth_Radius: 0 (flat) or from this
constexpr double kMaxEarthRadiusM = 1e9;     // to this
constexpr double kMaxLapseKPerKm = 100.0;    // |Mirage_Lapse|
// kMaxFormHeightM, kMaxFormDeltaK, kMaxSmoothingM, kMinScaleHeightM: atmosphere/general_profile.h
constexpr int kMaxInversions = 8;  // Mirage_Inversion, Mirage_Inversion_2, ...
// Colour (docs/colour.md): Ciddor's range of wavelengths, nm, and the channels' default, the
// dominant wavelengths of the sRGB primaries (red 611 nm, green 549 nm, blue 464 nm), rounded.
constexpr double kMinWavelengthNm = 300.0, kMaxWavelengthNm = 1690.0;
using ChannelWavelengths = std::array<double, 3>;  // red, green, blue; nm
constexpr ChannelWavelengths kDefaultChannelWavelengthsNm = {610.0, 550.0, 465.0};
// The fitted model's |n_fit - n| bound: chosen from the path tolerance so that ray directions
// stay within half of it (pi sqrt(eps) <= tolerance / 2), within these limits.
// Mirage_Exaggeration (not air): from a thousandth of the air's index gradient to ten thousand
// times it, past the paper's profile (about 6000 times the hot road's n^2 - n0^2).
constexpr double kMinExaggeration = 1e-3;
constexpr double kMaxExaggeration = 1e4;
constexpr double kMinFitTolerance = 1e-13;
constexpr double kMaxFitTolerance = 1e-10;

/// A scene's Mirage_ settings: its atmosphere (the exponential profile or real air, the
/// exaggeration, the ground's height, the unit), and how a command renders it (the path
/// tolerance, the layers, the extent).
struct MirageSettings {
    Profile profile;               // in metres; ProfileKind::None when the scene declares none
    std::string profile_label;     // "paper (inferior)", "explicit inferior", ...
    bool declared = false;         // the scene declares an atmosphere at all
    double tolerance_px = 0.5;     // largest path error, pixels
    std::optional<double> extent;  // horizontal reach from the camera, scene units
    double unit_m = 1.0;           // metres per scene unit
    double ground_height = 0.0;    // the profile's y = 0 in the scene, scene units
    LayerMode layers = LayerMode::Adaptive;
    int layer_count = 0;  // uniform mode
    // Real air, traced by the general engine (atmosphere/general_profile.h): set when the
    // scene declares a sounding, a temperature form beyond the exponential fit, or an Earth
    // radius.  In metres; `profile` then stays ProfileKind::None unless the air is an
    // exponential profile on the curved Earth.
    std::shared_ptr<const AirSpec> air;
    std::vector<std::string> input_files;  // files the atmosphere was read from (a sounding)
    double exaggeration = 1.0;             // Mirage_Exaggeration: n^2 - n0^2 times this (not air)
    // Turbulent air (Mirage_Turbulence_Cn2 > 0, docs/turbulence.md): its settings in metres and
    // m/s; unset when the scene declares none or C_n^2 = 0.
    std::optional<TurbulenceSettings> turbulence;
    double turbulence_aperture_m = 0.0;  // Mirage_Turbulence_Aperture: the camera's, m
    // Colour (Mirage_Wavelengths = <R, G, B>, nm): the wavelengths the tracer and the compiled
    // designs render the red, green and blue channels at; unset: one wavelength for all three
    // (monochrome light).  `air` then has the green channel's wavelength.
    std::optional<ChannelWavelengths> channel_wavelengths_nm;
};

// Turbulence's defaults in a scene: an inner scale of 5 mm and an outer one of 1 m (the air a
// metre or two above hot ground), no wind, seed 1, a point aperture.
constexpr double kMaxTurbulenceSeed = 4294967295.0;  // Mirage_Turbulence_Seed: 0 to 2^32 - 1

/// Whether the scene's atmosphere bends rays at all.
bool bends_rays(const MirageSettings& settings);

/// Reads the Mirage_... declarations of a parsed scene.  An error names the declaration's
/// file, line and column and the bad value; unknown Mirage_ names are errors too (a typo
/// would otherwise be ignored silently).
Result<MirageSettings> read_atmosphere_settings(const Scene& scene);

/// The names of the settings a scene may declare (mirage.inc's own names left out).
std::vector<std::string> atmosphere_setting_names();

/// Exaggerates the air (Mirage_Exaggeration, not air): n_k(y)^2 = n(0)^2 + k (n(y)^2 - n(0)^2)
/// at every height, the ground's index kept (the exponential profiles' eta1^2 times k; real
/// air's n^2 - n0^2 times k before the Earth's flattening, which stays as it is).  Rays' curvature
/// y'' = (n^2)' / (2 beta^2) is then k times as large for the same invariant.  k = 1 changes
/// nothing.  An error, prefixed with `name` (the setting with its place), for k out of
/// [kMinExaggeration, kMaxExaggeration], no gradient, or a profile the factor makes invalid.
Status exaggerate_atmosphere(MirageSettings& settings, double k, const std::string& name);

/// Checks the wavelengths of a colour render's channels: three (red, green, blue), each from
/// kMinWavelengthNm to kMaxWavelengthNm; `name` says where they were given, with its place
/// ("--wavelengths 610,550", "scene.pov:3:1: Mirage_Wavelengths =").
Result<ChannelWavelengths> check_channel_wavelengths(const std::vector<double>& nm,
                                                     const std::string& name);

/// Sets the air's wavelength (one channel of a colour render): real air through Ciddor's
/// index only.  The exponential profiles, Gladstone-Dale's index and a sounding of n have no
/// wavelength: refused with `name` (the setting or option, with its place) and the reason.
Status set_wavelength(MirageSettings& settings, double wavelength_nm, const std::string& name);

/// Checks a tolerance in pixels against its range; `name` says where it was given, with its
/// place: "--tolerance", "scene.pov:3:10: Mirage_Tolerance =".  The one message of every
/// command for a tolerance out of range.
Status check_tolerance_px(double px, const std::string& name);

/// Checks a count of equal layers (a whole number from 1 to kMaxLayerCount), named as above.
Status check_layer_count(double count, const std::string& name);

/// The profile in scene units: heights in units of unit_m metres.
Profile profile_in_scene_units(const MirageSettings& settings);

/// The fit tolerance (|n_fit - n|) for paths sampled to `tolerance_rad`: directions through the
/// model stay within tolerance_rad / 2 of the true ones (pi sqrt(eps)), clamped to
/// [kMinFitTolerance, kMaxFitTolerance].
double fit_tolerance_for(double tolerance_rad);

/// The one angle every command fits real air's model to (scene_atmosphere) for paths kept
/// within `tolerance_px` of the camera's pixels: the footprint's angle plus its distance
/// across the rays seen over the paths' reach (a camera with many origins), times the
/// tolerance.  The tracer, frame and animate's views ask it at the scene's tolerance; the
/// compiler at a twentieth of it, where its pixel check's exact rays are.
double fit_angle_rad(const PixelFootprint& footprint, double tolerance_px, double reach);

/// The scene's atmosphere in scene units, for paths sampled to `tolerance_rad`: the
/// exponential closed forms (profile_in_scene_units), or real air's fitted model with its
/// heights (and Earth radius) in scene units.  `pieces` (may be null) gets the model's size.
Result<Atmosphere> scene_atmosphere(const MirageSettings& settings, double tolerance_rad,
                                    int* pieces = nullptr);

}  // namespace mirage
