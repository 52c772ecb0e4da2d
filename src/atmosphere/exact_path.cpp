#include "atmosphere/exact_path.h"

#include <cmath>
#include <limits>

#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class... F>
struct Overload : F... {
    using F::operator()...;
};
template <class... F>
Overload(F...) -> Overload<F...>;

// The exponential ray's turning point ahead, if it has one (inferior: its lowest point;
// superior, trapped going up: its apex).
bool exponential_turns(const ExactRay& r) {
    return (r.ray_class == RayClass::InfTurn || r.ray_class == RayClass::SupTrappedUp) &&
           r.dz_turn > 0.0;
}

}  // namespace

Atmosphere::Atmosphere() : model_(Profile{ProfileKind::None, 1.0, 0.0, 1.0}) {}

Atmosphere Atmosphere::exponential(const Profile& profile) {
    Atmosphere a;
    a.model_ = profile;
    return a;
}

Atmosphere Atmosphere::quadratic(std::shared_ptr<const QuadraticProfile> profile) {
    MIRAGE_CHECK(profile != nullptr);
    Atmosphere a;
    a.model_ = std::move(profile);
    return a;
}

const Profile* Atmosphere::exponential_profile() const { return std::get_if<Profile>(&model_); }

const QuadraticProfile* Atmosphere::quadratic_profile() const {
    auto p = std::get_if<std::shared_ptr<const QuadraticProfile>>(&model_);
    return p ? p->get() : nullptr;
}

double Atmosphere::n_sq(double y) const {
    if (auto p = exponential_profile()) return eta_sq(*p, y);
    return quadratic_profile()->n_sq(y);
}

double Atmosphere::n(double y) const { return std::sqrt(n_sq(y)); }

bool Atmosphere::has_gradient() const {
    if (auto p = exponential_profile()) return p->kind != ProfileKind::None && p->eta1 != 0.0;
    return !quadratic_profile()->homogeneous();
}

double Atmosphere::earth_radius() const {
    if (auto q = quadratic_profile()) return q->earth_radius();
    return 0.0;
}

void Atmosphere::n_range(double ya, double yb, double& lo, double& hi) const {
    if (auto p = exponential_profile()) {
        // Monotone in height.
        const double a = eta(*p, std::max(0.0, ya));
        const double b = std::isinf(yb) ? eta_infinity(*p) : eta(*p, std::max(0.0, yb));
        lo = std::min(a, b);
        hi = std::max(a, b);
        return;
    }
    const auto* q = quadratic_profile();
    double l, h;
    q->n_sq_range(ya, std::isinf(yb) ? q->top() : yb, l, h);
    lo = std::sqrt(l);
    hi = std::sqrt(h);
}

Result<ExactPath> ExactPath::make(const Atmosphere& atmosphere, double y0, double i_rad) {
    if (auto p = atmosphere.exponential_profile()) {
        auto ray = make_exact_ray(*p, y0, i_rad);
        if (!ray) return ray.error();
        return ExactPath(std::move(*ray));
    }
    auto path = QuadraticPath::make(*atmosphere.quadratic_profile(), y0, i_rad);
    if (!path) return path.error();
    return ExactPath(std::move(*path));
}

Result<ExactPath> ExactPath::make_direction(const Atmosphere& atmosphere, double y0, double cos_i,
                                            double sin_i) {
    if (atmosphere.exponential_profile()) return make(atmosphere, y0, std::atan2(sin_i, cos_i));
    return make_direction(atmosphere, quadratic_start(*atmosphere.quadratic_profile(), y0), cos_i,
                          sin_i);
}

Result<ExactPath> ExactPath::make_direction(const Atmosphere& atmosphere,
                                            const QuadraticStart& start, double cos_i,
                                            double sin_i) {
    const QuadraticProfile* profile = atmosphere.quadratic_profile();
    MIRAGE_CHECK(profile != nullptr);
    auto path = QuadraticPath::make_direction(*profile, start, cos_i, sin_i);
    if (!path) return path.error();
    return ExactPath(std::move(*path));
}

double ExactPath::y0() const {
    return std::visit(Overload{[](const ExactRay& r) { return r.y0; },
                               [](const QuadraticPath& q) { return q.y0(); }},
                      path_);
}

double ExactPath::i_rad() const {
    return std::visit(Overload{[](const ExactRay& r) { return r.i; },
                               [](const QuadraticPath& q) { return q.i_rad(); }},
                      path_);
}

