#include "patterns/patterns.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "patterns/pigment_eval.h"
#include "patterns/single_precision.h"
#include "patterns/warps.h"

namespace mirage {

namespace {

constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
constexpr double kPi = 3.1415926535897932384626;
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kTwoPi = 6.283185307179586476925286766560;

/// POV-Ray's CLIP_DENSITY: 1 - r inside [0, 1], 1 below, 0 above.
inline double clip_density(double r) {
    if (r < 0.0) return 1.0;
    if (r > 1.0) return 0.0;
    return 1.0 - r;
}

inline double sqr(double x) { return x * x; }

double agate(const Pattern& pat, const glm::dvec3& p, int generator) {
    // Agate always has a classic turbulence (POV-Ray's parser adds one for its octaves).
    static const Turbulence kDefault;
    const Turbulence& turb = pat.turbulence ? *pat.turbulence : kDefault;
    const double turb_val = to_single(pat.agate_turb) * turbulence(p, turb, generator);
    double value = 0.5 * (cycloidal(1.3 * turb_val + 1.1 * p.z) + 1.0);
    if (value < 0.0) return 0.0;
    value = std::min(1.0, value);
    return std::pow(value, 0.77);
}

double brick(const Pattern& pat, const glm::dvec3& point) {
    const double mortar = to_single(pat.mortar);
    const double fudge = kEpsilon + mortar;
    const double x = point.x + fudge, y = point.y + fudge, z = point.z + fudge;
    const double width = pat.brick_size.x, height = pat.brick_size.y, depth = pat.brick_size.z;
    const double mortar_w = mortar / width;
    const double mortar_h = mortar / height;
    const double mortar_d = mortar / depth;
    // The fractional part as POV-Ray takes it: truncate, then wrap negatives up by one.
    auto frac = [](double v) {
        v -= static_cast<double>(static_cast<int>(v));
        return v < 0.0 ? v + 1.0 : v;
    };
    if (frac(y / height) <= mortar_h) return 0.0;
    const double by = frac((y / height) * 0.5);
    const double bx_odd = frac(x / width);
    if (bx_odd <= mortar_w && by <= 0.5) return 0.0;
    const double bx_even = frac(x / width + 0.5);
    if (bx_even <= mortar_w && by > 0.5) return 0.0;
    const double bz_odd = frac(z / depth);
    if (bz_odd <= mortar_d && by > 0.5) return 0.0;
    const double bz_even = frac(z / depth + 0.5);
    if (bz_even <= mortar_d && by <= 0.5) return 0.0;
    return 1.0;
}

double cells(const glm::dvec3& p) {
    return std::min(pattern_rand(hash3d(static_cast<int>(std::floor(p.x + kEpsilon)),
                                        static_cast<int>(std::floor(p.y + kEpsilon)),
                                        static_cast<int>(std::floor(p.z + kEpsilon)))),
                    1.0);
}

double checker(const glm::dvec3& p) {
    const int value = static_cast<int>(std::floor(p.x + kEpsilon) + std::floor(p.y + kEpsilon) +
                                       std::floor(p.z + kEpsilon));
    return (value & 1) ? 1.0 : 0.0;
}

/// The crackle pattern's neighbourhood: offsets in -2..2 with at most one of them +-2.
const std::array<std::array<int, 3>, 81>& crackle_cubes() {
    static const auto table = [] {
        std::array<std::array<int, 3>, 81> t{};
        int n = 0;
        for (int x = -2; x <= 2; ++x) {
            for (int y = -2; y <= 2; ++y) {
                for (int z = -2; z <= 2; ++z) {
                    if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) <= 1) {
                        t[n++] = {x, y, z};
                    }
                }
            }
        }
        return t;
    }();
    return table;
}

/// POV-Ray's IntPickInCube: the random point of a unit cube.
glm::dvec3 pick_in_cube(int x, int y, int z) {
    const std::size_t seed = static_cast<std::size_t>(hash3d(x & 0xFFF, y & 0xFFF, z & 0xFFF));
    return glm::dvec3(x + pattern_rand(seed), y + pattern_rand(seed + 1),
                      z + pattern_rand(seed + 2));
}

