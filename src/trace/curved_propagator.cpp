#include "trace/curved_propagator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "scene/camera.h"
#include "util/check.h"

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Below this |sin i| a ray is taken as vertical: it has no horizontal distance to sample
// along, and bends by less than kVerticalSin times the relative index change.
constexpr double kVerticalSin = 1e-12;

// How far below y = 0 a start still counts as on the ground: the hit points of the ground
// plane are computed, not exact.
double ground_slack(const glm::dvec3& p) {
    return 1e-9 * (1.0 + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
}

std::string place(const FileLoc& loc) {
    if (loc.file.empty()) return "";
    return loc.file + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column) + ": ";
}

std::string degrees(double rad) {
    std::ostringstream out;
    out.precision(3);
    out << std::abs(rad) * 180.0 / M_PI;
    return out.str();
}

// The largest turn of a ray's direction anywhere along its path, from the invariant
// eta(y) sin i(y) = beta over the heights the ray can reach; +inf when it can turn round.
// An inferior profile's index grows with height, so a rising ray stays above its start;
// a superior profile's falls with height, so a descending ray stays below it.
double largest_bend(const Profile& profile, double y0, double sin_i, bool rising) {
    const bool inferior = profile.kind == ProfileKind::Inferior;
    const double at_start = eta(profile, y0);
    double lo = std::min(profile.eta0, eta_infinity(profile));
    double hi = std::max(profile.eta0, eta_infinity(profile));
    if (inferior && rising) lo = at_start;
    if (!inferior && !rising) lo = at_start;
    const double beta = at_start * sin_i;
    const double s_max = beta / lo;
    if (!(s_max < 1.0)) return kInf;
    return std::asin(s_max) - std::asin(beta / hi);
}

// What a ray's path can meet, seen in its vertical plane: the boxes of the scene's bounded
// objects and a ground plane.  The first question goes down the hierarchy, pruned by the
// region's heights; a ray that asks again gets the list of the boxes its plane crosses (found
// once, into storage reused from ray to ray).
class SceneObstacles final : public PathObstacles {
  public:
    SceneObstacles(const SceneAccel& accel, const glm::dvec3& origin, const glm::dvec2& heading,
                   std::vector<SceneAccel::Crossing>& crossings)
        : accel_(accel), origin_(origin), heading_(heading), crossings_(crossings) {}
    bool may_meet(const PathRegion& region) const override {
        if (asked_ == 0) {
            ++asked_;
            return accel_.region_may_meet(origin_, heading_, region);
        }
        if (asked_ == 1) {
            ++asked_;
            crossings_.clear();
            accel_.plane_crossings(origin_, heading_, crossings_);
        }
        for (const SceneAccel::Crossing& c : crossings_) {
            if (c.dz_hi < region.dz_lo || c.dz_lo > region.dz_hi) continue;
            if (region_meets_rectangle(region, c.dz_lo, c.dz_hi, c.y_lo, c.y_hi)) return true;
        }
        return false;
    }
    bool ground() const override { return accel_.has_ground_plane(); }

  private:
    const SceneAccel& accel_;
    glm::dvec3 origin_;
    glm::dvec2 heading_;
    std::vector<SceneAccel::Crossing>& crossings_;
    mutable int asked_ = 0;
};

// The shared constants of rays from height y0, kept per thread for the last height asked
// for: a frame's camera rays all start at the eye.
const ExactRayOrigin& ray_origin(const Profile& p, double y0) {
    thread_local ExactRayOrigin cached;
    thread_local bool valid = false;
    const Profile& c = cached.profile;
    if (!valid || cached.y0 != y0 || c.kind != p.kind || c.eta0 != p.eta0 || c.eta1 != p.eta1 ||
        c.alpha != p.alpha) {
        auto o = make_exact_ray_origin(p, y0);
        MIRAGE_CHECK(o.ok());
        cached = *o;
        valid = true;
    }
    return cached;
}

// largest_bend(...) <= limit, from the origin's constants: asin grows at least as fast as its
// argument, so the arcsines are needed only when the arguments differ by at most the limit.
bool bends_at_most(const ExactRayOrigin& o, double sin_i, bool rising, double limit) {
    const bool inferior = o.profile.kind == ProfileKind::Inferior;
    double lo = std::min(o.profile.eta0, o.eta_inf);
    const double hi = std::max(o.profile.eta0, o.eta_inf);
    if (inferior == rising) lo = o.eta_p;
    const double beta = o.eta_p * sin_i;
    const double s_max = beta / lo;
    if (!(s_max < 1.0)) return false;
    const double s_min = beta / hi;
    if (s_max - s_min > limit) return false;
    return std::asin(s_max) - std::asin(s_min) <= limit;
}

