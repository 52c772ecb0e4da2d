#include "compare/compare.h"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "atmosphere/profile.h"
#include "compare/compare_report.h"
#include "compare/povray_render.h"
#include "compile/compile.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "load/mirage_scene.h"
#include "pov/povray_path.h"
#include "report/contact_sheet.h"
#include "trace/object_query.h"
#include "trace_scene/trace_scene.h"
#include "util/atomic_file.h"
#include "util/format.h"
#include "util/new_directories.h"
#include "util/output_set.h"
#include "util/process.h"

namespace mirage {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxCount = kMaxLayerCount;  // the largest uniform layer count a sweep tries
constexpr int kMaxSteps = 256;  // the largest count of index steps the default sweep tries
constexpr int kFirstCount = 8;  // the default doubling starts here

std::string list_text(const std::vector<double>& values) {
    std::string s;
    for (double v : values) {
        if (!s.empty()) s += ',';
        s += shortest(v);
    }
    return s;
}

std::string list_text(const std::vector<int>& values) {
    std::string s;
    for (int v : values) {
        if (!s.empty()) s += ',';
        s += std::to_string(v);
    }
    return s;
}

std::string shell_quoted(const std::string& s) {
    if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-+=/.,:@%") == std::string::npos)
        return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

double process_cpu_seconds() {
    rusage u{};
    ::getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// A name for a temporary image beside `path` that keeps its extension last: OpenImageIO and
/// POV-Ray both choose (or append) the format's extension.
std::string temporary_image_name(const fs::path& path) {
    std::string name = ".";
    name += path.stem().string();
    name += ".tmp";
    name += std::to_string(::getpid());
    name += path.extension().string();
    return (path.parent_path() / name).string();
}

/// The sweep's state: the options, the reference and what has been measured so far.
///
/// The results (results.csv, the plots, the contact sheet, summary.md, reference.png and
/// renders/) are written under a staging directory inside the output directory and renamed
/// into place together at the end, all or none; work/ holds what POV-Ray reads while the
/// sweep runs (each design's compiled scene) and the logs, written as it goes.
struct Sweep {
    NewDirectories folders;  // the output folders made by this run; first, so that it goes last
    CompareOptions opt;
    fs::path out, stage, renders, work;  // renders: the staged renders/
    OutputSet outputs;  // knows the scene's files: no result replaces one; owns the staging
                        // folder
    Image reference;    // code values / 255
    CompareResult result;
    std::vector<SheetTile> tiles;
    std::string povray_version;
    std::set<std::string> compile_warnings;  // noted once each
    bool redesigned = false;  // the last design compiled was refitted with fewer layers or steps
    std::vector<std::string> render_failures;  // POV-Ray's failed renders, with their cause

    void say(const std::string& line) const {
        if (opt.progress) opt.progress(line);
    }
    void note(const std::string& line) {
        result.notes.push_back(line);
        say(line);
    }

    /// Where a result is written until it is committed.
    fs::path staged(const fs::path& result) const { return stage / fs::relative(result, out); }

    /// Refuses an output that would replace a file the scene was read from.
    Status guard(const fs::path& output) const { return outputs.check(output.string()); }

    /// Measures an image (code values / 255) against the reference.
    Result<ImageComparison> measure(const Image& codes) const {
        return compare_images(codes, reference, opt.threshold);
    }
};

std::string row_id(CompareModel model, const std::string& setting) {
    return model_name(model) + "-" + setting;
}

enum class BandRunOutcome { Rendered, Skipped, OverBudget };

/// A compiled scene rendered by POV-Ray: its log kept as dir/povray.log, its image at
/// `image` (both through temporary names).
struct CompiledRender : PovrayRender {
    bool ok = false;       // POV-Ray ran and wrote the image
    std::string failure;   // why not, with the log's place
    std::string log_path;  // dir/povray.log
};

/// Renders `ini` with POV-Ray.  An error when POV-Ray cannot be started or a file cannot be
/// put in place; a render that fails is `ok == false`, with its reason.
Result<CompiledRender> render_compiled(Sweep& sw, const CompileReport& rep, const fs::path& dir,
                                       const std::string& image) {
    const std::string& ini = rep.ini_path;
    PovrayRenderSettings ps;
    ps.povray = sw.opt.povray;
    ps.ini = ini;
    ps.work_dir = sw.out.string();
    CompiledRender r;
    r.log_path = (dir / "povray.log").string();
    ps.log = temporary_name_for(r.log_path);
    ps.output = temporary_image_name(image);
    ps.threads = sw.opt.threads;
    if (rep.camera == "corrected") ps.crop_top_row = ps.output;
    auto run = render_povray(ps);
    if (!run) return run.error();
    static_cast<PovrayRender&>(r) = *run;
    if (auto s = commit_file(ps.log, r.log_path); !s) return s.error();
    std::error_code ec;
    if (run->exit_code != 0 || !fs::exists(ps.output, ec)) {
        fs::remove(ps.output, ec);
        r.failure = "POV-Ray failed (exit " + std::to_string(run->exit_code) + "; " + r.log_path +
                    "): " + povray_failure_cause(r.log_path);
        sw.render_failures.push_back(r.failure);
        return r;
    }
    if (auto s = commit_file(ps.output, image); !s) return s.error();
    if (sw.povray_version.empty()) sw.povray_version = run->log.version;
    r.ok = true;
    return r;
}

/// "uniform-bands: stopped at 256 layers: a camera ray ... (not rendered)": where a sweep of
/// counts ends at POV-Ray's trace-level ceiling.
std::string over_budget_note(const std::string& model, int n, const std::string& unit,
                             const CompileReport& over) {
    return model + ": stopped at " + std::to_string(n) + " " + unit +
           ": a camera ray with its reflections needs trace level " +
           std::to_string(over.max_trace_level) + ", over POV-Ray's ceiling of " +
           std::to_string(kPovrayMaxTraceLevel) + " (not rendered)";
}

/// Compiles one band design, renders it with POV-Ray and measures it.  A fatal error (POV-Ray
/// cannot be started, the scene would be overwritten) is an error; a design that cannot be
/// compiled or rendered is a note.
Result<BandRunOutcome> run_band(Sweep& sw, CompareModel model, double setting,
                                CompileReport* over_budget) {
    CompareRow row;
    row.model = model;
    row.setting = setting;
    const std::string id = row_id(model, setting_text(row));
    const std::string label = (model == CompareModel::UniformBands     ? "uniform "
                               : model == CompareModel::AdaptiveBands  ? "adaptive "
                               : model == CompareModel::CorrectedBands ? "corrected "
                                                                       : "index-step-bands ") +
                              setting_label(row);
    const fs::path dir = sw.work / id;
    const fs::path image = sw.out / "renders" / (id + ".png");
    if (auto s = sw.guard(image); !s) return s.error();

    CompileOptions c;
    c.input() = sw.opt.input();
    c.out_dir = dir.string();
    c.image = image.string();
    // The renders compared are not antialiased: the check of the pixel centres is enough.
    c.samples_per_side = 1;
    c.progress = false;
    c.camera = CameraModel::Perspective;
    if (model == CompareModel::CorrectedBands) {
        // The default design under the corrected camera, at the count asked for.
        c.camera = CameraModel::Corrected;
        c.layer_count = static_cast<int>(std::lround(setting));
    } else if (model == CompareModel::UniformBands) {
        c.layers = LayerMode::Uniform;
        c.layer_count = static_cast<int>(std::lround(setting));
    } else if (model == CompareModel::IndexStepBands) {
        c.layers = LayerMode::IndexSteps;
        c.layer_count = static_cast<int>(std::lround(setting));
    } else {
        c.layers = LayerMode::Adaptive;
        c.tolerance_px = setting;
    }
    auto rep = compile_scene(c);
    if (!rep) {
        sw.note(label + ": skipped, mirage compile failed: " + rep.message());
        return BandRunOutcome::Skipped;
    }
    if (rep->max_trace_level > kPovrayMaxTraceLevel) {
        if (over_budget) *over_budget = *rep;
        return BandRunOutcome::OverBudget;
    }
    // What compile had to give up (a refit within a tighter trace-level budget) explains an
    // error that does not fall with the tolerance.
    sw.redesigned = false;
    for (const auto& w : rep->warnings) {
        if (w.find("redesigned with") != std::string::npos) sw.redesigned = true;
        if (sw.compile_warnings.insert(w).second) sw.note(label + ": mirage compile: " + w);
    }

    auto run = render_compiled(sw, *rep, dir, sw.staged(image).string());
    if (!run) return run.error();
    if (!run->ok) {
        sw.note(label + ": skipped, " + run->failure + ":\n" + log_tail(run->log_path, 5));
        return BandRunOutcome::Skipped;
    }
    auto codes = read_image(sw.staged(image).string());
    if (!codes) return codes.error();
    auto cmp = sw.measure(*codes);
    if (!cmp) return make_error(image.string() + ": " + cmp.message());

    row.layers = rep->layers;
    row.seconds = run->seconds;
    row.render_seconds = run->log.trace_seconds.value_or(0.0);
    row.cpu_seconds = run->log.cpu_seconds.value_or(0.0);
    row.process_cpu_seconds = run->process_cpu_seconds;
    row.threads = run->log.threads;
    row.compile_seconds = rep->seconds;
    row.rmse = cmp->rmse;
    row.psnr_db = cmp->psnr_db;
    row.share_over =
        cmp->pixel_count > 0 ? static_cast<double>(cmp->pixels_over) / cmp->pixel_count : 0.0;
    row.max_error_px = rep->max_error_px;
    row.p95_error_px = rep->p95_error_px;
    row.p95_shift_rows = rep->p95_shift_rows;
    row.max_trace_level = rep->max_trace_level;
    row.image = fs::relative(image, sw.out).string();
    sw.result.rows.push_back(row);
    // (A count of layers is the setting itself.)
    const bool counted_layers =
        model == CompareModel::UniformBands || model == CompareModel::CorrectedBands;
    sw.tiles.push_back({std::move(*codes),
                        model_name(model) + " " + setting_label(row) +
                            (!counted_layers ? ", " + std::to_string(row.layers) + " layers" : "") +
                            "\nPOV-Ray " + sig(row.seconds, 3) + " s, RMSE " + sig(row.rmse, 3)});
    sw.say(label + ": " + (!counted_layers ? std::to_string(row.layers) + " layers, " : "") +
           "POV-Ray " + sig(row.seconds, 3) + " s, RMSE " + sig(row.rmse, 3));
    return BandRunOutcome::Rendered;
}

/// Traces one polyline setting and measures it; a trace that fails is a note.
Status run_tracer(Sweep& sw, CompareModel model, double tolerance) {
    CompareRow row;
    row.model = model;
    row.setting = tolerance;
    const std::string id = row_id(model, setting_text(row));
    const std::string label = model_name(model) + " " + setting_label(row);
    const fs::path image = sw.out / "renders" / (id + ".png");
    if (auto s = sw.guard(image); !s) return s;
    TraceOptions t;
    t.input() = sw.opt.input();
    t.output = sw.staged(image).string();
    t.tolerance_px = tolerance;
    t.threads = sw.opt.threads;
    t.scanline_paths = model == CompareModel::Scanline;
    t.progress = false;
    t.monochrome = true;  // as the band designs: the green channel's air
    const double cpu0 = process_cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    auto rep = trace_scene(t);
    const auto t1 = std::chrono::steady_clock::now();
    const double cpu1 = process_cpu_seconds();
    if (!rep) {
        sw.note(label + ": skipped, the tracer failed: " + rep.message());
        return Ok{};
    }
    Image codes = quantize_srgb8(rep->render.image);
    auto cmp = sw.measure(codes);
    if (!cmp) return make_error(image.string() + ": " + cmp.message());
    row.seconds = std::chrono::duration<double>(t1 - t0).count();
    row.render_seconds = rep->render.stats.seconds;
    row.cpu_seconds = cpu1 - cpu0;
    row.process_cpu_seconds = row.cpu_seconds;
    row.threads = rep->render.stats.threads;
    row.rmse = cmp->rmse;
    row.psnr_db = cmp->psnr_db;
    row.share_over =
        cmp->pixel_count > 0 ? static_cast<double>(cmp->pixels_over) / cmp->pixel_count : 0.0;
    row.max_error_px = rep->tolerance_px;
    row.segments_per_ray = rep->render.stats.segments_per_ray();
    row.image = fs::relative(image, sw.out).string();
    sw.result.rows.push_back(row);
    sw.tiles.push_back({std::move(codes), label + "\ntracer " + sig(row.seconds, 3) + " s, RMSE " +
                                              sig(row.rmse, 3)});
    sw.say(label + ": " + sig(row.segments_per_ray, 3) + " segments/ray, tracer " +
           sig(row.seconds, 3) + " s on " + std::to_string(row.threads) + " threads, RMSE " +
           sig(row.rmse, 3));
    return Ok{};
}

/// POV-Ray with no layers against the tracer with straight rays: how far apart the two
/// renderers are before any atmosphere.  Failures are notes.
Status run_straight(Sweep& sw) {
    const fs::path dir = sw.work / "straight";
    CompileOptions c;
    c.input() = sw.opt.input();
    c.out_dir = dir.string();
    c.image = (dir / "povray.png").string();
    c.samples_per_side = 1;
    c.progress = false;
    c.profile = Profile{};  // ProfileKind::None: no layers at all
    c.profile_label = "none (straight rays)";
    auto rep = compile_scene(c);
    if (!rep) {
        sw.note("straight rays: not compared, mirage compile failed: " + rep.message());
        return Ok{};
    }
    auto run = render_compiled(sw, *rep, dir, c.image);
    if (!run) return run.error();
    if (!run->ok) {
        sw.note("straight rays: not compared, " + run->failure);
        return Ok{};
    }
    TraceOptions t;
    t.input() = sw.opt.input();
    t.output = (dir / "tracer.png").string();
    t.threads = sw.opt.threads;
    t.atmosphere = false;
    t.progress = false;
    auto traced = trace_scene(t);
    if (!traced) {
        sw.note("straight rays: not compared, the tracer failed: " + traced.message());
        return Ok{};
    }
    auto pov = read_image(c.image);
    if (!pov) return pov.error();
    auto cmp = compare_images(*pov, quantize_srgb8(traced->render.image), sw.opt.threshold);
    if (!cmp) return make_error(c.image + ": " + cmp.message());
    sw.result.straight_rmse = cmp->rmse;
    sw.say("straight rays: POV-Ray against the tracer, RMSE " + sig(cmp->rmse, 3));
    return Ok{};
}

/// Draws error_vs_time.png and .svg with gnuplot from the script, through temporary names.
Status plot(Sweep& sw) {
    CompareResult& r = sw.result;
    if (!find_program(sw.opt.gnuplot)) {
        sw.note(sw.opt.gnuplot +
                " not found on PATH: no plot drawn (run error_vs_time.gp "
                "with gnuplot to draw it)");
        return Ok{};
    }
    const std::string png_tmp = temporary_image_name(sw.staged(r.plot_png));
    const std::string svg_tmp = temporary_image_name(sw.staged(r.plot_svg));
    const std::string log = (sw.work / "gnuplot.log").string();
    const std::string vars = "png_out='" + fs::path(png_tmp).filename().string() + "'; svg_out='" +
                             fs::path(svg_tmp).filename().string() + "'";
    auto run = run_process({sw.opt.gnuplot, "-e", vars, "error_vs_time.gp"}, sw.stage.string(),
                           temporary_name_for(log));
    if (!run) return run.error();
    if (auto s = commit_file(temporary_name_for(log), log); !s) return s.error();
    std::error_code ec;
    if (run->exit_code != 0 || !fs::exists(png_tmp, ec) || !fs::exists(svg_tmp, ec)) {
        fs::remove(png_tmp, ec);
        fs::remove(svg_tmp, ec);
        sw.note("gnuplot failed (exit " + std::to_string(run->exit_code) + "; " + log +
                "): no plot drawn");
        return Ok{};
    }
    if (auto s = commit_file(png_tmp, sw.staged(r.plot_png).string()); !s) return s;
    if (auto s = commit_file(svg_tmp, sw.staged(r.plot_svg).string()); !s) return s;
    r.plotted = true;
    return Ok{};
}

}  // namespace

std::string model_name(CompareModel model) {
    switch (model) {
        case CompareModel::UniformBands:
            return "uniform-bands";
        case CompareModel::AdaptiveBands:
            return "adaptive-bands";
        case CompareModel::IndexStepBands:
            return "index-step-bands";
        case CompareModel::CorrectedBands:
            return "corrected-bands";
        case CompareModel::Polyline:
            return "polyline";
        case CompareModel::Scanline:
            return "scanline";
    }
    return "";
}

MachineInfo read_machine_info() {
    MachineInfo m;
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof set, &set) == 0) m.cores = CPU_COUNT(&set);
    if (m.cores <= 0) m.cores = static_cast<int>(::sysconf(_SC_NPROCESSORS_ONLN));
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) {
                m.cpu = line.substr(colon + 1);
                m.cpu.erase(0, m.cpu.find_first_not_of(" \t"));
            }
            break;
        }
    }
    std::ifstream loadavg("/proc/loadavg");
    std::string a, b, c;
    if (loadavg >> a >> b >> c) m.load = a + " " + b + " " + c;
    return m;
}

