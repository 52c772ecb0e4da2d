#include "layers/band_tracer3d.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "util/check.h"

namespace mirage {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

double distance_to_box_edge(const HorizontalBox& b, double x, double z, double hx, double hz) {
    double t = kInf;
    if (hx > 0.0) t = std::min(t, (b.x1 - x) / hx);
    if (hx < 0.0) t = std::min(t, (b.x0 - x) / hx);
    if (hz > 0.0) t = std::min(t, (b.z1 - z) / hz);
    if (hz < 0.0) t = std::min(t, (b.z0 - z) / hz);
    return std::max(t, 0.0);
}

int pov_camera_layer(const LayerStack& s, double y, double camera_y) {
    return s.layer_at(std::isnan(camera_y) ? y : camera_y);
}

float pov_ior(const LayerStack& s, int k_cam, int k) { return pov_relative_ior(s, k_cam, k); }

double pov_ior_ratio(const LayerStack& s, int k_cam, int from, int to) {
    // Entering from the atmosphere (the camera's layer, a gap) or leaving into it, POV-Ray
    // divides its double atmosphere index by the float ior (or the float by it); between
    // two layers it divides one float ior by the other, in single precision (trace.cpp,
    // ComputeRefraction).
    auto air = [&](int k) { return k == k_cam || (!s.air.empty() && s.air[k]); };
    if (air(from) && air(to)) return 1.0;
    if (air(from)) return 1.0 / static_cast<double>(pov_ior(s, k_cam, to));
    if (air(to)) return static_cast<double>(pov_ior(s, k_cam, from));
    const float a = pov_ior(s, k_cam, from), b = pov_ior(s, k_cam, to);
    return static_cast<double>(a / b);
}

Trace3dOutcome trace_layers_3d(const LayerStack& s, const glm::dvec3& origin,
                               const glm::dvec3& dir_in, const HorizontalBox& scene,
                               const HorizontalBox& layers, const Trace3dOptions& opt) {
    const int max_events = opt.max_events;
    const ObjectQuery* objects = opt.objects;
    const double camera_y = opt.camera_y;
    MIRAGE_CHECK(origin.y >= 0.0);
    // The indices POV-Ray gets: each layer's index divided by the camera layer's, held as
    // single-precision floats (POV-Ray 3.7's Interior::IOR is SNGL); the camera's layer is
    // outside every plane, POV-Ray's atmosphere of index 1.
    const int k_cam = pov_camera_layer(s, origin.y, camera_y);

    Trace3dOutcome out;
    glm::dvec3 p = origin;
    glm::dvec3 d = glm::normalize(dir_in);
    int k = s.layer_at(origin.y);
    bool in_scene = true;
    const int top = s.boundaries();
    // Each layer but the camera's is an object of POV-Ray's within a box: those below the
    // camera's layer within `below`, the others within `layers`.  Outside its layer's box, and
    // in the camera's layer, a ray is in POV-Ray's atmosphere (`free`): k is then the layer
    // its height is in, and the next boundary refracts only where the layer beyond it is there.
    const HorizontalBox& below = opt.below ? *opt.below : layers;
    auto box_of = [&](int layer) -> const HorizontalBox& { return layer < k_cam ? below : layers; };
    bool free = k == k_cam || !box_of(k).contains(origin.x, origin.z);
    for (int events = 0;; ++events) {
        if (events >= max_events) {
            out.cut_off = true;
            return out;
        }
        // Next boundary along d, and the edges of the scene and of the layers.
        double t_plane = kInf;
        int next = k;
        if (d.y > 0.0 && k < top) {
            t_plane = (s.heights[k] - p.y) / d.y;
            next = k + 1;
        } else if (d.y < 0.0) {
            const double floor = k == 0 ? 0.0 : s.heights[k - 1];
            t_plane = (floor - p.y) / d.y;
            next = k - 1;  // -1: the ground
        }
        t_plane = std::max(t_plane, 0.0);
        // Unit directions and scene-sized distances: no overflow for hypot to guard against.
        const double hlen = std::sqrt(d.x * d.x + d.z * d.z);
        auto to_edge = [&](const HorizontalBox& b) {
            if (!b.contains(p.x, p.z)) return 0.0;
            return hlen > 0.0 ? distance_to_box_edge(b, p.x, p.z, d.x / hlen, d.z / hlen) / hlen
                              : kInf;
        };
        const double t_scene = in_scene ? (hlen > 0.0 ? to_edge(scene) : kInf) : kInf;
        // Inside a layer's box: where the ray leaves it sideways.  Free: whether the layer
        // beyond the boundary ahead is there where the ray meets it.
        const double t_box = free ? kInf : to_edge(box_of(k));
        bool present = true;
        if (free && next >= 0 && next != k_cam && std::isfinite(t_plane)) {
            const glm::dvec3 q = p + t_plane * d;
            present = box_of(next).contains(q.x, q.z);
        }
        const bool leaves_box = t_box <= t_plane;
        const double t_step = std::min(t_plane, t_box);
        if (objects) {
            if (auto hit = (*objects)(p, d, std::isfinite(t_step) ? t_step : 1e30)) {
                if (in_scene && t_scene < hit->t) {
                    out.scene_point = p + t_scene * d;
                    out.scene_dir = d;
                }
                out.object = hit;
                out.object_point = p + hit->t * d;
                out.object_dir = d;
                return out;
            }
        }
        if (in_scene && t_scene <= t_step) {
            out.scene_point = p + t_scene * d;
            out.scene_dir = d;
            in_scene = false;
        }
        if (!std::isfinite(t_step)) {
            // Straight on for good (every object ahead was asked for above, to 1e30).
            out.sky = d.y > 0.0;
            out.final_dir = d;
            return out;
        }
        if (leaves_box) {
            // Out of the layer's box into POV-Ray's atmosphere; its vertical face refracts by
            // the layer's index over the camera's, which leaves a near-horizontal ray's slope as
            // it was (not followed).
            p += t_box * d;
            free = true;
            continue;
        }
        p += t_plane * d;
        if (next < 0) {  // the ground
            if (in_scene) {
                out.ground = true;
                out.scene_point = glm::dvec3(p.x, 0.0, p.z);
                out.scene_dir = d;
            }
            return out;
        }
        if (free && (next == k_cam || !present)) {  // no object there: on in the atmosphere
            k = next;
            free = next == k_cam || !box_of(next).contains(p.x, p.z);
            continue;
        }
        // Snell's law at the horizontal boundary, with POV-Ray's ratio eta = n_from / n_to
        // (from the atmosphere when free, into it when entering the camera's layer).
        // POV-Ray passes a boundary of ratio 1 without refracting or spending a trace level.
        const int from = free ? k_cam : k;
        const double eta =
            opt.pov_precision ? pov_ior_ratio(s, k_cam, from, next) : s.index(from) / s.index(next);
        if (std::fabs(eta - 1.0) < 1e-10) {
            k = next;
            free = next == k_cam;
            continue;
        }
        ++out.crossings;
        const double ex = p.x - origin.x, ez = p.z - origin.z;
        out.last_event = std::sqrt(ex * ex + ez * ez);
        const glm::dvec3 normal(0.0, d.y > 0.0 ? -1.0 : 1.0, 0.0);  // facing the incoming ray
        const glm::dvec3 t = glm::refract(d, normal, eta);
        if (t == glm::dvec3(0.0)) {
            d = glm::reflect(d, normal);  // total internal reflection (GLM returns zero)
        } else {
            d = glm::normalize(t);
            k = next;
            free = next == k_cam;
        }
    }
}

}  // namespace mirage