double ExactPath::beta() const {
    return std::visit(Overload{[](const ExactRay& r) { return r.beta; },
                               [](const QuadraticPath& q) { return q.beta(); }},
                      path_);
}

double ExactPath::eta_start() const {
    return std::visit(Overload{[](const ExactRay& r) { return r.eta_p; },
                               [](const QuadraticPath& q) { return q.eta_start(); }},
                      path_);
}

double ExactPath::height_at(double dz) const {
    if (auto r = exponential()) return mirage::height_at(*r, dz);
    return quadratic()->height_at(dz);
}

double ExactPath::distance_to_height(double y) const {
    if (auto r = exponential()) return mirage::distance_to_height(*r, y);
    return quadratic()->distance_to_height(y);
}

double ExactPath::slope_at(double dz) const {
    if (auto r = exponential()) return mirage::slope_at(*r, dz);
    return quadratic()->slope_at(dz);
}

double ExactPath::curvature_bound(double ya, double yb) const {
    if (auto r = exponential()) {
        // |y''| = alpha eta1^2 exp(-alpha y) / (2 beta^2) falls with height in both profiles.
        return std::fabs(curvature_at_height(*r, std::max(0.0, std::min(ya, yb))));
    }
    return quadratic()->curvature_bound(ya, yb);
}

int ExactPath::turning_point_count() const {
    if (auto r = exponential()) return exponential_turns(*r) ? 1 : 0;
    return quadratic()->turning_point_count();
}

TurningPoint ExactPath::turning_point(int k) const {
    if (auto r = exponential()) {
        MIRAGE_CHECK(k == 0 && exponential_turns(*r));
        return {r->dz_turn, r->y_turn, r->s > 0};
    }
    return quadratic()->turning_point(k);
}

bool ExactPath::turning_point_before(int k, double dz, TurningPoint& tp) const {
    if (auto r = exponential()) {
        if (k != 0 || !exponential_turns(*r)) return false;
        tp = {r->dz_turn, r->y_turn, r->s > 0};
        return tp.dz < dz;
    }
    return quadratic()->turning_point_before(k, dz, tp);
}

int ExactPath::first_turning_point_after(double dz) const {
    if (auto r = exponential()) return exponential_turns(*r) && dz <= r->dz_turn ? 0 : -1;
    return quadratic()->first_turning_point_after(dz);
}

bool ExactPath::hits_ground() const {
    if (auto r = exponential()) return r->hits_ground;
    return quadratic()->hits_ground();
}

double ExactPath::dz_ground() const {
    if (auto r = exponential()) return r->hits_ground ? r->dz_ground : kInf;
    return quadratic()->dz_ground();
}

bool ExactPath::straight() const {
    if (auto r = exponential()) return r->s == 0;
    return quadratic()->fate() == PathFate::Straight;
}

double ExactPath::asymptotic_slope() const {
    if (auto r = exponential()) {
        if (r->s == 0) return r->cos_i / r->sin_i;
        return has_asymptote(*r) ? mirage::asymptotic_slope(*r) : kNaN;
    }
    return quadratic()->asymptotic_slope();
}

double ExactPath::asymptote_departure(double dz) const {
    if (auto r = exponential()) {
        if (r->s == 0) return 0.0;
        return has_asymptote(*r) ? mirage::asymptote_departure(*r, dz) : kInf;
    }
    return quadratic()->asymptote_departure(dz);
}

PathFate ExactPath::fate() const {
    if (auto r = exponential()) {
        if (r->s == 0) return PathFate::Straight;
        return r->hits_ground ? PathFate::Ground : PathFate::Escape;
    }
    return quadratic()->fate();
}

std::string ExactPath::class_name() const {
    if (auto r = exponential()) return std::string(ray_class_name(r->ray_class));
    return std::string(path_fate_name(quadratic()->fate()));
}

std::vector<QuadraticSegment> ExactPath::release_storage() {
    if (auto* q = std::get_if<QuadraticPath>(&path_)) return q->release_storage();
    return {};
}

void ExactPath::adopt_storage(std::vector<QuadraticSegment>&& storage) {
    if (auto* q = std::get_if<QuadraticPath>(&path_)) q->adopt_storage(std::move(storage));
}

}  // namespace mirage
