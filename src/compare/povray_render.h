// One POV-Ray render of a compiled scene, timed: the process run from its .ini in a working
// directory, its console output kept in a log, and the figures POV-Ray prints about itself
// (trace time, threads, CPU time, deepest trace level) read back from that log.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "util/result.h"

namespace mirage {

/// What POV-Ray 3.7 says about a render at the end of its console output.
struct PovrayLog {
    std::string version;                  // "3.7.0.10.unofficial"
    std::optional<double> trace_seconds;  // "Trace Time: ... (3.601 seconds)"
    std::optional<double> cpu_seconds;    // "using 2 thread(s) with 3.599 CPU-seconds total"
    int threads = 0;                      // of the render (the line after Trace Time)
    std::optional<int> max_level;         // "Max Level: 166/256"
};

/// Reads the figures above from POV-Ray's console text; what is missing stays empty.
PovrayLog parse_povray_log(std::string_view text);

struct PovrayRenderSettings {
    std::string povray = "povray";  // the program, looked up on PATH
    std::string ini;                // the .ini written by mirage compile
    std::string work_dir;           // POV-Ray runs here (its I/O restrictions allow writing
                                    // only below its working directory)
    std::string log;                // console output goes here (replaced)
    std::string output;             // overrides the .ini's image (+O); empty: the .ini's
    int threads = 0;                // render threads (+WT); 0: POV-Ray's default (all cores)
    // After a render that succeeded, the image whose top row to drop: a corrected camera's
    // .ini renders one row more (pov/emit_camera.h).  Empty: none.
    std::string crop_top_row;
};

struct PovrayRender {
    int exit_code = 0;
    double seconds = 0.0;  // wall-clock time of the whole process
    // Processor time (user + system, all threads) of the whole process: start, parse,
    // bounding, trace and writing the image, without the wall clock's idle waits (POV-Ray 3.7
    // spends about 0.6 s of wall-clock time on a 1x1 image while using 0.01 s of processor).
    double process_cpu_seconds = 0.0;
    PovrayLog log;
};

/// Renders; an error means POV-Ray could not be started (a render that failed is an exit
/// code).  Runs with -D (no display) beside the .ini, which decides everything else; an
/// `output` given is passed as +O after it.  POV-Ray appends ".png" to an output name that
/// does not end in it.
Result<PovrayRender> render_povray(const PovrayRenderSettings& settings);

/// Why a render failed, from its log: POV-Ray's first error line ("Parse Error: Cannot open
/// input file."), else the log's last line.
std::string povray_failure_cause(const std::string& log_path);

/// The last `lines` lines of a log file, for a message about a failed render.
std::string log_tail(const std::string& path, int lines);

}  // namespace mirage
