// Isosurfaces after POV-Ray 3.7's isosurf.cpp (R. Suzuki's method): the ray clipped to the
// container (box or sphere), the container's own surface where it lies inside the function
// (unless `open`), then up to max_trace roots found by recursive bisection of the interval,
// an interval dropped when the values at its ends are too far above zero for the function,
// with slope at most max_gradient, to reach zero inside it; the normal by forward
// differences of `accuracy`.
//
// Left out: POV-Ray's per-thread cache that skips the root search for a ray whose interval
// lies near the last one without a root (it depends on the order rays are traced in), and
// `evaluate` carrying the raised max_gradient over to later rays: here each ray starts from
// max_gradient, so the image does not depend on the thread count.
#include "shapes/isosurface.h"

#include <algorithm>
#include <cmath>

#include "scene/function.h"
#include "patterns/noise.h"
#include "patterns/pigment_eval.h"

namespace mirage {
namespace {

constexpr double kBoxDepthTolerance = 1.0e-6;  // boxes.cpp's DEPTH_TOLERANCE
constexpr int kMaxHits = 12;                    // the container's two and ISOSURFACE_MAXTRACE

thread_local long t_root_search_steps = 0;  // root_search_steps_on_this_thread

double trace_noise(double x, double y, double z, int generator) {
    return noise(glm::dvec3(x, y, z), generator);
}

void trace_pigment(const Pigment& pigment, double x, double y, double z, double* rgbft) {
    const PigmentColour c = evaluate_pigment(pigment, glm::dvec3(x, y, z));
    rgbft[0] = c.rgb.x;
    rgbft[1] = c.rgb.y;
    rgbft[2] = c.rgb.z;
    rgbft[3] = c.filter;
    rgbft[4] = c.transmit;
}

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

class IsosurfaceShape final : public ComplexShape {
  public:
    IsosurfaceShape(const Isosurface& iso, const Transform& t) : iso_(iso) {
        env_.noise = &trace_noise;
        env_.pigment = &trace_pigment;
        env_.noise_generator = iso.noise_generator;
        world_to_local_ = t.inverse;
        local_to_world_ = t.matrix;
        normal_to_world_ = glm::transpose(glm::dmat3(t.inverse));
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        // A query reaching behind its origin (a polyline joint) starts that far back.
        const double shift = sink.t_min() < 0.0 ? sink.t_min() : 0.0;
        Hit hits[kMaxHits];
        const int n = all_intersections(origin + shift * direction, direction, hits);
        for (int i = 0; i < n; ++i) sink.add(hits[i].t + shift, hits[i].side);
    }

    // IsoSurface::Inside.
    bool inside(const glm::dvec3& point) const override {
        const glm::dvec3 p = transform_point(world_to_local_, point);
        if (iso_.sphere_container) {
            const glm::dvec3 oc = iso_.centre - p;
            if (glm::dot(oc, oc) > iso_.radius * iso_.radius) return false;
        } else {
            for (int a = 0; a < 3; ++a) {
                if (p[a] < iso_.corner1[a] || p[a] > iso_.corner2[a]) return false;
            }
        }
        return !(value(p) > 0.0);
    }

    // IsoSurface::Normal: a container side's normal where the container was hit, else the
    // forward differences of the function over `accuracy`.
    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit& hit) const override {
        glm::dvec3 n(0.0);
        if (hit.part >= 1 && hit.part <= 6) {
            const int axis = (hit.part - 1) / 2;
            n[axis] = hit.part % 2 == 1 ? -1.0 : 1.0;
        } else {
            const glm::dvec3 p = transform_point(world_to_local_, point);
            bool done = false;
            if (iso_.sphere_container) {
                const glm::dvec3 r = p - iso_.centre;
                if (std::abs(glm::length(r) - iso_.radius) < kPovEpsilon) {
                    n = r / iso_.radius;
                    done = true;
                }
            }
            if (!done) {
                const double f0 = function(p);
                const double h = iso_.accuracy;
                n = glm::dvec3(function(p + glm::dvec3(h, 0, 0)) - f0,
                               function(p + glm::dvec3(0, h, 0)) - f0,
                               function(p + glm::dvec3(0, 0, h)) - f0);
                if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) n.x = 1.0;
                n = glm::normalize(n);
            }
        }
        return glm::normalize(normal_to_world_ * n);
    }

