#include "trace/curved_propagator.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "atmosphere/sky_exit.h"
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

// A monotone function of the azimuth atan2(x, z) of (x, z), in (-2, 2], without a
// trigonometric function: the "diamond angle", the seam (+-2) straight along -z.
double pseudo_angle(double x, double z) {
    const double s = x / (std::abs(x) + std::abs(z));
    if (z >= 0.0) return s;
    return x >= 0.0 ? 2.0 - s : -2.0 - s;
}

// The boxes of the scene's bounded objects that the vertical planes of rays from one eye can
// cross, by the planes' azimuth: each box is listed in the bins of the azimuths from the eye
// its x-z rectangle spans (one bin more on each side, for rounding).  What rays from one eye
// share, built once per scene.
class EyeIndex {
  public:
    EyeIndex(const SceneAccel& accel, const glm::dvec3& eye)
        : accel_id_(accel.id()), eye_(eye), start_(kBins + 1, 0) {
        std::vector<std::pair<int, int>> spans;  // per box: its bin ranges, [first, last]
        std::vector<int> owner;
        for (int i = 0; i < accel.box_count(); ++i) {
            const Aabb& b = accel.item_box(i);
            if (!b.finite()) continue;
            const double x0 = b.lo.x - eye.x, x1 = b.hi.x - eye.x;
            const double z0 = b.lo.z - eye.z, z1 = b.hi.z - eye.z;
            auto add = [&](int first, int last) {
                spans.push_back({std::max(0, first), std::min(kBins - 1, last)});
                owner.push_back(i);
            };
            if (x0 <= 0.0 && x1 >= 0.0 && z0 <= 0.0 && z1 >= 0.0) {  // the eye is above it
                add(0, kBins - 1);
                continue;
            }
            const double corners[4] = {pseudo_angle(x0, z0), pseudo_angle(x0, z1),
                                       pseudo_angle(x1, z0), pseudo_angle(x1, z1)};
            if (x0 <= 0.0 && x1 >= 0.0 && z1 < 0.0) {
                // Behind the eye across the seam: from the corners right of it up to +2, and
                // from -2 up to the corners left of it.
                double lo_pos = 2.0, hi_neg = -2.0;
                for (const double c : corners) {
                    if (c > 0.0) lo_pos = std::min(lo_pos, c);
                    if (c < 0.0) hi_neg = std::max(hi_neg, c);
                }
                add(bin(lo_pos) - 1, kBins - 1);
                add(0, bin(hi_neg) + 1);
                continue;
            }
            const auto [lo, hi] = std::minmax({corners[0], corners[1], corners[2], corners[3]});
            add(bin(lo) - 1, bin(hi) + 1);
        }
        for (const auto& [first, last] : spans) {
            for (int k = first; k <= last; ++k) ++start_[k + 1];
        }
        for (int k = 0; k < kBins; ++k) start_[k + 1] += start_[k];
        items_.resize(start_[kBins]);
        std::vector<int> fill(start_.begin(), start_.end() - 1);
        for (std::size_t j = 0; j < spans.size(); ++j) {
            for (int k = spans[j].first; k <= spans[j].second; ++k) items_[fill[k]++] = owner[j];
        }
    }

    bool serves(const SceneAccel& accel, const glm::dvec3& eye) const {
        return accel_id_ == accel.id() && eye_ == eye;
    }

    /// The crossings, at dz >= 0, of the boxes a plane along unit `heading` from the eye may
    /// cross (appended to `out`).
    void crossings(const SceneAccel& accel, const glm::dvec2& heading,
                   std::vector<SceneAccel::Crossing>& out) const {
        const int k = bin(pseudo_angle(heading.x, heading.y));
        const double inv_x = 1.0 / heading.x, inv_z = 1.0 / heading.y;
        for (int j = start_[k]; j < start_[k + 1]; ++j) {
            const Aabb& b = accel.item_box(items_[j]);
            double p = -std::numeric_limits<double>::infinity();
            double q = std::numeric_limits<double>::infinity();
            // As the hierarchy's footprint test: a line in a face's plane counts as inside.
            const double x0 = (b.lo.x - eye_.x) * inv_x, x1 = (b.hi.x - eye_.x) * inv_x;
            const double z0 = (b.lo.z - eye_.z) * inv_z, z1 = (b.hi.z - eye_.z) * inv_z;
            for (auto [t0, t1] : {std::pair{x0, x1}, std::pair{z0, z1}}) {
                if (t0 > t1) std::swap(t0, t1);
                if (t0 > p) p = t0;
                if (t1 < q) q = t1;
            }
            p = std::max(p, 0.0);
            if (p <= q) out.push_back({p, q, b.lo.y, b.hi.y});
        }
    }

