#include "load/atmosphere_settings.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <memory>
#include <vector>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"
#include "atmosphere/phase_screens.h"
#include "util/edit_distance.h"
#include "util/format.h"

namespace mirage {

namespace {

const char* const kKnown[] = {
    "Mirage_Preset",
    "Mirage_Profile",
    "Mirage_Eta0",
    "Mirage_Eta1",
    "Mirage_Alpha",
    "Mirage_Air_Temperature",
    "Mirage_Ground_Temperature",
    "Mirage_Scale_Height",
    "Mirage_Pressure",
    "Mirage_Tolerance",
    "Mirage_Extent",
    "Mirage_Unit",
    "Mirage_Ground_Height",
    "Mirage_Layers",
    "Mirage_Layer_Count",
    "Mirage_Exaggeration",
    // turbulent air (docs/turbulence.md)
    "Mirage_Turbulence_Cn2",
    "Mirage_Turbulence_Inner",
    "Mirage_Turbulence_Outer",
    "Mirage_Turbulence_Seed",
    "Mirage_Turbulence_Aperture",
    "Mirage_Wind",
    // real air (the general engine)
    "Mirage_Sounding",
    "Mirage_Sounding_Max_Gap",
    "Mirage_Lapse",
    "Mirage_Inversion",
    "Mirage_Inversion_Smoothing",
    "Mirage_Index",
    "Mirage_Wavelength",
    "Mirage_Wavelengths",
    "Mirage_Humidity",
    "Mirage_Top",
    "Mirage_Upper_Air",
    "Mirage_Earth_Radius",
    // mirage.inc's own and the compiled layers' names
    "Mirage_Inc_Temp",
    "Mirage_Compiled",
    "Mirage_Layer_Texture",
};

// Every known name: kKnown and the numbered inversions (Mirage_Inversion_2, ...).
const std::vector<std::string>& known_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v(std::begin(kKnown), std::end(kKnown));
        for (int k = 2; k <= kMaxInversions; ++k) {
            v.push_back("Mirage_Inversion_" + std::to_string(k));
            v.push_back("Mirage_Inversion_Smoothing_" + std::to_string(k));
        }
        return v;
    }();
    return names;
}

bool internal_name(const std::string& name) {
    return name == "Mirage_Inc_Temp" || name == "Mirage_Compiled" || name == "Mirage_Layer_Texture";
}

std::string where(const Declared& d) { return to_string(d.loc) + ": "; }

class Reader {
  public:
    explicit Reader(const Scene& scene) : scene_(scene) {}

    const Declared* find(const char* name) const {
        auto it = scene_.symbols.find(name);
        return it == scene_.symbols.end() ? nullptr : &it->second;
    }

    Result<std::optional<double>> number(const char* name) const {
        const Declared* d = find(name);
        if (!d) return std::optional<double>();
        if (!std::holds_alternative<double>(d->value))
            return make_error(where(*d) + std::string(name) + " must be a number");
        const double v = std::get<double>(d->value);
        if (!std::isfinite(v))
            return make_error(where(*d) + std::string(name) + " = " + shortest(v) +
                              " must be a finite number");
        return std::optional<double>(v);
    }

    Result<std::optional<std::string>> text(const char* name, const char* example) const {
        const Declared* d = find(name);
        if (!d) return std::optional<std::string>();
        if (!std::holds_alternative<std::string>(d->value))
            return make_error(where(*d) + std::string(name) + " must be a string, e.g. \"" +
                              example + "\"");
        return std::optional<std::string>(std::get<std::string>(d->value));
    }

    Result<std::optional<glm::dvec3>> vector(const char* name, const char* example) const {
        const Declared* d = find(name);
        if (!d) return std::optional<glm::dvec3>();
        if (!std::holds_alternative<glm::dvec3>(d->value))
            return make_error(where(*d) + std::string(name) + " must be a vector, e.g. " + example);
        const glm::dvec3 v = std::get<glm::dvec3>(d->value);
        if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
            return make_error(where(*d) + std::string(name) + " must have finite components");
        return std::optional<glm::dvec3>(v);
    }

    bool has(const char* name) const { return find(name) != nullptr; }

    std::string at(const char* name) const {
        const Declared* d = find(name);
        return d ? where(*d) : scene_.file + ": ";
    }

  private:
    const Scene& scene_;
};

