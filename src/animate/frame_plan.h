// The frames of an animation as POV-Ray 3.7 numbers them and clocks them: the range options
// (Initial_Frame / +KFI, Final_Frame / +KFF, Initial_Clock / +KI, Final_Clock / +KF,
// Subset_Start_Frame / +SF, Subset_End_Frame / +EF, Cyclic_Animation / +KC, Clock / +K)
// read from .ini files and command-line switches, and every frame's clock, clock_delta,
// frame_number, ... computed with the formulas of POV-Ray's front end
// (source/frontend/animationprocessing.cpp, vfe/vfe.cpp), single-precision roundings included.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/animation_clock.h"
#include "util/result.h"

namespace mirage {

/// The most frames one animation may have.
constexpr int kMaxAnimationFrames = 100000;

/// POV-Ray's animation options as given; unset ones take POV-Ray's defaults.
struct AnimationRange {
    std::optional<int> initial_frame, final_frame;     // +KFI, +KFF
    std::optional<double> initial_clock, final_clock;  // +KI, +KF
    std::optional<double> clock;                       // +K: the clock of a still
    std::optional<double> subset_start, subset_end;    // +SF, +EF (a fraction when in (0, 1))
    bool cyclic = false;                               // +KC
    // Where each value came from ("walk.ini:3", "+KFF"), for messages.
    std::string initial_frame_from = "Initial_Frame", final_frame_from = "Final_Frame";
    std::string subset_start_from = "Subset_Start_Frame", subset_end_from = "Subset_End_Frame";
};

/// One frame: its number (what POV-Ray's output names carry) and what the scene sees.
struct PlannedFrame {
    int number = 0;
    AnimationClock clock;
};

struct FramePlan {
    bool animation = false;            // false: a still (POV-Ray's frame range 0-0 or 1-1)
    int digits = 1;                    // of the frame numbers in POV-Ray's output names
    std::vector<PlannedFrame> frames;  // in rendering order
};

/// The frames POV-Ray 3.7 renders for these options.  Where POV-Ray would clamp silently
/// or divide by zero (a subset outside the range, Final_Frame before Initial_Frame, a range
/// of one frame), this is an error naming the option and its value; so is an animation of
/// more than kMaxAnimationFrames frames.
Result<FramePlan> plan_frames(const AnimationRange& range);

/// Reads one option into `range`: an INI line ("Final_Frame=10", "Initial_Clock = 0.5") or a
/// switch ("+KFF10", "+KI0.5", "+SF0.5", "+KC", "-KC").  Names are case-insensitive, as in
/// POV-Ray.  Returns false (and leaves `range` alone) for an option that is not about the
/// animation; an error for an animation option with a bad value.  `where` names its place.
Result<bool> read_animation_option(const std::string& option, const std::string& where,
                                   AnimationRange& range);

/// Reads the animation options of an INI file (up to its first [section] label, as POV-Ray
/// reads a file given without a section).  Other options are listed in `ignored` as
/// "file:line: Name".
Status read_animation_ini(const std::string& path, AnimationRange& range,
                          std::vector<std::string>& ignored);

/// A clock as text that reads back as the same single-precision value (9 digits).
std::string clock_text(double clock);

}  // namespace mirage
