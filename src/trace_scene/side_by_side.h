// `mirage trace --side-by-side`: the scene traced without its atmosphere and with it, the two
// pictures in one image, left and right, each labelled under it.
#pragma once

#include <string>

#include "trace_scene/trace_scene.h"
#include "util/result.h"

namespace mirage {

struct SideBySideReport {
    TraceReport without;  // straight rays (the atmosphere off)
    TraceReport with;     // the scene's atmosphere
    std::string font;     // the labels' font; empty: none found, the halves are unlabelled
    std::string output;   // the file written
    int left_x = 0;       // where each picture starts in the image, pixels from the top-left
    int right_x = 0;
    int top_y = 0;
};

/// The labels under the halves.
inline constexpr const char* kWithoutMirageLabel = "without mirage";
inline constexpr const char* kWithMirageLabel = "with mirage";

/// Traces `options.scene` twice (options.atmosphere ignored) and writes one 8-bit PNG to
/// options.output: the picture without the atmosphere on the left, with it on the right, each
/// exactly as `mirage trace` writes it.  Refuses a scene whose atmosphere bends no ray (both
/// halves would be the same), an output that is not a PNG, and what trace_scene refuses.
Result<SideBySideReport> trace_side_by_side(const TraceOptions& options);

/// What was traced, both statistics lines and the file written (with a note when the halves
/// could not be labelled).
std::string side_by_side_summary(const SideBySideReport& report);

}  // namespace mirage
