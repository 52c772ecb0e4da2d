// Drawing a plot with gnuplot from library code: the script written under a temporary name
// beside the plot, run, and removed; a failure reported with gnuplot's own log.
#pragma once

#include <string>
#include <vector>

#include "util/result.h"

namespace mirage {

/// `s` as a double-quoted gnuplot string that gnuplot reads back as `s`: backslashes and double
/// quotes escaped, and line breaks and tabs written as escapes (a raw line break would end the
/// command).  For file names in a script as well as titles.
std::string gnuplot_quoted(const std::string& s);

/// Runs `gnuplot` on `script`, written beside `anchor` (the plot's target path) under a
/// temporary name and removed afterwards.  The script writes the files `expected` (absolute
/// paths, usually an OutputSet's temporary names): a failure to start, a non-zero exit or a
/// missing file is an error carrying gnuplot's log.  gnuplot not on PATH is an error naming
/// `what` it would have drawn.
Status run_gnuplot(const std::string& gnuplot, const std::string& script, const std::string& anchor,
                   const std::vector<std::string>& expected, const std::string& what);

}  // namespace mirage
