#include "compile/compile.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>

#include "compile/pixel_check.h"
#include "compile/stages.h"
#include "image/image_io.h"
#include "pov/emit_camera.h"
#include "pov/emit_layers.h"
#include "pov/emit_stamp.h"
#include "util/format.h"
#include "util/new_directories.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/stats.h"
#include "util/text_escape.h"

namespace fs = std::filesystem;

namespace mirage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Times the pipeline's stages into the report.
class StageClock {
  public:
    explicit StageClock(CompileReport& rep) : rep_(rep), last_(std::chrono::steady_clock::now()) {}
    void done(const std::string& stage) {
        const auto now = std::chrono::steady_clock::now();
        rep_.stage_seconds.emplace_back(stage, std::chrono::duration<double>(now - last_).count());
        last_ = now;
    }

  private:
    CompileReport& rep_;
    std::chrono::steady_clock::time_point last_;
};

/// The pixels' errors as an image: seen error (px), shift (rows), reflections' error (px).
Image error_map_image(const CompileReport& r) {
    Image im(r.width, r.height);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const size_t i = static_cast<size_t>(y) * r.width + x;
            im.set(x, y,
                   glm::vec3(r.pixel_error_px[i], r.pixel_shift_rows[i],
                             r.pixel_reflection_error_px[i]));
        }
    return im;
}

/// The design's errors at the scene's edge, over the pixel centres: percentiles and the rows
/// over the tolerance.
void summarize_design_errors(const std::vector<double>& err, const CameraRays& centres,
                             double tolerance_px, CompileReport& rep) {
    rep.pixels = static_cast<int>(err.size());
    rep.p50_error_px = percentile(err, 0.50);
    rep.p95_error_px = percentile(err, 0.95);
    rep.p99_error_px = percentile(err, 0.99);
    rep.max_error_px = err.empty() ? 0.0 : *std::max_element(err.begin(), err.end());
    const int W = centres.width, H = centres.height;
    for (int row = 0; row < H; ++row) {
        RowExcess ex;
        ex.row = row;
        for (int col = 0; col < W; ++col) {
            const double e = err[static_cast<size_t>(row) * W + col];
            ex.max_error_px = std::max(ex.max_error_px, e);
            if (e > tolerance_px) ++ex.pixels_over;
        }
        rep.pixels_over += ex.pixels_over;
        if (ex.pixels_over > 0) rep.rows_over.push_back(ex);
    }
    rep.within_tolerance = rep.pixels_over == 0;
}