    // IsoSurface::Compute_BBox: the container's box, transformed.
    Aabb bounds() const override {
        glm::dvec3 lo = iso_.corner1, hi = iso_.corner2;
        if (iso_.sphere_container) {
            lo = iso_.centre - glm::dvec3(iso_.radius);
            hi = iso_.centre + glm::dvec3(iso_.radius);
        }
        Aabb box;
        for (int i = 0; i < 8; ++i) {
            box.extend(transform_point(local_to_world_, glm::dvec3(i & 1 ? hi.x : lo.x,
                                                                   i & 2 ? hi.y : lo.y,
                                                                   i & 4 ? hi.z : lo.z)));
        }
        return box;
    }

  private:
    struct Hit {
        double t;
        int side;
    };
    struct Pair {
        double t, f;
    };
    // One ray's search: its local origin and direction and the sign that makes "inside"
    // negative for the part of the ray being searched (POV-Ray's Inv3).
    struct Search {
        glm::dvec3 P, D;
        double vlength = 1.0;
        double inv = 1.0;
        double maxg = 1.1;
        // Function evaluations the bisection may still make for this ray (kMaxRootSearchSteps
        // in all): a fine accuracy with a huge max_gradient drops no interval and would halve
        // the ray's interval down to the accuracy everywhere.
        long steps_left = kMaxRootSearchSteps;
    };

    double function(const glm::dvec3& p) const {
        const double a[3] = {p.x, p.y, p.z};
        return evaluate_function(*iso_.function, a, 3, &env_);
    }
    // Vector_Function: the function less the threshold.
    double value(const glm::dvec3& p) const { return function(p) - iso_.threshold; }
    // Float_Function: the same along the ray, signed.
    double along(const Search& s, double t) const { return s.inv * value(s.P + t * s.D); }

    // IsoSurface::All_Intersections: the hits in world depths along the unit `direction`.
    int all_intersections(const glm::dvec3& origin, const glm::dvec3& direction,
                          Hit* hits) const {
        Search s;
        s.P = transform_point(world_to_local_, origin);
        s.D = glm::dmat3(world_to_local_) * direction;
        s.vlength = glm::length(s.D);
        s.maxg = iso_.max_gradient;
        double depth1 = 0.0, depth2 = 0.0;
        int side1 = 0, side2 = 0;
        if (iso_.sphere_container) {
            if (!sphere_roots(iso_.centre, iso_.radius * iso_.radius, s.P, s.D / s.vlength,
                              false, depth1, depth2)) {
                return 0;
            }
            depth1 /= s.vlength;
            depth2 /= s.vlength;
        } else {
            if (!box_roots(iso_.corner1, iso_.corner2, s.P, s.D, 0.0, depth1, side1, depth2,
                           side2) ||
                depth2 < kBoxDepthTolerance) {
                return 0;
            }
        }
        if (depth1 < 0.0) depth1 = 0.0;
        const double acc = iso_.accuracy;
        int n = 0;
        int itrace = 0;
        if (!iso_.open) {
            const double f1 = value(s.P + depth1 * s.D);
            if (depth1 > acc) {
                if (f1 < 0.0) {  // the container's surface, inside the function
                    hits[n++] = Hit{depth1, side1};
                    ++itrace;
                    s.inv = -s.inv;
                }
            } else {
                // Starting inside the container: step off a surface the origin is on.
                if (f1 < s.maxg * acc * 4.0) {
                    depth1 = acc * 5.0;
                    if (value(s.P + depth1 * s.D) < 0.0) s.inv = -1.0;
                }
                if (value(s.P + depth2 * s.D) < 0.0) hits[n++] = Hit{depth2, side2};
            }
        }
        double tmax = depth2 = std::min(depth2, kPovBoundHuge);
        double tmin = depth1 = std::min(depth2, depth1);
        if (tmax - tmin < acc) return 0;  // POV-Ray reports no intersection then
        if (depth1 < acc && s.inv == 1.0) {
            if (std::abs(value(s.P + tmin * s.D)) < s.maxg * acc * 4.0) {
                tmin = acc * 5.0;
                if (value(s.P + tmin * s.D) < 0.0) s.inv = -1.0;
            }
        }
        for (; itrace < iso_.max_trace && n < kMaxHits; ++itrace) {
            if (!find_root(s, tmin, tmax)) break;
            hits[n++] = Hit{tmin, 0};
            tmin += acc * 5.0;
            if (tmax - tmin < acc) break;
            s.inv = -s.inv;
        }
        return n;
    }

