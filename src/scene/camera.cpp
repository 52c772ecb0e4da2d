// Camera statement semantics and primary rays, after POV-Ray 3.7's parse.cpp and
// render/tracepixel.cpp.
#include "scene/camera.h"

#include <algorithm>
#include <cmath>

#include "scene/transform.h"

namespace mirage {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON
constexpr double kPi = 3.14159265358979323846;

/// `v` turned by `angle` (rad) about `axis` (any length), as POV-Ray's
/// Compute_Axis_Rotation_Transform turns points.
glm::dvec3 rotate_about_axis(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
    const glm::dvec3 a = glm::normalize(axis);
    const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    // POV-Ray's matrix (row vectors, points multiply from the left).
    const glm::dmat3 m(t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y,
                       t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x,
                       t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c);
    // glm's columns are POV-Ray's rows, so m * v is POV-Ray's row vector v times its matrix.
    return m * v;
}

}  // namespace

CameraRay camera_ray(const Camera& camera, double x, double y, int width, int height) {
    // POV-Ray is called with the pixel's integer coordinates, moves them by half a pixel
    // (x + 0.5, y - 0.5) and takes x0 = x / width - 0.5, y0 = ((height - 1) - y) / height - 0.5.
    // In image coordinates (the centre of pixel (col, row) at (col + 0.5, row + 0.5)) its
    // shifted y is ours minus 1; the same expressions keep its rounding, bit for bit.
    const double py = y - 1.0;
    const double x0 = x / width - 0.5;
    const double y0 = ((height - 1.0) - py) / height - 0.5;
    glm::dvec3 right = camera.right, up = camera.up, direction = camera.direction;
    const double length_right = glm::length(right), length_up = glm::length(up);
    double aspect = length_right / length_up;
    // The projections other than the perspective and orthographic ones use unit vectors and
    // take the aspect ratio from their lengths (TracePixel's constructor).
    switch (camera.type) {
        case CameraType::Cylinder1:
        case CameraType::Cylinder3:
            aspect = length_up;
            break;
        case CameraType::Cylinder2:
        case CameraType::Cylinder4:
            aspect = length_right;
            break;
        case CameraType::UltraWideAngle:
            aspect = length_up / length_right;
            break;
        default:
            break;
    }
    if (camera.type != CameraType::Perspective && camera.type != CameraType::Orthographic &&
        camera.type != CameraType::Panoramic && camera.type != CameraType::Spherical) {
        right = glm::normalize(right);
        up = glm::normalize(up);
        direction = glm::normalize(direction);
    }
    CameraRay ray{camera.location, glm::normalize(camera.direction), true};
    const double angle_rad = camera.angle_deg * kPi / 180.0;
    glm::dvec3 d(0.0);
    switch (camera.type) {
        case CameraType::Perspective:
            d = direction + x0 * right + y0 * up;
            break;
        case CameraType::Orthographic:
            d = direction;
            ray.origin = camera.location + x0 * right + y0 * up;
            break;
        case CameraType::Fisheye:
        case CameraType::Omnimax: {
            double fx = 2.0 * x / width - 1.0;
            double fy = 2.0 * ((height - 1.0) - py) / height - 1.0;
            if (camera.type == CameraType::Fisheye) {
                fx *= length_right;
                fy *= length_up;
            } else if (aspect > 1.0) {
                if (aspect > 1.283458) {
                    fx *= aspect / 1.283458;
                    fy = (fy - 1.0) / 1.283458 + 1.0;
                } else {
                    fy = (fy - 1.0) / aspect + 1.0;
                }
            } else {
                fy /= aspect;
            }
            // Outside the unit circle POV-Ray traces no ray; the direction the mapping would
            // give is kept (distinct per pixel, for callers that need one for every pixel).
            const double rad = std::sqrt(fx * fx + fy * fy);
            if (rad > 1.0) ray.traced = false;
            double phi = 0.0;
            if (rad != 0.0) phi = fx < 0.0 ? kPi - std::asin(fy / rad) : std::asin(fy / rad);
            const double theta = camera.type == CameraType::Fisheye
                                     ? rad * camera.angle_deg * kPi / 360.0
                                     : 1.411269 * rad - 0.09439 * rad * rad * rad +
                                           0.25674 * rad * rad * rad * rad * rad;
            const double cx = std::cos(phi), sx = std::sin(phi);
            const double cy = std::cos(theta), sy = std::sin(theta);
            if (camera.type == CameraType::Omnimax &&
                sx * sy < std::tan(135.0 * kPi / 180.0) * cy) {
                ray.traced = false;
            }
            d = cx * sy * right + sx * sy * up + cy * direction;
            break;
        }
        case CameraType::Panoramic: {
            const double px = (1.0 - x / width) * kPi;
            const double pyy = kPi / 2.0 * (2.0 * ((height - 1.0) - py) / height - 1.0);
            double ty;
            if (std::abs(kPi / 2.0 - std::abs(pyy)) < kEpsilon) {
                ty = pyy > 0.0 ? 2.0e10 : -2.0e10;
            } else {
                ty = std::tan(pyy);
            }
            d = std::cos(px) * right + ty * up + std::sin(px) * direction;
            break;
        }
        case CameraType::UltraWideAngle: {
            const double ax = x0 * angle_rad;
            const double ay = y0 * angle_rad * aspect;
            d = std::sin(ax) * right + std::sin(ay) * up + std::cos(ax) * std::cos(ay) * direction;
            break;
        }
        case CameraType::Cylinder1:
        case CameraType::Cylinder3: {
            const double ax = x0 * angle_rad;
            const double h = y0 * aspect;
            if (camera.type == CameraType::Cylinder1) {
                d = std::sin(ax) * right + h * up + std::cos(ax) * direction;
            } else {
                d = std::sin(ax) * right + std::cos(ax) * direction;
                ray.origin = camera.location + h * up;
            }
            break;
        }
        case CameraType::Cylinder2:
        case CameraType::Cylinder4: {
            const double ay = y0 * angle_rad;
            const double w = x0 * aspect;
            if (camera.type == CameraType::Cylinder2) {
                d = w * right + std::sin(ay) * up + std::cos(ay) * direction;
            } else {
                d = std::sin(ay) * up + std::cos(ay) * direction;
                ray.origin = camera.location + w * right;
            }
            break;
        }
        case CameraType::Spherical: {
            const double v_angle =
                camera.v_angle_deg > 0.0 ? camera.v_angle_deg : camera.angle_deg * 0.5;
            const double lat = y0 * (v_angle / 360.0) * 2.0 * kPi;
            const double lon = x0 * (camera.angle_deg / 360.0) * 2.0 * kPi;
            // POV-Ray turns direction about right by -latitude, then about up by longitude.
            const glm::dvec3 v1 = rotate_about_axis(direction, right, -lat);
            d = rotate_about_axis(v1, up, lon);
            break;
        }
    }
    ray.direction = glm::normalize(d);
    return ray;
}