/// What the check found, over the pixel centres (the per-pixel maps) and over every sample.
void summarize_check(const PixelCheck& pc, const CameraRays& rays, double tolerance_px,
                     CompileReport& rep) {
    const int W = rays.width, H = rays.height, k = rays.per_side, GW = rays.grid_width();
    const size_t n = static_cast<size_t>(W) * H;
    rep.samples_per_side = k;
    rep.pixel_error_px.assign(n, 0.0f);
    rep.pixel_shift_rows.assign(n, 0.0f);
    rep.pixel_reflection_error_px.assign(n, 0.0f);
    std::vector<double> seen, shift, seen_all, shift_all, camera, camera_all;
    std::vector<LineError> rows(H), cols(W);
    for (int r = 0; r < H; ++r) rows[r].index = r;
    for (int c = 0; c < W; ++c) cols[c].index = c;
    for (size_t g = 0; g < rays.size(); ++g) {
        const int gx = static_cast<int>(g % GW), gy = static_cast<int>(g / GW);
        const int col = gx / k, row = gy / k;
        const float e = pc.seen_error_px[g];
        // Shifts are in rows of the sample grid: per_side of them to a pixel row.
        const float s = pc.shift_rows[g] / static_cast<float>(k);
        seen_all.push_back(e);
        if (!pc.camera_error_px.empty()) camera_all.push_back(pc.camera_error_px[g]);
        if (std::isfinite(s))
            shift_all.push_back(s);
        else
            ++rep.samples_not_shown;
        for (LineError* l : {&rows[row], &cols[col]}) {
            l->max_seen_error_px = std::max(l->max_seen_error_px, static_cast<double>(e));
            if (e > tolerance_px) ++l->samples_over;
        }
        if (g != rays.centre(col, row)) continue;
        const size_t i = static_cast<size_t>(row) * W + col;
        rep.pixel_error_px[i] = e;
        rep.pixel_shift_rows[i] = s;
        rep.pixel_reflection_error_px[i] = pc.reflection_error_px[g];
        seen.push_back(e);
        if (!pc.camera_error_px.empty()) camera.push_back(pc.camera_error_px[g]);
        if (std::isfinite(s))
            shift.push_back(s);
        else
            ++rep.pixels_not_shown;
    }
    rep.p95_seen_error_px = percentile(seen, 0.95);
    rep.max_seen_error_px = seen.empty() ? 0.0 : *std::max_element(seen.begin(), seen.end());
    rep.p95_shift_rows = percentile(shift, 0.95);
    rep.max_shift_rows = shift.empty() ? 0.0 : *std::max_element(shift.begin(), shift.end());
    rep.p95_seen_error_px_samples = percentile(seen_all, 0.95);
    rep.max_seen_error_px_samples =
        seen_all.empty() ? 0.0 : *std::max_element(seen_all.begin(), seen_all.end());
    rep.p95_shift_rows_samples = percentile(shift_all, 0.95);
    rep.max_shift_rows_samples =
        shift_all.empty() ? 0.0 : *std::max_element(shift_all.begin(), shift_all.end());
    if (!camera.empty()) {
        rep.p95_camera_error_px = percentile(camera, 0.95);
        rep.max_camera_error_px = *std::max_element(camera.begin(), camera.end());
        rep.p95_camera_error_px_samples = percentile(camera_all, 0.95);
        rep.max_camera_error_px_samples = *std::max_element(camera_all.begin(), camera_all.end());
    }
    auto worst = [](std::vector<LineError> v) {
        std::stable_sort(v.begin(), v.end(), [](const LineError& a, const LineError& b) {
            return a.max_seen_error_px > b.max_seen_error_px;
        });
        v.resize(std::min<size_t>(5, v.size()));
        return v;
    };
    rep.worst_rows = worst(rows);
    rep.worst_columns = worst(cols);
}

/// The corrected camera's outputs: the mesh camera's include and the scene that renders the
/// template through it.
struct CameraTexts {
    std::string mesh, scene;
};