double crackle(const Pattern& pat, const glm::dvec3& p, int generator) {
    const double metric = pat.crackle_metric;
    const bool square = metric == 2;
    const bool unity = metric == 1;
    const int fx = static_cast<int>(std::floor(p.x - kEpsilon));
    const int fy = static_cast<int>(std::floor(p.y - kEpsilon));
    const int fz = static_cast<int>(std::floor(p.z - kEpsilon));
    const auto& cubes = crackle_cubes();
    std::array<glm::dvec3, 81> points;
    for (int i = 0; i < 81; ++i) {
        points[i] = pick_in_cube(fx + cubes[i][0], fy + cubes[i][1], fz + cubes[i][2]);
    }
    auto distance = [&](const glm::dvec3& q) {
        const glm::dvec3 d = q - p;
        if (square) return d.x * d.x + d.y * d.y + d.z * d.z;
        if (unity) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
        return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
               std::pow(std::fabs(d.z), metric);
    };
    double m1 = distance(points[0]);
    double m2 = distance(points[1]);
    double m3 = distance(points[2]);
    int nearest = 0;
    if (m2 < m1) {
        std::swap(m1, m2);
        nearest = 1;
    }
    if (m3 < m1) {
        std::swap(m1, m3);
        nearest = 2;
    }
    if (m3 < m2) std::swap(m2, m3);
    for (int i = 3; i < 81; ++i) {
        const double sum = distance(points[i]);
        if (sum < m1) {
            m3 = m2;
            m2 = m1;
            m1 = sum;
            nearest = i;
        } else if (sum < m2) {
            m3 = m2;
            m2 = sum;
        } else if (sum < m3) {
            m3 = sum;
        }
    }
    const double offset = pat.crackle_offset;
    if (offset != 0.0) {
        const double add = square ? offset * offset : unity ? offset : std::pow(offset, metric);
        m1 += add;
        m2 += add;
        m3 += add;
    }
    double value;
    const glm::dvec3& form = pat.crackle_form;
    if (pat.crackle_solid) {
        value = noise(points[nearest], generator);
    } else if (square) {
        value = form.x * std::sqrt(m1) + form.y * std::sqrt(m2) + form.z * std::sqrt(m3);
    } else if (unity) {
        value = form.x * m1 + form.y * m2 + form.z * m3;
    } else {
        value = form.x * std::pow(m1, 1.0 / metric) + form.y * std::pow(m2, 1.0 / metric) +
                form.z * std::pow(m3, 1.0 / metric);
    }
    return std::max(std::min(value, 1.0), 0.0);
}

double gradient(const Pattern& pat, const glm::dvec3& p) {
    // The axis as POV-Ray's parser normalises it (scenes built in code may not have).
    const double length = glm::length(pat.gradient_axis);
    const glm::dvec3 axis = length > 0.0 ? pat.gradient_axis * (1.0 / length) : pat.gradient_axis;
    const double value = p.x * axis.x + p.y * axis.y + p.z * axis.z;
    return value > 1.0 ? std::fmod(value, 1.0) : value;
}

double granite(const glm::dvec3& p, int generator) {
    const glm::dvec3 base(p.x * 4.0, p.y * 4.0, p.z * 4.0);
    double value = 0.0, freq = 1.0;
    for (int i = 0; i < 6; freq *= 2.0, ++i) {
        const glm::dvec3 q(base.x * freq, base.y * freq, base.z * freq);
        double temp;
        if (generator == 1) {
            temp = std::fabs(0.5 - noise(q, generator));
        } else {
            temp = std::fabs(1.0 - 2.0 * noise(q, generator));
            if (temp > 0.5) temp = 0.5;
        }
        value += temp / freq;
    }
    return value;
}