#define MIRAGE_TRY(var, expr)                       \
    auto var##_result = (expr);                     \
    if (!var##_result) return var##_result.error(); \
    auto var = *var##_result

// A number within [lo, hi], named with its place, its limits and its unit.
Result<std::optional<double>> ranged(const Reader& r, const char* name, double lo, double hi,
                                     const char* unit) {
    auto v = r.number(name);
    if (!v) return v.error();
    if (*v && !(**v >= lo && **v <= hi))
        return make_error(r.at(name) + name + " = " + shortest(**v) + " must be from " +
                          shortest(lo) + " to " + shortest(hi) + " (" + unit + ")");
    return *v;
}

// Whether the scene declares real air that only the general engine traces.
bool real_air_forms_declared(const Reader& r) {
    for (const char* name : {"Mirage_Sounding", "Mirage_Sounding_Max_Gap", "Mirage_Lapse",
                             "Mirage_Inversion", "Mirage_Inversion_Smoothing", "Mirage_Index",
                             "Mirage_Wavelength", "Mirage_Humidity", "Mirage_Top",
                             "Mirage_Upper_Air"})
        if (r.has(name)) return true;
    return false;
}

std::string inversion_name(int k, bool smoothing) {
    std::string name = smoothing ? "Mirage_Inversion_Smoothing" : "Mirage_Inversion";
    return k == 1 ? name : name + "_" + std::to_string(k);
}

// The inversions Mirage_Inversion, Mirage_Inversion_2, ... (numbered without gaps), each
// with its smoothing; `first` becomes the place of the first when it still names the Earth's
// radius.
Result<std::vector<Inversion>> read_inversions(const Reader& r, std::string& first) {
    std::vector<Inversion> inversions;
    for (int k = 1; k <= kMaxInversions; ++k) {
        const std::string name = inversion_name(k, false);
        const std::string smooth_name = inversion_name(k, true);
        MIRAGE_TRY(v, r.vector(name.c_str(), "<50, 60, 2> (bottom m, top m, rise K)"));
        MIRAGE_TRY(smooth,
                   ranged(r, smooth_name.c_str(), 0.0, kMaxSmoothingM, "m, standard deviation"));
        if (!v) {
            if (smooth)
                return make_error(r.at(smooth_name.c_str()) + smooth_name + " without " + name);
            for (int j = k + 1; j <= kMaxInversions; ++j) {
                const std::string later = inversion_name(j, false);
                if (r.has(later.c_str()))
                    return make_error(r.at(later.c_str()) + later + " without " + name +
                                      " (number them without gaps)");
            }
            break;
        }
        const std::string at = r.at(name.c_str()) + name + " = <" + shortest(v->x) + ", " +
                               shortest(v->y) + ", " + shortest(v->z) + ">: ";
        if (!(v->x >= 0.0 && v->y > v->x && v->y <= kMaxFormHeightM))
            return make_error(at +
                              "its bottom must be at least 0 and its top above the bottom "
                              "and at most " +
                              shortest(kMaxFormHeightM) + " m");
        if (!(std::abs(v->z) <= kMaxFormDeltaK))
            return make_error(at + "its temperature rise must be from " +
                              shortest(-kMaxFormDeltaK) + " to " + shortest(kMaxFormDeltaK) + " K");
        inversions.push_back({v->x, v->y, v->z, smooth ? *smooth : 0.0});
        if (first == r.at("Mirage_Earth_Radius")) first = r.at(name.c_str());
    }
    return inversions;
}

// Mirage_Upper_Air: "standard" continues the air above Mirage_Top as the standard atmosphere to
// 47 km (the curved Earth's, for air that gives temperature and pressure), "none" keeps it
// homogeneous.
Status read_upper_air(const Reader& r, AirSpec& spec) {
    MIRAGE_TRY(upper, r.text("Mirage_Upper_Air", "standard"));
    if (upper) {
        const std::string at = r.at("Mirage_Upper_Air") + "Mirage_Upper_Air \"" + *upper + "\"";
        if (*upper != "standard" && *upper != "none")
            return make_error(at + ": expected \"standard\" (the standard atmosphere above "
                                   "Mirage_Top, to 47 km) or \"none\" (homogeneous air above)");
        if (*upper == "standard") {
            if (spec.earth_radius_m == 0.0)
                return make_error(at + ": the upper air is the curved Earth's; on flat ground "
                                       "(Mirage_Earth_Radius = 0) rays never leave the air");
            if (spec.source == AirSpec::Source::Sounding &&
                spec.sounding.kind == Sounding::Kind::Index)
                return make_error(at + ": the upper air continues the air's temperature and "
                                       "pressure, which a sounding of n does not give");
            spec.upper_air = true;
        }
    }
    return Ok{};
}

// Real air: the spec of the general engine, from a sounding or the temperature forms, or an
// exponential profile declared already (s.profile) on the curved Earth.
Status read_real_air(const Reader& r, const Scene& scene, MirageSettings& s) {
    AirSpec spec;
    std::string label;
    // The place that names the air as a whole, for what make_air_model finds.
    std::string first = r.at("Mirage_Earth_Radius");
    MIRAGE_TRY(radius, r.number("Mirage_Earth_Radius"));
    if (radius && !(*radius == 0.0 || (*radius >= kMinEarthRadiusM && *radius <= kMaxEarthRadiusM)))
        return make_error(r.at("Mirage_Earth_Radius") +
                          "Mirage_Earth_Radius = " + shortest(*radius) +
                          " must be 0 (flat ground) or from " + shortest(kMinEarthRadiusM) +
                          " to " + shortest(kMaxEarthRadiusM) + " (m)");
    if (s.declared && !real_air_forms_declared(r)) {
        // An exponential profile: on flat ground the closed forms, as without the setting.
        if (*radius == 0.0) return Ok{};
        spec.source = AirSpec::Source::Exponential;
        spec.exponential = s.profile;
        spec.earth_radius_m = *radius;
        s.air = std::make_shared<const AirSpec>(spec);
        s.profile_label += ", Earth radius " + shortest(*radius / 1000.0) + " km";
        return Ok{};
    }
    MIRAGE_TRY(sounding, r.text("Mirage_Sounding", "road.csv"));
    MIRAGE_TRY(gap, ranged(r, "Mirage_Sounding_Max_Gap", 1e-3, kMaxFormHeightM, "m"));
    MIRAGE_TRY(lapse, ranged(r, "Mirage_Lapse", -kMaxLapseKPerKm, kMaxLapseKPerKm, "K per km"));
    MIRAGE_TRY(t_air, ranged(r, "Mirage_Air_Temperature", 100.0, 400.0, "K"));
    MIRAGE_TRY(t_ground, ranged(r, "Mirage_Ground_Temperature", 100.0, 400.0, "K"));
    MIRAGE_TRY(height, ranged(r, "Mirage_Scale_Height", kMinScaleHeightM, kMaxFormHeightM, "m"));
    MIRAGE_TRY(pressure, ranged(r, "Mirage_Pressure", 1.0, 2000.0, "hPa"));
    MIRAGE_TRY(index, r.text("Mirage_Index", "ciddor"));
    MIRAGE_TRY(wavelength, ranged(r, "Mirage_Wavelength", 300.0, 1690.0, "nm, Ciddor's range"));
    MIRAGE_TRY(humidity, ranged(r, "Mirage_Humidity", 0.0, 100.0, "%"));
    MIRAGE_TRY(top, ranged(r, "Mirage_Top", 1e-3, kMaxFormHeightM, "m"));
    MIRAGE_TRY(inversions, read_inversions(r, first));
    if (sounding) {
        if (lapse || !inversions.empty() || t_air || t_ground || height)
            return make_error(r.at("Mirage_Sounding") +
                              "Mirage_Sounding gives the whole profile: leave out Mirage_Lapse, "
                              "Mirage_Inversion and the Mirage_..._Temperature values");
        namespace fs = std::filesystem;
        fs::path path(*sounding);
        if (path.is_relative()) path = fs::path(scene.file).parent_path() / path;
        SoundingRules rules;
        if (gap) rules.max_gap_m = *gap;
        auto read = read_sounding(path.string(), rules);
        if (!read)
            return make_error(r.at("Mirage_Sounding") + "Mirage_Sounding: " + read.message());
        spec.source = AirSpec::Source::Sounding;
        spec.sounding = std::move(*read);
        s.input_files.push_back(path.string());
        label = "sounding " + *sounding + " (" + std::to_string(spec.sounding.height_m.size()) +
                " rows of " + (spec.sounding.kind == Sounding::Kind::Index ? "n" : "temperature") +
                ")";
        first = r.at("Mirage_Sounding");
    } else {
        if (gap)
            return make_error(r.at("Mirage_Sounding_Max_Gap") +
                              "Mirage_Sounding_Max_Gap without Mirage_Sounding");
        if ((t_ground || height) && !(t_ground && height))
            return make_error(r.at(t_ground ? "Mirage_Ground_Temperature" : "Mirage_Scale_Height") +
                              "a surface layer needs both Mirage_Ground_Temperature and "
                              "Mirage_Scale_Height");
        if (t_ground && !t_air)
            return make_error(r.at("Mirage_Ground_Temperature") +
                              "a surface layer needs Mirage_Air_Temperature (the air above it)");
        AirColumn& col = spec.column;
        spec.source = AirSpec::Source::Column;
        col.ground_temperature_k = t_air ? *t_air : 288.15;
        col.lapse_k_per_m = lapse ? 1e-3 * *lapse : 0.0;
        label = "air at " + shortest(col.ground_temperature_k) + " K";
        if (lapse) label += ", lapse " + shortest(*lapse) + " K/km";
        if (t_ground) {
            col.layers.push_back({*t_ground - *t_air, *height});
            label +=
                ", " + shortest(*t_ground) + " K at the ground (scale " + shortest(*height) + " m)";
        }
        for (const Inversion& v : inversions)
            label += ", inversion " + shortest(v.delta_k) + " K from " + shortest(v.bottom_m) +
                     " to " + shortest(v.top_m) + " m" +
                     (v.smoothing_m > 0.0 ? " (smoothed " + shortest(v.smoothing_m) + " m)" : "");
        col.inversions = std::move(inversions);
        if (t_air) first = r.at("Mirage_Air_Temperature");
        if (lapse) first = r.at("Mirage_Lapse");
    }
    if (index) {
        auto f = parse_index_formula(*index);
        if (!f) return make_error(r.at("Mirage_Index") + "Mirage_Index: " + f.message());
        spec.index.formula = *f;
    }
    if (wavelength) spec.index.wavelength_nm = *wavelength;
    if (humidity) spec.relative_humidity = 0.01 * *humidity;
    if (pressure) spec.ground_pressure_pa = 100.0 * *pressure;
    if (top) spec.top_m = *top;
    spec.earth_radius_m = radius ? *radius : kEarthRadiusM;
    if (auto st = read_upper_air(r, spec); !st) return st.error();
    label += spec.index.formula == IndexFormula::Ciddor
                 ? ", Ciddor " + shortest(spec.index.wavelength_nm) + " nm"
                 : ", Gladstone-Dale";
    label += spec.earth_radius_m > 0.0
                 ? ", Earth radius " + shortest(spec.earth_radius_m / 1000.0) + " km"
                 : ", flat ground";
    if (spec.upper_air) label += ", standard upper air to 47 km";
    // The whole air checked once here, with the place of the setting that describes it.
    if (auto model = make_air_model(spec); !model)
        return make_error((top ? r.at("Mirage_Top") : first) + model.message());
    s.air = std::make_shared<const AirSpec>(std::move(spec));
    s.profile = Profile{};
    s.profile.kind = ProfileKind::None;
    s.profile_label = std::move(label);
    s.declared = true;
    return Ok{};
}

// Turbulent air: Mirage_Turbulence_Cn2 (0 or none: off) and the settings that go with it, each
// checked with its place.
Status read_turbulence(const Reader& r, MirageSettings& s) {
    MIRAGE_TRY(cn2, ranged(r, "Mirage_Turbulence_Cn2", 0.0, kMaxCn2, "m^-2/3"));
    MIRAGE_TRY(inner, ranged(r, "Mirage_Turbulence_Inner", kMinScaleM, kMaxScaleM, "m"));
    MIRAGE_TRY(outer, ranged(r, "Mirage_Turbulence_Outer", kMinScaleM, kMaxScaleM, "m"));
    MIRAGE_TRY(seed, ranged(r, "Mirage_Turbulence_Seed", 0.0, kMaxTurbulenceSeed,
                            "a whole number"));
    MIRAGE_TRY(aperture, ranged(r, "Mirage_Turbulence_Aperture", 0.0, kMaxApertureM, "m"));
    MIRAGE_TRY(wind, r.vector("Mirage_Wind", "<1.5, 0, 0> (m/s)"));
    if (!cn2) {
        for (const char* name : {"Mirage_Turbulence_Inner", "Mirage_Turbulence_Outer",
                                 "Mirage_Turbulence_Seed", "Mirage_Turbulence_Aperture",
                                 "Mirage_Wind"})
            if (r.has(name))
                return make_error(r.at(name) + name +
                                  " without Mirage_Turbulence_Cn2 (the turbulence's strength)");
        return Ok{};
    }
    if (seed && std::floor(*seed) != *seed)
        return make_error(r.at("Mirage_Turbulence_Seed") + "Mirage_Turbulence_Seed = " +
                          shortest(*seed) + " must be a whole number from 0 to " +
                          shortest(kMaxTurbulenceSeed));
    TurbulenceSettings t;
    t.cn2 = *cn2;
    if (inner) t.inner_scale_m = *inner;
    if (outer) t.outer_scale_m = *outer;
    if (!(t.inner_scale_m < t.outer_scale_m))
        return make_error(r.at(inner ? "Mirage_Turbulence_Inner" : "Mirage_Turbulence_Outer") +
                          "the inner scale " + shortest(t.inner_scale_m) +
                          " m (Mirage_Turbulence_Inner) must be below the outer scale " +
                          shortest(t.outer_scale_m) + " m (Mirage_Turbulence_Outer)");
    if (wind) {
        const double speed = glm::length(*wind);
        if (!(speed <= kMaxWindMps))
            return make_error(r.at("Mirage_Wind") + "Mirage_Wind = <" + shortest(wind->x) + ", " +
                              shortest(wind->y) + ", " + shortest(wind->z) + ">: its speed " +
                              shortest(speed) + " m/s must be at most " + shortest(kMaxWindMps) +
                              " m/s");
        t.wind = *wind;
    }
    if (seed) t.seed = static_cast<std::uint64_t>(*seed);
    if (auto st = check_turbulence(t); !st)
        return make_error(r.at("Mirage_Turbulence_Cn2") + "Mirage_Turbulence_Cn2: " + st.message());
    s.turbulence_aperture_m = aperture ? *aperture : 0.0;
    if (t.cn2 > 0.0) s.turbulence = t;
    return Ok{};
}

// Colour: Mirage_Wavelengths = <red, green, blue> (nm), checked with its place; the air then
// has the green channel's wavelength.
Status read_colour(const Reader& r, MirageSettings& s) {
    MIRAGE_TRY(v, r.vector("Mirage_Wavelengths", "<610, 550, 465> (red, green, blue; nm)"));
    if (!v) return Ok{};
    const std::string name = r.at("Mirage_Wavelengths") + "Mirage_Wavelengths = <" +
                             shortest(v->x) + ", " + shortest(v->y) + ", " + shortest(v->z) + ">";
    if (r.has("Mirage_Wavelength"))
        return make_error(r.at("Mirage_Wavelength") +
                          "declare one: Mirage_Wavelength (one wavelength for every channel) or "
                          "Mirage_Wavelengths (colour: one per channel)");
    MIRAGE_TRY(nm, check_channel_wavelengths({v->x, v->y, v->z}, name));
    if (auto st = set_wavelength(s, nm[1], name); !st) return st.error();
    s.channel_wavelengths_nm = nm;
    return Ok{};
}

}  // namespace

