// What `mirage path` is asked: the air (an exponential profile or real air), one ray, its fan
// diagram, a batch of rays, the transfer curve or a point's mirrored image.  Plain data: NaN
// stands for a number not given.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace mirage {

inline constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();

/// The options that say what the air is.  An exponential profile (--preset, or --profile with
/// --eta0/--eta1/--alpha) alone keeps its closed forms and the reference's report; any of the
/// others selects real air through the general engine (the exponential n^2 fitted with
/// `general`).
struct PathAirOptions {
    std::string preset;
    std::string profile;
    double eta0 = kNotGiven, eta1 = kNotGiven, alpha = kNotGiven;

    double air_temperature_c = kNotGiven;
    double lapse_k_per_km = kNotGiven;
    std::vector<std::string> surface_layers;  // "DT_K,SCALE_M"
    std::vector<std::string> inversions;      // "BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M]"
    std::string sounding;
    double sounding_max_gap = 1000.0;  // m
    double pressure_hpa = kNotGiven;
    bool isobaric = false;
    double humidity_pct = kNotGiven;
    std::string index;
    double gladstone_dale = kNotGiven, wavelength_nm = kNotGiven, co2_ppm = kNotGiven;
    double earth_radius = kNotGiven;  // m
    double top = kNotGiven;           // m
    double fit_tolerance = 1e-10;     // largest |n_fit - n| of the piecewise-quadratic model
    bool general = false;
};

struct PathOptions {
    PathAirOptions air;
    double eye_height = kNotGiven;     // m
    double elevation_deg = kNotGiven;  // the ray's elevation at the eye
    double i_rad = kNotGiven;          // or its angle from the upward vertical
    double tolerance_rad = 1e-3;       // sampling tolerance, an angle seen from the eye
    double tolerance_m = 0.0;          // its fixed part, m
    double max_distance = std::numeric_limits<double>::infinity();  // m
    bool json = false;

    std::string svg;  // the fan diagram, or the transfer diagram with `transfer`
    double fan_from_deg = kNotGiven, fan_to_deg = kNotGiven;
    int fan_count = 13;
    // Turbulent air (docs/turbulence.md): the fan's rays through `realizations` of it, dashed.
    double turbulence_cn2 = kNotGiven;                                  // m^-2/3
    double turbulence_inner = kNotGiven, turbulence_outer = kNotGiven;  // m
    double turbulence_aperture = 0.0;                                   // m
    double turbulence_seed = 1.0;
    int realizations = 4;

    std::string batch;  // a CSV of rays in the reference's columns
    double object_distance = kNotGiven, object_height = kNotGiven;  // a point's mirrored image

    bool ducts = false;
    double transfer = kNotGiven;  // the transfer curve's distance, m
    double transfer_from_deg = -0.25, transfer_to_deg = 0.25;
    int transfer_count = 2001;
    std::string png;  // the transfer diagram
};

/// The files the command reads: no output may replace one of them.
std::vector<std::string> path_input_files(const PathOptions& options);

/// Whether the options ask for the general engine's report: any real-air option, the Earth's
/// radius, --general, --transfer or --ducts.
bool general_requested(const PathOptions& options);

}  // namespace mirage
