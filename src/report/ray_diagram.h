// Ray diagrams in the manner of Khote & Howard's figures 1, 2 and 6: a fan of rays from the
// eye, their sample points, turning points and the ground, with axes in metres, for any
// atmosphere (exact_path.h): ducts are shaded, and with an Earth radius heights are drawn above
// the sphere against distances along it.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "atmosphere/exact_path.h"
#include "util/result.h"

namespace mirage {

/// The most rays a diagram draws.
constexpr int kMaxFanRays = 500;

/// A ray drawn thin over the fan: points (horizontal distance, model height) in m, and the fan ray
/// it goes with (its colour).
struct OverlaidRay {
    int fan_ray = 0;
    std::vector<glm::dvec2> points;
};

struct RayDiagramSettings {
    Atmosphere atmosphere;
    std::string profile_label;        // shown in the title and legend, e.g. "paper (inferior)"
    std::vector<std::string> legend;  // lines describing the profile (e.g. its parameters)
    double eye_height = 1.5;          // m (above the sphere with an Earth radius)
    double elev_from_deg = -20.0;     // first ray's elevation, degrees
    double elev_to_deg = 5.0;         // last ray's elevation, degrees
    int count = 11;                   // rays in the fan, 1 to kMaxFanRays
    double max_distance = 40.0;       // horizontal extent drawn, m
    double tolerance_rad = 1e-3;      // sampling tolerance, angle seen from the eye
    double tolerance_m = 0.0;         // sampling tolerance, fixed part, m
    // Drawn thin over the fan (mirage path's rays through turbulent air), with a legend line.
    std::vector<OverlaidRay> overlaid;
    std::string overlaid_label;
    int width_px = 960;
    int height_px = 560;
};

/// The diagram as a standalone SVG document.
Result<std::string> ray_diagram_svg(const RayDiagramSettings& settings);

}  // namespace mirage
