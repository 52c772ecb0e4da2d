#include "report/refraction_table.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "util/format.h"
#include "report/gnuplot_run.h"

namespace mirage {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kArcsec = kDeg / 3600.0;

bool pulkovo_conditions(const RefractionTableOptions& o, double wavelength_nm) {
    return o.temperature_c + 273.15 == kPulkovoTemperatureK &&
           100.0 * o.pressure_hpa == kPulkovoPressurePa && wavelength_nm == kPulkovoWavelengthNm &&
           o.observer_height_m == 0.0;
}

Result<RefractionModel> model_for(const RefractionTableOptions& o, double wavelength_nm) {
    StandardAirSettings s;
    s.ground_temperature_k = o.temperature_c + 273.15;
    s.ground_pressure_pa = 100.0 * o.pressure_hpa;
    s.wavelength_nm = wavelength_nm;
    auto air = StandardAir::make(s);
    if (!air) return air.error();
    auto m = standard_air_model(*air);
    if (!m) return m.error();
    return RefractionModel{*air, *m};
}

std::string fixed(double v, int decimals) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
    return b;
}

}  // namespace

Result<RefractionTable> refraction_table(const RefractionTableOptions& o) {
    if (o.wavelengths_nm.empty()) return make_error("no wavelength asked");
    if (o.elevations_deg.empty()) return make_error("no elevation asked");
    for (double e : o.elevations_deg)
        if (!(e >= 0.0 && e < 90.0))
            return make_error("elevation " + shortest(e) + " degrees must be from 0 to 90");
    // StandardAir's ranges, in the units given.
    if (!(o.temperature_c + 273.15 >= kMinGroundTemperatureK &&
          o.temperature_c + 273.15 <= kMaxGroundTemperatureK))
        return make_error("temperature " + shortest(o.temperature_c) + " degC must be from " +
                          sig(kMinGroundTemperatureK - 273.15, 6) + " to " +
                          sig(kMaxGroundTemperatureK - 273.15, 6) + " degC");
    if (!(100.0 * o.pressure_hpa >= kMinGroundPressurePa &&
          100.0 * o.pressure_hpa <= kMaxGroundPressurePa))
        return make_error("pressure " + shortest(o.pressure_hpa) + " hPa must be from " +
                          shortest(kMinGroundPressurePa / 100.0) + " to " +
                          shortest(kMaxGroundPressurePa / 100.0) + " hPa");
    if (!(o.observer_height_m >= 0.0 && o.observer_height_m <= 10000.0))
        return make_error("observer height " + shortest(o.observer_height_m) +
                          " m must be from 0 to 10000 m");
    RefractionTable t;
    t.options = o;
    for (double nm : o.wavelengths_nm) {
        auto m = model_for(o, nm);
        if (!m) return m.error();
        std::vector<double> row;
        for (double e : o.elevations_deg) {
            auto r = refraction_by_path(m->air, m->atmosphere, o.observer_height_m, e * kDeg);
            if (!r) return r.error();
            row.push_back(*r);
        }
        t.refraction_rad.push_back(row);
        t.models.push_back(std::move(*m));
    }
    const auto tables = std::find_if(o.wavelengths_nm.begin(), o.wavelengths_nm.end(),
                                     [&o](double nm) { return pulkovo_conditions(o, nm); });
    if (tables != o.wavelengths_nm.end()) {
        t.tables_name = "Pulkovo tables (15 degC, 1013.25 hPa, 590 nm, sea level)";
        t.tables_wavelength = static_cast<size_t>(tables - o.wavelengths_nm.begin());
        for (double e : o.elevations_deg) t.tables_rad.push_back(pulkovo_refraction(e * kDeg));
    }
    return t;
}

std::string refraction_text(const RefractionTable& t) {
    const RefractionTableOptions& o = t.options;
    std::ostringstream s;
    s << "Astronomical refraction: the standard atmosphere (US 1976) from " << shortest(o.temperature_c)
      << " degC and " << shortest(o.pressure_hpa)
      << " hPa at the ground, dry, Ciddor's index; observer " << shortest(o.observer_height_m)
      << " m up; each ray followed by its exact path to 47 km on the curved Earth.\n\n";
    auto cell = [&s](const std::string& text) { s << std::string(text.size() < 16 ? 16 - text.size() : 1, ' ') << text; };
    s << "elevation (deg)";
    for (double nm : o.wavelengths_nm) cell(shortest(nm) + " nm (\")");
    if (o.wavelengths_nm.size() > 1)
        cell(shortest(o.wavelengths_nm.front()) + "-" + shortest(o.wavelengths_nm.back()) + " nm (\")");
    if (!t.tables_rad.empty()) {
        cell("tables (\")");
        cell("difference");
    }
    s << "\n";
    for (size_t j = 0; j < o.elevations_deg.size(); ++j) {
        const std::string e = sig(o.elevations_deg[j], 4);
        s << e << std::string(e.size() < 15 ? 15 - e.size() : 1, ' ');
        for (const auto& row : t.refraction_rad) cell(fixed(row[j] / kArcsec, 2));
        if (t.refraction_rad.size() > 1)
            cell(fixed((t.refraction_rad.front()[j] - t.refraction_rad.back()[j]) / kArcsec, 3));
        if (!t.tables_rad.empty()) {
            cell(fixed(t.tables_rad[j] / kArcsec, 2));
            cell(fixed(100.0 * (t.refraction_rad[t.tables_wavelength][j] / t.tables_rad[j] - 1.0),
                       3) +
                 " %");
        }
        s << "\n";
    }
    if (!t.tables_rad.empty()) s << "\ntables: " << t.tables_name << "\n";
    return s.str();
}