  private:
    static constexpr int kBins = 4096;
    static int bin(double pseudo) {
        return std::clamp(static_cast<int>(std::floor((pseudo + 2.0) * (kBins / 4.0))), 0,
                          kBins - 1);
    }

    std::uint64_t accel_id_;
    glm::dvec3 eye_;
    std::vector<int> start_;  // bin k lists items_[start_[k]] to items_[start_[k + 1] - 1]
    std::vector<int> items_;
};

// What a ray's path can meet, seen in its vertical plane: the boxes of the scene's bounded
// objects and a ground plane.  For a ray from the eye the boxes its plane crosses come from
// the eye's index; for another ray the first questions go down the hierarchy, pruned by the
// regions' heights, and a ray that asks more gets the list of the boxes its plane crosses
// (found once, into storage reused from ray to ray).
class SceneObstacles final : public PathObstacles {
  public:
    SceneObstacles(const SceneAccel& accel, const glm::dvec3& origin, const glm::dvec2& heading,
                   std::vector<SceneAccel::Crossing>& crossings, const EyeIndex* eye)
        : accel_(accel), origin_(origin), heading_(heading), crossings_(crossings) {
        if (eye) {
            crossings_.clear();
            eye->crossings(accel, heading, crossings_);
            asked_ = kDirectQuestions + 1;
        }
    }
    bool may_meet(const PathRegion& region) const override {
        if (asked_ < kDirectQuestions) {
            ++asked_;
            return accel_.region_may_meet(origin_, heading_, region);
        }
        if (asked_ == kDirectQuestions) {
            ++asked_;
            crossings_.clear();
            accel_.plane_crossings(origin_, heading_, crossings_);
        }
        // The region's test is prepared at the first box its stretch of dz overlaps.
        std::optional<RegionTest> test;
        for (const SceneAccel::Crossing& c : crossings_) {
            if (c.dz_hi < region.dz_lo || c.dz_lo > region.dz_hi) continue;
            if (!test) test.emplace(region);
            if (test->meets(c.dz_lo, c.dz_hi, c.y_lo, c.y_hi)) return true;
        }
        return false;
    }
    bool ground() const override { return accel_.has_ground_plane(); }
    double reach() const override {
        if (asked_ <= kDirectQuestions) {
            asked_ = kDirectQuestions + 1;
            crossings_.clear();
            accel_.plane_crossings(origin_, heading_, crossings_);
        }
        double r = 0.0;
        for (const SceneAccel::Crossing& c : crossings_) r = std::max(r, c.dz_hi);
        return r;
    }

  private:
    const SceneAccel& accel_;
    glm::dvec3 origin_;
    glm::dvec2 heading_;
    std::vector<SceneAccel::Crossing>& crossings_;
    mutable int asked_ = 0;
    static constexpr int kDirectQuestions = 1;  // answered by the hierarchy
};

// The eye's index for the scene, kept per thread.
const EyeIndex& eye_index(const SceneAccel& accel, const glm::dvec3& eye) {
    thread_local std::unique_ptr<EyeIndex> index;
    if (!index || !index->serves(accel, eye)) index = std::make_unique<EyeIndex>(accel, eye);
    return *index;
}

// The shared constants of rays from height y0, kept per thread for the last two heights asked
// for: a frame's camera rays all start at the eye, and each reflection asks for another.
const ExactRayOrigin& ray_origin(const Profile& p, double y0) {
    struct Slot {
        ExactRayOrigin origin;
        bool valid = false;
    };
    thread_local Slot slots[2];
    thread_local int last = 0;
    auto matches = [&](const Slot& s) {
        const Profile& c = s.origin.profile;
        return s.valid && s.origin.y0 == y0 && c.kind == p.kind && c.eta0 == p.eta0 &&
               c.eta1 == p.eta1 && c.alpha == p.alpha;
    };
    for (int k : {last, 1 - last}) {
        if (matches(slots[k])) {
            last = k;
            return slots[k].origin;
        }
    }
    auto o = make_exact_ray_origin(p, y0);
    MIRAGE_CHECK(o.ok());
    last = 1 - last;  // replace the one used less recently
    slots[last] = {*o, true};
    return slots[last].origin;
}

