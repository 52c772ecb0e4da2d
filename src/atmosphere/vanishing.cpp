#include "atmosphere/vanishing.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "atmosphere/exact_path.h"
#include "util/format.h"

namespace mirage {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Golden-section search for a minimum of f on [a, b].
double golden_min(const std::function<double(double)>& f, double a, double b, int iterations) {
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = f(c), fd = f(d);
    for (int i = 0; i < iterations; ++i) {
        if (fc < fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    return fc < fd ? c : d;
}

// The minimum (or, with sign -1, the maximum) of f over [a, b], over the points where f is
// defined (f NaN elsewhere): a dense scan with the samples packed towards a
// (y = a + (b - a) u^2), then a golden-section refinement around the best.  {NaN, NaN} when f
// is defined at no sample.
std::pair<double, double> scan_extremum(const std::function<double(double)>& f, double a, double b,
                                        int samples, double sign) {
    auto at = [&](int k) {
        const double u = double(k) / samples;
        return a + (b - a) * u * u;
    };
    int best = -1;
    double best_v = kInf;
    for (int k = 0; k <= samples; ++k) {
        const double v = sign * f(at(k));
        if (v < best_v) {
            best_v = v;
            best = k;
        }
    }
    if (best < 0) return {kNaN, kNaN};
    const double lo = at(std::max(best - 1, 0)), hi = at(std::min(best + 1, samples));
    const double x = golden_min(
        [&](double t) {
            const double v = sign * f(t);
            return std::isnan(v) ? kInf : v;
        },
        lo, hi, 60);
    const double vx = sign * f(x);
    if (vx < best_v) return {x, sign * vx};
    return {at(best), sign * best_v};
}

// The distances from a turning point at y_t up to heights ya and yb, when the ray that is
// level at y_t rises through both before it turns again: then the eye's ray that turns at y_t
// turns there (n stays above n(y_t) up to the eye), and not higher.  False otherwise: the
// level ray turns below one of them, or n falls with height at y_t (the level ray is then at
// an apex and never rises).
bool rise_from_turn(const Atmosphere& atm, double y_t, double ya, double yb, double& da,
                    double& db) {
    auto level = ExactPath::make(atm, y_t, 0.5 * kPi);
    if (!level) return false;
    da = ya > y_t ? level->distance_to_height(ya) : 0.0;
    db = yb > y_t ? level->distance_to_height(yb) : 0.0;
    return std::isfinite(da) && std::isfinite(db);
}

Status check_heights(double eye_height, double object_height) {
    if (!(eye_height > 0.0) || !std::isfinite(eye_height))
        return make_error("eye height " + shortest(eye_height) +
                          ": must be above the ground (> 0)");
    if (!(object_height > 0.0) || !std::isfinite(object_height))
        return make_error("object height " + shortest(object_height) +
                          ": must be above the ground (> 0)");
    return Ok{};
}

}  // namespace

double turn_to_height_distance(const Atmosphere& atmosphere, double y_turn, double y) {
    if (y <= y_turn) return 0.0;
    double d, unused;
    return rise_from_turn(atmosphere, y_turn, y, y_turn, d, unused) ? d : kInf;
}

double turn_to_height_distance(const Profile& profile, double y_turn, double y) {
    return turn_to_height_distance(Atmosphere::exponential(profile), y_turn, y);
}

Result<MirrorReach> mirror_reach(const Atmosphere& atmosphere, double eye_height,
                                 double object_height) {
    if (const Profile* p = atmosphere.exponential_profile();
        p && (p->kind != ProfileKind::Inferior || !(p->eta1 > 0.0)))
        return make_error(
            "the mirrored image that vanishes is the inferior mirage's: the profile "
            "is " +
            std::string(profile_kind_name(p->kind)));
    if (auto ok = check_heights(eye_height, object_height); !ok) return ok.error();
    const double top = std::min(eye_height, object_height);
    // L(y_t) = X(y_t -> y0) + X(y_t -> h), defined where the eye's ray turns at y_t.
    auto reach = [&](double y_turn) {
        double to_eye, to_point;
        if (!rise_from_turn(atmosphere, y_turn, eye_height, object_height, to_eye, to_point))
            return kNaN;
        return to_eye + to_point;
    };
    constexpr int kSamples = 400;
    const auto [y_near, d_near] = scan_extremum(reach, 0.0, top, kSamples, 1.0);
    if (std::isnan(d_near))
        return make_error("no ray from the eye at " + shortest(eye_height) +
                          " turns below " + shortest(top) + " and rises again to " +
                          shortest(object_height) +
                          ": the air has no inferior mirage of that point (the index must grow "
                          "with height between the turning point and both)");
    const double d_far = scan_extremum(reach, 0.0, top, kSamples, -1.0).second;
    MirrorReach m;
    m.nearest = d_near;
    m.farthest = d_far;
    m.nearest_turn_height = y_near;
    m.grazing = y_near <= 1e-12 * top;
    m.nearest_elevation_rad = -std::acos(
        std::min(1.0, atmosphere.n(y_near) / atmosphere.n(eye_height)));
    return m;
}

Result<MirrorReach> mirror_reach(const Profile& profile, double eye_height, double object_height) {
    return mirror_reach(Atmosphere::exponential(profile), eye_height, object_height);
}

SphereMirror mirrored_image_of_sphere(const Atmosphere& atmosphere, double eye_height,
                                      double distance, double centre_height, double radius) {
    SphereMirror out;
    if (const Profile* p = atmosphere.exponential_profile(); p && p->kind != ProfileKind::Inferior)
        return out;
    if (!(radius > 0.0) || !(eye_height > 0.0)) return out;
    const double n_eye = atmosphere.n(eye_height);
    // The elevation of the ray that turns at height y_t: n(y_t) = n(y0) cos e.
    auto elevation_of = [&](double y_t) {
        return -std::acos(std::min(1.0, atmosphere.n(y_t) / n_eye));
    };
    // Whether the ray at elevation e first meets the sphere's section after its turn (a
    // lowest point).
    auto mirrored = [&](double e) {
        auto ray = ExactPath::make(atmosphere, eye_height, 0.5 * kPi - e);
        if (!ray || ray->turning_point_count() == 0) return false;
        const TurningPoint turn = ray->turning_point(0);
        if (!turn.lowest) return false;
        const double a = std::max(0.0, distance - radius), b = distance + radius;
        auto inside = [&](double dz) {
            const double dy = ray->height_at(dz) - centre_height, dx = dz - distance;
            return dx * dx + dy * dy <= radius * radius;
        };
        constexpr int kSteps = 256;
        for (int k = 0; k <= kSteps; ++k) {
            const double dz = a + (b - a) * k / kSteps;
            if (inside(dz)) return dz > turn.dz;
        }
        return false;
    };
    // Rays from the one grazing the ground (y_t = 0) to the level one, packed towards the
    // ground, where the last of the image lives as it vanishes.
    constexpr int kRays = 3000;
    auto y_of = [&](int k) {
        const double u = double(k) / kRays;
        return eye_height * u * u;
    };
    int first = -1, last = -1;
    for (int k = 1; k < kRays; ++k) {
        if (mirrored(elevation_of(y_of(k)))) {
            if (first < 0) first = k;
            last = k;
        }
    }
    if (first < 0) return out;
    // Bisect each edge of the set between a ray that misses and one that hits.
    auto edge = [&](double hit_y, double miss_y) {
        for (int i = 0; i < 50; ++i) {
            const double m = 0.5 * (hit_y + miss_y);
            (mirrored(elevation_of(m)) ? hit_y : miss_y) = m;
        }
        return hit_y;
    };
    const double y_lo = edge(y_of(first), y_of(first - 1));
    const double y_hi = edge(y_of(last), y_of(last + 1));
    out.visible = true;
    // A lower turning height is a steeper ray: the lower edge of the image.
    out.elevation_low_rad = elevation_of(y_lo);
    out.elevation_high_rad = elevation_of(y_hi);
    out.angular_size_rad = out.elevation_high_rad - out.elevation_low_rad;
    return out;
}

SphereMirror mirrored_image_of_sphere(const Profile& profile, double eye_height, double distance,
                                      double centre_height, double radius) {
    return mirrored_image_of_sphere(Atmosphere::exponential(profile), eye_height, distance,
                                    centre_height, radius);
}

Result<double> sphere_vanishing_distance(const Atmosphere& atmosphere, double eye_height,
                                         double centre_height, double radius) {
    if (!(radius > 0.0) || !std::isfinite(radius))
        return make_error("sphere radius " + shortest(radius) + ": must be > 0");
    if (!(centre_height - radius > 0.0))
        return make_error("a sphere of radius " + shortest(radius) + " at height " +
                          shortest(centre_height) +
                          " reaches the ground: its mirrored image "
                          "never vanishes that way");
    if (auto check = mirror_reach(atmosphere, eye_height, centre_height); !check)
        return check.error();
    // Points of the section at angle phi from the centre, phi = 0 farthest from the eye.
    auto needed = [&](double phi) {
        auto m = mirror_reach(atmosphere, eye_height, centre_height + radius * std::sin(phi));
        return m ? m->nearest - radius * std::cos(phi) : kInf;
    };
    int best = 0;
    constexpr int kAngles = 180;
    double best_v = kInf;
    for (int k = 0; k < kAngles; ++k) {
        const double v = needed(-kPi + 2.0 * kPi * k / kAngles);
        if (v < best_v) {
            best_v = v;
            best = k;
        }
    }
    const double step = 2.0 * kPi / kAngles;
    const double phi0 = -kPi + step * best;
    const double phi = golden_min(needed, phi0 - step, phi0 + step, 50);
    return std::min(best_v, needed(phi));
}

Result<double> sphere_vanishing_distance(const Profile& profile, double eye_height,
                                         double centre_height, double radius) {
    return sphere_vanishing_distance(Atmosphere::exponential(profile), eye_height, centre_height,
                                     radius);
}

}  // namespace mirage
