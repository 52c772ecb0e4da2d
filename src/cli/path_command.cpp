// `mirage path`: one exact ray (class, invariant, turning point, ground hit, samples), a ray
// diagram as SVG, or a batch of rays from a CSV.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "atmosphere/exact_path.h"
#include "atmosphere/exact_ray.h"
#include "atmosphere/general_profile.h"
#include "atmosphere/path_batch.h"
#include "atmosphere/path_sampler.h"
#include "atmosphere/profile.h"
#include "atmosphere/sampler.h"
#include "atmosphere/vanishing.h"
#include "cli/commands.h"
#include "report/ray_diagram.h"
#include "trace/curved_propagator.h"
#include "report/transfer_diagram.h"
#include "util/csv.h"
#include "util/format.h"
#include "util/json_text.h"
#include "util/output_set.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct PathOptions {
    std::string preset;
    std::string profile;
    double eta0 = kNaN, eta1 = kNaN, alpha = kNaN;
    double eye_height = kNaN;
    double elevation_deg = kNaN;
    double i_rad = kNaN;
    double tolerance_rad = 1e-3;
    double tolerance_m = 0.0;
    double max_distance = std::numeric_limits<double>::infinity();
    bool json = false;
    std::string svg;
    double fan_from_deg = kNaN, fan_to_deg = kNaN;
    int fan_count = 13;
    // Turbulent air (docs/turbulence.md): the fan's rays through `realizations` of it, dashed.
    double turbulence_cn2 = kNaN;
    double turbulence_inner = kNaN, turbulence_outer = kNaN, turbulence_aperture = 0.0;
    double turbulence_seed = 1.0;
    int realizations = 4;
    std::string batch;
    double object_distance = kNaN, object_height = kNaN;  // the vanishing of a point's mirage

    // Real air: any of these selects the general engine (the exponential profile's n^2 fitted
    // with --general).
    double air_temperature_c = kNaN;
    double lapse_k_per_km = kNaN;
    std::vector<std::string> surface_layers;  // "DT_K,SCALE_M"
    std::vector<std::string> inversions;      // "BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M]"
    std::string sounding;
    double sounding_max_gap = 1000.0;
    double pressure_hpa = kNaN;
    bool isobaric = false;
    double humidity_pct = kNaN;
    std::string index;
    double gladstone_dale = kNaN, wavelength_nm = kNaN, co2_ppm = kNaN;
    double earth_radius = kNaN;
    double top = kNaN;
    double fit_tolerance = 1e-10;
    bool general = false;
    bool ducts = false;
    double transfer = kNaN;
    double transfer_from_deg = -0.25, transfer_to_deg = 0.25;
    int transfer_count = 2001;
    std::string png;
};

// The files the command reads: no output may replace one of them.
std::vector<std::string> input_files(const PathOptions& o) {
    std::vector<std::string> in;
    for (const auto& f : {o.sounding, o.batch})
        if (!f.empty()) in.push_back(f);
    return in;
}

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "mirage path: " << escape_terminal(message) << "\n";
    throw CommandFailed{1};
}

std::string g(double v, int digits = 10) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

Profile resolve_profile(const PathOptions& o, std::string& label) {
    Profile p;
    if (!o.preset.empty()) {
        auto preset = preset_profile(o.preset);
        if (!preset) fail("--preset: " + preset.message());
        p = *preset;
        label = o.preset + " (" + std::string(profile_kind_name(p.kind)) + ")";
        if (!o.profile.empty() || !std::isnan(o.eta0) || !std::isnan(o.eta1) ||
            !std::isnan(o.alpha))
            fail("--preset " + o.preset +
                 " fixes the profile: give either --preset or --profile/--eta0/--eta1/--alpha");
    } else {
        if (o.profile.empty()) fail("give --preset NAME or --profile inferior|superior|none");
        auto kind = parse_profile_kind(o.profile);
        if (!kind) fail("--profile: " + kind.message());
        p.kind = *kind;
        if (p.kind != ProfileKind::None) {
            if (std::isnan(o.eta0) || std::isnan(o.eta1) || std::isnan(o.alpha))
                fail("--profile " + o.profile + " needs --eta0, --eta1 and --alpha");
            p.eta0 = o.eta0;
            p.eta1 = o.eta1;
            p.alpha = o.alpha;
        } else if (!std::isnan(o.eta0)) {
            p.eta0 = o.eta0;
        }
        label = o.profile;
    }
    if (auto s = validate(p, ProfileNames{"--eta0", "--eta1", "--alpha"}); !s) fail(s.message());
    return p;
}

double resolve_angle(const PathOptions& o) {
    if (!std::isnan(o.i_rad) && !std::isnan(o.elevation_deg))
        fail("give either --elevation-deg or --i-rad, not both");
    if (!std::isnan(o.i_rad)) return o.i_rad;
    if (!std::isnan(o.elevation_deg)) {
        if (!(std::fabs(o.elevation_deg) < 90.0))
            fail("--elevation-deg " + g(o.elevation_deg) +
                 ": must lie strictly between -90 and 90");
        return M_PI / 2 - o.elevation_deg * M_PI / 180.0;
    }
    fail("give the ray's direction with --elevation-deg DEG (or --i-rad RAD)");
}

void run_batch(const PathOptions& o) {
    auto table = read_csv_file(o.batch);
    if (!table) fail(table.message());
    auto out = run_path_batch(*table);
    if (!out) fail(out.message());
    std::cout << *out;
}