// largest_bend(...) <= limit, from the origin's constants; the arcsines are needed only where
// a bound of their difference does not settle it.
bool bends_at_most(const ExactRayOrigin& o, double sin_i, bool rising, double limit) {
    const bool inferior = o.profile.kind == ProfileKind::Inferior;
    double lo = std::min(o.profile.eta0, o.eta_inf);
    const double hi = std::max(o.profile.eta0, o.eta_inf);
    if (inferior == rising) lo = o.eta_p;
    const double beta = o.eta_p * sin_i;
    const double s_max = beta / lo;
    if (!(s_max < 1.0)) return false;
    const double s_min = beta / hi;
    // asin' = 1 / sqrt(1 - x^2) is at least 1 / sqrt(1 - s_min^2) between the two.
    if (s_max - s_min > limit * std::sqrt((1.0 - s_min) * (1.0 + s_min))) return false;
    return std::asin(s_max) - std::asin(s_min) <= limit;
}

// The horizontal reach of the scene's bounded objects from the eye: the farthest corner of
// their boxes, kept per thread for the last scene asked for.
double scene_reach(const SceneAccel& accel, const glm::dvec3& eye) {
    struct Slot {
        bool valid = false;
        std::uint64_t id = 0;
        glm::dvec3 eye{0.0};
        double reach = 0.0;
    };
    thread_local Slot slot;
    if (slot.valid && slot.id == accel.id() && slot.eye == eye) return slot.reach;
    double reach = 0.0;
    for (int i = 0; i < accel.box_count(); ++i) {
        const Aabb& b = accel.item_box(i);
        if (b.empty() || !b.finite()) continue;
        const double dx = std::max(std::abs(b.lo.x - eye.x), std::abs(b.hi.x - eye.x));
        const double dz = std::max(std::abs(b.lo.z - eye.z), std::abs(b.hi.z - eye.z));
        reach = std::max(reach, std::hypot(dx, dz));
    }
    slot = {true, accel.id(), eye, reach};
    return reach;
}

// With no bounded object to follow paths to, they are followed this far (scene units).
constexpr double kMinGeneralReach = 1e4;

double general_max_dz(const CurvedSettings& settings, const SceneAccel* accel,
                      const glm::dvec3& origin) {
    if (settings.max_dz > 0.0) return settings.max_dz;
    const glm::dvec3 eye = settings.eye ? *settings.eye : origin;
    const double reach = accel ? scene_reach(*accel, eye) : 0.0;
    return std::max(2.0 * reach, kMinGeneralReach);
}

}  // namespace

double general_path_reach(const SceneAccel& accel, const glm::dvec3& eye) {
    return std::max(2.0 * scene_reach(accel, eye), kMinGeneralReach);
}

