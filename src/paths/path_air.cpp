#include "paths/path_air.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "atmosphere/sounding.h"
#include "util/format.h"

namespace mirage {

namespace {

// The numbers of a comma-separated flag value, count between lo and hi.
Result<std::vector<double>> numbers(const std::string& flag, const std::string& value, size_t lo,
                                    size_t hi, const std::string& form) {
    std::vector<double> v;
    std::stringstream in(value);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double x = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(x))
            return make_error(flag + " " + value + ": '" + item + "' is not a number (expected " +
                              form + ")");
        v.push_back(x);
    }
    if (v.size() < lo || v.size() > hi)
        return make_error(flag + " " + value + ": expected " + form);
    return v;
}

bool temperature_forms_given(const PathAirOptions& o) {
    return !std::isnan(o.air_temperature_c) || !std::isnan(o.lapse_k_per_km) ||
           !o.surface_layers.empty() || !o.inversions.empty();
}

// The sounding of --sounding, checked against --sounding-max-gap.
Status read_sounding_air(const PathAirOptions& o, PathAir& air, AirSpec& spec) {
    if (temperature_forms_given(o))
        return make_error("--sounding gives the whole profile: leave out the temperature forms");
    if (!(o.sounding_max_gap > 0.0 && o.sounding_max_gap <= kMaxSoundingGapM))
        return make_error("--sounding-max-gap " + sig(o.sounding_max_gap, 10) +
                          ": must be more than 0 and at most " + sig(kMaxSoundingGapM, 10) + " m");
    SoundingRules rules;
    rules.max_gap_m = o.sounding_max_gap;
    auto s = read_sounding(o.sounding, rules);
    if (!s) return s.error();
    spec.source = AirSpec::Source::Sounding;
    spec.sounding = std::move(*s);
    air.label = "sounding " + o.sounding;
    air.legend.push_back(std::to_string(spec.sounding.height_m.size()) + " rows of " +
                         (spec.sounding.kind == Sounding::Kind::Index ? "n" : "temperature") +
                         ", 0 to " + shortest(spec.sounding.height_m.back()) + " m");
    return Ok{};
}

// The temperature forms: the base at --air-temperature-c with its lapse, the surface layers and
// the inversions.
Status column_air(const PathAirOptions& o, PathAir& air, AirSpec& spec) {
    spec.source = AirSpec::Source::Column;
    AirColumn& col = spec.column;
    const double t_c = std::isnan(o.air_temperature_c) ? 15.0 : o.air_temperature_c;
    col.ground_temperature_k = t_c + 273.15;
    col.lapse_k_per_m = std::isnan(o.lapse_k_per_km) ? 0.0 : 1e-3 * o.lapse_k_per_km;
    air.label = "air at " + shortest(t_c) + " degC";
    if (col.lapse_k_per_m != 0.0)
        air.legend.push_back("lapse " + shortest(o.lapse_k_per_km) + " K/km");
    for (const auto& v : o.surface_layers) {
        auto n = numbers("--surface-layer", v, 2, 2, "DT_K,SCALE_M");
        if (!n) return n.error();
        col.layers.push_back({(*n)[0], (*n)[1]});
        if (auto s = check_surface_layer(col.layers.back()); !s)
            return make_error("--surface-layer " + v + ": " + s.message());
        air.legend.push_back("surface layer " + shortest((*n)[0]) + " K, scale " +
                             shortest((*n)[1]) + " m");
    }
    for (const auto& v : o.inversions) {
        auto r = numbers("--inversion", v, 3, 4, "BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M]");
        if (!r) return r.error();
        const std::vector<double>& n = *r;
        col.inversions.push_back({n[0], n[1], n[2], n.size() > 3 ? n[3] : 0.0});
        if (auto s = check_inversion(col.inversions.back()); !s)
            return make_error("--inversion " + v + ": " + s.message());
        air.legend.push_back(
            "inversion " + shortest(n[2]) + " K, " + shortest(n[0]) + " to " + shortest(n[1]) +
            " m" + (n.size() > 3 && n[3] > 0.0 ? ", smoothing " + shortest(n[3]) + " m" : ""));
    }
    return Ok{};
}

