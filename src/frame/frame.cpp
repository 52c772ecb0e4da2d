#include "frame/frame.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "atmosphere/general_profile.h"
#include "atmosphere/vanishing.h"
#include "load/mirage_scene.h"
#include "scene/camera.h"
#include "scene/ground.h"
#include "trace/scene_accel.h"
#include "shapes/shape_intersect.h"
#include "trace_scene/trace_scene.h"
#include "util/check.h"
#include "util/format.h"

namespace mirage {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kSteepest = 0.5 * kPi - 1e-6;  // elevations are kept within this

// The reach a frame is read to when the scene does not bound it: as compile_settings does.
constexpr double kReachMargin = 1.25;
constexpr double kUnboundedReachEyeHeights = 1e4;

// The lowest and highest of the elevations where `holds` is true, each edge bisected between
// the sample where it holds and its neighbour where it does not.  `samples` sorted upwards.
bool span_where(const std::function<bool(double)>& holds, const std::vector<double>& samples,
                double& low, double& high) {
    int first = -1, last = -1;
    for (int k = 0; k < static_cast<int>(samples.size()); ++k) {
        if (!holds(samples[k])) continue;
        if (first < 0) first = k;
        last = k;
    }
    if (first < 0) return false;
    auto edge = [&](double in, double out) {
        for (int i = 0; i < 50; ++i) {
            const double m = 0.5 * (in + out);
            (holds(m) ? in : out) = m;
        }
        return in;
    };
    low = first > 0 ? edge(samples[first], samples[first - 1]) : samples[first];
    high = last + 1 < static_cast<int>(samples.size()) ? edge(samples[last], samples[last + 1])
                                                       : samples[last];
    return true;
}

// The boundary between elevations of fate `below` (at lo) and another fate (at hi).
double fate_edge(const Atmosphere& atm, double y0, double lo, double hi, RayFate below) {
    for (int i = 0; i < 80; ++i) {
        const double m = 0.5 * (lo + hi);
        (ray_outcome(atm, y0, m).fate == below ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

// The grazing ray's elevation: the highest that meets the ground, when the ray just below the
// horizontal turns low (NaN otherwise).
double grazing_elevation(const Atmosphere& atm, double y0) {
    if (ray_outcome(atm, y0, -1e-12).fate != RayFate::TurnsLow) return kNaN;
    if (ray_outcome(atm, y0, -kSteepest).fate != RayFate::Ground) return kNaN;
    return fate_edge(atm, y0, -kSteepest, -1e-12, RayFate::Ground);
}

// The highest ray that still comes down from an apex, when the ray just above the horizontal
// does (NaN otherwise).
double apex_limit(const Atmosphere& atm, double y0) {
    if (ray_outcome(atm, y0, 1e-12).fate != RayFate::TurnsHigh) return kNaN;
    if (ray_outcome(atm, y0, kSteepest).fate == RayFate::TurnsHigh) return kSteepest;
    return fate_edge(atm, y0, 1e-12, kSteepest, RayFate::TurnsHigh);
}

void add_row(RowSpan& span, int row) {
    if (span.count == 0) span.first = row;
    span.last = row;
    ++span.count;
}

// The image position of direction v from the eye (perspective camera):
// v s = direction + a right + b up, x = (a + 1/2) width, y = (1/2 - b) height.
bool project(const FrameView& view, const glm::dvec3& v, double& x, double& y) {
    const Camera& c = view.camera;
    const glm::dmat3 m(v, -c.right, -c.up);
    if (std::abs(glm::determinant(m)) < 1e-300) return false;
    const glm::dvec3 sab = glm::inverse(m) * c.direction;
    if (!(sab.x > 0.0)) return false;
    x = (sab.y + 0.5) * view.width;
    y = (0.5 - sab.z) * view.height;
    return std::isfinite(x) && std::isfinite(y);
}

// An object's section in the vertical plane through the eye and its centre.
struct Section {
    glm::dvec2 heading{0.0};  // unit, horizontal (x, z)
    double distance = 0.0;    // to the box's centre
    double dz_lo = 0.0, dz_hi = 0.0;
    double y_lo = 0.0, y_hi = 0.0;
    bool ok = false;
};

Section section_of(const FrameView& view, const FrameObject& o, double shift = 0.0) {
    Section s;
    const glm::dvec3& eye = view.camera.location;
    const glm::dvec3 c = 0.5 * (o.lo + o.hi);
    const glm::dvec2 to(c.x - eye.x, c.z - eye.z);
    s.distance = glm::length(to);
    if (!(s.distance > 0.0)) return s;
    s.heading = to / s.distance;
    const glm::dvec2 move = shift * s.heading;
    const glm::dvec2 lo(o.lo.x + move.x, o.lo.z + move.y), hi(o.hi.x + move.x, o.hi.z + move.y);
    double t0 = 0.0, t1 = kInf;
    const glm::dvec2 from(eye.x, eye.z);
    for (int a = 0; a < 2; ++a) {
        if (s.heading[a] == 0.0) {
            if (from[a] < lo[a] || from[a] > hi[a]) return s;
            continue;
        }
        double ta = (lo[a] - from[a]) / s.heading[a], tb = (hi[a] - from[a]) / s.heading[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t1 > t0)) return s;
    s.distance += shift;
    s.dz_lo = t0;
    s.dz_hi = t1;
    s.y_lo = o.lo.y;
    s.y_hi = o.hi.y;
    s.ok = true;
    return s;
}

// Where the ray at elevation e first meets the section: -1 none, 0 before any lowest turning
// point, 1 after one.
int first_hit(const Atmosphere& atm, double y0, const Section& s, double e) {
    auto p = ExactPath::make(atm, y0, 0.5 * kPi - e);
    if (!p) return -1;
    const double ground = p->hits_ground() ? p->dz_ground() : kInf;
    if (ground < s.dz_lo) return -1;
    double turn = kInf;
    if (p->turning_point_count() != 0) {
        const TurningPoint tp = p->turning_point(0);
        if (tp.lowest) turn = tp.dz;
    }
    constexpr int kSteps = 200;
    for (int k = 0; k <= kSteps; ++k) {
        const double dz = s.dz_lo + (s.dz_hi - s.dz_lo) * k / kSteps;
        if (dz > ground) return -1;
        const double y = p->height_at(dz);
        if (y >= s.y_lo && y <= s.y_hi) return dz > turn ? 1 : 0;
    }
    return -1;
}

ImageSpan image_span(const Atmosphere& atm, const FrameView& view, const Section& s, bool mirrored,
                     double grazing) {
    ImageSpan out;
    if (!s.ok) return out;
    const double y0 = view.eye_y;
    std::vector<double> samples;
    if (mirrored) {
        if (!std::isfinite(grazing)) return out;
        // Between the grazing ray and the horizontal, packed towards the grazing one, where the
        // images of low points lie.
        constexpr int kRays = 1500;
        for (int k = 1; k < kRays; ++k) {
            const double u = double(k) / kRays;
            samples.push_back(grazing * (1.0 - u * u));
        }
    } else {
        double a = std::atan2(s.y_lo - y0, s.dz_hi), b = std::atan2(s.y_hi - y0, s.dz_lo);
        const double bend = std::isfinite(grazing) ? 2.0 * std::abs(grazing) : 0.0;
        const double margin = 0.1 * (b - a) + bend + 1e-4;
        a = std::max(a - margin, -kSteepest);
        b = std::min(b + margin, kSteepest);
        constexpr int kRays = 600;
        for (int k = 0; k <= kRays; ++k) samples.push_back(a + (b - a) * k / kRays);
    }
    const int want = mirrored ? 1 : 0;
    auto holds = [&](double e) { return first_hit(atm, y0, s, e) == want; };
    double lo, hi;
    if (!span_where(holds, samples, lo, hi)) return out;
    out.visible = true;
    out.elevation_low_rad = lo;
    out.elevation_high_rad = hi;
    auto dir = [&](double e) {
        return glm::dvec3(s.heading.x * std::cos(e), std::sin(e), s.heading.y * std::cos(e));
    };
    double x, y;
    if (project(view, dir(hi), x, y)) out.row_top = y;
    if (project(view, dir(lo), x, y)) out.row_bottom = y;
    if (project(view, dir(0.5 * (lo + hi)), x, y)) out.column = x;
    return out;
}

std::string csg_name(const CompoundObject& c) {
    if (c.nodes.empty()) return "object";
    switch (c.nodes[c.root].kind) {
        case CsgKind::Union:
            return "union";
        case CsgKind::Merge:
            return "merge";
        case CsgKind::Intersection:
            return "intersection";
        default:
            return "object";
    }
}

}  // namespace

RayOutcome ray_outcome(const Atmosphere& atmosphere, double y0, double elevation_rad) {
    const double e = std::clamp(elevation_rad, -kSteepest, kSteepest);
    auto p = ExactPath::make(atmosphere, y0, 0.5 * kPi - e);
    MIRAGE_CHECK(static_cast<bool>(p));
    const double ground = p->hits_ground() ? p->dz_ground() : kInf;
    if (p->turning_point_count() != 0) {
        const TurningPoint tp = p->turning_point(0);
        if (tp.dz < ground) return {tp.lowest ? RayFate::TurnsLow : RayFate::TurnsHigh, tp.dz};
    }
    if (std::isfinite(ground)) return {RayFate::Ground, ground};
    return {RayFate::Escapes, kInf};
}

double row_elevation(const FrameView& view, double y) {
    const glm::dvec3 d =
        camera_ray(view.camera, 0.5 * view.width, y, view.width, view.height).direction;
    return std::asin(std::clamp(d.y, -1.0, 1.0));
}

double elevation_row(const FrameView& view, double elevation_rad) {
    double lo = -8.0 * view.height, hi = 9.0 * view.height;
    // Elevation falls with the row for an upright camera; the other way for one upside down.
    const bool falls = row_elevation(view, lo) > row_elevation(view, hi);
    for (int i = 0; i < 100; ++i) {
        const double m = 0.5 * (lo + hi);
        ((row_elevation(view, m) > elevation_rad) == falls ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

ColumnReading read_column(const Atmosphere& atmosphere, const FrameView& view) {
    ColumnReading c;
    for (int r = 0; r < view.height; ++r) {
        const RayOutcome o = ray_outcome(atmosphere, view.eye_y, row_elevation(view, r + 0.5));
        c.rows.push_back(o);
        if (o.fate == RayFate::TurnsLow) {
            add_row(c.turning_low, r);
            if (o.dz <= view.reach) add_row(c.turning_low_in_reach, r);
        } else if (o.fate == RayFate::TurnsHigh) {
            add_row(c.turning_high, r);
            if (o.dz <= view.reach) add_row(c.turning_high_in_reach, r);
        }
    }
    return c;
}

Result<std::vector<FrameObject>> frame_objects(const Scene& scene) {
    auto accel = SceneAccel::build(scene);
    if (!accel) return accel.error();
    std::vector<FrameObject> out;
    std::vector<Aabb> compound_box(scene.compounds.size());
    std::vector<int> compound_first(scene.compounds.size(), -1);
    std::vector<bool> compound_unbounded(scene.compounds.size(), false);
    for (int i = 0; i < static_cast<int>(scene.primitives.size()); ++i) {
        const Primitive& p = scene.primitives[i];
        const Aabb box = shape_bounds(accel->shape(i));
        if (p.compound >= 0) {
            if (compound_first[p.compound] < 0) compound_first[p.compound] = i;
            if (!box.empty() && !box.finite()) compound_unbounded[p.compound] = true;
            if (!box.empty()) compound_box[p.compound].extend(box);
            continue;
        }
        if (box.empty() || !box.finite()) continue;
        FrameObject o;
        o.loc = p.loc;
        o.kind = shape_keyword(p.shape);
        o.lo = box.lo;
        o.hi = box.hi;
        o.name = o.kind + " at " + to_string(p.loc);
        out.push_back(o);
    }
    for (size_t c = 0; c < scene.compounds.size(); ++c) {
        const Aabb& box = compound_box[c];
        if (compound_first[c] < 0 || compound_unbounded[c] || box.empty() || !box.finite())
            continue;
        FrameObject o;
        o.loc = scene.primitives[compound_first[c]].loc;
        o.kind = csg_name(scene.compounds[c]);
        o.lo = box.lo;
        o.hi = box.hi;
        o.name = o.kind + " (its first part at " + to_string(o.loc) + ")";
        out.push_back(o);
    }
    return out;
}

ObjectReading read_object(const Atmosphere& atmosphere, const FrameView& view,
                          const FrameObject& object) {
    ObjectReading r;
    r.object = object;
    const Section s = section_of(view, object);
    r.distance = s.distance;
    r.top = object.hi.y;
    {
        double x, y;
        const glm::dvec3 c = 0.5 * (object.lo + object.hi) - view.camera.location;
        if (project(view, c, x, y)) r.column = x;
    }
    const double grazing = grazing_elevation(atmosphere, view.eye_y);
    r.direct = image_span(atmosphere, view, s, false, grazing);
    r.mirrored = image_span(atmosphere, view, s, true, grazing);
    r.vanishing = r.farthest = kNaN;
    if (!(r.top > 0.0)) {
        r.vanishing_note = "it lies below the ground";
        return r;
    }
    auto reach = mirror_reach(atmosphere, view.eye_y, r.top);
    if (!reach) {
        r.vanishing_note = reach.message();
        return r;
    }
    r.vanishing = reach->nearest;
    r.farthest = reach->farthest;
    // Where its top is seen directly from the vanishing distance: the ray that reaches the top's
    // height there before any turn, by bisection about the straight line's elevation.
    if (s.ok) {
        const double y0 = view.eye_y;
        const double straight = std::atan2(r.top - y0, r.vanishing);
        const double spread = (std::isfinite(grazing) ? 2.0 * std::abs(grazing) : 0.0) + 1e-3;
        double lo = std::max(straight - spread, -kSteepest),
               hi = std::min(straight + spread, kSteepest);
        auto above = [&](double e) {
            auto p = ExactPath::make(atmosphere, y0, 0.5 * kPi - e);
            if (!p || (p->hits_ground() && p->dz_ground() < r.vanishing)) return false;
            return p->height_at(r.vanishing) >= r.top;
        };
        if (!above(lo) && above(hi)) {
            for (int i = 0; i < 60; ++i) {
                const double m = 0.5 * (lo + hi);
                (above(m) ? hi : lo) = m;
            }
            const double e = 0.5 * (lo + hi);
            const glm::dvec3 v(s.heading.x * std::cos(e), std::sin(e), s.heading.y * std::cos(e));
            double x, y;
            if (project(view, v, x, y)) r.vanishing_row = y;
        }
    }
    return r;
}

ImageSpan mirrored_image_at(const Atmosphere& atmosphere, const FrameView& view,
                            const FrameObject& object, double distance) {
    const Section now = section_of(view, object);
    if (!now.ok) return {};
    const Section s = section_of(view, object, distance - now.distance);
    return image_span(atmosphere, view, s, true, grazing_elevation(atmosphere, view.eye_y));
}

double camera_angle_deg(const Camera& camera) {
    return 2.0 * std::atan(0.5 * glm::length(camera.right) / glm::length(camera.direction)) *
           180.0 / kPi;
}

Camera with_angle(const Camera& camera, double angle_deg) {
    Camera c = camera;
    // POV-Ray's `angle`: direction's length |right| / (2 tan(angle / 2)).
    c.direction = glm::normalize(camera.direction) *
                  (0.5 * glm::length(camera.right) / std::tan(0.5 * angle_deg * kPi / 180.0));
    return c;
}

namespace {

// The frame read in one atmosphere: apparent horizon, column, objects.
void read_frame(const Atmosphere& atm, FrameReading& f) {
    const double y0 = f.view.eye_y;
    f.true_horizon_row = elevation_row(f.view, 0.0);
    f.apparent_horizon_rad = grazing_elevation(atm, y0);
    f.inferior = std::isfinite(f.apparent_horizon_rad);
    f.apex_limit_rad = apex_limit(atm, y0);
    f.superior = std::isfinite(f.apex_limit_rad);
    f.ground_ends = kNaN;
    f.band_top_in_reach_rad = kNaN;
    if (f.inferior) {
        f.apparent_horizon_row = elevation_row(f.view, f.apparent_horizon_rad);
        f.ground_ends = turn_to_height_distance(atm, 0.0, y0);
    }
    f.column = read_column(atm, f.view);
    if (f.inferior && f.column.turning_low_in_reach.count > 0) {
        // The highest ray that turns within the reach: between the band's top row in reach and
        // the row above it.
        const int top = f.column.turning_low_in_reach.first;
        double in = row_elevation(f.view, top + 0.5), out = row_elevation(f.view, top - 0.5);
        auto turns_in_reach = [&](double e) {
            const RayOutcome o = ray_outcome(atm, y0, e);
            return o.fate == RayFate::TurnsLow && o.dz <= f.view.reach;
        };
        if (!turns_in_reach(out)) {
            for (int i = 0; i < 60; ++i) {
                const double m = 0.5 * (in + out);
                (turns_in_reach(m) ? in : out) = m;
            }
        }
        f.band_top_in_reach_rad = in;
    }
}

std::string metres(double v, double unit_m) { return sig(v * unit_m, 3) + " m"; }

std::string short_name(const FrameObject& o) { return o.kind + " at " + to_string(o.loc); }

// An image at least half a row tall.
bool seen(const ImageSpan& image, double pixel_rad) {
    return image.visible && image.angular_size_rad() >= 0.5 * pixel_rad;
}

bool mirrored_from(double distance, double vanishing, double farthest) {
    return std::isfinite(vanishing) && distance >= vanishing && distance <= farthest;
}

/// Lenses: the scene's angle and narrower ones, the same exact rays per row.
void try_lenses(const Atmosphere& atmosphere, const FrameView& view, FrameReading& f) {
    const double angle = camera_angle_deg(view.camera);
    std::vector<double> angles = {angle};
    for (double a : {60.0, 40.0, 20.0, 10.0, 5.0, 2.0, 1.0, 0.5})
        if (a < 0.99 * angle) angles.push_back(a);
    for (double a : angles) {
        FrameView v = view;
        v.camera = with_angle(view.camera, a);
        const ColumnReading c = read_column(atmosphere, v);
        f.lenses.push_back(
            {a, c.turning_low.count, c.turning_low_in_reach.count, c.turning_high.count});
    }
}

/// Camera heights: the scene's and lower ones.
void try_heights(const Atmosphere& atmosphere, const FrameView& view, double unit_m,
                 FrameReading& f) {
    const double R = atmosphere.earth_radius();
    const double eye_m = view.camera.location.y * unit_m;
    std::vector<double> heights_m = {eye_m};
    for (double h : {1.0, 0.5, 0.3, 0.2, 0.1})
        if (h < 0.95 * eye_m) heights_m.push_back(h);
    for (double h_m : heights_m) {
        FrameView v = view;
        v.camera.location.y = h_m / unit_m;
        v.eye_y = flattened_height(v.camera.location.y, R);
        HeightOption o;
        o.eye_height = v.camera.location.y;
        o.apparent_depression_rad = -grazing_elevation(atmosphere, v.eye_y);
        o.ground_ends = std::isfinite(o.apparent_depression_rad)
                            ? turn_to_height_distance(atmosphere, 0.0, v.eye_y)
                            : kNaN;
        o.band_rows = read_column(atmosphere, v).turning_low.count;
        for (const ObjectReading& r : f.objects) {
            auto reach = r.top > 0.0 ? mirror_reach(atmosphere, v.eye_y, r.top)
                                     : Result<MirrorReach>(make_error("below the ground"));
            o.vanishing.push_back(reach ? reach->nearest : kNaN);
        }
        f.heights.push_back(o);
    }
}

/// Distances: for each object without a mirrored image, where it would have the tallest.
void try_distances(const Atmosphere& atmosphere, const FrameView& view, FrameReading& f) {
    for (int k = 0; k < static_cast<int>(f.objects.size()); ++k) {
        const ObjectReading& r = f.objects[k];
        if (seen(r.mirrored, f.pixel_rad) || !std::isfinite(r.vanishing)) continue;
        const double near = 1.02 * r.vanishing, far = std::min(r.farthest, 4.0 * r.vanishing);
        DistanceOption best;
        best.object = k;
        constexpr int kTries = 8;
        for (int i = 0; i <= kTries; ++i) {
            const double d = near * std::pow(far / near, double(i) / kTries);
            const ImageSpan m = mirrored_image_at(atmosphere, view, r.object, d);
            if (m.visible && (!best.mirrored.visible ||
                              m.angular_size_rad() > best.mirrored.angular_size_rad())) {
                best.distance = d;
                best.mirrored = m;
            }
        }
        if (best.mirrored.visible) f.distances.push_back(best);
    }
}

/// Exaggerations (not air), times the scene's own: weaker and stronger.
void try_exaggerations(const MirageSettings& settings, double tolerance_rad, const FrameView& view,
                       FrameReading& f) {
    for (double k :
         {0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0}) {
        MirageSettings s = settings;
        if (!exaggerate_atmosphere(s, k, "exaggeration")) continue;
        auto air = scene_atmosphere(s, tolerance_rad);
        if (!air) continue;
        ExaggerationOption o;
        o.factor = s.exaggeration;
        o.apparent_depression_rad = -grazing_elevation(*air, view.eye_y);
        o.apparent_row = elevation_row(view, -o.apparent_depression_rad);
        const ColumnReading c = read_column(*air, view);
        o.band_rows = c.turning_low.count;
        o.band_rows_in_reach = c.turning_low_in_reach.count;
        for (const ObjectReading& r : f.objects) {
            auto reach = r.top > 0.0 ? mirror_reach(*air, view.eye_y, r.top)
                                     : Result<MirrorReach>(make_error("below the ground"));
            o.vanishing.push_back(reach ? reach->nearest : kNaN);
            o.farthest.push_back(reach ? reach->farthest : kNaN);
            if (reach && mirrored_from(r.distance, reach->nearest, reach->farthest))
                ++o.mirrored_objects;
        }
        f.exaggerations.push_back(o);
    }
}

/// The advice on the inferior mirage's band: where it lies, and the lens that shows it
/// `target` rows tall (returned; null when the band is tall enough, or without an inferior
/// mirage).
const LensOption* advise_band(const FrameView& view, double u,
                              const std::vector<const ExaggerationOption*>& by_change, int target,
                              FrameReading& f) {
    const double deg = 180.0 / kPi, angle = camera_angle_deg(view.camera);
    auto& advice = f.advice;
    const LensOption* lens = nullptr;  // the widest angle that shows the band to the target
    if (f.inferior) {
        if (std::isfinite(f.ground_ends) && f.ground_ends > view.reach)
            advice.push_back("in this air the mirage lies within " +
                             sig(-f.apparent_horizon_rad * deg, 3) +
                             " deg below the horizon, and only what stands beyond about " +
                             metres(f.ground_ends, u) +
                             " (where the grazing ray touches the ground) can be mirrored whole; "
                             "the scene reaches " +
                             metres(view.reach, u));
        if (f.apparent_horizon_row > view.height) {
            std::string s = "the apparent horizon lies below the frame (row " +
                            sig(f.apparent_horizon_row, 4) + " of " + std::to_string(view.height) +
                            "): the ground shows only within " + metres(f.ground_ends, u) +
                            " and all below the horizon is mirrored sky";
            for (const ExaggerationOption* e : by_change)
                if (e->factor < f.exaggeration && e->apparent_row < 0.9 * view.height &&
                    e->apparent_row > f.true_horizon_row + 2.0) {
                    s += "; with Mirage_Exaggeration = " + shortest(e->factor) +
                         " (not air) it would be at row " + sig(e->apparent_row, 4) + ", " +
                         sig(e->apparent_depression_rad * deg, 3) + " deg below the horizon";
                    break;
                }
            advice.push_back(s);
        }
        const int rows = f.column.turning_low.count;
        if (rows < target) {
            for (const LensOption& l : f.lenses) {
                lens = &l;
                if (l.band_rows >= target) break;
            }
            std::string s = "the mirage band is " + std::to_string(rows) + " rows tall at angle " +
                            sig(angle, 3);
            if (lens && lens->angle_deg != angle)
                s += "; with angle " + sig(lens->angle_deg, 3) + " it would be " +
                     std::to_string(lens->band_rows) + " rows (camera { ... angle " +
                     sig(lens->angle_deg, 3) + " })";
            advice.push_back(s);
        }
    }
    return lens;
}

/// The advice on each object without a mirrored image: move it, lower the camera, or change
/// the air's strength.
void advise_objects(const FrameView& view, double u,
                    const std::vector<const ExaggerationOption*>& by_change, const LensOption* lens,
                    FrameReading& f) {
    const double deg = 180.0 / kPi, angle = camera_angle_deg(view.camera);
    auto& advice = f.advice;
    auto exaggeration_advice = [&](int k, const ObjectReading& r) {
        for (const ExaggerationOption* e : by_change)
            if (mirrored_from(r.distance, e->vanishing[k], e->farthest[k])) {
                advice.push_back(
                    "  or change the air's strength (not air): with "
                    "Mirage_Exaggeration = " +
                    shortest(e->factor) + " its top is mirrored from " +
                    metres(e->vanishing[k], u) + " to " + metres(e->farthest[k], u) +
                    " and the band is " + std::to_string(e->band_rows) + " rows");
                return;
            }
    };
    const double lens_pixel_rad =
        lens ? pixel_angle_rad(with_angle(view.camera, lens->angle_deg), view.width, view.height)
             : f.pixel_rad;
    for (int k = 0; k < static_cast<int>(f.objects.size()); ++k) {
        const ObjectReading& r = f.objects[k];
        if (seen(r.mirrored, f.pixel_rad) || !std::isfinite(r.vanishing)) continue;
        const std::string name = short_name(r.object);
        std::string s = name + " is " + metres(r.distance, u) +
                        " away; the mirrored image of its " + metres(r.top, u) + " top " +
                        (r.distance < r.vanishing ? "vanishes nearer than " + metres(r.vanishing, u)
                                                  : "is lost beyond " + metres(r.farthest, u));
        advice.push_back(s);
        if (r.distance > r.farthest) {
            // Too far: the turned rays pass above it.  Nearer, within its range.
            for (const DistanceOption& d : f.distances)
                if (d.object == k)
                    advice.push_back("  move it nearer, to " + metres(d.distance, u) +
                                     ": its mirrored image would be " +
                                     sig(d.mirrored.angular_size_rad() * deg, 3) + " deg, " +
                                     sig(d.mirrored.angular_size_rad() / f.pixel_rad, 3) +
                                     " rows tall");
            exaggeration_advice(k, r);
            continue;
        }
        // Lower the camera: the highest of the lower heights that brings the vanishing distance
        // below the object's distance, else the lowest tried (an eye at the top's own height
        // sees it along rays that turn at once, a sliver at the horizon: not counted).
        const HeightOption* pick = nullptr;
        for (size_t i = 1; i < f.heights.size(); ++i) {
            if (std::abs(f.heights[i].eye_height - r.top) < 0.1 * r.top) continue;
            if (!std::isfinite(f.heights[i].vanishing[k])) continue;
            pick = &f.heights[i];
            if (f.heights[i].vanishing[k] <= r.distance) break;
        }
        if (pick && pick->vanishing[k] < r.vanishing)
            advice.push_back("  lower the camera to " + metres(pick->eye_height, u) +
                             ": the mirrored image of its top vanishes nearer than " +
                             metres(pick->vanishing[k], u) + " instead of " +
                             metres(r.vanishing, u));
        for (const DistanceOption& d : f.distances)
            if (d.object == k) {
                std::string s = "  move it to " + metres(d.distance, u) +
                                " from the camera: its mirrored image would be " +
                                sig(d.mirrored.angular_size_rad() * deg, 3) + " deg, " +
                                sig(d.mirrored.rows(), 3) + " rows tall";
                if (lens && lens->angle_deg != angle)
                    s += " (" + sig(d.mirrored.angular_size_rad() / lens_pixel_rad, 3) +
                         " rows with angle " + sig(lens->angle_deg, 3) + ")";
                advice.push_back(s);
            }
        exaggeration_advice(k, r);
    }
}

/// The advice, in sentences with the figures of the options tried.
void advise(const FrameView& view, double unit_m, FrameReading& f) {
    // The factors nearest 1 first: the least change that does it.
    std::vector<const ExaggerationOption*> by_change;
    for (const ExaggerationOption& e : f.exaggerations) by_change.push_back(&e);
    std::stable_sort(by_change.begin(), by_change.end(), [&](auto* a, auto* b) {
        return std::abs(std::log(a->factor / f.exaggeration)) <
               std::abs(std::log(b->factor / f.exaggeration));
    });
    const int target = std::max(8, view.height / 12);
    const LensOption* lens = advise_band(view, unit_m, by_change, target, f);
    advise_objects(view, unit_m, by_change, lens, f);
    const double angle = camera_angle_deg(view.camera);
    if (f.superior && f.column.turning_high.count < target) {
        const LensOption* pick = nullptr;
        for (const LensOption& l : f.lenses) {
            pick = &l;
            if (l.lifted_rows >= target) break;
        }
        if (pick && pick->angle_deg != angle)
            f.advice.push_back("the lifted rows are " +
                               std::to_string(f.column.turning_high.count) + "; with angle " +
                               sig(pick->angle_deg, 3) + " they would be " +
                               std::to_string(pick->lifted_rows));
    }
}

}  // namespace

Result<FrameReading> frame_scene(const FrameOptions& options) {
    SceneLoadOptions lo = scene_load_options(options);
    lo.strict = false;  // the objects' boxes are enough
    auto loaded = load_mirage_scene(lo);
    if (!loaded) return loaded.error();
    const MirageSettings& settings = loaded->settings;
    Scene& scene = loaded->scene;
    if (scene.camera.type != CameraType::Perspective)
        return make_error(place_prefix(scene.camera.loc, scene.file) +
                          "mirage frame reads a perspective camera, not a " +
                          camera_type_name(scene.camera.type) + " one");
    if (!bends_rays(settings))
        return make_error(scene.file +
                          ": the scene declares no atmosphere that bends rays: there is no "
                          "mirage to frame (declare Mirage_Preset, ...)");
    // A camera under the atmosphere's ground: refused as compile and trace refuse it.
    auto lowest = [&]() -> std::optional<double> {
        auto accel = SceneAccel::build(scene);
        if (!accel || accel->finite_bounds().empty()) return std::nullopt;
        return accel->finite_bounds().lo.y;
    };
    if (auto s = check_camera_above_ground(scene, settings.ground_height, lowest); !s)
        return s.error();
    lower_scene(scene, settings.ground_height);

    FrameReading f;
    f.scene = options.scene;
    f.files = scene.files;
    f.atmosphere = settings.profile_label;
    f.unit_m = settings.unit_m;
    f.exaggeration = settings.exaggeration;
    f.pixel_rad = pixel_angle_rad(scene.camera, options.width, options.height);
    const double tolerance_rad =
        fit_angle_rad(PixelFootprint{0.0, f.pixel_rad}, settings.tolerance_px, 0.0);
    auto atmosphere = scene_atmosphere(settings, tolerance_rad);
    if (!atmosphere) return make_error(options.scene + ": " + atmosphere.message());
    const double R = atmosphere->earth_radius();
    f.earth_radius = R;

    auto objects = frame_objects(scene);
    if (!objects) return objects.error();
    // Heights in the model's frame (flattened on the curved Earth).
    for (FrameObject& o : *objects) {
        o.lo.y = flattened_height(o.lo.y, R);
        o.hi.y = flattened_height(o.hi.y, R);
    }
    FrameView& view = f.view;
    view.camera = scene.camera;
    view.width = options.width;
    view.height = options.height;
    view.eye_y = flattened_height(scene.camera.location.y, R);
    if (settings.extent) {
        view.reach = *settings.extent;
    } else {
        double reach = 0.0;
        const glm::dvec3& eye = scene.camera.location;
        for (const FrameObject& o : *objects)
            for (int i = 0; i < 4; ++i) {
                const double x = (i & 1) ? o.hi.x : o.lo.x, z = (i & 2) ? o.hi.z : o.lo.z;
                reach = std::max(reach, std::hypot(x - eye.x, z - eye.z));
            }
        view.reach = reach > 0.0 ? kReachMargin * reach : kUnboundedReachEyeHeights * view.eye_y;
    }
    read_frame(*atmosphere, f);
    for (const FrameObject& o : *objects) f.objects.push_back(read_object(*atmosphere, view, o));
    if (!options.advise) return f;

    try_lenses(*atmosphere, view, f);
    try_heights(*atmosphere, view, settings.unit_m, f);
    try_distances(*atmosphere, view, f);
    try_exaggerations(settings, tolerance_rad, view, f);
    advise(view, settings.unit_m, f);
    return f;
}

Result<Image> frame_background(const FrameOptions& options) {
    TraceOptions t;
    t.input() = options.input();
    t.progress = false;
    auto traced = trace_scene(t);
    if (!traced) return traced.error();
    return std::move(traced->render.image);
}

}  // namespace mirage