/// The mesh camera for the check's chosen directions, and the scene and .ini that render
/// through it (files.ini is replaced); names the outputs in the report.
Result<CameraTexts> emit_corrected_camera(const CompileContext& ctx, const CameraRays& rays,
                                          const PixelCheck& pc, const fs::path& dir,
                                          CompileReport& rep, EmittedFiles& files) {
    const CompileOptions& opt = ctx.options;
    const int W = rays.width, H = rays.height, k = rays.per_side, GW = rays.grid_width();
    const auto samples = shot_samples(k, opt.antialias);
    // (compile_settings refused meshes past kMaxMeshCameraFaces.)
    MeshCameraSettings ms;
    ms.width = W;
    ms.height = H;
    ms.eye = ctx.camera.location + glm::dvec3(0.0, ctx.settings.ground_height, 0.0);
    // The rays POV-Ray shoots, with their trace levels as the check followed them.
    rep.max_trace_level = 0;
    for (const auto& [sx, sy] : samples) {
        std::vector<glm::dvec3> dirs(static_cast<size_t>(W) * H);
        for (int row = 0; row < H; ++row)
            for (int col = 0; col < W; ++col) {
                const size_t g = static_cast<size_t>(row * k + sy) * GW + (col * k + sx);
                dirs[static_cast<size_t>(row) * W + col] = pc.band_direction[g];
                rep.max_trace_level = std::max(rep.max_trace_level, pc.trace_level[g]);
            }
        ms.samples.push_back(std::move(dirs));
    }
    ms.header = {"mirage_camera.inc: the corrected camera of " + rep.name + " at " +
                     std::to_string(W) + "x" + std::to_string(H) + ", written by mirage compile.",
                 "Every pixel's ray aimed through the layers of mirage_layers.inc to where its "
                 "exact ray ends.",
                 "Do not edit: run mirage compile again."};
    rep.camera_samples = static_cast<int>(samples.size());
    if (rep.max_trace_level > kMaxTraceLevel)
        rep.warnings.push_back("some of the aimed rays reach POV-Ray's trace-level ceiling (" +
                               std::to_string(rep.max_trace_level) +
                               " levels with their reflections): they will render black; ask "
                               "for fewer layers (--count)");
    rep.camera_path = (dir / "mirage_camera.inc").string();
    rep.render_scene_path = (dir / (rep.name + "_render.pov")).string();
    const std::string scene_abs = fs::absolute(opt.scene).string();
    RenderSceneSettings rs;
    rs.scene = scene_abs;
    rs.camera_include = rep.camera_path;
    rs.width = W;
    rs.height = H;
    rs.settings_check = settings_check(stamped_settings(ctx.scene, atmosphere_setting_names()));
    rs.header = {rep.name + "_render.pov: renders " + scene_abs +
                     " through its corrected camera, written by mirage compile.",
                 "POV-Ray 3.7 gives image rows 0 and 1 the same faces of a mesh camera: this "
                 "renders one row more,",
                 "and the top row is dropped after (mirage compile --render does it)."};
    IniSettings ini;
    ini.scene = rep.render_scene_path;
    ini.output_image = rep.image_path;
    ini.width = W;
    ini.height = H + 1;
    ini.library_paths.push_back(dir.string());
    for (const auto& p : ctx.library_paths) ini.library_paths.push_back(p);
    ini.library_paths.push_back(fs::path(scene_abs).parent_path().string());
    ini.antialias = false;  // POV-Ray averages the meshes' samples itself
    ini.clock = opt.clock;
    ini.declares = opt.declares;
    files.ini = render_ini(ini);
    CameraTexts t;
    t.mesh = mesh_camera_include(ms);
    t.scene = render_scene(rs);
    return t;
}

// The report's lines that come from the settings alone.
void start_report(const CompileContext& ctx, CompileReport& rep) {
    const CompileOptions& opt = ctx.options;
    const MirageSettings& st = ctx.settings;
    rep.scene = opt.scene;
    rep.name = ctx.name;
    rep.width = opt.width;
    rep.height = opt.height;
    rep.tolerance_px = st.tolerance_px;
    rep.atmosphere = st.declared ? st.profile_label : "none declared";
    rep.layout = ctx.gaps ? "gaps" : "nested";
    rep.gap = ctx.gaps ? ctx.gap : 0.0;
    rep.extent = ctx.extent;
    rep.left_out = ctx.left_out;
    rep.warnings = ctx.warnings;
}

// What the design says of itself, and a warning when the turbulent air cannot shimmer through
// POV-Ray (only the corrected camera's rays are aimed where it sends the exact ones).
void record_design(const CompileContext& ctx, const Design& design, bool corrected,
                   CompileReport& rep) {
    rep.mode = design.mode;
    rep.layers = design.stack.boundaries();
    rep.max_error_px_fitted = design.max_error_px_fitted;
    rep.max_trace_level = design.max_trace_level;
    for (const auto& l : design.left_out) rep.left_out.push_back(l);
    for (const auto& w : design.warnings) rep.warnings.push_back(w);
    if (ctx.turbulence && !corrected)
        rep.warnings.push_back(
            "the turbulent air (Mirage_Turbulence_Cn2) shimmers in POV-Ray's render only through "
            "the corrected camera, which " +
            std::string(ctx.options.camera != CameraModel::Corrected
                            ? "--camera perspective leaves out"
                        : ctx.many_origins ? "a camera with many origins cannot have"
                                           : "needs layers to aim through (this scene has none)") +
            ": this render is still; mirage trace's shimmers");
}