nlohmann::json refraction_json(const RefractionTable& t) {
    const RefractionTableOptions& o = t.options;
    nlohmann::json j;
    j["temperature_c"] = o.temperature_c;
    j["pressure_hpa"] = o.pressure_hpa;
    j["observer_height_m"] = o.observer_height_m;
    j["elevations_deg"] = o.elevations_deg;
    j["wavelengths_nm"] = o.wavelengths_nm;
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : t.refraction_rad) {
        nlohmann::json r = nlohmann::json::array();
        for (double v : row) r.push_back(v / kArcsec);
        rows.push_back(r);
    }
    j["refraction_arcsec"] = rows;
    if (!t.tables_rad.empty()) {
        nlohmann::json r = nlohmann::json::array();
        for (double v : t.tables_rad) r.push_back(v / kArcsec);
        j["tables_arcsec"] = r;
        j["tables"] = t.tables_name;
    }
    return j;
}

Status draw_refraction_plot(const RefractionTable& t, OutputSet& outputs, const std::string& png,
                            const std::string& gnuplot) {
    namespace fs = std::filesystem;
    const RefractionTableOptions& o = t.options;
    const double top = std::clamp(
        *std::max_element(o.elevations_deg.begin(), o.elevations_deg.end()), 1.0, 10.0);
    std::ostringstream gp;
    gp << "# Astronomical refraction, written by mirage refraction.\n";
    const int steps = 100;
    const size_t nw = o.wavelengths_nm.size();
    std::vector<std::vector<double>> curve(nw);  // arcseconds, per wavelength and step
    for (size_t w = 0; w < nw; ++w) {
        const RefractionModel& m = t.models[w];
        for (int k = 0; k <= steps; ++k) {
            auto r = refraction_by_path(m.air, m.atmosphere, o.observer_height_m,
                                        top * k / steps * kDeg);
            if (!r) return r.error();
            curve[w].push_back(*r / kArcsec);
        }
    }
    // Per wavelength: elevation, refraction (arcmin), and its excess over the last wavelength's
    // (arcsec).
    for (size_t w = 0; w < nw; ++w) {
        gp << "$w" << w << " << EOD\n";
        for (int k = 0; k <= steps; ++k)
            gp << sig(top * k / steps, 8) << ' ' << sig(curve[w][k] / 60.0, 10) << ' '
               << sig(curve[w][k] - curve[nw - 1][k], 10) << '\n';
        gp << "EOD\n";
    }
    const bool tables = !t.tables_rad.empty();
    if (tables) {
        gp << "$tables << EOD\n";
        for (int k = 0; k <= steps; ++k) {
            const double e = top * k / steps;
            gp << sig(e, 8) << ' ' << sig(pulkovo_refraction(e * kDeg) / kArcsec / 60.0, 10) << '\n';
        }
        gp << "EOD\n";
    }
    auto staged = outputs.stage(png);
    if (!staged) return staged.error();
    const std::string out = fs::absolute(*staged).string();
    gp << "set terminal pngcairo size 900," << (nw > 1 ? 900 : 560) << " font ',11'\nset output "
       << gnuplot_quoted(out) << "\n";
    if (nw > 1) gp << "set multiplot layout 2,1\n";
    gp << "set title 'Astronomical refraction through the standard atmosphere (" << shortest(o.temperature_c)
       << " degC, " << shortest(o.pressure_hpa) << " hPa)'\n"
       << "set xlabel 'apparent elevation (degrees)'\nset ylabel 'refraction (arcminutes)'\n"
       << "set grid\nset key top right\nplot ";
    const char* colours[] = {"#3060c0", "#30a040", "#d04030", "#9040b0", "#c08020"};
    for (size_t w = 0; w < o.wavelengths_nm.size(); ++w)
        gp << (w ? ", " : "") << "$w" << w << " using 1:2 with lines lw 2 lc rgb '"
           << colours[w % 5] << "' title 'mirage, " << shortest(o.wavelengths_nm[w]) << " nm'";
    if (tables)
        gp << ", $tables using 1:2 every 5 with points pt 6 ps 1.2 lc rgb 'black' title '"
           << t.tables_name << "'";
    gp << "\n";
    if (nw > 1) {
        gp << "set title 'How much higher each colour is seen than " << shortest(o.wavelengths_nm.back())
           << " nm'\nset ylabel 'separation (arcseconds)'\nplot ";
        for (size_t w = 0; w + 1 < nw; ++w)
            gp << (w ? ", " : "") << "$w" << w << " using 1:3 with lines lw 2 lc rgb '"
               << colours[w % 5] << "' title '" << shortest(o.wavelengths_nm[w]) << " nm'";
        gp << "\nunset multiplot\n";
    }
    return run_gnuplot(gnuplot, gp.str(), png, {out}, "the refraction plot");
}

}  // namespace mirage
