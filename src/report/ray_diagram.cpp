#include "report/ray_diagram.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "atmosphere/exact_ray.h"
#include "atmosphere/sampler.h"
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
    ExactRay ray;
    SampledPath path;
    std::vector<glm::dvec2> curve;  // dense exact curve, clipped to the ground
};

}  // namespace

Result<std::string> ray_diagram_svg(const RayDiagramSettings& st) {
    if (!(st.count >= 1 && st.count <= kMaxFanRays))
        return make_error("ray count " + std::to_string(st.count) + " must be 1 to " +
                          std::to_string(kMaxFanRays));
    if (!(st.max_distance > 0.0)) return make_error("the drawn distance must be > 0 m");
    if (!(st.eye_height > 0.0)) return make_error("the eye must be above the ground");
    std::vector<DrawnRay> rays;
    double y_top = st.eye_height * 1.25;
    for (int j = 0; j < st.count; ++j) {
        const double t = st.count == 1 ? 0.5 : double(j) / (st.count - 1);
        const double elev =
            (st.elev_from_deg + t * (st.elev_to_deg - st.elev_from_deg)) * M_PI / 180;
        auto ray = make_exact_ray(st.profile, st.eye_height, M_PI / 2 - elev);
        if (!ray) return ray.error();
        SampleSettings ss;
        ss.tolerance_rad = st.tolerance_rad;
        ss.tolerance_m = st.tolerance_m;
        ss.max_dz = st.max_distance;
        DrawnRay d{*ray, sample_path(*ray, ss), {}};
        const double end =
            ray->hits_ground ? std::min(ray->dz_ground, st.max_distance) : st.max_distance;
        const int n = 600;
        for (int k = 0; k <= n; ++k) {
            const double dz = end * k / n;
            d.curve.push_back({dz, k == n && ray->hits_ground && end == ray->dz_ground
                                       ? 0.0
                                       : height_at(*ray, dz)});
        }
        for (const auto& p : d.curve) y_top = std::max(y_top, std::min(p.y, 50.0 * st.eye_height));
        rays.push_back(std::move(d));
    }
    y_top *= 1.08;

    const double left = 70, top = 50, right = 230, bottom = 60;
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
    s << f.axes("horizontal distance from the eye (m)", "height (m)");
    // Ground.
    s << "<rect x=\"" << f.left << "\" y=\"" << f.py(0.0) - 3 << "\" width=\"" << f.width
      << "\" height=\"3\" fill=\"#b08850\"/>\n";
    s << "<g clip-path=\"url(#plot)\" fill=\"none\" stroke-width=\"1.4\">\n";
    for (size_t j = 0; j < rays.size(); ++j) {
        const double t = rays.size() == 1 ? 0.5 : double(j) / (rays.size() - 1);
        const auto& d = rays[j];
        s << "<polyline stroke=\"" << fan_colour(t) << "\" points=\"";
        for (const auto& p : d.curve) s << f.px(p.x) << "," << f.py(p.y) << " ";
        s << "\"/>\n";
    }
    s << "</g>\n<g clip-path=\"url(#plot)\">\n";
    for (size_t j = 0; j < rays.size(); ++j) {
        const double t = rays.size() == 1 ? 0.5 : double(j) / (rays.size() - 1);
        const auto& d = rays[j];
        for (const auto& p : d.path.points)
            s << "<circle cx=\"" << f.px(p.x) << "\" cy=\"" << f.py(p.y) << "\" r=\"2.2\" fill=\""
              << fan_colour(t) << "\"/>\n";
        if (d.path.turns) {
            const double x = f.px(d.path.dz_turn), y = f.py(height_at(d.ray, d.path.dz_turn));
            s << "<path d=\"M" << x << "," << y - 6 << " L" << x + 5 << "," << y << " L" << x << ","
              << y + 6 << " L" << x - 5 << "," << y << " Z\" fill=\"none\" stroke=\"#000\"/>\n";
        }
        if (d.ray.hits_ground && d.ray.dz_ground <= st.max_distance) {
            const double x = f.px(d.ray.dz_ground), y = f.py(0.0);
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
    line("eta0 = " + tick_label(st.profile.eta0) + ", eta1 = " + tick_label(st.profile.eta1));
    line("alpha = " + tick_label(st.profile.alpha) + " /m");
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
    s << "</svg>\n";
    return s.str();
}

}  // namespace mirage
