// POV-Ray 3.7's pattern functions (pattern/pattern.cpp Evaluate_TPat): the value of a
// pattern at a point of its own space (already through the warp chain), then its frequency,
// phase and wave type.  The scene-wide inputs (noise generator, wave sources) come in a
// PatternContext.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "patterns/noise.h"

namespace mirage {

/// What the pattern functions need from the scene.
struct PatternContext {
    int noise_generator = 2;             // global_settings' noise_generator
    const WaveSources* waves = nullptr;  // the waves and ripples patterns' sources
    glm::dvec3 normal{0.0};              // the surface normal at the point (slope), facing the ray
    glm::dvec3 point{0.0};               // the surface point in world space (slope with point_at)
};

/// The default context: generator 2 and POV-Ray's 10 wave sources.
const PatternContext& default_pattern_context();

/// The pattern's value before the wave is applied (POV-Ray's xxx_pattern functions), at a
/// point of the pattern's space.  Usually in [0, 1]; the list patterns give their entry
/// index (hexagon 0 to 2, brick and checker 0 or 1...).
double raw_pattern_value(const Pattern& pattern, const glm::dvec3& p, const PatternContext& ctx);

/// POV-Ray's Evaluate_TPat: the raw value, then `frequency` and `phase` (unless the pattern
/// sets frequency 0, as the list patterns do), then the wave type.
double evaluate_pattern(const Pattern& pattern, const glm::dvec3& p, const PatternContext& ctx);

/// The noise generator that applies to a pattern: its own, else the scene's.
inline int pattern_noise_generator(const Pattern& pattern, const PatternContext& ctx) {
    return pattern.noise_generator != 0 ? pattern.noise_generator : ctx.noise_generator;
}

/// Whether POV-Ray evaluates this pattern with a dedicated normal function instead of the
/// finite difference of its values (bumps, dents, ripples, waves, wrinkles, quilted, facets,
/// image maps, average).
bool is_normal_only_pattern(PatternKind kind);

/// POV-Ray's quilt_cubic (the quilted pattern's profile).
double quilt_cubic(double t, double p1, double p2);

}  // namespace mirage