// Where the layers lie around the camera, and what the fitted designs leave out below and
// above them (the corrected camera's layers say that themselves).
void record_layer_span(const CompileContext& ctx, const Design& design, CompileReport& rep) {
    const LayerStack& stack = design.stack;
    const int k_cam = stack.layer_at(ctx.eye_y);
    rep.below_camera = k_cam;
    rep.above_camera = stack.boundaries() - k_cam;
    if (rep.layers == 0) return;
    rep.lowest = stack.heights.front();
    rep.highest = stack.heights.back();
    const bool fitted = design.mode == "adaptive" || design.mode == "uniform";
    const Profile* closed = ctx.atmosphere.exponential_profile();
    if (closed && closed->kind == ProfileKind::Inferior && fitted)
        rep.left_out.push_back("layers below y = " + sig(rep.lowest, 4) +
                               ": no camera ray turns lower");
    if (closed && fitted)
        rep.left_out.push_back("layers above y = " + sig(rep.highest, 4) +
                               ": the index is within 1% of eta(infinity), or no camera ray "
                               "reaches higher");
}

// The pixel check of every ray against its exact ray: the layers as far as they reach, the
// exact paths a twentieth of a pixel from the truth (errors read to that), real air's model
// and the turbulent air as the tracer has them.
PixelCheckSettings pixel_check_settings(const CompileContext& ctx, const CameraRays& rays,
                                        const LayerStack& rendered, double reach,
                                        const std::optional<double>& reach_below) {
    double finest = kInf;
    for (double p : rays.pixel_rad) finest = std::min(finest, p);
    const glm::dvec3 eye = ctx.camera.location;
    PixelCheckSettings ps;
    ps.width = rays.grid_width();
    ps.height = rays.grid_height();
    ps.eye = eye;
    ps.camera_y = ctx.reference_y(rendered);
    if (ctx.many_origins) {
        ps.origins = &rays.origin;
        ps.footprint = ctx.footprint;
        ps.far = ctx.extent;
    }
    ps.layers = {eye.x - reach, eye.x + reach, eye.z - reach, eye.z + reach};
    if (reach_below) {
        const double r = *reach_below;
        ps.layers_below = HorizontalBox{eye.x - r, eye.x + r, eye.z - r, eye.z + r};
    }
    ps.exact_tolerance_rad = 0.05 * finest;
    ps.atmosphere = ctx.atmosphere;
    ps.max_dz = ctx.max_dz;
    ps.turbulence = ctx.turbulence;
    ps.turbulence_time_s = ctx.turbulence_time_s;
    ps.unit_m = ctx.settings.unit_m;
    return ps;
}

// Where every output goes (in the output folder, the image where the options say), the image
// checked: not an input, and a file when the corrected camera's render is to be cropped.
Status name_outputs(const CompileContext& ctx, bool corrected, const OutputSet& outputs,
                    CompileReport& rep) {
    const fs::path dir = ctx.out_dir;
    rep.include_path = (dir / "mirage_layers.inc").string();
    rep.csv_path = (dir / "layers.csv").string();
    rep.ini_path = (dir / (rep.name + ".ini")).string();
    rep.report_path = (dir / "report.json").string();
    rep.image_path = ctx.image;
    rep.error_map_path = ctx.options.error_map;
    if (auto s = outputs.check(rep.image_path); !s) return s.error();  // POV-Ray renders it
    // The corrected camera's render is read back to drop its extra row: a file, not a stream.
    if (auto out = resolve_output_path(rep.image_path); corrected && out && out->stream)
        return make_error(rep.image_path +
                          ": POV-Ray's render through the corrected camera is read back and "
                          "cropped after it is written, so the image must be a file, not a "
                          "device or a pipe (render to a file and copy it, or use --camera "
                          "perspective)");
    return Ok{};
}

// Every file the compile writes, staged and then committed: all of them, or none.
Status write_outputs(const CompileReport& rep, const EmittedFiles& files, CameraTexts camera_text,
                     OutputSet& outputs) {
    std::vector<std::pair<std::string, std::string>> texts = {{rep.include_path, files.include},
                                                              {rep.csv_path, files.csv},
                                                              {rep.ini_path, files.ini},
                                                              {rep.report_path, report_json(rep)}};
    if (!camera_text.mesh.empty()) {
        texts.emplace_back(rep.camera_path, std::move(camera_text.mesh));
        texts.emplace_back(rep.render_scene_path, std::move(camera_text.scene));
    }
    for (const auto& [path, text] : texts)
        if (auto s = outputs.write_text(path, text); !s) return s.error();
    if (!rep.error_map_path.empty())
        if (auto s = write_exr(error_map_image(rep), rep.error_map_path, &outputs); !s)
            return s.error();
    return outputs.commit();
}

