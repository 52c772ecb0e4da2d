#include "render/antialias.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "util/check.h"
#include "util/format.h"

namespace mirage {

namespace {

/// splitmix64's finaliser: every input bit reaches every output bit.
std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

std::uint64_t bits_of(double v) {
    std::uint64_t b = 0;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

/// [0, 1) from the top 53 bits.
double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

/// Whether two encoded colours differ by the threshold.  POV-Ray keeps colours, the gamma
/// and the threshold (read as a float) in single precision; so does this.
bool differ(const glm::vec4& a, const glm::vec4& b, float threshold) {
    const glm::vec4 d = glm::abs(a - b);
    return d.x + d.y + d.z + d.w >= threshold;
}

/// Method 1 (+AM1), POV-Ray's NonAdaptiveSupersamplingM1: the pixels in raster order, each
/// traced through its centre and compared with its left and top neighbours as they stand
/// (a neighbour already supersampled counts with its average).  Where either difference
/// reaches the threshold, the pixel and the differing neighbours not yet supersampled get
/// depth x depth rays on a grid of cell centres, averaged with the first ray.  The row above
/// the block and the column left of it are traced for the comparison only, never
/// supersampled: POV-Ray renders its blocks independently.
class NonRecursiveBlock {
  public:
    NonRecursiveBlock(const AntialiasSettings& settings, double exponent, const PixelBlock& block,
                      const SampleFunction& sample, AntialiasCounters& counters)
        : s_(settings),
          exponent_(exponent),
          b_(block),
          sample_(sample),
          counters_(counters),
          threshold_(static_cast<float>(settings.threshold)),
          stride_(block.x1 - block.x0 + 1),
          colour_(static_cast<std::size_t>(stride_) * (block.y1 - block.y0 + 1)),
          encoded_(colour_.size()),
          done_(colour_.size(), 0) {}

    void render(Image& image) {
        for (int x = b_.x0; x < b_.x1; ++x) first_ray(x, b_.y0 - 1, true);
        for (int y = b_.y0; y < b_.y1; ++y) {
            first_ray(b_.x0 - 1, y, true);
            for (int x = b_.x0; x < b_.x1; ++x) {
                first_ray(x, y, false);
                const glm::vec4& c = encoded_[at(x, y)];
                const bool left_differs = differ(encoded_[at(x - 1, y)], c, threshold_);
                const bool top_differs = differ(encoded_[at(x, y - 1)], c, threshold_);
                if (left_differs) supersample(x - 1, y);
                if (top_differs) supersample(x, y - 1);
                if (left_differs || top_differs) supersample(x, y);
            }
        }
        for (int y = b_.y0; y < b_.y1; ++y)
            for (int x = b_.x0; x < b_.x1; ++x) image.set(x, y, glm::vec3(colour_[at(x, y)]));
        counters_.pixels += static_cast<std::uint64_t>(b_.x1 - b_.x0) * (b_.y1 - b_.y0);
    }

  private:
    /// Index of pixel (x, y); column 0 and row 0 hold the neighbours left of and above the
    /// block.
    std::size_t at(int x, int y) const {
        return static_cast<std::size_t>(y - b_.y0 + 1) * stride_ + (x - b_.x0 + 1);
    }

    void first_ray(int x, int y, bool frame) {
        colour_[at(x, y)] = sample_(x + 0.5, y + 0.5);
        encoded_[at(x, y)] = antialias_encode(colour_[at(x, y)], exponent_);
        done_[at(x, y)] = frame ? 1 : 0;  // the frame is never supersampled
        ++counters_.samples;
    }

    /// The pixel's first ray and depth x depth more, at the centres of a depth x depth grid
    /// of cells over the pixel, each moved by up to half a cell when jittered.
    void supersample(int x, int y) {
        if (done_[at(x, y)]) return;
        done_[at(x, y)] = 1;
        const int n = s_.depth;
        const double cell = 1.0 / n;
        const double jitter = s_.jitter * cell;
        glm::dvec4 sum = colour_[at(x, y)];
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                glm::dvec2 p(x + (i + 0.5) * cell, y + (j + 0.5) * cell);
                if (jitter > 0.0) p += jitter * jitter_offset(s_.jitter_seed, p.x, p.y);
                sum += sample_(p.x, p.y);
            }
        }
        counters_.samples += static_cast<std::uint64_t>(n) * n;
        ++counters_.pixels_supersampled;
        colour_[at(x, y)] = sum / static_cast<double>(n * n + 1);
        encoded_[at(x, y)] = antialias_encode(colour_[at(x, y)], exponent_);
    }

