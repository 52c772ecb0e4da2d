#include "patterns/warps.h"

#include <cmath>

#include "patterns/noise.h"

namespace mirage {

namespace {

constexpr double kEpsilon = 1.0e-10;
constexpr double kCoordinateLimit = 1.0e17;
constexpr double kPi = 3.1415926535897932384626;
constexpr double kTwoPi = 6.283185307179586476925286766560;

/// POV-Ray's MInvTransPoint: the inverse matrix applied to a point.
glm::dvec3 inverse_point(const Transform& t, const glm::dvec3& p) {
    const glm::dmat4& m = t.inverse;
    return glm::dvec3(p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0] + m[3][0],
                      p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1] + m[3][1],
                      p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2] + m[3][2]);
}

/// The mapped coordinates (x, y, z) of the cylindrical, spherical and toroidal warps, turned
/// to the warp's orientation as POV-Ray turns them.
glm::dvec3 orient(const Warp& w, double x, double y, double z) {
    const glm::dvec3& o = w.orientation;
    if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return glm::dvec3(x, y, z);
    return glm::dvec3(o.x * z + o.y * x + o.z * x, o.x * y + o.y * -z + o.z * y,
                      o.x * -x + o.y * y + o.z * z);
}

/// The angle about y from +x, 0 to 2 pi (the cylindrical and spherical warps).
double azimuth(double x, double z, double len) {
    if (z == 0.0) return x > 0 ? 0.0 : kPi;
    double theta = std::acos(x / len);
    if (z < 0.0) theta = kTwoPi - theta;
    return theta;
}

void warp_cylindrical(glm::dvec3& p, const Warp& w) {
    const double x = p.x, y = p.y, z = p.z;
    const double len = std::sqrt(x * x + z * z);
    if (len == 0.0) return;
    double theta = azimuth(x, z, len) / kTwoPi;
    if (w.dist_exp == 1.0) {
        theta *= len;
    } else if (w.dist_exp != 0.0) {
        theta *= std::pow(len, w.dist_exp);
    }
    p = orient(w, theta, y, len);
}

void warp_spherical(glm::dvec3& p, const Warp& w) {
    double x = p.x, y = p.y, z = p.z;
    const double dist = std::sqrt(x * x + y * y + z * z);
    if (dist == 0.0) return;
    x /= dist;
    y /= dist;
    z /= dist;
    double phi = 0.5 + std::asin(y) / kPi;
    const double len = std::sqrt(x * x + z * z);
    double theta = len == 0.0 ? 0.0 : azimuth(x, z, len) / kTwoPi;
    if (w.dist_exp == 1.0) {
        theta *= dist;
        phi *= dist;
    } else if (w.dist_exp != 0.0) {
        theta *= std::pow(dist, w.dist_exp);
        phi *= std::pow(dist, w.dist_exp);
    }
    p = orient(w, theta, phi, dist);
}

void warp_toroidal(glm::dvec3& p, const Warp& w) {
    double x = p.x;
    const double y = p.y, z = p.z;
    double len = std::sqrt(x * x + z * z);
    if (len == 0.0) return;
    double theta = 0.0 - azimuth(x, z, len);
    x = len - w.major_radius;
    len = std::sqrt(x * x + y * y);
    double phi = std::acos(-x / len);
    if (y > 0.0) phi = kTwoPi - phi;
    theta /= -kTwoPi;
    phi /= kTwoPi;
    if (w.dist_exp == 1.0) {
        theta *= len;
        phi *= len;
    } else if (w.dist_exp != 0.0) {
        theta *= std::pow(len, w.dist_exp);
        phi *= std::pow(len, w.dist_exp);
    }
    p = orient(w, theta, phi, len);
}

void warp_planar(glm::dvec3& p, const Warp& w) { p = orient(w, p.x, p.y, w.planar_offset); }

