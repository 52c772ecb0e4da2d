#include "atmosphere/exact_ray.h"

#include <cmath>
#include <limits>

#include "util/check.h"
#include "util/format.h"

// Derivations (notation of exact_ray.h; x = c dz).
//
// Every class satisfies (dy/dz)^2 = (eta^2 - beta^2) / beta^2 and, with F = exp(alpha (y - y0)/2),
//   inferior            F = cosh x + sg (P/k) sinh x       = cosh(x - x_t) / cosh(x_t)
//   superior trapped    F = cos x  + sg (P/kappa) sin x    = cos(x - x_M) / cos(x_M)
//   superior escaping   F = cosh x + sg (P/sigma) sinh x   = sinh(A + sg x) / sinh(A)
//   boundary (k2 = 0)   F = 1 + sg P gamma dz
// Written as C(x) + sg P gamma dz S(x)/x the last three are one continuous family in k2, which
// is what keeps rays near the trapped/escaping boundary accurate ("sinc form").  The inferior
// form becomes -x + logaddexp(ln((1-rho)/2), ln((1+rho)/2) + 2x) with ln(1 - |rho|) computed as
// -(ln(1 + w^2) + ln(1 + |rho|)): no overflow at alpha y0 = 2000 and no cancellation for
// steep rays whose vertex lies far below the ground.