// How far the layers reach, and that they end there.
void record_layers_reach(double reach, const std::optional<double>& reach_below,
                         CompileReport& rep) {
    rep.layers_extent = reach;
    if (rep.layers > 0)
        rep.left_out.push_back(
            "the layers beyond " + sig(reach, 4) + " units from the camera" +
            (reach_below ? " (those below the camera's beyond " + sig(*reach_below, 4) + ")"
                         : std::string()) +
            ": every camera ray has left them by then");
}

}  // namespace

Result<CompileReport> compile_scene(const CompileOptions& opt) {
    const auto t0 = std::chrono::steady_clock::now();
    CompileReport rep;
    StageClock clock(rep);

    auto ctx_r = compile_settings(opt);
    if (!ctx_r) return ctx_r.error();
    const CompileContext& ctx = *ctx_r;
    // Every output is written at the end, all or none, and none over a file the scene was
    // read from (those the options name were refused by compile_settings already).
    // The output folder is made when the outputs are written, and taken away again (if empty)
    // when the run fails; declared first, so that the staged files go before it.
    NewDirectories folders;
    OutputSet outputs(ctx.scene.files);
    const MirageSettings& st = ctx.settings;
    start_report(ctx, rep);
    clock.done("settings");

    const CameraRays rays = camera_rays(ctx, opt.samples_per_side);
    const CameraRays centres = rays.centres();
    clock.done("rays");

    auto design_r = design_layers(ctx, centres);
    if (!design_r) return design_r.error();
    const Design& design = *design_r;
    const LayerStack& stack = design.stack;
    const LayerStack rendered = ctx.rendered(stack);
    // The corrected camera: POV-Ray's rays aimed through the layers (stage "camera"), for a
    // camera with one eye and layers to aim through.
    const bool corrected =
        opt.camera == CameraModel::Corrected && !ctx.many_origins && stack.boundaries() > 0;
    record_design(ctx, design, corrected, rep);
    // (With many origins the design's errors are the check's at the pixel centres, below:
    // the errors at the scene's edge are angles seen from one eye.  With the corrected camera
    // they are the check's too: the camera's own rays are not what POV-Ray shoots.)
    if (!ctx.many_origins && !corrected) {
        const std::vector<double> err =
            stack.boundaries() > 0 ? design_errors(ctx, rendered, centres, &rep.max_crossings)
                                   : std::vector<double>(centres.size(), 0.0);
        summarize_design_errors(err, centres, st.tolerance_px, rep);
    }
    clock.done("design");

    // The layers reach as far as the camera's rays still meet a boundary before they leave
    // through the top or reach the ground, and at least past the scene: no farther.  The
    // corrected camera's rays are aimed first, through layers as far as they may reach, and
    // the layers then end where the aimed rays leave them.
    const glm::dvec3 eye = ctx.camera.location;
    double reach = 0.0;
    std::optional<double> reach_below;
    if (corrected) {
        reach = ctx.layers_box.x1 - eye.x;
        if (ctx.layers_below_box) reach_below = ctx.layers_below_box->x1 - eye.x;
    } else {
        reach = ctx.many_origins ? many_origins_reach(ctx, rendered, centres, &rep.max_crossings)
                                 : layers_reach(ctx, rendered, centres);
        reach_below =
            ctx.many_origins ? std::nullopt : layers_reach_below(ctx, rendered, centres, reach);
    }
    clock.done("reach");
    record_layer_span(ctx, design, rep);
    if (ctx.many_origins && !(rep.layers > 0)) {
        // No layers: nothing bends, and no pixel errs.
        summarize_design_errors(std::vector<double>(centres.size(), 0.0), centres, st.tolerance_px,
                                rep);
    }
    // (compile_settings checked these paths for POV-Ray.)
    const fs::path abs_dir = ctx.out_dir;
    if (auto s = folders.make(ctx.out_dir); !s) return s.error();
    if (auto s = name_outputs(ctx, corrected, outputs, rep); !s) return s.error();
    // The include's header, once the pixel centres' errors are known.
    auto header = [&] {
        return std::vector<std::string>{
            "mirage_layers.inc: the banded atmosphere of " + escape_control(rep.name) + " at " +
                std::to_string(opt.width) + "x" + std::to_string(opt.height) +
                ", written by mirage compile.",
            "Atmosphere: " + escape_control(rep.atmosphere) + "; " + rep.mode + " layers.",
            ctx.many_origins
                ? "The camera's rays start at different points: every pixel's error, from its own "
                  "origin, is in report.json (tolerance " +
                      sig(rep.tolerance_px, 3) + " px)."
                : "Error over the " + std::to_string(rep.pixels) + " pixel centres: p50 " +
                      sig(rep.p50_error_px, 3) + " px, p95 " + sig(rep.p95_error_px, 3) +
                      " px, max " + sig(rep.max_error_px, 3) + " px (tolerance " +
                      sig(rep.tolerance_px, 3) + " px).",
            "Do not edit: run mirage compile again."};
    };
    EmittedFiles files;
    if (!corrected) {
        files = emit_files(ctx, stack, reach, reach_below, abs_dir.string(), rep.image_path,
                           header(), false);
        clock.done("emit");
    }
    rep.camera = corrected ? "corrected" : "perspective";

    CameraTexts camera_text;
    // What every pixel and sample shows: its ray through the rendered layers against the
    // exact ray, to the surfaces they meet (the design's errors above are taken at the
    // scene's edge).
    if (stack.boundaries() > 0) {
        std::vector<bool> cut_off(rays.size(), false);
        PixelCheckSettings ps = pixel_check_settings(ctx, rays, rendered, reach, reach_below);
        ps.progress = opt.progress;
        if (corrected) ps.aim = corrected_camera_aim(ctx, rendered, rays);
        const PixelCheck pc =
            check_pixels(rendered, ctx.scene, *ctx.accel, object_query(*ctx.accel),
                         rays.direction, rays.pixel_rad, cut_off, ps);
        summarize_check(pc, rays, st.tolerance_px, rep);
        // The errors at the scene's edge are angles seen from one eye along the camera's own
        // rays: with many origins, or the corrected camera's aimed rays, the pixel centres'
        // errors are the check's.
        if (ctx.many_origins || corrected) {
            std::vector<double> err(rep.pixel_error_px.begin(), rep.pixel_error_px.end());
            summarize_design_errors(err, centres, st.tolerance_px, rep);
        }
        if (corrected) {
            rep.within_tolerance =
                rep.within_tolerance && rep.max_seen_error_px_samples <= st.tolerance_px;
            // The layers end where the aimed rays leave them.
            rep.max_crossings = *std::max_element(pc.crossings.begin(), pc.crossings.end());
            const double last = *std::max_element(pc.last_event.begin(), pc.last_event.end());
            reach = std::min(reach, std::max(1.1 * ctx.extent, 1.1 * last));
            if (reach_below)
                reach_below = 1.1 * last > reach
                                  ? std::optional<double>(std::min(*reach_below, 1.1 * last))
                                  : std::nullopt;
            files = emit_files(ctx, stack, reach, reach_below, abs_dir.string(), rep.image_path,
                               header(), true);
            clock.done("check");
            auto cam = emit_corrected_camera(ctx, rays, pc, abs_dir, rep, files);
            if (!cam) return cam.error();
            camera_text = std::move(*cam);
        }
    } else {
        // No layers: no pixel errs.
        const size_t n = static_cast<size_t>(opt.width) * opt.height;
        rep.pixel_error_px.assign(n, 0.0f);
        rep.pixel_shift_rows.assign(n, 0.0f);
        rep.pixel_reflection_error_px.assign(n, 0.0f);
        rep.samples_per_side = rays.per_side;
    }
    clock.done(corrected ? "camera" : "check");
    record_layers_reach(reach, reach_below, rep);

    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (auto s = write_outputs(rep, files, std::move(camera_text), outputs); !s) return s.error();
    folders.keep();
    clock.done("report");
    return rep;
}

}  // namespace mirage
