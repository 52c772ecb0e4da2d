// The stages of `mirage compile`, in the order the pipeline runs them (compile.cpp):
//
//   settings  the scene, its atmosphere in scene units, the camera, the scene's extent and
//             the layout POV-Ray needs (compile_settings)
//   rays      every pixel centre's ray and a grid of sub-pixel samples (camera_rays)
//   design    the layers: none, Berger's equal layers or the fit to the camera's rays, refitted
//             until every camera ray with its reflections keeps POV-Ray's trace-level budget
//             (design_layers, which measures the budget with deepest_trace_level)
//   emit      the layers include, the .ini and the layer table (emit_files)
//   check     what every pixel centre and sample shows (compile/pixel_check.h)
//   report    the report (compile.h) and every output written, all or none
//
// Each stage reads what the ones before it made and nothing else.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "atmosphere/phase_screens.h"
#include "compile/compile.h"
#include "compile/pixel_check.h"
#include "layers/band_tracer3d.h"
#include "layers/stack.h"
#include "load/atmosphere_settings.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "trace/scene_accel.h"
#include "util/result.h"

namespace mirage {

/// POV-Ray counts a camera ray and every ray it spawns (refraction, reflection) as one more
/// trace level; max_trace_level 256 is its ceiling and a ray that reaches it returns black.
/// Staying at 255 or below keeps the statistics' "Max Level" under 256.
inline constexpr int kMaxTraceLevel = 255;

/// How far the layers may reach beyond the scene, in scene extents: far enough that the
/// camera's rays leave them through the top (towards the sky, with eta(infinity)) or reach
/// the ground.
inline constexpr double kLayersExtentFactor = 1000.0;

/// On the curved Earth a band ray's final direction is the flattened frame's, which is
/// turned by dz / R from the eye's where the ray stops bending (at most where the layers
/// end): the layers at and above the camera's may reach no farther than this many radians of
/// the Earth, 1 mrad (6.4 km on the Earth), so that the sky POV-Ray looks up is at most that far
/// off.  (Those below reach as far as a camera ray turns in them: layers_reach_below.)
inline constexpr double kMaxCurvedSkyRad = 1e-3;

/// What every stage reads: the scene and its atmosphere as the compiler sees them.
struct CompileContext {
    CompileOptions options;
    Scene scene;
    MirageSettings settings;
    // The atmosphere in scene units, which the layers band and the pixel check's exact rays
    // follow: an exponential profile, or real air (a sounding, the temperature forms, the
    // curved Earth) as the general engine's model (the flattened profile n* on the curved
    // Earth).
    Atmosphere atmosphere;
    double max_dz = 0.0;  // how far the tracer follows the general engine's paths (CurvedSettings)
    // Turbulent air (Mirage_Turbulence_Cn2): its screens and the time they stand at, which the
    // pixel check's exact rays are walked through (CurvedSettings::turbulence).
    std::shared_ptr<const PhaseScreens> turbulence;
    double turbulence_time_s = 0.0;
    std::string name;
    Camera camera;
    double eye_y = 0.0;
    double extent = 0.0;         // horizontal reach of the scene from the camera
    HorizontalBox scene_box{};   // the scene, around the camera
    HorizontalBox layers_box{};  // how far the layers may reach
    // How far the layers below the camera's may reach when farther than layers_box (the
    // curved Earth: compile_settings), else nothing.
    std::optional<HorizontalBox> layers_below_box = std::nullopt;
    bool gaps = false;                        // the gap layout (see pov/emit_layers.h)
    double gap = 0.0;                         // its gap thickness
    double steepest_sine = 0.0;               // |sin(elevation)| of the steepest camera ray
    std::shared_ptr<const SceneAccel> accel;  // the scene's objects for the rays
    std::vector<std::string> library_paths;   // as the .ini will list them (absolute)
    std::string out_dir;  // where the outputs go (absolute): -o, else build/render/<name>
    std::string image;    // the image the .ini renders (absolute): --image, else in out_dir
    std::vector<std::string> left_out, warnings;
    // A camera whose rays start at different points (orthographic, cylinder 3 and 4): every
    // ray from its own origin, the layers at equal steps of the index over the heights the
    // rays reach (design_many_origins), always in the gap layout, and errors in the camera's
    // own unit of a pixel.
    bool many_origins = false;
    PixelFootprint footprint;  // one pixel along a camera ray (scene/camera.h)

