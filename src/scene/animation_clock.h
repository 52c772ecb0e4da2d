// The values of POV-Ray 3.7's animation identifiers for the frame being parsed: `clock` and
// `clock_on` (reserved words) and the six identifiers its front end declares for every
// parse (clock_delta, final_clock, final_frame, frame_number, initial_clock, initial_frame).
// How a frame's values follow from an animation's range is src/animate/frame_plan.h.
#pragma once

namespace mirage {

/// One frame's animation identifiers.  The default is what POV-Ray 3.7 (Unix front end,
/// vfe/vfe.cpp) gives a still: clock 0, clock_on 0, the other six declared as 0.
/// The values are the ones the scene sees (src/animate/frame_plan.cpp rounds them as POV-Ray's
/// front end does); frame numbers are held as POV-Ray declares them, as numbers.
struct AnimationClock {
    double clock = 0.0;     // `clock`
    bool clock_on = false;  // `clock_on`: a clock was given (+K, Clock=, or an animation)
    double clock_delta = 0.0;
    double initial_clock = 0.0, final_clock = 0.0;
    double initial_frame = 0.0, final_frame = 0.0, frame_number = 0.0;
};

/// The clock a parse on this thread sees when its ParseOptions set none: the still above,
/// or the frame of the innermost ScopedAnimationClock.  It lets a caller give a frame's
/// clock to library calls that parse a scene with options of their own (compile_scene,
/// trace_scene), the way POV-Ray's front end gives it to its parser.
const AnimationClock& thread_animation_clock();

/// Sets this thread's animation clock for its lifetime.
class ScopedAnimationClock {
  public:
    explicit ScopedAnimationClock(const AnimationClock& clock);
    ~ScopedAnimationClock();
    ScopedAnimationClock(const ScopedAnimationClock&) = delete;
    ScopedAnimationClock& operator=(const ScopedAnimationClock&) = delete;

  private:
    AnimationClock saved_;
};

}  // namespace mirage
