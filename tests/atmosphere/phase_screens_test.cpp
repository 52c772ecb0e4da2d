#include "atmosphere/phase_screens.h"
#include "atmosphere/turbulence_theory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <vector>

namespace mirage {
namespace {

using testing::integrate_kappa;
using testing::TiltCorrelations;
using testing::tilt_variance_ap;
using testing::tilt_variance_integral;
using testing::uniform;

constexpr double kPi = std::numbers::pi;

PhaseScreens make_screens(const TurbulenceSettings& s, const ScreenLayout& l) {
    auto f = PhaseScreens::make(s, l);
    EXPECT_TRUE(f.ok()) << f.message();
    return std::move(f).value();
}

// The tilt, both axes across z, of a ray along +z through the whole stack from (x, y, 0).
glm::dvec3 plane_wave_tilt(const PhaseScreens& screens, const glm::dvec3& start, double t) {
    ScreenWalk walk(screens, t, start);
    std::vector<glm::dvec3> points;
    walk.to(start + glm::dvec3(0.0, 0.0, screens.layout().reach_m), points);
    return walk.turn();
}

TEST(PhaseScreens, LayoutOutOfRangeIsNamed) {
    ScreenLayout l;
    l.count = 0;
    EXPECT_EQ(check_screen_layout(l).message(), "screens 0 must be from 1 to 1024");
    l = {};
    l.aperture_m = -0.1;
    EXPECT_EQ(check_screen_layout(l).message(), "aperture -0.1 m must be from 0 to 10 m");
    l = {};
    l.reach_m = 0.0;
    EXPECT_EQ(check_screen_layout(l).message(),
              "the turbulent air's reach 0 m must be from 1e-05 to 1e+09 m");
    l = {};
    l.axis = glm::dvec3(0.0);
    EXPECT_FALSE(PhaseScreens::make(TurbulenceSettings{}, l).ok());
    EXPECT_TRUE(check_screen_layout(ScreenLayout{}).ok());
}

TEST(PhaseScreens, ModesLieAcrossTheAxisAndScreensDiffer) {
    ScreenLayout l;
    l.axis = glm::dvec3(1.0, 0.2, 0.5);
    const PhaseScreens s = make_screens(TurbulenceSettings{}, l);
    const glm::dvec3 e = glm::normalize(l.axis);
    for (int j = 0; j < s.count(); ++j)
        for (const auto& m : s.modes(j))
            EXPECT_LT(std::abs(glm::dot(m.wavevector, e)), 1e-12 * glm::length(m.wavevector));
    EXPECT_NE(s.phase(0, glm::dvec3(0.3, 0.1, 0.2), 0.0),
              s.phase(1, glm::dvec3(0.3, 0.1, 0.2), 0.0));
}

TEST(PhaseScreens, TiltIsThePhasesGradientWithoutAperture) {
    TurbulenceSettings ts;
    ts.wind = glm::dvec3(1.0, 2.0, 0.0);
    const PhaseScreens s = make_screens(ts, ScreenLayout{});
    const glm::dvec3 p(0.4, 1.3, s.distance(3));
    const double h = 1e-6, t = 0.21;
    const glm::dvec3 g = s.tilt(3, p, t);
    for (int i = 0; i < 2; ++i) {
        glm::dvec3 e(0.0);
        e[i] = h;
        const double fd = (s.phase(3, p + e, t) - s.phase(3, p - e, t)) / (2.0 * h);
        EXPECT_NEAR(g[i], fd, 1e-6 * glm::length(g)) << "axis " << i;
    }
    EXPECT_EQ(g.z, 0.0);
}

// The tilt's fast sine and its sums against the library's sine, mode by mode, at points far
// from the origin (phases of thousands of turns), with and without wind.
TEST(PhaseScreens, TiltIsTheSumOfItsModesGradients) {
    TurbulenceSettings ts;
    ts.inner_scale_m = 0.002;
    ts.wind = glm::dvec3(3.0, -1.0, 0.5);
    ScreenLayout l;
    l.axis = glm::dvec3(0.2, 0.1, 1.0);
    const PhaseScreens s = make_screens(ts, l);
    std::mt19937_64 rng(12);
    for (int i = 0; i < 200; ++i) {
        const int j = i % s.count();
        const glm::dvec3 p(200.0 * (uniform(rng) - 0.5), 50.0 * uniform(rng), s.distance(j));
        const double t = 2.0 * uniform(rng);
        glm::dvec3 direct(0.0);
        double scale = 0.0;
        for (const auto& m : s.modes(j)) {
            const double phase = glm::dot(m.wavevector, p - ts.wind * t) + m.phase;
            direct -= m.amplitude * std::sin(phase) * m.wavevector;
            scale += m.amplitude * glm::length(m.wavevector);
        }
        // The sine's error bound, 1.15e-9 per mode (phase_screens.cpp), and rounding.
        EXPECT_LT(glm::length(s.tilt(j, p, t) - direct), 2e-9 * scale) << i;
    }
}

// The structure function of one screen's phase, psi = int dn dz over its slab, against the
// 5/3 law D_psi(r) = 8 pi^2 dz int q Phi_n(q) (1 - J0(q r)) dq = 2.914 C_n^2 dz r^(5/3)
// (A&P 2005, ch. 6, the phase structure function divided by k^2), over a decade of separations
// inside the inertial range (l0 = 1 mm, r = 2 to 50 cm), 8 seeds x 16 screens x 500 pairs, random
// points and random directions of r in the screen.  The phase feels the outer scale far more
// than dn does (its departure from the law is about 0.8 (kappa0 r)^(1/3): 26 % at 50 cm for
// L0 = 100 m, which the model's integral and the measurement both show), so L0 = 100 km here.
TEST(PhaseScreens, PhaseStructureFunctionFollowsTheFiveThirdsLaw) {
    TurbulenceSettings s;
    s.cn2 = 1e-13;
    s.inner_scale_m = 1e-3;
    s.outer_scale_m = 1e5;
    ScreenLayout l;
    l.reach_m = 160.0;  // slabs of 10 m
    const int seeds = 8, pairs = 500;
    for (double r : {0.02, 0.05, 0.1, 0.2, 0.5}) {
        const double dz = l.reach_m / l.count;
        const double law = 2.914 * s.cn2 * dz * std::pow(r, 5.0 / 3.0);
        const double model = 8.0 * kPi * kPi * dz * integrate_kappa([&](double q) {
                                 const double x = q * r;
                                 return q * index_spectrum(s, q) *
                                        (x < 1e-4 ? x * x / 4.0 : 1.0 - std::cyl_bessel_j(0.0, x));
                             });
        std::vector<double> per_seed;
        for (int seed = 1; seed <= seeds; ++seed) {
            s.seed = 300 + seed;
            const PhaseScreens f = make_screens(s, l);
            std::mt19937_64 rng(seed);
            double sum = 0.0;
            for (int j = 0; j < f.count(); ++j) {
                for (int i = 0; i < pairs; ++i) {
                    const glm::dvec3 x(100.0 * uniform(rng), 100.0 * uniform(rng), f.distance(j));
                    const double a = 2.0 * kPi * uniform(rng);
                    const glm::dvec3 dr(r * std::cos(a), r * std::sin(a), 0.0);
                    const double d = f.phase(j, x + dr, 0.0) - f.phase(j, x, 0.0);
                    sum += d * d;
                }
            }
            per_seed.push_back(sum / (pairs * f.count()));
        }
        double mean = 0.0, var = 0.0;
        for (double v : per_seed) mean += v / seeds;
        for (double v : per_seed) var += (v - mean) * (v - mean) / (seeds - 1);
        const double error = std::sqrt(var / seeds) / mean;
        std::printf(
            "  r = %.2f m: D_psi / (2.914 C_n^2 dz r^5/3) = %.4f (model's integral %.4f), "
            "statistical error %.2f %%\n",
            r, mean / law, model / law, 100.0 * error);
        EXPECT_LT(error, 0.03) << "too few samples to test at 10 %";
        EXPECT_NEAR(mean / law, 1.0, 0.10) << "r = " << r;
    }
}

// The tilts of rays along the axis through the whole stack, `rays` of them at random points
// 50 m apart at most, both axes, in each of `realizations` from `first_seed` on.
std::vector<double> stack_tilts(TurbulenceSettings s, const ScreenLayout& l, int realizations,
                                int rays, std::uint64_t first_seed) {
    std::vector<double> out;
    std::mt19937_64 rng(first_seed);
    for (int r = 0; r < realizations; ++r) {
        s.seed = first_seed + r;
        const PhaseScreens f = make_screens(s, l);
        for (int i = 0; i < rays; ++i) {
            const glm::dvec3 a(50.0 * uniform(rng), 50.0 * uniform(rng), 0.0);
            const glm::dvec3 t = plane_wave_tilt(f, a, 0.0);
            out.push_back(t.x);
            out.push_back(t.y);
        }
    }
    return out;
}

double mean_square(const std::vector<double>& v) {
    double sum = 0.0;
    for (double x : v) sum += x * x;
    return sum / static_cast<double>(v.size());
}

// (b) The plane-wave angle-of-arrival variance at a point receiver for C_n^2 = 1e-14, 1e-13,
// 1e-12 (l0 = 1 cm, L0 = 100 m, L = 10 m in 10 screens, as turbulence_test.cpp checks the
// three-dimensional field): 300 realizations x 16 rays x 2 axes = 9600 tilts each; the
// statistical error from 30 batches.
TEST(PhaseScreens, AngleOfArrivalVarianceMatchesThePlaneWaveFormula) {
    TurbulenceSettings s;
    s.inner_scale_m = 0.01;
    s.outer_scale_m = 100.0;
    ScreenLayout l;
    l.reach_m = 10.0;
    l.count = 10;
    const int realizations = 300, rays = 16, batches = 30;
    std::uint64_t seed = 1;
    for (double cn2 : {1e-14, 1e-13, 1e-12}) {
        s.cn2 = cn2;
        const std::vector<double> t = stack_tilts(s, l, realizations, rays, seed);
        seed += realizations;
        const double variance = mean_square(t);
        const std::size_t per = t.size() / batches;
        double spread = 0.0;
        for (int b = 0; b < batches; ++b) {
            const std::vector<double> part(t.begin() + b * per, t.begin() + (b + 1) * per);
            const double v = mean_square(part);
            spread += (v - variance) * (v - variance) / (batches - 1);
        }
        const double error = std::sqrt(spread / batches) / variance;
        const double ap = tilt_variance_ap(s, l.reach_m);
        std::printf(
            "  C_n^2 = %.0e: <alpha^2> = %.4g rad^2, A&P %.4g (ratio %.3f), integral %.4g, "
            "statistical error %.1f %%\n",
            cn2, variance, ap, variance / ap, tilt_variance_integral(s, l.reach_m, 0.0),
            100.0 * error);
        EXPECT_LT(error, 0.07) << "too few samples to test at 20 %";
        EXPECT_NEAR(variance / ap, 1.0, 0.20) << "C_n^2 = " << cn2;
    }
}

// The largest x^2 / sigma^2 among n samples of a Gaussian that a correct model exceeds with
// probability at most p, from the union bound P(max > x) <= n P(chi^2_1 > x) = n erfc(sqrt(x/2)),
// which holds whatever the samples' correlation: solved for x by bisection.
double gaussian_max_bound(double n, double p) {
    double lo = 1.0, hi = 200.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (n * std::erfc(std::sqrt(0.5 * mid)) > p ? lo : hi) = mid;
    }
    return hi;
}

// The flaw the screens were made for (docs/turbulence.md): within ONE realization, long paths
// through air with a millimetre inner scale (l0 = 1 mm, L0 = 100 m, L = 100 m in 16 screens),
// 4000 rays at random points x 2 axes = 8000 tilts.  For six seeds: the realization's variance
// within 20 % of the formula, and its largest tilt^2 / variance below what 48000 Gaussian samples
// exceed with probability 1e-3 (the union bound above: 31.4).  The three-dimensional field of
// turbulence.h, asked the same for the first seed (4000 rays of random horizontal azimuth),
// exceeds the bound: the check sees the heavy tail.
TEST(PhaseScreens, OneRealizationsTiltsAreGaussianOverLongPaths) {
    TurbulenceSettings s;
    s.cn2 = 1e-13;
    s.inner_scale_m = 1e-3;
    s.outer_scale_m = 100.0;
    ScreenLayout l;
    l.reach_m = 100.0;
    l.count = 16;
    const int seeds = 6, rays = 4000;
    const double bound = gaussian_max_bound(2.0 * rays * seeds, 1e-3);
    const double ap = tilt_variance_ap(s, l.reach_m);
    for (int k = 0; k < seeds; ++k) {
        const std::vector<double> t = stack_tilts(s, l, 1, rays, 7000 + k);
        const double variance = mean_square(t);
        double largest = 0.0;
        for (double x : t) largest = std::max(largest, x * x / variance);
        std::printf(
            "  seed %d: variance / formula %.3f, largest tilt^2 / variance %.1f (bound %.1f)\n",
            7000 + k, variance / ap, largest, bound);
        EXPECT_NEAR(variance / ap, 1.0, 0.20) << "seed " << 7000 + k;
        EXPECT_LT(largest, bound) << "seed " << 7000 + k;
    }
    // The same air as three-dimensional modes: heavy-tailed.
    s.seed = 7000;
    auto field = TurbulentField::make(s);
    ASSERT_TRUE(field.ok());
    std::mt19937_64 rng(5);
    std::vector<double> t;
    for (int i = 0; i < rays; ++i) {
        const double az = 2.0 * kPi * uniform(rng);
        const glm::dvec3 d(std::cos(az), 0.0, std::sin(az)), side(-d.z, 0.0, d.x);
        const glm::dvec3 a(50.0 * uniform(rng), 2.0 * uniform(rng), 50.0 * uniform(rng));
        const glm::dvec3 path[] = {a, a + l.reach_m * d};
        const glm::dvec3 bent = deflection(*field, path, 0.0);
        t.push_back(bent.y);
        t.push_back(glm::dot(bent, side));
    }
    const double variance = mean_square(t);
    double largest = 0.0;
    for (double x : t) largest = std::max(largest, x * x / variance);
    std::printf("  three-dimensional modes: largest tilt^2 / variance %.1f\n", largest);
    EXPECT_GT(largest, bound);
}

// An aperture much larger than the inner scale averages the tilt (l0 = 2 mm, D = 5 cm, L0 =
// 100 m, L = 50 m): the variance against the filtered integral, within 20 %; A&P's large-aperture
// form 2.91 C_n^2 L D^(-1/3) printed beside it.  200 realizations x 16 rays.
TEST(PhaseScreens, ApertureAveragesTheTilt) {
    TurbulenceSettings s;
    s.cn2 = 1e-13;
    s.inner_scale_m = 2e-3;
    s.outer_scale_m = 100.0;
    ScreenLayout l;
    l.reach_m = 50.0;
    l.aperture_m = 0.05;
    const double variance = mean_square(stack_tilts(s, l, 200, 16, 90000));
    const double expected = tilt_variance_integral(s, l.reach_m, l.aperture_m);
    const double point = tilt_variance_integral(s, l.reach_m, 0.0);
    std::printf(
        "  D = 5 cm: <alpha^2> %.4g, integral %.4g (ratio %.3f), 2.91 C_n^2 L D^-1/3 %.4g, "
        "a point %.4g\n",
        variance, expected, variance / expected,
        2.91 * s.cn2 * l.reach_m * std::pow(l.aperture_m, -1.0 / 3.0), point);
    EXPECT_NEAR(variance / expected, 1.0, 0.20);
    EXPECT_LT(expected, 0.5 * point);  // the aperture matters at these scales
}

// (c) Frozen flow: each screen at (p, t + dt) is the screen at (p - wind dt, t), and the tilt of
// a ray decorrelates as the wind moves the air across it, against the plane-wave covariance of
// two parallel paths rho apart, B(rho) / B(0), B(rho) = int kappa^3 Phi_n J1(kappa rho) /
// (kappa rho) dkappa (turbulence_test.cpp), for the tilt across both the ray and the wind.
TEST(PhaseScreens, TiltsDecorrelateAsTheWindMovesTheAir) {
    TurbulenceSettings s;
    s.cn2 = 1e-13;
    s.inner_scale_m = 0.01;
    s.outer_scale_m = 100.0;
    s.wind = glm::dvec3(5.0, 0.0, 1.0);  // the part along the axis moves nothing across it
    ScreenLayout l;
    l.reach_m = 10.0;
    l.count = 10;
    {
        const PhaseScreens f = make_screens(s, l);
        const glm::dvec3 p(0.3, 0.7, f.distance(2));
        const glm::dvec3 later = f.tilt(2, p, 0.8), moved = f.tilt(2, p - s.wind * 0.3, 0.5);
        EXPECT_LT(glm::length(later - moved), 1e-9 * glm::length(later));
        EXPECT_GT(glm::length(later - f.tilt(2, p, 0.5)), 1e-3 * glm::length(later));
    }
    TiltCorrelations corr({0.002, 0.005, 0.01, 0.02});
    const std::vector<double>& rhos = corr.rhos();
    std::mt19937_64 rng(99);
    for (int r = 0; r < 300; ++r) {
        s.seed = 50000 + r;
        const PhaseScreens f = make_screens(s, l);
        for (int i = 0; i < 16; ++i) {
            const glm::dvec3 a(50.0 * uniform(rng), 50.0 * uniform(rng), 0.0);
            const double now = plane_wave_tilt(f, a, 0.0).y;
            for (std::size_t j = 0; j < rhos.size(); ++j) {
                const double later = plane_wave_tilt(f, a, rhos[j] / s.wind.x).y;
                corr.add(j, now, later);
            }
        }
    }
    corr.expect_near(s, 0.08, "tilt correlation");
}

// The walk: a point at distance L is seen moved by sum_j turn_j (L - z_j) (the spherical wave's
// weights), the same whether the path to it is given in one piece or several, forward or back,
// and every screen crossed leaves its kink.
TEST(PhaseScreens, WalkCarriesEachTurnToTheEnd) {
    TurbulenceSettings s;
    s.cn2 = 1e-12;
    ScreenLayout l;
    l.reach_m = 40.0;
    l.count = 8;
    const PhaseScreens f = make_screens(s, l);
    const glm::dvec3 a(0.2, 0.3, 0.0), b(1.0, 0.5, 33.0);  // crosses screens 0 to 6
    std::vector<glm::dvec3> points;
    ScreenWalk one(f, 0.1, a);
    one.to(b, points);
    ASSERT_EQ(points.size(), 8u);
    // By hand: the turns at the kinks, each carried over the rest of the way.
    const glm::dvec3 d = glm::normalize(b - a);
    const double length = glm::length(b - a);
    glm::dvec3 turn(0.0), offset(0.0);
    double done = 0.0;
    for (int j = 0; j < 7; ++j) {
        const double sj = length * f.distance(j) / (b.z - a.z);
        offset += turn * (sj - done);
        done = sj;
        EXPECT_LT(glm::length(points[j] - (a + sj * d + offset)), 1e-12);
        turn += f.turn(j, points[j], 0.1, d);
    }
    offset += turn * (length - done);
    EXPECT_LT(glm::length(points.back() - (b + offset)), 1e-12);
    EXPECT_GT(glm::length(offset), 0.0);
    EXPECT_LT(glm::length(one.direction(d) - glm::normalize(d + turn)), 1e-15);
    // In three pieces, the same (to rounding).
    ScreenWalk three(f, 0.1, a);
    three.to(a + 0.3 * (b - a), points);
    three.to(a + 0.55 * (b - a), points);
    three.to(b, points);
    EXPECT_LT(glm::length(points.back() - (b + offset)), 1e-12);
    // A last ray on crosses the remaining screen and no more.
    one.ray(d, points);
    EXPECT_EQ(points.size(), 1u);
    // Backwards from the far end: the screens in reverse order.
    ScreenWalk back(f, 0.1, b);
    back.to(a, points);
    EXPECT_EQ(points.size(), 8u);
    EXPECT_GT(points[0].z, points[6].z);
}

}  // namespace
}  // namespace mirage
