#include "trace/curved_propagator.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "atmosphere/sky_exit.h"
#include "scene/camera.h"
#include "trace/stretch_march.h"
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

// What rays from height y0 share, kept per thread for the last two heights asked for (each
// with its atmosphere, so that no other model can take its address): a frame's camera rays
// all start at the eye, and each reflection asks for another.
const PathOrigin& path_origin(const Atmosphere& atmosphere, double y0) {
    thread_local std::optional<PathOrigin> slots[2];
    thread_local int last = 0;
    auto matches = [&](const std::optional<PathOrigin>& s) {
        return s && s->y0() == y0 && s->atmosphere() == atmosphere;
    };
    for (int k : {last, 1 - last}) {
        if (matches(slots[k])) {
            last = k;
            return *slots[k];
        }
    }
    auto o = PathOrigin::make(atmosphere, y0);
    MIRAGE_CHECK(o.ok());
    last = 1 - last;  // replace the one used less recently
    slots[last] = std::move(*o);
    return *slots[last];
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

// How far a path from `origin` is followed (CurvedSettings::max_dz).
double path_max_dz(const CurvedSettings& settings, const SceneAccel* accel,
                   const glm::dvec3& origin) {
    if (settings.atmosphere.closed_form()) return kInf;
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

// The ray's exact path and its samples into `cp` (its storage reused); false when the ray
// goes straight: no index gradient, a start below the ground (y < 0, or on it heading down)
// or far above it, a (nearly) vertical ray, or one that cannot turn by more than half the
// tolerance.  `accel` (may be null) is the scene the path is sampled for.
bool exact_path(const CurvedSettings& settings, const SceneAccel* accel, const glm::dvec3& origin,
                const glm::dvec3& direction, double travelled, CurvedPath& cp) {
    const Atmosphere& atm = settings.atmosphere;
    if (!atm.has_gradient()) return false;
    // Below the ground the atmosphere is not defined: the band model's bottom layer has the
    // ground's index throughout, so such rays go straight there too.
    if (origin.y < -ground_slack(origin)) return false;
    // So far above the ground (beyond any scene mirage follows) the index is flat to far
    // below a double's precision: straight.
    if (origin.y > kMaxHeight) return false;
    if (origin.y <= 0.0 && direction.y <= 0.0) return false;
    // A direction's components are near 1 or 0 (no overflow to guard against, as hypot does).
    const double hl = std::sqrt(direction.x * direction.x + direction.z * direction.z);
    if (hl < kVerticalSin) return false;
    double cos_i = direction.y, sin_i = hl;
    const double n2 = hl * hl + direction.y * direction.y;
    if (std::abs(n2 - 1.0) > 1e-15) {  // not quite a unit direction
        const double n = std::sqrt(n2);
        cos_i /= n;
        sin_i /= n;
    }
    const PathOrigin& start = path_origin(atm, std::max(origin.y, 0.0));
    if (start.bends_at_most(sin_i, direction.y > 0.0, 0.5 * settings.tolerance_rad)) return false;
    start.path(cos_i, sin_i, cp.exact);
    cp.heading = glm::dvec2(direction.x / hl, direction.z / hl);
    cp.earth_radius = atm.earth_radius();
    SampleSettings ss;
    ss.tolerance_rad = settings.tolerance_rad;
    ss.tolerance_m = settings.tolerance_m;
    ss.start_distance = travelled;
    ss.max_dz = path_max_dz(settings, accel, origin);
    if (settings.sampling == PathSampling::Reference) {
        cp.path = sample_path(*cp.exact, ss);
    } else if (accel && !accel->unbounded_elsewhere()) {
        thread_local std::vector<SceneAccel::Crossing> crossings;
        const EyeIndex* eye =
            settings.eye && origin == *settings.eye ? &eye_index(*accel, origin) : nullptr;
        const SceneObstacles obstacles(*accel, origin, cp.heading, crossings, eye);
        sample_path_near(*cp.exact, ss, &obstacles, cp.path);
    } else {
        sample_path_near(*cp.exact, ss, nullptr, cp.path);
    }
    return true;
}

// A ray's walk through the turbulent air's screens (CurvedSettings::turbulence), in scene
// units (the screens are in metres).
class Shimmer {
  public:
    Shimmer(const CurvedSettings& s, const glm::dvec3& start)
        : unit_(s.unit_m), walk_(*s.turbulence, s.turbulence_time_s, start * s.unit_m) {}

    /// Marches on to the image of the path's point `to`: the kinks on the way, then it,
    /// queried only where they can meet something (march_stretch).  True on a hit.
    bool to(PolylineMarch& march, const SceneAccel& accel, const glm::dvec3& to) {
        walk_.to(to * unit_, points());
        return march_stretch(march, accel, in_scene_units());
    }
    /// The last straight ray along unit d: the kinks ahead, then the ray turned by them all.
    bool ray(PolylineMarch& march, const SceneAccel& accel, const glm::dvec3& d) {
        walk_.ray(d, points());
        if (march_stretch(march, accel, in_scene_units())) return true;
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
    // points() in scene units.
    const std::vector<glm::dvec3>& in_scene_units() const {
        thread_local std::vector<glm::dvec3> p;
        p.clear();
        for (const glm::dvec3& q : points()) p.push_back(q / unit_);
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
        slope = cp.exact->slope_at(cp.exact->dz_ground());
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
        if (auto exit = sky_exit(*cp.exact)) e = exit->elevation - exit->dz / cp.earth_radius;
        out.sky = glm::dvec3(std::cos(e) * heading.x, std::sin(e), std::cos(e) * heading.y);
    }
    return out;
}

// Marches `cp` from `origin` on from the march's current point (which is `origin`), through
// the screens of `shimmer` when given.
PathHit march_from(PolylineMarch& march, const SceneAccel& accel, const glm::dvec3& origin,
                   const glm::dvec2& heading, const CurvedPath& cp, Shimmer* shimmer = nullptr) {
    const auto& points = cp.path.points;
    const auto& clear = cp.path.clear_length;
    auto world = [&](const glm::dvec2& p) {
        return glm::dvec3(origin.x + p.x * heading.x, p.y, origin.z + p.x * heading.y);
    };
    // The first sample is the start itself.
    for (std::size_t k = 1; k < points.size(); ++k) {
        if (shimmer) {
            // The sampler's clear stretches are not the perturbed path's: each stretch is
            // tested as walked, untested where it passes far from everything.
            if (shimmer->to(march, accel, world(points[k]))) return march.result();
        } else if (k <= clear.size() && clear[k - 1] > 0.0) {
            march.skip_to(world(points[k]), clear[k - 1]);
        } else if (march.segment_to(world(points[k]))) {
            return march.result();
        }
    }
    const PathEndDirections end = end_directions(heading, cp);
    if (shimmer) {
        shimmer->ray(march, accel, end.final_direction);
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
        return march_from(march, accel, origin, heading, cp, &shimmer);
    }
    return march_from(march, accel, origin, heading, cp);
}

// A straight ray, walked through the screens when the settings have them.
PathHit march_straight(const SceneAccel& accel, const RayStart& start,
                       const CurvedSettings& settings, const StraightPropagator& straight) {
    if (!settings.turbulence) return straight.propagate(accel, start);
    PolylineMarch march(accel, start.origin);
    Shimmer shimmer(settings, start.origin);
    shimmer.ray(march, accel, start.direction);
    return march.result();
}

}  // namespace

std::optional<CurvedPath> curved_path(const CurvedSettings& settings, const glm::dvec3& origin,
                                      const glm::dvec3& direction, double travelled) {
    CurvedPath cp;
    if (!exact_path(settings, nullptr, origin, direction, travelled, cp)) return std::nullopt;
    return cp;
}

std::optional<CurvedPath> curved_path(const CurvedSettings& settings, const SceneAccel& accel,
                                      const glm::dvec3& origin, const glm::dvec3& direction,
                                      double travelled) {
    CurvedPath cp;
    if (!exact_path(settings, &accel, origin, direction, travelled, cp)) return std::nullopt;
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
    MIRAGE_CHECK(!settings.atmosphere.has_gradient() || settings.tolerance_rad > 0.0 ||
                 settings.tolerance_m > 0.0);
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
        if (shimmer ? shimmer->to(march, accel, at_ground) : march.segment_to(at_ground))
            return march.result();
        RayStart rest = start;
        rest.origin = at_ground;
        rest.travelled = start.travelled + march.path_length();
        const std::optional<CurvedPath> cp =
            curved_path(settings_, accel, rest.origin, rest.direction, rest.travelled);
        if (!cp) {
            if (shimmer) {
                shimmer->ray(march, accel, start.direction);
            } else {
                march.ray(start.direction);
            }
            return march.result();
        }
        return march_from(march, accel, rest.origin, cp->heading, *cp,
                          shimmer ? &*shimmer : nullptr);
    }
    // One path per thread, its storage reused from ray to ray.
    thread_local CurvedPath cp;
    if (!exact_path(settings_, &accel, start.origin, start.direction, start.travelled, cp))
        return march_straight(accel, start, settings_, straight_);
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