std::vector<std::string> atmosphere_setting_names() {
    std::vector<std::string> names;
    for (const auto& n : known_names())
        if (!internal_name(n)) names.push_back(n);
    return names;
}

namespace {

// The settings besides the atmosphere: the tolerance, the extent, the unit, the ground's height
// and the layers asked for, each checked with its place.
Status read_rendering_settings(const Reader& r, MirageSettings& s) {
    MIRAGE_TRY(tol, r.number("Mirage_Tolerance"));
    if (tol) {
        if (auto c = check_tolerance_px(*tol, r.at("Mirage_Tolerance") + "Mirage_Tolerance ="); !c)
            return c.error();
        s.tolerance_px = *tol;
    }
    MIRAGE_TRY(extent, r.number("Mirage_Extent"));
    if (extent) {
        if (!(*extent > 0.0 && *extent <= kMaxCoordinate))
            return make_error(r.at("Mirage_Extent") + "Mirage_Extent = " + shortest(*extent) +
                              " must be more than 0 and at most " + shortest(kMaxCoordinate) +
                              " (scene units)");
        s.extent = *extent;
    }
    MIRAGE_TRY(unit, r.number("Mirage_Unit"));
    if (unit) {
        if (!(*unit >= kMinUnitM && *unit <= kMaxUnitM))
            return make_error(r.at("Mirage_Unit") + "Mirage_Unit = " + shortest(*unit) +
                              " must be from " + shortest(kMinUnitM) + " to " +
                              shortest(kMaxUnitM) + " (metres per unit)");
        s.unit_m = *unit;
        // The profile the tracer and the compiler use has alpha per scene unit.
        const Profile scaled = profile_in_scene_units(s);
        if (s.declared && !s.air && !validate(scaled))
            return make_error(r.at("Mirage_Unit") + "Mirage_Unit = " + shortest(*unit) +
                              " makes alpha " + shortest(scaled.alpha) +
                              " per scene unit, outside " + shortest(kMinAlpha) + " to " +
                              shortest(kMaxAlpha));
    }
    MIRAGE_TRY(ground, r.number("Mirage_Ground_Height"));
    if (ground) {
        // The scene is moved by it (the tracer lowers every object to the ground).
        if (!(std::abs(*ground) <= kMaxCoordinate))
            return make_error(r.at("Mirage_Ground_Height") + "Mirage_Ground_Height = " +
                              shortest(*ground) + " must be from " + shortest(-kMaxCoordinate) +
                              " to " + shortest(kMaxCoordinate) + " (scene units)");
        s.ground_height = *ground;
    }
    MIRAGE_TRY(mode, r.text("Mirage_Layers", "adaptive"));
    if (mode) {
        if (*mode == "adaptive") {
            s.layers = LayerMode::Adaptive;
        } else if (*mode == "uniform") {
            s.layers = LayerMode::Uniform;
        } else if (*mode == "index-steps") {
            s.layers = LayerMode::IndexSteps;
        } else {
            return make_error(r.at("Mirage_Layers") + "Mirage_Layers \"" + *mode +
                              "\": expected \"adaptive\", \"uniform\" or \"index-steps\"");
        }
    }
    MIRAGE_TRY(count, r.number("Mirage_Layer_Count"));
    if (count) {
        if (auto c = check_layer_count(*count, r.at("Mirage_Layer_Count") + "Mirage_Layer_Count =");
            !c)
            return c.error();
        s.layer_count = static_cast<int>(*count);
    }
    return Ok{};
}

}  // namespace

