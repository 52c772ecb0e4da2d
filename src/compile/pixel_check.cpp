#include "compile/pixel_check.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

#include "scene/camera.h"
#include "layers/band_aim.h"
#include "trace/curved_propagator.h"
#include "util/check.h"
#include "util/parallel.h"
#include "util/progress.h"

namespace mirage {

namespace {

// What the exact rays of the check follow, as the tracer's do: the atmosphere, how far, and
// the turbulent air.
CurvedSettings exact_ray_settings(const PixelCheckSettings& s) {
    CurvedSettings cs;
    cs.atmosphere = s.atmosphere;
    cs.max_dz = s.max_dz;
    cs.turbulence = s.turbulence;
    cs.turbulence_time_s = s.turbulence_time_s;
    cs.unit_m = s.unit_m;
    return cs;
}

// The nearest row to `row` (outward from it, up and down alternately) of the H rows for which
// `ends_there(q)` holds, as a distance in rows; +inf when none.
template <class EndsThere>
double nearest_row(int row, int H, EndsThere ends_there) {
    for (int d = 0; d < H; ++d)
        for (int q : {row - d, row + d})
            if (q >= 0 && q < H && ends_there(q)) return d;
    return std::numeric_limits<double>::infinity();
}

constexpr double kInf = std::numeric_limits<double>::infinity();

// Where a ray ends: the surface it meets, or the direction it leaves in.
struct RayEnd {
    bool cut_off = false;  // the band tracer gave up on it (a ray skimming along a layer)
    bool hit = false;
    glm::dvec3 point{0.0};      // on the surface
    glm::dvec3 direction{0.0};  // unit, of travel there (or when leaving)
    glm::dvec3 normal{0.0};     // of the surface, facing the ray
    int primitive = -1;         // -1: the ground where no object is
    double length = 0.0;        // path length from the ray's start to the hit
    int crossings = 0;          // band rays: boundaries crossed (a trace level each)
    double last_event = 0.0;    // band rays: horizontal distance to the last crossing
};

/// Where a ray's end lies as seen from `from`: towards its point, or along its direction.
glm::dvec3 seen_from(const glm::dvec3& from, const RayEnd& e) {
    const glm::dvec3 v = e.hit ? e.point - from : e.direction;
    const double n = glm::length(v);
    return n > 0.0 ? v / n : glm::dvec3(0.0, 0.0, 1.0);
}

/// The angle between where two rays from `from` end, as seen from a point `distance` behind
/// `from` along the path (the eye, for a reflected ray): seen from farther back, the angle
/// at `from` between two end points shrinks in proportion to the distances.
double end_error_rad(const glm::dvec3& from, double distance, const RayEnd& a, const RayEnd& b) {
    const double angle = angle_between(seen_from(from, a), seen_from(from, b));
    if (a.hit && b.hit) {
        const double reach = std::max(a.length, b.length);
        return reach > 0.0 ? angle * reach / (distance + reach) : angle;
    }
    return angle;
}

RayEnd exact_end(const CurvedPropagator& exact, const SceneAccel& accel, const glm::dvec3& origin,
                 const glm::dvec3& dir, double travelled) {
    RayStart start;
    start.origin = origin;
    start.direction = dir;
    start.travelled = travelled;
    const PathHit h = exact.propagate(accel, start);
    RayEnd e;
    e.hit = h.hit;
    e.direction = h.direction;
    if (h.hit) {
        e.point = h.surface.point;
        e.normal =
            glm::dot(h.surface.normal, h.direction) > 0.0 ? -h.surface.normal : h.surface.normal;
        e.primitive = h.surface.primitive;
        e.length = h.length;
    }
    return e;
}

RayEnd band_end(const LayerStack& stack, const ObjectQuery& objects, double camera_y,
                const glm::dvec3& origin, const glm::dvec3& dir, const HorizontalBox& box,
                const std::optional<HorizontalBox>& below) {
    Trace3dOptions o{100000, &objects, camera_y};
    o.below = below;
    const Trace3dOutcome t = trace_layers_3d(stack, origin, dir, box, box, o);
    RayEnd e;
    e.cut_off = t.cut_off;
    e.crossings = t.crossings;
    e.last_event = t.last_event;
    if (t.ground) {  // the ground where no object is: the exact ray ends there too
        e.hit = true;
        e.point = t.scene_point;
        e.direction = t.scene_dir;
        e.length = glm::length(t.scene_point - origin);
    } else if (t.object) {
        e.hit = true;
        e.point = t.object_point;
        e.direction = t.object_dir;
        e.normal =
            glm::dot(t.object->normal, t.object_dir) > 0.0 ? -t.object->normal : t.object->normal;
        e.primitive = t.object->id;
        e.length = glm::length(t.object_point - origin);  // the chord: enough for a scale
    } else {
        e.direction = t.sky ? t.final_dir : t.scene_dir;
    }
    return e;
}

double reflection_weight(const Scene& scene, int primitive) {
    const glm::dvec3 r = scene.primitives[primitive].texture.finish.reflection;
    return std::max({r.x, r.y, r.z});
}

// The trace level POV-Ray reaches along a band ray that ended at `b`: one for the camera
// ray, one per boundary crossed, and as much again along each reflection that still counts
// (POV-Ray stops a reflection whose weight falls under 1/255).
int band_trace_level(const LayerStack& rendered, const Scene& scene, const ObjectQuery& objects,
                     const PixelCheckSettings& s, RayEnd b) {
    constexpr int kCutOff = 1 << 20;  // past any ceiling
    int level = 1 + b.crossings;
    double weight = 1.0;
    while (!b.cut_off && b.hit && b.primitive >= 0) {
        weight *= reflection_weight(scene, b.primitive);
        if (weight < 1.0 / 255.0 || level > kCutOff) break;
        glm::dvec3 o = b.point + 1e-6 * b.normal;
        o.y = std::max(o.y, 0.0);
        b = band_end(rendered, objects, s.camera_y, o, glm::reflect(b.direction, b.normal),
                     s.layers, s.layers_below);
        level += 1 + b.crossings;
    }
    return b.cut_off ? kCutOff : level;
}

// One pixel's rays: where the camera rays end as seen from the eye, and the reflections'
// error.
struct PixelEnds {
    bool cut_off = false;
    glm::dvec3 band_seen{0.0}, exact_seen{0.0};
    double camera_error_rad = 0.0;
    double reflection_error_rad = 0.0;
    RayEnd band;          // where the band ray ended
    int trace_level = 0;  // with an aim: POV-Ray's trace level along the chosen band ray
};

// The reflections a pixel's band and exact rays follow while they meet the same mirror, and
// the largest error between them that `error(origin, travelled, band, exact)` measures.  Both
// reflections leave the point the band ray met: the exact image shows that point from a pixel
// nearby (the shift measures how far), and its reflection there is what the pixel would show.
// A small move on a curved mirror turns the reflected ray far but moves the picture only as
// far as the point moves.  The exact reflection arrives with the exact direction.
template <typename Error>
double worst_reflection_error(const LayerStack& rendered, const Scene& scene,
                              const SceneAccel& accel, const ObjectQuery& objects,
                              const CurvedPropagator& exact, const PixelCheckSettings& s, RayEnd b,
                              RayEnd e, const Error& error) {
    double worst = 0.0, travelled = 0.0, weight = 1.0;
    for (int bounce = 0;
         bounce < s.max_bounces && b.hit && e.hit && b.primitive >= 0 && b.primitive == e.primitive;
         ++bounce) {
        weight *= reflection_weight(scene, b.primitive);
        if (weight < 1.0 / 255.0) break;
        travelled += e.length;
        glm::dvec3 o = b.point + 1e-6 * b.normal;
        o.y = std::max(o.y, 0.0);
        const RayEnd b2 = band_end(rendered, objects, s.camera_y, o,
                                   glm::reflect(b.direction, b.normal), s.layers, s.layers_below);
        const RayEnd e2 =
            exact_end(exact, accel, o, glm::reflect(e.direction, b.normal), travelled);
        worst = std::max(worst, error(o, travelled, b2, e2));
        b = b2;
        e = e2;
    }
    return worst;
}

PixelEnds band_against_exact(const LayerStack& rendered, const Scene& scene,
                             const SceneAccel& accel, const ObjectQuery& objects,
                             const CurvedPropagator& exact, const PixelCheckSettings& s,
                             const glm::dvec3& band_dir, const RayEnd& e) {
    RayEnd b = band_end(rendered, objects, s.camera_y, s.eye, band_dir, s.layers, s.layers_below);
    PixelEnds p;
    p.cut_off = b.cut_off;
    p.band = b;
    p.band_seen = seen_from(s.eye, b);
    p.exact_seen = seen_from(s.eye, e);
    p.camera_error_rad = end_error_rad(s.eye, 0.0, b, e);
    p.reflection_error_rad = worst_reflection_error(
        rendered, scene, accel, objects, exact, s, b, e,
        [](const glm::dvec3& o, double travelled, const RayEnd& b2, const RayEnd& e2) {
            return end_error_rad(o, travelled, b2, e2);
        });
    return p;
}

// Which surface a band ray ends on: the primitive it meets (-1 the ground), or the sky (-2).
int end_key(const RayEnd& b) { return b.hit ? b.primitive : -2; }

// The elevation (rad) of a direction.
double elevation_of(const glm::dvec3& d) {
    return std::asin(std::clamp(d.y / glm::length(d), -1.0, 1.0));
}

// At an edge, where the exact ray passes close by one surface and meets another, the band rays
// aimed so far may end on either side of it, each off the exact end.  The elevations between
// the best of them (along `best_dir`, ending on surface `best_key`) and the nearest one that
// ends on another surface cross that edge: bisected down to a millionth of a pixel, every ray
// followed a candidate, so that the band ray just on the exact ray's side of the edge is found
// (the least error the layers allow there).
template <typename Follow>
void edge_search(int best_key, const glm::dvec3& best_dir,
                 const std::vector<std::pair<PixelEnds, glm::dvec3>>& tried, double same,
                 double pixel_rad, const Follow& follow) {
    const double e_best = elevation_of(best_dir);
    // For each other surface the rays ended on, the nearest elevation that ended there.
    std::vector<double> others;
    std::vector<int> keys;
    for (const auto& [p, c] : tried) {
        const int k = end_key(p.band);
        if (k == best_key) continue;
        const double e = elevation_of(c);
        const auto it = std::find(keys.begin(), keys.end(), k);
        if (it == keys.end()) {
            keys.push_back(k);
            others.push_back(e);
        } else {
            double& o = others[static_cast<size_t>(it - keys.begin())];
            if (std::fabs(e - e_best) < std::fabs(o - e_best)) o = e;
        }
    }
    for (const double other : others) {
        double a = e_best, b = other;
        for (int step = 0; step < 60 && std::fabs(b - a) > 1e-6 * pixel_rad; ++step) {
            const double m = 0.5 * (a + b);
            const PixelEnds p = follow(mesh_camera_direction(direction_at_elevation(best_dir, m)));
            if (p.cut_off) break;
            if (p.camera_error_rad <= same) return;
            (end_key(p.band) == best_key ? a : b) = m;
        }
    }
}

PixelEnds pixel_ends(const LayerStack& rendered, const Scene& scene, const SceneAccel& accel,
                     const ObjectQuery& objects, const CurvedPropagator& exact,
                     const PixelCheckSettings& s, size_t i, const glm::dvec3& dir, double pixel_rad,
                     std::vector<glm::dvec3>& candidates, glm::dvec3* chosen) {
    const RayEnd e = exact_end(exact, accel, s.eye, dir, 0.0);
    if (!s.aim) return band_against_exact(rendered, scene, accel, objects, exact, s, dir, e);
    candidates.clear();
    s.aim.candidates(i, dir, ExactEnd{e.hit, e.point, e.direction}, candidates);
    MIRAGE_CHECK(!candidates.empty());
    // The camera ray's own end first (what the pixel shows), then its reflections': a
    // candidate wins with a smaller camera error, or with one as small (to a hundredth of a
    // pixel) and smaller reflections'.
    const double same = 0.01 * pixel_rad;
    PixelEnds best;
    bool have = false;
    // Every band ray followed and not cut off, with its direction.
    std::vector<std::pair<PixelEnds, glm::dvec3>> tried;
    // A candidate wins with a smaller camera error, or with one as small (to a hundredth of a
    // pixel) and smaller reflections'.
    auto consider = [&](const PixelEnds& p, const glm::dvec3& c) {
        if (!p.cut_off) tried.emplace_back(p, c);
        if (p.cut_off && have) return;
        const bool better = !have || (best.cut_off && !p.cut_off) ||
                            p.camera_error_rad < best.camera_error_rad - same ||
                            (p.camera_error_rad <= best.camera_error_rad + same &&
                             std::max(p.camera_error_rad, p.reflection_error_rad) <
                                 std::max(best.camera_error_rad, best.reflection_error_rad));
        if (better) {
            best = p;
            have = true;
            *chosen = c;
        }
    };
    auto follow = [&](const glm::dvec3& c) {
        const PixelEnds p = band_against_exact(rendered, scene, accel, objects, exact, s, c, e);
        consider(p, c);
        return p;
    };
    // The camera ray's own end first (what the pixel shows), then its reflections'.  The
    // candidates come best first: one within a hundredth of a pixel is kept.
    for (const glm::dvec3& c : candidates) {
        if (have && !best.cut_off && best.camera_error_rad <= same) break;
        follow(c);
    }
    // A band path that meets something the exact path passes by (or passes what the exact
    // path meets): aimed again through the exact path's point at that distance, a few times,
    // from each candidate followed, the nearest first (the best one may lie on another sheet
    // than the exact ray, a direct ray for a turned one, where no such aim helps).
    std::vector<std::pair<PixelEnds, glm::dvec3>> starts = tried;
    std::stable_sort(starts.begin(), starts.end(), [](const auto& a, const auto& b) {
        return a.first.camera_error_rad < b.first.camera_error_rad;
    });
    for (const auto& [start, start_dir] : starts) {
        if (!s.aim.through || best.camera_error_rad <= same) break;
        PixelEnds from = start;
        for (int round = 0; round < 4 && from.camera_error_rad > same; ++round) {
            // The nearer of the two ends that lie on a surface.
            double r = kInf;
            for (const RayEnd* end : {static_cast<const RayEnd*>(&from.band), &e})
                if (end->hit)
                    r = std::min(r, std::hypot(end->point.x - s.eye.x, end->point.z - s.eye.z));
            if (!std::isfinite(r)) break;
            const auto c = s.aim.through(i, dir, r);
            if (!c) break;
            const PixelEnds p = follow(*c);
            if (p.cut_off || !(p.camera_error_rad < from.camera_error_rad - same)) break;
            from = p;
        }
    }
    if (!best.cut_off && best.camera_error_rad > same)
        edge_search(end_key(best.band), *chosen, tried, same, pixel_rad, follow);
    best.trace_level = band_trace_level(rendered, scene, objects, s, best.band);
    return best;
}

// With many origins: where a ray ends as a point (a hit, or `far` along its final direction
// from its origin), and the length of path that led there.
struct EndPoint {
    glm::dvec3 point{0.0};
    double length = 0.0;
};

EndPoint end_point(const glm::dvec3& origin, const RayEnd& e, double far) {
    if (e.hit) return {e.point, e.length};
    return {origin + far * e.direction, far};
}

// The distance between two end points across the exact ray's direction of arrival there, in
// pixels of the footprint at the exact end's path length (plus `travelled` before the start).
double across_px(const PixelFootprint& fp, const glm::dvec3& exact_direction, const EndPoint& band,
                 const EndPoint& exact, double travelled) {
    const glm::dvec3 v = band.point - exact.point;
    const double along = glm::dot(v, exact_direction);
    const double across = std::sqrt(std::max(0.0, glm::dot(v, v) - along * along));
    const double unit = fp.distance + fp.angle_rad * (travelled + exact.length);
    return unit > 0.0 ? across / unit : (across > 0.0 ? kInf : 0.0);
}

// The band ray from an origin that may lie below the ground: straight there (the bottom
// layer's index, the ground's) to the first surface or up to the ground, then through the
// layers.
RayEnd band_end_from(const LayerStack& stack, const ObjectQuery& objects, double camera_y,
                     const glm::dvec3& origin, const glm::dvec3& dir, const HorizontalBox& box,
                     const std::optional<HorizontalBox>& layers_below) {
    if (origin.y >= 0.0) return band_end(stack, objects, camera_y, origin, dir, box, layers_below);
    const double below = dir.y > 0.0 ? -origin.y / dir.y : kInf;
    RayEnd e;
    if (auto h = objects(origin, dir, below)) {
        e.hit = true;
        e.point = origin + h->t * dir;
        e.direction = dir;
        e.normal = glm::dot(h->normal, dir) > 0.0 ? -h->normal : h->normal;
        e.primitive = h->id;
        e.length = h->t;
        return e;
    }
    if (!std::isfinite(below)) {
        e.direction = dir;
        return e;
    }
    glm::dvec3 at = origin + below * dir;
    at.y = 0.0;
    e = band_end(stack, objects, camera_y, at, dir, box, layers_below);
    e.length += below;
    return e;
}

struct OriginEnds {
    bool cut_off = false;
    EndPoint band, exact;
    double camera_error_px = 0.0, reflection_error_px = 0.0;
};

OriginEnds origin_ends(const LayerStack& rendered, const Scene& scene, const SceneAccel& accel,
                       const ObjectQuery& objects, const CurvedPropagator& exact,
                       const PixelCheckSettings& s, const glm::dvec3& origin,
                       const glm::dvec3& dir) {
    RayEnd b = band_end_from(rendered, objects, s.camera_y, origin, dir, s.layers, s.layers_below);
    RayEnd e = exact_end(exact, accel, origin, dir, 0.0);
    OriginEnds p;
    p.cut_off = b.cut_off;
    p.band = end_point(origin, b, s.far);
    p.exact = end_point(origin, e, s.far);
    p.camera_error_px = across_px(s.footprint, e.direction, p.band, p.exact, 0.0);
    p.reflection_error_px = worst_reflection_error(
        rendered, scene, accel, objects, exact, s, b, e,
        [&s](const glm::dvec3& o, double travelled, const RayEnd& b2, const RayEnd& e2) {
            return across_px(s.footprint, e2.direction, end_point(o, b2, s.far),
                             end_point(o, e2, s.far), travelled);
        });
    return p;
}

PixelCheck check_many_origins(const LayerStack& rendered, const Scene& scene, const SceneAccel& accel,
                              const ObjectQuery& objects, const std::vector<glm::dvec3>& directions,
                              const std::vector<bool>& cut_off, const PixelCheckSettings& s) {
    const int W = s.width, H = s.height;
    const size_t n = static_cast<size_t>(W) * H;
    const std::vector<glm::dvec3>& origins = *s.origins;
    MIRAGE_CHECK(origins.size() == n);
    CurvedSettings cs = exact_ray_settings(s);
    // The exact paths a twentieth of a pixel from the truth.
    cs.tolerance_rad = 0.05 * s.footprint.angle_rad;
    cs.tolerance_m = 0.05 * s.footprint.distance;
    const CurvedPropagator exact(cs);

    std::vector<OriginEnds> ends(n);
    ProgressBar bar("check", H, s.progress);
    parallel_for(
        H,
        [&](long row) {
            for (size_t i = static_cast<size_t>(row) * W; i < static_cast<size_t>(row + 1) * W; ++i)
                if (!cut_off[i])
                    ends[i] = origin_ends(rendered, scene, accel, objects, exact, s, origins[i],
                                          directions[i]);
            bar.advance();
        },
        0, 1);
    bar.finish();

    PixelCheck out;
    out.seen_error_px.assign(n, 0.0f);
    out.shift_rows.assign(n, 0.0f);
    out.reflection_error_px.assign(n, 0.0f);
    auto unit = [&](const EndPoint& e) {
        return s.footprint.distance + s.footprint.angle_rad * e.length;
    };
    parallel_for(
        W,
        [&](long col) {
            // Each exact end's reach: the distance to the farther of its neighbours' ends in
            // the column, at least a hundredth of a pixel there.
            std::vector<double> reach(H);
            for (int row = 0; row < H; ++row) {
                const size_t i = static_cast<size_t>(row) * W + col;
                double r = 0.01 * unit(ends[i].exact);
                for (int nb : {row - 1, row + 1}) {
                    if (nb < 0 || nb >= H) continue;
                    const size_t j = static_cast<size_t>(nb) * W + col;
                    r = std::max(r, glm::length(ends[i].exact.point - ends[j].exact.point));
                }
                reach[row] = r;
            }
            for (int row = 0; row < H; ++row) {
                const size_t i = static_cast<size_t>(row) * W + col;
                if (cut_off[i] || ends[i].cut_off) {
                    out.seen_error_px[i] = out.shift_rows[i] = static_cast<float>(kInf);
                    continue;
                }
                const OriginEnds& p = ends[i];
                out.seen_error_px[i] =
                    static_cast<float>(std::max(p.camera_error_px, p.reflection_error_px));
                out.reflection_error_px[i] = static_cast<float>(p.reflection_error_px);
                out.shift_rows[i] = static_cast<float>(
                    nearest_row(row, H, [&](int q) {
                        const size_t j = static_cast<size_t>(q) * W + col;
                        return !cut_off[j] && !ends[j].cut_off &&
                               glm::length(ends[j].exact.point - p.band.point) <= reach[q];
                    }));
            }
        },
        0, 1);
    return out;
}

}  // namespace

PixelCheck check_pixels(const LayerStack& rendered, const Scene& scene,
                        const SceneAccel& accel, const ObjectQuery& objects,
                        const std::vector<glm::dvec3>& directions,
                        const std::vector<double>& pixel_rad, const std::vector<bool>& cut_off,
                        const PixelCheckSettings& s) {
    if (s.origins)
        return check_many_origins(rendered, scene, accel, objects, directions, cut_off, s);
    const int W = s.width, H = s.height;
    const size_t n = static_cast<size_t>(W) * H;
    MIRAGE_CHECK(directions.size() == n && pixel_rad.size() == n && cut_off.size() == n);
    CurvedSettings cs = exact_ray_settings(s);
    cs.tolerance_rad = s.exact_tolerance_rad;
    cs.eye = s.eye;  // the camera rays' start: they share its index of the scene's boxes
    const CurvedPropagator exact(cs);

    std::vector<PixelEnds> ends(n);
    PixelCheck out;
    out.band_direction = directions;
    ProgressBar bar("check", H, s.progress);
    parallel_for(
        H,
        [&](long row) {
            std::vector<glm::dvec3> candidates;
            for (size_t i = static_cast<size_t>(row) * W; i < static_cast<size_t>(row + 1) * W; ++i)
                if (!cut_off[i])
                    ends[i] =
                        pixel_ends(rendered, scene, accel, objects, exact, s, i, directions[i],
                                   pixel_rad[i], candidates, &out.band_direction[i]);
            bar.advance();
        },
        0, 1);
    bar.finish();

    out.seen_error_px.assign(n, 0.0f);
    out.shift_rows.assign(n, 0.0f);
    out.reflection_error_px.assign(n, 0.0f);
    out.camera_error_px.assign(n, 0.0f);
    if (s.aim) {
        out.crossings.assign(n, 0);
        out.trace_level.assign(n, 0);
        out.last_event.assign(n, 0.0);
        for (size_t i = 0; i < n; ++i)
            if (!cut_off[i] && !ends[i].band.cut_off) {
                out.crossings[i] = ends[i].band.crossings;
                out.last_event[i] = ends[i].band.last_event;
                out.trace_level[i] = ends[i].trace_level;
            }
    }
    parallel_for(
        W,
        [&](long col) {
            // Each exact ray's reach: the angle to the farther of its neighbours' ends in the
            // column, at least a hundredth of a pixel.  A band end within it is what that row
            // shows (between two rows' samples, or on an edge between them).
            std::vector<double> reach_cos(H);
            for (int row = 0; row < H; ++row) {
                const size_t i = static_cast<size_t>(row) * W + col;
                double reach = 0.01 * pixel_rad[i];
                for (int nb : {row - 1, row + 1}) {
                    if (nb < 0 || nb >= H) continue;
                    const size_t j = static_cast<size_t>(nb) * W + col;
                    reach = std::max(reach, angle_between(ends[i].exact_seen, ends[j].exact_seen));
                }
                reach_cos[row] = std::cos(std::min(reach, M_PI));
            }
            for (int row = 0; row < H; ++row) {
                const size_t i = static_cast<size_t>(row) * W + col;
                if (cut_off[i] || ends[i].cut_off) {
                    out.seen_error_px[i] = out.shift_rows[i] = static_cast<float>(kInf);
                    out.camera_error_px[i] = static_cast<float>(kInf);
                    continue;
                }
                const PixelEnds& p = ends[i];
                out.seen_error_px[i] = static_cast<float>(
                    std::max(p.camera_error_rad, p.reflection_error_rad) / pixel_rad[i]);
                out.reflection_error_px[i] =
                    static_cast<float>(p.reflection_error_rad / pixel_rad[i]);
                out.camera_error_px[i] = static_cast<float>(p.camera_error_rad / pixel_rad[i]);
                // The nearest row whose exact ray ends where this band ray does: outward from the
                // pixel's own row, up and down alternately.
                out.shift_rows[i] = static_cast<float>(nearest_row(row, H, [&](int q) {
                    const size_t j = static_cast<size_t>(q) * W + col;
                    return !cut_off[j] && !ends[j].cut_off &&
                           glm::dot(ends[j].exact_seen, p.band_seen) >= reach_cos[q];
                }));
            }
        },
        0, 1);
    return out;
}

}  // namespace mirage
