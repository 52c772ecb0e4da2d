// POV-Ray 3.7's solid noise (texture.cpp): Perlin-style lattice noise over its own hash
// table and random table (noise_generator 1 and 2), the gradient noise of generator 3, the
// vector-valued DNoise, fractal turbulence, the cycloidal and triangle waves, the pattern
// random sequence (a Mersenne twister's first 32768 draws) and the wave sources of the
// waves and ripples patterns.  All in double precision with POV-Ray's integer hashing, so
// values are the ones POV-Ray computes, bit for bit on the same floating-point hardware.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace mirage {

/// POV-Ray's Noise: a value in [0, 1] at `p`.  `generator` is 1 (the original, range folded
/// into [0, 1] by clipping), 2 (rescaled to fill [0, 1], POV-Ray's default) or 3 (gradient
/// noise).
double noise(const glm::dvec3& p, int generator);

/// POV-Ray's DNoise: a vector-valued noise in roughly [-1, 1] per component.
glm::dvec3 dnoise(const glm::dvec3& p);

/// POV-Ray's Turbulence: `octaves` of noise at frequencies multiplied by `lambda` and
/// amplitudes by `omega` (the turbulence amount is not applied here).
double turbulence(const glm::dvec3& p, const Turbulence& turb, int generator);

/// POV-Ray's DTurbulence: the same with DNoise.
glm::dvec3 dturbulence(const glm::dvec3& p, const Turbulence& turb);

/// POV-Ray's cycloidal: sin(2 pi value) computed from the fractional part, as POV-Ray
/// does (its period is exactly 1).
double cycloidal(double value);

/// POV-Ray's Triangle_Wave: 0 at integers, 1 at half-integers.
double triangle_wave(double value);

/// POV-Ray's FLOOR macro: floor, with negative integers mapped one lower.
double pov_floor(double x);

/// POV-Ray's Hash3d over its 4096-entry permutation table.
int hash3d(int a, int b, int c);

/// POV-Ray's PatternRands(index): a fixed sequence of 32768 uniform numbers in [0, 1).
double pattern_rand(std::size_t index);

/// The sources and frequencies of the waves and ripples patterns (Initialize_Waves) for
/// global_settings' number_of_waves.
struct WaveSources {
    std::vector<glm::dvec3> sources;  // unit vectors
    std::vector<double> frequencies;
};
WaveSources make_wave_sources(int count);

}  // namespace mirage