// The fan's rays through `realizations` of turbulent air (phase screens across the level line of
// sight, out to the drawn distance, seeds from --turbulence-seed on), each walked as the tracer
// walks it (followed_points), cut where it reaches the ground.
void add_perturbed_rays(const PathOptions& o, RayDiagramSettings& st) {
    TurbulenceSettings t;
    t.cn2 = o.turbulence_cn2;
    if (!std::isnan(o.turbulence_inner)) t.inner_scale_m = o.turbulence_inner;
    if (!std::isnan(o.turbulence_outer)) t.outer_scale_m = o.turbulence_outer;
    if (!(o.turbulence_seed >= 0.0 && o.turbulence_seed <= 4294967295.0 &&
          std::floor(o.turbulence_seed) == o.turbulence_seed))
        fail("--turbulence-seed " + shortest(o.turbulence_seed) +
             ": must be a whole number from 0 to 4294967295");
    if (auto c = check_turbulence(t); !c) fail("--turbulence-cn2 and its options: " + c.message());
    if (!(t.cn2 > 0.0)) fail("--turbulence-cn2 0: nothing to draw (give more than 0)");
    const double y0 = flattened_height(o.eye_height, st.atmosphere.earth_radius());
    const glm::dvec3 eye(0.0, y0, 0.0);
    ScreenLayout layout;
    layout.origin = eye;
    layout.reach_m = st.max_distance;
    layout.aperture_m = o.turbulence_aperture;
    if (auto c = check_screen_layout(layout); !c) fail("--turbulence-aperture: " + c.message());
    for (int r = 0; r < o.realizations; ++r) {
        t.seed = static_cast<std::uint64_t>(o.turbulence_seed) + r;
        auto screens = PhaseScreens::make(t, layout);
        if (!screens) fail(screens.message());
        CurvedSettings cs;
        cs.atmosphere = st.atmosphere;
        cs.tolerance_rad = st.tolerance_rad;
        cs.tolerance_m = st.tolerance_m;
        cs.max_dz = st.max_distance;
        cs.eye = eye;
        cs.turbulence = std::make_shared<const PhaseScreens>(std::move(*screens));
        for (int j = 0; j < st.count; ++j) {
            const double f = st.count == 1 ? 0.5 : double(j) / (st.count - 1);
            const double e = (st.elev_from_deg + f * (st.elev_to_deg - st.elev_from_deg)) * M_PI / 180;
            const std::vector<glm::dvec3> points =
                followed_points(cs, eye, glm::dvec3(0.0, std::sin(e), std::cos(e)), st.max_distance);
            OverlaidRay ray;
            ray.fan_ray = j;
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
            st.overlaid.push_back(std::move(ray));
        }
    }
    st.overlaid_label = "through turbulent air, C_n^2 " + shortest(t.cn2) + " m^-2/3, " +
                        std::to_string(o.realizations) + " realizations";
}

void write_svg(const PathOptions& o, const Atmosphere& atm, const std::string& label,
               const std::vector<std::string>& legend, double elev_deg) {
    RayDiagramSettings st;
    st.atmosphere = atm;
    st.profile_label = label;
    st.legend = legend;
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
    } else {
        // Far enough to show every turn and ground hit of the fan.
        double reach = 10.0 * o.eye_height;
        for (int j = 0; j < st.count; ++j) {
            const double t = st.count == 1 ? 0.5 : double(j) / (st.count - 1);
            const double e =
                (st.elev_from_deg + t * (st.elev_to_deg - st.elev_from_deg)) * M_PI / 180;
            auto ray = ExactPath::make(atm, flattened_height(o.eye_height, atm.earth_radius()),
                                       M_PI / 2 - e);
            if (!ray) continue;
            if (ray->turning_point_count() != 0)
                reach = std::max(reach, 1.6 * ray->turning_point(0).dz);
            if (ray->hits_ground()) reach = std::max(reach, 1.1 * ray->dz_ground());
        }
        st.max_distance = std::min(reach, 1e6);
    }
    if (!std::isnan(o.turbulence_cn2)) add_perturbed_rays(o, st);
    auto svg = ray_diagram_svg(st);
    if (!svg) fail(svg.message());
    OutputSet outputs(input_files(o));
    if (auto s = outputs.write_text(o.svg, *svg); !s) fail(s.message());
    if (auto s = outputs.commit(); !s) fail(s.message());
}

// The eye, the ray's direction, the sampling tolerance and the distance of a single ray, in
// either engine; returns the angle from the vertical.
double check_ray_flags(const PathOptions& o) {
    if (std::isnan(o.eye_height)) fail("give the eye height with --eye-height M");
    if (!(o.eye_height > 0.0 && o.eye_height <= kMaxHeight))
        fail("--eye-height " + g(o.eye_height) +
             ": the eye must be above the ground (> 0 m) and at most " + shortest(kMaxHeight) +
             " m");
    const double i = resolve_angle(o);
    if (!(o.tolerance_rad == 0.0 ||
          (o.tolerance_rad >= kMinToleranceRad && o.tolerance_rad <= 1.0)))
        fail("--tolerance " + g(o.tolerance_rad) + ": must be 0 or from " + g(kMinToleranceRad) +
             " to 1 rad");
    if (!(o.tolerance_m == 0.0 || (o.tolerance_m >= kMinToleranceM && o.tolerance_m <= 1e9)))
        fail("--tolerance-m " + g(o.tolerance_m) + ": must be 0 or from " + g(kMinToleranceM) +
             " to 1e+09 m");
    if (!(o.tolerance_rad > 0.0 || o.tolerance_m > 0.0))
        fail("--tolerance " + g(o.tolerance_rad) + " and --tolerance-m " + g(o.tolerance_m) +
             ": need a positive tolerance");
    if (!(o.max_distance > 0.0)) fail("--max-distance " + g(o.max_distance) + ": must be > 0 m");
    return i;
}

