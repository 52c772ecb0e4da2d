// `mirage animate`: every frame of an animated scene compiled and rendered with POV-Ray (the
// band model) or traced along the exact paths, on all local cores, on a Slurm cluster or on
// ssh hosts through GNU parallel; then the frames assembled into an H.264 video and a small
// looping GIF, and a report of the marked objects' mirrored images frame by frame.
//
// Every frame is one task, `mirage animate <the same options> --frame N`, whichever runner
// starts it, so a frame has the same bytes wherever it ran.  A frame is done when its image
// exists (written under a temporary name and renamed); a rerun renders only what is missing.
//
// The output directory holds:
//   animation.json           what the frames are of (a rerun with other settings is refused)
//   frames/frame_NNNN.png    the frames; .log beside each (its task's output), .json (times)
//   frames/frame_NNNN/       the band model's compiled scene for the frame
//   NAME.mp4, NAME.gif       the video and its preview
//   vanishing.csv/.png/.svg  the marked objects' mirrored images against distance
//   report.json, summary.md  frames, times, how it ran
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "animate/animate_report.h"
#include "animate/frame_plan.h"
#include "animate/marked.h"
#include "util/result.h"

namespace mirage {

enum class FrameModel { Bands, Trace };

enum class FrameRunner { Local, Slurm, Hosts };

struct SlurmSettings {
    std::string partition;          // --partition (empty: the cluster's default)
    std::string time = "01:00:00";  // --time per task
    std::string mem = "2G";         // --mem per task
    std::string sbatch = "sbatch", squeue = "squeue";
    double poll_seconds = 2.0;         // between looks at squeue
    double timeout_seconds = 86400.0;  // give up waiting after this long (the job goes on)
};

struct AnimateOptions {
    std::string scene;
    // .ini files, POV-Ray switches (+KFI1 +KFF24 +KI0 +KF1 +SF3 +EF5 +KC +K0.5) and INI
    // options (Final_Frame=24), read in this order after --frames.
    std::vector<std::string> range_args;
    std::optional<int> frames;  // --frames N: Initial_Frame 1, Final_Frame N
    int width = 320, height = 240;
    FrameModel model = FrameModel::Bands;
    std::string out_dir;  // default build/animate/NAME
    std::optional<double> tolerance_px;
    std::vector<std::string> library_paths;
    int threads = 1;  // per frame (POV-Ray +WT, the tracer's threads, Slurm --cpus-per-task)
    int jobs = 0;     // frames at once on this machine; 0: its cores / threads
    double fps = 12.0;
    int preview_width = 160;  // pixels of the GIF
    FrameRunner runner = FrameRunner::Local;
    SlurmSettings slurm;
    std::string hosts_file;  // GNU parallel --sshloginfile (FrameRunner::Hosts)
    std::string povray = "povray", ffmpeg = "ffmpeg", gnuplot = "gnuplot", parallel = "parallel";
    std::string self;      // the mirage program the frame tasks run (default: this one)
    bool progress = true;  // a progress bar (on a terminal) and a line per frame on stderr
};

/// The options made absolute and checked, with the frames they give.
struct Animation {
    AnimateOptions options;  // paths absolute
    std::string name;        // the scene's name, without directory and extension
    AnimationRange range;
    FramePlan plan;
    std::string frames_dir;
    int width_digits = 4;              // of the frame numbers in file names
    std::vector<std::string> ignored;  // .ini options that are not about the animation

    std::string frame_stem(int number) const;  // frames_dir/frame_NNNN
    std::string frame_image(int number) const { return frame_stem(number) + ".png"; }
    /// The command line of the task that renders frame `number` (`frame` empty: the line
    /// without the frame, for scripts that append it).
    std::vector<std::string> task_argv(const std::string& frame) const;
};

/// Reads and checks the options: the scene and .ini files readable, the frame range as POV-Ray
/// numbers it (an error names the value for a range with no frames, 0 or too many frames),
/// the sizes and counts in range.  Touches no file.
Result<Animation> resolve_animation(const AnimateOptions& options);

/// What one frame's task did.
struct FrameRecord {
    int number = 0;
    double clock = 0.0;
    double compile_seconds = 0.0;  // band model
    double render_seconds = 0.0;   // POV-Ray's whole process, or the tracer's call
    int layers = 0;                // band model
    std::string image;
};

/// Renders one frame: the scene parsed with the frame's clock, compiled and rendered by
/// POV-Ray with the same clock (bands) or traced (trace); the image written last, through a
/// temporary name.  An error says which frame, its clock and why.
Result<FrameRecord> render_frame(const Animation& animation, int number);

struct FrameTiming {
    int number = 0;
    double clock = 0.0;
    double seconds = 0.0;  // the task's wall time, as the runner saw it (0: done before)
    bool rendered_now = false;
};

struct AnimateReport {
    std::vector<FrameTiming> frames;
    std::vector<std::string> failures;  // "frame 5 (clock 0.571429): why"
    double frames_seconds = 0.0;        // wall time of rendering the missing frames
    double assemble_seconds = 0.0;
    std::string video, preview, vanishing_csv, vanishing_png, vanishing_svg, summary;
    std::vector<std::string> notes;  // what could not be done and why
};

/// Renders the missing frames with the chosen runner, then (when every frame is there)
/// assembles the video and writes the report.  Frames that failed are named in `failures`
/// and in the error; the frames done are kept.
Result<AnimateReport> run_animation(const AnimateOptions& options);

/// The marked spheres of every frame, as the report has them (one row per frame and sphere).
Result<std::vector<VanishingRow>> vanishing_rows(const Animation& animation);

/// The Slurm batch script of an array job rendering `frames` (one task per frame).
std::string slurm_script(const Animation& animation, const std::vector<int>& frames);

/// How the script is submitted: sbatch with the job's name, its log pattern and its directory
/// as arguments (file names never go into a line of the script).
std::vector<std::string> slurm_submit_argv(const Animation& animation, const std::string& script);

/// The command GNU parallel starts for a frame on an ssh host, the frame number to be
/// appended: `mirage --args-hex HEX --frame`, HEX the task's arguments (task_argv) and
/// `--task-log` (the task writes its output to its frame's log itself).
std::vector<std::string> hosts_task_argv(const Animation& animation);

/// "1-4,7,9-10": the --array list of frame numbers (sorted, distinct).
std::string slurm_array_list(const std::vector<int>& frames);

}  // namespace mirage