    /// The stack as POV-Ray renders it: with the gaps of the gap layout.
    LayerStack rendered(const LayerStack& stack) const;
    /// The height whose layer POV-Ray's atmosphere (index 1) stands for: the camera's; with
    /// many origins a height inside the layer of the largest index (the last such layer POV-
    /// Ray does not already see as its atmosphere), so that a ray from any origin never
    /// meets a total reflection in a gap that its own layer would not give it.
    double reference_y(const LayerStack& stack) const;
};

/// Stage "settings": parses the scene (leniently: the compiler needs the camera, the
/// atmosphere and the objects' extent), reads its Mirage_ settings with the options'
/// overrides, checks the camera and takes the scene's extent.
Result<CompileContext> compile_settings(const CompileOptions& options);

/// The camera's rays on a grid of per_side x per_side samples in every pixel, at the offsets
/// (i + 1/2) / per_side, row-major from the top of the image: grid row 3 r + 1 (for per_side
/// 3) is the row of pixel row r's centres.
struct CameraRays {
    int width = 0, height = 0;       // of the image, pixels
    int per_side = 1;                // samples per pixel and side
    std::vector<glm::dvec3> origin;  // where each ray starts (the camera's location for a
                                     // camera with one eye point; empty: every ray from it)
    std::vector<glm::dvec3> direction;
    std::vector<double> elevation;  // rad, > 0 up
    std::vector<double> exit_dz;    // horizontal distance from its origin at which it leaves
                                    // the scene's box
    std::vector<double> pixel_rad;  // angle of one pixel row at this sample, rad

