#include "atmosphere/turbulence.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <string>

#include "util/check.h"
#include "util/format.h"

namespace mirage {

namespace {

constexpr double kPi = std::numbers::pi;

// A uniform double in [0, 1) from the top 53 bits: the same on every standard library
// (std::uniform_real_distribution's algorithm is left to the implementation).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

double kappa_outer(const TurbulenceSettings& s) { return 2.0 * kPi / s.outer_scale_m; }
double kappa_inner(const TurbulenceSettings& s) { return 5.92 / s.inner_scale_m; }

// sin(x) / x without the 0/0.
double sinc(double x) { return std::abs(x) < 1e-8 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

}  // namespace

Status check_turbulence(const TurbulenceSettings& s) {
    if (!(s.cn2 >= 0.0 && s.cn2 <= kMaxCn2))
        return make_error("C_n^2 " + shortest(s.cn2) + " m^-2/3 must be from 0 to " +
                          shortest(kMaxCn2) + " m^-2/3");
    for (auto [name, v] :
         {std::pair{"inner scale", s.inner_scale_m}, std::pair{"outer scale", s.outer_scale_m}})
        if (!(v >= kMinScaleM && v <= kMaxScaleM))
            return make_error(std::string(name) + " " + shortest(v) + " m must be from " +
                              shortest(kMinScaleM) + " to " + shortest(kMaxScaleM) + " m");
    if (!(s.inner_scale_m < s.outer_scale_m))
        return make_error("inner scale " + shortest(s.inner_scale_m) +
                          " m must be below the outer scale " + shortest(s.outer_scale_m) + " m");
    const double w = glm::length(s.wind);
    if (!(w <= kMaxWindMps))
        return make_error("wind speed " + shortest(w) + " m/s must be at most " +
                          shortest(kMaxWindMps) + " m/s");
    if (s.modes_per_e_fold < 1 || s.modes_per_e_fold > kMaxModesPerEFold)
        return make_error("modes per e-fold " + std::to_string(s.modes_per_e_fold) +
                          " must be from 1 to " + std::to_string(kMaxModesPerEFold));
    return Ok{};
}

double kolmogorov_spectrum_constant() {
    return std::tgamma(8.0 / 3.0) * std::sin(kPi / 3.0) / (4.0 * kPi * kPi);
}

double index_spectrum(const TurbulenceSettings& s, double kappa) {
    const double k0 = kappa_outer(s), km = kappa_inner(s);
    return kolmogorov_spectrum_constant() * s.cn2 * std::pow(kappa * kappa + k0 * k0, -11.0 / 6.0) *
           std::exp(-(kappa * kappa) / (km * km));
}

Result<TurbulentField> TurbulentField::make(const TurbulenceSettings& settings) {
    if (auto st = check_turbulence(settings); !st) return st.error();
    TurbulentField field;
    field.settings_ = settings;
    // From kappa0 / 20 (the spectrum is flat below kappa0, so the shell's variance falls as
    // kappa^3) to 3.5 kappa_m (exp(-12) of the spectrum left).
    const double lo = std::log(kappa_outer(settings) / 20.0);
    const double hi = std::log(3.5 * kappa_inner(settings));
    const int n = static_cast<int>(std::ceil((hi - lo) * settings.modes_per_e_fold));
    const double step = (hi - lo) / n;
    std::mt19937_64 rng(settings.seed);
    field.modes_.reserve(n);
    for (int j = 0; j < n; ++j) {
        const double kappa = std::exp(lo + (j + uniform(rng)) * step);
        const double cos_theta = 2.0 * uniform(rng) - 1.0;
        const double azimuth = 2.0 * kPi * uniform(rng);
        const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
        const glm::dvec3 dir(sin_theta * std::cos(azimuth), sin_theta * std::sin(azimuth),
                             cos_theta);
        // The shell's variance, 4 pi kappa^2 Phi_n(kappa) dkappa with dkappa = kappa dln(kappa),
        // is a^2 / 2 for a cosine of random phase.
        const double shell =
            4.0 * kPi * kappa * kappa * index_spectrum(settings, kappa) * kappa * step;
        TurbulenceMode mode;
        mode.wavevector = kappa * dir;
        mode.amplitude = std::sqrt(2.0 * shell);
        mode.phase = 2.0 * kPi * uniform(rng);
        field.modes_.push_back(mode);
    }
    return field;
}

double TurbulentField::index(const glm::dvec3& p, double t) const {
    const glm::dvec3 q = p - settings_.wind * t;  // frozen flow
    double dn = 0.0;
    for (const auto& m : modes_) dn += m.amplitude * std::cos(glm::dot(m.wavevector, q) + m.phase);
    return dn;
}

IndexFluctuation TurbulentField::sample(const glm::dvec3& p, double t) const {
    const glm::dvec3 q = p - settings_.wind * t;
    IndexFluctuation out;
    for (const auto& m : modes_) {
        const double arg = glm::dot(m.wavevector, q) + m.phase;
        out.dn += m.amplitude * std::cos(arg);
        out.gradient -= (m.amplitude * std::sin(arg)) * m.wavevector;
    }
    return out;
}

glm::dvec3 TurbulentField::integrated_gradient(const glm::dvec3& a, const glm::dvec3& b,
                                               double t) const {
    const glm::dvec3 q = a - settings_.wind * t;
    const glm::dvec3 along = b - a;
    glm::dvec3 sum(0.0);
    for (const auto& m : modes_) {
        // int_0^1 sin(A + B u) du = sin(A + B / 2) sinc(B / 2), u the fraction of the segment:
        // stable for the modes nearly across the segment (B near 0), which carry the deflection.
        const double A = glm::dot(m.wavevector, q) + m.phase;
        const double B = glm::dot(m.wavevector, along);
        sum -= (m.amplitude * std::sin(A + 0.5 * B) * sinc(0.5 * B)) * m.wavevector;
    }
    return sum * glm::length(along);
}

glm::dvec3 deflection(const TurbulentField& field, std::span<const glm::dvec3> path, double t,
                      double background_index) {
    MIRAGE_CHECK(path.size() >= 2);
    MIRAGE_CHECK(background_index > 0.0);
    glm::dvec3 total(0.0);
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        const double len = glm::length(path[i + 1] - path[i]);
        if (len == 0.0) continue;
        const glm::dvec3 d = (path[i + 1] - path[i]) / len;
        const glm::dvec3 g = field.integrated_gradient(path[i], path[i + 1], t);
        total += g - glm::dot(g, d) * d;  // the part across the segment turns the ray
    }
    MIRAGE_CHECK(std::isfinite(total.x) && std::isfinite(total.y) && std::isfinite(total.z));
    return total / background_index;
}

}  // namespace mirage
