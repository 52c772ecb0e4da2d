#include "atmosphere/astronomical_refraction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "atmosphere/general_profile.h"
#include "atmosphere/quadratic_profile.h"
#include "util/check.h"
#include "util/format.h"

namespace mirage {

namespace {

// US Standard Atmosphere 1976: the radius its geopotential heights refer to, and its layers
// above the troposphere (geopotential base, m; lapse, K per m), to 47 km.
constexpr double kGeopotentialRadius = 6356766.0;
constexpr double kTropopauseK = 216.65;
constexpr double kTroposphereLapse = -0.0065;
struct StandardLayer {
    double bottom, lapse;
};
constexpr StandardLayer kUpperLayers[] = {{20000.0, 0.001}, {32000.0, 0.0028}};
constexpr double kStandardTop = 47000.0;  // geopotential m: about 1 hPa
constexpr double kCo2Ppm = 450.0;

double geopotential(double z) { return kGeopotentialRadius * z / (kGeopotentialRadius + z); }
double geometric(double h) { return kGeopotentialRadius * h / (kGeopotentialRadius - h); }

}  // namespace

Result<StandardAir> StandardAir::make(const StandardAirSettings& s) {
    if (!(s.ground_temperature_k >= kMinGroundTemperatureK &&
          s.ground_temperature_k <= kMaxGroundTemperatureK))
        return make_error("ground temperature " + shortest(s.ground_temperature_k) +
                          " K must be from " + shortest(kMinGroundTemperatureK) + " to " +
                          shortest(kMaxGroundTemperatureK) + " K");
    if (!(s.ground_pressure_pa >= kMinGroundPressurePa &&
          s.ground_pressure_pa <= kMaxGroundPressurePa))
        return make_error("ground pressure " + shortest(s.ground_pressure_pa / 100.0) +
                          " hPa must be from " + shortest(kMinGroundPressurePa / 100.0) + " to " +
                          shortest(kMaxGroundPressurePa / 100.0) + " hPa");
    if (!(s.wavelength_nm >= 300.0 && s.wavelength_nm <= 1690.0))
        return make_error("wavelength " + shortest(s.wavelength_nm) +
                          " nm must be from 300 to 1690 nm (Ciddor's range)");
    if (!(s.earth_radius_m >= 1e6 && s.earth_radius_m <= 1e8))
        return make_error("Earth radius " + shortest(s.earth_radius_m) +
                          " m must be from 1e6 to 1e8 m");
    StandardAir a;
    a.settings_ = s;
    // The troposphere from the ground temperature to the tropopause, isothermal to 20 km.
    a.layers_.push_back({0.0, kTroposphereLapse, s.ground_temperature_k, s.ground_pressure_pa});
    const double tropopause = (s.ground_temperature_k - kTropopauseK) / -kTroposphereLapse;
    a.layers_.push_back({tropopause, 0.0, 0.0, 0.0});
    for (const StandardLayer& l : kUpperLayers) a.layers_.push_back({l.bottom, l.lapse, 0.0, 0.0});
    for (size_t k = 1; k < a.layers_.size(); ++k) {
        const Layer& below = a.layers_[k - 1];
        Layer& l = a.layers_[k];
        l.temperature = below.temperature_at(l.bottom);
        l.pressure = below.pressure_at(l.bottom);
    }
    a.top_m_ = geometric(kStandardTop);
    return a;
}

int StandardAir::layer_at(double h) const {
    int k = 0;
    while (k + 1 < static_cast<int>(layers_.size()) && h >= layers_[k + 1].bottom) ++k;
    return k;
}

double StandardAir::Layer::temperature_at(double h) const {
    return temperature + lapse * (h - bottom);
}

double StandardAir::Layer::pressure_at(double h) const {
    // The hydrostatic equation in a layer of constant lapse (or none).
    return lapse == 0.0
               ? pressure * std::exp(-kHydrostaticScale * (h - bottom) / temperature)
               : pressure * std::pow(temperature / temperature_at(h), kHydrostaticScale / lapse);
}

const StandardAir::Layer& StandardAir::layer_of(double z, double& h) const {
    h = geopotential(std::clamp(z, 0.0, top_m_));
    return layers_[layer_at(h)];
}

double StandardAir::temperature_k(double z) const {
    double h = 0.0;
    return layer_of(z, h).temperature_at(h);
}

double StandardAir::pressure_pa(double z) const {
    double h = 0.0;
    return layer_of(z, h).pressure_at(h);
}

double StandardAir::refractivity(double z) const {
    double h = 0.0;
    const Layer& l = layer_of(z, h);
    return ciddor_refractivity(settings_.wavelength_nm, l.temperature_at(h), l.pressure_at(h),
                               0.0, kCo2Ppm);
}

double StandardAir::refractivity_slope(double z) const {
    // Central differences, one-sided at the ends; the index is smooth inside each layer and its
    // slope only turns at their boundaries (a centimetre's step is far below any of them).
    constexpr double d = 0.01;
    const double lo = std::max(0.0, z - d), hi = std::min(top_m_, z + d);
    return (refractivity(hi) - refractivity(lo)) / (hi - lo);
}

double refraction_by_integral(const StandardAir& air, double observer_height_m, double elevation) {
    MIRAGE_CHECK(elevation >= 0.0 && elevation < M_PI / 2);
    const double R = air.settings().earth_radius_m;
    const double r0 = R + observer_height_m, r_top = R + air.top_m();
    auto n = [&](double r) { return 1.0 + air.refractivity(r - R); };
    const double z0 = M_PI / 2 - elevation;
    const double k = n(r0) * r0 * std::sin(z0);  // Bouguer's invariant
    const double z_top = std::asin(k / (n(r_top) * r_top));
    // r(z) on the ray: n(r) r sin z = k, n r increasing with r (no duct in the standard air).
    auto r_at = [&](double z) {
        double a = r0, b = r_top;
        for (int i = 0; i < 200 && b - a > 1e-9 * r0; ++i) {
            const double m = 0.5 * (a + b);
            (n(m) * m * std::sin(z) < k ? a : b) = m;
        }
        return 0.5 * (a + b);
    };
    auto integrand = [&](double z) {
        const double r = r_at(z);
        const double dn = air.refractivity_slope(r - R);
        return -r * dn / (n(r) + r * dn);
    };
    // Simpson's rule over z, finer where the ray is low (the index changes fastest there).
    constexpr int kIntervals = 4000;
    const double a = z_top, b = z0;
    double sum = integrand(a) + integrand(b);
    for (int i = 1; i < kIntervals; ++i) {
        const double t = static_cast<double>(i) / kIntervals;
        sum += (i % 2 ? 4.0 : 2.0) * integrand(a + (b - a) * t);
    }
    const double inside = sum * (b - a) / (3.0 * kIntervals);
    // From the top's index to vacuum, at the top's sphere.
    const double vacuum = std::asin(std::min(1.0, n(r_top) * std::sin(z_top))) - z_top;
    return inside + vacuum;
}

Result<Atmosphere> standard_air_model(const StandardAir& air, double tolerance_n) {
    ProfileFunction f;
    const double n0 = 1.0 + air.refractivity(0.0);
    f.n0_sq = n0 * n0;
    f.excess = [&air, n0](double z) {
        const double n = 1.0 + air.refractivity(z);
        return (n - n0) * (n + n0);
    };
    f.excess_slope = [&air](double z, int) {
        return 2.0 * (1.0 + air.refractivity(z)) * air.refractivity_slope(z);
    };
    f.top = air.top_m();
    for (double h : {0.0, 20000.0, 32000.0})
        if (h > 0.0) f.breakpoints.push_back(geometric(h));
    const double tropopause =
        (air.settings().ground_temperature_k - kTropopauseK) / -kTroposphereLapse;
    f.breakpoints.push_back(geometric(tropopause));
    std::sort(f.breakpoints.begin(), f.breakpoints.end());
    // The flattened frame goes a kilometre above the top, where the air no longer changes.
    const ProfileFunction flat = flatten(f, air.settings().earth_radius_m, 1000.0);
    FitSettings fs;
    fs.tolerance_n = tolerance_n;
    auto q = fit_quadratic_profile(flat, fs);
    if (!q) return q.error();
    return Atmosphere::quadratic(std::make_shared<const QuadraticProfile>(std::move(*q)));
}

Result<double> refraction_by_path(const StandardAir& air, const Atmosphere& model,
                                  double observer_height_m, double elevation) {
    if (!(elevation >= 0.0 && elevation < M_PI / 2))
        return make_error("elevation " + shortest(elevation * 180.0 / M_PI) +
                          " degrees must be from 0 to 90");
    const double R = air.settings().earth_radius_m;
    auto path = ExactPath::make(model, flattened_height(observer_height_m, R), M_PI / 2 - elevation);
    if (!path) return path.error();
    const double y_top = flattened_height(air.top_m(), R);
    const double dz = path->distance_to_height(y_top);
    if (!std::isfinite(dz))
        return make_error("the ray at " + shortest(elevation * 180.0 / M_PI) +
                          " degrees never reaches the top of the air");
    // The flattening is conformal: the slope there is the elevation over the local horizontal,
    // which has turned by dz / R from the observer's.
    const double local = std::atan(path->slope_at(dz));
    const double n_top = 1.0 + air.refractivity(air.top_m());
    const double vacuum = std::acos(std::min(1.0, n_top * std::cos(local)));
    return elevation - (vacuum - dz / R);
}

double pulkovo_refraction(double elevation) {
    const double h = elevation * 180.0 / M_PI;
    return (M_PI / 180.0 / 62.8093) / std::tan((h + 4.2206 / (h + 15.1115 / (h + 5.9431))) *
                                               M_PI / 180.0);
}

double bennett_refraction(double elevation) {
    const double h = elevation * 180.0 / M_PI;
    const double arcmin = 1.0 / std::tan((h + 7.31 / (h + 4.4)) * M_PI / 180.0);
    return arcmin / 60.0 * M_PI / 180.0;
}

}  // namespace mirage
