#include "load/atmosphere_settings.h"

#include <algorithm>
#include <cmath>
#include <vector>

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
    // mirage.inc's own and the compiled layers' names
    "Mirage_Inc_Temp",
    "Mirage_Compiled",
    "Mirage_Layer_Texture",
};

std::string where(const Declared& d) { return to_string(d.loc) + ": "; }

// Edit distance, for "did you mean".
size_t distance(const std::string& a, const std::string& b) {
    std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

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

}  // namespace

Result<AtmosphereSettings> read_atmosphere_settings(const Scene& scene) {
    for (const auto& [name, d] : scene.symbols) {
        if (name.rfind("Mirage_", 0) != 0) continue;
        if (std::find(std::begin(kKnown), std::end(kKnown), name) != std::end(kKnown)) continue;
        std::string best;
        size_t best_d = 4;
        for (const char* k : kKnown) {
            const size_t dist = distance(name, k);
            if (dist < best_d) {
                best_d = dist;
                best = k;
            }
        }
        return make_error(where(d) + "unknown setting " + name +
                          (best.empty() ? "" : " (did you mean " + best + "?)"));
    }
    Reader r(scene);
    AtmosphereSettings s;
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
    } else if (air) {
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
        if (s.declared && !validate(scaled))
            return make_error(r.at("Mirage_Unit") + "Mirage_Unit = " + shortest(*unit) +
                              " makes alpha " + shortest(scaled.alpha) +
                              " per scene unit, outside " + shortest(kMinAlpha) + " to " +
                              shortest(kMaxAlpha));
    }
    MIRAGE_TRY(ground, r.number("Mirage_Ground_Height"));
    if (ground) s.ground_height = *ground;
    MIRAGE_TRY(mode, r.text("Mirage_Layers", "adaptive"));
    if (mode) {
        if (*mode == "adaptive") {
            s.layers = LayerMode::Adaptive;
        } else if (*mode == "uniform") {
            s.layers = LayerMode::Uniform;
        } else {
            return make_error(r.at("Mirage_Layers") + "Mirage_Layers \"" + *mode +
                              "\": expected \"adaptive\" or \"uniform\"");
        }
    }
    MIRAGE_TRY(count, r.number("Mirage_Layer_Count"));
    if (count) {
        if (auto c = check_layer_count(*count, r.at("Mirage_Layer_Count") + "Mirage_Layer_Count =");
            !c)
            return c.error();
        s.layer_count = static_cast<int>(*count);
    }
    return s;
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

Profile profile_in_scene_units(const AtmosphereSettings& s) {
    Profile p = s.profile;
    p.alpha *= s.unit_m;  // exp(-alpha y): alpha per metre times metres per unit
    return p;
}

}  // namespace mirage
