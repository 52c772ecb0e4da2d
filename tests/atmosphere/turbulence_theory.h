// Test helper of the turbulence tests (atmosphere/turbulence.h, atmosphere/phase_screens.h and
// the shimmer the tracer walks): the closed forms and integrals over the index spectrum that
// the generated fields are held to, and the uniform numbers the tests draw.
#pragma once

#include <cmath>
#include <numbers>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "atmosphere/turbulence.h"

namespace mirage::testing {

/// A uniform number in [0, 1), the same on every machine.
inline double uniform(std::mt19937_64& rng) {
    return static_cast<double>(rng() >> 11) * 0x1p-53;
}

/// int_0^inf f(kappa) dkappa on a fine grid in ln(kappa) (trapezoid): the integrands of these
/// tests are smooth in ln(kappa) and negligible outside [1e-6, 1e7] per metre.
template <class F>
double integrate_kappa(F f) {
    const double lo = std::log(1e-6), hi = std::log(1e7);
    const int n = 200000;
    const double h = (hi - lo) / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double k = std::exp(lo + i * h);
        sum += (i == 0 || i == n ? 0.5 : 1.0) * f(k) * k;
    }
    return sum * h;
}

/// The plane-wave angle-of-arrival variance per axis at a point receiver, Andrews & Phillips
/// (2005, ch. 6): 3.28 C_n^2 L l0^(-1/3) [1 - 0.72 (kappa0 l0)^(1/3)].
inline double tilt_variance_ap(const TurbulenceSettings& s, double length_m) {
    const double k0l0 = 2.0 * std::numbers::pi / s.outer_scale_m * s.inner_scale_m;
    return 3.28 * s.cn2 * length_m * std::pow(s.inner_scale_m, -1.0 / 3.0) *
           (1.0 - 0.72 * std::cbrt(k0l0));
}

/// The same as an integral, 2 pi^2 L int kappa^3 Phi_n(kappa) dkappa, with an aperture of
/// diameter D averaging the tilt (G-tilt: the integrand times (2 J1(kappa D/2) / (kappa D/2))^2).
inline double tilt_variance_integral(const TurbulenceSettings& s, double length_m,
                                     double aperture_m = 0.0) {
    const double r = 0.5 * aperture_m;
    const double pi = std::numbers::pi;
    return 2.0 * pi * pi * length_m * integrate_kappa([&](double k) {
               const double x = k * r;
               const double a = x < 1e-6 ? 1.0 : 2.0 * std::cyl_bessel_j(1.0, x) / x;
               return k * k * k * index_spectrum(s, k) * a * a;
           });
}

/// The correlation of one tilt component between two parallel rays rho apart (across the
/// rays, along the component), B(rho) / B(0) with B(rho) = int kappa^3 Phi_n(kappa)
/// 2 J1(kappa rho) / (kappa rho) dkappa: what frozen flow gives for the wind's displacement.
inline double tilt_correlation(const TurbulenceSettings& s, double rho) {
    const double b0 = integrate_kappa([&](double k) { return k * k * k * index_spectrum(s, k); });
    const double b = integrate_kappa([&](double k) {
        const double x = k * rho;
        return k * k * k * index_spectrum(s, k) *
               (x < 1e-6 ? 1.0 : 2.0 * std::cyl_bessel_j(1.0, x) / x);
    });
    return b / b0;
}

/// A tilt (or image shift) now and a separation's worth of wind later, summed over samples for
/// each separation: the measured correlation c1 / sqrt(c0 c2), held to tilt_correlation.
class TiltCorrelations {
  public:
    explicit TiltCorrelations(std::vector<double> rhos)
        : rhos_(std::move(rhos)), c0_(rhos_.size()), c1_(rhos_.size()), c2_(rhos_.size()) {}
    const std::vector<double>& rhos() const { return rhos_; }
    void add(std::size_t j, double now, double later) {
        c0_[j] += now * now;
        c1_[j] += now * later;
        c2_[j] += later * later;
    }
    /// Each separation's measured correlation within `tolerance` of tilt_correlation(s, rho);
    /// `what` names it in the printed table.
    void expect_near(const TurbulenceSettings& s, double tolerance, const std::string& what) const {
        for (std::size_t j = 0; j < rhos_.size(); ++j) {
            const double rho = rhos_[j];
            const double expected = tilt_correlation(s, rho);
            const double measured = c1_[j] / std::sqrt(c0_[j] * c2_[j]);
            std::printf("  rho = %.3f m: %s %.3f, expected %.3f\n", rho, what.c_str(), measured,
                        expected);
            EXPECT_NEAR(measured, expected, tolerance) << "rho = " << rho;
        }
    }

  private:
    std::vector<double> rhos_, c0_, c1_, c2_;
};

}  // namespace mirage::testing
