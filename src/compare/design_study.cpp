#include "compare/design_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <tuple>

#include "atmosphere/exact_ray.h"
#include "compare/compare.h"
#include "compare/povray_render.h"
#include "compile/compile.h"
#include "compile/stages.h"
#include "layers/graded.h"
#include "layers/revolution.h"
#include "load/atmosphere_settings.h"
#include "pov/povray_path.h"
#include "util/atomic_file.h"
#include "util/check.h"
#include "util/format.h"
#include "util/new_directories.h"
#include "util/output_set.h"
#include "util/parallel.h"
#include "util/process.h"
#include "util/stats.h"

namespace fs = std::filesystem;

namespace mirage {

namespace {

// The study's designs are fitted with the exponential profiles' closed forms: run_design_study
// refuses any other atmosphere.
const Profile& closed_profile(const CompileContext& ctx) {
    const Profile* p = ctx.atmosphere.exponential_profile();
    MIRAGE_CHECK(p != nullptr);
    return *p;
}


constexpr double kInf = std::numeric_limits<double>::infinity();

// The continuum of the camera's rays: elevations through the interval every sample of the
// image covers, with the angle of a pixel row there, and each one's exact ray.
struct Continuum {
    std::vector<double> elevation, pixel_rad;
    std::vector<ExactRay> exact;
};

Continuum make_continuum(const CompileContext& ctx, int rays_per_row) {
    const CameraRays samples = camera_rays(ctx, 3);
    const double lo = *std::min_element(samples.elevation.begin(), samples.elevation.end());
    const double hi = *std::max_element(samples.elevation.begin(), samples.elevation.end());
    // Pixel size against elevation, from the centre column's centres.
    const CameraRays c = samples.centres();
    std::vector<std::pair<double, double>> px;
    const int col = c.width / 2;
    for (int row = 0; row < c.height; ++row) {
        const size_t i = static_cast<size_t>(row) * c.width + col;
        px.emplace_back(c.elevation[i], c.pixel_rad[i]);
    }
    std::sort(px.begin(), px.end());
    auto pixel_at = [&](double e) {
        auto it = std::lower_bound(px.begin(), px.end(), std::make_pair(e, -kInf));
        if (it == px.begin()) return px.front().second;
        if (it == px.end()) return px.back().second;
        const auto& a = *(it - 1);
        const auto& b = *it;
        return b.first > a.first
                   ? a.second + (e - a.first) / (b.first - a.first) * (b.second - a.second)
                   : a.second;
    };
    Continuum k;
    const int n = std::max(16, rays_per_row * c.height);
    const double t_lo = std::tan(lo), t_hi = std::tan(hi);
    for (int i = 0; i < n; ++i) {
        const double e = std::atan(t_lo + (t_hi - t_lo) * (i + 0.5) / n);
        auto ray = make_exact_ray(closed_profile(ctx), ctx.eye_y, M_PI / 2 - e);
        if (!ray) continue;
        k.elevation.push_back(e);
        k.pixel_rad.push_back(pixel_at(e));
        k.exact.push_back(*ray);
    }
    return k;
}

// The nearest horizontal distance from the eye of any finite object, and the scene's edge.
std::pair<double, double> object_zone(const CompileContext& ctx) {
    const glm::dvec3& eye = ctx.camera.location;
    double lo = ctx.extent;
    for (int i = 0; i < ctx.accel->primitive_count(); ++i) {
        const Aabb b = shape_bounds(ctx.accel->shape(i));
        if (b.empty() || !b.finite()) continue;
        const double dx = std::max({b.lo.x - eye.x, 0.0, eye.x - b.hi.x});
        const double dz = std::max({b.lo.z - eye.z, 0.0, eye.z - b.hi.z});
        lo = std::min(lo, std::hypot(dx, dz));
    }
    return {std::max(lo, 1e-3 * ctx.extent), ctx.extent};
}

struct RayError {
    double px = 0.0;
    int crossings = 0;
};

// A ray's error wherever it may meet an object: at every distance of the zone (the ground
// included, where the exact ray reaches it), and in its final direction for a ray that
// leaves towards the sky; pixels.
RayError ray_error(const RevolutionStack& s, const ExactRay& ex, double elevation, double px,
                   double zone_lo, double zone_hi, double reach, bool pov_iors) {
    const MeridianPath p = trace_meridian(s, elevation, reach, 100000, pov_iors);
    RayError out;
    out.crossings = p.crossings;
    if (p.cut_off) {
        out.px = kInf;
        return out;
    }
    const double y0 = s.eye_y;
    double worst = 0.0;
    constexpr int kSamples = 160;
    const double end_exact = ex.hits_ground ? ex.dz_ground : kInf;
    const double end_band = p.ground ? p.points.back().x : kInf;
    for (int q = 0; q <= kSamples; ++q) {
        const double r = zone_lo + (zone_hi - zone_lo) * q / kSamples;
        if (r > end_exact || r > end_band) {
            // Where either reaches the ground first: the angle between the two ground points,
            // or between one's ground point and the other's height there.
            const double re = std::min(end_exact, zone_hi), rb = std::min(end_band, zone_hi);
            const double ye = re < end_exact ? height_at(ex, re) : 0.0;
            const double yb = rb < end_band ? path_height(p, rb) : 0.0;
            if (std::isfinite(ye) && std::isfinite(yb))
                worst =
                    std::max(worst, std::fabs(std::atan2(yb - y0, rb) - std::atan2(ye - y0, re)));
            else
                worst = kInf;
            break;
        }
        const double yb = path_height(p, r), ye = height_at(ex, r);
        if (!std::isfinite(yb)) {
            worst = kInf;  // the band ray turned back before the scene's edge
            break;
        }
        worst = std::max(worst, std::fabs(std::atan2(yb - y0, r) - std::atan2(ye - y0, r)));
    }
    if (!ex.hits_ground && !p.ground && std::isfinite(worst)) {
        const double fe = std::atan(asymptotic_slope(ex));
        const double fb = std::atan2(p.direction.y, p.direction.x);
        if (p.direction.y > 0.0) worst = std::max(worst, std::fabs(fb - fe));
    }
    out.px = worst / px;
    return out;
}

/// A figure for the table: `digits` significant, or "inf".
std::string sig_or_inf(double v, int digits) {
    return std::isfinite(v) ? sig(v, digits) : std::string("inf");
}

std::string slug(const std::string& s) {
    std::string o;
    for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return o;
}

CompileOptions study_compile_options(const StudyOptions& opt) {
    CompileOptions co;
    co.input() = opt.input();
    co.progress = false;
    co.samples_per_side = 3;
    // The designs are those of the scene's own camera; the corrected camera is a row of its
    // own.
    co.camera = CameraModel::Perspective;
    return co;
}

/// The study's state: the scene compiled once, the continuum of its camera's rays, where the
/// results are staged, and what has been measured so far.
struct Study {
    // The output folders made by this run, taken away again (if empty) when the study fails;
    // first, so that it goes last, after the staging folder.
    NewDirectories folders;
    // The results (curves, table, plots, summary) are written into a staging folder and
    // renamed into place together at the end, all of them or none, and none over a file the
    // scene was read from.
    OutputSet outputs;
    const StudyOptions& opt;
    CompileOptions co;  // the scene's own camera, 3x3 samples: each design starts from it
    CompileContext ctx;
    Continuum k;
    double zone_lo = 0.0, zone_hi = 0.0, reach = 0.0;
    CameraRays centres;
    fs::path dir, staging;
    StudyResult res;
    std::vector<std::string> render_failures;  // POV-Ray's, with their cause