void run_single(const PathOptions& o) {
    std::string label;
    const Profile profile = resolve_profile(o, label);
    const double i = check_ray_flags(o);
    auto ray = make_exact_ray(profile, o.eye_height, i);
    if (!ray) fail(ray.message());
    SampleSettings st;
    st.tolerance_rad = o.tolerance_rad;
    st.tolerance_m = o.tolerance_m;
    st.max_dz = o.max_distance;
    const SampledPath path = sample_path(*ray, st);
    const double elev_deg = (M_PI / 2 - i) * 180.0 / M_PI;
    const char* end_name = path.end == PathEnd::Ground     ? "ground"
                           : path.end == PathEnd::Straight ? "straight"
                                                           : "cut";
    if (o.json) {
        nlohmann::json j;
        j["profile"] = {{"kind", profile_kind_name(profile.kind)},
                        {"eta0", profile.eta0},
                        {"eta1", profile.eta1},
                        {"alpha", profile.alpha}};
        j["eye_height"] = o.eye_height;
        j["elevation_deg"] = elev_deg;
        j["i_rad"] = i;
        j["eta_eye"] = ray->eta_p;
        j["beta"] = ray->beta;
        j["k2"] = ray->k2;
        j["ray_class"] = ray_class_name(ray->ray_class);
        j["turn_kind"] = turn_kind_name(ray->turn_kind);
        j["y_turn"] = std::isnan(ray->y_turn) ? nlohmann::json() : nlohmann::json(ray->y_turn);
        j["dz_turn"] = std::isnan(ray->dz_turn) ? nlohmann::json() : nlohmann::json(ray->dz_turn);
        j["hits_ground"] = ray->hits_ground;
        j["dz_ground"] = ray->hits_ground ? nlohmann::json(ray->dz_ground) : nlohmann::json();
        j["tolerance_rad"] = o.tolerance_rad;
        j["tolerance_m"] = o.tolerance_m;
        nlohmann::json pts = nlohmann::json::array();
        for (const auto& p : path.points) pts.push_back({p.x, p.y});
        j["samples"] = pts;
        j["end"] = end_name;
        if (path.end != PathEnd::Ground) j["end_slope"] = path.end_slope;
        std::cout << json_text(j) << "\n";
    } else {
        std::cout << "profile     " << label << ": eta0 = " << shortest(profile.eta0)
                  << ", eta1 = " << shortest(profile.eta1)
                  << ", alpha = " << shortest(profile.alpha) << " /m\n";
        std::cout << "eye         y0 = " << g(o.eye_height) << " m, elevation " << g(elev_deg)
                  << " deg (i = " << shortest(i) << " rad)\n";
        std::cout << "invariant   beta = eta(y0) sin i = " << shortest(ray->beta)
                  << " (eta(y0) = " << shortest(ray->eta_p) << ", k2 = " << shortest(ray->k2)
                  << ")\n";
        std::cout << "class       " << ray_class_name(ray->ray_class) << "\n";
        if (ray->turn_kind == TurnKind::None) {
            std::cout << "turning     none\n";
        } else {
            const char* what = ray->s > 0 ? "lowest point" : "apex";
            std::cout << "turning     " << what << " y = " << g(ray->y_turn)
                      << " m at dz = " << g(ray->dz_turn) << " m ("
                      << turn_kind_name(ray->turn_kind) << ")\n";
        }
        if (ray->hits_ground)
            std::cout << "ground      hit at dz = " << g(ray->dz_ground) << " m\n";
        else
            std::cout << "ground      not reached\n";
        std::cout << "samples     " << path.points.size() << " (tolerance " << g(o.tolerance_rad)
                  << " rad seen from the eye";
        if (o.tolerance_m > 0.0) std::cout << " + " << g(o.tolerance_m) << " m";
        std::cout << "), then " << end_name;
        if (path.end != PathEnd::Ground) std::cout << " with slope " << g(path.end_slope);
        std::cout << "\n        dz (m)            y (m)\n";
        for (const auto& p : path.points) std::printf("  %14.8g  %14.8g\n", p.x, p.y);
    }
    if (!o.svg.empty()) write_svg(o, Atmosphere::exponential(profile), label, {}, elev_deg);
}

// ---- Real air: any profile through the general engine -------------------------------------

bool general_requested(const PathOptions& o) {
    return o.general || !std::isnan(o.air_temperature_c) || !std::isnan(o.lapse_k_per_km) ||
           !o.surface_layers.empty() || !o.inversions.empty() || !o.sounding.empty() ||
           !std::isnan(o.pressure_hpa) || o.isobaric || !std::isnan(o.humidity_pct) ||
           !o.index.empty() || !std::isnan(o.gladstone_dale) || !std::isnan(o.wavelength_nm) ||
           !std::isnan(o.co2_ppm) || !std::isnan(o.earth_radius) || !std::isnan(o.top) ||
           !std::isnan(o.transfer) || o.ducts;
}

// The numbers of a comma-separated flag value, count between lo and hi.
std::vector<double> numbers(const std::string& flag, const std::string& value, size_t lo, size_t hi,
                            const std::string& form) {
    std::vector<double> v;
    std::stringstream in(value);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double x = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(x))
            fail(flag + " " + value + ": '" + item + "' is not a number (expected " + form + ")");
        v.push_back(x);
    }
    if (v.size() < lo || v.size() > hi) fail(flag + " " + value + ": expected " + form);
    return v;
}

struct AirChoice {
    Atmosphere atmosphere;
    AirSpec spec;
    std::string label;
    std::vector<std::string> legend;
    FitReport fit;
    AirModel model;
};

