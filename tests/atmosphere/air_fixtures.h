// Atmospheres for the general-profile tests: the exponential presets fitted by the general
// engine, real-air temperature profiles, ducts, and the profiles of
// tests/data/general_profiles.json.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"

namespace mirage::testing {

inline std::shared_ptr<const QuadraticProfile> fit_or_die(const AirSpec& spec, double tol = 1e-12,
                                                          bool spans = false,
                                                          double span_allowance = 1.0) {
    FitSettings fs;
    fs.tolerance_n = tol;
    fs.coarse_spans = spans;
    fs.span_allowance = span_allowance;
    auto q = fit_air(spec, fs);
    EXPECT_TRUE(q.ok()) << (q.ok() ? "" : q.message());
    return q.ok() ? *q : nullptr;
}

inline AirSpec exponential_spec(const char* preset) {
    AirSpec spec;
    spec.source = AirSpec::Source::Exponential;
    spec.exponential = *preset_profile(preset);
    return spec;
}

/// Hot road: T = 300 K + 20 K exp(-y / 0.3 m), Gladstone-Dale, hydrostatic.
inline AirSpec hot_road_spec() {
    AirSpec spec;
    spec.column.ground_temperature_k = 300.0;
    spec.column.layers.push_back({20.0, 0.3});
    spec.top_m = 100.0;
    return spec;
}

/// A flat-Earth duct: a hot ground under an inversion (n peaks near 1 m).
inline AirSpec road_duct_spec() {
    AirSpec spec;
    spec.column.ground_temperature_k = 300.0;
    spec.column.layers.push_back({15.0, 0.2});
    spec.column.inversions.push_back({1.0, 2.5, 6.0, 0.2});
    spec.top_m = 100.0;
    return spec;
}

/// Young's inversion: standard lapse, 2 K between 50 and 60 m, Ciddor at 550 nm, curved Earth.
inline AirSpec young_spec(double smoothing_m) {
    AirSpec spec;
    spec.column.ground_temperature_k = 288.15;
    spec.column.lapse_k_per_m = 0.0065;
    spec.column.inversions.push_back({50.0, 60.0, 2.0, smoothing_m});
    spec.index.formula = IndexFormula::Ciddor;
    spec.index.wavelength_nm = 550.0;
    spec.earth_radius_m = 6371000.0;
    return spec;
}

/// The spec of a profile of tests/data/general_profiles.json (written by
/// tools/gen_general_paths.py).
inline AirSpec spec_from_json(const nlohmann::json& j) {
    AirSpec spec;
    auto num = [&](const nlohmann::json& v) {
        return v.is_string() ? std::stod(v.get<std::string>()) : v.get<double>();
    };
    auto vec = [&](const char* key) {
        std::vector<double> out;
        for (const auto& v : j.at(key)) out.push_back(num(v));
        return out;
    };
    const std::string kind = j.at("kind");
    if (kind == "exponential") {
        spec.source = AirSpec::Source::Exponential;
        spec.exponential = {
            j.at("profile") == "inferior" ? ProfileKind::Inferior : ProfileKind::Superior,
            num(j.at("eta0")), num(j.at("eta1")), num(j.at("alpha"))};
        spec.top_m = num(j.at("top_m"));
        return spec;
    }
    if (kind == "n_sounding") {
        spec.source = AirSpec::Source::Sounding;
        spec.sounding.kind = Sounding::Kind::Index;
        spec.sounding.source = "json";
        spec.sounding.height_m = vec("height_m");
        spec.sounding.index = vec("n");
        return spec;
    }
    if (j.contains("index")) {
        const auto& ix = j.at("index");
        spec.index.formula =
            ix.at("formula") == "ciddor" ? IndexFormula::Ciddor : IndexFormula::GladstoneDale;
        if (ix.contains("gladstone_dale")) spec.index.gladstone_dale = num(ix.at("gladstone_dale"));
        if (ix.contains("wavelength_nm")) spec.index.wavelength_nm = num(ix.at("wavelength_nm"));
        if (ix.contains("co2_ppm")) spec.index.co2_ppm = num(ix.at("co2_ppm"));
    }
    if (j.contains("ground_pressure_pa")) spec.ground_pressure_pa = num(j.at("ground_pressure_pa"));
    if (j.contains("hydrostatic")) spec.hydrostatic = j.at("hydrostatic").get<bool>();
    if (j.contains("relative_humidity") && !j.at("relative_humidity").is_array())
        spec.relative_humidity = num(j.at("relative_humidity"));
    if (j.contains("earth_radius_m")) spec.earth_radius_m = num(j.at("earth_radius_m"));
    if (kind == "column") {
        spec.column.ground_temperature_k = num(j.at("ground_temperature_k"));
        if (j.contains("lapse_k_per_m")) spec.column.lapse_k_per_m = num(j.at("lapse_k_per_m"));
        if (j.contains("layers"))
            for (const auto& l : j.at("layers"))
                spec.column.layers.push_back({num(l[0]), num(l[1])});
        if (j.contains("inversions"))
            for (const auto& v : j.at("inversions"))
                spec.column.inversions.push_back({num(v[0]), num(v[1]), num(v[2]), num(v[3])});
        spec.top_m = num(j.at("top_m"));
        return spec;
    }
    spec.source = AirSpec::Source::Sounding;
    spec.sounding.kind = Sounding::Kind::Temperature;
    spec.sounding.source = "json";
    spec.sounding.height_m = vec("height_m");
    for (double t : vec("temperature_c")) spec.sounding.temperature_k.push_back(t + 273.15);
    if (j.contains("pressure_hpa"))
        for (double p : vec("pressure_hpa")) spec.sounding.pressure_pa.push_back(100.0 * p);
    if (j.contains("relative_humidity"))
        for (double h : vec("relative_humidity"))
            spec.sounding.relative_humidity.push_back(0.01 * h);
    return spec;
}

inline nlohmann::json load_general_profiles() {
    std::ifstream in(std::string(MIRAGE_REFERENCE_DIR) + "/general_profiles.json");
    EXPECT_TRUE(in.good());
    nlohmann::json j;
    if (in) in >> j;
    return j;
}

}  // namespace mirage::testing
