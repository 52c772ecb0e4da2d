#include "atmosphere/exact_path.h"

#include <algorithm>
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

double Atmosphere::constant_above() const {
    if (const QuadraticProfile* q = quadratic_profile()) return q->top();
    return kInf;
}

bool Atmosphere::closed_form() const { return exponential_profile() != nullptr; }

bool Atmosphere::operator==(const Atmosphere& other) const {
    const Profile* a = exponential_profile();
    const Profile* b = other.exponential_profile();
    if (a && b) {
        return a->kind == b->kind && a->eta0 == b->eta0 && a->eta1 == b->eta1 &&
               a->alpha == b->alpha;
    }
    return !a && !b && quadratic_profile() == other.quadratic_profile();
}

std::vector<double> Atmosphere::key() const {
    if (const Profile* p = exponential_profile())
        return {static_cast<double>(p->kind), p->eta0, p->eta1, p->alpha};
    const QuadraticProfile& q = *quadratic_profile();
    std::vector<double> key = {-1.0, q.n0_sq(), q.earth_radius()};
    for (int j = 0; j <= q.piece_count(); ++j) {
        key.push_back(q.knot(j));
        key.push_back(q.e(j));
    }
    return key;
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

Result<PathOrigin> PathOrigin::make(const Atmosphere& atmosphere, double y0) {
    PathOrigin o(atmosphere, y0);
    if (const Profile* p = atmosphere.exponential_profile()) {
        auto start = make_exact_ray_origin(*p, y0);
        if (!start) return start.error();
        // Monotone in height: n runs from eta0 at the ground through eta_p to eta_inf.
        const double lo = std::min(p->eta0, start->eta_inf);
        const double hi = std::max(p->eta0, start->eta_inf);
        const bool inferior = p->kind == ProfileKind::Inferior;
        o.n_ = start->eta_p;
        o.lo_up_ = inferior ? start->eta_p : lo;
        o.lo_down_ = inferior ? lo : start->eta_p;
        o.hi_up_ = o.hi_down_ = hi;
        o.start_ = *start;
        return o;
    }
    const QuadraticProfile* q = atmosphere.quadratic_profile();
    if (!(y0 >= 0.0 && std::isfinite(y0)))
        return make_error("a ray's start height must be finite and at least 0");
    atmosphere.n_range(y0, kInf, o.lo_up_, o.hi_up_);
    atmosphere.n_range(0.0, y0, o.lo_down_, o.hi_down_);
    o.n_ = atmosphere.n(y0);
    o.start_ = quadratic_start(*q, y0);
    return o;
}

bool PathOrigin::bends_at_most(double sin_i, bool rising, double limit) const {
    const double lo = rising ? lo_up_ : lo_down_;
    const double hi = rising ? hi_up_ : hi_down_;
    const double beta = n_ * sin_i;
    const double s_max = beta / lo;
    if (!(s_max < 1.0)) return false;
    const double s_min = beta / hi;
    // asin' = 1 / sqrt(1 - x^2) is at least 1 / sqrt(1 - s_min^2) between the two.
    if (s_max - s_min > limit * std::sqrt((1.0 - s_min) * (1.0 + s_min))) return false;
    return std::asin(s_max) - std::asin(s_min) <= limit;
}

void PathOrigin::path(double cos_i, double sin_i, std::optional<ExactPath>& path) const {
    if (const auto* start = std::get_if<ExactRayOrigin>(&start_)) {
        if (!path || !path->exponential()) path.emplace(ExactPath(ExactRay{}));
        make_exact_ray(*start, cos_i, sin_i, std::get<ExactRay>(path->path_));
        return;
    }
    std::vector<QuadraticSegment> storage;
    if (path) storage = path->release_storage();
    auto made = ExactPath::make_direction(atmosphere_, std::get<QuadraticStart>(start_), cos_i,
                                          sin_i);
    MIRAGE_CHECK(made.ok());
    made->adopt_storage(std::move(storage));
    path.emplace(std::move(*made));
}

}  // namespace mirage
