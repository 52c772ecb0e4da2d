// Running another program (POV-Ray, gnuplot) from library code: found on PATH, started in a
// chosen directory with its output sent to a log file, timed by the wall clock.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "util/result.h"

namespace mirage {

/// The full path of `program` as the shell would find it on PATH (or `program` itself when it
/// names a path with a slash and is executable); nothing when there is none.
std::optional<std::string> find_program(const std::string& program);

struct ProcessRun {
    int exit_code = -1;    // the program's exit status; -1 when a signal ended it
    double seconds = 0.0;  // wall-clock time from start to exit
    double cpu_seconds = 0.0;  // processor time (user + system) of the program and its threads
};

/// Runs argv[0] (looked up on PATH) with the arguments argv[1..] in `work_dir` (empty: the
/// current directory), standard output and error both appended to `log_path` (empty: both
/// discarded), and waits for it.  An error means it could not be started; a program that
/// ran and failed is a ProcessRun with a non-zero exit code.
Result<ProcessRun> run_process(const std::vector<std::string>& argv, const std::string& work_dir,
                               const std::string& log_path);

}  // namespace mirage