namespace {

// What every ray of the general engine from one height shares: the index's range above and
// below it, its index there and the model's start.  Kept per thread with the model for the last
// two heights asked for (held, so that no other model can take its address): a frame's camera
// rays all start at the eye, and each reflection asks for another.
struct GeneralStart {
    std::optional<Atmosphere> atm;
    double y0 = -1.0;
    double lo_up = 0.0, hi_up = 0.0;      // n over [y0, inf)
    double lo_down = 0.0, hi_down = 0.0;  // n over [0, y0]
    double n = 0.0;
    std::optional<QuadraticStart> start;  // with a piecewise-quadratic model
};

const GeneralStart& general_start(const Atmosphere& atm, double y0) {
    thread_local GeneralStart slots[2];
    thread_local int last = 0;
    const QuadraticProfile* model = atm.quadratic_profile();
    auto matches = [&](const GeneralStart& s) {
        return model && s.atm && s.atm->quadratic_profile() == model && s.y0 == y0;
    };
    for (int k : {last, 1 - last}) {
        if (matches(slots[k])) {
            last = k;
            return slots[k];
        }
    }
    last = 1 - last;  // replace the one used less recently
    GeneralStart& s = slots[last];
    s.atm = atm;
    s.y0 = y0;
    atm.n_range(y0, kInf, s.lo_up, s.hi_up);
    atm.n_range(0.0, y0, s.lo_down, s.hi_down);
    s.n = atm.n(y0);
    s.start.reset();
    if (model) s.start = quadratic_start(*model, y0);
    return s;
}

// Whether a ray of the general engine from the start with sin i = sin_i turns by at most
// `limit` anywhere: from the invariant n(y) sin i(y) = beta over the heights it can reach
// without turning (above the start rising, below it descending); false when it can turn.
bool general_bends_at_most(const GeneralStart& start, double sin_i, bool rising, double limit) {
    const double lo = rising ? start.lo_up : start.lo_down;
    const double hi = rising ? start.hi_up : start.hi_down;
    const double beta = start.n * sin_i;
    const double s_max = beta / lo;
    if (!(s_max < 1.0)) return false;
    const double s_min = beta / hi;
    // asin' = 1 / sqrt(1 - x^2) is at least 1 / sqrt(1 - s_min^2) between the two.
    if (s_max - s_min > limit * std::sqrt((1.0 - s_min) * (1.0 + s_min))) return false;
    return std::asin(s_max) - std::asin(s_min) <= limit;
}

// The general engine's path of a ray (settings.general) into `cp`; false when it goes
// straight (as near_surfaces_path says).  `accel` (may be null) is the scene it is sampled
// for; `reference`: to the tolerance all along (sample_exact_path).
bool general_path(const CurvedSettings& settings, const SceneAccel* accel, const glm::dvec3& origin,
                  const glm::dvec3& direction, double travelled, bool reference, CurvedPath& cp) {
    const Atmosphere& atm = *settings.general;
    if (!atm.has_gradient()) return false;
    if (origin.y < -ground_slack(origin)) return false;
    if (origin.y > kMaxHeight) return false;
    if (origin.y <= 0.0 && direction.y <= 0.0) return false;
    // A direction's components are near 1 or 0 (no overflow to guard against, as hypot does).
    const double hl = std::sqrt(direction.x * direction.x + direction.z * direction.z);
    if (hl < kVerticalSin) return false;
    const double y0 = std::max(origin.y, 0.0);
    const double length = std::sqrt(hl * hl + direction.y * direction.y);
    const double sin_i = hl / length, cos_i = direction.y / length;
    const GeneralStart& start = general_start(atm, y0);
    if (general_bends_at_most(start, sin_i, direction.y > 0.0, 0.5 * settings.tolerance_rad))
        return false;
    std::vector<QuadraticSegment> storage;
    if (cp.general) storage = cp.general->release_storage();
    auto path = start.start ? ExactPath::make_direction(atm, *start.start, cos_i, sin_i)
                            : ExactPath::make_direction(atm, y0, cos_i, sin_i);
    MIRAGE_CHECK(path.ok());
    path->adopt_storage(std::move(storage));
    cp.general.emplace(std::move(*path));
    cp.heading = glm::dvec2(direction.x / hl, direction.z / hl);
    cp.earth_radius = atm.earth_radius();
    SampleSettings ss;
    ss.tolerance_rad = settings.tolerance_rad;
    ss.tolerance_m = settings.tolerance_m;
    ss.start_distance = travelled;
    ss.max_dz = general_max_dz(settings, accel, origin);
    if (reference) {
        cp.path = sample_exact_path(*cp.general, ss);
    } else if (accel && !accel->unbounded_elsewhere()) {
        thread_local std::vector<SceneAccel::Crossing> crossings;
        const EyeIndex* eye =
            settings.eye && origin == *settings.eye ? &eye_index(*accel, origin) : nullptr;
        const SceneObstacles obstacles(*accel, origin, cp.heading, crossings, eye);
        sample_exact_path_near(*cp.general, ss, &obstacles, cp.path);
    } else {
        sample_exact_path_near(*cp.general, ss, nullptr, cp.path);
    }
    return true;
}

// The ray's path for PathSampling::NearSurfaces, into `cp` (its storage reused); false when
// the ray goes straight.  `accel` (may be null) is the scene the path is sampled for.
bool near_surfaces_path(const CurvedSettings& settings, const SceneAccel* accel,
                        const glm::dvec3& origin, const glm::dvec3& direction, double travelled,
                        CurvedPath& cp) {
    if (settings.general)
        return general_path(settings, accel, origin, direction, travelled, false, cp);
    cp.general.reset();
    cp.earth_radius = 0.0;
    const Profile& p = settings.profile;
    if (p.kind == ProfileKind::None || p.eta1 == 0.0) return false;
    // Below the ground the atmosphere is not defined: the band model's bottom layer has the
    // ground's index throughout, so such rays go straight there too.
    if (origin.y < -ground_slack(origin)) return false;
    // So far above the ground (beyond any scene mirage follows) the index is flat to far
    // below a double's precision: straight.
    if (origin.y > kMaxHeight) return false;
    if (origin.y <= 0.0 && direction.y <= 0.0) return false;
    const double hl = std::sqrt(direction.x * direction.x + direction.z * direction.z);
    if (hl < kVerticalSin) return false;
    double cos_i = direction.y, sin_i = hl;
    const double n2 = hl * hl + direction.y * direction.y;
    if (std::abs(n2 - 1.0) > 1e-15) {  // not quite a unit direction
        const double n = std::sqrt(n2);
        cos_i /= n;
        sin_i /= n;
    }
    const ExactRayOrigin& o = ray_origin(p, std::max(origin.y, 0.0));
    if (bends_at_most(o, sin_i, direction.y > 0.0, 0.5 * settings.tolerance_rad)) return false;
    make_exact_ray(o, cos_i, sin_i, cp.ray);
    cp.heading = glm::dvec2(direction.x / hl, direction.z / hl);
    SampleSettings ss;
    ss.tolerance_rad = settings.tolerance_rad;
    ss.tolerance_m = settings.tolerance_m;
    ss.start_distance = travelled;
    if (accel && !accel->unbounded_elsewhere()) {
        thread_local std::vector<SceneAccel::Crossing> crossings;
        const EyeIndex* eye =
            settings.eye && origin == *settings.eye ? &eye_index(*accel, origin) : nullptr;
        const SceneObstacles obstacles(*accel, origin, cp.heading, crossings, eye);
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
    ss.tolerance_m = settings.tolerance_m;
    ss.start_distance = travelled;
    CurvedPath cp;
    cp.ray = *ray;
    cp.path = sample_path(cp.ray, ss);
    cp.heading = glm::dvec2(direction.x / hl, direction.z / hl);
    return cp;
}

// A ray's walk through the turbulent air's screens (CurvedSettings::turbulence), in scene
// units (the screens are in metres).
class Shimmer {
  public:
    Shimmer(const CurvedSettings& s, const glm::dvec3& start)
        : unit_(s.unit_m), walk_(*s.turbulence, s.turbulence_time_s, start * s.unit_m) {}

    /// Marches on to the image of the path's point `to`: the kinks on the way, then it.  True
    /// on a hit.
    bool to(PolylineMarch& march, const glm::dvec3& to) {
        walk_.to(to * unit_, points());
        for (const glm::dvec3& p : points())
            if (march.segment_to(p / unit_)) return true;
        return false;
    }
    /// The last straight ray along unit d: the kinks ahead, then the ray turned by them all.
    bool ray(PolylineMarch& march, const glm::dvec3& d) {
        walk_.ray(d, points());
        for (const glm::dvec3& p : points())
            if (march.segment_to(p / unit_)) return true;
        return march.ray(walk_.direction(d));
    }
    glm::dvec3 direction(const glm::dvec3& d) const { return walk_.direction(d); }
    /// The image of the path's point `to` without marching (for plots).
    void to(const glm::dvec3& to, std::vector<glm::dvec3>& out) {
        walk_.to(to * unit_, points());
        for (const glm::dvec3& p : points()) out.push_back(p / unit_);
    }
    void ray(const glm::dvec3& d, std::vector<glm::dvec3>& out) {
        walk_.ray(d, points());
        for (const glm::dvec3& p : points()) out.push_back(p / unit_);
    }

  private:
    static std::vector<glm::dvec3>& points() {
        thread_local std::vector<glm::dvec3> p;
        return p;
    }
    double unit_;
    ScreenWalk walk_;
};

// The final direction of a sampled path and the sky's direction when it escapes (on the
// curved Earth, turned from the local horizontal where that slope holds to the start's).
struct PathEndDirections {
    glm::dvec3 final_direction;
    std::optional<glm::dvec3> sky;
};

PathEndDirections end_directions(const glm::dvec2& heading, const CurvedPath& cp) {
    double slope = cp.path.end_slope;
    if (cp.path.end == PathEnd::Ground) {
        slope = cp.general ? cp.general->slope_at(cp.general->dz_ground())
                           : slope_at(cp.ray, cp.ray.dz_ground);
    }
    MIRAGE_CHECK(std::isfinite(slope));
    PathEndDirections out;
    out.final_direction = glm::normalize(glm::dvec3(heading.x, slope, heading.y));
    if (cp.earth_radius > 0.0 && cp.path.end != PathEnd::Ground) {
        // The slope is the path's in the flattened frame, against the local horizontal at
        // end_slope_dz; the sky is seen from the start, whose horizontal is tilted from that
        // by end_slope_dz / R.
        double e = std::atan(slope) - cp.path.end_slope_dz / cp.earth_radius;
        // A model of the whole atmosphere: the sky where the ray leaves its top (sky_exit.h).
        if (cp.general)
            if (auto exit = sky_exit(*cp.general)) e = exit->elevation - exit->dz / cp.earth_radius;
        out.sky = glm::dvec3(std::cos(e) * heading.x, std::sin(e), std::cos(e) * heading.y);
    }
    return out;
}

// Marches `cp` from `origin` on from the march's current point (which is `origin`), through
// the screens of `shimmer` when given.
PathHit march_from(PolylineMarch& march, const glm::dvec3& origin, const glm::dvec2& heading,
                   const CurvedPath& cp, Shimmer* shimmer = nullptr) {
    const auto& points = cp.path.points;
    const auto& clear = cp.path.clear_length;
    auto world = [&](const glm::dvec2& p) {
        return glm::dvec3(origin.x + p.x * heading.x, p.y, origin.z + p.x * heading.y);
    };
    // The first sample is the start itself.
    for (std::size_t k = 1; k < points.size(); ++k) {
        if (shimmer) {
            // A stretch known clear of the scene is tested all the same: the perturbed path
            // is not the one the sampler cleared.
            if (shimmer->to(march, world(points[k]))) return march.result();
        } else if (k <= clear.size() && clear[k - 1] > 0.0) {
            march.skip_to(world(points[k]), clear[k - 1]);
        } else if (march.segment_to(world(points[k]))) {
            return march.result();
        }
    }
    const PathEndDirections end = end_directions(heading, cp);
    if (shimmer) {
        shimmer->ray(march, end.final_direction);
    } else if (cp.path.end_clear) {
        march.skip_ray(end.final_direction);
    } else {
        march.ray(end.final_direction);
    }
    PathHit result = march.result();
    if (!result.hit && end.sky) {
        result.direction = shimmer ? shimmer->direction(*end.sky) : *end.sky;
    }
    return result;
}

PathHit march(const SceneAccel& accel, const glm::dvec3& origin, const glm::dvec2& heading,
              const CurvedPath& cp, const CurvedSettings& settings) {
    PolylineMarch march(accel, origin);
    if (settings.turbulence) {
        Shimmer shimmer(settings, origin);
        return march_from(march, origin, heading, cp, &shimmer);
    }
    return march_from(march, origin, heading, cp);
}

// A straight ray, walked through the screens when the settings have them.
PathHit march_straight(const SceneAccel& accel, const RayStart& start,
                       const CurvedSettings& settings, const StraightPropagator& straight) {
    if (!settings.turbulence) return straight.propagate(accel, start);
    PolylineMarch march(accel, start.origin);
    Shimmer shimmer(settings, start.origin);
    shimmer.ray(march, start.direction);
    return march.result();
}

// Whether a ray goes straight, for the reference sampling (curved_path).
bool goes_straight(const CurvedSettings& settings, const glm::dvec3& origin,
                   const glm::dvec3& direction) {
    if (settings.profile.kind == ProfileKind::None || settings.profile.eta1 == 0.0) return true;
    // Below the ground the atmosphere is not defined: the band model's bottom layer has the
    // ground's index throughout, so such rays go straight there too.
    if (origin.y < -ground_slack(origin)) return true;
    // So far above the ground (beyond any scene mirage follows) the index is flat to far
    // below a double's precision: straight.
    if (origin.y > kMaxHeight) return true;
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
    if (settings.general) {
        CurvedPath cp;
        if (!general_path(settings, nullptr, origin, direction, travelled,
                          settings.sampling == PathSampling::Reference, cp))
            return std::nullopt;
        return cp;
    }
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
    CurvedPath cp;
    if (settings.general) {
        if (!general_path(settings, &accel, origin, direction, travelled,
                          settings.sampling == PathSampling::Reference, cp))
            return std::nullopt;
        return cp;
    }
    if (settings.sampling == PathSampling::Reference) {
        return curved_path(settings, origin, direction, travelled);
    }
    if (!near_surfaces_path(settings, &accel, origin, direction, travelled, cp))
        return std::nullopt;
    return cp;
}

PathHit march_curved_path(const SceneAccel& accel, const glm::dvec3& origin, const CurvedPath& cp,
                          const CurvedSettings& settings) {
    return march(accel, origin, cp.heading, cp, settings);
}

std::vector<glm::dvec3> followed_points(const CurvedSettings& settings, const glm::dvec3& origin,
                                        const glm::dvec3& direction, double tail) {
    std::vector<glm::dvec3> out{origin};
    const std::optional<CurvedPath> cp = curved_path(settings, origin, direction, 0.0);
    std::optional<Shimmer> shimmer;
    if (settings.turbulence) shimmer.emplace(settings, origin);
    glm::dvec3 last = direction;
    if (cp) {
        auto world = [&](const glm::dvec2& p) {
            return glm::dvec3(origin.x + p.x * cp->heading.x, p.y, origin.z + p.x * cp->heading.y);
        };
        for (std::size_t k = 1; k < cp->path.points.size(); ++k) {
            if (shimmer) {
                shimmer->to(world(cp->path.points[k]), out);
            } else {
                out.push_back(world(cp->path.points[k]));
            }
        }
        last = end_directions(cp->heading, *cp).final_direction;
    }
    if (shimmer) {
        shimmer->ray(last, out);
        last = shimmer->direction(last);
    }
    out.push_back(out.back() + tail * last);
    return out;
}

double bounded_reach(const SceneAccel& accel, const glm::dvec3& eye) {
    return scene_reach(accel, eye);
}

CurvedPropagator::CurvedPropagator(const CurvedSettings& settings) : settings_(settings) {
    MIRAGE_CHECK((settings.profile.kind == ProfileKind::None && !settings.general) ||
                 settings.tolerance_rad > 0.0 || settings.tolerance_m > 0.0);
}

PathHit CurvedPropagator::propagate(const SceneAccel& accel, const RayStart& start) const {
    if (start.origin.y < -ground_slack(start.origin) && start.direction.y > 0.0) {
        // Below the ground the index is the ground's throughout (the band model's bottom
        // layer): straight up to the ground, then along the exact path from there.
        const double t = -start.origin.y / start.direction.y;
        glm::dvec3 at_ground = start.origin + t * start.direction;
        at_ground.y = 0.0;
        PolylineMarch march(accel, start.origin);
        std::optional<Shimmer> shimmer;
        if (settings_.turbulence) shimmer.emplace(settings_, start.origin);
        if (shimmer ? shimmer->to(march, at_ground) : march.segment_to(at_ground))
            return march.result();
        RayStart rest = start;
        rest.origin = at_ground;
        rest.travelled = start.travelled + march.path_length();
        const std::optional<CurvedPath> cp =
            curved_path(settings_, accel, rest.origin, rest.direction, rest.travelled);
        if (!cp) {
            if (shimmer) {
                shimmer->ray(march, start.direction);
            } else {
                march.ray(start.direction);
            }
            return march.result();
        }
        return march_from(march, rest.origin, cp->heading, *cp, shimmer ? &*shimmer : nullptr);
    }
    if (settings_.sampling == PathSampling::Reference) {
        const auto cp =
            settings_.general
                ? curved_path(settings_, accel, start.origin, start.direction, start.travelled)
                : curved_path(settings_, start.origin, start.direction, start.travelled);
        if (!cp) return march_straight(accel, start, settings_, straight_);
        return march_curved_path(accel, start.origin, *cp, settings_);
    }
    // One path per thread, its storage reused from ray to ray.
    thread_local CurvedPath cp;
    if (!near_surfaces_path(settings_, &accel, start.origin, start.direction, start.travelled,
                            cp)) {
        return march_straight(accel, start, settings_, straight_);
    }
    return march_curved_path(accel, start.origin, cp, settings_);
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
        return make_error(place_prefix(camera.loc) +
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
    const CurvedSettings& settings = per_ray_.settings();
    if (r.path) return march(accel, start.origin, heading, *r.path, settings);
    if (d.y / hl == r.slope) return march_straight(accel, start, settings, straight_);
    RayStart turned = start;
    turned.direction = glm::normalize(glm::dvec3(heading.x, r.slope, heading.y));
    return march_straight(accel, turned, settings, straight_);
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