Result<MirageSettings> read_atmosphere_settings(const Scene& scene) {
    for (const auto& [name, d] : scene.symbols) {
        if (name.rfind("Mirage_", 0) != 0) continue;
        const auto& known = known_names();
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        const std::string best = closest_name(name, known, 4);
        return make_error(where(d) + "unknown setting " + name +
                          (best.empty() ? "" : " (did you mean " + best + "?)"));
    }
    Reader r(scene);
    MirageSettings s;
    MIRAGE_TRY(preset, r.text("Mirage_Preset", "paper"));
    MIRAGE_TRY(kind_name, r.text("Mirage_Profile", "inferior"));
    MIRAGE_TRY(eta0, r.number("Mirage_Eta0"));
    MIRAGE_TRY(eta1, r.number("Mirage_Eta1"));
    MIRAGE_TRY(alpha, r.number("Mirage_Alpha"));
    MIRAGE_TRY(t_air, r.number("Mirage_Air_Temperature"));
    MIRAGE_TRY(t_ground, r.number("Mirage_Ground_Temperature"));
    MIRAGE_TRY(height, r.number("Mirage_Scale_Height"));
    MIRAGE_TRY(pressure, r.number("Mirage_Pressure"));
    const bool explicit_profile = eta0 || eta1 || alpha;
    const bool air = t_air || t_ground || height || pressure;
    const bool exponential = preset || explicit_profile || kind_name;
    // Real air: a sounding or temperature forms the exponential fit cannot say; the
    // Mirage_..._Temperature values then describe it exactly.
    const bool forms = real_air_forms_declared(r);
    if (forms && exponential)
        return make_error(r.at(preset      ? "Mirage_Preset"
                               : kind_name ? "Mirage_Profile"
                                           : "Mirage_Eta0") +
                          "declare the atmosphere one way: an exponential profile (Mirage_Preset, "
                          "Mirage_Profile) or real air (Mirage_Sounding, Mirage_Lapse, "
                          "Mirage_Inversion, ...)");
    const int ways = (preset ? 1 : 0) + (explicit_profile ? 1 : 0) + (air ? 1 : 0);
    if (ways > 1)
        return make_error(r.at(preset ? "Mirage_Preset" : "Mirage_Eta0") +
                          "declare the atmosphere one way: Mirage_Preset, or Mirage_Profile with "
                          "Mirage_Eta0/Eta1/Alpha, or the Mirage_..._Temperature values");
    if (preset) {
        auto p = preset_profile(*preset);
        if (!p) return make_error(r.at("Mirage_Preset") + "Mirage_Preset: " + p.message());
        s.profile = *p;
        s.profile_label = *preset + " (" + std::string(profile_kind_name(p->kind)) + ")";
        s.declared = true;
        if (kind_name && *kind_name != profile_kind_name(p->kind))
            return make_error(r.at("Mirage_Profile") + "Mirage_Profile \"" + *kind_name +
                              "\" contradicts Mirage_Preset \"" + *preset + "\" (" +
                              std::string(profile_kind_name(p->kind)) + ")");
    } else if (explicit_profile || kind_name) {
        ProfileKind kind = ProfileKind::Inferior;
        if (kind_name) {
            auto k = parse_profile_kind(*kind_name);
            if (!k) return make_error(r.at("Mirage_Profile") + "Mirage_Profile: " + k.message());
            kind = *k;
        } else {
            return make_error(
                r.at("Mirage_Eta0") +
                "an explicit profile needs Mirage_Profile (\"inferior\" or \"superior\")");
        }
        if (kind != ProfileKind::None && !(eta0 && eta1 && alpha))
            return make_error(r.at("Mirage_Profile") + "Mirage_Profile \"" + *kind_name +
                              "\" needs Mirage_Eta0, Mirage_Eta1 and Mirage_Alpha");
        s.profile = Profile{kind, eta0 ? *eta0 : 1.0, eta1 ? *eta1 : 0.0, alpha ? *alpha : 1.0};
        const ProfileNames names{r.at("Mirage_Eta0") + "Mirage_Eta0",
                                 r.at("Mirage_Eta1") + "Mirage_Eta1",
                                 r.at("Mirage_Alpha") + "Mirage_Alpha"};
        if (auto v = validate(s.profile, names); !v) return v.error();
        s.profile_label = "explicit " + std::string(profile_kind_name(kind));
        s.declared = kind != ProfileKind::None;
    } else if (air && !forms && !r.has("Mirage_Earth_Radius")) {
        if (!t_air || !t_ground || !height)
            return make_error(r.at(t_air ? "Mirage_Air_Temperature" : "Mirage_Ground_Temperature") +
                              "real air needs Mirage_Air_Temperature, Mirage_Ground_Temperature "
                              "and Mirage_Scale_Height");
        auto p = air_profile(*t_air, *t_ground - *t_air, *height, pressure ? *pressure : 1013.25);
        if (!p) return make_error(r.at("Mirage_Air_Temperature") + p.message());
        s.profile = *p;
        s.profile_label = "air " + shortest(*t_ground) + " K at the ground, " + shortest(*t_air) +
                          " K aloft (" + std::string(profile_kind_name(p->kind)) + ")";
        s.declared = true;
    }
    if (forms || r.has("Mirage_Earth_Radius")) {
        if (auto st = read_real_air(r, scene, s); !st) return st.error();
    }
    MIRAGE_TRY(exaggeration, ranged(r, "Mirage_Exaggeration", kMinExaggeration, kMaxExaggeration,
                                    "times the air's index excess over the ground's"));
    if (exaggeration) {
        const std::string name =
            r.at("Mirage_Exaggeration") + "Mirage_Exaggeration = " + shortest(*exaggeration);
        if (auto st = exaggerate_atmosphere(s, *exaggeration, name); !st) return st.error();
    }
    if (auto st = read_rendering_settings(r, s); !st) return st.error();
    if (auto st = read_turbulence(r, s); !st) return st.error();
    if (auto st = read_colour(r, s); !st) return st.error();
    return s;
}

