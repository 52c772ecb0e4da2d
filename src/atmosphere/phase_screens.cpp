#include "atmosphere/phase_screens.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
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

// The tilt's partial sums (screen_tilt): a multiple of every vector width it is compiled for.
constexpr std::size_t kTiltLanes = 8;

double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// The disc's average of cos(q . x + phase) over a disc of radius r is this times its value at
// the centre.
double disc_average(double qr) {
    return qr < 1e-6 ? 1.0 - qr * qr / 8.0 : 2.0 * std::cyl_bessel_j(1.0, qr) / qr;
}

// sin(2 pi t) for the tilts' sums, t in turns: several times as fast as the library's sine and
// free of branches, so that a loop of it vectorizes.  t is reduced to f in [-1/2, 1/2] by the
// nearest whole number (rounded by adding and taking away 1.5 * 2^52, for |t| below 2^51; the
// subtraction is exact), then sin(2 pi f) = f P(f^2), P the minimax polynomial of degree 6 in
// f^2 (Remez, absolute error), whose error is below 1.15e-9 over the whole turn, evaluated
// in double arithmetic as well (checked on 2e5 points).  Without a branch or a table: the same
// bytes on every thread.
inline double sin_turns(double t) {
    constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
    const double f = t - ((t + kRound) - kRound);
    // P by Estrin's scheme, whose chain of dependent operations is half as long as Horner's:
    // the walk's turns come one screen after another, each waiting for the last.
    const double y = f * f, y2 = y * y, y4 = y2 * y2;
    const double p01 = 6.283185272722502 - 41.34169706896686 * y;
    const double p23 = 81.60502462296647 - 76.70155118171844 * y;
    const double p45 = 42.016165857284825 - 14.868611102966621 * y;
    const double p0123 = p01 + p23 * y2;
    const double p456 = p45 + 3.199693782371611 * y2;
    return f * (p0123 + p456 * y4);
}

// The screen's tilt along u and v at (xu, xv): the sum over its modes of their sines times
// their tilts per unit sine, in kTiltLanes partial sums (mode k in lane k % kTiltLanes, each
// lane in the modes' order) added in a fixed order at the end, so the result does not depend
// on how wide the machine's vectors are.  Compiled twice on x86-64 (GCC and Clang pick one when
// the program starts): for AVX2 and FMA (x86-64-v3), four doubles to a vector, and for the
// baseline's two.  The AVX2 version fuses multiplications and additions, which rounds a little
// differently from the baseline's (as the library's own exp, log and sin do on such machines):
// the same bytes on every thread of one machine.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__INTEL_COMPILER)
#define MIRAGE_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define MIRAGE_VECTOR_CLONES
#endif

MIRAGE_VECTOR_CLONES
glm::dvec2 screen_tilt(const double* turns_u, const double* turns_v, const double* turns_phase,
                       const double* tilt_u, const double* tilt_v, std::size_t n, double xu,
                       double xv) {
    double su[kTiltLanes] = {}, sv[kTiltLanes] = {};
    for (std::size_t k = 0; k < n; k += kTiltLanes) {
        for (std::size_t l = 0; l < kTiltLanes; ++l) {
            const double s =
                sin_turns(turns_u[k + l] * xu + turns_v[k + l] * xv + turns_phase[k + l]);
            su[l] += s * tilt_u[k + l];
            sv[l] += s * tilt_v[k + l];
        }
    }
    static_assert(kTiltLanes == 8);
    const double u = ((su[0] + su[4]) + (su[2] + su[6])) + ((su[1] + su[5]) + (su[3] + su[7]));
    const double v = ((sv[0] + sv[4]) + (sv[2] + sv[6])) + ((sv[1] + sv[5]) + (sv[3] + sv[7]));
    return glm::dvec2(u, v);
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
    out.u_ = u;
    out.v_ = v;
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
            const double weight = mode.amplitude * disc_average(q * radius);
            const double ku = glm::dot(mode.wavevector, u), kv = glm::dot(mode.wavevector, v);
            screen.turns_u.push_back(ku / (2.0 * kPi));
            screen.turns_v.push_back(kv / (2.0 * kPi));
            screen.turns_phase.push_back(mode.phase / (2.0 * kPi));
            screen.tilt_u.push_back(-weight * ku);
            screen.tilt_v.push_back(-weight * kv);
        }
        // Modes of no weight up to a whole number of lanes: each adds a zero.
        while (screen.turns_u.size() % kTiltLanes != 0) {
            for (auto* c : {&screen.turns_u, &screen.turns_v, &screen.turns_phase, &screen.tilt_u,
                            &screen.tilt_v})
                c->push_back(0.0);
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
    const glm::dvec3 x = p - settings_.wind * t;  // frozen flow
    const glm::dvec2 g = tilt_across(j, glm::dvec2(glm::dot(x, u_), glm::dot(x, v_)));
    return g.x * u_ + g.y * v_;
}

glm::dvec2 PhaseScreens::tilt_across(int j, const glm::dvec2& at) const {
    MIRAGE_CHECK(j >= 0 && j < count());
    const Screen& s = screens_[j];
    return screen_tilt(s.turns_u.data(), s.turns_v.data(), s.turns_phase.data(), s.tilt_u.data(),
                       s.tilt_v.data(), s.turns_u.size(), at.x, at.y);
}

glm::dvec3 PhaseScreens::turn(int j, const glm::dvec3& p, double t, const glm::dvec3& d) const {
    return turn(j, p, t, d, slant(d));
}

double PhaseScreens::slant(const glm::dvec3& d) const {
    return 1.0 / std::sqrt(std::max(std::abs(glm::dot(d, layout_.axis)), kMinObliquity));
}

glm::dvec3 PhaseScreens::turn(int j, const glm::dvec3& p, double t, const glm::dvec3& d,
                              double slant) const {
    const glm::dvec3 g = tilt(j, p, t);
    return (g - glm::dot(g, d) * d) * slant;
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
    const double slant = screens_->slant(d);
    // The same across the axis: the screens' coordinates of a (the wind's motion taken away)
    // and of d.
    const glm::dvec3 &u = screens_->across_u(), &v = screens_->across_v();
    const glm::dvec3 still = a - screens_->settings().wind * t_;  // frozen flow
    const glm::dvec2 a_across(glm::dot(still, u), glm::dot(still, v));
    const glm::dvec2 d_across(glm::dot(d, u), glm::dot(d, v));
    auto at_screen = [&](int j) {
        const double zj = screens_->distance(j);
        const double s = length * (zj - za) / (zb - za);
        offset_ += turn_ * (s - done);
        offset_across_ += turn_across_ * (s - done);
        done = s;
        out.push_back(a + s * d + offset_);
        // The screen's gradient there, less its part along d, times the slant (turn()).
        const glm::dvec2 g = screens_->tilt_across(j, a_across + s * d_across + offset_across_);
        const double along = g.x * d_across.x + g.y * d_across.y;  // g . d
        turn_across_ += (g - along * d_across) * slant;
        turn_ += (g.x * u + g.y * v - along * d) * slant;
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
    offset_across_ += turn_across_ * (length - done);
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