// The cube's six faces unfolded into a cross on the unit square (POV-Ray's CubicWarp): the
// face the point's largest coordinate picks, the other two divided by it; z keeps that
// coordinate's size.
void warp_cubic(glm::dvec3& p) {
    const double x = p.x, y = p.y, z = p.z;
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    constexpr double third = 1.0 / 3.0;
    if (x >= 0 && x >= ay && x >= az) {
        p = glm::dvec3(0.75 - 0.25 * (z / x + 1.0) / 2.0, third + third * (y / x + 1.0) / 2.0, x);
    } else if (y >= 0 && y >= ax && y >= az) {
        p = glm::dvec3(0.25 + 0.25 * (x / y + 1.0) / 2.0, 1.0 - third * (z / y + 1.0) / 2.0, y);
    } else if (z >= 0 && z >= ax && z >= ay) {
        p = glm::dvec3(0.25 + 0.25 * (x / z + 1.0) / 2.0, third + third * (y / z + 1.0) / 2.0, z);
    } else if (x < 0 && x <= -ay && x <= -az) {
        const double m = -x;
        p = glm::dvec3(0.25 * (z / m + 1.0) / 2.0, third + third * (y / m + 1.0) / 2.0, m);
    } else if (y < 0 && y <= -ax && y <= -az) {
        const double m = -y;
        p = glm::dvec3(0.25 + 0.25 * (x / m + 1.0) / 2.0, third * (z / m + 1.0) / 2.0, m);
    } else {
        const double m = -z;
        p = glm::dvec3(1.0 - 0.25 * (x / m + 1.0) / 2.0, third + third * (y / m + 1.0) / 2.0, m);
    }
}

void warp_repeat(glm::dvec3& p, const Warp& w) {
    glm::dvec3 r = p;
    const int axis = w.axis;
    // POV-Ray keeps the block number in single precision.
    const float block = static_cast<float>(std::floor(p[axis] / w.width));
    r[axis] = p[axis] - block * w.width;
    if (static_cast<int>(block) & 1) {
        r *= w.flip;
        if (w.flip[axis] < 0) r[axis] = w.width + r[axis];
    }
    r += static_cast<double>(block) * w.offset;
    p = r;
}

void warp_black_hole(glm::dvec3& p, const Warp& w) {
    glm::dvec3 centre = w.centre;
    if (w.repeat) {
        int bx = 0, by = 0, bz = 0;
        if (w.repeat_vector.x >= kEpsilon)
            bx = static_cast<int>(std::floor(p.x / w.repeat_vector.x));
        if (w.repeat_vector.y >= kEpsilon)
            by = static_cast<int>(std::floor(p.y / w.repeat_vector.y));
        if (w.repeat_vector.z >= kEpsilon)
            bz = static_cast<int>(std::floor(p.z / w.repeat_vector.z));
        if (w.uncertain) {
            // POV-Ray's WarpRands is the same sequence as its PatternRands.
            const int seed = hash3d(bx, by, bz);
            centre.x += pattern_rand(seed) * w.uncertainty.x;
            centre.y += pattern_rand(seed + 1) * w.uncertainty.y;
            centre.z += pattern_rand(seed + 2) * w.uncertainty.z;
        }
        centre.x += w.repeat_vector.x * bx;
        centre.y += w.repeat_vector.y * by;
        centre.z += w.repeat_vector.z * bz;
    }
    glm::dvec3 delta = p - centre;
    double length = std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z);
    if (length >= w.radius) return;
    length = (w.radius - length) / w.radius;
    double strength = std::pow(length, w.power) * w.strength;
    if (strength > 1.0) strength = 1.0;
    delta *= w.inverse ? -strength : strength;
    p += delta;
}

}  // namespace

bool pattern_applies_own_turbulence(PatternKind kind) {
    return kind == PatternKind::Marble || kind == PatternKind::Wood;
}

