#include "shading/spectral.h"

#include <algorithm>
#include <cmath>

namespace mirage {

namespace {

constexpr double kViolet = 380.0;
constexpr double kRed = 730.0;
constexpr double kBandwidth = kRed - kViolet;
constexpr double kCentre = (kViolet + kRed) / 2;

// POV-Ray's table of the hues' integral over wavelength, 375 to 740 nm in steps of 5 nm
// (its "variant 3", from the formula of earlier versions).
constexpr int kTableSize = 74;
constexpr double kTableBase = 375.0;
constexpr double kTableStep = 5.0;
constexpr double kHueIntegral[kTableSize][3] = {
    {0.0000, 0.0000, 0.0000}, {0.0009, 0.0000, 0.0038}, {0.0029, 0.0000, 0.0113},
    {0.0058, 0.0000, 0.0222}, {0.0094, 0.0000, 0.0363}, {0.0135, 0.0000, 0.0534},
    {0.0178, 0.0000, 0.0734}, {0.0223, 0.0000, 0.0960}, {0.0267, 0.0000, 0.1210},
    {0.0308, 0.0000, 0.1482}, {0.0344, 0.0000, 0.1775}, {0.0374, 0.0000, 0.2085},
    {0.0394, 0.0000, 0.2412}, {0.0404, 0.0000, 0.2753}, {0.0404, 0.0000, 0.3106},
    {0.0404, 0.0000, 0.3470}, {0.0404, 0.0000, 0.3841}, {0.0404, 0.0000, 0.4219},
    {0.0404, 0.0000, 0.4600}, {0.0404, 0.0000, 0.4984}, {0.0404, 0.0000, 0.5368},
    {0.0404, 0.0000, 0.5750}, {0.0404, 0.0000, 0.6128}, {0.0404, 0.0000, 0.6500},
    {0.0404, 0.0000, 0.6864}, {0.0404, 0.0045, 0.7218}, {0.0404, 0.0131, 0.7560},
    {0.0404, 0.0256, 0.7888}, {0.0404, 0.0417, 0.8200}, {0.0404, 0.0612, 0.8494},
    {0.0404, 0.0839, 0.8768}, {0.0404, 0.1095, 0.9020}, {0.0404, 0.1378, 0.9248},
    {0.0404, 0.1684, 0.9449}, {0.0404, 0.2013, 0.9623}, {0.0404, 0.2360, 0.9767},
    {0.0404, 0.2724, 0.9878}, {0.0404, 0.3102, 0.9956}, {0.0404, 0.3492, 0.9997},
    {0.0404, 0.3891, 1.0000}, {0.0429, 0.4297, 1.0000}, {0.0502, 0.4707, 1.0000},
    {0.0620, 0.5119, 1.0000}, {0.0780, 0.5530, 1.0000}, {0.0979, 0.5937, 1.0000},
    {0.1215, 0.6340, 1.0000}, {0.1483, 0.6733, 1.0000}, {0.1781, 0.7117, 1.0000},
    {0.2105, 0.7487, 1.0000}, {0.2454, 0.7841, 1.0000}, {0.2823, 0.8178, 1.0000},
    {0.3210, 0.8494, 1.0000}, {0.3611, 0.8786, 1.0000}, {0.4024, 0.9054, 1.0000},
    {0.4446, 0.9293, 1.0000}, {0.4873, 0.9501, 1.0000}, {0.5302, 0.9677, 1.0000},
    {0.5731, 0.9817, 1.0000}, {0.6155, 0.9919, 1.0000}, {0.6573, 0.9981, 1.0000},
    {0.6982, 1.0000, 1.0000}, {0.7377, 1.0000, 1.0000}, {0.7756, 1.0000, 1.0000},
    {0.8116, 1.0000, 1.0000}, {0.8454, 1.0000, 1.0000}, {0.8767, 1.0000, 1.0000},
    {0.9052, 1.0000, 1.0000}, {0.9306, 1.0000, 1.0000}, {0.9525, 1.0000, 1.0000},
    {0.9707, 1.0000, 1.0000}, {0.9849, 1.0000, 1.0000}, {0.9947, 1.0000, 1.0000},
    {0.9998, 1.0000, 1.0000}, {1.0000, 1.0000, 1.0000},
};

glm::dvec3 hue_integral(double wavelength) {
    double offset = std::clamp((wavelength - kTableBase) / kTableStep, 0.0, kTableSize - 1.0);
    const int index = std::min(static_cast<int>(offset), kTableSize - 2);
    offset -= index;
    const glm::dvec3 a(kHueIntegral[index][0], kHueIntegral[index][1], kHueIntegral[index][2]);
    const glm::dvec3 b(kHueIntegral[index + 1][0], kHueIntegral[index + 1][1],
                       kHueIntegral[index + 1][2]);
    return (1.0 - offset) * a + offset * b;
}

}  // namespace

SpectralBand spectral_band(unsigned band, unsigned bands) {
    SpectralBand b;
    b.wavelength = static_cast<float>(
        kViolet + kBandwidth * ((static_cast<float>(band) + 0.5) / static_cast<float>(bands)));
    b.bandwidth = static_cast<float>(kBandwidth / static_cast<float>(bands));
    return b;
}

double dispersion_ior(const SpectralBand& band, double ior, double dispersion) {
    return ior * std::pow(dispersion, -(band.wavelength - kCentre) / kBandwidth);
}

glm::dvec3 spectral_hue(const SpectralBand& band) {
    // The ends of the band in single precision, as POV-Ray adds them.
    const float high = band.wavelength + band.bandwidth / 2;
    const float low = band.wavelength - band.bandwidth / 2;
    return (hue_integral(high) - hue_integral(low)) * (kBandwidth / band.bandwidth);
}

}  // namespace mirage