    int grid_width() const { return width * per_side; }
    int grid_height() const { return height * per_side; }
    size_t size() const { return direction.size(); }
    /// Room for n rays in each of the per-ray arrays.
    void resize(size_t n);
    /// The grid index of the sample at the centre of pixel (col, row) (per_side odd), or of
    /// the sample nearest to it.
    size_t centre(int col, int row) const;
    /// The pixel centres alone, as rays of their own (per_side 1).
    CameraRays centres() const;
};

/// Stage "rays".
CameraRays camera_rays(const CompileContext& ctx, int per_side);

/// A layer design and what it left out.
struct Design {
    LayerStack stack;                  // as designed; POV-Ray gets ctx.rendered(stack)
    std::string mode;                  // "adaptive", "uniform" or "none"
    double max_error_px_fitted = 0.0;  // over the rays the fit was fitted to
    int max_trace_level = 0;           // of the camera rays with their reflections
    std::vector<std::string> left_out, warnings;
};

/// The largest trace level POV-Ray reaches for any of `rays` through `rendered` (one level per
/// boundary event in the layers and per reflection off an object, following every reflection
/// whose weight stays above POV-Ray's adc_bailout); followed past the ceiling, to 4 times it,
/// so that a design over it knows by how much.
int deepest_trace_level(const CompileContext& ctx, const LayerStack& rendered,
                        const CameraRays& rays);

/// A design of `count` steps whose rays reached d.max_trace_level past POV-Ray's ceiling: the
/// count to design again with (scaled to fit, at least 2, fewer than `count`), with the warning
/// that says so (`steps` names them: "index steps", "steps").
int fewer_steps_for_trace_level(Design& d, int count, const std::string& steps);

/// The warning, when some camera rays of d reach POV-Ray's trace-level ceiling.
void warn_past_trace_level_ceiling(Design& d);

/// Every ray's error (pixels) of the design at the scene's edge against the exact path
/// (layers/outcome.h), +inf for a ray the band tracer cut off, and the most boundary events
/// of a ray.
std::vector<double> design_errors(const CompileContext& ctx, const LayerStack& rendered,
                                  const CameraRays& rays, int* max_crossings = nullptr);

/// The corrected camera's layers when no count is asked for (Mirage_Layer_Count, --count).
inline constexpr int kCorrectedCameraLayers = 24;

/// The layers the corrected camera sees through (exponential profiles): `count` boundaries
/// at equal steps of eta^2, most on the side of the eye where the rays turn, none above
/// `top`; the ground's layer holds eta0, the eye's eta(eye), the half-space over the top
/// eta(infinity), the others the value midway between their boundaries.
LayerStack corrected_camera_layers(const Profile& profile, double eye_y, int count, double top);

/// Stage "design": the layers for the rays (the pixel centres).
Result<Design> design_layers(const CompileContext& ctx, const CameraRays& centres);

/// The design for a camera with many origins (stage_design_origins.cpp): no fit to one eye's
/// rays; boundaries at equal steps of the index (or, Mirage_Layers "uniform", at equal
/// heights) between the lowest and the highest point the rays' exact paths reach inside the
/// scene (the top no higher than where the index is within 1 % of its value aloft), fewer
/// until every camera ray with its reflections keeps POV-Ray's trace-level budget.
Result<Design> design_many_origins(const CompileContext& ctx, const CameraRays& centres);

/// With many origins: how far from the camera the rendered layers must reach (as
/// layers_reach): past the scene and past every ray's last boundary event; and the most
/// boundary events of a ray.
double many_origins_reach(const CompileContext& ctx, const LayerStack& rendered,
                          const CameraRays& rays, int* max_crossings = nullptr);

/// Where a ray from `origin` along unit `dir` enters the atmosphere: the origin itself, or
/// for an origin below the ground rising, the point where it reaches the ground (below it the
/// index is the ground's, the bottom layer's: the ray is straight there).  Nothing for an
/// origin below the ground that never rises to it.
std::optional<glm::dvec3> entry_into_atmosphere(const glm::dvec3& origin, const glm::dvec3& dir);

/// How far the rendered layers must reach: as far as the camera's rays still meet a boundary
/// before they leave through the top or reach the ground, at least a tenth past the scene,
/// at most ctx.layers_box.
double layers_reach(const CompileContext& ctx, const LayerStack& rendered, const CameraRays& rays);

/// How far the rendered layers below the camera's must reach, when ctx.layers_below_box lets
/// them reach farther than `reach` (that of the others): as far as a camera ray still meets
/// one of them (the band tracer's last boundary event, + 10 %), at least `reach`, at most
/// ctx.layers_below_box.  Nothing otherwise.
std::optional<double> layers_reach_below(const CompileContext& ctx, const LayerStack& rendered,
                                         const CameraRays& rays, double reach);

/// Stage "camera": the corrected camera's aim for the check (compile/pixel_check.h): for ray
/// i of `rays`, the direction as the camera has it and the direction whose path through the
/// rendered layers passes through the point where the exact ray ends (for a ray that leaves
/// the scene for the sky, its exact height at the scene's edge), each carried to the float
/// precision of POV-Ray's mesh camera.  ctx and rays must outlive it.
BandAim corrected_camera_aim(const CompileContext& ctx, const LayerStack& rendered,
                             const CameraRays& rays);

/// The samples of a pixel POV-Ray shoots through the corrected camera, as grid offsets within
/// the pixel's per_side x per_side samples: the centre, and antialiased the four corner
/// samples too (POV-Ray averages one mesh per sample).
std::vector<std::pair<int, int>> shot_samples(int per_side, bool antialias);

/// The texts of the outputs, by file name.
struct EmittedFiles {
    std::string include, csv, ini;
};

/// Stage "emit": the layers clipped to `reach` around the camera, the .ini that renders
/// the template with them into `image` (finding the include in `out_dir`), the layer table.
/// `header` lines open the include.  The include stops a render it was not compiled for: at
/// another size, or for `corrected` layers (aimed through by the corrected camera, whose
/// render scene checks the size) through the template's own camera.
EmittedFiles emit_files(const CompileContext& ctx, const LayerStack& stack, double reach,
                        std::optional<double> reach_below, const std::string& out_dir,
                        const std::string& image, const std::vector<std::string>& header,
                        bool corrected);

/// The rays POV-Ray's band render follows: stops band rays at the scene's surfaces.
ObjectQuery object_query(const SceneAccel& accel);

}  // namespace mirage