Status validate_compare_options(const CompareOptions& o) {
    if (o.scene.empty()) return make_error("no scene given");
    if (auto s = check_image_size(o.width, o.height); !s) return s;
    if (auto s = check_tolerance_px(o.reference_tolerance_px, "--reference-tolerance"); !s)
        return s;
    for (int n : o.counts)
        if (auto s = check_layer_count(n, "--counts"); !s) return s;
    for (int n : o.steps)
        if (auto s = check_layer_count(n, "--steps"); !s) return s;
    for (int n : o.corrected_counts)
        if (auto s = check_layer_count(n, "--corrected-counts"); !s) return s;
    const std::pair<const char*, const std::vector<double>*> lists[] = {
        {"--tolerances", &o.tolerances}, {"--trace-tolerances", &o.trace_tolerances}};
    for (const auto& [flag, values] : lists)
        for (double t : *values)
            if (auto s = check_tolerance_px(t, flag); !s) return s;
    for (const auto& [flag, values] : lists)
        for (double t : *values)
            if (!(o.reference_tolerance_px < t))
                return make_error("--reference-tolerance " + shortest(o.reference_tolerance_px) +
                                  " px is not finer than " + shortest(t) + " px in " + flag +
                                  ": the reference must be finer than every setting it judges");
    if (!(o.threshold > 0.0 && o.threshold < 1.0))
        return make_error("--threshold " + shortest(o.threshold) +
                          ": must be between 0 and 1 (a difference of 8-bit codes / 255)");
    if (o.threads < 0)
        return make_error("--threads " + std::to_string(o.threads) +
                          ": must be 0 (all cores) or more");
    return Ok{};
}

