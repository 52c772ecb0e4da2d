// Camera statement semantics and primary rays, after POV-Ray 3.7's parse.cpp and
// render/tracepixel.cpp.
#include "scene/camera.h"

#include <cmath>

#include "scene/transform.h"

namespace mirage {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON
constexpr double kPi = 3.14159265358979323846;

}  // namespace

CameraRay camera_ray(const Camera& camera, double x, double y, int width, int height) {
    // POV-Ray is called with the pixel's integer coordinates, moves them by half a pixel
    // (x + 0.5, y - 0.5) and takes x0 = x / width - 0.5, y0 = ((height - 1) - y) / height - 0.5.
    // In image coordinates (the centre of pixel (col, row) at (col + 0.5, row + 0.5)) its
    // shifted y is ours minus 1; the same expression keeps its rounding, bit for bit.
    const double x0 = x / width - 0.5;
    const double y0 = ((height - 1.0) - (y - 1.0)) / height - 0.5;
    glm::dvec3 d = camera.direction + x0 * camera.right + y0 * camera.up;
    return CameraRay{camera.location, glm::normalize(d)};
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

Result<CameraState> apply_camera_statement(const CameraState& base, const CameraModifiers& mods) {
    CameraState cam = base;
    if (mods.location) cam.location = *mods.location;
    if (mods.direction) cam.direction = *mods.direction;
    if (mods.up) cam.up = *mods.up;
    if (mods.right) cam.right = *mods.right;
    if (mods.sky) cam.sky = *mods.sky;

    if (mods.angle_deg) {
        double angle = *mods.angle_deg;
        if (angle < 0.0) return make_error("negative viewing angle");
        if (angle >= 180.0) return make_error("viewing angle must be smaller than 180 degrees");
        if (angle > 0.0) {
            double length = glm::length(cam.right) / std::tan(angle * kPi / 360.0) / 2.0;
            cam.direction = glm::normalize(cam.direction) * length;
        }
        cam.angle_deg = angle;
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

    cam.location = transform_point(mods.transform, cam.location);
    cam.direction = transform_direction(mods.transform, cam.direction);
    cam.up = transform_direction(mods.transform, cam.up);
    cam.right = transform_direction(mods.transform, cam.right);
    return cam;
}

Camera camera_from_state(const CameraState& state) {
    Camera camera;
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
