#include "animate/animate.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "animate/video.h"
#include "compare/compare.h"
#include "compare/povray_render.h"
#include "compile/compile.h"
#include "load/mirage_scene.h"
#include "pov/emit_camera.h"
#include "pov/povray_path.h"
#include "trace/object_query.h"
#include "trace_scene/trace_scene.h"
#include "util/atomic_file.h"
#include "util/format.h"
#include "util/hex_args.h"
#include "util/json_text.h"
#include "util/new_directories.h"
#include "util/process.h"
#include "util/progress.h"
#include "util/text_escape.h"

namespace mirage {

namespace fs = std::filesystem;

namespace {

std::string model_name(FrameModel m) { return m == FrameModel::Bands ? "bands" : "trace"; }

std::string frame_label(const PlannedFrame& f) {
    return "frame " + std::to_string(f.number) + " (clock " + clock_text(f.clock.clock) + ")";
}

bool ends_with_ini(const std::string& s) {
    if (s.size() < 4) return false;
    std::string e = s.substr(s.size() - 4);
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e == ".ini";
}

std::string absolute(const std::string& p) { return fs::absolute(p).lexically_normal().string(); }

std::string self_program() {
    std::error_code ec;
    const auto p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("mirage") : p.string();
}

// FNV-1a, 64 bits: a stable fingerprint of the scene text.
std::string fingerprint(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

// Why a task failed, from its log: its own last message ("mirage animate: frame 3 (clock
// 0.5): ..."), else the log's last non-empty line.
std::string last_line(const std::string& path) {
    std::ifstream in(path);
    std::string line, last, said;
    const std::string prefix = "mirage animate: ";
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
        if (line.rfind(prefix, 0) == 0) said = line.substr(prefix.size());
    }
    return said.empty() ? last : said;
}

std::string shell_quote(const std::string& s) {
    if (!s.empty() && s.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                          "0123456789_./=+:,-%") == std::string::npos)
        return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string join_command(const std::vector<std::string>& argv) {
    std::string s;
    for (const auto& a : argv) {
        if (!s.empty()) s += ' ';
        s += shell_quote(a);
    }
    return s;
}

// POV-Ray's switches that give a frame the clock the plan gives it: the animation's range and
// a subset of this one frame, so that POV-Ray's own front end computes every identifier.
std::vector<std::string> povray_frame_switches(const Animation& a, const PlannedFrame& f) {
    std::vector<std::string> s;
    const AnimationRange& r = a.range;
    if (!a.plan.animation) {
        if (r.clock) s.push_back("+K" + clock_text(static_cast<float>(*r.clock)));
        return s;
    }
    s.push_back("+KFI" + std::to_string(r.initial_frame.value_or(1)));
    s.push_back("+KFF" + std::to_string(r.final_frame.value_or(1)));
    s.push_back("+KI" + clock_text(static_cast<float>(r.initial_clock.value_or(0.0))));
    s.push_back("+KF" + clock_text(static_cast<float>(r.final_clock.value_or(1.0))));
    if (r.cyclic) s.push_back("+KC");
    s.push_back("+SF" + std::to_string(f.number));
    s.push_back("+EF" + std::to_string(f.number));
    return s;
}

// The progress of the frames on stderr: the bar on a terminal (util/progress.h), a line per
// finished frame, and without a terminal a line when frames done elsewhere are counted.
class Progress {
  public:
    Progress(bool on, int total)
        : bar_("frames", total, on), counted_lines_(on && !::isatty(STDERR_FILENO)) {}
    void frame_done(const std::string& what, double seconds, bool ok) {
        bar_.message("  " + what + (ok ? ": " : ": FAILED after ") + sig(seconds, 3) + " s (" +
                     std::to_string(++done_) + "/" + std::to_string(total()) + ")");
        bar_.advance();
    }
    void set_done(int done) {
        if (done == done_) return;
        done_ = done;
        if (counted_lines_)
            bar_.message("  " + std::to_string(done) + "/" + std::to_string(total()) +
                         " frames done");
        bar_.set_done(done);
    }
    void finish() { bar_.finish(); }

