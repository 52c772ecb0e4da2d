// Refractive-index profiles of a horizontally stratified atmosphere: the exponential
// profiles of Khular, Thyagarajan & Ghatak, their presets, and validation.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace mirage {

/// Which way the index changes with height.
enum class ProfileKind {
    None,      ///< homogeneous air: rays are straight
    Inferior,  ///< eta^2 = eta0^2 + eta1^2 (1 - exp(-alpha y)): hot ground, index grows with height
    Superior,  ///< eta^2 = eta0^2 - eta1^2 (1 - exp(-alpha y)): cold ground, index falls with
               ///< height
};

/// eta(y)^2 = eta0^2 + s eta1^2 (1 - exp(-alpha y)), s = +1 inferior, -1 superior, 0 none.
/// Heights in metres above the ground (y = 0).
struct Profile {
    ProfileKind kind = ProfileKind::None;
    double eta0 = 1.0;   // index at the ground
    double eta1 = 0.0;   // amplitude of eta^2's change (dimensionless)
    double alpha = 1.0;  // decay rate of the change, in 1/m
};

/// +1 for inferior, -1 for superior, 0 for none.
int profile_sign(const Profile& p);

/// eta(y)^2 - eta0^2, without cancellation (expm1).
double eta_sq_excess(const Profile& p, double y);

/// eta(y)^2.
double eta_sq(const Profile& p, double y);

/// eta(y).
double eta(const Profile& p, double y);

/// The index far above the ground, eta(infinity).
double eta_infinity(const Profile& p);

/// Height at which eta^2 - eta0^2 equals `excess` (inverse of eta_sq_excess);
/// +infinity when the excess is at or beyond the asymptote.
double height_of_excess(const Profile& p, double excess);

/// The ranges validate() accepts: wide enough for real air (eta1 about 0.006, alpha a few
/// per metre) and the paper's exaggerated profile (eta1 0.46), narrow enough that every
/// exact ray and its samples stay finite in binary64 (docs/robustness.md).
constexpr double kMaxEta = 10.0;    // eta0 and eta1 at most
constexpr double kMinEta1 = 1e-10;  // a nonzero eta1 at least
constexpr double kMinAlpha = 1e-9;  // per unit of height (1/m, or per scene unit)
constexpr double kMaxAlpha = 1e9;

/// How the parameters are named in validate's messages, with any place before the name
/// ("scene.pov:3:10: Mirage_Eta1", "--eta1", "rays.csv:4:18: eta1").
struct ProfileNames {
    std::string eta0 = "eta0", eta1 = "eta1", alpha = "alpha";
};

/// Checks the parameters: eta0 from 1 to kMaxEta, eta1 0 or from kMinEta1 to kMaxEta, alpha
/// from kMinAlpha to kMaxAlpha, and for a superior profile eta0^2 > eta1^2 (the
/// index must stay real).  The message names the bad value as `names` says.
Status validate(const Profile& p, const ProfileNames& names = {});

/// Builds and validates a profile.
Result<Profile> make_profile(ProfileKind kind, double eta0, double eta1, double alpha);

/// Parses "inferior", "superior" or "none".
Result<ProfileKind> parse_profile_kind(std::string_view name);
std::string_view profile_kind_name(ProfileKind kind);

/// A named profile: "paper" (Khote & Howard's exaggerated desert), "paper-superior" (its
/// mirror), "hot-road" and "cold-sea" (Gladstone-Dale fits of realistic air).
Result<Profile> preset_profile(std::string_view name);
std::vector<std::string_view> preset_names();

/// Realistic air over a heated or cooled ground, T(y) = t_aloft_k + dt_ground_k exp(-y / h),
/// by Gladstone-Dale, n - 1 = 2.93e-4 (p / 1013.25 hPa) (288.15 K / T); fitted with the
/// exact index at the ground and aloft and alpha = 1/h.  dt > 0 gives an inferior profile.
/// Temperatures from 1 to 10000 K, h from 1e-6 to 1e6 m, p from 1e-3 to 1e6 hPa.
Result<Profile> air_profile(double t_aloft_k, double dt_ground_k, double scale_height_m,
                            double pressure_hpa = 1013.25);

}  // namespace mirage