    const AntialiasSettings& s_;
    double exponent_;
    PixelBlock b_;
    const SampleFunction& sample_;
    AntialiasCounters& counters_;
    float threshold_;
    int stride_;
    std::vector<glm::dvec4> colour_;  // the pixels as they stand
    std::vector<glm::vec4> encoded_;  // the same after the antialias gamma, for comparisons
    std::vector<char> done_;
};

/// Method 2 (+AM2), POV-Ray's AdaptiveSupersamplingM2: every pixel corner traced (never
/// jittered); a pixel is the mean of its corners unless two of them differ by the threshold,
/// when its square is cut in four (the edge midpoints and the centre traced) and each quarter
/// is treated the same way, down to depth - 1 cuts, the pixel being the mean of its quarters.
class RecursiveBlock {
  public:
    RecursiveBlock(const AntialiasSettings& settings, double exponent, const PixelBlock& block,
                   const SampleFunction& sample, AntialiasCounters& counters)
        : s_(settings),
          exponent_(exponent),
          b_(block),
          sample_(sample),
          counters_(counters),
          cells_(1 << (settings.depth - 1)),
          // POV-Ray divides the jitter by the side of a grid twice as fine as the finest cut.
          jitter_(settings.jitter / ((1 << settings.depth) + 1)),
          threshold_(static_cast<float>(settings.threshold)),
          grid_(static_cast<std::size_t>(cells_ + 1) * (cells_ + 1)),
          grid_encoded_(grid_.size()),
          sampled_(grid_.size(), 0) {}

    void render(Image& image) {
        const int w = b_.x1 - b_.x0;
        const int h = b_.y1 - b_.y0;
        std::vector<glm::dvec4> corner(static_cast<std::size_t>(w + 1) * (h + 1));
        std::vector<glm::vec4> encoded(corner.size());
        for (int j = 0; j <= h; ++j) {
            for (int i = 0; i <= w; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * (w + 1) + i;
                corner[k] = sample_(b_.x0 + i, b_.y0 + j);
                encoded[k] = antialias_encode(corner[k], exponent_);
            }
        }
        counters_.samples += corner.size();
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                std::fill(sampled_.begin(), sampled_.end(), 0);
                const std::size_t k = static_cast<std::size_t>(j) * (w + 1) + i;
                set(0, 0, corner[k], encoded[k]);
                set(cells_, 0, corner[k + 1], encoded[k + 1]);
                set(0, cells_, corner[k + w + 1], encoded[k + w + 1]);
                set(cells_, cells_, corner[k + w + 2], encoded[k + w + 2]);
                bool cut = false;
                const glm::dvec4 c = subdivide(b_.x0 + i + 0.5, b_.y0 + j + 0.5, 0.5, 0, 0, cells_,
                                               s_.depth - 1, &cut);
                counters_.pixels_supersampled += cut;
                image.set(b_.x0 + i, b_.y0 + j, glm::vec3(c));
            }
        }
        counters_.pixels += static_cast<std::uint64_t>(w) * h;
    }

  private:
    std::size_t at(int gx, int gy) const {
        return static_cast<std::size_t>(gy) * (cells_ + 1) + gx;
    }
    void set(int gx, int gy, const glm::dvec4& c, const glm::vec4& encoded) {
        grid_[at(gx, gy)] = c;
        grid_encoded_[at(gx, gy)] = encoded;
        sampled_[at(gx, gy)] = 1;
    }

    /// Traces grid point (gx, gy) at image position (x, y) unless the pixel has it already.
    void sample_once(int gx, int gy, double x, double y) {
        if (sampled_[at(gx, gy)]) return;
        glm::dvec2 p(x, y);
        if (jitter_ > 0.0) p += jitter_ * jitter_offset(s_.jitter_seed, x, y);
        const glm::dvec4 c = sample_(p.x, p.y);
        set(gx, gy, c, antialias_encode(c, exponent_));
        ++counters_.samples;
    }

    /// The square of half side `d` centred at (x, y), its corners at grid points (gx, gy) and
    /// (gx + step, gy + step).
    glm::dvec4 subdivide(double x, double y, double d, int gx, int gy, int step, int level,
                         bool* cut) {
        const std::size_t i00 = at(gx, gy), i10 = at(gx + step, gy), i01 = at(gx, gy + step),
                          i11 = at(gx + step, gy + step);
        const auto apart = [this](std::size_t a, std::size_t b) {
            return differ(grid_encoded_[a], grid_encoded_[b], threshold_);
        };
        if (level <= 0 || !(apart(i00, i01) || apart(i00, i10) || apart(i00, i11) ||
                            apart(i01, i10) || apart(i01, i11) || apart(i10, i11))) {
            return (grid_[i00] + grid_[i01] + grid_[i10] + grid_[i11]) / 4.0;
        }
        if (cut) *cut = true;
        const int half = step / 2;
        sample_once(gx, gy + half, x - d, y);
        sample_once(gx + half, gy, x, y - d);
        sample_once(gx + step, gy + half, x + d, y);
        sample_once(gx + half, gy + step, x, y + d);
        sample_once(gx + half, gy + half, x, y);
        const double q = d / 2.0;
        const glm::dvec4 sum =
            subdivide(x - q, y - q, q, gx, gy, half, level - 1, nullptr) +
            subdivide(x - q, y + q, q, gx, gy + half, half, level - 1, nullptr) +
            subdivide(x + q, y - q, q, gx + half, gy, half, level - 1, nullptr) +
            subdivide(x + q, y + q, q, gx + half, gy + half, half, level - 1, nullptr);
        return sum / 4.0;
    }

    const AntialiasSettings& s_;
    double exponent_;
    PixelBlock b_;
    const SampleFunction& sample_;
    AntialiasCounters& counters_;
    int cells_;      // the finest cuts across a pixel: 2^(depth - 1)
    double jitter_;  // the scale of the jitter offsets, pixels
    float threshold_;
    std::vector<glm::dvec4> grid_;         // the pixel's samples on its finest grid
    std::vector<glm::vec4> grid_encoded_;  // the same after the antialias gamma
    std::vector<char> sampled_;
};

}  // namespace