AirChoice resolve_air(const PathOptions& o) {
    AirChoice c;
    AirSpec& spec = c.spec;
    const bool forms = !std::isnan(o.air_temperature_c) || !std::isnan(o.lapse_k_per_km) ||
                       !o.surface_layers.empty() || !o.inversions.empty();
    if (!o.preset.empty() || !o.profile.empty()) {
        if (forms || !o.sounding.empty())
            fail(
                "--preset/--profile give an exponential profile and --air-temperature-c, "
                "--lapse-k-per-km, --surface-layer, --inversion and --sounding another: give one");
        Profile p = resolve_profile(o, c.label);
        spec.source = AirSpec::Source::Exponential;
        spec.exponential = p;
        c.legend.push_back("exponential n^2, eta0 = " + shortest(p.eta0) + ", eta1 = " +
                           shortest(p.eta1) + ", alpha = " + shortest(p.alpha) + " /m");
    } else if (!o.sounding.empty()) {
        if (forms) fail("--sounding gives the whole profile: leave out the temperature forms");
        if (!(o.sounding_max_gap > 0.0 && o.sounding_max_gap <= kMaxSoundingGapM))
            fail("--sounding-max-gap " + g(o.sounding_max_gap) +
                 ": must be more than 0 and at most " + g(kMaxSoundingGapM) + " m");
        SoundingRules rules;
        rules.max_gap_m = o.sounding_max_gap;
        auto s = read_sounding(o.sounding, rules);
        if (!s) fail(s.message());
        spec.source = AirSpec::Source::Sounding;
        spec.sounding = std::move(*s);
        c.label = "sounding " + o.sounding;
        c.legend.push_back(std::to_string(spec.sounding.height_m.size()) + " rows of " +
                           (spec.sounding.kind == Sounding::Kind::Index ? "n" : "temperature") +
                           ", 0 to " + shortest(spec.sounding.height_m.back()) + " m");
    } else {
        spec.source = AirSpec::Source::Column;
        AirColumn& col = spec.column;
        const double t_c = std::isnan(o.air_temperature_c) ? 15.0 : o.air_temperature_c;
        col.ground_temperature_k = t_c + 273.15;
        col.lapse_k_per_m = std::isnan(o.lapse_k_per_km) ? 0.0 : 1e-3 * o.lapse_k_per_km;
        c.label = "air at " + shortest(t_c) + " degC";
        if (col.lapse_k_per_m != 0.0)
            c.legend.push_back("lapse " + shortest(o.lapse_k_per_km) + " K/km");
        for (const auto& v : o.surface_layers) {
            const auto n = numbers("--surface-layer", v, 2, 2, "DT_K,SCALE_M");
            col.layers.push_back({n[0], n[1]});
            if (auto s = check_surface_layer(col.layers.back()); !s)
                fail("--surface-layer " + v + ": " + s.message());
            c.legend.push_back("surface layer " + shortest(n[0]) + " K, scale " + shortest(n[1]) +
                               " m");
        }
        for (const auto& v : o.inversions) {
            const auto n = numbers("--inversion", v, 3, 4, "BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M]");
            col.inversions.push_back({n[0], n[1], n[2], n.size() > 3 ? n[3] : 0.0});
            if (auto s = check_inversion(col.inversions.back()); !s)
                fail("--inversion " + v + ": " + s.message());
            c.legend.push_back(
                "inversion " + shortest(n[2]) + " K, " + shortest(n[0]) + " to " + shortest(n[1]) +
                " m" + (n.size() > 3 && n[3] > 0.0 ? ", smoothing " + shortest(n[3]) + " m" : ""));
        }
    }
    if (!o.index.empty()) {
        auto f = parse_index_formula(o.index);
        if (!f) fail("--index: " + f.message());
        spec.index.formula = *f;
    }
    if (!std::isnan(o.gladstone_dale)) spec.index.gladstone_dale = o.gladstone_dale;
    if (!std::isnan(o.wavelength_nm)) spec.index.wavelength_nm = o.wavelength_nm;
    if (!std::isnan(o.co2_ppm)) spec.index.co2_ppm = o.co2_ppm;
    if (!std::isnan(o.pressure_hpa)) spec.ground_pressure_pa = 100.0 * o.pressure_hpa;
    spec.hydrostatic = !o.isobaric;
    if (!std::isnan(o.humidity_pct)) spec.relative_humidity = 0.01 * o.humidity_pct;
    if (!std::isnan(o.earth_radius)) spec.earth_radius_m = o.earth_radius;
    if (!std::isnan(o.top)) spec.top_m = o.top;
    if (spec.source != AirSpec::Source::Exponential) {
        c.legend.push_back(spec.index.formula == IndexFormula::Ciddor
                               ? "index: Ciddor, " + shortest(spec.index.wavelength_nm) + " nm"
                               : "index: Gladstone-Dale " + shortest(spec.index.gladstone_dale));
        if (spec.source == AirSpec::Source::Column || spec.sounding.pressure_pa.empty())
            c.legend.push_back("pressure " + shortest(spec.ground_pressure_pa / 100.0) + " hPa, " +
                               (spec.hydrostatic ? "hydrostatic" : "isobaric"));
        if (spec.relative_humidity > 0.0)
            c.legend.push_back("humidity " + shortest(100.0 * spec.relative_humidity) + " %");
    }
    if (!(o.fit_tolerance > 0.0)) fail("--fit-tolerance " + g(o.fit_tolerance) + ": must be > 0");
    auto model = make_air_model(spec);
    if (!model) fail(model.message());
    c.model = *model;
    if (spec.source == AirSpec::Source::Exponential && !o.general && spec.earth_radius_m == 0.0) {
        // The closed forms, exact as they are.
        c.atmosphere = Atmosphere::exponential(spec.exponential);
        c.legend.push_back("closed forms");
        return c;
    }
    FitSettings fs;
    fs.tolerance_n = o.fit_tolerance;
    auto q = fit_air(spec, fs, &c.fit);
    if (!q) fail(q.message());
    c.atmosphere = Atmosphere::quadratic(*q);
    c.legend.push_back("fitted: " + std::to_string(c.fit.pieces) +
                       " pieces, |dn| <= " + shortest(o.fit_tolerance));
    return c;
}

