#include "report/transfer_diagram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "atmosphere/general_profile.h"
#include "report/gnuplot_run.h"
#include "report/svg.h"
#include "util/atomic_file.h"
#include "util/format.h"

namespace mirage {

namespace {

constexpr double kArcmin = M_PI / (180.0 * 60.0);


}  // namespace

double true_elevation(double h0, double h, double d, double R) {
    if (R <= 0.0) return std::atan2(h - h0, d);
    const double phi = d / R;
    return std::atan2((R + h) * std::cos(phi) - (R + h0), (R + h) * std::sin(phi));
}

Result<TransferCurve> transfer_curve(const TransferSettings& st) {
    if (!(st.eye_height > 0.0 && std::isfinite(st.eye_height)))
        return make_error("eye height " + shortest(st.eye_height) + " m must be above the ground");
    if (!(st.distance > 0.0 && std::isfinite(st.distance)))
        return make_error("transfer distance " + shortest(st.distance) + " m must be > 0");
    if (!(st.from_deg < st.to_deg && st.from_deg > -90.0 && st.to_deg < 90.0))
        return make_error("transfer elevations " + shortest(st.from_deg) + " to " +
                          shortest(st.to_deg) + " deg must increase within (-90, 90)");
    if (!(st.count >= 2 && st.count <= 1000000))
        return make_error("transfer ray count " + std::to_string(st.count) +
                          " must be 2 to 1000000");
    const double R = st.atmosphere.earth_radius();
    const double y0 = flattened_height(st.eye_height, R);
    TransferCurve curve;
    for (int k = 0; k < st.count; ++k) {
        const double e =
            (st.from_deg + (st.to_deg - st.from_deg) * k / (st.count - 1)) * M_PI / 180.0;
        auto path = ExactPath::make(st.atmosphere, y0, M_PI / 2 - e);
        if (!path) return path.error();
        TransferPoint p;
        p.apparent_rad = e;
        p.reached = !(path->hits_ground() && path->dz_ground() < st.distance);
        if (p.reached) {
            p.height_m = height_above_sphere(path->height_at(st.distance), R);
            p.true_rad = true_elevation(st.eye_height, p.height_m, st.distance, R);
        }
        curve.points.push_back(p);
    }
    // Images: how many rays reach each target height (crossings of the curve's height).
    std::vector<double> heights;
    for (const auto& p : curve.points)
        if (p.reached) heights.push_back(p.height_m);
    std::sort(heights.begin(), heights.end());
    for (size_t k = 0; k + 1 < heights.size(); k += std::max<size_t>(1, heights.size() / 2000)) {
        const double h = 0.5 * (heights[k] + heights[k + 1]);
        int crossings = 0;
        for (size_t j = 0; j + 1 < curve.points.size(); ++j) {
            const auto &a = curve.points[j], &b = curve.points[j + 1];
            if (a.reached && b.reached && (a.height_m - h) * (b.height_m - h) < 0.0) ++crossings;
        }
        if (crossings > curve.max_images) {
            curve.max_images = crossings;
            curve.max_images_height_m = h;
        }
    }
    return curve;
}

std::string transfer_gnuplot_script(const TransferSettings& st, const TransferCurve& curve,
                                    const ProfilePanel& panel, const std::string& svg_out,
                                    const std::string& png_out) {
    std::ostringstream gp;
    gp << "# Transfer curve and profile, written by mirage path --transfer.\n";
    // The profile over the heights the rays reach, and the eye's.
    double h_top = st.eye_height;
    for (const auto& p : curve.points)
        if (p.reached) h_top = std::max(h_top, p.height_m);
    h_top = std::max(1.3 * h_top, st.eye_height + 1.0);
    for (const auto& d : panel.ducts)
        h_top = std::max(h_top, std::min(1.2 * d.second, 4.0 * h_top));
    const bool temps = static_cast<bool>(panel.temperature_k);
    gp << "$profile << EOD\n";
    double v_lo = 1e300, v_hi = -1e300;
    for (int k = 0; k <= 800; ++k) {
        const double h = h_top * k / 800.0;
        const double v = temps ? panel.temperature_k(h) - 273.15 : 1e6 * panel.refractivity(h);
        v_lo = std::min(v_lo, v);
        v_hi = std::max(v_hi, v);
        gp << sig(v, 12) << ' ' << sig(h, 10) << '\n';
    }
    // Three or four ticks on the narrow profile panel.
    const auto ticks = nice_ticks(v_lo, v_hi, 3);
    const double tick_step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
    gp << "EOD\n$transfer << EOD\n";
    bool gap = false;
    for (const auto& p : curve.points) {
        if (!p.reached) {
            if (!gap) gp << '\n';  // a blank line breaks the curve where rays meet the ground
            gap = true;
            continue;
        }
        gap = false;
        gp << sig(p.true_rad / kArcmin, 12) << ' ' << sig(p.apparent_rad / kArcmin, 12) << ' '
           << sig(p.height_m, 10) << '\n';
    }
    gp << "EOD\n\n";
    double lo = 1e300, hi = -1e300;
    for (const auto& p : curve.points) {
        lo = std::min(lo, p.apparent_rad / kArcmin);
        hi = std::max(hi, p.apparent_rad / kArcmin);
    }
    const std::string title = "Transfer curve at " + sig(st.distance, 6) + " m, eye at " +
                              sig(st.eye_height, 6) + " m" +
                              (st.atmosphere.earth_radius() > 0.0 ? " (curved Earth)" : "");
    std::ostringstream plot;
    plot << "set multiplot layout 1,2 title " << gnuplot_quoted(title) << " noenhanced\n"
         << "set size 0.36,0.92\nset origin 0.0,0.0\n"
         << "set title " << gnuplot_quoted(panel.label) << " noenhanced font \",10\"\n"
         << "set xlabel " << gnuplot_quoted(temps ? "temperature (degC)" : "(n - 1) x 1e6") << "\n"
         << "set ylabel \"height (m)\"\nset yrange [0:" << sig(h_top, 8) << "]\nset autoscale x\n"
         << "set xtics " << sig(tick_step, 6) << "\n"
         << "set grid lc rgb \"#dddddd\"\nunset key\n";
    int obj = 1;
    for (const auto& d : panel.ducts) {
        plot << "set object " << obj++ << " rect from graph 0, first " << sig(d.first, 8)
             << " to graph 1, first " << sig(std::min(d.second, h_top), 8)
             << " fc rgb \"#f3ecd2\" fs solid 1.0 noborder behind\n";
    }
    plot << "set arrow 1 from graph 0, first " << sig(st.eye_height, 8) << " to graph 1, first "
         << sig(st.eye_height, 8) << " nohead dt 2 lc rgb \"#555555\"\n"
         << "plot $profile using 1:2 with lines lw 2 lc rgb \"#1f77b4\"\n";
    for (int k = 1; k < obj; ++k) plot << "unset object " << k << "\n";
    plot << "unset arrow 1\n"
         << "set size 0.64,0.92\nset origin 0.36,0.0\n"
         << "set title \"apparent against true elevation of points at the distance\" font \",10\"\n"
         << "set xtics autofreq\n"
         << "set xlabel \"true elevation (arcmin)\"\nset ylabel \"apparent elevation (arcmin)\"\n"
         << "set yrange [" << sig(lo, 8) << ":" << sig(hi, 8) << "]\nset autoscale x\n"
         << "set key top left box opaque\n"
         << "plot $transfer using 1:2 with lines lw 2 lc rgb \"#d62728\" title \"exact rays\", \\\n"
         << "     x with lines dt 2 lc rgb \"#777777\" title \"no refraction\"\n"
         << "unset multiplot\n";
    if (!png_out.empty()) {
        gp << "if (strstrt(GPVAL_TERMINALS, \"pngcairo\") > 0) {\n"
           << "    set terminal pngcairo size 1200,560 font \"DejaVu Sans,11\"\n"
           << "} else {\n    set terminal png size 1200,560\n}\n"
           << "set output " << gnuplot_quoted(png_out) << "\n"
           << plot.str() << "set output\n";
    }
    if (!svg_out.empty()) {
        gp << "set terminal svg size 1200,560 dynamic font \"DejaVu Sans,11\"\n"
           << "set output " << gnuplot_quoted(svg_out) << "\n"
           << plot.str() << "set output\n";
    }
    return gp.str();
}

Status draw_transfer_diagram(const TransferSettings& st, const TransferCurve& curve,
                             const ProfilePanel& panel, OutputSet& outputs,
                             const std::string& svg_path, const std::string& png_path,
                             const std::string& gnuplot) {
    namespace fs = std::filesystem;
    // gnuplot writes the outputs' temporary names; the caller's commit() renames them into
    // place, and an OutputSet destroyed uncommitted (gnuplot failed) removes them.
    auto abs = [](const std::string& p) { return fs::absolute(p).string(); };
    std::string svg_tmp, png_tmp;
    if (!svg_path.empty()) {
        auto t = outputs.stage(svg_path);
        if (!t) return t.error();
        svg_tmp = abs(*t);
    }
    if (!png_path.empty()) {
        auto t = outputs.stage(png_path);
        if (!t) return t.error();
        png_tmp = abs(*t);
    }
    const std::string anchor = !svg_path.empty() ? svg_path : png_path;
    std::vector<std::string> expected;
    for (const std::string* t : {&svg_tmp, &png_tmp})
        if (!t->empty()) expected.push_back(*t);
    return run_gnuplot(gnuplot, transfer_gnuplot_script(st, curve, panel, svg_tmp, png_tmp),
                       anchor, expected, "the transfer diagram");
}

}  // namespace mirage
