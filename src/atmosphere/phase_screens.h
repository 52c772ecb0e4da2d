// Turbulent air for rendering: a stack of phase screens across the camera's line of sight, each
// the index fluctuations of one slab of air integrated through it, and the first-order walk of a
// ray's path through them (each screen a small kink).
//
// Why screens rather than the three-dimensional field of turbulence.h (docs/turbulence.md): a
// ray's tilt is the integral of grad dn across it along its path, which keeps only the slice of
// the spectrum with kappa . d = 0.  A sum of a few hundred three-dimensional modes puts almost no
// mode in that slice for a path of hundreds of metres, so in one realization a few rays (those
// along which a fine mode happens to lie across) turn hundreds of times more than the rest.  A
// screen holds exactly that slice: two-dimensional modes, every one of them across the line of
// sight, so every ray through a screen feels all its modes and one realization's tilts are as
// Gaussian as the ensemble's.  The slab integral of dn over a slab dz thick (dz much longer than
// the gradient's correlation length, about the inner scale) has the two-dimensional spectrum
//   Phi_psi(q) = 2 pi dz Phi_n(q)          (Tatarskii 1971; A&P 2005, ch. 6 and 12)
// and screens of independent seeds stand for independent slabs.
//
// A camera's aperture of diameter D (0: a point, the pinhole) averages the tilt over the bundle
// of rays it collects: each mode is multiplied by the disc's average of a plane wave,
// 2 J1(q D / 2) / (q D / 2), the G-tilt of A&P ch. 6, whose variance for l0 << D << L0 is
// 2.91 C_n^2 L D^(-1/3) for a plane wave.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "atmosphere/turbulence.h"
#include "util/result.h"

namespace mirage {

/// Where the screens stand: planes across `axis`, `count` of them at (j + 1/2) reach / count
/// from `origin` (j = 0 .. count - 1), each for the slab of air reach / count thick around it.
struct ScreenLayout {
    glm::dvec3 origin{0.0};          // the eye, m
    glm::dvec3 axis{0.0, 0.0, 1.0};  // the line of sight: the screens' normal (made unit)
    double reach_m = 100.0;          // how far the turbulent air reaches along the axis
    int count = 16;                  // screens
    double aperture_m = 0.0;         // the camera's aperture diameter D (0: a point)
    // Wavenumbers per factor e of |q| on each screen: a ray sums the modes of every screen it
    // crosses, so a few per screen make its tilt Gaussian (PhaseScreens tests), and each costs a
    // sine per crossing.
    int modes_per_e_fold = 6;
};

constexpr int kMaxScreens = 1024;
constexpr double kMaxApertureM = 10.0;

/// Checks the layout: a finite origin, a non-zero axis, reach from kMinScaleM to 1e9 m, count
/// from 1 to kMaxScreens, aperture from 0 to kMaxApertureM, modes per e-fold from 1 to
/// kMaxModesPerEFold.  The message names the value.
Status check_screen_layout(const ScreenLayout& layout);

/// One screen's two-dimensional mode: amplitude * cos(wavevector . x + phase), the wavevector
/// across the axis.
using ScreenMode = TurbulenceMode;

class PhaseScreens {
  public:
    /// Draws the screens of `settings.seed` (each screen its own stream of it); both must pass
    /// their checks.
    static Result<PhaseScreens> make(const TurbulenceSettings& settings,
                                     const ScreenLayout& layout);

    int count() const { return static_cast<int>(screens_.size()); }
    /// Screen j's distance from the origin along the axis, m.
    double distance(int j) const { return (j + 0.5) * spacing_; }
    double spacing() const { return spacing_; }
    /// The distance of point p (m) along the axis from the origin.
    double depth(const glm::dvec3& p) const;

    /// Screen j's integrated index psi_j = int dn dz over its slab (m), at point p of its plane
    /// (m) and time t (s): frozen flow, psi_j(p - wind t).  Not aperture-averaged.
    double phase(int j, const glm::dvec3& p, double t) const;
    /// The gradient of screen j's psi at p and t, aperture-averaged: the turn (rad) it gives a
    /// ray along the axis there, a vector across the axis.
    glm::dvec3 tilt(int j, const glm::dvec3& p, double t) const;
    /// The turn screen j gives a ray of unit direction d crossing it at p: the tilt across d,
    /// divided by sqrt(|d . axis|) (a slanted ray crosses 1 / |d . axis| times as much air, and
    /// the variance of its turn grows as the path), at most that of |d . axis| = kMinObliquity.
    glm::dvec3 turn(int j, const glm::dvec3& p, double t, const glm::dvec3& d) const;
    /// The same with slant(d) given (it is the same at every screen a straight stretch
    /// crosses).
    glm::dvec3 turn(int j, const glm::dvec3& p, double t, const glm::dvec3& d, double slant) const;
    /// The factor of a ray of unit direction d's turns: 1 / sqrt(|d . axis|), at most
    /// 1 / sqrt(kMinObliquity).
    double slant(const glm::dvec3& d) const;

