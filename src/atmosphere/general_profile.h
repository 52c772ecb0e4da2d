// Profiles of real air of any shape: temperatures from forms that add up (a base with a linear
// lapse, exponential surface layers, inversion layers with smoothed corners), a sounding, or
// the exponential n^2 of Khular, Thyagarajan & Ghatak; the index from the temperature by
// Gladstone-Dale or Ciddor (air.h), the pressure by the hydrostatic equation unless given; the
// Earth's curvature by the conformal Earth-flattening map; and the fitted piecewise-quadratic
// model (quadratic_profile.h) on which every exact path is computed.
//
// Temperature forms, T(y) in K for heights y >= 0 above the ground:
//   base             T0 - lapse y
//   surface layer    + dT exp(-y / H)                              (dT > 0: hot ground)
//   inversion        + dT R(y), R the ramp from 0 below `bottom` to 1 above `top`, linear in
//                    between, its corners smoothed by a Gaussian of standard deviation sigma:
//                    R = (F(y - bottom) - F(y - top)) / (top - bottom), F(x) = x Phi(x / sigma)
//                    + sigma phi(x / sigma) (the ramp convolved with the Gaussian; sigma = 0: the
//                    sharp "zigzag" profile with corners).
// Pressure: p(y) = p0 exp(-(g M / R) int_0^y dy' / T(y')), dry air (air.h), unless isobaric.
//
// Earth curvature (radius R): heights above the sphere h and distances along it x = R phi map to
// y = R ln(1 + h / R) and x, and n to n* = n (R + h) / R.  In every plane through the Earth's
// centre this map is conformal and exact (Fermat's principle keeps n ds); rays of the flattened
// profile are the true rays.  Above the profile's top the air is homogeneous.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atmosphere/air.h"
#include "atmosphere/profile.h"
#include "atmosphere/quadratic_profile.h"
#include "atmosphere/sounding.h"
#include "util/result.h"

namespace mirage {

struct SurfaceLayer {
    double delta_k = 0.0;  // temperature excess at the ground, K
    double scale_m = 1.0;  // e-folding height, m
};

struct Inversion {
    double bottom_m = 0.0;
    double top_m = 1.0;
    double delta_k = 0.0;      // temperature rise from bottom to top, K
    double smoothing_m = 0.0;  // standard deviation of the Gaussian that rounds the corners
};

/// The ranges of the temperature forms, for the command line and the scene settings alike:
/// beyond them no air is physical, and the fit would follow a form over heights without end.
constexpr double kMaxFormHeightM = 1e4;    // inversions' heights, Mirage_Top
constexpr double kMaxFormDeltaK = 100.0;   // |temperature steps| of inversions and layers
constexpr double kMaxSmoothingM = 100.0;   // an inversion's smoothing
constexpr double kMinScaleHeightM = 1e-3;  // a surface layer's scale height, up to the top's

/// A surface layer's or an inversion's values against their ranges: the error says which value
/// ("temperature excess 1e+308 K must be from -100 to 100 K").
Status check_surface_layer(const SurfaceLayer& layer);
Status check_inversion(const Inversion& inversion);

/// Air described by temperature forms that add up.
struct AirColumn {
    double ground_temperature_k = 288.15;  // the base at y = 0
    double lapse_k_per_m = 0.0;            // the base falls by this per metre
    std::vector<SurfaceLayer> layers;
    std::vector<Inversion> inversions;
};

/// Everything that says what the air is.
struct AirSpec {
    enum class Source { Column, Sounding, Exponential };
    Source source = Source::Column;
    AirColumn column;
    Sounding sounding;    // Source::Sounding
    Profile exponential;  // Source::Exponential (fitted like any other profile)
    IndexSettings index;
    double ground_pressure_pa = 101325.0;
    bool hydrostatic = true;             // else the pressure is the same at every height
    double relative_humidity = 0.0;      // 0 to 1, where the sounding gives none
    double top_m = 0.0;                  // 0: the default (the sounding's top, else 1000 m or
                                         // above the highest feature)
    double earth_radius_m = 0.0;         // 0: flat ground
    double earth_extension_m = 10000.0;  // with curvature: the model goes this far above the top
    // With curvature: the air above `top_m` continues as the standard atmosphere to
    // kUpperAirTopM (upper_air_refractivity), and the model says that the sky is seen where a
    // ray leaves it (QuadraticProfile::sky_at_top), so that a sun at the horizon is refracted
    // all the way (Mirage_Upper_Air, docs/colour.md).  Needs the air's temperature and pressure.
    bool upper_air = false;
    // Not air: n^2 - n0^2 multiplied by this over the whole profile, before the Earth's
    // flattening (Mirage_Exaggeration, docs/framing.md).  1: the air as described.
    double exaggeration = 1.0;
};

/// The air as functions of the height above the ground.
struct AirModel {
    ProfileFunction physical;                     // n^2 - n0^2 over [0, top], flat
    std::function<double(double)> temperature_k;  // empty when the source has none
    std::function<double(double)> pressure_pa;    // empty when the source has none
    std::function<double(double)> refractivity;   // n - 1
    double top = 0.0;
};

/// Checks the spec and builds its functions.  Refusals name the value and its limit.  With an
/// exaggeration k != 1 the index is n_k^2 = n0^2 + k (n^2 - n0^2) (the temperature and the
/// pressure stay those described).
Result<AirModel> make_air_model(const AirSpec& spec);

/// Temperature of the forms at height y, K.
double column_temperature(const AirColumn& column, double y);
/// dT/dy; side -1 the left, +1 the right limit at a corner.
double column_temperature_slope(const AirColumn& column, double y, int side);

/// The conformal Earth-flattening map and its inverse (R = 0: the identity).
double flattened_height(double height_above_sphere, double earth_radius);
double height_above_sphere(double flattened_height, double earth_radius);

/// The profile in the flattened frame: n*^2 = n^2 (1 + h/R)^2 over y in [0, y(top + extension)],
/// homogeneous n above the physical top.
ProfileFunction flatten(const ProfileFunction& physical, double earth_radius, double extension_m);

/// The top of the upper air (AirSpec::upper_air), m above the ground: the US Standard
/// Atmosphere's 47 km, where n - 1 has fallen to about 3e-7; vacuum above, reached by one
/// refraction at the top's sphere (sky_exit.h).
constexpr double kUpperAirTopM = 47000.0;

/// n - 1 above the described air's top (m, `top_m`), from its temperature, pressure and
/// refractivity there: the temperature falls at 6.5 K/km to the standard tropopause's 216.65 K,
/// stays there to 20 km, rises 1 K/km to 32 km and 2.8 K/km above (the US Standard Atmosphere's
/// layers, at geometric heights), the pressure hydrostatic in each layer; the index by the
/// spec's formula for dry air, scaled to meet `refractivity_top` at the top.
std::function<double(double)> upper_air_refractivity(const AirSpec& spec, double top_m,
                                                     double temperature_top_k,
                                                     double pressure_top_pa,
                                                     double refractivity_top);

/// The fitted model of the spec (through the flattening when it has an Earth radius).  An index
/// sounding on flat ground is its own quadratic model (its spline of n^2), fitted exactly.
Result<std::shared_ptr<const QuadraticProfile>> fit_air(const AirSpec& spec,
                                                        const FitSettings& settings,
                                                        FitReport* report = nullptr);

}  // namespace mirage
