#include "atmosphere/profile.h"

#include <cmath>
#include <limits>

#include "util/format.h"
#include "util/input_file.h"

namespace mirage {

int profile_sign(const Profile& p) {
    switch (p.kind) {
        case ProfileKind::Inferior:
            return 1;
        case ProfileKind::Superior:
            return -1;
        case ProfileKind::None:
            return 0;
    }
    return 0;
}

double eta_sq_excess(const Profile& p, double y) {
    const int s = profile_sign(p);
    if (s == 0) return 0.0;
    return s * p.eta1 * p.eta1 * -std::expm1(-p.alpha * y);
}

double eta_sq(const Profile& p, double y) { return p.eta0 * p.eta0 + eta_sq_excess(p, y); }

double eta(const Profile& p, double y) { return std::sqrt(eta_sq(p, y)); }

double eta_infinity(const Profile& p) {
    return std::sqrt(p.eta0 * p.eta0 + profile_sign(p) * p.eta1 * p.eta1);
}

double height_of_excess(const Profile& p, double excess) {
    const int s = profile_sign(p);
    if (s == 0 || p.eta1 == 0.0) return std::numeric_limits<double>::infinity();
    const double f = s * excess / (p.eta1 * p.eta1);  // 1 - exp(-alpha y)
    if (f >= 1.0) return std::numeric_limits<double>::infinity();
    return -std::log1p(-f) / p.alpha;
}

Status validate(const Profile& p, const ProfileNames& names) {
    auto range = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
    if (!range(p.eta0, 1.0, kMaxEta))
        return make_error(names.eta0 + " = " + shortest(p.eta0) +
                          " must be a refractive index from 1 to " + shortest(kMaxEta));
    if (p.kind == ProfileKind::None) return Ok{};
    if (!(p.eta1 == 0.0 || range(p.eta1, kMinEta1, kMaxEta)))
        return make_error(names.eta1 + " = " + shortest(p.eta1) + " must be 0 or from " +
                          shortest(kMinEta1) + " to " + shortest(kMaxEta));
    if (!range(p.alpha, kMinAlpha, kMaxAlpha))
        return make_error(names.alpha + " = " + shortest(p.alpha) + " must be from " +
                          shortest(kMinAlpha) + " to " + shortest(kMaxAlpha) + " (1/m)");
    if (p.kind == ProfileKind::Superior && !(p.eta0 * p.eta0 > p.eta1 * p.eta1))
        return make_error(names.eta1 + " = " + shortest(p.eta1) +
                          ": a superior profile needs eta0^2 > eta1^2, and eta0 = " +
                          shortest(p.eta0) + " (the index aloft would not be real)");
    return Ok{};
}

Result<Profile> make_profile(ProfileKind kind, double eta0, double eta1, double alpha) {
    Profile p{kind, eta0, eta1, alpha};
    if (auto s = validate(p); !s) return s.error();
    return p;
}

Result<ProfileKind> parse_profile_kind(std::string_view name) {
    if (name == "inferior") return ProfileKind::Inferior;
    if (name == "superior") return ProfileKind::Superior;
    if (name == "none") return ProfileKind::None;
    return make_error("unknown profile '" + quote_cut(std::string(name)) +
                      "' (expected inferior, superior or none)");
}

std::string_view profile_kind_name(ProfileKind kind) {
    switch (kind) {
        case ProfileKind::Inferior:
            return "inferior";
        case ProfileKind::Superior:
            return "superior";
        case ProfileKind::None:
            return "none";
    }
    return "none";
}

std::vector<std::string_view> preset_names() {
    return {"paper", "paper-superior", "hot-road", "cold-sea"};
}

Result<Profile> preset_profile(std::string_view name) {
    if (name == "paper") return Profile{ProfileKind::Inferior, 1.000233, 0.4584, 2.303};
    if (name == "paper-superior") {
        // The mirror of the paper's profile: the same indices, cold air at the ground.
        const double ground = std::sqrt(1.000233 * 1.000233 + 0.4584 * 0.4584);
        return Profile{ProfileKind::Superior, ground, 0.4584, 2.303};
    }
    if (name == "hot-road") return air_profile(300.0, 20.0, 0.3);
    if (name == "cold-sea") return air_profile(293.15, -10.0, 5.0);
    std::string known;
    for (auto n : preset_names()) known += (known.empty() ? "" : ", ") + std::string(n);
    return make_error("unknown preset '" + std::string(name) + "' (known: " + known + ")");
}

Result<Profile> air_profile(double t_aloft_k, double dt_ground_k, double scale_height_m,
                            double pressure_hpa) {
    auto range = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
    if (!range(t_aloft_k, 1.0, 1e4))
        return make_error("air temperature aloft " + shortest(t_aloft_k) +
                          " K must be from 1 to 10000 K");
    if (!range(t_aloft_k + dt_ground_k, 1.0, 1e4))
        return make_error("ground temperature " + shortest(t_aloft_k + dt_ground_k) +
                          " K must be from 1 to 10000 K");
    if (!range(scale_height_m, 1e-6, 1e6))
        return make_error("scale height " + shortest(scale_height_m) +
                          " m must be from 1e-06 to 1e+06 m");
    if (!range(pressure_hpa, 1e-3, 1e6))
        return make_error("pressure " + shortest(pressure_hpa) +
                          " hPa must be from 0.001 to 1e+06 hPa");
    // Gladstone-Dale at 550 nm.
    auto excess = [&](double t) { return 2.93e-4 * (pressure_hpa / 1013.25) * (288.15 / t); };
    const double n_ground_m1 = excess(t_aloft_k + dt_ground_k);
    const double n_aloft_m1 = excess(t_aloft_k);
    const double eta0 = 1.0 + n_ground_m1;
    // eta_aloft^2 - eta0^2 = (n_a - n_g)(2 + n_a + n_g), without cancellation.
    const double d = (n_aloft_m1 - n_ground_m1) * (2.0 + n_aloft_m1 + n_ground_m1);
    // A difference too small to bend any ray (eta1 below kMinEta1) is no gradient at all.
    if (std::sqrt(std::fabs(d)) < kMinEta1)
        return Profile{ProfileKind::None, eta0, 0.0, 1.0 / scale_height_m};
    const ProfileKind kind = d > 0.0 ? ProfileKind::Inferior : ProfileKind::Superior;
    return make_profile(kind, eta0, std::sqrt(std::fabs(d)), 1.0 / scale_height_m);
}

}  // namespace mirage
