#include "patterns/image_map.h"

#include <cmath>

#include "patterns/single_precision.h"

namespace mirage {

namespace {

constexpr double kEpsilon = 1.0e-10;
constexpr double kPi = 3.1415926535897932384626;
constexpr double kTwoPi = 6.283185307179586476925286766560;

/// POV-Ray's wrap: fmod into [0, limit).
double wrap(double v, double limit) {
    double t = std::fmod(v, limit);
    if (t < 0.0) t += limit;
    if (t >= limit) t = 0.0;
    return t;
}

double azimuth01(double x, double z, double len) {
    double theta;
    if (z == 0.0) {
        theta = x > 0 ? 0.0 : kPi;
    } else {
        theta = std::acos(x / len);
        if (z < 0.0) theta = kTwoPi - theta;
    }
    return theta / kTwoPi;
}

/// The map's coordinates in pixels (POV-Ray's map_pos); false when the point maps to nothing.
bool map_position(const Pattern& pat, const glm::dvec3& p, double& u, double& v) {
    const ImageData& img = *pat.image;
    const double width = img.width * pat.image_repeat.x;
    const double height = img.height * pat.image_repeat.y;
    u = 0.0;
    v = 0.0;
    double x = p.x, y = p.y, z = p.z;
    switch (pat.map_type) {
        case 1: {  // spherical
            double len = std::sqrt(x * x + y * y + z * z);
            if (len == 0.0) return false;
            x /= len;
            y /= len;
            z /= len;
            const double phi = 0.5 + std::asin(y) / kPi;
            len = std::sqrt(x * x + z * z);
            const double theta = len == 0.0 ? 0.0 : azimuth01(x, z, len);
            u = theta * width;
            v = phi * height;
            break;
        }
        case 2: {  // cylindrical
            if (pat.once && (y < 0.0 || y > 1.0)) return false;
            v = std::fmod(y * height, height);
            double len = std::sqrt(x * x + y * y + z * z);
            if (len == 0.0) return false;
            x /= len;
            z /= len;
            len = std::sqrt(x * x + z * z);
            if (len == 0.0) return false;
            u = azimuth01(x, z, len) * width;
            break;
        }
        case 5: {  // torus
            const double r0 = pat.image_gradient.x;
            double len = std::sqrt(x * x + z * z);
            if (len == 0.0) return false;
            const double theta = -azimuth01(x, z, len);
            x = len - r0;
            len = std::sqrt(x * x + y * y);
            double phi = std::acos(-x / len);
            if (y > 0.0) phi = kTwoPi - phi;
            phi /= kTwoPi;
            u = -theta * width;
            v = phi * height;
            break;
        }
        default: {  // planar
            const glm::dvec3& g = pat.image_gradient;
            const double c[3] = {x, y, z};
            for (int i = 0; i < 3; ++i) {
                if (g[i] == 0.0) continue;
                if (pat.once && (c[i] < 0.0 || c[i] > 1.0)) return false;
                if (g[i] > 0) {
                    u = std::fmod(c[i] * width, width);
                } else {
                    v = std::fmod(c[i] * height, height);
                }
            }
            break;
        }
    }
    u += -pat.image_offset.x * img.width + kEpsilon;
    v += -pat.image_offset.y * img.height + kEpsilon;
    if (pat.once && (u >= img.width || v >= img.height || u < 0.0 || v < 0.0)) return false;
    u = wrap(u, img.width);
    v = wrap(-v, img.height);  // images are stored top row first
    return true;
}

PigmentColour pixel(const Pattern& pat, double u, double v, int& index) {
    const ImageData& img = *pat.image;
    int ix, iy;
    if (pat.once) {
        ix = u < 0.0 ? 0 : u >= img.width ? img.width - 1 : static_cast<int>(u);
        iy = v < 0.0 ? 0 : v >= img.height ? img.height - 1 : static_cast<int>(v);
    } else {
        ix = static_cast<int>(wrap(u, img.width));
        iy = static_cast<int>(wrap(v, img.height));
    }
    const std::size_t at = static_cast<std::size_t>(iy) * img.width + ix;
    const float* px = &img.pixels[at * 5];
    PigmentColour c;
    c.rgb = glm::dvec3(px[0], px[1], px[2]);
    c.filter = px[3];
    c.transmit = px[4];
    if (img.is_indexed) {
        index = img.indices[at];
    } else {
        index = -1;
        c.transmit += pat.transmit_all;
        c.filter += pat.filter_all;
    }
    return c;
}

/// POV-Ray's cubic: the four weights of a Catmull-Rom step at the fraction of x.
void cubic_factors(double x, double f[4]) {
    const double p = x - static_cast<int>(x);
    const double q = 1 - p;
    f[0] = -0.5 * p * q * q;
    f[1] = 0.5 * q * (q * (3 * p + 1) + 1);
    f[2] = 0.5 * p * (p * (3 * q + 1) + 1);
    f[3] = -0.5 * q * p * p;
}

PigmentColour colour_at(const Pattern& pat, double u, double v, int& index) {
    if (pat.interpolate == 3) {
        // InterpolateBicubic: 4 x 4 pixels around the point.
        u += 0.5;
        v += 0.5;
        const int iu = static_cast<int>(u), iv = static_cast<int>(v);
        double fx[4], fy[4];
        cubic_factors(u, fx);
        cubic_factors(v, fy);
        PigmentColour out;
        double index_sum = 0.0;
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
                int idx;
                const PigmentColour c = pixel(pat, iu + i - 2.0, iv + j - 2.0, idx);
                const double f = fx[i] * fy[j];
                out.rgb += c.rgb * f;
                out.filter += c.filter * f;
                out.transmit += c.transmit * f;
                index_sum += idx * f;
            }
        }
        index = static_cast<int>(index_sum);
        return out;
    }
    if (pat.interpolate != 2 && pat.interpolate != 4) return pixel(pat, u, v, index);
    u += 0.5;
    v += 0.5;
    const int iu = static_cast<int>(u), iv = static_cast<int>(v);
    int idx[4];
    const PigmentColour c[4] = {pixel(pat, iu, iv, idx[0]), pixel(pat, iu - 1.0, iv, idx[1]),
                                pixel(pat, iu, iv - 1.0, idx[2]),
                                pixel(pat, iu - 1.0, iv - 1.0, idx[3])};
    const double p = u - static_cast<int>(u), q = v - static_cast<int>(v);
    double f[4];
    if (pat.interpolate == 2) {
        f[0] = p * q;
        f[1] = (1 - p) * q;
        f[2] = p * (1 - q);
        f[3] = (1 - p) * (1 - q);
    } else {
        const double w[4] = {1.0 / ((1 - p) * (1 - p) + (1 - q) * (1 - q)),
                             1.0 / (p * p + (1 - q) * (1 - q)), 1.0 / ((1 - p) * (1 - p) + q * q),
                             1.0 / (p * p + q * q)};
        const double sum = w[0] + w[1] + w[2] + w[3];
        for (int i = 0; i < 4; ++i) f[i] = w[i] / sum;
    }
    PigmentColour out;
    double index_sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        out.rgb += c[i].rgb * f[i];
        out.filter += c[i].filter * f[i];
        out.transmit += c[i].transmit * f[i];
        index_sum += idx[i] * f[i];
    }
    index = static_cast<int>(index_sum);
    return out;
}

}  // namespace