Result<ChannelWavelengths> check_channel_wavelengths(const std::vector<double>& nm,
                                                     const std::string& name) {
    if (nm.size() != 3)
        return make_error(name + ": give three wavelengths, the red, green and blue channels' "
                                 "(nm), e.g. 610,550,465");
    ChannelWavelengths out{};
    for (int k = 0; k < 3; ++k) {
        if (!(nm[k] >= kMinWavelengthNm && nm[k] <= kMaxWavelengthNm))
            return make_error(name + ": the " + (k == 0 ? "red" : k == 1 ? "green" : "blue") +
                              " channel's wavelength " + shortest(nm[k]) + " nm must be from " +
                              shortest(kMinWavelengthNm) + " to " + shortest(kMaxWavelengthNm) +
                              " nm (Ciddor's range)");
        out[k] = nm[k];
    }
    return out;
}

Status set_wavelength(MirageSettings& s, double nm, const std::string& name) {
    if (!(nm >= kMinWavelengthNm && nm <= kMaxWavelengthNm))
        return make_error(name + ": the wavelength " + shortest(nm) + " nm must be from " +
                          shortest(kMinWavelengthNm) + " to " + shortest(kMaxWavelengthNm) +
                          " nm (Ciddor's range)");
    const char* refusal = nullptr;
    if (!bends_rays(s)) {
        refusal = "the scene declares no atmosphere to give a wavelength to";
    } else if (!s.air || s.air->source == AirSpec::Source::Exponential) {
        // Khular's eta0, eta1 and alpha are indices at no stated wavelength: scaling them by
        // Ciddor's dispersion would invent the air they stand for (docs/colour.md).
        refusal =
            "an exponential profile (Mirage_Preset, Mirage_Profile, the exponential fit of "
            "Mirage_..._Temperature) has no wavelength: declare real air (Mirage_Lapse, "
            "Mirage_Inversion or Mirage_Sounding) with Mirage_Index = \"ciddor\"";
    } else if (s.air->source == AirSpec::Source::Sounding &&
               s.air->sounding.kind == Sounding::Kind::Index) {
        refusal = "a sounding of the index n has no wavelength: give it as temperatures";
    } else if (s.air->index.formula != IndexFormula::Ciddor) {
        refusal =
            "Gladstone-Dale's index has no wavelength: declare Mirage_Index = \"ciddor\"";
    }
    if (refusal) return make_error(name + ": " + refusal);
    AirSpec spec = *s.air;
    const std::string before = ", Ciddor " + shortest(spec.index.wavelength_nm) + " nm";
    spec.index.wavelength_nm = nm;
    if (auto model = make_air_model(spec); !model) return make_error(name + ": " + model.message());
    s.air = std::make_shared<const AirSpec>(std::move(spec));
    if (auto at = s.profile_label.find(before); at != std::string::npos)
        s.profile_label.replace(at, before.size(), ", Ciddor " + shortest(nm) + " nm");
    return Ok{};
}

