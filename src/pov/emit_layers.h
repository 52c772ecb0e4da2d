// Writing a layer design for POV-Ray: the include with the layers, the .ini that renders the
// scene with them, and the layer table as CSV.
//
// The layout follows the measured facts about POV-Ray (DESIGN.md): never adjacent boxes
// (their coincident faces corrupt POV-Ray's list of interiors); instead planes split at the
// camera's layer, `plane { y, h }` below it (inside is below) and `plane { -y, -h }` above it
// (inside is above), each plane's index divided by the camera layer's.  The camera is then
// inside no layer and POV-Ray's outside index of 1 stands for its layer.  Each plane is
// clipped to a thin slab around it spanning the layers' horizontal extent, which with +BM2
// bounds it tightly; layers are invisible (rgbf 1, no finish) and cast no shadow.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "layers/band_tracer3d.h"
#include "layers/stack.h"

namespace mirage {

enum class LayerLayout {
    Nested,  // planes split at the camera's layer, nested: one trace level per boundary
    Gaps,    // disjoint slabs with thin gaps of the camera's index between them: two levels
             // per boundary, every refraction in double precision (see below)
};

// Why two layouts: POV-Ray 3.7 holds an ior in single precision (Interior::IOR is SNGL) and
// between two nested objects refracts with the quotient of their iors computed in single
// precision, a relative error of up to 6e-8 per boundary.  Against the index steps of the
// paper's profile that is nothing; against real air (index differences of 1e-5 in all)
// it bends grazing rays by pixels.  In the gap layout a ray leaves each layer into POV-Ray's
// atmosphere (the camera's index, held in double precision) before entering the next, so
// each refraction is float over double and nothing accumulates; it costs twice the levels.

struct LayerEmitSettings {
    double camera_y = 0.0;  // height of the camera (or of the reference layer), scene units
    HorizontalBox extent;   // horizontal extent of the layers, scene units
    // Of the layers below the camera's, when they reach farther (the curved Earth: rays turn
    // in them beyond the scene, while the layers above end near it).
    std::optional<HorizontalBox> extent_below = std::nullopt;
    LayerLayout layout = LayerLayout::Nested;
    double gap = 0.0;                 // thickness of the gaps (Gaps layout), scene units
    double ground_height = 0.0;       // Mirage_Ground_Height: every layer is raised by it (the
                                      // heights above are above the ground, scene/ground.h)
    std::vector<std::string> header;  // comment lines at the top of the include
    std::string checks;               // SDL that stops a render they were not compiled for
    // The lowest point a camera ray starts at (a camera with many origins may start some
    // below the ground): the bottom layer reaches below it, so that POV-Ray finds those
    // origins inside it.
    double lowest_y = 0.0;
    // The rays start at different points (camera_y is then the height of the layer of the
    // largest index, which POV-Ray's atmosphere stands for): only the include's comment says so.
    bool many_origins = false;
};

/// The text of mirage_layers.inc.
std::string layers_include(const LayerStack& stack, const LayerEmitSettings& settings);

/// The layer table: per layer its bottom and top (scene units), absolute index, eta^2 - eta0^2
/// and the ior as written to POV-Ray (relative to the camera's layer).
std::string layers_csv(const LayerStack& stack, double camera_y);

struct IniSettings {
    std::string scene;         // the template, absolute
    std::string output_image;  // absolute
    int width = 320, height = 240;
    std::vector<std::string> library_paths;  // absolute, searched in order
    bool antialias = false;
    double antialias_threshold = 0.3;
    std::optional<double> clock;             // Clock= (POV-Ray's +K): the still's clock
    std::map<std::string, double> declares;  // Declare=NAME=VALUE, before Mirage_Compiled
};

/// The text of the .ini that renders the scene with its compiled layers.
std::string render_ini(const IniSettings& settings);

}  // namespace mirage