std::string compare_command_line(const CompareOptions& o) {
    std::ostringstream s;
    s << "mirage compare " << shell_quoted(o.scene) << " -W " << o.width << " -H " << o.height;
    if (!o.out_dir.empty()) s << " -o " << shell_quoted(o.out_dir);
    s << " --reference-tolerance " << shortest(o.reference_tolerance_px);
    if (!o.counts.empty()) s << " --counts " << list_text(o.counts);
    if (!o.tolerances.empty()) s << " --tolerances " << list_text(o.tolerances);
    if (!o.steps.empty()) s << " --steps " << list_text(o.steps);
    s << " --corrected-counts " << list_text(o.corrected_counts);
    if (!o.trace_tolerances.empty()) s << " --trace-tolerances " << list_text(o.trace_tolerances);
    if (o.scanline) s << " --scanline-paths";
    s << " --threshold " << shortest(o.threshold);
    if (o.threads > 0) s << " --threads " << o.threads;
    for (const auto& p : o.library_paths) s << " -L " << shell_quoted(p);
    return s.str();
}

namespace {

/// From coarse to fine, each setting once.
void sort_settings(CompareOptions& opt) {
    for (auto* list : {&opt.counts, &opt.steps, &opt.corrected_counts}) {
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    for (auto* list : {&opt.tolerances, &opt.trace_tolerances}) {
        std::sort(list->begin(), list->end(), std::greater<>());
        list->erase(std::unique(list->begin(), list->end()), list->end());
    }
}

/// The results' names in the output folder, checked against POV-Ray's limits and the scene's
/// files, and the folders (the output's, renders/, work/ and the staging folder) made.
Status place_results(Sweep& sw) {
    const CompareOptions& opt = sw.opt;
    CompareResult& r = sw.result;
    std::error_code ec;
    sw.out = fs::absolute(opt.out_dir.empty() ? fs::path("build/compare") / r.name
                                              : fs::path(opt.out_dir));
    sw.work = sw.out / "work";
    // POV-Ray renders every design from an .ini that names these: refused at once if it
    // cannot take one, before the reference is traced.
    if (auto s = check_povray_path(fs::absolute(opt.scene).string(), "the scene"); !s) return s;
    if (auto s = check_povray_path(sw.out.string(), "the output folder (-o)"); !s) return s;
    for (const auto& l : opt.library_paths)
        if (auto s = check_povray_path(fs::absolute(l).string(), "-L"); !s) return s;
    for (const auto& d : {sw.out, sw.out / "renders", sw.work})
        if (auto s = sw.folders.make(d.string()); !s) return s;
    auto stage = sw.outputs.make_staging_folder(sw.out.string());
    if (!stage) return stage.error();
    sw.stage = *stage;
    sw.renders = sw.stage / "renders";
    fs::create_directories(sw.renders, ec);
    if (ec) return make_error(sw.renders.string() + ": cannot create: " + ec.message());
    r.out_dir = sw.out.string();
    r.csv_path = (sw.out / "results.csv").string();
    r.plot_script = (sw.out / "error_vs_time.gp").string();
    r.plot_png = (sw.out / "error_vs_time.png").string();
    r.plot_svg = (sw.out / "error_vs_time.svg").string();
    r.sheet_path = (sw.out / "contact_sheet.png").string();
    r.summary_path = (sw.out / "summary.md").string();
    r.reference_path = (sw.out / "reference.png").string();
    for (const std::string& p : {r.csv_path, r.plot_script, r.plot_png, r.plot_svg, r.sheet_path,
                                 r.summary_path, r.reference_path})
        if (auto s = sw.guard(p); !s) return s;
    return Ok{};
}

/// The reference: per-ray paths at the finest tolerance.
Status run_reference(Sweep& sw) {
    const CompareOptions& opt = sw.opt;
    CompareResult& r = sw.result;
    // A scene that does not parse fails here, with its place.
    TraceOptions t;
    t.input() = opt.input();
    t.tolerance_px = opt.reference_tolerance_px;
    t.threads = opt.threads;
    t.progress = false;
    t.monochrome = true;  // as the band designs: the green channel's air
    auto ref = trace_scene(t);
    if (!ref) return ref.error();
    if (ref->mode == PathMode::Straight)
        return make_error(opt.scene + ": the scene declares no atmosphere (" + ref->atmosphere +
                          "): there is nothing to compare; declare one as mirage.inc describes");
    if (auto s = write_png(ref->render.image, sw.staged(r.reference_path).string()); !s) return s;
    r.atmosphere = ref->atmosphere;
    r.reference_seconds = ref->render.stats.seconds;
    r.reference_threads = ref->render.stats.threads;
    sw.reference = quantize_srgb8(ref->render.image);
    sw.tiles.push_back({sw.reference, "reference: per-ray paths " +
                                          shortest(opt.reference_tolerance_px) + " px\ntracer " +
                                          sig(r.reference_seconds, 3) + " s"});
    sw.say("reference " + shortest(opt.reference_tolerance_px) + " px: per-ray paths, tracer " +
           sig(r.reference_seconds, 3) + " s on " + std::to_string(r.reference_threads) +
           " threads");
    return Ok{};
}

/// Uniform layers, doubling (or as listed) until a design exceeds the trace-level budget.
Status run_uniform_sweep(Sweep& sw) {
    const CompareOptions& opt = sw.opt;
    std::vector<int> counts = opt.counts;
    if (counts.empty())
        for (int n = kFirstCount; n <= kMaxCount; n *= 2) counts.push_back(n);
    bool stopped = false;
    for (int n : counts) {
        CompileReport over;
        auto outcome = run_band(sw, CompareModel::UniformBands, n, &over);
        if (!outcome) return outcome.error();
        if (*outcome == BandRunOutcome::OverBudget) {
            sw.note(over_budget_note("uniform-bands", n, "layers", over));
            stopped = true;
            break;
        }
    }
    if (!stopped && opt.counts.empty())
        sw.note("uniform-bands: stopped at " + std::to_string(kMaxCount) +
                " layers, the sweep's largest count, still within the trace-level budget");
    return Ok{};
}

/// Real air's own design: equal steps of the index, doubling (or as listed) until a design
/// exceeds the trace-level budget.  (mirage compile refits a design over the budget with
/// fewer steps, and says so: the sweep stops there, at the first such warning.)
Status run_index_step_sweep(Sweep& sw, bool air) {
    const CompareOptions& opt = sw.opt;
    CompareResult& r = sw.result;
    if (air) {
        std::vector<int> steps = opt.steps;
        if (steps.empty())
            for (int n = kFirstCount; n <= kMaxSteps; n *= 2) steps.push_back(n);
        for (int n : steps) {
            CompileReport over;
            auto outcome = run_band(sw, CompareModel::IndexStepBands, n, &over);
            if (!outcome) return outcome.error();
            if (*outcome == BandRunOutcome::OverBudget) {
                sw.note(over_budget_note("index-step-bands", n, "steps", over));
                break;
            }
            if (opt.steps.empty() && *outcome == BandRunOutcome::Rendered && sw.redesigned) {
                sw.note("index-step-bands: stopped at " + std::to_string(n) +
                        " steps, where mirage compile had to use fewer (above)");
                break;
            }
        }
    } else if (!opt.steps.empty()) {
        sw.note(
            "index-step-bands: not run: index steps are the design for real air, and this "
            "scene's atmosphere is " +
            r.atmosphere);
    }
    return Ok{};
}

/// The fit to the camera's rays at each tolerance.  It needs the exponential profiles' closed
/// forms: for real air one note, not one refusal per tolerance.
Status run_adaptive_sweep(Sweep& sw, bool air) {
    CompareOptions& opt = sw.opt;
    if (air && !opt.tolerances.empty()) {
        sw.note(
            "adaptive-bands: not run: the fit to the camera's rays needs the exponential "
            "profiles' closed forms, and this scene's atmosphere is real air; its own "
            "design is index-step-bands");
        opt.tolerances.clear();
    }
    for (double tol : opt.tolerances) {
        CompileReport over;
        auto outcome = run_band(sw, CompareModel::AdaptiveBands, tol, &over);
        if (!outcome) return outcome.error();
        if (*outcome == BandRunOutcome::OverBudget)
            sw.note("adaptive " + shortest(tol) +
                    " px: skipped: a camera ray with its "
                    "reflections needs trace level " +
                    std::to_string(over.max_trace_level) + ", over POV-Ray's ceiling of " +
                    std::to_string(kPovrayMaxTraceLevel));
    }
    return Ok{};
}

/// The corrected camera (mirage compile's default) at a few layer counts.
Status run_corrected_sweep(Sweep& sw) {
    for (int n : sw.opt.corrected_counts) {
        CompileReport over;
        auto outcome = run_band(sw, CompareModel::CorrectedBands, n, &over);
        if (!outcome) return outcome.error();
        if (*outcome == BandRunOutcome::OverBudget) {
            sw.note(over_budget_note("corrected-bands", n, "layers", over));
            break;
        }
    }
    return Ok{};
}

/// The table, the plot, the contact sheet and the summary, staged.
Status write_results(Sweep& sw) {
    CompareResult& r = sw.result;
    r.povray_version = sw.povray_version;
    if (auto s = write_file_atomic(sw.staged(r.csv_path).string(), results_csv(r)); !s) return s;
    if (auto s = write_file_atomic(sw.staged(r.plot_script).string(), gnuplot_script(r)); !s)
        return s;
    if (auto s = plot(sw); !s) return s;
    auto sheet = make_contact_sheet(sw.tiles);
    if (!sheet) return sheet.error();
    r.caption_font = sheet->font;
    if (r.caption_font.empty())
        sw.note("contact sheet without captions: OpenImageIO found none of the fonts " +
                std::string("DejaVuSans, LiberationSans-Regular, NotoSans-Regular, FreeSans ") +
                "(Debian: apt-get install fonts-dejavu-core)");
    if (auto s = write_png_codes(sheet->image, sw.staged(r.sheet_path).string()); !s) return s;
    if (auto s = write_file_atomic(sw.staged(r.summary_path).string(), summary_markdown(r)); !s)
        return s;
    return Ok{};
}

}  // namespace

Result<CompareResult> run_comparison(const CompareOptions& options) {
    if (auto s = validate_compare_options(options); !s) return s.error();
    Sweep sw;
    sw.opt = options;
    CompareOptions& opt = sw.opt;
    sort_settings(opt);
    if (!find_program(opt.povray))
        return make_error(opt.povray +
                          ": not found on PATH; the band models are rendered by POV-Ray 3.7 "
                          "(Debian: apt-get install povray)");
    // The scene is read first: a scene that does not load fails here, with its place, and
    // its files are the inputs no result may replace.
    SceneLoadOptions lo = scene_load_options(opt);
    lo.object_queries = tracer_object_queries();
    auto loaded = load_mirage_scene(lo);
    if (!loaded) return loaded.error();
    sw.outputs.protect(loaded->scene.files);
    std::error_code ec;

    CompareResult& r = sw.result;
    r.scene = opt.scene;
    r.name = fs::path(opt.scene).stem().string();
    r.width = opt.width;
    r.height = opt.height;
    r.threshold = opt.threshold;
    r.reference_tolerance_px = opt.reference_tolerance_px;
    r.command = compare_command_line(options);
    r.machine = read_machine_info();
    if (auto s = place_results(sw); !s) return s.error();
    if (auto s = run_reference(sw); !s) return s.error();
    if (auto s = run_straight(sw); !s) return s.error();
    if (auto s = run_uniform_sweep(sw); !s) return s.error();
    const bool air = loaded->settings.air != nullptr;
    if (auto s = run_index_step_sweep(sw, air); !s) return s.error();
    if (auto s = run_adaptive_sweep(sw, air); !s) return s.error();
    if (auto s = run_corrected_sweep(sw); !s) return s.error();
    for (double tol : opt.trace_tolerances)
        if (auto s = run_tracer(sw, CompareModel::Polyline, tol); !s) return s.error();
    if (opt.scanline)
        for (double tol : opt.trace_tolerances)
            if (auto s = run_tracer(sw, CompareModel::Scanline, tol); !s) return s.error();

    if (auto s = write_results(sw); !s) return s.error();
    // Everything staged goes into place together.
    if (auto s = sw.outputs.commit_staging_folder(); !s) return s.error();
    sw.folders.keep();
    // The results are written (they say which designs were skipped), but a sweep whose
    // renders failed did not do what it was asked.
    if (!sw.render_failures.empty())
        return make_error(std::to_string(sw.render_failures.size()) +
                          " POV-Ray render(s) failed; the results in " + sw.out.string() +
                          " leave them out.  The first: " + sw.render_failures.front());
    return r;
}

}  // namespace mirage