Status exaggerate_atmosphere(MirageSettings& s, double k, const std::string& name) {
    if (k == 1.0) return Ok{};
    if (!(k >= kMinExaggeration && k <= kMaxExaggeration))
        return make_error(name + ": the exaggeration must be from " + shortest(kMinExaggeration) +
                          " to " + shortest(kMaxExaggeration));
    if (!bends_rays(s))
        return make_error(name +
                          ": there is no index gradient to exaggerate: declare an "
                          "atmosphere (Mirage_Preset, ...) first");
    // n_k^2 = n0^2 + k (n^2 - n0^2): the exponential profiles' eta1^2 times k.
    const double root_k = std::sqrt(k);
    if (s.profile.kind != ProfileKind::None) {
        s.profile.eta1 *= root_k;
        const std::string made = name + ": the exaggerated profile's ";
        if (auto v =
                validate(s.profile, ProfileNames{made + "eta0", made + "eta1", made + "alpha"});
            !v)
            return v.error();
    }
    if (s.air) {
        AirSpec spec = *s.air;
        if (spec.source == AirSpec::Source::Exponential) {
            spec.exponential = s.profile;
        } else {
            spec.exaggeration *= k;
            if (auto model = make_air_model(spec); !model)
                return make_error(name + ": " + model.message());
        }
        s.air = std::make_shared<const AirSpec>(std::move(spec));
    }
    s.exaggeration *= k;
    s.profile_label += ", exaggerated " + shortest(s.exaggeration) + " times (not air)";
    return Ok{};
}