double hexagon(const glm::dvec3& p) {
    constexpr double kXFactor = 0.5;
    constexpr double kZFactor = 0.866025404;
    const double x = std::fabs(p.x);
    // Avoids mirroring across the x axis (the grid is 6 blocks high).
    const double z = p.z < 0.0 ? 5.196152424 - std::fabs(p.z) : p.z;
    double xs = x / kXFactor;
    double zs = z / kZFactor;
    xs -= std::floor(xs / 6.0) * 6.0;
    zs -= std::floor(zs / 6.0) * 6.0;
    const int xm = static_cast<int>(pov_floor(xs)) % 6;
    const int zm = static_cast<int>(pov_floor(zs)) % 6;
    double value = 0.0;
    switch (xm) {
        case 0:
        case 5:
            value = (zm == 0 || zm == 5) ? 0 : (zm == 1 || zm == 2) ? 1 : 2;
            break;
        case 2:
        case 3:
            value = (zm == 0 || zm == 1) ? 2 : (zm == 2 || zm == 3) ? 0 : 1;
            break;
        case 1:
        case 4: {
            double xl = xs - xm;
            const double zl = zs - zm;
            if (((xm + zm) % 2) == 1) xl = 1.0 - xl;
            if (xl == 0.0) xl = 0.0001;
            const bool below = (zl / xl) < 1.0;
            if (below) {
                value = (zm == 0 || zm == 3) ? 0 : (zm == 2 || zm == 5) ? 1 : 2;
            } else {
                value = (zm == 0 || zm == 3) ? 2 : (zm == 2 || zm == 5) ? 0 : 1;
            }
            break;
        }
        default:
            break;
    }
    return std::fmod(value, 3.0);
}

double cubic(const glm::dvec3& p) {
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    if (p.x >= 0 && p.x >= ay && p.x >= az) return 0.0;
    if (p.y >= 0 && p.y >= ax && p.y >= az) return 1.0;
    if (p.z >= 0 && p.z >= ax && p.z >= ay) return 2.0;
    if (p.x < 0 && p.x <= -ay && p.x <= -az) return 3.0;
    if (p.y < 0 && p.y <= -ax && p.y <= -az) return 4.0;
    return 5.0;
}

double square(const glm::dvec3& p) {
    const int vx = static_cast<int>(std::floor(p.x));
    const int vz = static_cast<int>(std::floor(p.z));
    if (vx & 1) return (vz & 1) ? 2.0 : 3.0;
    return (vz & 1) ? 1.0 : 0.0;
}

double triangular(const glm::dvec3& p) {
    constexpr double kSqrt3 = 1.7320508075688772935274463415059;
    constexpr double kSqrt3Half = 0.86602540378443864676372317075294;
    double xs = p.x - 3.0 * std::floor(p.x / 3.0);
    double zs = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    const int a = static_cast<int>(std::floor(xs));
    xs -= a;
    const bool b = zs >= kSqrt3Half;
    if (b) zs = kSqrt3 - zs;
    const double k = 1.0 - xs;
    double answer = 1.0;
    if (xs != 0.0 && k != 0.0) {
        const double slope1 = zs / xs;
        const double slope2 = zs / k;
        switch ((slope1 < kSqrt3 ? 1 : 0) + (slope2 < kSqrt3 ? 2 : 0)) {
            case 3:
                answer = 0.0;
                break;
            case 2:
                answer = 1.0;
                break;
            case 1:
                answer = 3.0;
                break;
            default:
                break;  // POV-Ray leaves the value undefined; 1 as for a degenerate point
        }
    }
    const int mask = static_cast<int>(answer);
    answer = (mask & 1) ? std::fmod(answer + 2.0 * a, 6.0) : std::fmod(6.0 + answer - 2.0 * a, 6.0);
    if (b) answer = 5.0 - answer;
    return answer;
}

double leopard(const glm::dvec3& p) {
    const double a = std::sin(p.x), b = std::sin(p.y), c = std::sin(p.z);
    return sqr((a + b + c) / 3.0);
}