    explicit Study(const StudyOptions& options)
        : opt(options), co(study_compile_options(options)) {}
    void say(const std::string& line) const {
        if (opt.progress) opt.progress(line);
    }
    /// Writes a result (a path relative to the output folder) into the staging folder.
    Status put(const std::string& rel, const std::string& content) const {
        return write_file_atomic((staging / rel).string(), content);
    }
};

/// Measures a design over the continuum into `row` and writes its curve.
Status evaluate(Study& st, StudyRow& row, const RevolutionStack& s, bool pov_iors) {
    const Continuum& k = st.k;
    std::vector<RayError> e(k.elevation.size());
    parallel_for(static_cast<long>(e.size()), [&](long i) {
        e[i] = ray_error(s, k.exact[i], k.elevation[i], k.pixel_rad[i], st.zone_lo, st.zone_hi,
                         st.reach, pov_iors);
    });
    std::vector<double> px;
    double sum = 0.0;
    int over = 0;
    for (const auto& r : e) {
        px.push_back(r.px);
        sum += r.crossings;
        row.max_crossings = std::max(row.max_crossings, r.crossings);
        if (r.px > 1.0) ++over;
    }
    row.boundaries = s.boundaries();
    row.mean_crossings = e.empty() ? 0.0 : sum / e.size();
    row.p50_px = percentile(px, 0.5);
    row.p95_px = percentile(px, 0.95);
    row.max_px = *std::max_element(px.begin(), px.end());
    row.share_over_px = e.empty() ? 0.0 : double(over) / e.size();
    std::ostringstream c;
    c << "elevation_deg,error_px,crossings\n";
    for (size_t i = 0; i < e.size(); ++i)
        c << sig(k.elevation[i] * 180.0 / M_PI, 9) << "," << sig_or_inf(e[i].px, 6) << ","
          << e[i].crossings << "\n";
    row.curve = "curves/" + slug(row.design) + ".csv";
    return st.put(row.curve, c.str());
}

/// A plane design compiled, checked and rendered as `mirage compile` and `make render` do.
Status compile_and_render(Study& st, StudyRow& row, CompileOptions c) {
    c.out_dir = (st.dir / "work" / slug(row.design)).string();
    c.image = (st.dir / "work" / (slug(row.design) + ".png")).string();
    c.samples_per_side = 3;
    auto rep = compile_scene(c);
    if (!rep) return rep.error();
    row.seen_p95_px = rep->p95_seen_error_px;
    row.seen_max_px = rep->max_seen_error_px;
    row.seen_p95_px_samples = rep->p95_seen_error_px_samples;
    row.seen_max_px_samples = rep->max_seen_error_px_samples;
    row.compile_seconds = rep->seconds;
    row.max_trace_level = rep->max_trace_level;
    if (!st.opt.render) return Ok{};
    PovrayRenderSettings ps;
    ps.povray = st.opt.povray;
    ps.ini = rep->ini_path;
    ps.work_dir = c.out_dir;
    ps.log = c.out_dir + "/povray.log";
    if (rep->camera == "corrected") ps.crop_top_row = rep->image_path;
    auto r = render_povray(ps);
    if (!r) return r.error();
    if (r->exit_code != 0) {
        st.render_failures.push_back(row.design + ": POV-Ray failed (exit " +
                                     std::to_string(r->exit_code) + "; " + ps.log +
                                     "): " + povray_failure_cause(ps.log));
        return make_error("POV-Ray failed: " + log_tail(ps.log, 5));
    }
    row.povray_seconds = r->seconds;
    row.povray_trace_seconds = r->log.trace_seconds.value_or(-1.0);
    return Ok{};
}

/// POV-Ray's time on the template without an atmosphere, the floor of every plane design's.
void render_plain(Study& st) {
    CompileOptions plain = st.co;
    plain.profile = Profile{};
    plain.profile_label = "none";
    StudyRow none;
    none.design = "no atmosphere";
    none.geometry = "planes";
    if (auto s = compile_and_render(st, none, plain); s)
        st.res.plain_povray_seconds = none.povray_seconds;
    else
        st.res.notes.push_back("plain render: " + s.message());
}

/// One plane design: designed from the context `design`, measured, then compiled with the
/// options `c` (whose failure is a note).
Status study_plane_design(Study& st, StudyRow row, const CompileContext& design,
                          const CompileOptions& c) {
    row.geometry = "planes";
    st.say(row.design);
    auto d = design_layers(design, st.centres);
    if (!d) return d.error();
    if (auto s = evaluate(st, row, revolution_of(design.rendered(d->stack), design.eye_y), true);
        !s)
        return s.error();
    if (auto s = compile_and_render(st, row, c); !s)
        st.res.notes.push_back(row.design + ": " + s.message());
    st.res.rows.push_back(row);
    return Ok{};
}

/// Planes: Berger's equal layers and the fit to the camera's rays.
Status study_planes(Study& st) {
    for (int n : st.opt.uniform_counts) {
        StudyRow row;
        row.design = "uniform " + std::to_string(n);
        CompileContext u = st.ctx;
        u.settings.layers = LayerMode::Uniform;
        u.settings.layer_count = n;
        CompileOptions c = st.co;
        c.layers = LayerMode::Uniform;
        c.layer_count = n;
        if (auto s = study_plane_design(st, row, u, c); !s) return s;
    }
    for (int cols : {1, 4}) {
        StudyRow row;
        row.design =
            cols == 1 ? "fit (centre column)" : "fit (" + std::to_string(cols) + " columns)";
        CompileContext f = st.ctx;
        f.options.fit_columns = cols;
        CompileOptions c = st.co;
        c.fit_columns = cols;
        if (auto s = study_plane_design(st, row, f, c); !s) return s;
    }
    return Ok{};
}

/// Graded layers of revolution (2D only: emitted they would be meshes).
Status study_graded(Study& st) {
    const CompileContext& ctx = st.ctx;
    StudyResult& res = st.res;
    const double top = std::max(
        ctx.eye_y * 1.01, height_of_excess(closed_profile(ctx), eta_sq_excess(closed_profile(ctx), kInf) * 0.99));
    const double range = std::fabs(eta(closed_profile(ctx), top) - closed_profile(ctx).eta0);
    const double n_eye = eta(closed_profile(ctx), ctx.eye_y);
    for (int levels : st.opt.graded_levels) {
        for (double steps : st.opt.graded_steps) {
            StudyRow row;
            row.design =
                "graded " + std::to_string(levels) + " levels, " + sig(steps, 3) + " steps";
            row.geometry = "revolution";
            st.say(row.design);
            const double dn = range / levels;
            GradedSettings gs;
            gs.grading = steps * dn / n_eye;
            gs.saturation = n_eye * st.zone_lo;  // levelled off before the nearest object
            gs.softness = 0.15;
            const IndexRange ir = graded_index_range(closed_profile(ctx), ctx.eye_y, top, gs);
            std::vector<double> lv;
            // Levels on a grid with the eye's index in the middle of a layer.
            const double c0 = n_eye + 0.5 * dn - dn * std::ceil((n_eye - ir.lo) / dn);
            for (double c = c0; c < ir.hi && lv.size() <= kMaxGradedLevels; c += dn)
                if (c > ir.lo) lv.push_back(c);
            if (lv.size() > kMaxGradedLevels) {
                res.notes.push_back(row.design + ": more than " + std::to_string(kMaxGradedLevels) +
                                    " levels over the graded index range: left out");
                continue;
            }
            auto g = graded_stack(closed_profile(ctx), ctx.eye_y, res.elevation_lo, res.elevation_hi,
                                  std::min(st.reach, 1.2 * st.zone_hi), top, gs, lv);
            if (!g) {
                res.notes.push_back(row.design + ": " + g.message());
                continue;
            }
            if (auto s = evaluate(st, row, *g, false); !s) return s.error();
            res.rows.push_back(row);
        }
    }
    return Ok{};
}

std::string study_csv(const StudyResult& res) {
    std::ostringstream csv;
    csv << "design,geometry,boundaries,mean_crossings,max_crossings,p50_px,p95_px,max_px,"
           "share_over_1px,seen_p95_px,seen_max_px,seen_p95_px_samples,seen_max_px_samples,"
           "compile_seconds,povray_seconds,povray_trace_seconds,max_trace_level,curve\n";
    auto num = [](double v) { return sig_or_inf(v, 6); };
    for (const auto& r : res.rows)
        csv << "\"" << r.design << "\"," << r.geometry << "," << r.boundaries << ","
            << num(r.mean_crossings) << "," << r.max_crossings << "," << num(r.p50_px) << ","
            << num(r.p95_px) << "," << num(r.max_px) << "," << num(r.share_over_px) << ","
            << num(r.seen_p95_px) << "," << num(r.seen_max_px) << "," << num(r.seen_p95_px_samples)
            << "," << num(r.seen_max_px_samples) << "," << num(r.compile_seconds) << ","
            << num(r.povray_seconds) << "," << num(r.povray_trace_seconds) << ","
            << r.max_trace_level << "," << r.curve << "\n";
    return csv.str();
}

/// The plots: the error over the continuum against elevation, and p95 against crossings.
std::string study_gnuplot_script(const StudyResult& res) {
    std::ostringstream gp;
    gp << "# Written by mirage study; run it in this directory: gnuplot study.gp\n"
       << "set datafile separator ','\nset terminal pngcairo size 1100,640 font 'DejaVu Sans,10'\n"
       << "set output 'error_vs_elevation.png'\nset logscale y\nset yrange [0.01:1000]\n"
       << "set xlabel 'elevation of the camera ray (degrees)'\n"
       << "set ylabel 'error where it may meet an object (pixels)'\nset grid\n"
       << "set title '" << res.name << " " << res.width << "x" << res.height
       << ": every camera ray of the image, against its exact path'\nset key outside right\n"
       << "plot ";
    bool first = true;
    for (const auto& r : res.rows) {
        if (r.design.rfind("uniform", 0) == 0 && r.design != "uniform 64") continue;
        gp << (first ? "" : ", ") << "'" << r.curve
           << "' using 1:($2+0.01) every ::1 with points pt 7 ps 0.25 title '" << r.design << "'";
        first = false;
    }
    gp << "\nset output 'error_vs_crossings.png'\nunset logscale\nset logscale xy\nset yrange "
          "[*:*]\n"
       << "set xlabel 'boundary crossings per camera ray (mean)'\n"
       << "set ylabel '95th percentile of the error (pixels)'\n"
       << "set title '" << res.name << ": error against the cost of a band design'\n"
       << "set key outside right\n"
       // Three families, each plane design labelled.
       << "is(p) = strstrt(strcol(1), p) == 1\n"
       << "plot 'study.csv' using 4:(is('uniform') ? $7 : 1/0) every ::1 with points pt 7 ps 1.5 "
          "title 'equal layers', "
       << "'study.csv' using 4:(is('fit') ? $7 : 1/0) every ::1 with points pt 9 ps 1.8 "
          "title 'fitted planes', "
       << "'study.csv' using 4:(strcol(2) eq \"revolution\" ? $7 : 1/0) every ::1 with points pt 5 "
          "ps 1.5 title 'graded layers of revolution', "
       << "'study.csv' using 4:(strcol(2) eq \"planes\" ? $7 : 1/0):1 every ::1 with labels offset "
          "0,1 "
          "font ',8' notitle\n";
    return gp.str();
}

std::string study_summary(const StudyOptions& opt, const StudyResult& res) {
    std::ostringstream md;
    const MachineInfo m = read_machine_info();
    md << "# Band designs for " << res.name << " at " << res.width << "x" << res.height << "\n\n"
       << "`mirage study " << opt.scene << " -W " << opt.width << " -H " << opt.height << "` on "
       << m.cores << " cores (" << m.cpu << "), load " << m.load << ".\n\n"
       << "The continuum: " << res.rays << " camera rays with elevations from "
       << sig(res.elevation_lo * 180 / M_PI, 4) << " to " << sig(res.elevation_hi * 180 / M_PI, 4)
       << " degrees (every column and sub-pixel sample of the image has an elevation in it). "
       << "Error: the angle seen from the eye between the band path and the exact path at every "
       << "distance from " << sig(res.zone_lo, 4) << " to " << sig(res.zone_hi, 4)
       << " units (the nearest object to the scene's edge) and at the ground, and the final "
       << "direction of rays that leave to the sky, in pixels. Crossings: boundary events of a "
       << "camera ray (POV-Ray's trace levels). Plane designs are also compiled and checked "
       << "pixel by pixel (seen error, pixel centres and 3x3 samples, reflections included) and "
       << "rendered by POV-Ray (wall clock of the process";
    if (res.plain_povray_seconds > 0)
        md << "; the template without an atmosphere: " << sig(res.plain_povray_seconds, 3) << " s";
    md << ").\n\n| design | boundaries | crossings mean / max | error p50 / p95 / max (px) | over "
          "1 px "
          "| seen p95 / max, centres (px) | seen p95 / max, samples (px) | compile (s) | POV-Ray "
          "(s) "
          "| max level |\n|---|---|---|---|---|---|---|---|---|---|\n";
    auto cell = [&](double v, int d = 3) { return v < 0 ? std::string("-") : sig_or_inf(v, d); };
    for (const auto& r : res.rows)
        md << "| " << r.design << " | " << r.boundaries << " | " << cell(r.mean_crossings) << " / "
           << r.max_crossings << " | " << cell(r.p50_px) << " / " << cell(r.p95_px) << " / "
           << cell(r.max_px) << " | " << sig(100 * r.share_over_px, 3) << " % | "
           << cell(r.seen_p95_px) << " / " << cell(r.seen_max_px) << " | "
           << cell(r.seen_p95_px_samples) << " / " << cell(r.seen_max_px_samples) << " | "
           << cell(r.compile_seconds) << " | " << cell(r.povray_seconds) << " | "
           << (r.max_trace_level < 0 ? std::string("-") : std::to_string(r.max_trace_level))
           << " |\n";
    for (const auto& n : res.notes) md << "\n- " << n;
    md << "\n";
    return md.str();
}

/// Writes the table, the plots (gnuplot run in the staging folder) and the summary.
Status write_results(Study& st) {
    StudyResult& res = st.res;
    res.csv_path = (st.dir / "study.csv").string();
    if (auto s = st.put("study.csv", study_csv(res)); !s) return s.error();
    res.plot_elevation = (st.dir / "error_vs_elevation.png").string();
    res.plot_crossings = (st.dir / "error_vs_crossings.png").string();
    if (auto s = st.put("study.gp", study_gnuplot_script(res)); !s) return s.error();
    if (find_program(st.opt.gnuplot)) {
        auto run = run_process({st.opt.gnuplot, "study.gp"}, st.staging.string(),
                               (st.staging / "gnuplot.log").string());
        res.plotted = run && run->exit_code == 0;
        if (!res.plotted) res.notes.push_back("gnuplot failed: see gnuplot.log");
    } else {
        res.notes.push_back("no plots: gnuplot not found");
    }
    res.summary_path = (st.dir / "summary.md").string();
    return st.put("summary.md", study_summary(st.opt, res));
}

}  // namespace

Status validate_study_options(const StudyOptions& o) {
    for (int n : o.uniform_counts)
        if (auto s = check_layer_count(n, "--counts"); !s) return s;
    for (int n : o.graded_levels)
        if (auto s = check_layer_count(n, "--graded-levels"); !s) return s;
    for (double steps : o.graded_steps)
        if (!(steps >= 0.0 && steps <= kMaxGradedSteps))
            return make_error("--graded-steps " + shortest(steps) + ": must be from 0 to " +
                              shortest(kMaxGradedSteps) + " levels");
    return Ok{};
}

Result<StudyResult> run_design_study(const StudyOptions& opt) {
    if (auto s = validate_study_options(opt); !s) return s.error();
    Study st(opt);
    auto ctx_r = compile_settings(st.co);
    if (!ctx_r) return ctx_r.error();
    st.ctx = std::move(*ctx_r);
    const CompileContext& ctx = st.ctx;
    if (!ctx.settings.declared || !ctx.atmosphere.has_gradient())
        return make_error(opt.scene + ": the scene declares no atmosphere: nothing to study");
    if (!ctx.atmosphere.exponential_profile())
        return make_error(opt.scene + ": the layer designs studied are fitted with the " +
                          "exponential profiles' closed forms, and this scene's atmosphere is " +
                          "real air (" + ctx.settings.profile_label + ")");

    StudyResult& res = st.res;
    res.scene = opt.scene;
    res.name = ctx.name;
    res.width = opt.width;
    res.height = opt.height;
    st.dir = fs::absolute(opt.out_dir.empty() ? fs::path("build/study") / ctx.name
                                              : fs::path(opt.out_dir));
    const fs::path& dir = st.dir;
    if (auto s = check_povray_path(dir.string(), "the output folder (-o)"); !s) return s.error();
    st.outputs.protect(ctx.scene.files);
    for (const char* sub : {"curves", "work"})
        if (auto s = st.folders.make((dir / sub).string()); !s) return s.error();
    res.out_dir = dir.string();
    auto staging = st.outputs.make_staging_folder(dir.string());
    if (!staging) return staging.error();
    st.staging = *staging;
    std::error_code ec;
    fs::create_directories(st.staging / "curves", ec);
    if (ec)
        return make_error((st.staging / "curves").string() + ": cannot create: " + ec.message());

    st.k = make_continuum(ctx, opt.rays_per_row);
    res.rays = static_cast<int>(st.k.elevation.size());
    res.elevation_lo = st.k.elevation.front();
    res.elevation_hi = st.k.elevation.back();
    std::tie(st.zone_lo, st.zone_hi) = object_zone(ctx);
    res.zone_lo = st.zone_lo;
    res.zone_hi = st.zone_hi;
    st.reach = ctx.layers_box.x1 - ctx.camera.location.x;
    st.centres = camera_rays(ctx, 1);

    if (opt.render) render_plain(st);
    if (auto s = study_planes(st); !s) return s.error();
    if (auto s = study_graded(st); !s) return s.error();
    if (auto s = write_results(st); !s) return s.error();

    if (auto s = st.outputs.commit_staging_folder(); !s) return s.error();
    st.folders.keep();
    // The results are written (their notes say what failed), but a study whose renders failed
    // did not do what it was asked.
    if (!st.render_failures.empty())
        return make_error(std::to_string(st.render_failures.size()) +
                          " POV-Ray render(s) failed; the results in " + dir.string() +
                          " leave them out.  The first: " + st.render_failures.front());
    return res;
}

}  // namespace mirage
