#include "paths/path_diagram.h"

#include <cmath>
#include <cstdint>
#include <memory>

#include "atmosphere/phase_screens.h"
#include "trace/curved_propagator.h"
#include "util/format.h"
#include "util/output_set.h"

namespace mirage {

namespace {

// The elevation of the fan's j-th ray, rad.
double fan_elevation(const RayDiagramSettings& st, int j) {
    const double f = st.count == 1 ? 0.5 : double(j) / (st.count - 1);
    return (st.elev_from_deg + f * (st.elev_to_deg - st.elev_from_deg)) * M_PI / 180;
}

// The tracer's settings for the fan's rays through one realization of the screens: the one
// place the path command reaches into the tracer.
CurvedSettings turbulent_settings(const RayDiagramSettings& st, const glm::dvec3& eye,
                                  PhaseScreens screens) {
    CurvedSettings cs;
    cs.atmosphere = st.atmosphere;
    cs.tolerance_rad = st.tolerance_rad;
    cs.tolerance_m = st.tolerance_m;
    cs.max_dz = st.max_distance;
    cs.eye = eye;
    cs.turbulence = std::make_shared<const PhaseScreens>(std::move(screens));
    return cs;
}

// The followed points of one ray in its vertical plane (dz, y), cut where they reach the ground.
OverlaidRay ray_to_ground(int fan_ray, const std::vector<glm::dvec3>& points) {
    OverlaidRay ray;
    ray.fan_ray = fan_ray;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const glm::dvec3& p = points[k];
        if (p.y < 0.0 && k > 0) {  // to the ground, then no further
            const glm::dvec3& a = points[k - 1];
            const double u = a.y / (a.y - p.y);
            ray.points.push_back({a.z + u * (p.z - a.z), 0.0});
            break;
        }
        ray.points.push_back({p.z, p.y});
    }
    return ray;
}

}  // namespace

RayDiagramSettings fan_diagram_settings(const PathOptions& o, const PathAir& air, double elev_deg) {
    RayDiagramSettings st;
    st.atmosphere = air.atmosphere;
    st.profile_label = air.label;
    st.legend = air.legend;
    st.eye_height = o.eye_height;
    const double span = std::max(std::fabs(elev_deg), 1e-3);
    st.elev_from_deg =
        std::isnan(o.fan_from_deg) ? (elev_deg < 0 ? 2.0 * elev_deg : -span) : o.fan_from_deg;
    st.elev_to_deg =
        std::isnan(o.fan_to_deg) ? (elev_deg < 0 ? 0.25 * span : 2.0 * span) : o.fan_to_deg;
    st.count = o.fan_count;
    st.tolerance_rad = o.tolerance_rad;
    st.tolerance_m = o.tolerance_m;
    if (std::isfinite(o.max_distance)) {
        st.max_distance = o.max_distance;
        return st;
    }
    // Far enough to show every turn and ground hit of the fan.
    const Atmosphere& atm = air.atmosphere;
    double reach = 10.0 * o.eye_height;
    for (int j = 0; j < st.count; ++j) {
        auto ray = ExactPath::make(atm, flattened_height(o.eye_height, atm.earth_radius()),
                                   M_PI / 2 - fan_elevation(st, j));
        if (!ray) continue;
        if (ray->turning_point_count() != 0)
            reach = std::max(reach, 1.6 * ray->turning_point(0).dz);
        if (ray->hits_ground()) reach = std::max(reach, 1.1 * ray->dz_ground());
    }
    st.max_distance = std::min(reach, 1e6);
    return st;
}

Status add_perturbed_rays(const PathOptions& o, RayDiagramSettings& st) {
    TurbulenceSettings t;
    t.cn2 = o.turbulence_cn2;
    if (!std::isnan(o.turbulence_inner)) t.inner_scale_m = o.turbulence_inner;
    if (!std::isnan(o.turbulence_outer)) t.outer_scale_m = o.turbulence_outer;
    if (!(o.turbulence_seed >= 0.0 && o.turbulence_seed <= 4294967295.0 &&
          std::floor(o.turbulence_seed) == o.turbulence_seed))
        return make_error("--turbulence-seed " + shortest(o.turbulence_seed) +
                          ": must be a whole number from 0 to 4294967295");
    if (auto c = check_turbulence(t); !c)
        return make_error("--turbulence-cn2 and its options: " + c.message());
    if (!(t.cn2 > 0.0)) return make_error("--turbulence-cn2 0: nothing to draw (give more than 0)");
    const glm::dvec3 eye(0.0, flattened_height(o.eye_height, st.atmosphere.earth_radius()), 0.0);
    ScreenLayout layout;
    layout.origin = eye;
    layout.reach_m = st.max_distance;
    layout.aperture_m = o.turbulence_aperture;
    if (auto c = check_screen_layout(layout); !c)
        return make_error("--turbulence-aperture: " + c.message());
    for (int r = 0; r < o.realizations; ++r) {
        t.seed = static_cast<std::uint64_t>(o.turbulence_seed) + r;
        auto screens = PhaseScreens::make(t, layout);
        if (!screens) return screens.error();
        const CurvedSettings cs = turbulent_settings(st, eye, std::move(*screens));
        for (int j = 0; j < st.count; ++j) {
            const double e = fan_elevation(st, j);
            st.overlaid.push_back(
                ray_to_ground(j, followed_points(cs, eye, glm::dvec3(0.0, std::sin(e), std::cos(e)),
                                                 st.max_distance)));
        }
    }
    st.overlaid_label = "through turbulent air, C_n^2 " + shortest(t.cn2) + " m^-2/3, " +
                        std::to_string(o.realizations) + " realizations";
    return Ok{};
}

Status write_fan_diagram(const PathOptions& o, const PathAir& air, double elevation_deg) {
    RayDiagramSettings st = fan_diagram_settings(o, air, elevation_deg);
    if (!std::isnan(o.turbulence_cn2))
        if (auto s = add_perturbed_rays(o, st); !s) return s;
    auto svg = ray_diagram_svg(st);
    if (!svg) return svg.error();
    OutputSet outputs(path_input_files(o));
    if (auto s = outputs.write_text(o.svg, *svg); !s) return s;
    return outputs.commit();
}

}  // namespace mirage