  private:
    int total() const { return static_cast<int>(bar_.total()); }
    ProgressBar bar_;
    bool counted_lines_;
    std::atomic<int> done_{0};
};

struct TaskOutcome {
    int number = 0;
    double seconds = 0.0;
    bool ok = false;
};

// Local: `jobs` frames at a time, each a task process with its log beside its frame.
std::vector<TaskOutcome> run_local(const Animation& a, const std::vector<PlannedFrame>& todo,
                                   int jobs, Progress& progress) {
    std::vector<TaskOutcome> out(todo.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < todo.size(); i = next++) {
            const PlannedFrame& f = todo[i];
            const std::string log = a.frame_stem(f.number) + ".log";
            std::error_code ec;
            fs::remove(log, ec);
            auto run = run_process(a.task_argv(std::to_string(f.number)), "", log);
            out[i].number = f.number;
            out[i].seconds = run ? run->seconds : 0.0;
            out[i].ok = run && run->exit_code == 0 && fs::exists(a.frame_image(f.number), ec);
            if (!run) {
                std::ofstream(log, std::ios::app) << "mirage animate: " << run.message() << "\n";
            }
            progress.frame_done(frame_label(f), out[i].seconds, out[i].ok);
        }
    };
    std::vector<std::thread> pool;
    const int n = std::max(1, std::min<int>(jobs, static_cast<int>(todo.size())));
    for (int t = 0; t < n; ++t) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    return out;
}

int count_done(const Animation& a) {
    int done = 0;
    std::error_code ec;
    for (const auto& f : a.plan.frames) done += fs::exists(a.frame_image(f.number), ec) ? 1 : 0;
    return done;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Slurm: an array job of the missing frames, then squeue until none of its tasks is left.
Status run_slurm(const Animation& a, const std::vector<PlannedFrame>& todo, Progress& progress,
                 std::vector<std::string>& notes) {
    const SlurmSettings& st = a.options.slurm;
    const fs::path dir = fs::path(a.options.out_dir) / "slurm";
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return make_error(dir.string() + ": cannot create: " + ec.message());
    std::vector<int> numbers;
    for (const auto& f : todo) numbers.push_back(f.number);
    const std::string script = (dir / (a.name + ".sbatch")).string();
    if (auto s = write_file_atomic(script, slurm_script(a, numbers)); !s) return s;
    const std::string submit_log = (dir / "sbatch.log").string();
    fs::remove(submit_log, ec);
    auto submit = run_process(slurm_submit_argv(a, script), "", submit_log);
    if (!submit) return make_error("--slurm: " + submit.message());
    const std::string said = read_text(submit_log);
    if (submit->exit_code != 0)
        return make_error("--slurm: sbatch " + script + " failed (exit " +
                          std::to_string(submit->exit_code) + "): " + last_line(submit_log));
    std::string job = said.substr(0, said.find_first_of(";\r\n"));
    if (job.empty() || job.find_first_not_of("0123456789") != std::string::npos)
        return make_error("--slurm: sbatch said '" + said + "', not a job id");
    notes.push_back("Slurm job " + job + " (" + script + ")");
    if (a.options.progress)
        std::cerr << "  submitted Slurm job " << job << ": " << numbers.size()
                  << " tasks (--array=" << slurm_array_list(numbers) << ")\n";
    const auto t0 = std::chrono::steady_clock::now();
    const std::string poll_log = (dir / "squeue.log").string();
    for (;;) {
        fs::remove(poll_log, ec);
        auto q = run_process({st.squeue, "-h", "-j", job, "-o", "%i %T"}, "", poll_log);
        if (!q) return make_error("--slurm: " + q.message());
        const std::string text = read_text(poll_log);
        const bool gone =
            (q->exit_code == 0 && text.find_first_not_of(" \r\n") == std::string::npos) ||
            (q->exit_code != 0 && text.find("Invalid job id") != std::string::npos);
        progress.set_done(count_done(a));
        if (gone) break;
        if (q->exit_code != 0)
            return make_error("--slurm: squeue failed (exit " + std::to_string(q->exit_code) +
                              "): " + last_line(poll_log));
        const double waited =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (waited > st.timeout_seconds)
            return make_error("--slurm: job " + job + " still in the queue after " +
                              sig(waited, 3) + " s (--slurm-timeout " + sig(st.timeout_seconds, 3) +
                              "); the frames done are kept: run the same command again once it "
                              "has ended to assemble the video");
        std::this_thread::sleep_for(std::chrono::duration<double>(st.poll_seconds));
    }
    return Ok{};
}

// ssh hosts: GNU parallel runs one task per frame over --sshloginfile; the output directory
// must be the same path on every host (a shared filesystem).  What parallel reads as input is
// the frame numbers alone; the task's command is its arguments, quoted by parallel for each
// host's shell (-q), with every option of the task in hex (hosts_task_argv), and each task
// writes its own log (--task-log): no file name passes through a task line, a replacement
// string or a redirection.
Status run_hosts(const Animation& a, const std::vector<PlannedFrame>& todo, Progress& progress,
                 std::vector<std::string>& notes) {
    const fs::path dir = fs::path(a.options.out_dir) / "hosts";
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return make_error(dir.string() + ": cannot create: " + ec.message());
    std::string numbers;
    for (const auto& f : todo) numbers += std::to_string(f.number) + "\n";
    const std::string frames_file = (dir / "frames.txt").string();
    if (auto s = write_file_atomic(frames_file, numbers); !s) return s;
    const std::string log = (dir / "parallel.log").string();
    fs::remove(log, ec);
    std::vector<std::string> argv = {a.options.parallel,
                                     "--will-cite",
                                     "-q",
                                     "--sshloginfile",
                                     a.options.hosts_file,
                                     "--joblog",
                                     (dir / "joblog.txt").string(),
                                     "-a",
                                     frames_file};
    for (const auto& w : hosts_task_argv(a)) argv.push_back(w);
    auto run = run_process(argv, "", log);
    if (!run) return make_error("--hosts: " + run.message());
    progress.set_done(count_done(a));
    if (run->exit_code != 0) {
        // What parallel said (an unknown host, ssh refused) is in its log: said here too.
        const std::string said = escape_control(last_line(log));
        notes.push_back("GNU parallel exited with " + std::to_string(run->exit_code) + " (" + log +
                        ")" + (said.empty() ? std::string() : ": " + said));
        if (a.options.progress)
            std::cerr << "mirage animate: --hosts: GNU parallel exited with " << run->exit_code
                      << (said.empty() ? std::string() : ": " + said) << " (" << log << ")\n";
    }
    return Ok{};
}

// POV-Ray 3.7 stamps its PNGs with the time of the render (a tIME chunk and a "Comment" text
// chunk holding "Render Date: ..."); a frame is copied without them so that it has the same
// bytes wherever and whenever it was rendered.  The other chunks, the pixels' IDAT among
// them, are copied as they are.
Status copy_png_without_dates(const std::string& from, const std::string& to) {
    const std::string png = read_text(from);
    static const char kSignature[] = "\x89PNG\r\n\x1a\n";
    if (png.size() < 8 || png.compare(0, 8, kSignature, 8) != 0)
        return make_error(from + ": not a PNG file");
    std::string out = png.substr(0, 8);
    for (std::size_t i = 8; i + 12 <= png.size();) {
        const auto* b = reinterpret_cast<const unsigned char*>(png.data() + i);
        const std::size_t length = (std::size_t(b[0]) << 24) | (std::size_t(b[1]) << 16) |
                                   (std::size_t(b[2]) << 8) | std::size_t(b[3]);
        if (i + 12 + length > png.size()) return make_error(from + ": a PNG chunk is cut short");
        const std::string type = png.substr(i + 4, 4);
        const bool dated =
            type == "tIME" ||
            (type == "tEXt" && png.compare(i + 8, 8, std::string("Comment\0", 8)) == 0);
        if (!dated) out += png.substr(i, 12 + length);
        i += 12 + length;
    }
    return write_file_atomic(to, out);
}

double frame_seconds_from_record(const Animation& a, int number) {
    std::ifstream in(a.frame_stem(number) + ".json");
    if (!in) return 0.0;
    try {
        const auto j = nlohmann::json::parse(in);
        return j.value("compile_seconds", 0.0) + j.value("render_seconds", 0.0);
    } catch (...) {
        return 0.0;
    }
}

}  // namespace

std::string Animation::frame_stem(int number) const {
    char buf[32];
    std::snprintf(buf, sizeof buf, "frame_%0*d", width_digits, number);
    return (fs::path(frames_dir) / buf).string();
}

std::vector<std::string> Animation::task_argv(const std::string& frame) const {
    const AnimateOptions& o = options;
    std::vector<std::string> v = {o.self, "animate", o.scene};
    for (const auto& r : o.range_args) v.push_back(r);
    if (o.frames) v.insert(v.end(), {"--frames", std::to_string(*o.frames)});
    v.insert(v.end(), {"-W", std::to_string(o.width), "-H", std::to_string(o.height), "--model",
                       model_name(o.model), "-o", o.out_dir});
    if (o.tolerance_px) v.insert(v.end(), {"--tolerance", shortest(*o.tolerance_px)});
    for (const auto& l : o.library_paths) v.insert(v.end(), {"-L", l});
    v.insert(v.end(), {"--threads", std::to_string(o.threads)});
    if (!frame.empty()) v.insert(v.end(), {"--frame", frame});
    return v;
}

std::vector<std::string> hosts_task_argv(const Animation& a) {
    std::vector<std::string> task = a.task_argv("");
    const std::string self = task.front();
    task.erase(task.begin());
    task.push_back("--task-log");
    // GNU parallel appends the frame number read from its input after "--frame".
    return {self, "--args-hex", args_to_hex(task), "--frame"};
}

Result<Animation> resolve_animation(const AnimateOptions& options) {
    Animation a;
    a.options = options;
    AnimateOptions& o = a.options;
    std::error_code ec;
    if (o.scene.empty()) return make_error("give the scene: mirage animate SCENE.pov --frames N");
    if (!fs::is_regular_file(o.scene, ec)) return make_error(o.scene + ": no such scene file");
    o.scene = absolute(o.scene);
    a.name = fs::path(o.scene).stem().string();
    if (o.frames) {
        if (*o.frames < 1)
            return make_error("--frames " + std::to_string(*o.frames) + ": must be at least 1");
        if (*o.frames > kMaxAnimationFrames)
            return make_error("--frames " + std::to_string(*o.frames) + ": at most " +
                              std::to_string(kMaxAnimationFrames) + " frames");
        a.range.initial_frame = 1;
        a.range.final_frame = *o.frames;
        a.range.initial_frame_from = "--frames";
        a.range.final_frame_from = "--frames " + std::to_string(*o.frames) + ", Final_Frame";
    }
    bool ranged = o.frames.has_value();
    for (auto& arg : o.range_args) {
        if (ends_with_ini(arg)) {
            if (!fs::is_regular_file(arg, ec)) return make_error(arg + ": no such .ini file");
            arg = absolute(arg);
            if (auto s = read_animation_ini(arg, a.range, a.ignored); !s) return s.error();
            ranged = true;
            continue;
        }
        auto read = read_animation_option(arg, "", a.range);
        if (!read) return read.error();
        if (!*read)
            return make_error("'" + arg +
                              "': mirage animate reads the scene, .ini files and POV-Ray's "
                              "animation options (+KFI +KFF +KI +KF +SF +EF +KC +K, or "
                              "Initial_Frame=... and the like)");
        ranged = true;
    }
    if (!ranged)
        return make_error(
            "no frames given: --frames N, or a frame range (+KFF N, Final_Frame=N "
            "in an .ini)");
    auto plan = plan_frames(a.range);
    if (!plan) return plan.error();
    a.plan = std::move(*plan);
    if (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384)
        return make_error("image size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                          ": must be 1 to 16384 pixels each way");
    if (o.threads < 1 || o.threads > 1024)
        return make_error("--threads " + std::to_string(o.threads) + ": must be 1 to 1024");
    if (o.jobs < 0) return make_error("--jobs " + std::to_string(o.jobs) + ": must be >= 0");
    // They go into #SBATCH lines of the job's script: one word of Slurm's own characters.
    for (const auto& [flag, value] :
         {std::pair<const char*, const std::string&>{"--partition", o.slurm.partition},
          {"--time", o.slurm.time},
          {"--mem", o.slurm.mem}}) {
        if (value.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                    "0123456789:._,+-") != std::string::npos)
            return make_error(std::string(flag) + " '" + escape_control(value) +
                              "': Slurm takes letters, digits and : . _ , + - here");
    }
    if (!(o.fps > 0.0 && o.fps <= 240.0))
        return make_error("--fps " + shortest(o.fps) + ": must be above 0 and at most 240");
    if (o.preview_width < 16 || o.preview_width > 4096)
        return make_error("--preview-width " + std::to_string(o.preview_width) +
                          ": must be 16 to 4096 pixels");
    if (o.tolerance_px && !(*o.tolerance_px > 0.0 && std::isfinite(*o.tolerance_px)))
        return make_error("--tolerance " + shortest(*o.tolerance_px) + ": must be > 0 pixels");
    if (o.out_dir.empty()) o.out_dir = (fs::path("build") / "animate" / a.name).string();
    o.out_dir = absolute(o.out_dir);
    for (auto& l : o.library_paths) l = absolute(l);
    if (o.self.empty()) o.self = self_program();
    if (o.jobs == 0) {
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        o.jobs = std::max(1, static_cast<int>(cores) / o.threads);
    }
    a.frames_dir = (fs::path(o.out_dir) / "frames").string();
    int last = 0;
    for (const auto& f : a.plan.frames) last = std::max(last, f.number);
    a.width_digits = std::max(4, static_cast<int>(std::to_string(last).size()));
    return a;
}

Result<FrameRecord> render_frame(const Animation& a, int number) {
    const PlannedFrame* frame = nullptr;
    for (const auto& f : a.plan.frames)
        if (f.number == number) frame = &f;
    if (!frame)
        return make_error("--frame " + std::to_string(number) + ": not a frame of the animation (" +
                          std::to_string(a.plan.frames.front().number) + " to " +
                          std::to_string(a.plan.frames.back().number) + ")");
    const std::string label = frame_label(*frame);
    auto failed = [&](const std::string& why) { return make_error(label + ": " + why); };
    const AnimateOptions& o = a.options;
    // The frame's clock for every parse below (compile_scene and trace_scene parse the scene
    // with options of their own).
    ScopedAnimationClock clock(frame->clock);
    const fs::path work = a.frame_stem(number);
    std::error_code ec;
    fs::create_directories(work, ec);
    if (ec) return failed(work.string() + ": cannot create: " + ec.message());
    FrameRecord rec;
    rec.number = number;
    rec.clock = frame->clock.clock;
    rec.image = a.frame_image(number);
    std::string rendered;
    if (o.model == FrameModel::Bands) {
        CompileOptions co;
        co.scene = o.scene;
        co.width = o.width;
        co.height = o.height;
        co.out_dir = work.string();
        co.image = (work / "render.png").string();
        co.tolerance_px = o.tolerance_px;
        co.library_paths = o.library_paths;
        // A frame's report needs no sub-pixel samples, and the frames have their own bar.
        co.samples_per_side = 1;
        co.progress = false;
        auto compiled = compile_scene(co);
        if (!compiled) return failed("compile: " + compiled.message());
        rec.compile_seconds = compiled->seconds;
        rec.layers = compiled->layers;
        // POV-Ray splits an option at spaces unless its value is quoted (pov/povray_path.h).
        std::vector<std::string> argv = {o.povray, "-D", "+WT" + std::to_string(o.threads),
                                         povray_quoted(compiled->ini_path)};
        for (const auto& s : povray_frame_switches(a, *frame)) argv.push_back(s);
        argv.push_back("+O" + povray_quoted((work / "render.png").string()));
        const std::string log = (work / "povray.log").string();
        fs::remove(log, ec);
        auto run = run_process(argv, work.string(), log);
        if (!run) return failed(run.message());
        rec.render_seconds = run->seconds;
        // In an animation POV-Ray appends the frame number to the image's name.
        char suffix[32] = "";
        if (a.plan.animation) std::snprintf(suffix, sizeof suffix, "%0*d", a.plan.digits, number);
        rendered = (work / ("render" + std::string(suffix) + ".png")).string();
        if (run->exit_code != 0 || !fs::exists(rendered, ec))
            return failed("POV-Ray failed (exit " + std::to_string(run->exit_code) + ", " + log +
                          "): " + povray_failure_cause(log));
        if (compiled->camera == "corrected")
            if (auto s = crop_mesh_camera_render(rendered); !s) return failed(s.message());
        const std::string undated = (work / "frame.png").string();
        if (auto s = copy_png_without_dates(rendered, undated); !s) return failed(s.message());
        fs::remove(rendered, ec);
        rendered = undated;
    } else {
        TraceOptions to;
        to.scene = o.scene;
        to.output = (work / "render.png").string();
        to.width = o.width;
        to.height = o.height;
        to.tolerance_px = o.tolerance_px;
        to.threads = o.threads;
        to.library_paths = o.library_paths;
        to.progress = false;
        const auto t0 = std::chrono::steady_clock::now();
        auto traced = trace_scene(to);
        if (!traced) return failed("trace: " + traced.message());
        rec.render_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rendered = to.output;
    }
    nlohmann::json j;
    j["frame"] = number;
    j["clock"] = rec.clock;
    j["model"] = model_name(o.model);
    j["compile_seconds"] = rec.compile_seconds;
    j["render_seconds"] = rec.render_seconds;
    j["layers"] = rec.layers;
    j["command"] = join_command(a.task_argv(std::to_string(number)));
    if (auto s = write_file_atomic(a.frame_stem(number) + ".json", json_text(j) + "\n"); !s)
        return failed(s.message());
    // Last: the image under its final name marks the frame done.
    if (auto s = commit_file(rendered, rec.image); !s) return failed(s.message());
    return rec;
}

std::string slurm_array_list(const std::vector<int>& frames) {
    std::vector<int> f = frames;
    std::sort(f.begin(), f.end());
    f.erase(std::unique(f.begin(), f.end()), f.end());
    std::string s;
    for (std::size_t i = 0; i < f.size();) {
        std::size_t j = i;
        while (j + 1 < f.size() && f[j + 1] == f[j] + 1) ++j;
        if (!s.empty()) s += ",";
        s += std::to_string(f[i]);
        if (j > i) {
            s += '-';
            s += std::to_string(f[j]);
        }
        i = j + 1;
    }
    return s;
}

namespace {

/// A Slurm job name from the scene's name: letters, digits, '.', '_' and '-' (the rest '_').
std::string slurm_job_name(const std::string& name) {
    std::string s = "mirage-";
    for (unsigned char c : name) s += std::isalnum(c) || c == '.' || c == '-' ? char(c) : '_';
    return s;
}

/// A path in a Slurm file name pattern: '%' stands for itself as "%%".
std::string slurm_literal(const std::string& path) {
    std::string s;
    for (char c : path) s += c == '%' ? std::string("%%") : std::string(1, c);
    return s;
}

}  // namespace

std::string slurm_script(const Animation& a, const std::vector<int>& frames) {
    const SlurmSettings& st = a.options.slurm;
    // Only numbers and the checked resources go into #SBATCH lines; the job's name, its log
    // pattern and its directory, made of file names, are sbatch's arguments
    // (slurm_submit_argv), and the task's options are in hex.
    std::ostringstream s;
    s << "#!/bin/sh\n"
      << "# " << escape_control(a.name)
      << ": one task per frame, written by mirage animate --slurm.  Each task\n"
      << "# runs the command a local frame runs; its log is beside its frame (sbatch's --output).\n"
      << "#SBATCH --array=" << slurm_array_list(frames) << "\n"
      << "#SBATCH --ntasks=1\n"
      << "#SBATCH --cpus-per-task=" << a.options.threads << "\n"
      << "#SBATCH --mem=" << st.mem << "\n"
      << "#SBATCH --time=" << st.time << "\n";
    if (!st.partition.empty()) s << "#SBATCH --partition=" << st.partition << "\n";
    // The task's options in hex (as for --hosts): a line end in a name would otherwise be a
    // line of the script, which sbatch reads for #SBATCH directives of its own.
    std::vector<std::string> task = a.task_argv("");
    const std::string self = task.front();
    task.erase(task.begin());
    s << "# The task: " << escape_control(join_command(a.task_argv("")))
      << " --frame \"$SLURM_ARRAY_TASK_ID\"\n"
      << "exec " << shell_quote(self) << " --args-hex " << args_to_hex(task)
      << " --frame \"$SLURM_ARRAY_TASK_ID\"\n";
    return s.str();
}

std::vector<std::string> slurm_submit_argv(const Animation& a, const std::string& script) {
    const std::string log_pattern = slurm_literal((fs::path(a.frames_dir) / "frame_").string()) +
                                    "%" + std::to_string(a.width_digits) + "a.log";
    std::error_code ec;
    return {a.options.slurm.sbatch,
            "--parsable",
            "--job-name=" + slurm_job_name(a.name),
            "--output=" + log_pattern,
            "--chdir=" + fs::current_path(ec).string(),
            script};
}

Result<std::vector<VanishingRow>> vanishing_rows(const Animation& a) {
    std::vector<VanishingRow> rows;
    // Each frame's scene read as compile and trace read it: load/mirage_scene.h.
    SceneLoadOptions lo = scene_load_options(a.options.scene, a.options.width, a.options.height,
                                             a.options.library_paths);
    lo.strict = false;
    lo.object_queries = tracer_object_queries();
    VanishingCache cache;
    for (const auto& f : a.plan.frames) {
        lo.animation = f.clock;
        auto loaded = load_mirage_scene(lo);
        if (!loaded) return make_error(frame_label(f) + ": " + loaded.message());
        auto views = view_marked_spheres(loaded->scene, a.options.width, a.options.height, &cache);
        if (!views) return make_error(frame_label(f) + ": " + views.message());
        for (const auto& v : *views) rows.push_back({f.number, f.clock.clock, v});
    }
    return rows;
}

// What the run needs before any frame: POV-Ray's paths and program (the band model), ffmpeg,
// and the runner's programs and hosts.
Status check_tools_and_inputs(const AnimateOptions& o) {
    std::error_code ec;
    if (o.model == FrameModel::Bands) {
        // Every frame's .ini names these for POV-Ray: refused at once if it cannot take one.
        if (auto s = check_povray_path(o.scene, "the scene"); !s) return s.error();
        if (auto s = check_povray_path(o.out_dir, "the output folder (-o)"); !s) return s.error();
        for (const auto& l : o.library_paths)
            if (auto s = check_povray_path(l, "-L"); !s) return s.error();
    }
    if (o.model == FrameModel::Bands && !find_program(o.povray))
        return make_error(o.povray +
                          " is not on PATH: the band model renders with POV-Ray "
                          "(apt-get install povray, or --model trace)");
    if (!find_program(o.ffmpeg))
        return make_error(o.ffmpeg +
                          " is not on PATH: the frames could not be made into a "
                          "video (apt-get install ffmpeg)");
    if (o.runner == FrameRunner::Slurm) {
        if (!find_program(o.slurm.sbatch))
            return make_error("--slurm: " + o.slurm.sbatch +
                              " is not on PATH (run on the cluster's login node, or install "
                              "slurm-client)");
        if (!find_program(o.slurm.squeue))
            return make_error("--slurm: " + o.slurm.squeue + " is not on PATH");
    }
    if (o.runner == FrameRunner::Hosts) {
        if (!find_program(o.parallel))
            return make_error("--hosts: " + o.parallel +
                              " (GNU parallel) is not on PATH (apt-get install parallel)");
        if (!fs::is_regular_file(o.hosts_file, ec))
            return make_error("--hosts " + o.hosts_file + ": no such file");
        // GNU parallel runs an empty list of hosts on this machine, without a word.
        bool any = false;
        {
            std::istringstream lines(read_text(o.hosts_file));
            std::string line;
            while (!any && std::getline(lines, line)) {
                const auto at = line.find_first_not_of(" \t\r");
                any = at != std::string::npos && line[at] != '#';
            }
        }
        if (!any)
            return make_error("--hosts " + o.hosts_file +
                              ": names no host (one ssh login a line, ':' for this machine)");
        if (o.self.find('{') != std::string::npos)
            return make_error("--hosts: the path of mirage, " + o.self +
                              ", holds '{', which GNU parallel would replace");
    }
    return Ok{};
}

// What the frames are of, written to animation.json: a directory of another animation's
// frames (another scene, a changed scene, another frame command) is not reused.
Status claim_frames(const Animation& a) {
    const AnimateOptions& o = a.options;
    std::error_code ec;
    nlohmann::json what;
    what["scene"] = o.scene;
    what["scene_fingerprint"] = fingerprint(read_text(o.scene));
    what["frame_command"] = join_command(a.task_argv("N"));
    nlohmann::json clocks = nlohmann::json::array();
    for (const auto& f : a.plan.frames) clocks.push_back({f.number, f.clock.clock});
    what["frames"] = clocks;
    // As it reads back from the file (a name that is not UTF-8 is written with U+FFFD).
    what = nlohmann::json::parse(json_text(what));
    const std::string what_path = (fs::path(o.out_dir) / "animation.json").string();
    if (fs::exists(what_path, ec)) {
        nlohmann::json before;
        try {
            before = nlohmann::json::parse(read_text(what_path));
        } catch (...) {
        }
        for (const char* key : {"scene", "scene_fingerprint", "frame_command"}) {
            if (before.value(key, nlohmann::json()) != what[key])
                return make_error(
                    o.out_dir + " holds the frames of another animation (its " + key +
                    (std::string(key) == "scene_fingerprint"
                         ? ": the scene has changed since"
                         : " was " + json_text(before.value(key, nlohmann::json()), -1)) +
                    "): choose another -o, or remove " + a.frames_dir + " to render them again");
        }
    }
    return write_file_atomic(what_path, json_text(what) + "\n");
}

// The summary and the report of the marked objects (an addition: when it cannot be made, a
// scene whose atmosphere is not an inferior mirage, the frames and the video stand and a note
// says why).
Status write_summary(const Animation& a, AnimateReport& rep) {
    const AnimateOptions& o = a.options;
    auto rows = vanishing_rows(a);
    if (!rows) {
        rep.notes.push_back("no vanishing report: " + rows.message());
        rows = std::vector<VanishingRow>{};
    }
    AnimationSummary sum;
    sum.name = a.name;
    sum.scene = o.scene;
    sum.model = model_name(o.model);
    sum.width = o.width;
    sum.height = o.height;
    sum.runner = o.runner == FrameRunner::Local   ? "local, " + std::to_string(o.jobs) + " at once"
                 : o.runner == FrameRunner::Slurm ? "Slurm array job"
                                                  : "GNU parallel over " + o.hosts_file;
    sum.threads = o.threads;
    sum.frames_seconds = rep.frames_seconds;
    sum.assemble_seconds = rep.assemble_seconds;
    sum.out_dir = o.out_dir;
    sum.gnuplot = o.gnuplot;
    const MachineInfo m = read_machine_info();
    sum.machine = std::to_string(m.cores) + " cores, " + m.cpu + ", load " + m.load;
    sum.frame_command = join_command(a.task_argv("N"));
    for (const auto& f : rep.frames)
        sum.frames.push_back({f.number, f.clock, f.seconds, f.rendered_now});
    auto written = write_animation_report(sum, *rows);
    if (!written) return written.error();
    rep.vanishing_csv = written->csv;
    rep.vanishing_png = written->png;
    rep.vanishing_svg = written->svg;
    rep.summary = written->summary;
    for (const auto& n : written->notes) rep.notes.push_back(n);
    return Ok{};
}
Result<AnimateReport> run_animation(const AnimateOptions& options) {
    auto resolved = resolve_animation(options);
    if (!resolved) return resolved.error();
    const Animation& a = *resolved;
    const AnimateOptions& o = a.options;
    AnimateReport rep;
    std::error_code ec;

    // Everything that could stop the run before a frame is rendered is checked first.
    if (auto s = check_tools_and_inputs(o); !s) return s.error();
    // Taken away again (if empty) when the run is refused before animation.json is written.
    NewDirectories folders;
    if (auto s = folders.make(a.frames_dir); !s)
        return make_error(o.out_dir + ": cannot create the output directory: " + s.message());
    {
        const std::string probe = temporary_name_for((fs::path(a.frames_dir) / "probe").string());
        std::ofstream p(probe);
        const bool writable = static_cast<bool>(p << "probe\n");
        p.close();
        fs::remove(probe, ec);
        if (!writable) return make_error(o.out_dir + ": cannot write in the output directory");
    }

    if (auto s = claim_frames(a); !s) return s.error();
    folders.keep();
    for (const auto& i : a.ignored) rep.notes.push_back(i + ": not an animation option, ignored");

    std::vector<PlannedFrame> todo;
    for (const auto& f : a.plan.frames)
        if (!fs::exists(a.frame_image(f.number), ec)) todo.push_back(f);
    if (o.progress) {
        std::cerr << "mirage animate: " << a.name << ", " << a.plan.frames.size() << " frames at "
                  << o.width << "x" << o.height << ", " << model_name(o.model) << " model";
        if (todo.size() < a.plan.frames.size())
            std::cerr << " (" << a.plan.frames.size() - todo.size() << " done before)";
        std::cerr << "\n";
    }
    Progress progress(o.progress, static_cast<int>(a.plan.frames.size()));
    progress.set_done(static_cast<int>(a.plan.frames.size() - todo.size()));
    const auto t0 = std::chrono::steady_clock::now();
    std::map<int, double> seconds;
    if (!todo.empty()) {
        if (o.runner == FrameRunner::Local) {
            for (const auto& t : run_local(a, todo, o.jobs, progress))
                seconds[t.number] = t.seconds;
        } else if (o.runner == FrameRunner::Slurm) {
            auto s = run_slurm(a, todo, progress, rep.notes);
            progress.finish();
            if (!s) return s.error();
        } else {
            auto s = run_hosts(a, todo, progress, rep.notes);
            progress.finish();
            if (!s) return s.error();
        }
    }
    progress.finish();
    rep.frames_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::set<int> now;
    for (const auto& f : todo) now.insert(f.number);
    for (const auto& f : a.plan.frames) {
        FrameTiming t;
        t.number = f.number;
        t.clock = f.clock.clock;
        t.rendered_now = now.count(f.number) > 0;
        t.seconds =
            seconds.count(f.number) ? seconds[f.number] : frame_seconds_from_record(a, f.number);
        rep.frames.push_back(t);
        if (!fs::exists(a.frame_image(f.number), ec)) {
            const std::string log = a.frame_stem(f.number) + ".log";
            const std::string why = last_line(log);
            const std::string label = frame_label(f);
            std::string reason = why.empty() ? "no image and no log (" + log + ")" : why;
            if (reason.rfind(label + ": ", 0) == 0) reason = reason.substr(label.size() + 2);
            rep.failures.push_back(label + " failed: " + reason + " (log: " + log + ")");
        }
    }
    if (!rep.failures.empty()) {
        std::string msg = std::to_string(rep.failures.size()) + " of " +
                          std::to_string(a.plan.frames.size()) +
                          " frames failed (the others are kept; run again to retry):";
        for (const auto& f : rep.failures) msg += "\n  " + f;
        return make_error(msg);
    }

    const auto t1 = std::chrono::steady_clock::now();
    VideoSettings vs;
    vs.ffmpeg = o.ffmpeg;
    vs.pattern =
        (fs::path(a.frames_dir) / ("frame_%0" + std::to_string(a.width_digits) + "d.png")).string();
    vs.first_number = a.plan.frames.front().number;
    vs.frame_count = static_cast<int>(a.plan.frames.size());
    vs.fps = o.fps;
    vs.preview_width = o.preview_width;
    vs.video = (fs::path(o.out_dir) / (a.name + ".mp4")).string();
    vs.preview = (fs::path(o.out_dir) / (a.name + ".gif")).string();
    vs.log = (fs::path(o.out_dir) / "ffmpeg.log").string();
    if (auto s = assemble_video(vs); !s) return s.error();
    rep.video = vs.video;
    rep.preview = vs.preview;
    rep.assemble_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

    if (auto s = write_summary(a, rep); !s) return s.error();
    return rep;
}

}  // namespace mirage