// The index formula, the pressure, the humidity, the Earth and the top; the legend's lines on
// the index, the pressure and the humidity of real air.
Status index_and_ground(const PathAirOptions& o, PathAir& air, AirSpec& spec) {
    if (!o.index.empty()) {
        auto f = parse_index_formula(o.index);
        if (!f) return make_error("--index: " + f.message());
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
    if (spec.source == AirSpec::Source::Exponential) return Ok{};
    air.legend.push_back(spec.index.formula == IndexFormula::Ciddor
                             ? "index: Ciddor, " + shortest(spec.index.wavelength_nm) + " nm"
                             : "index: Gladstone-Dale " + shortest(spec.index.gladstone_dale));
    if (spec.source == AirSpec::Source::Column || spec.sounding.pressure_pa.empty())
        air.legend.push_back("pressure " + shortest(spec.ground_pressure_pa / 100.0) + " hPa, " +
                             (spec.hydrostatic ? "hydrostatic" : "isobaric"));
    if (spec.relative_humidity > 0.0)
        air.legend.push_back("humidity " + shortest(100.0 * spec.relative_humidity) + " %");
    return Ok{};
}

// The air's source: the exponential profile, the sounding or the temperature forms.
Status air_source(const PathAirOptions& o, PathAir& air, AirSpec& spec) {
    if (o.preset.empty() && o.profile.empty())
        return o.sounding.empty() ? column_air(o, air, spec) : read_sounding_air(o, air, spec);
    if (temperature_forms_given(o) || !o.sounding.empty())
        return make_error(
            "--preset/--profile give an exponential profile and --air-temperature-c, "
            "--lapse-k-per-km, --surface-layer, --inversion and --sounding another: give one");
    auto p = resolve_profile(o, air.label);
    if (!p) return p.error();
    spec.source = AirSpec::Source::Exponential;
    spec.exponential = *p;
    air.legend.push_back("exponential n^2, eta0 = " + shortest(p->eta0) + ", eta1 = " +
                         shortest(p->eta1) + ", alpha = " + shortest(p->alpha) + " /m");
    return Ok{};
}

}  // namespace

Result<Profile> resolve_profile(const PathAirOptions& o, std::string& label) {
    Profile p;
    if (!o.preset.empty()) {
        auto preset = preset_profile(o.preset);
        if (!preset) return make_error("--preset: " + preset.message());
        p = *preset;
        label = o.preset + " (" + std::string(profile_kind_name(p.kind)) + ")";
        if (!o.profile.empty() || !std::isnan(o.eta0) || !std::isnan(o.eta1) ||
            !std::isnan(o.alpha))
            return make_error(
                "--preset " + o.preset +
                " fixes the profile: give either --preset or --profile/--eta0/--eta1/--alpha");
    } else {
        if (o.profile.empty())
            return make_error("give --preset NAME or --profile inferior|superior|none");
        auto kind = parse_profile_kind(o.profile);
        if (!kind) return make_error("--profile: " + kind.message());
        p.kind = *kind;
        if (p.kind != ProfileKind::None) {
            if (std::isnan(o.eta0) || std::isnan(o.eta1) || std::isnan(o.alpha))
                return make_error("--profile " + o.profile + " needs --eta0, --eta1 and --alpha");
            p.eta0 = o.eta0;
            p.eta1 = o.eta1;
            p.alpha = o.alpha;
        } else if (!std::isnan(o.eta0)) {
            p.eta0 = o.eta0;
        }
        label = o.profile;
    }
    if (auto s = validate(p, ProfileNames{"--eta0", "--eta1", "--alpha"}); !s) return s.error();
    return p;
}

Result<PathAir> resolve_reference_air(const PathAirOptions& options) {
    PathAir air;
    air.form = AirForm::Reference;
    auto p = resolve_profile(options, air.label);
    if (!p) return p.error();
    air.atmosphere = Atmosphere::exponential(*p);
    return air;
}