std::vector<std::pair<double, double>> duct_heights(const AirChoice& c) {
    std::vector<std::pair<double, double>> out;
    if (!c.atmosphere.quadratic_profile()) return out;  // exponential: monotone, no duct
    const double R = c.atmosphere.earth_radius();
    for (const auto& d : find_ducts(*c.atmosphere.quadratic_profile()))
        out.push_back({height_above_sphere(d.bottom, R), height_above_sphere(d.top, R)});
    return out;
}

void print_air(const AirChoice& c) {
    std::cout << "profile     " << c.label << "\n";
    for (const auto& l : c.legend) std::cout << "            " << l << "\n";
    if (c.atmosphere.earth_radius() > 0.0)
        std::cout << "            Earth radius " << g(c.atmosphere.earth_radius())
                  << " m: heights above "
                  << "the sphere, distances along it\n";
    const auto ducts = duct_heights(c);
    if (ducts.empty()) {
        std::cout << "ducts       none\n";
    }
    for (const auto& d : ducts)
        std::cout << "ducts       level rays trapped from " << g(d.first) << " m to " << g(d.second)
                  << " m\n";
}

nlohmann::json air_json(const AirChoice& c) {
    nlohmann::json j;
    j["label"] = c.label;
    j["legend"] = c.legend;
    if (c.atmosphere.quadratic_profile()) {
        j["pieces"] = c.fit.pieces;
        j["fit_max_error_n"] = c.fit.max_error_n;
    }
    j["earth_radius"] = c.atmosphere.earth_radius();
    nlohmann::json d = nlohmann::json::array();
    for (const auto& [lo, hi] : duct_heights(c)) d.push_back({{"bottom", lo}, {"top", hi}});
    j["ducts"] = d;
    return j;
}

void run_transfer(const PathOptions& o, const AirChoice& c) {
    if (std::isnan(o.eye_height)) fail("give the eye height with --eye-height M");
    TransferSettings ts;
    ts.atmosphere = c.atmosphere;
    ts.eye_height = o.eye_height;
    ts.distance = o.transfer;
    ts.from_deg = o.transfer_from_deg;
    ts.to_deg = o.transfer_to_deg;
    ts.count = o.transfer_count;
    auto curve = transfer_curve(ts);
    if (!curve) fail(curve.message());
    if (!o.svg.empty() || !o.png.empty()) {
        ProfilePanel panel;
        panel.temperature_k = c.model.temperature_k;
        panel.refractivity = c.model.refractivity;
        panel.ducts = duct_heights(c);
        panel.label = c.label;
        OutputSet outputs(input_files(o));
        if (auto s = draw_transfer_diagram(ts, *curve, panel, outputs, o.svg, o.png); !s)
            fail(s.message());
        if (auto s = outputs.commit(); !s) fail(s.message());
    }
    if (o.json) {
        nlohmann::json j;
        j["profile"] = air_json(c);
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
        std::cout << json_text(j, 1) << "\n";
        return;
    }
    print_air(c);
    std::cout << "transfer    points at " << g(o.transfer) << " m seen from an eye at "
              << g(o.eye_height) << " m, " << curve->points.size() << " rays from "
              << g(o.transfer_from_deg) << " to " << g(o.transfer_to_deg) << " deg\n";
    std::cout << "images      up to " << curve->max_images << " (e.g. of the point at "
              << g(curve->max_images_height_m, 6) << " m)\n";
    std::cout << "  apparent_deg         true_deg     height_m\n";
    const size_t step = std::max<size_t>(1, curve->points.size() / 40);
    for (size_t k = 0; k < curve->points.size(); k += step) {
        const auto& p = curve->points[k];
        if (p.reached)
            std::printf("  %12.6f  %15.8f  %11.5g\n", p.apparent_rad * 180 / M_PI,
                        p.true_rad * 180 / M_PI, p.height_m);
        else
            std::printf("  %12.6f  %15s  %11s\n", p.apparent_rad * 180 / M_PI, "ground", "-");
    }
}

