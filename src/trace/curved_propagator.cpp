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
    return to_string(loc) + ": ";
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

// The exact ray and its samples; origin.y >= -ground_slack, and a horizontal component.
CurvedPath sample_curved_path(const CurvedSettings& settings, const glm::dvec3& origin,
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
    auto world = [&](const glm::dvec2& p) {
        return glm::dvec3(origin.x + p.x * heading.x, p.y, origin.z + p.x * heading.y);
    };
    // The first sample is the start itself.
    for (std::size_t k = 1; k < points.size(); ++k) {
        if (march.segment_to(world(points[k]))) return march.result();
    }
    const double slope =
        cp.path.end == PathEnd::Ground ? slope_at(cp.ray, cp.ray.dz_ground) : cp.path.end_slope;
    MIRAGE_CHECK(std::isfinite(slope));
    march.ray(glm::normalize(glm::dvec3(heading.x, slope, heading.y)));
    return march.result();
}

}  // namespace

std::optional<CurvedPath> curved_path(const CurvedSettings& settings, const glm::dvec3& origin,
                                      const glm::dvec3& direction, double travelled) {
    if (settings.profile.kind == ProfileKind::None || settings.profile.eta1 == 0.0) {
        return std::nullopt;
    }
    // Below the ground the atmosphere is not defined: the band model's bottom layer has the
    // ground's index throughout, so such rays go straight there too.
    if (origin.y < -ground_slack(origin)) return std::nullopt;
    // So far above the ground (beyond any scene mirage follows) the index is flat to far
    // below a double's precision: straight.
    if (origin.y > kMaxHeight) return std::nullopt;
    if (origin.y <= 0.0 && direction.y <= 0.0) return std::nullopt;
    const double hl = std::hypot(direction.x, direction.z);
    if (hl < kVerticalSin) return std::nullopt;
    const double bend =
        largest_bend(settings.profile, std::max(origin.y, 0.0), hl, direction.y > 0.0);
    if (bend <= 0.5 * settings.tolerance_rad) return std::nullopt;
    return sample_curved_path(settings, origin, direction, travelled);
}

PathHit march_curved_path(const SceneAccel& accel, const glm::dvec3& origin, const CurvedPath& cp) {
    return march(accel, origin, cp.heading, cp);
}

CurvedPropagator::CurvedPropagator(const CurvedSettings& settings) : settings_(settings) {
    MIRAGE_CHECK(settings.profile.kind == ProfileKind::None || settings.tolerance_rad > 0.0);
}

PathHit CurvedPropagator::propagate(const SceneAccel& accel, const RayStart& start) const {
    const auto cp = curved_path(settings_, start.origin, start.direction, start.travelled);
    if (!cp) return straight_.propagate(accel, start);
    return march_curved_path(accel, start.origin, *cp);
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

bool camera_is_level(const Camera& camera) {
    constexpr double kRel = 1e-9;
    const double up = glm::length(camera.up);
    return up > 0.0 && camera.up.y > 0.0 && std::abs(camera.up.x) <= kRel * up &&
           std::abs(camera.up.z) <= kRel * up &&
           std::abs(camera.direction.y) <= kRel * glm::length(camera.direction) &&
           std::abs(camera.right.y) <= kRel * glm::length(camera.right);
}

}  // namespace mirage