bool image_map_colour(const Pattern& pattern, const glm::dvec3& p, PigmentColour& out) {
    double u, v;
    if (!pattern.image || !map_position(pattern, p, u, v)) {
        out = PigmentColour{glm::dvec3(1.0), 0.0, 1.0};
        return false;
    }
    int index;
    out = colour_at(pattern, u, v, index);
    return true;
}

void bump_map_normal(const Normal& n, const glm::dvec3& p, glm::dvec3& normal) {
    double u, v;
    if (!n.image || !map_position(n, p, u, v)) return;
    const ImageData& img = *n.image;
    int i1, i2, i3;
    const PigmentColour c1 = colour_at(n, u, v, i1);
    u -= 1.0;
    v += 1.0;
    if (u < 0.0) {
        u += img.width;
    } else if (u >= img.width) {
        u -= img.width;
    }
    if (v < 0.0) {
        v += img.height;
    } else if (v >= img.height) {
        v -= img.height;
    }
    const PigmentColour c2 = colour_at(n, u, v, i2);
    u += 2.0;
    if (u < 0.0) {
        u += img.width;
    } else if (u >= img.width) {
        u -= img.width;
    }
    const PigmentColour c3 = colour_at(n, u, v, i3);
    const double amount = to_single(n.amount);
    const bool by_colour = !n.use_index || i1 == -1 || i2 == -1 || i3 == -1;
    const glm::dvec3 p1(0, amount * (by_colour ? greyscale(c1.rgb) : i1), 0);
    const glm::dvec3 p2(-1, amount * (by_colour ? greyscale(c2.rgb) : i2), 1);
    const glm::dvec3 p3(1, amount * (by_colour ? greyscale(c3.rgb) : i3), 1);
    glm::dvec3 bump = glm::cross(p3 - p2, p1 - p2);
    bump = glm::normalize(bump);
    glm::dvec3 yprime = normal;
    glm::dvec3 xprime = glm::cross(yprime, glm::dvec3(0.0, 1.0, 0.0));
    double length = glm::length(xprime);
    if (length < kEpsilon) {
        yprime = std::fabs(normal.y - 1.0) < kEpsilon ? glm::dvec3(0, 1, 0) : glm::dvec3(0, -1, 0);
        xprime = glm::dvec3(1, 0, 0);
        length = 1.0;
    }
    xprime *= 1.0 / length;
    glm::dvec3 zprime = glm::normalize(glm::cross(xprime, yprime));
    normal = xprime * bump.x + yprime * bump.y - zprime * bump.z;
}

}  // namespace mirage
