// Exact ray paths in the exponential atmospheres, in closed form and in a form that stays
// accurate in binary64 where the paper's literal formulas break (tiny eta1, grazing rays,
// stiff alpha y0, k near 0 or 1, the superior trapped/escaping boundary).
//
// A ray starts at height y0 >= 0 with direction at angle i from the upward vertical and
// stays in the vertical plane of that direction.  dz is the horizontal distance travelled
// from the start; the path is y(dz).  Notation of the reference README:
//   eta_p = eta(y0), beta = eta_p sin i (invariant), P = eta_p |cos i| / eta1,
//   E = exp(-alpha y0 / 2), w = P / E, sg = +1 going up (or level), -1 going down,
//   k2 = exp(-alpha y0) + s P^2, q = sqrt(|k2|) (k, kappa or sigma), c = gamma q with
//   gamma = alpha eta1 / (2 beta).
// Every height is evaluated as y = y0 + (2/alpha) ln F(dz) with F chosen per class in a
// form without cancellation (see exact_ray.cpp).
#pragma once

#include <string_view>

#include "atmosphere/profile.h"
#include "util/result.h"

namespace mirage {

/// The reference's ray classes, plus Straight for a homogeneous atmosphere.
enum class RayClass {
    Straight,        // no index gradient: a straight line
    InfTurn,         // inferior, going down, turns above the ground
    InfGround,       // inferior, going down, k >= 1: reaches the ground
    InfUp,           // inferior, going up (or level)
    SupTrappedUp,    // superior, going up, rises to an apex and comes down to the ground
    SupTrappedDown,  // superior, going down, apex behind, reaches the ground
    SupEscapeUp,     // superior, going up, escapes (includes the trapped/escaping boundary)
    SupEscapeDown,   // superior, going down, not trapped: reaches the ground
};

/// Where the turning point (inferior: lowest point; superior: apex) lies.
enum class TurnKind { Ahead, Behind, BelowGround, None };

std::string_view ray_class_name(RayClass c);
std::string_view turn_kind_name(TurnKind k);

/// One exact ray and the invariants of its closed form.  Build with make_exact_ray.
struct ExactRay {
    Profile profile;
    double y0 = 0.0;     // start height, m
    double i = 0.0;      // angle from the upward vertical, rad
    double cos_i = 0.0;  // cos i (> 0 looking up)
    double sin_i = 1.0;  // sin i (> 0)
    int sg = 1;          // +1 going up or level, -1 going down
    int s = 0;           // profile sign: +1 inferior, -1 superior, 0 none

    double eta_p = 1.0;  // eta(y0)
    double beta = 1.0;   // eta_p sin i, invariant along the ray
    double P = 0.0;      // eta_p |cos i| / eta1
    double ln_P =
        0.0;  // ln P (-inf for a level ray; from an origin's constants NaN where not needed)
    double ln_E = 0.0;   // -alpha y0 / 2
    double E = 1.0;      // exp(-alpha y0 / 2)
    double ln_w = 0.0;   // ln(P / E) (as ln_P)
    double gamma = 0.0;  // alpha eta1 / (2 beta), 1/m
    double k2 = 0.0;     // exp(-alpha y0) + s P^2 (reference column k2)
    double q = 0.0;      // sqrt(|k2|): k (inferior), kappa (trapped), sigma (escaping)
    double c = 0.0;      // gamma q, 1/m
    // Of every point's height, slope and curvature (state_at): eta1 / beta and
    // s alpha eta1^2 / (2 beta^2), so that y'' = curvature_scale exp(-alpha y).
    double slope_scale = 0.0;
    double curvature_scale = 0.0;

    // Class-specific constants of the stable forms.
    double asinh_w = 0.0;      // inferior: asinh(w)
    double log1p_w2 = 0.0;     // inferior: ln(1 + w^2)
    double ln_coef_lo = 0.0;   // inferior: ln((1 - rho)/2), rho = sg P / k
    double ln_coef_hi = 0.0;   // inferior: ln((1 + rho)/2)
    double theta = 0.0;        // trapped: asin(w), the angle from the start to the apex
    bool vertex_form = false;  // trapped: evaluate from the apex (else from the start)

