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
        // Unit directions and scene-sized distances: no overflow for hypot to guard against.
        const double hlen = std::sqrt(d.x * d.x + d.z * d.z);
        const double t_scene =
            in_scene && hlen > 0.0
                ? distance_to_box_edge(scene, p.x, p.z, d.x / hlen, d.z / hlen) / hlen
                : kInf;
        const double t_layers =
            hlen > 0.0 ? distance_to_box_edge(layers, p.x, p.z, d.x / hlen, d.z / hlen) / hlen
                       : kInf;
        if (objects) {
            const double reach = std::min(t_plane, t_layers);
            if (auto hit = (*objects)(p, d, std::isfinite(reach) ? reach : 1e30)) {
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
        if (in_scene && t_scene <= t_plane) {
            out.scene_point = p + t_scene * d;
            out.scene_dir = d;
            in_scene = false;
        }
        if (t_layers <= t_plane || !std::isfinite(t_plane)) {
            out.sky = d.y > 0.0;
            out.final_dir = d;
            return out;
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
        // Snell's law at the horizontal boundary, with POV-Ray's ratio eta = n_from / n_to.
        // POV-Ray passes a boundary of ratio 1 without refracting or spending a trace level.
        const double eta =
            opt.pov_precision ? pov_ior_ratio(s, k_cam, k, next) : s.index(k) / s.index(next);
        if (std::fabs(eta - 1.0) < 1e-10) {
            k = next;
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
        }
    }
}

}  // namespace mirage
