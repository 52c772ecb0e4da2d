// POV-Ray 3.7's spectral bands (colour/spectral.h, spectral.cpp): the wavelengths a
// dispersive refraction is split into, the index of refraction of each, and the colour each
// band carries (its share of white).
#pragma once

#include <glm/glm.hpp>

namespace mirage {

/// A band of the visible spectrum, 380 to 730 nm (POV-Ray keeps them in single precision).
struct SpectralBand {
    float wavelength = 555.0f;  // nm, the band's centre
    float bandwidth = 350.0f;   // nm
};

/// Band `band` of `bands` equal bands across the spectrum.
SpectralBand spectral_band(unsigned band, unsigned bands);

/// The band's index of refraction for a nominal index and dispersion (POV-Ray's
/// GetDispersionIOR: the dispersion is the ratio of the violet to the red index).
double dispersion_ior(const SpectralBand& band, double ior, double dispersion);

/// The colour the band carries; the bands of a split sum to about white times their count.
glm::dvec3 spectral_hue(const SpectralBand& band);

}  // namespace mirage