glm::dvec3 warp_point(const Pattern& pattern, const glm::dvec3& point) {
    glm::dvec3 p = inverse_point(pattern.transform, point);
    for (const Warp& w : pattern.warps) {
        switch (w.kind) {
            case Warp::Kind::Transform:
                p = inverse_point(w.transform, p);
                break;
            case Warp::Kind::Turbulence: {
                const glm::dvec3 d = dturbulence(p, w.turbulence);
                p.x += d.x * w.turbulence.amount.x;
                p.y += d.y * w.turbulence.amount.y;
                p.z += d.z * w.turbulence.amount.z;
                break;
            }
            case Warp::Kind::Repeat:
                warp_repeat(p, w);
                break;
            case Warp::Kind::BlackHole:
                warp_black_hole(p, w);
                break;
            case Warp::Kind::Cylindrical:
                warp_cylindrical(p, w);
                break;
            case Warp::Kind::Spherical:
                warp_spherical(p, w);
                break;
            case Warp::Kind::Toroidal:
                warp_toroidal(p, w);
                break;
            case Warp::Kind::Planar:
                warp_planar(p, w);
                break;
            case Warp::Kind::Cubic:
                warp_cubic(p);
                break;
        }
    }
    if (pattern.turbulence && !pattern_applies_own_turbulence(pattern.kind)) {
        const Turbulence& t = *pattern.turbulence;
        const glm::dvec3 d = dturbulence(p, t);
        p.x += d.x * t.amount.x;
        p.y += d.y * t.amount.y;
        p.z += d.z * t.amount.z;
    }
    for (int i = 0; i < 3; ++i) {
        if (p[i] > kCoordinateLimit) {
            p[i] = kCoordinateLimit;
        } else if (p[i] < -kCoordinateLimit) {
            p[i] = -kCoordinateLimit;
        }
    }
    return p;
}

namespace {

glm::dvec3 normalized(const glm::dvec3& v) {
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return len > 0.0 ? v * (1.0 / len) : v;
}

/// POV-Ray's MInvTransNormal: the transpose of the matrix applied to a normal.
glm::dvec3 inverse_normal(const Transform& t, const glm::dvec3& n) {
    const glm::dmat4& m = t.matrix;
    return glm::dvec3(n.x * m[0][0] + n.y * m[0][1] + n.z * m[0][2],
                      n.x * m[1][0] + n.y * m[1][1] + n.z * m[1][2],
                      n.x * m[2][0] + n.y * m[2][1] + n.z * m[2][2]);
}

/// POV-Ray's MTransNormal: the transpose of the inverse applied to a normal.
glm::dvec3 forward_normal(const Transform& t, const glm::dvec3& n) {
    const glm::dmat4& m = t.inverse;
    return glm::dvec3(n.x * m[0][0] + n.y * m[0][1] + n.z * m[0][2],
                      n.x * m[1][0] + n.y * m[1][1] + n.z * m[1][2],
                      n.x * m[2][0] + n.y * m[2][1] + n.z * m[2][2]);
}

}  // namespace

glm::dvec3 warp_normal(const Pattern& pattern, const glm::dvec3& normal, bool dont_scale_bumps) {
    glm::dvec3 n = dont_scale_bumps ? normal : normalized(normal);
    n = inverse_normal(pattern.transform, n);
    for (const Warp& w : pattern.warps) {
        if (w.kind == Warp::Kind::Transform) n = inverse_normal(w.transform, n);
    }
    return dont_scale_bumps ? n : normalized(n);
}

glm::dvec3 unwarp_normal(const Pattern& pattern, const glm::dvec3& normal, bool dont_scale_bumps) {
    glm::dvec3 n = dont_scale_bumps ? normal : normalized(normal);
    for (auto it = pattern.warps.rbegin(); it != pattern.warps.rend(); ++it) {
        if (it->kind == Warp::Kind::Transform) n = forward_normal(it->transform, n);
    }
    n = forward_normal(pattern.transform, n);
    return dont_scale_bumps ? n : normalized(n);
}

}  // namespace mirage
