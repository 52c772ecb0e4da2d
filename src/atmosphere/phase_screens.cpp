#include "atmosphere/phase_screens.h"

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
// The golden angle: successive modes' directions spread as evenly as a sequence can, so each
// screen's tilt has the same variance along both axes across it.
const double kGoldenAngle = kPi * (3.0 - std::sqrt(5.0));

double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// The disc's average of cos(q . x + phase) over a disc of radius r is this times its value at
// the centre.
double disc_average(double qr) {
    return qr < 1e-6 ? 1.0 - qr * qr / 8.0 : 2.0 * std::cyl_bessel_j(1.0, qr) / qr;
}

// sin(x) for the tilts' sums, several times as fast as the library's and free of branches,
// so that a loop of it vectorizes: x reduced to [-pi, pi] by the nearest multiple of 2 pi
// (rounded by adding and taking away 1.5 * 2^52; exact enough for |x| up to 1e6, whose
// reduction then rounds by 1e-10), then Taylor's series to x^19, whose error there is below
// pi^21 / 21! = 6e-10.  Plain double arithmetic: the same bytes on every thread.
inline double fast_sin(double x) {
    constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
    const double k = (x * (0.5 / kPi) + kRound) - kRound;
    const double r = (x - k * 6.283185307179586232) - k * 2.4492935982947064e-16;
    const double r2 = r * r;
    double p = -1.0 / 121645100408832000.0;  // -1 / 19!
    p = p * r2 + 1.0 / 355687428096000.0;
    p = p * r2 - 1.0 / 1307674368000.0;
    p = p * r2 + 1.0 / 6227020800.0;
    p = p * r2 - 1.0 / 39916800.0;
    p = p * r2 + 1.0 / 362880.0;
    p = p * r2 - 1.0 / 5040.0;
    p = p * r2 + 1.0 / 120.0;
    p = p * r2 - 1.0 / 6.0;
    return r + r * r2 * p;
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

Status check_screen_layout(const ScreenLayout& l) {
    if (!finite(l.origin)) return make_error("the screens' origin must be finite");
    const double a = glm::length(l.axis);
    if (!(a > 0.0 && std::isfinite(a))) return make_error("the screens' axis must be a direction");
    if (!(l.reach_m >= kMinScaleM && l.reach_m <= 1e9))
        return make_error("the turbulent air's reach " + shortest(l.reach_m) + " m must be from " +
                          shortest(kMinScaleM) + " to 1e+09 m");
    if (l.count < 1 || l.count > kMaxScreens)
        return make_error("screens " + std::to_string(l.count) + " must be from 1 to " +
                          std::to_string(kMaxScreens));
    if (!(l.aperture_m >= 0.0 && l.aperture_m <= kMaxApertureM))
        return make_error("aperture " + shortest(l.aperture_m) + " m must be from 0 to " +
                          shortest(kMaxApertureM) + " m");
    if (l.modes_per_e_fold < 1 || l.modes_per_e_fold > kMaxModesPerEFold)
        return make_error("modes per e-fold " + std::to_string(l.modes_per_e_fold) +
                          " must be from 1 to " + std::to_string(kMaxModesPerEFold));
    return Ok{};
}

Result<PhaseScreens> PhaseScreens::make(const TurbulenceSettings& settings,
                                        const ScreenLayout& layout) {
    if (auto st = check_turbulence(settings); !st) return st.error();
    if (auto st = check_screen_layout(layout); !st) return st.error();
    PhaseScreens out;
    out.settings_ = settings;
    out.layout_ = layout;
    out.layout_.axis = glm::normalize(layout.axis);
    out.spacing_ = layout.reach_m / layout.count;
    const glm::dvec3 e = out.layout_.axis;
    // Two unit vectors across the axis.
    const glm::dvec3 helper =
        std::abs(e.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, e));
    const glm::dvec3 v = glm::cross(e, u);
    // From kappa0 / 4 (the spectrum is flat below kappa0: a shell's share of the tilt variance
    // falls as q^4, and below kappa0 / 4 all of them hold less than 1e-3 of it, as they do of
    // the phase's structure function at r << L0) to 3.5 kappa_m (exp(-12) of the spectrum left)
    // or, with an aperture of radius R, to 16 / R, beyond which the aperture leaves about 1 % of
    // the tilt variance ((2 J1(x) / x)^2 < 8 / (pi x^3)).
    const double radius = 0.5 * layout.aperture_m;
    double top = 3.5 * 5.92 / settings.inner_scale_m;
    if (radius > 0.0) top = std::min(top, 16.0 / radius);
    const double bottom = 2.0 * kPi / settings.outer_scale_m / 4.0;
    const double lo = std::log(bottom), hi = std::log(std::max(top, 2.0 * bottom));
    const int n = static_cast<int>(std::ceil((hi - lo) * layout.modes_per_e_fold));
    const double step = (hi - lo) / n;
    out.screens_.resize(layout.count);
    for (int j = 0; j < layout.count; ++j) {
        // Each screen its own stream of the seed (seed_seq's mixing is the standard's).
        std::seed_seq seq{static_cast<std::uint32_t>(settings.seed),
                          static_cast<std::uint32_t>(settings.seed >> 32),
                          static_cast<std::uint32_t>(j), 0x5C4EE7u};
        std::mt19937_64 rng(seq);
        Screen& screen = out.screens_[j];
        screen.modes.reserve(n);
        const double first_angle = 2.0 * kPi * uniform(rng);
        for (int m = 0; m < n; ++m) {
            const double q = std::exp(lo + (m + uniform(rng)) * step);
            const double angle = first_angle + m * kGoldenAngle;
            // The slab's spectrum 2 pi dz Phi_n(q); its shell's variance, 2 pi q Phi_psi(q) dq
            // with dq = q dln(q), is a^2 / 2 for a cosine of random phase.
            const double phi_psi = 2.0 * kPi * out.spacing_ * index_spectrum(settings, q);
            const double shell = 2.0 * kPi * q * phi_psi * q * step;
            ScreenMode mode;
            mode.wavevector = q * (std::cos(angle) * u + std::sin(angle) * v);
            mode.amplitude = std::sqrt(2.0 * shell);
            mode.phase = 2.0 * kPi * uniform(rng);
            screen.modes.push_back(mode);
            screen.kx.push_back(mode.wavevector.x);
            screen.ky.push_back(mode.wavevector.y);
            screen.kz.push_back(mode.wavevector.z);
            screen.phase.push_back(mode.phase);
            screen.weight.push_back(mode.amplitude * disc_average(q * radius));
        }
    }
    return out;
}

