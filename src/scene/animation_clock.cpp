#include "scene/animation_clock.h"

namespace mirage {

namespace {
thread_local AnimationClock current_clock;
}  // namespace

const AnimationClock& thread_animation_clock() { return current_clock; }

ScopedAnimationClock::ScopedAnimationClock(const AnimationClock& clock) : saved_(current_clock) {
    current_clock = clock;
}

ScopedAnimationClock::~ScopedAnimationClock() { current_clock = saved_; }

}  // namespace mirage