double mandel(const Pattern& pat, const glm::dvec3& p) {
    double a = p.x, b = p.y;
    const double x = p.x, y = p.y;
    double a2 = a * a, b2 = b * b;
    double mindist2 = a2 + b2;
    const int it_max = pat.iterations;
    double value = 0.0;
    int col;
    for (col = 0; col < it_max; ++col) {
        b = 2.0 * a * b + y;
        a = a2 - b2 + x;
        a2 = a * a;
        b2 = b * b;
        const double dist2 = a2 + b2;
        if (dist2 < mindist2) mindist2 = dist2;
        if (dist2 > 4.0) {
            const double f = pat.exterior_factor;
            switch (pat.exterior_type) {
                case 0:
                    value = f;
                    break;
                case 1:
                    value = static_cast<double>(col) / static_cast<double>(it_max);
                    break;
                case 2:
                    value = a * f;
                    break;
                case 3:
                    value = b * f;
                    break;
                case 4:
                    value = a * a * f;
                    break;
                case 5:
                    value = b * b * f;
                    break;
                case 6:
                    value = std::sqrt(a * a + b * b) * f;
                    break;
                case 7:
                    value = static_cast<double>(col % static_cast<unsigned>(f)) / f;
                    break;
                case 8:
                    value = static_cast<double>(col % static_cast<unsigned>(1 + f)) / f;
                    break;
                default:
                    value = 0.0;
            }
            break;
        }
    }
    if (col == it_max) {
        const double f = pat.interior_factor;
        switch (pat.interior_type) {
            case 0:
                value = f;
                break;
            case 1:
                value = std::sqrt(mindist2) * f;
                break;
            case 2:
                value = a * f;
                break;
            case 3:
                value = b * f;
                break;
            case 4:
                value = a * a * f;
                break;
            case 5:
                value = b * b * f;
                break;
            case 6:
                value = a * a + b * b * f;  // POV-Ray's precedence
                break;
            default:
                value = 0.0;
        }
    }
    return value;
}

double marble(const Pattern& pat, const glm::dvec3& p, int generator) {
    const double turb_val =
        pat.turbulence ? pat.turbulence->amount.x * turbulence(p, *pat.turbulence, generator) : 0.0;
    return p.x + turb_val;
}

double onion(const glm::dvec3& p) {
    return std::fmod(std::sqrt(sqr(p.x) + sqr(p.y) + sqr(p.z)), 1.0);
}

double quilted(const Pattern& pat, const glm::dvec3& p) {
    glm::dvec3 v(p.x - pov_floor(p.x) - 0.5, p.y - pov_floor(p.y) - 0.5,
                 p.z - pov_floor(p.z) - 0.5);
    double t = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    t = quilt_cubic(t, to_single(pat.control0), to_single(pat.control1));
    v *= t;
    return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) / 3.0;
}

double radial(const glm::dvec3& p) {
    if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
    return 0.25 + (std::atan2(p.x, p.z) + kPi) / kTwoPi;
}

const WaveSources& waves_of(const PatternContext& ctx) {
    static const WaveSources kDefault = make_wave_sources(10);
    return ctx.waves ? *ctx.waves : kDefault;
}

double ripples(const Pattern& pat, const glm::dvec3& p, const PatternContext& ctx) {
    const WaveSources& w = waves_of(ctx);
    double scalar = 0.0;
    for (std::size_t i = 0; i < w.sources.size(); ++i) {
        const glm::dvec3 d = p - w.sources[i];
        double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (length == 0.0) length = 1.0;
        scalar += cycloidal(length * to_single(pat.frequency) + to_single(pat.phase));
    }
    return 0.5 * (1.0 + scalar / static_cast<double>(w.sources.size()));
}

double waves(const Pattern& pat, const glm::dvec3& p, const PatternContext& ctx) {
    const WaveSources& w = waves_of(ctx);
    double scalar = 0.0;
    for (std::size_t i = 0; i < w.sources.size(); ++i) {
        const glm::dvec3 d = p - w.sources[i];
        double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (length == 0.0) length = 1.0;
        const double index =
            length * to_single(pat.frequency) * w.frequencies[i] + to_single(pat.phase);
        scalar += cycloidal(index) / w.frequencies[i];
    }
    return 0.2 * (2.5 + scalar / static_cast<double>(w.sources.size()));
}

/// The spirals' angle in the x-y plane, 0 to 2 pi, and distance from the z axis.
void spiral_polar(const glm::dvec3& p, double& rad, double& phi) {
    rad = std::sqrt(p.x * p.x + p.y * p.y);
    if (rad == 0.0) {
        phi = 0.0;
    } else if (p.x < 0.0) {
        phi = 3.0 * kHalfPi - std::asin(p.y / rad);
    } else {
        phi = kHalfPi + std::asin(p.y / rad);
    }
}