double PhaseScreens::depth(const glm::dvec3& p) const {
    return glm::dot(p - layout_.origin, layout_.axis);
}

double PhaseScreens::phase(int j, const glm::dvec3& p, double t) const {
    MIRAGE_CHECK(j >= 0 && j < count());
    const glm::dvec3 x = p - settings_.wind * t;  // frozen flow
    double psi = 0.0;
    for (const auto& m : screens_[j].modes)
        psi += m.amplitude * std::cos(glm::dot(m.wavevector, x) + m.phase);
    return psi;
}

glm::dvec3 PhaseScreens::tilt(int j, const glm::dvec3& p, double t) const {
    MIRAGE_CHECK(j >= 0 && j < count());
    const glm::dvec3 x = p - settings_.wind * t;
    const Screen& s = screens_[j];
    const std::size_t n = s.kx.size();
    // The modes' sines first (a loop without a sum, which the compiler vectorizes), then the
    // sum in the modes' order.
    thread_local std::vector<double> sines;
    sines.resize(n);
    double* out = sines.data();
    const double *kx = s.kx.data(), *ky = s.ky.data(), *kz = s.kz.data();
    const double *phase = s.phase.data(), *weight = s.weight.data();
    for (std::size_t k = 0; k < n; ++k)
        out[k] = weight[k] * fast_sin(kx[k] * x.x + ky[k] * x.y + kz[k] * x.z + phase[k]);
    glm::dvec3 g(0.0);
    for (std::size_t k = 0; k < n; ++k) {
        g.x -= out[k] * kx[k];
        g.y -= out[k] * ky[k];
        g.z -= out[k] * kz[k];
    }
    return g;
}

