// `mirage animate SCENE.pov --frames N`: every frame of an animated scene rendered (locally,
// on a Slurm cluster or on ssh hosts), the video assembled, the vanishing reported.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <memory>

#include "animate/animate.h"
#include "cli/commands.h"
#include "util/format.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

struct AnimateCliOptions {
    AnimateOptions animate;
    std::vector<std::string> args;  // the scene, then .ini files and POV-Ray options
    int frames = 0;
    double tolerance = 0.0;
    std::string model = "bands";
    bool slurm = false, quiet = false;
    int frame = 0;          // the task of one frame (what every runner starts)
    bool task_log = false;  // the task writes its output into its frame's log
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "mirage animate: " << escape_terminal(message) << "\n";
    throw CommandFailed{1};
}

}  // namespace

void setup_animate_command(CLI::App& app) {
    auto o = std::make_shared<AnimateCliOptions>();
    auto* sub = app.add_subcommand(
        "animate",
        "Render every frame of an animated scene (POV-Ray's clock), make a video, report where "
        "the mirage vanishes");
    sub->add_option("args", o->args,
                    "SCENE.pov, then .ini files and POV-Ray animation options (+KFI +KFF +KI +KF "
                    "+SF +EF +KC +K, Final_Frame=N ...)")
        ->required();
    sub->allow_extras();
    auto* frames = sub->add_option("--frames", o->frames,
                                   "frames 1 to N, the clock from 0 to 1 (POV-Ray's +KFF N)");
    sub->add_option("-W,--width", o->animate.width, "image width, pixels")->capture_default_str();
    sub->add_option("-H,--height", o->animate.height, "image height, pixels")
        ->capture_default_str();
    sub->add_option("--model", o->model,
                    "bands: compile every frame and render it with POV-Ray; trace: the built-in "
                    "tracer along the exact paths")
        ->check(CLI::IsMember({"bands", "trace"}))
        ->capture_default_str();
    sub->add_option("-o,--output", o->animate.out_dir,
                    "output directory (default build/animate/NAME)")
        ->check(non_empty_name());
    auto* tol = sub->add_option("--tolerance", o->tolerance,
                                "largest path error, pixels (default: the scene's)");
    sub->add_option("-L,--library-path", o->animate.library_paths,
                    "extra include directory (searched first)");
    sub->add_option("--threads", o->animate.threads,
                    "threads per frame (POV-Ray +WT, the tracer; Slurm --cpus-per-task)")
        ->capture_default_str();
    sub->add_option("--jobs", o->animate.jobs,
                    "frames at once on this machine (default: its cores / --threads)");
    sub->add_option("--fps", o->animate.fps, "frames per second of the video")
        ->capture_default_str();
    sub->add_option("--preview-width", o->animate.preview_width, "width of the GIF, pixels")
        ->capture_default_str();
    sub->add_flag("--slurm", o->slurm,
                  "submit the frames as a Slurm array job (sbatch --array), wait for it, then "
                  "assemble");
    sub->add_option("--partition", o->animate.slurm.partition, "Slurm partition");
    sub->add_option("--time", o->animate.slurm.time, "Slurm time limit per frame")
        ->capture_default_str();
    sub->add_option("--mem", o->animate.slurm.mem, "Slurm memory per frame")->capture_default_str();
    sub->add_option("--slurm-timeout", o->animate.slurm.timeout_seconds,
                    "stop waiting for the Slurm job after this many seconds")
        ->capture_default_str();
    sub->add_option("--slurm-poll", o->animate.slurm.poll_seconds,
                    "seconds between looks at squeue")
        ->capture_default_str();
    sub->add_option("--hosts", o->animate.hosts_file,
                    "run the frames on these hosts with GNU parallel (--sshloginfile; the output "
                    "directory must be shared)")
        ->check(non_empty_name());
    sub->add_flag("-q,--quiet", o->quiet, "print nothing but errors");
    auto* frame = sub->add_option("--frame", o->frame, "render this frame only (a task)");
    frame->group("");  // hidden: what the runners start
    sub->add_flag("--task-log", o->task_log, "write the frame's output into its log")->group("");
    sub->callback([o, sub, frames, tol, frame] {
        AnimateOptions a = o->animate;
        if (o->args.empty()) fail("give the scene: mirage animate SCENE.pov --frames N");
        a.scene = o->args.front();
        a.range_args.assign(o->args.begin() + 1, o->args.end());
        // What CLI11 does not know ("-KC") is a POV-Ray option too.
        for (const auto& extra : sub->remaining()) a.range_args.push_back(extra);
        if (*frames) a.frames = o->frames;
        if (*tol) a.tolerance_px = o->tolerance;
        a.model = o->model == "trace" ? FrameModel::Trace : FrameModel::Bands;
        if (o->slurm && !a.hosts_file.empty()) fail("--slurm and --hosts: choose one");
        a.runner = o->slurm                ? FrameRunner::Slurm
                   : !a.hosts_file.empty() ? FrameRunner::Hosts
                                           : FrameRunner::Local;
        a.progress = !o->quiet;
        if (*frame) {
            auto anim = resolve_animation(a);
            if (!anim) fail(anim.message());
            if (o->task_log) {
                // Started by GNU parallel (--hosts): no shell redirects the output.
                const std::string log = anim->frame_stem(o->frame) + ".log";
                const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
                if (fd < 0) fail(log + ": cannot write: " + std::strerror(errno));
                std::cout.flush();
                ::dup2(fd, STDOUT_FILENO);
                ::dup2(fd, STDERR_FILENO);
                ::close(fd);
            }
            auto rec = render_frame(*anim, o->frame);
            if (!rec) fail(rec.message());
            std::cout << "frame " << rec->number << " (clock " << clock_text(rec->clock) << "): ";
            if (a.model == FrameModel::Bands)
                std::cout << rec->layers << " layers, compile " << sig(rec->compile_seconds, 3)
                          << " s, POV-Ray ";
            std::cout << sig(rec->render_seconds, 3) << " s -> " << rec->image << "\n";
            return;
        }
        auto report = run_animation(a);
        if (!report) fail(report.message());
        if (o->quiet) return;
        for (const auto& n : report->notes) std::cout << "note: " << n << "\n";
        std::cout << "frames   " << report->frames.size() << " in "
                  << sig(report->frames_seconds, 4) << " s\n"
                  << "video    " << report->video << "\n"
                  << "preview  " << report->preview << "\n"
                  << "report   " << report->summary << "\n";
        if (!report->vanishing_png.empty())
            std::cout << "plot     " << report->vanishing_png << "\n";
    });
}

}  // namespace mirage
