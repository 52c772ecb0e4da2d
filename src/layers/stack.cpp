#include "layers/stack.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/check.h"

namespace mirage {

int LayerStack::layer_at(double y) const {
    return static_cast<int>(std::upper_bound(heights.begin(), heights.end(), y) - heights.begin());
}

double LayerStack::index(int k) const {
    return std::sqrt(profile.eta0 * profile.eta0 + excess.at(k));
}

LayerStack with_gaps(const LayerStack& s, double camera_y, double gap) {
    const int k_cam = s.layer_at(camera_y);
    const double u_cam = s.excess[k_cam];
    LayerStack g;
    g.profile = s.profile;
    g.excess.push_back(s.excess[0]);
    g.air.push_back(0);
    for (int j = 0; j < s.boundaries(); ++j) {
        const bool touches_camera = j == k_cam - 1 || j == k_cam;
        if (touches_camera) {
            g.heights.push_back(s.heights[j]);
        } else {
            g.heights.push_back(s.heights[j] - 0.5 * gap);
            g.excess.push_back(u_cam);
            g.air.push_back(1);
            g.heights.push_back(s.heights[j] + 0.5 * gap);
        }
        g.excess.push_back(s.excess[j + 1]);
        g.air.push_back(0);
    }
    return g;
}

float pov_relative_ior(const LayerStack& s, int k_cam, int k) {
    return static_cast<float>(s.index(k) / s.index(k_cam));
}

LayerStack merge_invisible_boundaries(const LayerStack& s, double camera_y) {
    const int k_cam = s.layer_at(camera_y);
    const int N = s.boundaries();
    std::vector<int> kept;  // boundaries with different float iors on their two sides
    for (int j = 0; j < N; ++j)
        if (pov_relative_ior(s, k_cam, j) != pov_relative_ior(s, k_cam, j + 1)) kept.push_back(j);
    LayerStack m;
    m.profile = s.profile;
    for (size_t r = 0; r <= kept.size(); ++r) {
        // Run r: layers first..last between kept boundaries r - 1 and r.
        const int first = r == 0 ? 0 : kept[r - 1] + 1;
        const int last = r == kept.size() ? N : kept[r];
        const int k = k_cam >= first && k_cam <= last ? k_cam : (last < k_cam ? last : first);
        m.excess.push_back(s.excess[k]);
        if (!s.air.empty()) m.air.push_back(s.air[k]);
        if (r < kept.size()) m.heights.push_back(s.heights[kept[r]]);
    }
    return m;
}

bool well_formed(const LayerStack& s) {
    if (s.excess.size() != s.heights.size() + 1) return false;
    if (!s.air.empty() && s.air.size() != s.excess.size()) return false;
    for (size_t k = 0; k < s.heights.size(); ++k) {
        if (!(s.heights[k] > 0.0) || !std::isfinite(s.heights[k])) return false;
        if (k > 0 && !(s.heights[k] > s.heights[k - 1])) return false;
    }
    for (double u : s.excess)
        if (!std::isfinite(u) || s.profile.eta0 * s.profile.eta0 + u <= 0.0) return false;
    return true;
}

BandOutcome trace_band(const LayerStack& s, double y0, double elevation, double scene_dz,
                       double layers_dz, int max_events) {
    MIRAGE_CHECK(y0 > 0.0 && scene_dz > 0.0 && layers_dz >= scene_dz);
    const double eta0_sq = s.profile.eta0 * s.profile.eta0;
    int k = s.layer_at(y0);
    const double n2 = eta0_sq + s.excess[k];
    const double sin_e = std::sin(elevation);
    // Invariant: beta^2 = n^2 cos^2 e; B = beta^2 - eta0^2.  In layer j the slope is
    // sqrt(excess_j - B) / beta; a layer with excess_j <= B reflects the ray.
    const double B = s.excess[k] - n2 * sin_e * sin_e;
    const double beta = std::sqrt(eta0_sq + B);
    int dir = elevation >= 0.0 ? 1 : -1;
    const int top = s.boundaries();
    double z = 0.0, y = y0;
    BandOutcome out;
    bool in_scene = true;
    for (int events = 0;; ++events) {
        const double slope = std::sqrt(std::max(0.0, s.excess[k] - B)) / beta;
        if (events >= max_events) {
            out.cut_off = true;
            if (in_scene) {
                out.dz = z;
                out.y = y;
                out.slope = dir * slope;
            }
            return out;
        }
        const bool to_ground = dir < 0 && k == 0;
        const bool to_sky = dir > 0 && k == top;
        double target = 0.0;
        if (!to_sky) target = dir > 0 ? s.heights[k] : (k == 0 ? 0.0 : s.heights[k - 1]);
        const double run = (to_sky || slope == 0.0) ? std::numeric_limits<double>::infinity()
                                                    : std::fabs(target - y) / slope;
        if (in_scene && z + run >= scene_dz) {
            out.dz = scene_dz;
            out.y = y + dir * slope * (scene_dz - z);
            out.slope = dir * slope;
            in_scene = false;
        }
        if (z + run >= layers_dz || to_sky) {
            // Straight from here on: it rises to the sky, or comes down to the ground.
            out.sky = dir > 0 && slope > 0.0;
            out.final_slope = dir * slope;
            return out;
        }
        z += run;
        y = target;
        if (to_ground) {
            if (in_scene) {
                out.ground = true;
                out.dz = z;
                out.y = 0.0;
            }
            return out;
        }
        const int next = k + dir;
        if (s.excess[next] == s.excess[k]) {  // no index step: POV-Ray passes it freely
            k = next;
            continue;
        }
        ++out.crossings;
        if (s.excess[next] > B) {
            k = next;
        } else {
            dir = -dir;  // total internal reflection
        }
    }
}

}  // namespace mirage