Result<PathAir> resolve_air(const PathAirOptions& o) {
    PathAir air;
    AirSpec spec;
    if (auto s = air_source(o, air, spec); !s) return s.error();
    if (auto s = index_and_ground(o, air, spec); !s) return s.error();
    if (!(o.fit_tolerance > 0.0))
        return make_error("--fit-tolerance " + sig(o.fit_tolerance, 10) + ": must be > 0");
    auto model = make_air_model(spec);
    if (!model) return model.error();
    air.model = *model;
    if (spec.source == AirSpec::Source::Exponential && !o.general && spec.earth_radius_m == 0.0) {
        // The closed forms, exact as they are.
        air.atmosphere = Atmosphere::exponential(spec.exponential);
        air.legend.push_back("closed forms");
        return air;
    }
    FitSettings fs;
    fs.tolerance_n = o.fit_tolerance;
    auto q = fit_air(spec, fs, &air.fit);
    if (!q) return q.error();
    air.atmosphere = Atmosphere::quadratic(*q);
    air.legend.push_back("fitted: " + std::to_string(air.fit.pieces) +
                         " pieces, |dn| <= " + shortest(o.fit_tolerance));
    return air;
}

bool air_given(const PathAirOptions& o) {
    return !o.preset.empty() || !o.profile.empty() || temperature_forms_given(o) ||
           !o.sounding.empty() || !std::isnan(o.pressure_hpa) || o.isobaric ||
           !std::isnan(o.humidity_pct) || !o.index.empty() || !std::isnan(o.gladstone_dale) ||
           !std::isnan(o.wavelength_nm) || !std::isnan(o.co2_ppm);
}

std::vector<std::pair<double, double>> duct_heights(const PathAir& air) {
    std::vector<std::pair<double, double>> out;
    const QuadraticProfile* q = air.atmosphere.quadratic_profile();
    if (!q) return out;  // exponential: monotone, no duct
    const double R = air.atmosphere.earth_radius();
    for (const auto& d : find_ducts(*q))
        out.push_back({height_above_sphere(d.bottom, R), height_above_sphere(d.top, R)});
    return out;
}

void write_air_text(const PathAir& air, std::ostream& out) {
    if (air.form == AirForm::Reference) {
        const Profile& p = *air.atmosphere.exponential_profile();
        out << "profile     " << air.label << ": eta0 = " << shortest(p.eta0)
            << ", eta1 = " << shortest(p.eta1) << ", alpha = " << shortest(p.alpha) << " /m\n";
        return;
    }
    out << "profile     " << air.label << "\n";
    for (const auto& l : air.legend) out << "            " << l << "\n";
    if (air.atmosphere.earth_radius() > 0.0)
        out << "            Earth radius " << sig(air.atmosphere.earth_radius(), 10)
            << " m: heights above the sphere, distances along it\n";
    const auto ducts = duct_heights(air);
    if (ducts.empty()) out << "ducts       none\n";
    for (const auto& d : ducts)
        out << "ducts       level rays trapped from " << sig(d.first, 10) << " m to "
            << sig(d.second, 10) << " m\n";
}

nlohmann::json air_json(const PathAir& air) {
    nlohmann::json j;
    if (air.form == AirForm::Reference) {
        const Profile& p = *air.atmosphere.exponential_profile();
        j = {{"kind", profile_kind_name(p.kind)},
             {"eta0", p.eta0},
             {"eta1", p.eta1},
             {"alpha", p.alpha}};
        return j;
    }
    j["label"] = air.label;
    j["legend"] = air.legend;
    if (air.atmosphere.quadratic_profile()) {
        j["pieces"] = air.fit.pieces;
        j["fit_max_error_n"] = air.fit.max_error_n;
    }
    j["earth_radius"] = air.atmosphere.earth_radius();
    nlohmann::json d = nlohmann::json::array();
    for (const auto& [lo, hi] : duct_heights(air)) d.push_back({{"bottom", lo}, {"top", hi}});
    j["ducts"] = d;
    return j;
}

}  // namespace mirage
