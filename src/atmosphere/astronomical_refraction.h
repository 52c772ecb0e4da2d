// Astronomical refraction: how far a ray from an observer is bent on its way out of the whole
// atmosphere, so that a star (or the sun) is seen higher than it stands.
//
// The air is the US Standard Atmosphere 1976 (its temperature layers to 47 km of geopotential
// height, the pressure by the hydrostatic equation in each layer) from a given ground
// temperature and pressure; the index is Ciddor 1996 at a given wavelength (air.h).  Above the
// top (47 km, where the pressure falls to about 1 hPa and n - 1 to about 3e-7) the last step to
// vacuum is taken as one refraction at the top's sphere.
//
// Two independent ways to the same bending:
//   - by the exact path: the air's model on the curved Earth (the conformal flattening of
//     general_profile.h, fitted piecewise-quadratic), the ray followed by its exact path to the
//     top, its direction there turned back by the angle the Earth's surface has turned under it;
//   - by the classical integral R = -int r n'(r) / (n + r n'(r)) dz over the zenith angle z from
//     the top to the observer (the change of variable of Auer & Standish, Astron. J. 119, 2472
//     (2000), which keeps the integrand finite at the horizon), r(z) from Bouguer's invariant
//     n r sin z, with n(r) the air's own index, not the fitted model.
#pragma once

#include <memory>

#include "atmosphere/air.h"
#include "atmosphere/exact_path.h"
#include "util/result.h"

namespace mirage {

/// The ground's air StandardAir::make accepts.
constexpr double kMinGroundTemperatureK = 220.0, kMaxGroundTemperatureK = 330.0;
constexpr double kMinGroundPressurePa = 50000.0, kMaxGroundPressurePa = 110000.0;

struct StandardAirSettings {
    double ground_temperature_k = 283.15;  // the tables' 10 degC
    double ground_pressure_pa = 101000.0;  // the tables' 1010 hPa
    double wavelength_nm = 574.0;          // Ciddor, dry air, 450 ppm CO2
    double earth_radius_m = 6371000.0;
};

/// The standard atmosphere from the ground up: temperature, pressure and index at a height above
/// the ground (m, 0 to top_m()).  The troposphere falls from the ground temperature at 6.5 K/km
/// until it meets the standard tropopause (216.65 K); above, the standard layers.
class StandardAir {
  public:
    static Result<StandardAir> make(const StandardAirSettings& settings);
    double temperature_k(double height_m) const;
    double pressure_pa(double height_m) const;
    /// n - 1.
    double refractivity(double height_m) const;
    /// d(n - 1)/dh, per metre.
    double refractivity_slope(double height_m) const;
    double top_m() const { return top_m_; }
    const StandardAirSettings& settings() const { return settings_; }

  private:
    StandardAirSettings settings_;
    // Per layer, from the ground: bottom (geopotential m), lapse (K per geopotential m),
    // temperature and pressure at the bottom.
    struct Layer {
        double bottom = 0.0, lapse = 0.0, temperature = 0.0, pressure = 0.0;
        double temperature_at(double geopotential_m) const;
        double pressure_at(double geopotential_m) const;
    };
    std::vector<Layer> layers_;
    double top_m_ = 0.0;
    int layer_at(double geopotential_m) const;
    // The layer of height z above the ground, and z's geopotential height in `h`.
    const Layer& layer_of(double z, double& h) const;
};

/// The refraction (rad, > 0: seen higher) of a ray leaving an observer at `observer_height_m`
/// at apparent elevation `elevation` (rad, >= 0), by the classical integral over the air's own
/// index.
double refraction_by_integral(const StandardAir& air, double observer_height_m, double elevation);

/// The air's model on the curved Earth, as the tracer's exact paths follow it (flattened and
/// fitted to `tolerance_n` in the index).
Result<Atmosphere> standard_air_model(const StandardAir& air, double tolerance_n = 1e-12);

/// The same refraction by the exact path through `model` (standard_air_model of `air`).
Result<double> refraction_by_path(const StandardAir& air, const Atmosphere& model,
                                  double observer_height_m, double elevation);

/// The Pulkovo Refraction Tables (5th ed., 1985): their standard atmosphere at sea level, dry,
/// at 590 nm, and their refraction at an apparent elevation (rad in, rad out) by the fit
/// R = (1 degree / 62.8093) / tan(h + 4.2206 / (h + 15.1115 / (h + 5.9431))), h in degrees,
/// which stays within 0.29" of the tables from 0 to 90 degrees.
constexpr double kPulkovoTemperatureK = 288.15, kPulkovoPressurePa = 101325.0;
constexpr double kPulkovoWavelengthNm = 590.0;
double pulkovo_refraction(double elevation);

/// Bennett's formula for the refraction of the standard tables (J. Navigation 35, 255 (1982);
/// Meeus, Astronomical Algorithms, eq. 16.4): R = cot(h + 7.31 / (h + 4.4)) arcminutes for an
/// apparent altitude h in degrees, at 10 degC and 1010 hPa; within 0.07' of the tables from 0 to
/// 90 degrees.  rad in, rad out.
double bennett_refraction(double elevation);

}  // namespace mirage