namespace mirage {

namespace {

constexpr double kLn2 = 0.69314718055994530942;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string number(double v) { return shortest(v); }

double logaddexp(double a, double b) {
    if (a < b) std::swap(a, b);
    if (b == -kInf) return a;
    return a + std::log1p(std::exp(b - a));
}

// sin(x)/x and sinh(x)/x, accurate near 0.
double sinc(double x) {
    if (std::fabs(x) < 1e-4) return 1.0 - x * x / 6.0;
    return std::sin(x) / x;
}
double sinhc(double x) {
    if (std::fabs(x) < 1e-4) return 1.0 + x * x / 6.0;
    return std::sinh(x) / x;
}

// atanh(t)/t and atan(t)/t for the ground distances of rays near the boundary.
double atanhc(double t) {
    if (std::fabs(t) < 1e-4) return 1.0 + t * t / 3.0;
    return std::atanh(t) / t;
}
double atanc(double t) {
    if (std::fabs(t) < 1e-4) return 1.0 - t * t / 3.0;
    return std::atan(t) / t;
}

void classify_straight(ExactRay& r) {
    r.ray_class = RayClass::Straight;
    r.turn_kind = TurnKind::None;
    r.y_turn = kNaN;
    r.dz_turn = kNaN;
    r.hits_ground = r.cos_i < 0.0;
    r.dz_ground = r.hits_ground ? r.y0 * r.sin_i / -r.cos_i : kInf;
}

void setup_inferior(ExactRay& r) {
    const double alpha = r.profile.alpha;
    // ln k2 and ln(1 + w^2) in log space (w overflows for stiff alpha y0); for P >= E
    // from ln P, so that alpha y0 never enters a sum it would swamp.
    double ln_k2 = 0.0;
    if (r.P == 0.0) {
        r.log1p_w2 = 0.0;
        r.asinh_w = 0.0;
        ln_k2 = -alpha * r.y0;
    } else if (r.ln_w >= 0.0) {
        ln_k2 = 2.0 * r.ln_P + std::log1p(std::exp(-2.0 * r.ln_w));
        r.log1p_w2 = 2.0 * r.ln_w + std::log1p(std::exp(-2.0 * r.ln_w));
        r.asinh_w = r.ln_w > 300.0 ? r.ln_w + kLn2 : std::asinh(std::exp(r.ln_w));
    } else {
        const double w = std::exp(r.ln_w);
        r.log1p_w2 = std::log1p(w * w);
        r.asinh_w = std::asinh(w);
        ln_k2 = -alpha * r.y0 + r.log1p_w2;
    }
    r.k2 = std::exp(ln_k2);
    r.q = std::exp(0.5 * ln_k2);
    r.c = r.gamma * r.q;
    // |rho| = P / k = w / sqrt(1 + w^2);  ln(1 - |rho|) = -(ln(1 + w^2) + ln(1 + |rho|)).
    const double rho = r.P == 0.0 ? 0.0 : std::exp(r.ln_P - 0.5 * ln_k2);
    const double ln_1p_rho = std::log1p(rho) - kLn2;
    const double ln_1m_rho = -(r.log1p_w2 + std::log1p(rho)) - kLn2;
    r.ln_coef_lo = r.sg > 0 ? ln_1m_rho : ln_1p_rho;  // coefficient of exp(-x)
    r.ln_coef_hi = r.sg > 0 ? ln_1p_rho : ln_1m_rho;  // coefficient of exp(+x)

    r.y_turn = r.ln_w >= 0.0 ? -ln_k2 / alpha : r.y0 - r.log1p_w2 / alpha;
    r.dz_turn = -r.sg * r.asinh_w / r.c;
    const bool vertex_in_air = ln_k2 < 0.0;  // k < 1
    if (r.sg < 0) {
        r.ray_class = vertex_in_air ? RayClass::InfTurn : RayClass::InfGround;
        r.turn_kind = vertex_in_air ? TurnKind::Ahead : TurnKind::BelowGround;
    } else {
        r.ray_class = RayClass::InfUp;
        r.turn_kind = vertex_in_air ? TurnKind::Behind : TurnKind::BelowGround;
    }
    r.hits_ground = r.ray_class == RayClass::InfGround;
    r.dz_ground = kInf;
    if (r.hits_ground) {
        // c dz_g = 2 atanh(t), t = N / D, from tanh(x/2) and the quadratic it solves.
        const double k = r.q;
        const double N = k * -std::expm1(r.ln_E);
        const double rr = std::sqrt(-std::expm1(-alpha * r.y0));
        const double k2m1 = std::max(0.0, (r.P - rr) * (r.P + rr));
        const double D = r.P + r.E * std::sqrt(k2m1);
        const double t = N / D;
        if (t < 0.5) {
            r.dz_ground = 2.0 * t * atanhc(t) / r.c;
        } else {
            // ln((1 + t)/(1 - t)) with D - N = E B computed without cancellation.
            const double B = std::sqrt(k2m1) + k - r.E / (r.P + k);
            r.dz_ground = (std::log(D + N) - r.ln_E - std::log(B)) / r.c;
        }
    }
}

void setup_superior(ExactRay& r) {
    const double alpha = r.profile.alpha;
    const double E0 = std::exp(-alpha * r.y0);
    r.k2 = E0 - r.P * r.P;
    r.q = std::sqrt(std::fabs(r.k2));
    r.c = r.gamma * r.q;
    r.dz_ground = kInf;
    if (r.k2 > 0.0) {
        // Trapped: rises to the apex y_M and comes back to the ground.
        const double w = std::exp(r.ln_w);
        const double one_m_w2 = (1.0 - w) * (1.0 + w);
        r.theta = std::atan2(w, std::sqrt(one_m_w2));
        r.y_turn = r.y0 - (std::log1p(-w) + std::log1p(w)) / alpha;
        r.dz_turn = r.sg * r.theta / r.c;
        // From the apex unless the apex is so far above that y_M swamps y0.
        r.vertex_form = -(std::log1p(-w) + std::log1p(w)) <= 2.0 + alpha * r.y0;
        r.ray_class = r.sg > 0 ? RayClass::SupTrappedUp : RayClass::SupTrappedDown;
        r.turn_kind = r.sg > 0 ? TurnKind::Ahead : TurnKind::Behind;
        r.hits_ground = true;
        const double kappa = r.q;
        const double root = r.E * std::sqrt(1.0 - r.k2);
        if (r.sg > 0) {
            const double t = (r.P + root) / (kappa * (1.0 + r.E));
            r.dz_ground = 2.0 * std::atan(t) / r.c;
        } else {
            const double a = -std::expm1(r.ln_E) / (root + r.P);  // t / kappa
            r.dz_ground = 2.0 * a * atanc(kappa * a) / r.gamma;
        }
        return;
    }
    // Escaping, or exactly on the boundary k2 = 0.
    r.y_turn = kNaN;
    r.dz_turn = kNaN;
    r.turn_kind = TurnKind::None;
    r.ray_class = r.sg > 0 ? RayClass::SupEscapeUp : RayClass::SupEscapeDown;
    r.hits_ground = r.sg < 0;
    if (r.hits_ground) {
        const double sigma = r.q;
        const double one_m_E = -std::expm1(r.ln_E);
        const double root = std::sqrt(1.0 + sigma * sigma);
        const double D = r.P + r.E * root;
        const double t = sigma * one_m_E / D;
        if (t < 0.5) {
            r.dz_ground = 2.0 * (one_m_E / D) * atanhc(t) / r.gamma;
        } else {
            const double N = sigma * one_m_E;
            const double B = r.E / (r.P + sigma) + root + sigma;
            r.dz_ground = (std::log(D + N) - r.ln_E - std::log(B)) / r.c;
        }
    }
}

// setup_inferior with the origin's constants, and each transcendental function evaluated
// once: the same quantities, for many rays from one height.
// `ordinary`: E and P between 1e-150 and 1e150 and w below 1e150 (else ln_P and ln_w are
// set).
void setup_inferior_shared(ExactRay& r, const ExactRayOrigin& o, bool ordinary) {
    const double alpha = r.profile.alpha;
    double ln_k2 = 0.0;
    double log1p_rho = 0.0;  // ln(1 + rho), rho = P / k in [0, 1)
    if (r.P == 0.0) {
        r.log1p_w2 = 0.0;
        r.asinh_w = 0.0;
        ln_k2 = -alpha * r.y0;
        r.k2 = o.E0;
    } else if (ordinary) {
        // Ordinary numbers (w^2 finite): two logarithms.
        // asinh(w) = ln(w + s) = ln(1 + w + w^2 / (1 + s)), s = sqrt(1 + w^2), without
        // cancellation for small w; ln(1 + rho) = ln((s + w) / s) = asinh(w) - ln(1 + w^2) / 2,
        // to the absolute accuracy the coefficients need.  ln k2 = -alpha y0 + ln(1 + w^2)
        // loses at most (alpha y0 + ln(1 + w^2)) ulp, which is the rounding of y_turn's scale.
        const double w = r.P / o.E;
        const double w2 = w * w;
        const double s = std::sqrt(1.0 + w2);
        if (w >= 0.5) {
            // No cancellation to avoid (1 + w^2 >= 1.25, w + s >= 1.6): the faster logarithm.
            r.log1p_w2 = std::log(1.0 + w2);
            r.asinh_w = std::log(w + s);
        } else {
            r.log1p_w2 = std::log1p(w2);
            r.asinh_w = std::log1p(w + w2 / (1.0 + s));
        }
        ln_k2 = 2.0 * o.ln_E + r.log1p_w2;
        r.k2 = o.E0 * (1.0 + w2);
        log1p_rho = r.asinh_w - 0.5 * r.log1p_w2;
    } else if (r.ln_w >= 0.0) {
        // Extreme numbers (stiff alpha y0, extreme P): in log space as setup_inferior does.
        const double inv_w2 = std::exp(-2.0 * r.ln_w);  // w^-2
        const double t = std::log1p(inv_w2);
        ln_k2 = 2.0 * r.ln_P + t;
        r.log1p_w2 = 2.0 * r.ln_w + t;
        // asinh(w) = ln w + ln(1 + sqrt(1 + w^-2)).
        r.asinh_w = r.ln_w + std::log(1.0 + std::sqrt(1.0 + inv_w2));
        r.k2 = std::exp(ln_k2);
    } else {
        const double wl = std::exp(r.ln_w);
        r.log1p_w2 = std::log1p(wl * wl);
        r.asinh_w = std::asinh(wl);
        ln_k2 = -alpha * r.y0 + r.log1p_w2;
        r.k2 = std::exp(ln_k2);
    }
    r.q = ln_k2 > -700.0 ? std::sqrt(r.k2) : std::exp(0.5 * ln_k2);
    r.c = r.gamma * r.q;
    if (r.P != 0.0 && !ordinary) {
        const double rho = ln_k2 > -700.0 ? r.P / r.q : std::exp(r.ln_P - 0.5 * ln_k2);
        // ln(1 + rho) for rho in [0, 1): the coefficients need it to an absolute accuracy only.
        log1p_rho = std::log(1.0 + rho);
    }
    const double ln_1p_rho = log1p_rho - kLn2;
    const double ln_1m_rho = -(r.log1p_w2 + log1p_rho) - kLn2;
    r.ln_coef_lo = r.sg > 0 ? ln_1m_rho : ln_1p_rho;
    r.ln_coef_hi = r.sg > 0 ? ln_1p_rho : ln_1m_rho;

    // y_turn = y0 - ln(1 + w^2) / alpha; for w >= 1 from ln k2 (-ln k2 / alpha), which does
    // not swamp a far turning point's height with y0.
    const bool steep = ordinary ? r.P >= o.E : r.ln_w >= 0.0;
    r.y_turn = steep ? -ln_k2 / alpha : r.y0 - r.log1p_w2 / alpha;
    r.dz_turn = -r.sg * r.asinh_w / r.c;
    const bool vertex_in_air = ln_k2 < 0.0;
    if (r.sg < 0) {
        r.ray_class = vertex_in_air ? RayClass::InfTurn : RayClass::InfGround;
        r.turn_kind = vertex_in_air ? TurnKind::Ahead : TurnKind::BelowGround;
    } else {
        r.ray_class = RayClass::InfUp;
        r.turn_kind = vertex_in_air ? TurnKind::Behind : TurnKind::BelowGround;
    }
    r.hits_ground = r.ray_class == RayClass::InfGround;
    r.dz_ground = kInf;
    if (r.hits_ground) {
        const double k = r.q;
        const double N = k * o.one_m_E;
        const double rr = o.root_1m_E0;
        const double k2m1 = std::max(0.0, (r.P - rr) * (r.P + rr));
        const double root = std::sqrt(k2m1);
        const double D = r.P + r.E * root;
        const double t = N / D;
        if (t < 0.5) {
            r.dz_ground = 2.0 * t * atanhc(t) / r.c;
        } else {
            const double B = root + k - r.E / (r.P + k);
            r.dz_ground = (std::log(D + N) - r.ln_E - std::log(B)) / r.c;
        }
    }
}

// setup_superior with the origin's constants.
void setup_superior_shared(ExactRay& r, const ExactRayOrigin& o) {
    const double alpha = r.profile.alpha;
    r.k2 = o.E0 - r.P * r.P;
    r.q = std::sqrt(std::fabs(r.k2));
    r.c = r.gamma * r.q;
    r.dz_ground = kInf;
    if (r.k2 > 0.0) {
        const double w = o.E > 1e-150 ? r.P / o.E : std::exp(r.ln_w);
        const double one_m_w2 = (1.0 - w) * (1.0 + w);
        r.theta = std::atan2(w, std::sqrt(one_m_w2));
        // ln(1 - w^2) from the product of two exact differences: accurate near w = 1 too.
        const double ln_1m_w2 = std::log(one_m_w2);
        r.y_turn = r.y0 - ln_1m_w2 / alpha;
        r.dz_turn = r.sg * r.theta / r.c;
        r.vertex_form = -ln_1m_w2 <= 2.0 + alpha * r.y0;
        r.ray_class = r.sg > 0 ? RayClass::SupTrappedUp : RayClass::SupTrappedDown;
        r.turn_kind = r.sg > 0 ? TurnKind::Ahead : TurnKind::Behind;
        r.hits_ground = true;
        const double kappa = r.q;
        const double root = r.E * std::sqrt(1.0 - r.k2);
        if (r.sg > 0) {
            const double t = (r.P + root) / (kappa * (1.0 + r.E));
            r.dz_ground = 2.0 * std::atan(t) / r.c;
        } else {
            const double a = o.one_m_E / (root + r.P);
            r.dz_ground = 2.0 * a * atanc(kappa * a) / r.gamma;
        }
        return;
    }
    r.y_turn = kNaN;
    r.dz_turn = kNaN;
    r.turn_kind = TurnKind::None;
    r.ray_class = r.sg > 0 ? RayClass::SupEscapeUp : RayClass::SupEscapeDown;
    r.hits_ground = r.sg < 0;
    if (r.hits_ground) {
        const double sigma = r.q;
        const double one_m_E = o.one_m_E;
        const double root = std::sqrt(1.0 + sigma * sigma);
        const double D = r.P + r.E * root;
        const double t = sigma * one_m_E / D;
        if (t < 0.5) {
            r.dz_ground = 2.0 * (one_m_E / D) * atanhc(t) / r.gamma;
        } else {
            const double N = sigma * one_m_E;
            const double B = r.E / (r.P + sigma) + root + sigma;
            r.dz_ground = (std::log(D + N) - r.ln_E - std::log(B)) / r.c;
        }
    }
}

// ln F(dz) for the superior classes (see the header comment of this file).
double superior_ln_F(const ExactRay& r, double dz) {
    const double x = r.c * dz;
    if (r.k2 > 0.0) {
        if (r.vertex_form) {
            // ln F = ln(cos(x - sg theta) / cos(theta)); cos(theta) = kappa / E.
            return std::log(std::cos(x - r.sg * r.theta)) - std::log(r.q) + r.ln_E;
        }
        return std::log(std::cos(x) + r.sg * r.P * r.gamma * dz * sinc(x));
    }
    if (r.k2 == 0.0) return std::log1p(r.sg * r.P * r.gamma * dz);
    const double sigma = r.q;
    const double E0 = r.E * r.E;
    const double ps = r.P + sigma;
    if (r.sg > 0) {
        if (x < 1.0) return std::log(std::cosh(x) + r.P * r.gamma * dz * sinhc(x));
        return x + std::log(ps / (2.0 * sigma)) + std::log1p(-E0 / (ps * ps) * std::exp(-2.0 * x));
    }
    if (sigma < 0.5 * r.P) return std::log(std::cosh(x) - r.P * r.gamma * dz * sinhc(x));
    // E0 exp(2x) as one exponential: for a start far above the gradient (alpha y0 > 745) E0
    // underflows to 0 while exp(2x) overflows on the way down.
    return std::log(ps / (2.0 * sigma)) - x + std::log1p(-std::exp(2.0 * (x + r.ln_E)) / (ps * ps));
}

}  // namespace

std::string_view ray_class_name(RayClass c) {
    switch (c) {
        case RayClass::Straight:
            return "straight";
        case RayClass::InfTurn:
            return "inf_turn";
        case RayClass::InfGround:
            return "inf_ground";
        case RayClass::InfUp:
            return "inf_up";
        case RayClass::SupTrappedUp:
            return "sup_trapped_up";
        case RayClass::SupTrappedDown:
            return "sup_trapped_down";
        case RayClass::SupEscapeUp:
            return "sup_escape_up";
        case RayClass::SupEscapeDown:
            return "sup_escape_down";
    }
    return "?";
}

std::string_view turn_kind_name(TurnKind k) {
    switch (k) {
        case TurnKind::Ahead:
            return "ahead";
        case TurnKind::Behind:
            return "behind";
        case TurnKind::BelowGround:
            return "below_ground";
        case TurnKind::None:
            return "none";
    }
    return "?";
}

Result<ExactRay> make_exact_ray(const Profile& profile, double y0, double i_rad) {
    if (auto s = validate(profile); !s) return s.error();
    if (!(y0 >= 0.0 && y0 <= kMaxHeight))
        return make_error("start height y0 = " + number(y0) + " m must be from 0 to " +
                          number(kMaxHeight) + " m");
    if (!std::isfinite(i_rad) || i_rad <= 0.0 || i_rad >= M_PI)
        return make_error("angle from the vertical i = " + number(i_rad) +
                          " rad must lie strictly between 0 and pi (a vertical ray has no "
                          "horizontal distance)");
    ExactRay r;
    r.profile = profile;
    r.y0 = y0;
    r.i = i_rad;
    r.cos_i = std::cos(i_rad);
    r.sin_i = std::sin(i_rad);
    r.sg = r.cos_i < 0.0 ? -1 : 1;
    r.s = profile_sign(profile);
    r.eta_p = eta(profile, y0);
    r.beta = r.eta_p * r.sin_i;
    if (r.s == 0 || profile.eta1 == 0.0) {
        r.s = 0;
        classify_straight(r);
        return r;
    }
    const double alpha = profile.alpha;
    r.slope_scale = profile.eta1 / r.beta;
    r.curvature_scale = r.s * alpha * profile.eta1 * profile.eta1 / (2.0 * r.beta * r.beta);
    r.P = r.eta_p * std::fabs(r.cos_i) / profile.eta1;
    r.ln_P = std::log(r.P);
    r.ln_E = -0.5 * alpha * y0;
    r.E = std::exp(r.ln_E);
    r.ln_w = r.ln_P - r.ln_E;
    r.gamma = alpha * profile.eta1 / (2.0 * r.beta);
    if (r.s > 0) {
        setup_inferior(r);
    } else {
        setup_superior(r);
    }
    MIRAGE_CHECK(!std::isnan(r.k2) && !std::isnan(r.c) && !std::isnan(r.dz_ground));
    return r;
}

Result<ExactRayOrigin> make_exact_ray_origin(const Profile& profile, double y0) {
    if (auto s = validate(profile); !s) return s.error();
    if (!(y0 >= 0.0 && y0 <= kMaxHeight))
        return make_error("start height y0 = " + number(y0) + " m must be from 0 to " +
                          number(kMaxHeight) + " m");
    ExactRayOrigin o;
    o.profile = profile;
    o.y0 = y0;
    o.eta_p = eta(profile, y0);
    o.eta_inf = eta_infinity(profile);
    const double alpha = profile.alpha;
    o.ln_E = -0.5 * alpha * y0;
    o.E = std::exp(o.ln_E);
    o.E0 = std::exp(-alpha * y0);
    o.one_m_E = -std::expm1(o.ln_E);
    o.root_1m_E0 = std::sqrt(-std::expm1(-alpha * y0));
    if (profile.eta1 != 0.0) {
        o.p_scale = o.eta_p / profile.eta1;
        o.gamma_scale = alpha * profile.eta1 / (2.0 * o.eta_p);
    }
    return o;
}

ExactRay make_exact_ray(const ExactRayOrigin& o, double cos_i, double sin_i) {
    ExactRay r;
    make_exact_ray(o, cos_i, sin_i, r);
    return r;
}

void make_exact_ray(const ExactRayOrigin& o, double cos_i, double sin_i, ExactRay& r) {
    MIRAGE_CHECK(sin_i > 0.0 && std::isfinite(cos_i) && std::isfinite(sin_i));
    // Every field, those a class leaves alone at their defaults (field by field: a copy of a
    // whole default ray costs more than the ray's arithmetic).
    r.P = 0.0;
    r.ln_P = 0.0;
    r.ln_E = 0.0;
    r.E = 1.0;
    r.ln_w = 0.0;
    r.gamma = 0.0;
    r.k2 = 0.0;
    r.q = 0.0;
    r.c = 0.0;
    r.slope_scale = 0.0;
    r.curvature_scale = 0.0;
    r.asinh_w = 0.0;
    r.log1p_w2 = 0.0;
    r.ln_coef_lo = 0.0;
    r.ln_coef_hi = 0.0;
    r.theta = 0.0;
    r.vertex_form = false;
    r.profile = o.profile;
    r.y0 = o.y0;
    r.i = kNaN;  // the ray is given by its cosines, which the closed forms use
    r.cos_i = cos_i;
    r.sin_i = sin_i;
    r.sg = cos_i < 0.0 ? -1 : 1;
    r.s = profile_sign(o.profile);
    r.eta_p = o.eta_p;
    r.beta = r.eta_p * sin_i;
    if (r.s == 0 || o.profile.eta1 == 0.0) {
        r.s = 0;
        classify_straight(r);
        return;
    }
    const double e1 = o.profile.eta1;
    r.slope_scale = e1 / r.beta;
    r.curvature_scale = r.s * o.profile.alpha * e1 * e1 / (2.0 * r.beta * r.beta);
    r.P = o.p_scale * std::fabs(cos_i);
    r.ln_E = o.ln_E;
    r.E = o.E;
    // ln P and ln w only where the closed forms need them: for extreme numbers.
    const bool ordinary =
        o.E > 1e-150 && r.P > 1e-150 && r.P < 1e150 && r.P < 1e150 * o.E;  // w < 1e150
    r.ln_P = kNaN;
    r.ln_w = kNaN;
    if (r.s > 0 ? !ordinary : !(o.E > 1e-150)) {
        r.ln_P = std::log(r.P);
        r.ln_w = r.ln_P - r.ln_E;
    }
    r.gamma = o.gamma_scale / sin_i;
    if (r.s > 0) {
        setup_inferior_shared(r, o, ordinary);
    } else {
        setup_superior_shared(r, o);
    }
    MIRAGE_CHECK(!std::isnan(r.k2) && !std::isnan(r.c) && !std::isnan(r.dz_ground));
}

double height_at(const ExactRay& r, double dz) {
    const double alpha = r.profile.alpha;
    if (r.s == 0) return r.y0 + dz * r.cos_i / r.sin_i;
    if (r.s > 0) {
        const double x = r.c * dz;
        const double ln_F = -x + logaddexp(r.ln_coef_lo, r.ln_coef_hi + 2.0 * x);
        return r.y0 + (2.0 / alpha) * ln_F;
    }
    if (r.k2 > 0.0 && r.vertex_form) {
        // From the apex: y_M + (2/alpha) ln cos(x - x_M).
        return r.y_turn + (2.0 / alpha) * std::log(std::cos(r.c * dz - r.sg * r.theta));
    }
    return r.y0 + (2.0 / alpha) * superior_ln_F(r, dz);
}

double slope_at(const ExactRay& r, double dz) {
    if (r.s == 0) return r.cos_i / r.sin_i;
    const double scale = r.profile.eta1 / r.beta;  // 2 gamma / alpha
    const double x = r.c * dz;
    if (r.s > 0) return scale * r.q * std::tanh(x + r.sg * r.asinh_w);
    if (r.k2 > 0.0) {
        if (r.vertex_form) return -scale * r.q * std::tan(x - r.sg * r.theta);
        // d ln F / dz over gamma, from F = cos x + sg P gamma dz sinc x.
        const double F = std::cos(x) + r.sg * r.P * r.gamma * dz * sinc(x);
        const double dF = r.sg * r.P * std::cos(x) - r.k2 * r.gamma * dz * sinc(x);
        return scale * dF / F;
    }
    if (r.k2 == 0.0) return scale * r.sg * r.P / (1.0 + r.sg * r.P * r.gamma * dz);
    const double sigma = r.q;
    if (x >= 1.0 || (r.sg < 0 && sigma >= 0.5 * r.P)) {
        // sg sigma coth(A + sg x), A = asinh(sigma / E).
        const double A = std::asinh(sigma / r.E);
        return scale * r.sg * sigma / std::tanh(A + r.sg * x);
    }
    const double F = std::cosh(x) + r.sg * r.P * r.gamma * dz * sinhc(x);
    const double dF = r.sg * r.P * std::cosh(x) + r.q * r.q * r.gamma * dz * sinhc(x);
    return scale * dF / F;
}

double curvature_at_height(const ExactRay& r, double y) {
    if (r.s == 0) return 0.0;
    const double e1 = r.profile.eta1;
    return r.s * r.profile.alpha * e1 * e1 * std::exp(-r.profile.alpha * y) /
           (2.0 * r.beta * r.beta);
}

PathState state_at(const ExactRay& r, double dz) {
    PathState st;
    const double alpha = r.profile.alpha;
    // y'' = s alpha eta1^2 exp(-alpha y) / (2 beta^2), with exp(-alpha y) known at the start
    // (E^2), the turning point (k2) and the ground (1).
    const double curvature_scale = r.curvature_scale;
    if (r.s != 0 && dz == 0.0) {
        st.y = r.y0;
        st.slope = r.cos_i / r.sin_i;
        st.curvature = curvature_scale * r.E * r.E;
        return st;
    }
    if (r.s != 0 && r.turn_kind != TurnKind::BelowGround && r.turn_kind != TurnKind::None &&
        dz == r.dz_turn) {
        st.y = r.y_turn;
        st.slope = 0.0;
        st.curvature = curvature_scale * r.k2;
        return st;
    }
    if (r.s != 0 && r.hits_ground && dz == r.dz_ground) {
        st.y = 0.0;
        st.slope = slope_at(r, dz);
        st.curvature = curvature_scale;
        return st;
    }
    if (r.s > 0) {
        // F = cosh(u) / cosh(u0), u = x + sg asinh(w), cosh(u0) = sqrt(1 + w^2); the slope is
        // scale q tanh(u) and exp(-alpha y) = k2 sech^2(u): all three from exp(-2|u|).
        const double u = r.c * dz + r.sg * r.asinh_w;
        const double au = std::fabs(u);
        // ln(1 + e2) to an absolute accuracy of an ulp of 1 is all the height needs (it is
        // added to |u|): the faster logarithm rather than log1p.
        const double e2 = std::exp(-2.0 * au);
        const double ln_cosh = au - kLn2 + std::log(1.0 + e2);
        st.y = r.y0 + (2.0 / alpha) * (ln_cosh - 0.5 * r.log1p_w2);
        const double inv = 1.0 / (1.0 + e2);
        const double th = (1.0 - e2) * inv;
        st.slope = r.slope_scale * r.q * (u < 0.0 ? -th : th);
        const double sech2 = 4.0 * e2 * inv * inv;
        st.curvature = curvature_scale * r.k2 * sech2;
        return st;
    }
    if (r.s < 0 && r.k2 > 0.0 && r.vertex_form) {
        // From the apex: y = y_M + (2/alpha) ln cos v, slope -scale q tan v, and
        // exp(-alpha y) = kappa^2 / cos^2 v.
        const double v = r.c * dz - r.sg * r.theta;
        const double cv = std::cos(v), sv = std::sin(v);
        st.y = r.y_turn + (2.0 / alpha) * std::log(cv);
        st.slope = -r.slope_scale * r.q * sv / cv;
        st.curvature = curvature_scale * r.k2 / (cv * cv);
        return st;
    }
    if (r.s < 0 && r.k2 < 0.0 && r.c > 0.0) {
        // Escaping: the forms height_at chooses, and from F and its derivative the slope
        // (slope_at's) and exp(-alpha y) = E^2 / F^2.
        const double x = r.c * dz;
        const double sigma = r.q;
        const double scale = r.slope_scale;
        const bool near_form = r.sg > 0 ? x < 1.0 : sigma < 0.5 * r.P;
        if (near_form) {
            // F = cosh x + sg P gamma dz sinhc x; dF = sg P cosh x + sigma^2 gamma dz sinhc x;
            // cosh and sinh from expm1, without cancellation for small x.
            const double em = std::expm1(x);
            const double ch = 1.0 + em * em / (2.0 * (em + 1.0));
            const double sinh_x = em * (em + 2.0) / (2.0 * (em + 1.0));
            const double t = r.gamma * dz * (std::fabs(x) < 1e-4 ? 1.0 + x * x / 6.0 : sinh_x / x);
            const double F = ch + r.sg * r.P * t;
            st.y = r.y0 + (2.0 / alpha) * std::log(F);
            st.slope = scale * (r.sg * r.P * ch + sigma * sigma * t) / F;
            st.curvature = curvature_scale * r.E * r.E / (F * F);
            return st;
        }
        // ln F = ln(ps / 2 sigma) + sg x + ln(1 - g), g = r exp(-2 sg x), and the slope
        // sg sigma coth(A + sg x) = sg sigma (1 + g) / (1 - g).
        // E^2 exp(-2 sg x) as one exponential: for a start far above the gradient (alpha y0 >
        // 745) E^2 underflows to 0 while exp(2x) overflows on the way down.
        const double ps = r.P + sigma;
        const double g = std::exp(2.0 * (r.ln_E - r.sg * x)) / (ps * ps);
        const double ln_F = std::log(ps / (2.0 * sigma)) + r.sg * x + std::log1p(-g);
        st.y = r.y0 + (2.0 / alpha) * ln_F;
        st.slope = scale * r.sg * sigma * (1.0 + g) / (1.0 - g);
        st.curvature = curvature_scale * std::exp(2.0 * (r.ln_E - ln_F));
        return st;
    }
    st.y = height_at(r, dz);
    st.slope = slope_at(r, dz);
    st.curvature = curvature_at_height(r, st.y);
    return st;
}

double distance_to_height(const ExactRay& r, double y) {
    if (y == r.y0) return 0.0;
    const bool down = y < r.y0;
    if (down != (r.sg < 0)) return kInf;  // moving away from y
    // The monotone stretch: up to the turning point ahead, the ground, or far away.
    double end = kInf;
    if (r.turn_kind == TurnKind::Ahead) end = r.dz_turn;
    if (r.hits_ground) end = std::min(end, r.dz_ground);
    const double y_end = std::isfinite(end) ? height_at(r, end) : (down ? -kInf : kInf);
    if (down ? y < y_end : y > y_end) return kInf;
    if (r.s > 0 && r.c > 0.0) {
        // Inferior, closed form: F = a e^x + b e^-x (a, b the coefficients of the height's
        // form), solved for the root on the way to y (before the vertex going down).
        const double F = std::exp(0.5 * r.profile.alpha * (y - r.y0));
        const double a = std::exp(r.ln_coef_hi), b = std::exp(r.ln_coef_lo);
        const double disc = std::sqrt(std::max(0.0, F * F - 4.0 * a * b));
        const double x =
            down ? std::log(2.0 * b) - std::log(F + disc) : std::log(F + disc) - std::log(2.0 * a);
        return x / r.c;
    }
    if (r.s < 0 && r.k2 > 0.0 && r.c > 0.0) {
        // Superior, trapped: cos(x - sg theta) = exp(alpha (y - y_M) / 2), before the apex
        // going up and after it going down.
        const double a = std::acos(std::min(1.0, std::exp(0.5 * r.profile.alpha * (y - r.y_turn))));
        return (r.sg > 0 ? r.theta - a : a - r.theta) / r.c;
    }
    if (r.s < 0 && r.k2 < 0.0 && r.c > 0.0) {
        // Superior, escaping: sigma exp(alpha y / 2) = sinh(A + sg x).
        const double sigma = r.q;
        const double A = std::asinh(sigma / r.E);
        const double g = std::asinh(sigma * std::exp(0.5 * r.profile.alpha * y));
        return r.sg * (g - A) / r.c;
    }
    double lo = 0.0, hi = end;
    if (!std::isfinite(hi)) {
        hi = 1.0;
        while ((down ? height_at(r, hi) > y : height_at(r, hi) < y) && hi < 1e12) hi *= 2.0;
        if (hi >= 1e12) return kInf;
    }
    for (int i = 0; i < 100 && hi - lo > 1e-15 * hi; ++i) {
        const double m = 0.5 * (lo + hi);
        const double hm = height_at(r, m);
        if (down ? hm > y : hm < y)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}

double asymptotic_slope(const ExactRay& r) {
    if (r.s == 0) return r.cos_i >= 0.0 ? r.cos_i / r.sin_i : kNaN;
    if (r.s > 0) return r.hits_ground ? kNaN : r.profile.eta1 * r.q / r.beta;
    if (r.ray_class == RayClass::SupEscapeUp) return r.profile.eta1 * r.q / r.beta;
    return kNaN;
}

bool has_asymptote(const ExactRay& r) {
    return (r.s > 0 && !r.hits_ground) || (r.ray_class == RayClass::SupEscapeUp && r.k2 < 0.0);
}

double asymptote_departure(const ExactRay& ray, double dz) {
    const double alpha = ray.profile.alpha;
    if (ray.s > 0) {
        const double u = ray.c * (dz - ray.dz_turn);
        if (u <= 0.0) return kInf;
        return (2.0 / alpha) * std::log1p(std::exp(-2.0 * u));
    }
    if (ray.ray_class == RayClass::SupEscapeUp && ray.k2 < 0.0) {
        const double ps = ray.P + ray.q;
        const double r = ray.E * ray.E / (ps * ps);
        return (2.0 / alpha) * -std::log1p(-r * std::exp(-2.0 * ray.c * dz));
    }
    return kInf;
}

}  // namespace mirage