// The ray's path for PathSampling::NearSurfaces, into `cp` (its storage reused); false when
// the ray goes straight.  `accel` (may be null) is the scene the path is sampled for.
bool near_surfaces_path(const CurvedSettings& settings, const SceneAccel* accel,
                        const glm::dvec3& origin, const glm::dvec3& direction, double travelled,
                        CurvedPath& cp) {
    const Profile& p = settings.profile;
    if (p.kind == ProfileKind::None || p.eta1 == 0.0) return false;
    // Below the ground the atmosphere is not defined: the band model's bottom layer has the
    // ground's index throughout, so such rays go straight there too.
    if (origin.y < -ground_slack(origin)) return false;
    if (origin.y <= 0.0 && direction.y <= 0.0) return false;
    const double hl = std::sqrt(direction.x * direction.x + direction.z * direction.z);
    if (hl < kVerticalSin) return false;
    const double n = std::sqrt(hl * hl + direction.y * direction.y);
    const double cos_i = direction.y / n, sin_i = hl / n;
    const ExactRayOrigin& o = ray_origin(p, std::max(origin.y, 0.0));
    if (bends_at_most(o, sin_i, direction.y > 0.0, 0.5 * settings.tolerance_rad)) return false;
    cp.ray = make_exact_ray(o, cos_i, sin_i);
    cp.heading = glm::dvec2(direction.x / hl, direction.z / hl);
    SampleSettings ss;
    ss.tolerance_rad = settings.tolerance_rad;
    ss.start_distance = travelled;
    if (accel && !accel->unbounded_elsewhere()) {
        thread_local std::vector<SceneAccel::Crossing> crossings;
        const SceneObstacles obstacles(*accel, origin, cp.heading, crossings);
        sample_path_near(cp.ray, ss, &obstacles, cp.path);
    } else {
        sample_path_near(cp.ray, ss, nullptr, cp.path);
    }
    return true;
}

// The exact ray and its samples as the reference samples them; origin.y >= -ground_slack,
// and a horizontal component.
CurvedPath reference_path(const CurvedSettings& settings, const glm::dvec3& origin,
                          const glm::dvec3& direction, double travelled) {
    const double hl = std::hypot(direction.x, direction.z);
    MIRAGE_CHECK(hl > 0.0);
    const double y0 = std::max(origin.y, 0.0);
    const double i = std::atan2(hl, direction.y);
    auto ray = make_exact_ray(settings.profile, y0, i);
    MIRAGE_CHECK(ray.ok());
    SampleSettings ss;
    ss.tolerance_rad = settings.tolerance_rad;
    ss.start_distance = travelled;
    CurvedPath cp;
    cp.ray = *ray;
    cp.path = sample_path(cp.ray, ss);
    cp.heading = glm::dvec2(direction.x / hl, direction.z / hl);
    return cp;
}

PathHit march(const SceneAccel& accel, const glm::dvec3& origin, const glm::dvec2& heading,
              const CurvedPath& cp) {
    PolylineMarch march(accel, origin);
    const auto& points = cp.path.points;
    const auto& clear = cp.path.clear_length;
    auto world = [&](const glm::dvec2& p) {
        return glm::dvec3(origin.x + p.x * heading.x, p.y, origin.z + p.x * heading.y);
    };
    // The first sample is the start itself.
    for (std::size_t k = 1; k < points.size(); ++k) {
        if (k <= clear.size() && clear[k - 1] > 0.0) {
            march.skip_to(world(points[k]), clear[k - 1]);
        } else if (march.segment_to(world(points[k]))) {
            return march.result();
        }
    }
    const double slope =
        cp.path.end == PathEnd::Ground ? slope_at(cp.ray, cp.ray.dz_ground) : cp.path.end_slope;
    MIRAGE_CHECK(std::isfinite(slope));
    const glm::dvec3 final_direction = glm::normalize(glm::dvec3(heading.x, slope, heading.y));
    if (cp.path.end_clear) {
        march.skip_ray(final_direction);
    } else {
        march.ray(final_direction);
    }
    return march.result();
}

// Whether a ray goes straight, for the reference sampling (curved_path).
bool goes_straight(const CurvedSettings& settings, const glm::dvec3& origin,
                   const glm::dvec3& direction) {
    if (settings.profile.kind == ProfileKind::None || settings.profile.eta1 == 0.0) return true;
    // Below the ground the atmosphere is not defined: the band model's bottom layer has the
    // ground's index throughout, so such rays go straight there too.
    if (origin.y < -ground_slack(origin)) return true;
    if (origin.y <= 0.0 && direction.y <= 0.0) return true;
    const double hl = std::hypot(direction.x, direction.z);
    if (hl < kVerticalSin) return true;
    const double bend =
        largest_bend(settings.profile, std::max(origin.y, 0.0), hl, direction.y > 0.0);
    return bend <= 0.5 * settings.tolerance_rad;
}

}  // namespace

std::optional<CurvedPath> curved_path(const CurvedSettings& settings, const glm::dvec3& origin,
                                      const glm::dvec3& direction, double travelled) {
    if (settings.sampling == PathSampling::Reference) {
        if (goes_straight(settings, origin, direction)) return std::nullopt;
        return reference_path(settings, origin, direction, travelled);
    }
    CurvedPath cp;
    if (!near_surfaces_path(settings, nullptr, origin, direction, travelled, cp))
        return std::nullopt;
    return cp;
}