bool camera_has_one_viewpoint(const Camera& camera) {
    return camera.type != CameraType::Orthographic && camera.type != CameraType::Cylinder3 &&
           camera.type != CameraType::Cylinder4;
}

std::string camera_type_name(CameraType type) {
    switch (type) {
        case CameraType::Perspective:
            return "perspective";
        case CameraType::Orthographic:
            return "orthographic";
        case CameraType::Fisheye:
            return "fisheye";
        case CameraType::UltraWideAngle:
            return "ultra_wide_angle";
        case CameraType::Omnimax:
            return "omnimax";
        case CameraType::Panoramic:
            return "panoramic";
        case CameraType::Cylinder1:
            return "cylinder 1";
        case CameraType::Cylinder2:
            return "cylinder 2";
        case CameraType::Cylinder3:
            return "cylinder 3";
        case CameraType::Cylinder4:
            return "cylinder 4";
        case CameraType::Spherical:
            return "spherical";
    }
    return "camera";
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

double pixel_angle_rad(const Camera& camera, int width, int height) {
    const glm::dvec3 a =
        camera_ray(camera, 0.5 * width, 0.5 * height - 0.5, width, height).direction;
    const glm::dvec3 b =
        camera_ray(camera, 0.5 * width, 0.5 * height + 0.5, width, height).direction;
    return angle_between(a, b);
}

Result<PixelFootprint> pixel_footprint(const Camera& camera, int width, int height) {
    constexpr double kRel = 1e-9;
    const glm::dvec3 d = glm::normalize(camera.direction);
    PixelFootprint fp;
    switch (camera.type) {
        case CameraType::Orthographic: {
            // The components of right / width and up / height perpendicular to the rays span
            // the pixel's parallelogram; a displacement perpendicular to the rays smaller than
            // its smaller height stays within one pixel.
            const glm::dvec3 r = camera.right / static_cast<double>(width);
            const glm::dvec3 u = camera.up / static_cast<double>(height);
            const glm::dvec3 rp = r - glm::dot(r, d) * d, up = u - glm::dot(u, d) * d;
            const double area = glm::length(glm::cross(rp, up));
            const double longest = std::max(glm::length(rp), glm::length(up));
            fp.distance = longest > 0.0 ? area / longest : 0.0;
            return fp;
        }
        case CameraType::Cylinder3: {
            const double lu = glm::length(camera.up);
            const bool level =
                lu > 0.0 && camera.up.y > 0.0 && std::abs(camera.up.x) <= kRel * lu &&
                std::abs(camera.up.z) <= kRel * lu &&
                std::abs(camera.direction.y) <= kRel * glm::length(camera.direction) &&
                std::abs(camera.right.y) <= kRel * glm::length(camera.right);
            if (!level)
                return make_error(
                    "the cylinder 3 camera is not level (up vertical, direction and right "
                    "horizontal): its rows are offset along up and its columns turned, and "
                    "mirage follows its curved rays only when a ray's vertical plane meets the "
                    "rows alone");
            // TracePixel: the origin moves by y0 |up| along the unit up vector.
            fp.distance = lu / height;
            return fp;
        }
        case CameraType::Cylinder4: {
            const double lr = glm::length(camera.right);
            const glm::dvec3 r = camera.right / lr;
            const bool plane = lr > 0.0 && std::abs(r.y) <= kRel &&
                               std::abs(glm::dot(r, glm::normalize(camera.up))) <= kRel &&
                               std::abs(glm::dot(r, d)) <= kRel;
            if (!plane)
                return make_error(
                    "the cylinder 4 camera's right vector is not horizontal and perpendicular "
                    "to up and direction: its columns are offset along right and its rows "
                    "turned, and mirage follows its curved rays only when a ray's vertical "
                    "plane meets the rows alone");
            fp.angle_rad = camera.angle_deg * kPi / 180.0 / height;
            return fp;
        }
        default:
            fp.angle_rad = pixel_angle_rad(camera, width, height);
            return fp;
    }
}

Result<CameraState> apply_camera_statement(const CameraState& base, const CameraModifiers& mods) {
    CameraState cam = base;
    if (mods.type) cam.type = *mods.type;
    if (mods.location) cam.location = *mods.location;
    if (mods.direction) cam.direction = *mods.direction;
    if (mods.up) cam.up = *mods.up;
    if (mods.right) cam.right = *mods.right;
    if (mods.sky) cam.sky = *mods.sky;
    const bool flat = cam.type == CameraType::Perspective || cam.type == CameraType::Orthographic;

    if (mods.angle_deg) {
        double angle = *mods.angle_deg;
        if (angle < 0.0) return make_error("negative viewing angle");
        if (flat) {
            if (angle >= 180.0) return make_error("viewing angle must be smaller than 180 degrees");
            if (angle > 0.0) {
                double length = glm::length(cam.right) / std::tan(angle * kPi / 360.0) / 2.0;
                cam.direction = glm::normalize(cam.direction) * length;
            }
            cam.angle_deg = angle;
        }
        cam.angle_deg_given = angle;
        if (cam.type == CameraType::Spherical) cam.v_angle_deg = mods.v_angle_deg.value_or(0.0);
    }

    if (mods.look_at) {
        double direction_length = glm::length(cam.direction);
        double up_length = glm::length(cam.up);
        double right_length = glm::length(cam.right);
        double handedness = glm::dot(glm::cross(cam.up, cam.direction), cam.right);

        glm::dvec3 direction = *mods.look_at - cam.location;
        if (glm::dot(direction, direction) < kEpsilon) {
            return make_error("the camera location and look_at point must be different");
        }
        direction = glm::normalize(direction);
        glm::dvec3 right = glm::cross(cam.sky, direction);
        // Looking along the sky: POV-Ray keeps the right vector it had.
        if (std::abs(right.x) < kEpsilon && std::abs(right.y) < kEpsilon &&
            std::abs(right.z) < kEpsilon) {
            right = cam.right;
        }
        right = glm::normalize(right);
        glm::dvec3 up = glm::cross(direction, right);
        cam.direction = direction * direction_length;
        cam.right = right * (handedness > 0.0 ? right_length : -right_length);
        cam.up = up * up_length;
        cam.look_at = *mods.look_at;
    }

    if (cam.type == CameraType::Orthographic && ((!mods.up && !mods.right) || mods.angle_deg)) {
        // POV-Ray resizes right and up to show the area a perspective camera shows at the
        // look_at distance.
        const double k1 = glm::length(cam.look_at - cam.location);
        const double k2 = glm::length(cam.direction);
        if (k1 > kEpsilon && k2 > kEpsilon) {
            cam.right *= k1 / k2;
            cam.up *= k1 / k2;
        }
    }

    cam.location = transform_point(mods.transform, cam.location);
    cam.direction = transform_direction(mods.transform, cam.direction);
    cam.up = transform_direction(mods.transform, cam.up);
    cam.right = transform_direction(mods.transform, cam.right);
    return cam;
}

Camera camera_from_state(const CameraState& state) {
    Camera camera;
    camera.type = state.type;
    camera.angle_deg = state.angle_deg_given;
    camera.v_angle_deg = state.v_angle_deg;
    camera.location = state.location;
    camera.direction = state.direction;
    camera.right = state.right;
    camera.up = state.up;
    camera.sky = state.sky;
    return camera;
}

bool camera_vectors_perpendicular(const CameraState& s) {
    return std::abs(glm::dot(s.right, s.up)) <= kEpsilon &&
           std::abs(glm::dot(s.right, s.direction)) <= kEpsilon &&
           std::abs(glm::dot(s.up, s.direction)) <= kEpsilon;
}

}  // namespace mirage