    // IsoSurface::Function_Find_Root: the first root in [t1, t2] into t1.
    bool find_root(Search& s, double& t1, double t2) const {
        Pair a{t1, along(s, t1)};
        if (iso_.open && a.f < 0.0) {
            s.inv = -s.inv;
            a.f = -a.f;
        }
        const Pair b{t2, along(s, t2)};
        const double t21 = t2 - t1;
        if (iso_.evaluate && s.maxg > iso_.eval_params.x) s.maxg *= iso_.eval_params.z;
        const double dt = s.maxg * s.vlength * t21;
        double root = 0.0;
        if (!find_root_r(s, a, b, dt, t21, 1.0 / (s.vlength * t21), root)) return false;
        t1 = root;
        return true;
    }

    // IsoSurface::Function_Find_Root_R: halve [a, b] while the function could reach zero in
    // it (the ends' values sum below what max_gradient allows over its length), first half
    // first, down to `accuracy`.
    bool find_root_r(Search& s, const Pair& a, const Pair& b, double dt, double t21, double len,
                     double& root) const {
        if (iso_.evaluate) {
            const double slope = std::abs((b.f - a.f) * len);
            if (s.maxg < slope * iso_.eval_params.y) {
                s.maxg = slope * iso_.eval_params.y * iso_.eval_params.y;
                dt = s.maxg * s.vlength * t21;
            }
        }
        if (t21 < iso_.accuracy) {
            if (b.f < 0.0) {
                root = b.t;
                return true;
            }
            return false;
        }
        if (a.f + b.f - dt >= 0.0) return false;
        if (--s.steps_left < 0) return false;  // the bound on a ray's work: a miss
        ++t_root_search_steps;
        t21 *= 0.5;
        dt *= 0.5;
        const Pair m{a.t + t21, along(s, a.t + t21)};
        return find_root_r(s, a, m, dt, t21, len * 2.0, root) ||
               find_root_r(s, m, b, dt, t21, len * 2.0, root);
    }

    Isosurface iso_;
    FunctionEnv env_;
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
};

}  // namespace

long root_search_steps_on_this_thread() { return t_root_search_steps; }

Result<std::shared_ptr<const ComplexShape>> prepare_isosurface(const Isosurface& iso,
                                                               const Primitive& p) {
    if (!iso.function) {
        return make_error(primitive_place(p) + "isosurface: its function is not one mirage "
                                               "evaluates");
    }
    if (iso.sphere_container && !(iso.radius > 0.0)) {
        return make_error(primitive_place(p) + "isosurface: the container sphere's radius "
                                               "must be > 0, got " +
                          std::to_string(iso.radius));
    }
    return std::shared_ptr<const ComplexShape>(
        std::make_shared<IsosurfaceShape>(iso, p.transform));
}

}  // namespace mirage