double spiral(const Pattern& pat, const glm::dvec3& p, int generator, bool second) {
    const double turb_val =
        pat.turbulence ? pat.turbulence->amount.x * turbulence(p, *pat.turbulence, generator) : 0.0;
    double rad, phi;
    spiral_polar(p, rad, phi);
    const double value = p.z + rad + static_cast<double>(pat.arms) * phi / kTwoPi + turb_val;
    if (!second) return value;
    return triangle_wave(rad) + triangle_wave(value);
}

double wood(const Pattern& pat, const glm::dvec3& p) {
    glm::dvec3 q(0.0);
    if (pat.turbulence) {
        const Turbulence& t = *pat.turbulence;
        const glm::dvec3 d = dturbulence(p, t);
        q.x = cycloidal((p.x + d.x) * t.amount.x);
        q.y = cycloidal((p.y + d.y) * t.amount.y);
    }
    q.x += p.x;
    q.y += p.y;
    return std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
}

double wrinkles(const glm::dvec3& p, int generator) {
    double lambda = 2.0, omega = 0.5;
    double value;
    if (generator > 1) {
        value = std::clamp(noise(p, generator) * 2.0 - 0.5, 0.0, 1.0);
    } else {
        value = noise(p, generator);
    }
    for (int i = 1; i < 10; ++i) {
        const glm::dvec3 q(p.x * lambda, p.y * lambda, p.z * lambda);
        if (generator > 1) {
            value += omega * std::clamp(noise(q, generator) * 2.0 - 0.5, 0.0, 1.0);
        } else {
            value += omega * noise(q, generator);
        }
        lambda *= 2.0;
        omega *= 0.5;
    }
    return value / 2.0;
}

/// POV-Ray's slope_pattern: the surface's slope against a direction (and its altitude).
double slope(const Pattern& pat, const glm::dvec3& p, const PatternContext& ctx) {
    const glm::dvec3& n = ctx.normal;
    double value1;
    if (pat.slope_point_at) {
        const glm::dvec3 v = glm::normalize(pat.slope_vector - ctx.point);
        value1 = glm::dot(n, v);
    } else {
        value1 = glm::dot(n, pat.slope_vector);
    }
    value1 = std::clamp(value1, -1.0, 1.0);
    value1 = std::asin(value1) / kPi * 2;
    value1 = (value1 + 1.0) * 0.5;
    if (pat.slope_mod.y != 0.0) value1 = (value1 - pat.slope_mod.x) / pat.slope_mod.y;
    if (pat.altitude_len == 0.0) {
        if (value1 == 1.0) return value1 - kEpsilon;
        return value1 < 0.0 ? 1.0 + std::fmod(value1, 1.0) : std::fmod(value1, 1.0);
    }
    double value2 = glm::dot(p, pat.altitude_vector);
    if (pat.altitude_mod.y != 0.0) value2 = (value2 - pat.altitude_mod.x) / pat.altitude_mod.y;
    double value = pat.slope_len * value1 + pat.altitude_len * value2;
    if (value - 1.0 < kEpsilon && value >= 1.0) return value - kEpsilon;
    return value < 0.0 ? 1.0 + std::fmod(value, 1.0) : std::fmod(value, 1.0);
}

double pigment_pattern(const Pattern& pat, const glm::dvec3& p, const PatternContext& ctx) {
    if (!pat.pattern_pigment) return 0.0;
    PigmentColour c;
    if (!compute_pigment(*pat.pattern_pigment, p, ctx, c)) return 0.0;
    return greyscale(c.rgb);
}

}  // namespace

double quilt_cubic(double t, double p1, double p2) {
    constexpr double kInvSqrt34 = 1.154700538;
    const double it = 1 - t;
    const double itsqrd = it * it;
    const double tsqrd = t * t;
    const double tcubed = t * tsqrd;
    return (tcubed + 3.0 * t * itsqrd * p1 + 3.0 * tsqrd * it * p2) * kInvSqrt34;
}

const PatternContext& default_pattern_context() {
    static const WaveSources waves = make_wave_sources(10);
    static const PatternContext ctx{2, &waves, glm::dvec3(0.0), glm::dvec3(0.0)};
    return ctx;
}

