// Turbulent air: refractive-index fluctuations with the modified von Karman spectrum (Kolmogorov's
// inertial range between an inner and an outer scale), carried by a wind, and the deflection they
// give a ray along a polyline.
//
// Spectrum (Andrews & Phillips, "Laser Beam Propagation through Random Media", 2nd ed., 2005,
// ch. 3, the von Karman spectrum with Tatarskii's Gaussian inner-scale cutoff):
//   Phi_n(kappa) = A C_n^2 (kappa^2 + kappa0^2)^(-11/6) exp(-kappa^2 / kappa_m^2),
//   A = Gamma(8/3) sin(pi/3) / (4 pi^2) = 0.0330, kappa0 = 2 pi / L0, kappa_m = 5.92 / l0,
// whose structure function in the inertial range l0 << r << L0 is Kolmogorov's
// D_n(r) = <(dn(x + r) - dn(x))^2> = C_n^2 r^(2/3) (Tatarskii 1961; A is chosen for exactly this).
//
// Representation: a sum of random Fourier modes, dn(x) = sum_j a_j cos(k_j . x + phase_j), the
// wavenumbers |k_j| log-spaced from kappa0 / 20 to 3.5 kappa_m with a random offset inside each
// step (stratified sampling: the expected spectrum is the continuous one, with no bias from the
// spacing), directions uniform on the sphere, phases uniform, and a_j^2 / 2 = 4 pi kappa_j^2
// Phi_n(kappa_j) kappa_j dln(kappa) the variance of the mode's shell.  Why this form:
//  - it is continuous and smooth everywhere, with no grid and no box to wrap around, so a ray
//    may be asked about any point of a scene of any size;
//  - dn and its gradient are closed forms (the gradient a tracer needs is exact, not a finite
//    difference of a noisy field);
//  - the line integral of the gradient along a straight segment is a closed form too, so a
//    ray's deflection over hundreds of metres needs no quadrature step finer than the inner
//    scale (a millimetre), and it is exact for the field as generated;
//  - frozen flow is exact: dn(x, t) = dn(x - wind t, 0), so the frames of an animation are
//    the same air moved along.
// Its limit (docs/turbulence.md): a ray of length L feels only the modes with |k . d| below
// about 1 / L, a thin band of directions; the deflection's variance over realizations is the
// right one, but in one realization of a few hundred modes it is carried by few modes.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "util/result.h"

namespace mirage {

struct TurbulenceSettings {
    double cn2 = 1e-13;              // structure constant C_n^2, m^-2/3
    double inner_scale_m = 5e-3;     // l0
    double outer_scale_m = 1.0;      // L0
    glm::dvec3 wind{0.0, 0.0, 0.0};  // the air's velocity, m/s (frozen flow)
    std::uint64_t seed = 1;          // the realization: the same seed, the same air
    int modes_per_e_fold = 16;       // wavenumbers per factor e of |k|
};

/// Ranges check_turbulence accepts.
constexpr double kMaxCn2 = 1e-8;     // m^-2/3; strongest measured near ground ~1e-12
constexpr double kMinScaleM = 1e-5;  // inner and outer scales from 10 um ...
constexpr double kMaxScaleM = 1e5;   // ... to 100 km
constexpr double kMaxWindMps = 1e3;  // |wind|
constexpr int kMaxModesPerEFold = 1024;

/// Checks the settings: C_n^2 from 0 to kMaxCn2, scales from kMinScaleM to kMaxScaleM with the
/// inner below the outer, |wind| at most kMaxWindMps, modes per e-fold from 1 to
/// kMaxModesPerEFold.  The message names the value at fault.
Status check_turbulence(const TurbulenceSettings& settings);

/// A&P's constant A = Gamma(8/3) sin(pi/3) / (4 pi^2), for which D_n(r) = C_n^2 r^(2/3).
double kolmogorov_spectrum_constant();

/// Phi_n(kappa), the three-dimensional spectrum of the index fluctuations, in m^3.
double index_spectrum(const TurbulenceSettings& settings, double kappa);

/// One Fourier mode: amplitude * cos(wavevector . x + phase).
struct TurbulenceMode {
    glm::dvec3 wavevector{0.0};  // rad/m
    double amplitude = 0.0;      // of the index
    double phase = 0.0;          // rad
};

/// dn and its gradient at one point.
struct IndexFluctuation {
    double dn = 0.0;
    glm::dvec3 gradient{0.0};  // 1/m
};

/// One realization of turbulent air, moving with its wind.
class TurbulentField {
  public:
    /// Draws the modes of `settings.seed`; the settings must pass check_turbulence.
    static Result<TurbulentField> make(const TurbulenceSettings& settings);

    /// dn at point p (m) and time t (s).
    double index(const glm::dvec3& p, double t) const;
    /// dn and its gradient at p and t.
    IndexFluctuation sample(const glm::dvec3& p, double t) const;

    /// The integral of grad dn along the straight segment from a to b at time t (light's
    /// travel time ignored), exact for the field's modes.
    glm::dvec3 integrated_gradient(const glm::dvec3& a, const glm::dvec3& b, double t) const;

    const TurbulenceSettings& settings() const { return settings_; }
    std::span<const TurbulenceMode> modes() const { return modes_; }

  private:
    TurbulenceSettings settings_;
    std::vector<TurbulenceMode> modes_;
};

/// The angle by which the field turns a ray that follows `path` (a polyline, two points at
/// least) at time t: the integral along the path of the gradient of dn transverse to each
/// segment, divided by the background index n.  To first order in dn (the path is the unperturbed
/// one), the ray's unit direction at the end is its unperturbed one plus this vector.
glm::dvec3 deflection(const TurbulentField& field, std::span<const glm::dvec3> path, double t,
                      double background_index = 1.0);

}  // namespace mirage
