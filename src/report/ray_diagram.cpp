#include "report/ray_diagram.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "atmosphere/general_profile.h"
#include "atmosphere/path_sampler.h"
#include "report/svg.h"

namespace mirage {

namespace {

// Blue (downward) through grey to red (upward), by position in the fan.
std::string fan_colour(double t) {
    const int r = static_cast<int>(40 + 190 * t);
    const int g = static_cast<int>(90 + 40 * (1.0 - std::fabs(2.0 * t - 1.0)));
    const int b = static_cast<int>(220 - 180 * t);
    char buf[16];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
    return buf;
}

struct DrawnRay {
    SampledPath path;
    std::vector<glm::dvec2> curve;  // dense exact curve, clipped to the ground
    std::vector<glm::dvec2> turns;  // turning points within the drawn distance
    bool ground = false;
    double dz_ground = 0.0;
};

}  // namespace

Result<std::string> ray_diagram_svg(const RayDiagramSettings& st) {
    if (!(st.count >= 1 && st.count <= kMaxFanRays))
        return make_error("ray count " + std::to_string(st.count) + " must be 1 to " +
                          std::to_string(kMaxFanRays));
    if (!(st.max_distance > 0.0)) return make_error("the drawn distance must be > 0 m");
    if (!(st.eye_height > 0.0)) return make_error("the eye must be above the ground");
    const double R = st.atmosphere.earth_radius();
    auto phys = [&](double y) { return height_above_sphere(y, R); };
    std::vector<DrawnRay> rays;
    double y_top = st.eye_height * 1.25;
    for (int j = 0; j < st.count; ++j) {
        const double t = st.count == 1 ? 0.5 : double(j) / (st.count - 1);
        const double elev =
            (st.elev_from_deg + t * (st.elev_to_deg - st.elev_from_deg)) * M_PI / 180;
        auto path =
            ExactPath::make(st.atmosphere, flattened_height(st.eye_height, R), M_PI / 2 - elev);
        if (!path) return path.error();
        SampleSettings ss;
        ss.tolerance_rad = st.tolerance_rad;
        ss.tolerance_m = st.tolerance_m;
        ss.max_dz = st.max_distance;
        DrawnRay d;
        d.path = sample_exact_path(*path, ss);
        d.ground = path->hits_ground() && path->dz_ground() <= st.max_distance;
        d.dz_ground = path->dz_ground();
        const double end = d.ground ? d.dz_ground : st.max_distance;
        const int n = 600;
        for (int k = 0; k <= n; ++k) {
            const double dz = end * k / n;
            d.curve.push_back({dz, k == n && d.ground ? 0.0 : phys(path->height_at(dz))});
        }
        const int count = path->turning_point_count();
        for (int k = 0; count != 0 && (count < 0 || k < count) && k < 400; ++k) {
            const TurningPoint tp = path->turning_point(k);
            if (tp.dz > end) break;
            d.turns.push_back({tp.dz, phys(tp.y)});
        }
        for (const auto& p : d.curve) y_top = std::max(y_top, std::min(p.y, 50.0 * st.eye_height));
        rays.push_back(std::move(d));
    }
    y_top *= 1.08;

    const double left = 70, top = 50, right = 250, bottom = 60;
    PlotFrame f{0.0,
                st.max_distance,
                0.0,
                y_top,
                left,
                top,
                st.width_px - left - right,
                st.height_px - top - bottom};
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << st.width_px << "\" height=\""
      << st.height_px << "\" viewBox=\"0 0 " << st.width_px << " " << st.height_px << "\">\n";
    s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << left << "\" y=\"28\" font-family=\"sans-serif\" font-size=\"16\">"
      << svg_escape("Rays from an eye at " + tick_label(st.eye_height) + " m, " + st.profile_label)
      << "</text>\n";
    s << "<clipPath id=\"plot\"><rect x=\"" << f.left << "\" y=\"" << f.top << "\" width=\""
      << f.width << "\" height=\"" << f.height << "\"/></clipPath>\n";
    // Ducts: the heights where level rays are trapped.
    if (const auto* q = st.atmosphere.quadratic_profile()) {
        for (const auto& duct : find_ducts(*q)) {
            const double lo = phys(duct.bottom), hi = std::min(phys(duct.top), y_top);
            if (lo >= y_top) continue;
            s << "<rect clip-path=\"url(#plot)\" x=\"" << f.left << "\" y=\"" << f.py(hi)
              << "\" width=\"" << f.width << "\" height=\"" << f.py(lo) - f.py(hi)
              << "\" fill=\"#f3ecd2\"/>\n";
        }
    }
    s << f.axes(R > 0.0 ? "distance along the ground from the eye (m)"
                        : "horizontal distance from the eye (m)",
                R > 0.0 ? "height above the sphere (m)" : "height (m)");
    // Ground.
    s << "<rect x=\"" << f.left << "\" y=\"" << f.py(0.0) - 3 << "\" width=\"" << f.width
      << "\" height=\"3\" fill=\"#b08850\"/>\n";
    s << "<g clip-path=\"url(#plot)\" fill=\"none\" stroke-width=\"1.4\">\n";
    for (size_t j = 0; j < rays.size(); ++j) {
        const double t = rays.size() == 1 ? 0.5 : double(j) / (rays.size() - 1);
        s << "<polyline stroke=\"" << fan_colour(t) << "\" points=\"";
        for (const auto& p : rays[j].curve) s << f.px(p.x) << "," << f.py(p.y) << " ";
        s << "\"/>\n";
    }
    s << "</g>\n";
    if (!st.overlaid.empty()) {
        s << "<g clip-path=\"url(#plot)\" fill=\"none\" stroke-width=\"0.7\" opacity=\"0.8\">\n";
        for (const OverlaidRay& r : st.overlaid) {
            const double t = rays.size() == 1 ? 0.5 : double(r.fan_ray) / (rays.size() - 1);
            s << "<polyline stroke=\"" << fan_colour(t) << "\" stroke-dasharray=\"3,2\" points=\"";
            for (const auto& p : r.points) s << f.px(p.x) << "," << f.py(phys(p.y)) << " ";
            s << "\"/>\n";
        }
        s << "</g>\n";
    }
    s << "<g clip-path=\"url(#plot)\">\n";
    for (size_t j = 0; j < rays.size(); ++j) {
        const double t = rays.size() == 1 ? 0.5 : double(j) / (rays.size() - 1);
        const auto& d = rays[j];
        for (const auto& p : d.path.points)
            s << "<circle cx=\"" << f.px(p.x) << "\" cy=\"" << f.py(phys(p.y))
              << "\" r=\"2.2\" fill=\"" << fan_colour(t) << "\"/>\n";
        for (const auto& tp : d.turns) {
            const double x = f.px(tp.x), y = f.py(tp.y);
            s << "<path d=\"M" << x << "," << y - 6 << " L" << x + 5 << "," << y << " L" << x << ","
              << y + 6 << " L" << x - 5 << "," << y << " Z\" fill=\"none\" stroke=\"#000\"/>\n";
        }
        if (d.ground) {
            const double x = f.px(d.dz_ground), y = f.py(0.0);
            s << "<path d=\"M" << x - 4 << "," << y - 4 << " L" << x + 4 << "," << y + 4 << " M"
              << x - 4 << "," << y + 4 << " L" << x + 4 << "," << y - 4
              << "\" stroke=\"#000\" stroke-width=\"1.5\"/>\n";
        }
    }
    s << "</g>\n";
    // Eye.
    s << "<circle cx=\"" << f.px(0.0) << "\" cy=\"" << f.py(st.eye_height)
      << "\" r=\"5\" fill=\"#000\"/>\n";
    // Legend.
    const double lx = f.left + f.width + 20;
    double ly = f.top + 10;
    auto line = [&](const std::string& text) {
        s << "<text x=\"" << lx << "\" y=\"" << ly
          << "\" font-family=\"sans-serif\" font-size=\"12\">" << svg_escape(text) << "</text>\n";
        ly += 18;
    };
    line("profile: " + st.profile_label);
    if (const auto* p = st.atmosphere.exponential_profile()) {
        line("eta0 = " + tick_label(p->eta0) + ", eta1 = " + tick_label(p->eta1));
        line("alpha = " + tick_label(p->alpha) + " /m");
    }
    for (const auto& l : st.legend) line(l);
    if (R > 0.0) line("Earth radius " + tick_label(R / 1000.0) + " km");
    line("eye height: " + tick_label(st.eye_height) + " m");
    line("elevations: " + tick_label(st.elev_from_deg) + " to " + tick_label(st.elev_to_deg) +
         " deg");
    line(std::to_string(st.count) + " rays");
    line("sampling tolerance: " + tick_label(st.tolerance_rad) + " rad");
    ly += 8;
    line("lines: exact paths");
    line("dots: polyline samples");
    line("diamonds: turning points");
    line("crosses: ground hits");
    if (!st.overlaid.empty()) line("dashed: " + st.overlaid_label);
    if (st.atmosphere.quadratic_profile() &&
        !find_ducts(*st.atmosphere.quadratic_profile()).empty())
        line("shaded: ducts (level rays trapped)");
    s << "</svg>\n";
    return s.str();
}

}  // namespace mirage