bool is_normal_only_pattern(PatternKind kind) {
    switch (kind) {
        case PatternKind::ImageMap:
        case PatternKind::Bumps:
        case PatternKind::Dents:
        case PatternKind::Ripples:
        case PatternKind::Waves:
        case PatternKind::Wrinkles:
        case PatternKind::Quilted:
        case PatternKind::Facets:
        case PatternKind::Average:
            return true;
        default:
            return false;
    }
}

double raw_pattern_value(const Pattern& pat, const glm::dvec3& p, const PatternContext& ctx) {
    const int generator = pattern_noise_generator(pat, ctx);
    switch (pat.kind) {
        case PatternKind::Solid:
        case PatternKind::ImageMap:
        case PatternKind::Average:
        case PatternKind::Facets:
            return 0.0;
        case PatternKind::Agate:
            return agate(pat, p, generator);
        case PatternKind::Bozo:
        case PatternKind::Spotted:
        case PatternKind::Bumps:
            return noise(p, generator);
        case PatternKind::Boxed:
            return clip_density(std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
        case PatternKind::Brick:
            return brick(pat, p);
        case PatternKind::Cells:
            return cells(p);
        case PatternKind::Checker:
            return checker(p);
        case PatternKind::Crackle:
            return crackle(pat, p, generator);
        case PatternKind::Cubic:
            return cubic(p);
        case PatternKind::Cylindrical:
            return clip_density(std::sqrt(sqr(p.x) + sqr(p.z)));
        case PatternKind::Dents: {
            const double n = noise(p, generator);
            return n * n * n;
        }
        case PatternKind::Gradient:
            return gradient(pat, p);
        case PatternKind::Granite:
            return granite(p, generator);
        case PatternKind::Hexagon:
            return hexagon(p);
        case PatternKind::Leopard:
            return leopard(p);
        case PatternKind::Mandel:
            return mandel(pat, p);
        case PatternKind::Marble:
            return marble(pat, p, generator);
        case PatternKind::Onion:
            return onion(p);
        case PatternKind::Planar:
            return clip_density(std::fabs(p.y));
        case PatternKind::Slope:
            return slope(pat, p, ctx);
        case PatternKind::PigmentPattern:
            return pigment_pattern(pat, p, ctx);
        case PatternKind::Quilted:
            return quilted(pat, p);
        case PatternKind::Radial:
            return radial(p);
        case PatternKind::Ripples:
            return ripples(pat, p, ctx);
        case PatternKind::Spherical:
            return clip_density(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
        case PatternKind::Spiral1:
            return spiral(pat, p, generator, false);
        case PatternKind::Spiral2:
            return spiral(pat, p, generator, true);
        case PatternKind::Square:
            return square(p);
        case PatternKind::Triangular:
            return triangular(p);
        case PatternKind::Waves:
            return waves(pat, p, ctx);
        case PatternKind::Wood:
            return wood(pat, p);
        case PatternKind::Wrinkles:
            return wrinkles(p, generator);
    }
    return 0.0;
}

double evaluate_pattern(const Pattern& pat, const glm::dvec3& p, const PatternContext& ctx) {
    double value = raw_pattern_value(pat, p, ctx);
    // POV-Ray holds frequency, phase and exponent in single precision.
    const double frequency = to_single(pat.frequency);
    if (frequency != 0.0) value = std::fmod(value * frequency + to_single(pat.phase), 1.00001);
    if (value < 0.0) value -= std::floor(value);  // negative frequencies wrap up
    switch (pat.wave) {
        case WaveType::Ramp:
            break;
        case WaveType::Sine:
            value = (1.0 + cycloidal(value)) * 0.5;
            break;
        case WaveType::Triangle:
            value = triangle_wave(value);
            break;
        case WaveType::Scallop:
            value = std::fabs(cycloidal(value * 0.5));
            break;
        case WaveType::Cubic:
            value = sqr(value) * ((-2.0 * value) + 3.0);
            break;
        case WaveType::Poly:
            value = std::pow(value, to_single(pat.exponent));
            break;
    }
    return value;
}

}  // namespace mirage