std::optional<CurvedPath> curved_path(const CurvedSettings& settings, const SceneAccel& accel,
                                      const glm::dvec3& origin, const glm::dvec3& direction,
                                      double travelled) {
    if (settings.sampling == PathSampling::Reference) {
        return curved_path(settings, origin, direction, travelled);
    }
    CurvedPath cp;
    if (!near_surfaces_path(settings, &accel, origin, direction, travelled, cp))
        return std::nullopt;
    return cp;
}

PathHit march_curved_path(const SceneAccel& accel, const glm::dvec3& origin, const CurvedPath& cp) {
    return march(accel, origin, cp.heading, cp);
}

CurvedPropagator::CurvedPropagator(const CurvedSettings& settings) : settings_(settings) {
    MIRAGE_CHECK(settings.profile.kind == ProfileKind::None || settings.tolerance_rad > 0.0);
}

PathHit CurvedPropagator::propagate(const SceneAccel& accel, const RayStart& start) const {
    if (settings_.sampling == PathSampling::Reference) {
        const auto cp = curved_path(settings_, start.origin, start.direction, start.travelled);
        if (!cp) return straight_.propagate(accel, start);
        return march_curved_path(accel, start.origin, *cp);
    }
    // One path per thread, its storage reused from ray to ray.
    thread_local CurvedPath cp;
    if (!near_surfaces_path(settings_, &accel, start.origin, start.direction, start.travelled,
                            cp)) {
        return straight_.propagate(accel, start);
    }
    return march_curved_path(accel, start.origin, cp);
}

ScanlinePropagator::ScanlinePropagator(const CurvedSettings& settings, std::vector<Row> rows)
    : per_ray_(settings), rows_(std::move(rows)) {}

Result<ScanlinePropagator> ScanlinePropagator::make(const CurvedSettings& settings,
                                                    const Camera& camera, int width, int height) {
    MIRAGE_CHECK(width > 0 && height > 0);
    if (!camera_is_level(camera)) {
        std::string why;
        const double pitch = std::asin(std::clamp(glm::normalize(camera.direction).y, -1.0, 1.0));
        const double roll = std::asin(std::clamp(glm::normalize(camera.right).y, -1.0, 1.0));
        if (std::abs(pitch) > 1e-9) {
            why =
                "the camera looks " + degrees(pitch) + " degrees " + (pitch < 0.0 ? "down" : "up");
        } else if (std::abs(roll) > 1e-9) {
            why = "the camera is rolled " + degrees(roll) + " degrees";
        } else {
            why = "the camera's up vector is not vertical";
        }
        return make_error(place(camera.loc) +
                          "scanline paths need a level camera (one path per image row is "
                          "rotated about the vertical): " +
                          why);
    }
    std::vector<Row> rows(height);
    for (int row = 0; row < height; ++row) {
        // The central column: the same ray a per-ray render traces there (for an odd width,
        // the centre of a pixel), so that column is the same in both modes.
        const CameraRay r = camera_ray(camera, 0.5 * width, row + 0.5, width, height);
        rows[row].path = curved_path(settings, r.origin, r.direction, 0.0);
        rows[row].slope = r.direction.y / std::hypot(r.direction.x, r.direction.z);
    }
    return ScanlinePropagator(settings, std::move(rows));
}

PathHit ScanlinePropagator::propagate(const SceneAccel& accel, const RayStart& start) const {
    if (!start.image_position) return per_ray_.propagate(accel, start);
    const glm::dvec3& d = start.direction;
    const double hl = std::hypot(d.x, d.z);
    MIRAGE_CHECK(hl > 0.0);  // a level camera sees no vertical ray
    const int row = std::clamp(static_cast<int>(std::floor(start.image_position->y)), 0,
                               static_cast<int>(rows_.size()) - 1);
    const Row& r = rows_[row];
    // The row's path turned into this ray's azimuth.
    const glm::dvec2 heading(d.x / hl, d.z / hl);
    if (r.path) return march(accel, start.origin, heading, *r.path);
    if (d.y / hl == r.slope) return straight_.propagate(accel, start);
    RayStart turned = start;
    turned.direction = glm::normalize(glm::dvec3(heading.x, r.slope, heading.y));
    return straight_.propagate(accel, turned);
}

double pixel_angle_rad(const Camera& camera, int width, int height) {
    const glm::dvec3 a =
        camera_ray(camera, 0.5 * width, 0.5 * height - 0.5, width, height).direction;
    const glm::dvec3 b =
        camera_ray(camera, 0.5 * width, 0.5 * height + 0.5, width, height).direction;
    return angle_between(a, b);
}

bool camera_is_level(const Camera& camera) {
    constexpr double kRel = 1e-9;
    const double up = glm::length(camera.up);
    return up > 0.0 && camera.up.y > 0.0 && std::abs(camera.up.x) <= kRel * up &&
           std::abs(camera.up.z) <= kRel * up &&
           std::abs(camera.direction.y) <= kRel * glm::length(camera.direction) &&
           std::abs(camera.right.y) <= kRel * glm::length(camera.right);
}

}  // namespace mirage