// `--object-height H [--object-distance D]`: from which eye distances the point has a mirrored
// image (atmosphere/vanishing.h), and whether it has one from D: in the exponential profiles'
// closed forms, or in any atmosphere through the general engine (heights above the sphere and
// distances along it on the curved Earth).
void run_vanishing(const PathOptions& o) {
    if (std::isnan(o.eye_height)) fail("give the eye height with --eye-height M");
    if (std::isnan(o.object_height)) fail("give the point's height with --object-height M");
    if (!std::isnan(o.elevation_deg) || !std::isnan(o.i_rad))
        fail(
            "--object-height asks for the rays that reach the point: give no --elevation-deg or "
            "--i-rad");
    if (!std::isnan(o.object_distance) &&
        !(o.object_distance > 0.0 && std::isfinite(o.object_distance)))
        fail("--object-distance " + g(o.object_distance) + ": must be a distance > 0 m");
    std::string label;
    std::optional<Profile> profile;
    std::optional<AirChoice> air;
    Result<MirrorReach> reach = make_error("");
    if (general_requested(o)) {
        air = resolve_air(o);
        const double R = air->atmosphere.earth_radius();
        reach = mirror_reach(air->atmosphere, flattened_height(o.eye_height, R),
                             flattened_height(o.object_height, R));
        if (reach) reach->nearest_turn_height = height_above_sphere(reach->nearest_turn_height, R);
    } else {
        profile = resolve_profile(o, label);
        reach = mirror_reach(*profile, o.eye_height, o.object_height);
    }
    if (!reach) fail(reach.message());
    const double elev_deg = reach->nearest_elevation_rad * 180.0 / M_PI;
    const bool has_d = !std::isnan(o.object_distance);
    const bool seen =
        has_d && o.object_distance >= reach->nearest && o.object_distance <= reach->farthest;
    if (o.json) {
        nlohmann::json j;
        if (profile) {
            j["profile"] = {{"kind", profile_kind_name(profile->kind)},
                            {"eta0", profile->eta0},
                            {"eta1", profile->eta1},
                            {"alpha", profile->alpha}};
        } else {
            j["air"] = air_json(*air);
        }
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
        std::cout << json_text(j) << "\n";
        return;
    }
    if (profile) {
        std::cout << "profile     " << label << ": eta0 = " << shortest(profile->eta0)
                  << ", eta1 = " << shortest(profile->eta1)
                  << ", alpha = " << shortest(profile->alpha) << " /m\n";
    } else {
        print_air(*air);
    }
    std::cout << "eye         y0 = " << g(o.eye_height) << " m\n";
    std::cout << "point       y = " << g(o.object_height) << " m\n";
    std::cout << "vanishing   nearest eye distance with a mirrored image " << g(reach->nearest)
              << " m (the ray turning at y = " << g(reach->nearest_turn_height) << " m"
              << (reach->grazing ? ", grazing the ground" : "") << ", elevation " << g(elev_deg)
              << " deg)\n";
    std::cout << "            farthest " << g(reach->farthest) << " m\n";
    if (has_d)
        std::cout
            << "at " << g(o.object_distance) << " m    "
            << (seen ? "mirrored: rays from the eye reach the point after turning"
                     : "no mirrored image: no ray from the eye reaches the point after turning")
            << "\n";
}

// Whether the options say what the air is (else it is the default: air at 15 degC).
bool air_given(const PathOptions& o) {
    return !o.preset.empty() || !o.profile.empty() || !std::isnan(o.air_temperature_c) ||
           !std::isnan(o.lapse_k_per_km) || !o.surface_layers.empty() || !o.inversions.empty() ||
           !o.sounding.empty() || !std::isnan(o.pressure_hpa) || o.isobaric ||
           !std::isnan(o.humidity_pct) || !o.index.empty() || !std::isnan(o.gladstone_dale) ||
           !std::isnan(o.wavelength_nm) || !std::isnan(o.co2_ppm);
}

void run_general(const PathOptions& o) {
    if (!o.png.empty() && std::isnan(o.transfer))
        fail("--png draws the transfer diagram: give --transfer DIST");
    if (!o.batch.empty() && !air_given(o)) {
        auto table = read_csv_file(o.batch);
        if (!table) fail(table.message());
        if (batch_rows_give_profiles(*table)) {
            // Each row's own profile, on the curved Earth of --earth-radius: as the single-ray
            // command traces `--profile ... --earth-radius R` (not the default air).
            if (!(o.fit_tolerance > 0.0))
                fail("--fit-tolerance " + g(o.fit_tolerance) + ": must be > 0");
            AirSpec base;
            if (!std::isnan(o.earth_radius)) base.earth_radius_m = o.earth_radius;
            if (!std::isnan(o.top)) base.top_m = o.top;
            if (!(std::isfinite(base.earth_radius_m) && base.earth_radius_m >= 0.0))
                fail("--earth-radius " + g(base.earth_radius_m) + ": must be finite and >= 0");
            FitSettings fs;
            fs.tolerance_n = o.fit_tolerance;
            auto out = run_path_batch(*table, base, fs);
            if (!out) fail(out.message());
            std::cout << *out;
            return;
        }
    }
    const AirChoice c = resolve_air(o);
    if (!o.batch.empty()) {
        auto table = read_csv_file(o.batch);
        if (!table) fail(table.message());
        auto out = run_path_batch(*table, c.atmosphere);
        if (!out) fail(out.message());
        std::cout << *out;
        return;
    }
    if (o.ducts && std::isnan(o.eye_height)) {
        if (o.json) {
            std::cout << json_text(air_json(c)) << "\n";
        } else {
            print_air(c);
        }
        return;
    }
    if (!std::isnan(o.transfer)) return run_transfer(o, c);
    const double i = check_ray_flags(o);
    const double R = c.atmosphere.earth_radius();
    auto path = ExactPath::make(c.atmosphere, flattened_height(o.eye_height, R), i);
    if (!path) fail(path.message());
    SampleSettings st;
    st.tolerance_rad = o.tolerance_rad;
    st.tolerance_m = o.tolerance_m;
    st.max_dz = o.max_distance;
    const SampledPath poly = sample_exact_path(*path, st);
    const double elev_deg = (M_PI / 2 - i) * 180.0 / M_PI;
    const char* end_name = poly.end == PathEnd::Ground     ? "ground"
                           : poly.end == PathEnd::Straight ? "straight"
                                                           : "cut";
    auto h = [&](double y) { return height_above_sphere(y, R); };
    // The turning points ahead: all of them for a path that turns once, the first 20 of a
    // trapped one.
    std::vector<TurningPoint> turns;
    const int count = path->turning_point_count();
    for (int k = 0; count != 0 && (count < 0 || k < count) && k < 20; ++k) {
        const TurningPoint t = path->turning_point(k);
        if (t.dz <= 0.0 && k == 0 && count > 0) break;
        if (path->hits_ground() && t.dz > path->dz_ground()) break;
        turns.push_back(t);
    }
    if (o.json) {
        nlohmann::json j;
        j["engine"] = "general";
        j["profile"] = air_json(c);
        j["eye_height"] = o.eye_height;
        j["elevation_deg"] = elev_deg;
        j["i_rad"] = i;
        j["eta_eye"] = path->eta_start();
        j["beta"] = path->beta();
        j["ray_class"] = path->class_name();
        j["turn_count"] = count < 0 ? nlohmann::json("infinite") : nlohmann::json(count);
        nlohmann::json tj = nlohmann::json::array();
        for (const auto& t : turns)
            tj.push_back({{"dz", t.dz}, {"y", h(t.y)}, {"kind", t.lowest ? "lowest" : "apex"}});
        j["turning_points"] = tj;
        j["hits_ground"] = path->hits_ground();
        j["dz_ground"] = path->hits_ground() ? nlohmann::json(path->dz_ground()) : nlohmann::json();
        j["tolerance_rad"] = o.tolerance_rad;
        j["tolerance_m"] = o.tolerance_m;
        nlohmann::json pts = nlohmann::json::array();
        for (const auto& p : poly.points) pts.push_back({p.x, h(p.y)});
        j["samples"] = pts;
        j["end"] = end_name;
        if (poly.end != PathEnd::Ground) j["end_slope"] = poly.end_slope;
        std::cout << json_text(j) << "\n";
    } else {
        print_air(c);
        std::cout << "eye         y0 = " << g(o.eye_height) << " m, elevation " << g(elev_deg)
                  << " deg (i = " << shortest(i) << " rad)\n";
        std::cout << "invariant   beta = n(y0) sin i = " << shortest(path->beta())
                  << " (n(y0) = " << shortest(path->eta_start()) << ")\n";
        std::cout << "class       " << path->class_name() << "\n";
        if (turns.empty()) std::cout << "turning     none ahead\n";
        if (count < 0 && turns.size() >= 2)
            std::cout << "turning     trapped between " << g(h(std::min(turns[0].y, turns[1].y)))
                      << " m and " << g(h(std::max(turns[0].y, turns[1].y))) << " m, turning every "
                      << g(turns[1].dz - turns[0].dz) << " m\n";
        for (const auto& t : turns)
            std::cout << "turning     " << (t.lowest ? "lowest point" : "apex")
                      << " y = " << g(h(t.y)) << " m at dz = " << g(t.dz) << " m\n";
        if (path->hits_ground())
            std::cout << "ground      hit at dz = " << g(path->dz_ground()) << " m\n";
        else
            std::cout << "ground      not reached\n";
        std::cout << "samples     " << poly.points.size() << " (tolerance " << g(o.tolerance_rad)
                  << " rad seen from the eye";
        if (o.tolerance_m > 0.0) std::cout << " + " << g(o.tolerance_m) << " m";
        std::cout << "), then " << end_name;
        if (poly.end != PathEnd::Ground) std::cout << " with slope " << g(poly.end_slope);
        std::cout << "\n        dz (m)            y (m)\n";
        for (const auto& p : poly.points) std::printf("  %14.8g  %14.8g\n", p.x, h(p.y));
    }
    if (!o.svg.empty()) write_svg(o, c.atmosphere, c.label, c.legend, elev_deg);
}

}  // namespace