std::string antialias_label(const AntialiasSettings& s) {
    if (!s.enabled()) return "off";
    std::string text = s.method == AntialiasMethod::NonRecursive ? "method 1 (non-recursive)"
                                                                 : "method 2 (recursive)";
    text += ", threshold " + shortest(s.threshold) + ", depth " + std::to_string(s.depth) +
            ", jitter " + (s.jitter > 0.0 ? shortest(s.jitter) : std::string("off"));
    return text;
}

Status check_antialias(const AntialiasSettings& s) {
    if (!s.enabled()) return Ok{};
    if (!(s.threshold >= 0.0 && s.threshold <= 1.0))
        return make_error("--antialias " + shortest(s.threshold) +
                          ": the threshold must be in [0, 1] (POV-Ray's +A clips it there)");
    if (s.depth < 1 || s.depth > 9)
        return make_error("--antialias-depth " + std::to_string(s.depth) +
                          ": must be 1 to 9 (POV-Ray's +R clips it there)");
    if (!(s.jitter >= 0.0 && s.jitter <= 1.0))
        return make_error("--jitter " + shortest(s.jitter) +
                          ": the amount must be in [0, 1] (POV-Ray's +J clips it there)");
    if (!(s.gamma > 0.0 && std::isfinite(s.gamma)))
        return make_error("antialias gamma " + shortest(s.gamma) + ": must be positive");
    if (s.block_size <= 0)
        return make_error("antialias block size " + std::to_string(s.block_size) +
                          ": must be positive");
    return Ok{};
}

double antialias_exponent(const GlobalSettings& global, double antialias_gamma) {
    // The working values are linear ^ (1 / assumed_gamma) (trace_scene's apply_output_gamma);
    // a scene before 3.7 without assumed_gamma works in no gamma space at all, as a linear one.
    const bool legacy = global.language_version < 3.7 - 1e-9 && !global.assumed_gamma_given;
    const double working = legacy ? 1.0 : global.assumed_gamma;
    const double exponent = working / antialias_gamma;
    // POV-Ray takes a power within 1% of 1 for no encoding at all (PowerLawGammaCurve).
    return std::abs(1.0 - exponent) <= 0.01 ? 1.0 : exponent;
}

glm::vec4 antialias_encode(const glm::dvec4& colour, double exponent) {
    const glm::vec4 c(colour);
    if (exponent == 1.0) return c;
    const float e = static_cast<float>(exponent);
    // The transmit channel is not encoded (GammaCurve::Encode leaves it).
    return {std::pow(std::max(c.x, 0.0f), e), std::pow(std::max(c.y, 0.0f), e),
            std::pow(std::max(c.z, 0.0f), e), c.w};
}

double antialias_distance(const glm::dvec4& a, const glm::dvec4& b, double exponent) {
    const glm::vec4 d = glm::abs(antialias_encode(a, exponent) - antialias_encode(b, exponent));
    return static_cast<double>(d.x + d.y + d.z + d.w);
}

void AntialiasCounters::add(const AntialiasCounters& o) {
    pixels += o.pixels;
    pixels_supersampled += o.pixels_supersampled;
    samples += o.samples;
}

double AntialiasCounters::supersampled_share() const {
    return pixels > 0 ? static_cast<double>(pixels_supersampled) / static_cast<double>(pixels)
                      : 0.0;
}

void antialias_block(const AntialiasSettings& settings, double exponent, const PixelBlock& block,
                     const SampleFunction& sample, Image& image, AntialiasCounters& counters) {
    MIRAGE_CHECK(settings.enabled() && settings.depth >= 1 && settings.depth <= 9);
    MIRAGE_CHECK(block.x0 < block.x1 && block.y0 < block.y1);
    if (settings.method == AntialiasMethod::NonRecursive) {
        NonRecursiveBlock(settings, exponent, block, sample, counters).render(image);
    } else {
        RecursiveBlock(settings, exponent, block, sample, counters).render(image);
    }
}

glm::dvec2 jitter_offset(std::uint64_t seed, double x, double y) {
    const std::uint64_t h = mix(mix(seed ^ 0x9e3779b97f4a7c15ULL) ^ bits_of(x));
    const std::uint64_t k = mix(h ^ bits_of(y));
    return {unit(k) - 0.5, unit(mix(k)) - 0.5};
}

}  // namespace mirage
