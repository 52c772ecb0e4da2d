#include "patterns/noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "patterns/single_precision.h"

namespace mirage {

namespace {

constexpr double kEpsilon = 1.0e-10;    // POV-Ray's EPSILON
constexpr int kLatticeOffset = -10000;  // POV-Ray's MINX, MINY, MINZ

// POV-Ray's random table: 267 values; entry i of its interleaved table is the value, entry
// i + 1 half of it (Initialize_Noise).
constexpr double kRandomTable[267] = {
    -1,        0.604974,  -0.937102,  0.414115,  0.576226,   -0.0161593, 0.432334,    0.103685,
    0.590539,  0.0286412, 0.46981,    -0.84622,  -0.0734112, -0.304097,  -0.40206,    -0.210132,
    -0.919127, 0.652033,  -0.83151,   -0.183948, -0.671107,  0.852476,   0.043595,    -0.404532,
    0.75494,   -0.335653, 0.618433,   0.605707,  0.708583,   -0.477195,  0.899474,    0.490623,
    0.221729,  -0.400381, -0.853727,  -0.932586, 0.659113,   0.961303,   0.325948,    -0.750851,
    0.842466,  0.734401,  -0.649866,  0.394491,  -0.466056,  -0.434073,  0.109026,    0.0847028,
    -0.738857, 0.241505,  0.16228,    -0.71426,  -0.883665,  -0.150408,  -0.90396,    -0.686549,
    -0.785214, 0.488548,  0.0246433,  0.142473,  -0.602136,  0.375845,   -0.00779736, 0.498955,
    -0.268147, 0.856382,  -0.386007,  -0.596094, -0.867735,  -0.570977,  -0.914366,   0.28896,
    0.672206,  -0.233783, 0.94815,    0.895262,  0.343252,   -0.173388,  -0.767971,   -0.314748,
    0.824308,  -0.342092, 0.721431,   -0.24004,  -0.63653,   0.553277,   0.376272,    0.158984,
    -0.452659, 0.396323,  -0.420676,  -0.454154, 0.122179,   0.295857,   0.0664225,   -0.202075,
    -0.724788, 0.453513,  0.224567,   -0.908812, 0.176349,   -0.320516,  -0.697139,   0.742702,
    -0.900786, 0.471489,  -0.133532,  0.119127,  -0.889769,  -0.23183,   -0.669673,   -0.046891,
    -0.803433, -0.966735, 0.475578,   -0.652644, 0.0112459,  -0.730007,  0.128283,    0.145647,
    -0.619318, 0.272023,  0.392966,   0.646418,  -0.0207675, -0.315908,  0.480797,    0.535668,
    -0.250172, -0.83093,  -0.653773,  -0.443809, 0.119982,   -0.897642,  0.89453,     0.165789,
    0.633875,  -0.886839, 0.930877,   -0.537194, 0.587732,   0.722011,   -0.209461,   -0.0424659,
    -0.814267, -0.919432, 0.280262,   -0.66302,  -0.558099,  -0.537469,  -0.598779,   0.929656,
    -0.170794, -0.537163, 0.312581,   0.959442,  0.722652,   0.499931,   0.175616,    -0.534874,
    -0.685115, 0.444999,  0.17171,    0.108202,  -0.768704,  -0.463828,  0.254231,    0.546014,
    0.869474,  0.875212,  -0.944427,  0.130724,  -0.110185,  0.312184,   -0.33138,    -0.629206,
    0.0606546, 0.722866,  -0.0979477, 0.821561,  0.0931258,  -0.972808,  0.0318151,   -0.867033,
    -0.387228, 0.280995,  -0.218189,  -0.539178, -0.427359,  -0.602075,  0.311971,    0.277974,
    0.773159,  0.592493,  -0.0331884, -0.630854, -0.269947,  0.339132,   0.581079,    0.209461,
    -0.317433, -0.284993, 0.181323,   0.341634,  0.804959,   -0.229572,  -0.758907,   -0.336721,
    0.605463,  -0.991272, -0.0188754, -0.300191, 0.368307,   -0.176135,  -0.3832,     -0.749569,
    0.62356,   -0.573938, 0.278309,   -0.971313, 0.839994,   -0.830686,  0.439078,    0.66128,
    0.694514,  0.0565042, 0.54342,    -0.438804, -0.0228428, -0.687068,  0.857267,    0.301991,
    -0.494255, -0.941039, 0.775509,   0.410575,  -0.362081,  -0.671534,  -0.348379,   0.932433,
    0.886442,  0.868681,  -0.225666,  -0.062211, -0.0976425, -0.641444,  -0.848112,   0.724697,
    0.473503,  0.998749,  0.174701,   0.559625,  -0.029099,  -0.337392,  -0.958129,   -0.659785,
    0.236042,  -0.246937, 0.659449,   -0.027512, 0.821897,   -0.226215,  0.0181735,   0.500481,
    -0.420127, -0.427878, 0.566186,
};

/// POV-Ray's linear congruential step (next_rand = next_rand * 1812433253 + 12345, computed
/// in 64-bit longs and stored back in a 32-bit int) and its 15-bit draw.
struct PovRand {
    std::int32_t state;
    int next15() {
        const std::int64_t wide = static_cast<std::int64_t>(state) * 1812433253LL + 12345LL;
        state = static_cast<std::int32_t>(static_cast<std::uint32_t>(wide));
        return (state >> 16) & 0x7FFF;
    }
};

struct HashTable {
    std::array<unsigned short, 8192> h{};
    HashTable() {
        for (int i = 0; i < 4096; ++i) h[i] = static_cast<unsigned short>(i);
        PovRand r{0};
        for (int i = 4095; i >= 0; --i) {
            const int j = r.next15() % 4096;
            std::swap(h[i], h[j]);
        }
        for (int i = 0; i < 4096; ++i) h[4096 + i] = h[i];
    }
};

const HashTable& hash_table() {
    static const HashTable table;
    return table;
}

/// The random table as POV-Ray interleaves it: value, half value, value, ...
struct InterleavedTable {
    std::array<double, 534> t{};
    InterleavedTable() {
        for (int i = 0; i < 267; ++i) {
            t[2 * i] = kRandomTable[i];
            t[2 * i + 1] = kRandomTable[i] * 0.5;
        }
    }
};

const double* random_table() {
    static const InterleavedTable table;
    return table.t.data();
}

// Generator 3's tables (InitSolidNoise).
constexpr int kNoiseEntries = 2048;
struct SolidTables {
    std::array<int, 2 * (kNoiseEntries + 1)> permutation{};
    std::array<glm::dvec3, 2 * (kNoiseEntries + 1)> gradients{};
    SolidTables() {
        PovRand r{1};
        for (int i = 0; i < kNoiseEntries; ++i) {
            glm::dvec3 v;
            double s;
            do {
                for (int j = 0; j < 3; ++j) {
                    v[j] =
                        static_cast<double>((r.next15() % (kNoiseEntries << 1)) - kNoiseEntries) /
                        static_cast<double>(kNoiseEntries);
                }
                s = v.x * v.x + v.y * v.y + v.z * v.z;
            } while (s > 1.0 || s < 1.0e-5);
            s = 1.0 / std::sqrt(s);
            gradients[i] = glm::dvec3(v.x * s, v.y * s, v.z * s);
        }
        for (int i = 0; i < kNoiseEntries; ++i) permutation[i] = i;
        for (int i = kNoiseEntries; i > 0; i -= 2) {
            const int k = permutation[i];
            const int j = r.next15() % kNoiseEntries;
            permutation[i] = permutation[j];
            permutation[j] = k;
        }
        for (int i = 0; i < kNoiseEntries + 2; ++i) {
            permutation[kNoiseEntries + i] = permutation[i];
            gradients[kNoiseEntries + i] = gradients[i];
        }
    }
};

const SolidTables& solid_tables() {
    static const SolidTables tables;
    return tables;
}

inline double scurve(double a) { return a * a * (3.0 - 2.0 * a); }

/// One axis of the lattice: the cell index (POV-Ray's range fix) and the offset in the cell.
inline void lattice(double x, int& index, double& frac) {
    const int cell = x >= 0 ? static_cast<int>(x) : static_cast<int>(x - (1 - kEpsilon));
    index = (cell - kLatticeOffset) & 0xFFF;
    frac = x - cell;
}

inline int hash2d(const unsigned short* h, int a, int b) { return h[h[a] ^ b]; }
inline int table_index(const unsigned short* h, int a, int b) { return (h[a ^ b] & 0xFF) * 2; }

/// One corner's contribution: s (m[1] + m[2] x + m[4] y + m[6] z).
inline double corner(const double* m, double s, double x, double y, double z) {
    return s * (m[1] + m[2] * x + m[4] * y + m[6] * z);
}

double solid_noise(const glm::dvec3& p) {
    const SolidTables& t = solid_tables();
    constexpr double kRollover = 10000000.023157213;
    int b0[3], b1[3];
    double r0[3], r1[3];
    for (int i = 0; i < 3; ++i) {
        const double v = p[i] + kRollover;
        const int it = static_cast<int>(std::floor(v));
        b0[i] = it & (kNoiseEntries - 1);
        b1[i] = (b0[i] + 1) & (kNoiseEntries - 1);
        r0[i] = v - it;
        r1[i] = r0[i] - 1.0;
    }
    const int i = t.permutation[b0[0]];
    const int j = t.permutation[b1[0]];
    const int b00 = t.permutation[i + b0[1]];
    const int b10 = t.permutation[j + b0[1]];
    const int b01 = t.permutation[i + b1[1]];
    const int b11 = t.permutation[j + b1[1]];
    const double sx = scurve(r0[0]), sy = scurve(r0[1]), sz = scurve(r0[2]);
    auto at = [&](int index, double rx, double ry, double rz) {
        const glm::dvec3& g = t.gradients[index];
        return rx * g.x + ry * g.y + rz * g.z;
    };
    auto lerp = [](double s, double a, double b) { return a + s * (b - a); };
    double u = at(b00 + b0[2], r0[0], r0[1], r0[2]);
    double v = at(b10 + b0[2], r1[0], r0[1], r0[2]);
    double a = lerp(sx, u, v);
    u = at(b01 + b0[2], r0[0], r1[1], r0[2]);
    v = at(b11 + b0[2], r1[0], r1[1], r0[2]);
    double b = lerp(sx, u, v);
    const double c = lerp(sy, a, b);
    u = at(b00 + b1[2], r0[0], r0[1], r1[2]);
    v = at(b10 + b1[2], r1[0], r0[1], r1[2]);
    a = lerp(sx, u, v);
    u = at(b01 + b1[2], r0[0], r1[1], r1[2]);
    v = at(b11 + b1[2], r1[0], r1[1], r1[2]);
    b = lerp(sx, u, v);
    const double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

}  // namespace

double pov_floor(double x) { return x >= 0.0 ? std::floor(x) : (0.0 - std::floor(0.0 - x) - 1.0); }

int hash3d(int a, int b, int c) {
    const unsigned short* h = hash_table().h.data();
    return h[h[h[a & 0xfff] ^ (b & 0xfff)] ^ (c & 0xfff)];
}

double noise(const glm::dvec3& p, int generator) {
    if (generator == 3) {
        // POV-Ray's correction of the gradient noise's bias, then clipped.
        const double sum = 0.5 * (1.59 * solid_noise(p) + 0.985);
        return std::clamp(sum, 0.0, 1.0);
    }
    const unsigned short* h = hash_table().h.data();
    const double* rt = random_table();
    int ix, iy, iz;
    double x_ix, y_iy, z_iz;
    lattice(p.x, ix, x_ix);
    lattice(p.y, iy, y_iy);
    lattice(p.z, iz, z_iz);
    const double x_jx = x_ix - 1, y_jy = y_iy - 1, z_jz = z_iz - 1;
    const double sx = scurve(x_ix), sy = scurve(y_iy), sz = scurve(z_iz);
    const double tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
    const double txty = tx * ty, sxty = sx * ty, txsy = tx * sy, sxsy = sx * sy;
    const int h00 = hash2d(h, ix, iy);
    const int h10 = hash2d(h, ix + 1, iy);
    const int h01 = hash2d(h, ix, iy + 1);
    const int h11 = hash2d(h, ix + 1, iy + 1);
    // The eight corners in POV-Ray's order (the order of the sum matters to the last bit).
    double sum = corner(&rt[table_index(h, h00, iz)], txty * tz, x_ix, y_iy, z_iz);
    sum += corner(&rt[table_index(h, h10, iz)], sxty * tz, x_jx, y_iy, z_iz);
    sum += corner(&rt[table_index(h, h01, iz)], txsy * tz, x_ix, y_jy, z_iz);
    sum += corner(&rt[table_index(h, h11, iz)], sxsy * tz, x_jx, y_jy, z_iz);
    sum += corner(&rt[table_index(h, h00, iz + 1)], txty * sz, x_ix, y_iy, z_jz);
    sum += corner(&rt[table_index(h, h10, iz + 1)], sxty * sz, x_jx, y_iy, z_jz);
    sum += corner(&rt[table_index(h, h01, iz + 1)], txsy * sz, x_ix, y_jy, z_jz);
    sum += corner(&rt[table_index(h, h11, iz + 1)], sxsy * sz, x_jx, y_jy, z_jz);
    if (generator == 2) {
        // POV-Ray's measured range of the sum, -1.05242 to 0.988997, stretched to [0, 1].
        sum += 1.05242;
        sum *= 0.48985582;
    } else {
        sum += 0.5;
    }
    return std::clamp(sum, 0.0, 1.0);
}

glm::dvec3 dnoise(const glm::dvec3& p) {
    const unsigned short* h = hash_table().h.data();
    const double* rt = random_table();
    int ix, iy, iz;
    double x_ix, y_iy, z_iz;
    lattice(p.x, ix, x_ix);
    lattice(p.y, iy, y_iy);
    lattice(p.z, iz, z_iz);
    const double x_jx = x_ix - 1, y_jy = y_iy - 1, z_jz = z_iz - 1;
    const double sx = scurve(x_ix), sy = scurve(y_iy), sz = scurve(z_iz);
    const double tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
    const double txty = tx * ty, sxty = sx * ty, txsy = tx * sy, sxsy = sx * sy;
    const int h00 = hash2d(h, ix, iy);
    const int h10 = hash2d(h, ix + 1, iy);
    const int h01 = hash2d(h, ix, iy + 1);
    const int h11 = hash2d(h, ix + 1, iy + 1);
    glm::dvec3 r(0.0);
    bool first = true;
    // Each corner's x, y and z components come from three consecutive table entries, eight
    // interleaved slots apart; the corners go in POV-Ray's order for DNoise.
    auto add = [&](int hash, int z_index, double s, double x, double y, double z) {
        const double* m = &rt[table_index(h, hash, z_index)];
        const double cx = corner(m, s, x, y, z);
        const double cy = corner(m + 8, s, x, y, z);
        const double cz = corner(m + 16, s, x, y, z);
        if (first) {
            r = glm::dvec3(cx, cy, cz);
            first = false;
        } else {
            r.x += cx;
            r.y += cy;
            r.z += cz;
        }
    };
    add(h00, iz, txty * tz, x_ix, y_iy, z_iz);
    add(h10, iz, sxty * tz, x_jx, y_iy, z_iz);
    add(h11, iz, sxsy * tz, x_jx, y_jy, z_iz);
    add(h01, iz, txsy * tz, x_ix, y_jy, z_iz);
    add(h01, iz + 1, txsy * sz, x_ix, y_jy, z_jz);
    add(h11, iz + 1, sxsy * sz, x_jx, y_jy, z_jz);
    add(h10, iz + 1, sxty * sz, x_jx, y_iy, z_jz);
    add(h00, iz + 1, txty * sz, x_ix, y_iy, z_jz);
    return r;
}

double turbulence(const glm::dvec3& p, const Turbulence& turb, int generator) {
    double value;
    if (generator > 1) {
        value = std::clamp(2.0 * noise(p, generator) - 0.5, 0.0, 1.0);
    } else {
        value = noise(p, generator);
    }
    // POV-Ray holds lambda and omega in single precision.
    const double lambda = to_single(turb.lambda), omega = to_single(turb.omega);
    double l = lambda;
    double o = omega;
    for (int i = 2; i <= turb.octaves; ++i) {
        const glm::dvec3 q(p.x * l, p.y * l, p.z * l);
        // The later octaves are not clipped (POV-Ray's Turbulence).
        if (generator > 1) {
            value += o * (2.0 * noise(q, generator) - 0.5);
        } else {
            value += o * noise(q, generator);
        }
        if (i < turb.octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return value;
}

glm::dvec3 dturbulence(const glm::dvec3& p, const Turbulence& turb) {
    glm::dvec3 result = dnoise(p);
    const double lambda = to_single(turb.lambda), omega = to_single(turb.omega);
    double l = lambda;
    double o = omega;
    for (int i = 2; i <= turb.octaves; ++i) {
        const glm::dvec3 v = dnoise(glm::dvec3(p.x * l, p.y * l, p.z * l));
        result.x += o * v.x;
        result.y += o * v.y;
        result.z += o * v.z;
        if (i < turb.octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return result;
}

double cycloidal(double value) {
    constexpr double kTwoPi = 6.283185307179586476925286766559;
    if (value >= 0.0) {
        return std::sin((value - std::floor(value)) * 50000.0 / 50000.0 * kTwoPi);
    }
    return 0.0 - std::sin((0.0 - (value + std::floor(0.0 - value))) * 50000.0 / 50000.0 * kTwoPi);
}

double triangle_wave(double value) {
    const double offset =
        value >= 0.0 ? value - std::floor(value) : value + 1.0 + std::floor(std::fabs(value));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

namespace {

struct PatternRands {
    std::vector<double> values;
    PatternRands() : values(32768) {
        // boost's uniform_real<double>(0, 1) over the default-seeded mt19937: draw / 2^32.
        std::mt19937 generator;
        for (double& v : values) v = static_cast<double>(generator()) / 4294967296.0;
    }
};

}  // namespace

double pattern_rand(std::size_t index) {
    static const PatternRands rands;
    return rands.values[index % rands.values.size()];
}

WaveSources make_wave_sources(int count) {
    WaveSources w;
    PovRand r{-560851967};
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 d = dnoise(glm::dvec3(static_cast<double>(i), 0.0, 0.0));
        const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        w.sources.push_back(length > 0.0 ? d / length : d);
        w.frequencies.push_back(static_cast<double>(r.next15()) * 0.000030518509476 + 0.01);
    }
    return w;
}

}  // namespace mirage