Status check_tolerance_px(double px, const std::string& name) {
    if (px >= kMinTolerancePx && px <= kMaxTolerancePx) return Ok{};
    return make_error(name + " " + shortest(px) + ": the tolerance must be from " +
                      shortest(kMinTolerancePx) + " to " + shortest(kMaxTolerancePx) + " pixels");
}

Status check_layer_count(double count, const std::string& name) {
    if (count >= 1.0 && count <= kMaxLayerCount && std::floor(count) == count) return Ok{};
    return make_error(name + " " + shortest(count) +
                      ": the layer count must be a whole number from 1 to " +
                      std::to_string(kMaxLayerCount));
}

Profile profile_in_scene_units(const MirageSettings& s) {
    Profile p = s.profile;
    p.alpha *= s.unit_m;  // exp(-alpha y): alpha per metre times metres per unit
    return p;
}

bool bends_rays(const MirageSettings& s) {
    return s.declared && (s.air || s.profile.kind != ProfileKind::None);
}

double fit_tolerance_for(double tolerance_rad) {
    const double eps = std::pow(0.5 * tolerance_rad / M_PI, 2);
    return std::clamp(eps, kMinFitTolerance, kMaxFitTolerance);
}

double fit_angle_rad(const PixelFootprint& footprint, double tolerance_px, double reach) {
    double rad = tolerance_px * footprint.angle_rad;
    if (footprint.distance > 0.0) rad += tolerance_px * footprint.distance / reach;
    return rad;
}

Result<Atmosphere> scene_atmosphere(const MirageSettings& s, double tolerance_rad, int* pieces) {
    if (pieces) *pieces = 0;
    if (!s.air) return Atmosphere::exponential(profile_in_scene_units(s));
    FitSettings fs;
    fs.tolerance_n = fit_tolerance_for(tolerance_rad);
    fs.coarse_spans = true;
    FitReport report;
    auto fitted = fit_air(*s.air, fs, &report);
    if (!fitted) return fitted.error();
    if (pieces) *pieces = report.pieces;
    if (s.unit_m == 1.0) return Atmosphere::quadratic(*fitted);
    auto scaled = (*fitted)->rescaled(s.unit_m);
    if (!scaled) return scaled.error();
    return Atmosphere::quadratic(std::make_shared<const QuadraticProfile>(std::move(*scaled)));
}

}  // namespace mirage
