#include "paths/path_report.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "atmosphere/path_batch.h"
#include "atmosphere/path_sampler.h"
#include "atmosphere/vanishing.h"
#include "paths/path_diagram.h"
#include "report/transfer_diagram.h"
#include "util/csv.h"
#include "util/format.h"
#include "util/json_text.h"
#include "util/output_set.h"

namespace mirage {

namespace {

// Numbers in the reports: printf's %.10g.
std::string g(double v) { return sig(v, 10); }

// A table row of a text report, in printf's format.
template <class... Args>
std::string row(const char* format, Args... args) {
    char buf[160];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

Result<double> resolve_angle(const PathOptions& o) {
    if (!std::isnan(o.i_rad) && !std::isnan(o.elevation_deg))
        return make_error("give either --elevation-deg or --i-rad, not both");
    if (!std::isnan(o.i_rad)) return o.i_rad;
    if (!std::isnan(o.elevation_deg)) {
        if (!(std::fabs(o.elevation_deg) < 90.0))
            return make_error("--elevation-deg " + g(o.elevation_deg) +
                              ": must lie strictly between -90 and 90");
        return M_PI / 2 - o.elevation_deg * M_PI / 180.0;
    }
    return make_error("give the ray's direction with --elevation-deg DEG (or --i-rad RAD)");
}

// The eye, the ray's direction, the sampling tolerance and the distance of a single ray;
// returns the angle from the vertical.
Result<double> check_ray_flags(const PathOptions& o) {
    if (std::isnan(o.eye_height)) return make_error("give the eye height with --eye-height M");
    if (!(o.eye_height > 0.0 && o.eye_height <= kMaxHeight))
        return make_error("--eye-height " + g(o.eye_height) +
                          ": the eye must be above the ground (> 0 m) and at most " +
                          shortest(kMaxHeight) + " m");
    auto i = resolve_angle(o);
    if (!i) return i;
    if (!(o.tolerance_rad == 0.0 ||
          (o.tolerance_rad >= kMinToleranceRad && o.tolerance_rad <= 1.0)))
        return make_error("--tolerance " + g(o.tolerance_rad) + ": must be 0 or from " +
                          g(kMinToleranceRad) + " to 1 rad");
    if (!(o.tolerance_m == 0.0 || (o.tolerance_m >= kMinToleranceM && o.tolerance_m <= 1e9)))
        return make_error("--tolerance-m " + g(o.tolerance_m) + ": must be 0 or from " +
                          g(kMinToleranceM) + " to 1e+09 m");
    if (!(o.tolerance_rad > 0.0 || o.tolerance_m > 0.0))
        return make_error("--tolerance " + g(o.tolerance_rad) + " and --tolerance-m " +
                          g(o.tolerance_m) + ": need a positive tolerance");
    if (!(o.max_distance > 0.0))
        return make_error("--max-distance " + g(o.max_distance) + ": must be > 0 m");
    return i;
}

// One ray, traced and sampled: heights in its model's frame (flattened with an Earth radius).
struct TracedRay {
    double i_rad = 0.0;
    double elevation_deg = 0.0;
    double earth_radius = 0.0;
    ExactPath path;
    SampledPath samples;
    // The general form's turning points ahead: all of them for a path that turns once, the
    // first 20 of a trapped one.
    std::vector<TurningPoint> turns;

    double height(double y) const { return height_above_sphere(y, earth_radius); }
    const char* end_name() const {
        return samples.end == PathEnd::Ground     ? "ground"
               : samples.end == PathEnd::Straight ? "straight"
                                                  : "cut";
    }
};

std::vector<TurningPoint> turns_ahead(const ExactPath& path) {
    std::vector<TurningPoint> turns;
    const int count = path.turning_point_count();
    for (int k = 0; count != 0 && (count < 0 || k < count) && k < 20; ++k) {
        const TurningPoint t = path.turning_point(k);
        if (t.dz <= 0.0 && k == 0 && count > 0) break;
        if (path.hits_ground() && t.dz > path.dz_ground()) break;
        turns.push_back(t);
    }
    return turns;
}

Result<TracedRay> trace_ray(const PathOptions& o, const Atmosphere& atmosphere) {
    auto i = check_ray_flags(o);
    if (!i) return i.error();
    const double R = atmosphere.earth_radius();
    auto path = ExactPath::make(atmosphere, flattened_height(o.eye_height, R), *i);
    if (!path) return path.error();
    SampleSettings st;
    st.tolerance_rad = o.tolerance_rad;
    st.tolerance_m = o.tolerance_m;
    st.max_dz = o.max_distance;
    SampledPath samples = sample_exact_path(*path, st);
    std::vector<TurningPoint> turns = turns_ahead(*path);
    return TracedRay{*i,
                     (M_PI / 2 - *i) * 180.0 / M_PI,
                     R,
                     std::move(*path),
                     std::move(samples),
                     std::move(turns)};
}

nlohmann::json ray_json(const PathOptions& o, const PathAir& air, const TracedRay& t) {
    const ExactPath& path = t.path;
    nlohmann::json j;
    j["profile"] = air_json(air);
    j["eye_height"] = o.eye_height;
    j["elevation_deg"] = t.elevation_deg;
    j["i_rad"] = t.i_rad;
    j["eta_eye"] = path.eta_start();
    j["beta"] = path.beta();
    j["ray_class"] = path.class_name();
    if (air.form == AirForm::Reference) {
        // The closed forms' own quantities (the reference's columns).
        const ExactRay& ray = *path.exponential();
        auto number = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
        j["k2"] = ray.k2;
        j["turn_kind"] = turn_kind_name(ray.turn_kind);
        j["y_turn"] = number(ray.y_turn);
        j["dz_turn"] = number(ray.dz_turn);
    } else {
        const int count = path.turning_point_count();
        j["engine"] = "general";
        j["turn_count"] = count < 0 ? nlohmann::json("infinite") : nlohmann::json(count);
        nlohmann::json tj = nlohmann::json::array();
        for (const auto& p : t.turns)
            tj.push_back(
                {{"dz", p.dz}, {"y", t.height(p.y)}, {"kind", p.lowest ? "lowest" : "apex"}});
        j["turning_points"] = tj;
    }
    j["hits_ground"] = path.hits_ground();
    j["dz_ground"] = path.hits_ground() ? nlohmann::json(path.dz_ground()) : nlohmann::json();
    j["tolerance_rad"] = o.tolerance_rad;
    j["tolerance_m"] = o.tolerance_m;
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : t.samples.points) pts.push_back({p.x, t.height(p.y)});
    j["samples"] = pts;
    j["end"] = t.end_name();
    if (t.samples.end != PathEnd::Ground) j["end_slope"] = t.samples.end_slope;
    return j;
}

// The invariant and the turning points: the closed forms' (k2, the one turning point, ahead
// or not), or every one ahead.
void write_invariant_and_turns(const PathAir& air, const TracedRay& t, std::ostream& out) {
    const ExactPath& path = t.path;
    if (air.form == AirForm::Reference) {
        const ExactRay& ray = *path.exponential();
        out << "invariant   beta = eta(y0) sin i = " << shortest(ray.beta)
            << " (eta(y0) = " << shortest(ray.eta_p) << ", k2 = " << shortest(ray.k2) << ")\n";
        out << "class       " << path.class_name() << "\n";
        if (ray.turn_kind == TurnKind::None) {
            out << "turning     none\n";
        } else {
            out << "turning     " << (ray.s > 0 ? "lowest point" : "apex")
                << " y = " << g(ray.y_turn) << " m at dz = " << g(ray.dz_turn) << " m ("
                << turn_kind_name(ray.turn_kind) << ")\n";
        }
        return;
    }
    out << "invariant   beta = n(y0) sin i = " << shortest(path.beta())
        << " (n(y0) = " << shortest(path.eta_start()) << ")\n";
    out << "class       " << path.class_name() << "\n";
    const std::vector<TurningPoint>& turns = t.turns;
    if (turns.empty()) out << "turning     none ahead\n";
    if (path.turning_point_count() < 0 && turns.size() >= 2)
        out << "turning     trapped between " << g(t.height(std::min(turns[0].y, turns[1].y)))
            << " m and " << g(t.height(std::max(turns[0].y, turns[1].y))) << " m, turning every "
            << g(turns[1].dz - turns[0].dz) << " m\n";
    for (const auto& p : turns)
        out << "turning     " << (p.lowest ? "lowest point" : "apex") << " y = " << g(t.height(p.y))
            << " m at dz = " << g(p.dz) << " m\n";
}

void write_ray_text(const PathOptions& o, const PathAir& air, const TracedRay& t,
                    std::ostream& out) {
    write_air_text(air, out);
    out << "eye         y0 = " << g(o.eye_height) << " m, elevation " << g(t.elevation_deg)
        << " deg (i = " << shortest(t.i_rad) << " rad)\n";
    write_invariant_and_turns(air, t, out);
    if (t.path.hits_ground())
        out << "ground      hit at dz = " << g(t.path.dz_ground()) << " m\n";
    else
        out << "ground      not reached\n";
    out << "samples     " << t.samples.points.size() << " (tolerance " << g(o.tolerance_rad)
        << " rad seen from the eye";
    if (o.tolerance_m > 0.0) out << " + " << g(o.tolerance_m) << " m";
    out << "), then " << t.end_name();
    if (t.samples.end != PathEnd::Ground) out << " with slope " << g(t.samples.end_slope);
    out << "\n        dz (m)            y (m)\n";
    for (const auto& p : t.samples.points) out << row("  %14.8g  %14.8g\n", p.x, t.height(p.y));
}

// The output of a batch, or its error.
Status print_batch(const Result<std::string>& text, std::ostream& out) {
    if (!text) return text.error();
    out << *text;
    return Ok{};
}

// --batch with no air given and rows that name their profiles: each row in its own profile on
// the curved Earth of --earth-radius (as the single-ray command traces `--profile ...
// --earth-radius R`, not in the default air).
Status batch_in_own_profiles(const PathOptions& o, const CsvTable& table, std::ostream& out) {
    if (!(o.air.fit_tolerance > 0.0))
        return make_error("--fit-tolerance " + g(o.air.fit_tolerance) + ": must be > 0");
    AirSpec base;
    if (!std::isnan(o.air.earth_radius)) base.earth_radius_m = o.air.earth_radius;
    if (!std::isnan(o.air.top)) base.top_m = o.air.top;
    if (!(std::isfinite(base.earth_radius_m) && base.earth_radius_m >= 0.0))
        return make_error("--earth-radius " + g(base.earth_radius_m) + ": must be finite and >= 0");
    FitSettings fs;
    fs.tolerance_n = o.air.fit_tolerance;
    return print_batch(run_path_batch(table, base, fs), out);
}

// --batch: every row of the CSV in its own exponential profile (the reference's batch), or
// in the air of the options.
Status report_batch(const PathOptions& o, std::ostream& out) {
    std::optional<CsvTable> table;
    if (!general_requested(o) || !air_given(o.air)) {
        auto t = read_csv_file(o.batch);
        if (!t) return t.error();
        if (!general_requested(o)) return print_batch(run_path_batch(*t), out);
        if (batch_rows_give_profiles(*t)) return batch_in_own_profiles(o, *t, out);
        table = std::move(*t);
    }
    auto air = resolve_air(o.air);
    if (!air) return air.error();
    if (!table) {
        auto t = read_csv_file(o.batch);
        if (!t) return t.error();
        table = std::move(*t);
    }
    return print_batch(run_path_batch(*table, air->atmosphere), out);
}

Status report_transfer(const PathOptions& o, const PathAir& air, std::ostream& out) {
    if (std::isnan(o.eye_height)) return make_error("give the eye height with --eye-height M");
    TransferSettings ts;
    ts.atmosphere = air.atmosphere;
    ts.eye_height = o.eye_height;
    ts.distance = o.transfer;
    ts.from_deg = o.transfer_from_deg;
    ts.to_deg = o.transfer_to_deg;
    ts.count = o.transfer_count;
    auto curve = transfer_curve(ts);
    if (!curve) return curve.error();
    if (!o.svg.empty() || !o.png.empty()) {
        ProfilePanel panel;
        panel.temperature_k = air.model.temperature_k;
        panel.refractivity = air.model.refractivity;
        panel.ducts = duct_heights(air);
        panel.label = air.label;
        OutputSet outputs(path_input_files(o));
        if (auto s = draw_transfer_diagram(ts, *curve, panel, outputs, o.svg, o.png); !s) return s;
        if (auto s = outputs.commit(); !s) return s;
    }
    if (o.json) {
        nlohmann::json j;
        j["profile"] = air_json(air);
        j["eye_height"] = o.eye_height;
        j["distance"] = o.transfer;
        j["max_images"] = curve->max_images;
        j["max_images_height"] = curve->max_images_height_m;
        nlohmann::json pts = nlohmann::json::array();
        for (const auto& p : curve->points) {
            if (p.reached)
                pts.push_back({p.apparent_rad, p.true_rad, p.height_m});
            else
                pts.push_back({p.apparent_rad, nullptr, nullptr});
        }
        j["points"] = pts;
        out << json_text(j, 1) << "\n";
        return Ok{};
    }
    write_air_text(air, out);
    out << "transfer    points at " << g(o.transfer) << " m seen from an eye at " << g(o.eye_height)
        << " m, " << curve->points.size() << " rays from " << g(o.transfer_from_deg) << " to "
        << g(o.transfer_to_deg) << " deg\n";
    out << "images      up to " << curve->max_images << " (e.g. of the point at "
        << sig(curve->max_images_height_m, 6) << " m)\n";
    out << "  apparent_deg         true_deg     height_m\n";
    const size_t step = std::max<size_t>(1, curve->points.size() / 40);
    for (size_t k = 0; k < curve->points.size(); k += step) {
        const auto& p = curve->points[k];
        if (p.reached)
            out << row("  %12.6f  %15.8f  %11.5g\n", p.apparent_rad * 180 / M_PI,
                       p.true_rad * 180 / M_PI, p.height_m);
        else
            out << row("  %12.6f  %15s  %11s\n", p.apparent_rad * 180 / M_PI, "ground", "-");
    }
    return Ok{};
}

// The air as the options describe it, in the form they ask for.
Result<PathAir> options_air(const PathOptions& o) {
    return general_requested(o) ? resolve_air(o.air) : resolve_reference_air(o.air);
}

// `--object-height H [--object-distance D]`: from which eye distances the point has a mirrored
// image (atmosphere/vanishing.h), and whether it has one from D (heights above the sphere and
// distances along it on the curved Earth).
Status report_vanishing(const PathOptions& o, std::ostream& out) {
    if (std::isnan(o.eye_height)) return make_error("give the eye height with --eye-height M");
    if (std::isnan(o.object_height))
        return make_error("give the point's height with --object-height M");
    if (!std::isnan(o.elevation_deg) || !std::isnan(o.i_rad))
        return make_error(
            "--object-height asks for the rays that reach the point: give no --elevation-deg or "
            "--i-rad");
    if (!std::isnan(o.object_distance) &&
        !(o.object_distance > 0.0 && std::isfinite(o.object_distance)))
        return make_error("--object-distance " + g(o.object_distance) +
                          ": must be a distance > 0 m");
    auto air = options_air(o);
    if (!air) return air.error();
    const double R = air->atmosphere.earth_radius();
    auto reach = mirror_reach(air->atmosphere, flattened_height(o.eye_height, R),
                              flattened_height(o.object_height, R));
    if (!reach) return reach.error();
    reach->nearest_turn_height = height_above_sphere(reach->nearest_turn_height, R);
    const double elev_deg = reach->nearest_elevation_rad * 180.0 / M_PI;
    const bool has_d = !std::isnan(o.object_distance);
    const bool seen =
        has_d && o.object_distance >= reach->nearest && o.object_distance <= reach->farthest;
    if (o.json) {
        nlohmann::json j;
        j[air->form == AirForm::Reference ? "profile" : "air"] = air_json(*air);
        j["eye_height"] = o.eye_height;
        j["object_height"] = o.object_height;
        j["nearest_eye_distance"] = reach->nearest;
        j["farthest_eye_distance"] = reach->farthest;
        j["nearest_turn_height"] = reach->nearest_turn_height;
        j["nearest_elevation_deg"] = elev_deg;
        j["grazing"] = reach->grazing;
        if (has_d) {
            j["object_distance"] = o.object_distance;
            j["mirrored"] = seen;
        }
        out << json_text(j) << "\n";
        return Ok{};
    }
    write_air_text(*air, out);
    out << "eye         y0 = " << g(o.eye_height) << " m\n";
    out << "point       y = " << g(o.object_height) << " m\n";
    out << "vanishing   nearest eye distance with a mirrored image " << g(reach->nearest)
        << " m (the ray turning at y = " << g(reach->nearest_turn_height) << " m"
        << (reach->grazing ? ", grazing the ground" : "") << ", elevation " << g(elev_deg)
        << " deg)\n";
    out << "            farthest " << g(reach->farthest) << " m\n";
    if (has_d)
        out << "at " << g(o.object_distance) << " m    "
            << (seen ? "mirrored: rays from the eye reach the point after turning"
                     : "no mirrored image: no ray from the eye reaches the point after turning")
            << "\n";
    return Ok{};
}

}  // namespace

Status run_path(const PathOptions& o, std::ostream& out) {
    if (auto s = check_path_options(o); !s) return s;
    if (!std::isnan(o.object_height)) return report_vanishing(o, out);
    if (!o.batch.empty()) return report_batch(o, out);
    auto air = options_air(o);
    if (!air) return air.error();
    if (o.ducts && std::isnan(o.eye_height)) {
        if (o.json)
            out << json_text(air_json(*air)) << "\n";
        else
            write_air_text(*air, out);
        return Ok{};
    }
    if (!std::isnan(o.transfer)) return report_transfer(o, *air, out);
    return report_ray(o, *air, out);
}

Status check_path_options(const PathOptions& o) {
    if (!std::isnan(o.turbulence_cn2) && o.svg.empty())
        return make_error(
            "--turbulence-cn2 draws perturbed rays on the ray diagram: give --svg FILE");
    if (!o.batch.empty() && (!o.svg.empty() || !o.png.empty()))
        return make_error(std::string(!o.svg.empty() ? "--svg" : "--png") +
                          " draws one ray's diagram: it does not go with --batch, which prints a "
                          "CSV of its rows");
    const bool point = !std::isnan(o.object_height) || !std::isnan(o.object_distance);
    if (point && std::isnan(o.object_height))
        return make_error("--object-distance needs the point's height: --object-height M");
    if (!point && !o.png.empty() && std::isnan(o.transfer))
        return make_error("--png draws the transfer diagram: give --transfer DIST");
    return Ok{};
}

Status report_ray(const PathOptions& o, const PathAir& air, std::ostream& out) {
    auto traced = trace_ray(o, air.atmosphere);
    if (!traced) return traced.error();
    if (o.json)
        out << json_text(ray_json(o, air, *traced)) << "\n";
    else
        write_ray_text(o, air, *traced, out);
    if (!o.svg.empty()) return write_fan_diagram(o, air, traced->elevation_deg);
    return Ok{};
}

}  // namespace mirage