    /// Screen j's tilt at the point whose coordinates across the axis (along u and v of
    /// across()) are `at`, the wind's motion already taken away: tilt() without the
    /// projections, in the same coordinates.
    glm::dvec2 tilt_across(int j, const glm::dvec2& at) const;
    /// The two unit vectors across the axis that the screens' coordinates are taken along.
    const glm::dvec3& across_u() const { return u_; }
    const glm::dvec3& across_v() const { return v_; }

    std::span<const ScreenMode> modes(int j) const { return screens_[j].modes; }
    const TurbulenceSettings& settings() const { return settings_; }
    const ScreenLayout& layout() const { return layout_; }

    /// Rays more slanted than this to the axis are turned as at this slant.
    static constexpr double kMinObliquity = 0.25;

  private:
    struct Screen {
        std::vector<ScreenMode> modes;
        // For the tilt's sum, by component so that it vectorizes, padded with modes of no
        // weight to a whole number of kTiltLanes: the wavevector's components along u_ and v_
        // in turns per metre (k / 2 pi), the phase in turns, and the mode's tilt per unit of
        // its sine along u_ and v_, -amplitude * 2 J1(x) / x * (k . u_ or k . v_).
        std::vector<double> turns_u, turns_v, turns_phase, tilt_u, tilt_v;
    };
    TurbulenceSettings settings_;
    ScreenLayout layout_;
    glm::dvec3 u_{1.0, 0.0, 0.0}, v_{0.0, 1.0, 0.0};  // unit, across the axis and each other
    double spacing_ = 0.0;
    std::vector<Screen> screens_;
};

/// The first-order walk of one ray's path through the screens: fed the unperturbed path's
/// points in order (metres, along any path: straight, curved or reflected), it returns where the
/// perturbed path is at each and adds a point at every screen crossed on the way, the kinks.  The
/// perturbation is the displacement int_0^s T(s') ds', T(s) the sum of the turns of the screens
/// crossed before s, so the ray's sight of a point at distance L is moved by
/// int_0^L (1 - s / L) grad dn ds: the angle of arrival of a spherical wave from it.
///
///     ScreenWalk walk(screens, t, start);
///     for (each next point p of the unperturbed path) {
///         walk.to(p, points);               // points: the perturbed kinks then p's image
///         ...march the points...
///     }
///     walk.ray(final_direction, points);    // the kinks left ahead of a last straight ray
///     glm::dvec3 d = walk.direction(final_direction);
class ScreenWalk {
  public:
    ScreenWalk(const PhaseScreens& screens, double t, const glm::dvec3& start);

    /// Moves along the unperturbed path to p; appends to `out` (cleared first) the perturbed
    /// points of the screens crossed on the way and last the perturbed p.
    void to(const glm::dvec3& p, std::vector<glm::dvec3>& out);
    /// For a last straight ray along unit d from the current point: appends the perturbed
    /// points of the screens ahead (cleared first), and moves past them.
    void ray(const glm::dvec3& d, std::vector<glm::dvec3>& out);
    /// The perturbed direction of unit d: d plus the turns so far, made unit.
    glm::dvec3 direction(const glm::dvec3& d) const;

    const glm::dvec3& turn() const { return turn_; }
    const glm::dvec3& offset() const { return offset_; }

  private:
    void cross(const glm::dvec3& a, const glm::dvec3& d, double length, double depth_a,
               double depth_b, std::vector<glm::dvec3>& out);

    const PhaseScreens* screens_;
    double t_;
    glm::dvec3 at_;           // the unperturbed point reached
    glm::dvec3 offset_{0.0};  // the perturbed point minus the unperturbed, m
    glm::dvec3 turn_{0.0};    // the direction's change so far, rad
    // offset_ and turn_ across the axis, in the screens' coordinates (PhaseScreens::across),
    // kept beside them: the next crossing's screen coordinates wait on them alone, not on a
    // projection of the three-dimensional sums.
    glm::dvec2 offset_across_{0.0}, turn_across_{0.0};
};

}  // namespace mirage