    RayClass ray_class = RayClass::Straight;
    TurnKind turn_kind = TurnKind::None;
    double y_turn = 0.0;   // height of the turning point (NaN when none)
    double dz_turn = 0.0;  // signed horizontal distance to it (NaN when none)
    bool hits_ground = false;
    double dz_ground = 0.0;  // first distance where y = 0 (+inf when never)
};

/// The highest start height make_exact_ray takes (m, or scene units): paths are followed
/// about as far (atmosphere/sampler.cpp), and the stable forms stay finite below it.
constexpr double kMaxHeight = 1e9;

/// Builds the exact ray from height y0 (0 to kMaxHeight, m) at angle i (rad, strictly
/// between 0 and pi: a vertical ray has no horizontal distance).  The profile must be valid.
Result<ExactRay> make_exact_ray(const Profile& profile, double y0, double i_rad);

/// What every ray from one start height shares: the constants of the closed forms that
/// depend on the height only (built once for a frame's camera rays, which start at the eye).
struct ExactRayOrigin {
    Profile profile;
    double y0 = 0.0;           // start height, m
    double eta_p = 1.0;        // eta(y0)
    double eta_inf = 1.0;      // eta(infinity)
    double ln_E = 0.0;         // -alpha y0 / 2
    double E = 1.0;            // exp(-alpha y0 / 2)
    double E0 = 1.0;           // exp(-alpha y0)
    double one_m_E = 0.0;      // 1 - E, without cancellation
    double root_1m_E0 = 0.0;   // sqrt(1 - exp(-alpha y0)), without cancellation
    double p_scale = 0.0;      // eta_p / eta1: a ray's P is p_scale |cos i|
    double gamma_scale = 0.0;  // alpha eta1 / (2 eta_p): a ray's gamma is gamma_scale / sin i
};

/// The shared constants of rays from height y0 (finite, >= 0); the profile must be valid.
Result<ExactRayOrigin> make_exact_ray_origin(const Profile& profile, double y0);

/// The exact ray from the origin whose direction makes the angle i with the upward vertical,
/// given by cos i and sin i (sin i > 0; cos^2 + sin^2 = 1 to rounding): the ray
/// make_exact_ray(profile, y0, i) builds, to rounding, without the angle's round trip through
/// trigonometric functions and with the origin's constants computed once.  Its field i is
/// left NaN: the closed forms use cos_i and sin_i.
ExactRay make_exact_ray(const ExactRayOrigin& origin, double cos_i, double sin_i);

/// The same into `ray` (every field written): for many rays in a row, without a copy of the
/// ray.  Where the origin's numbers are ordinary (exp(-alpha y0 / 2) and P between 1e-150 and
/// 1e150) an inferior ray takes two logarithms and no ln P; ln_P and ln_w are then NaN.
void make_exact_ray(const ExactRayOrigin& origin, double cos_i, double sin_i, ExactRay& ray);

/// Height at horizontal distance dz >= 0 (meaningful up to dz_ground).
double height_at(const ExactRay& ray, double dz);

/// Slope dy/dz at horizontal distance dz.
double slope_at(const ExactRay& ray, double dz);

/// d2y/dz2 of any ray of this invariant at height y: s alpha eta1^2 exp(-alpha y) / (2 beta^2).
double curvature_at_height(const ExactRay& ray, double y);

/// The path at a horizontal distance: what a sampler needs there.
struct PathState {
    double y = 0.0;          // height
    double slope = 0.0;      // dy/dz
    double curvature = 0.0;  // d2y/dz2
};

/// Height, slope and curvature at horizontal distance dz >= 0 together, for about the cost of
/// one height (from one exponential where the closed form allows; height_at, slope_at and
/// curvature_at_height to rounding).  At the start, the turning point and the ground point
/// (dz exactly 0, dz_turn or dz_ground) their closed forms are used: y0, y_turn, 0.
PathState state_at(const ExactRay& ray, double dz);

/// The first horizontal distance at which the path reaches height y while still moving
/// towards it from y0 (before any turning point), or +infinity if it never does.
double distance_to_height(const ExactRay& ray, double y);

/// The slope the path tends to far from the start, for rays that never reach the ground
/// (inferior rays after their turn, escaping superior rays going up); NaN otherwise.
double asymptotic_slope(const ExactRay& ray);

/// Whether the path approaches an asymptote it never meets the ground before: inferior rays
/// that turn and do not reach the ground, escaping superior rays going up (k2 < 0).
bool has_asymptote(const ExactRay& ray);

/// How far the path beyond dz still departs from its asymptote: inferior, after the vertex,
/// (2/alpha) ln(1 + exp(-2u)), u = c (dz - dz_t); escaping superior going up,
/// (2/alpha) |ln(1 - r exp(-2x))|, r = E0 / (P + sigma)^2.  Both shrink monotonically, so the
/// line through the path at dz with the asymptotic slope stays within this distance beyond
/// it.  +infinity before the vertex and for paths with no asymptote.
double asymptote_departure(const ExactRay& ray, double dz);

}  // namespace mirage