void setup_path_command(CLI::App& app) {
    auto o = std::make_shared<PathOptions>();
    auto* sub = app.add_subcommand("path",
                                   "Exact ray path in any stratified atmosphere: class, turning "
                                   "points, samples, transfer curve");
    sub->add_option("--preset", o->preset, "paper, paper-superior, hot-road or cold-sea");
    sub->add_option("--profile", o->profile, "inferior, superior or none (with --eta0 ...)");
    sub->add_option("--eta0", o->eta0, "index at the ground");
    sub->add_option("--eta1", o->eta1, "amplitude of eta^2's change");
    sub->add_option("--alpha", o->alpha, "decay rate, 1/m");
    sub->add_option("--eye-height", o->eye_height, "height of the eye, m");
    sub->add_option("--elevation-deg", o->elevation_deg,
                    "elevation of the ray, degrees (< 0 down)");
    sub->add_option("--i-rad", o->i_rad, "angle from the upward vertical, rad (the paper's i)");
    sub->add_option("--tolerance", o->tolerance_rad,
                    "sampling tolerance: largest error as an angle seen from the eye, rad")
        ->capture_default_str();
    sub->add_option("--tolerance-m", o->tolerance_m, "fixed part of the tolerance, m")
        ->capture_default_str();
    sub->add_option("--max-distance", o->max_distance, "follow the ray this far, m");
    sub->add_flag("--json", o->json, "print the result as JSON");
    sub->add_option("--svg", o->svg, "draw a ray diagram (a fan of rays) to this SVG file")
        ->check(non_empty_name());
    sub->add_option("--fan-from-deg", o->fan_from_deg, "first elevation of the fan, degrees");
    sub->add_option("--fan-to-deg", o->fan_to_deg, "last elevation of the fan, degrees");
    sub->add_option("--fan-count", o->fan_count, "rays in the fan")
        ->check(CLI::Range(1, kMaxFanRays))
        ->capture_default_str();
    sub->add_option("--turbulence-cn2", o->turbulence_cn2,
                    "with --svg: draw the fan's rays through turbulent air of this C_n^2, m^-2/3 "
                    "(dashed; docs/turbulence.md)");
    sub->add_option("--turbulence-inner", o->turbulence_inner, "its inner scale, m (default 0.005)");
    sub->add_option("--turbulence-outer", o->turbulence_outer, "its outer scale, m (default 1)");
    sub->add_option("--turbulence-aperture", o->turbulence_aperture,
                    "the aperture its tilts are averaged over, m (default 0: a point)");
    sub->add_option("--turbulence-seed", o->turbulence_seed, "the first realization's seed")
        ->capture_default_str();
    sub->add_option("--realizations", o->realizations, "realizations of the turbulent air drawn")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    sub->add_option("--batch", o->batch,
                    "evaluate the rays of a CSV (reference columns) and print a CSV")
        ->check(non_empty_name());
    sub->add_option("--air-temperature-c", o->air_temperature_c,
                    "real air: temperature at the ground of the base profile, degC (default 15)");
    sub->add_option("--lapse-k-per-km", o->lapse_k_per_km,
                    "real air: the base cools by this much per km of height (standard: 6.5)");
    sub->add_option("--surface-layer", o->surface_layers,
                    "real air: + DT_K exp(-y / SCALE_M) (hot ground: DT_K > 0), as DT_K,SCALE_M "
                    "(repeat to add)");
    sub->add_option("--inversion", o->inversions,
                    "real air: the temperature rises by DT_K from BOTTOM_M to TOP_M, corners "
                    "smoothed by a Gaussian of standard deviation SMOOTHING_M (default 0), as "
                    "BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M] (repeat to add)");
    sub->add_option(
        "--sounding", o->sounding,
        "real air from a CSV: height_m,temperature_c[,pressure_hpa][,relative_humidity] "
        "or height_m,n");
    sub->add_option("--sounding-max-gap", o->sounding_max_gap,
                    "largest distance between sounding rows, m")
        ->capture_default_str();
    sub->add_option("--pressure-hpa", o->pressure_hpa,
                    "pressure at the ground, hPa (default 1013.25)");
    sub->add_flag("--isobaric", o->isobaric,
                  "the same pressure at every height (else hydrostatic)");
    sub->add_option("--humidity-pct", o->humidity_pct, "relative humidity, % (Ciddor)");
    sub->add_option("--index", o->index, "index of air: gladstone-dale (default) or ciddor");
    sub->add_option("--gladstone-dale", o->gladstone_dale,
                    "Gladstone-Dale: n - 1 at 288.15 K and 1013.25 hPa (default 2.93e-4)");
    sub->add_option("--wavelength-nm", o->wavelength_nm,
                    "Ciddor: vacuum wavelength, nm (default 550)");
    sub->add_option("--co2-ppm", o->co2_ppm, "Ciddor: CO2, ppm (default 450)");
    sub->add_option("--earth-radius", o->earth_radius,
                    "Earth radius, m (0: flat ground, the default; 6371000 for the Earth)");
    sub->add_option("--top", o->top,
                    "height above which the air is homogeneous, m (default 1000 or twice the "
                    "highest inversion or surface layer's reach; a sounding's last row)");
    sub->add_option("--fit-tolerance", o->fit_tolerance,
                    "largest |n_fit - n| of the general engine's piecewise-quadratic model")
        ->capture_default_str();
    sub->add_flag("--general", o->general,
                  "trace a --preset/--profile through the general engine (its n^2 fitted)");
    sub->add_flag("--ducts", o->ducts, "print the profile's ducts (with no ray: only them)");
    sub->add_option("--transfer", o->transfer,
                    "transfer curve: apparent against true elevation of points at this distance, m "
                    "(--svg/--png draw it with the profile)");
    sub->add_option("--transfer-from-deg", o->transfer_from_deg,
                    "first apparent elevation, degrees")
        ->capture_default_str();
    sub->add_option("--transfer-to-deg", o->transfer_to_deg, "last apparent elevation, degrees")
        ->capture_default_str();
    sub->add_option("--transfer-count", o->transfer_count, "rays of the transfer curve")
        ->capture_default_str();
    sub->add_option("--png", o->png, "draw the transfer diagram to this PNG file")
        ->check(non_empty_name());
    sub->add_option("--object-height", o->object_height,
                    "height of an object point, m: the eye distances at which it has a "
                    "mirrored image (the vanishing of the inferior mirage)");
    sub->add_option("--object-distance", o->object_distance,
                    "horizontal distance from the eye to that point, m: is it mirrored from here?");
    // A number option's "nan" would read as the option not given (its default is NaN), or
    // turn its check off: refused as the option is read.
    const CLI::Validator number(
        [](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end != text.c_str() && std::isnan(v)) return "'" + text + "' is not a number";
            return "";
        },
        "NUMBER", "number");
    for (CLI::Option* opt : sub->get_options()) {
        static const std::set<std::string> kNotNumbers = {
            "--help",     "--preset",   "--profile",       "--json",
            "--svg",      "--batch",    "--surface-layer", "--inversion",
            "--sounding", "--isobaric", "--index",         "--general",
            "--ducts",    "--png",      "--fan-count",     "--transfer-count",
            "--realizations"};
        if (!opt->get_name().empty() && !kNotNumbers.count(opt->get_name()) &&
            opt->get_type_size() != 0)
            opt->check(number);
    }
    sub->callback([o] {
        if (!std::isnan(o->turbulence_cn2) && o->svg.empty())
            fail("--turbulence-cn2 draws perturbed rays on the ray diagram: give --svg FILE");
        if (!o->batch.empty() && (!o->svg.empty() || !o->png.empty()))
            fail(std::string(!o->svg.empty() ? "--svg" : "--png") +
                 " draws one ray's diagram: it does not go with --batch, which prints a CSV of "
                 "its rows");
        if (!std::isnan(o->object_height) || !std::isnan(o->object_distance)) {
            if (std::isnan(o->object_height))
                fail("--object-distance needs the point's height: --object-height M");
            run_vanishing(*o);
        } else if (general_requested(*o)) {
            run_general(*o);
        } else if (!o->batch.empty()) {
            run_batch(*o);
        } else {
            if (!o->png.empty()) fail("--png draws the transfer diagram: give --transfer DIST");
            run_single(*o);
        }
    });
}

}  // namespace mirage