glm::dvec3 PhaseScreens::turn(int j, const glm::dvec3& p, double t, const glm::dvec3& d) const {
    const glm::dvec3 g = tilt(j, p, t);
    const double c = std::max(std::abs(glm::dot(d, layout_.axis)), kMinObliquity);
    return (g - glm::dot(g, d) * d) / std::sqrt(c);
}

ScreenWalk::ScreenWalk(const PhaseScreens& screens, double t, const glm::dvec3& start)
    : screens_(&screens), t_(t), at_(start) {
    MIRAGE_CHECK(finite(start));
}

// The screens crossed between depths depth_a (at a, excluded) and depth_b (included), a ray
// along unit d from a: each one's perturbed point appended, its turn added, the offset carried
// to it.  Returns with offset_ at the last crossing and the arc length of it in `done`.
void ScreenWalk::cross(const glm::dvec3& a, const glm::dvec3& d, double length, double za,
                       double zb, std::vector<glm::dvec3>& out) {
    const double dz = screens_->spacing();
    const int last = screens_->count() - 1;
    double done = 0.0;  // arc length from a to which offset_ is carried
    auto at_screen = [&](int j) {
        const double zj = screens_->distance(j);
        const double s = length * (zj - za) / (zb - za);
        offset_ += turn_ * (s - done);
        done = s;
        const glm::dvec3 p = a + s * d + offset_;
        out.push_back(p);
        turn_ += screens_->turn(j, p, t_, d);
    };
    if (zb > za) {
        const int first = std::max(0, static_cast<int>(std::floor(za / dz - 0.5)) + 1);
        const int end = std::min(last, static_cast<int>(std::floor(zb / dz - 0.5)));
        for (int j = first; j <= end; ++j) {
            const double zj = screens_->distance(j);
            if (zj > za && zj <= zb) at_screen(j);
        }
    } else if (zb < za) {
        const int first = std::min(last, static_cast<int>(std::ceil(za / dz - 0.5)) - 1);
        const int end = std::max(0, static_cast<int>(std::ceil(zb / dz - 0.5)));
        for (int j = first; j >= end; --j) {
            const double zj = screens_->distance(j);
            if (zj < za && zj >= zb) at_screen(j);
        }
    }
    offset_ += turn_ * (length - done);
}

void ScreenWalk::to(const glm::dvec3& p, std::vector<glm::dvec3>& out) {
    out.clear();
    MIRAGE_CHECK(finite(p));
    const glm::dvec3 step = p - at_;
    const double length = glm::length(step);
    if (length > 0.0) {
        cross(at_, step / length, length, screens_->depth(at_), screens_->depth(p), out);
    }
    at_ = p;
    out.push_back(p + offset_);
}

void ScreenWalk::ray(const glm::dvec3& d, std::vector<glm::dvec3>& out) {
    out.clear();
    const double rate = glm::dot(d, screens_->layout().axis);
    const double za = screens_->depth(at_);
    // The screens ahead: up to the far end of the stack, or back to its near end.
    double zb = za;
    if (rate > 0.0) zb = std::max(za, screens_->distance(screens_->count() - 1));
    if (rate < 0.0) zb = std::min(za, screens_->distance(0));
    if (zb == za) return;
    const double length = (zb - za) / rate;
    cross(at_, d, length, za, zb, out);
    at_ += length * d;
}

glm::dvec3 ScreenWalk::direction(const glm::dvec3& d) const { return glm::normalize(d + turn_); }

}  // namespace mirage
