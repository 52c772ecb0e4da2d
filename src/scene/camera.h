// POV-Ray's cameras: how a `camera { ... }` statement sets its vectors (POV-Ray 3.5 and later
// apply the modifiers in a fixed order, whatever order they are written in) and the primary
// ray POV-Ray 3.7 shoots through an image position for each projection.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

struct CameraRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};  // normalised
    bool traced = true;  // false where POV-Ray traces no ray (outside a fisheye's circle) and
                         // shows black; the direction continues the projection's mapping
};

/// The primary ray POV-Ray 3.7 traces for image position (x, y) in pixels of a width x height
/// image: (col + 0.5, row + 0.5) is the centre of pixel (col, row), row 0 at the top.  As in
/// POV-Ray's TracePixel::CreateCameraRay: for the perspective camera the ray leaves `location`
/// along direction + (x / width - 1/2) right + (1/2 - y / height) up (the image aspect ratio
/// is not applied, the lengths of right and up carry it); the orthographic camera moves the
/// origin instead; fisheye, ultra_wide_angle, omnimax, panoramic, cylinder 1 to 4 and
/// spherical map the position to angles as POV-Ray does.
CameraRay camera_ray(const Camera& camera, double x, double y, int width, int height);

/// True when every primary ray leaves the camera's location (all but the orthographic camera
/// and cylinders 3 and 4).
bool camera_has_one_viewpoint(const Camera& camera);

/// The projection's name as POV-Ray spells it ("perspective", "cylinder 3"...).
std::string camera_type_name(CameraType type);

/// The angle between two directions (any lengths), rad; accurate for tiny angles too, where
/// acos of the dot product is not.
double angle_between(const glm::dvec3& a, const glm::dvec3& b);

/// The angle one pixel subtends at the image's centre, between the camera rays through the
/// centre column half a pixel above and below the centre: the unit of tolerances in pixels.
double pixel_angle_rad(const Camera& camera, int width, int height);

/// One pixel's size along a camera ray, the unit of tolerances in pixels for every camera: at
/// path length s from the ray's own origin, a displacement of the ray within its vertical
/// plane of at most `distance + angle_rad * s` moves it by at most one pixel in the image.
/// For a camera with one eye point it is the angle of one pixel seen from the eye (distance 0,
/// angle_rad pixel_angle_rad).  An orthographic camera's rays are parallel: its rows and
/// columns are distances apart, perpendicular to the rays (angle 0; distance the smaller
/// height of the pixel's parallelogram).  A cylinder 3 camera's rows are offset along up and
/// its columns turn about it: a level one (up vertical, direction and right horizontal) moves
/// a ray within its vertical plane only across rows, |up| / height apart.  A cylinder 4
/// camera's columns are offset along right and its rows turn in the plane of up and
/// direction: with right horizontal and perpendicular to both, that plane is each ray's
/// vertical plane, and a row is the angle angle / height from the ray's own origin.
struct PixelFootprint {
    double distance = 0.0;   // scene units
    double angle_rad = 0.0;  // rad, times the path length from the ray's origin
};

/// The footprint of one pixel of a width x height image; fails (naming the camera's type)
/// for a cylinder 3 camera that is not level and a cylinder 4 camera whose right vector is
/// not horizontal or not perpendicular to up and direction: a ray's vertical displacement then
/// mixes rows offset by a distance with columns turned by an angle, which one allowance of the
/// form distance + angle * s does not bound.
Result<PixelFootprint> pixel_footprint(const Camera& camera, int width, int height);

/// The state POV-Ray keeps for a camera while parsing: its vectors plus look_at and angle.
/// The defaults are POV-Ray's default camera.
struct CameraState {
    CameraType type = CameraType::Perspective;
    double angle_deg_given = 90.0;  // the last angle given (POV-Ray's Angle; 90 by default)
    double v_angle_deg = 0.0;       // spherical: the vertical angle (0: not given)
    glm::dvec3 location{0.0, 0.0, 0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dvec3 right{1.33, 0.0, 0.0};
    glm::dvec3 sky{0.0, 1.0, 0.0};
    glm::dvec3 look_at{0.0, 0.0, 1.0};
    double angle_deg = 90.0;
};

/// The modifiers of one camera statement, each present only when written.
struct CameraModifiers {
    std::optional<CameraType> type;  // the projection keyword, when given
    std::optional<glm::dvec3> location, direction, up, right, sky, look_at;
    std::optional<double> angle_deg;
    std::optional<double> v_angle_deg;  // spherical: the second angle
    Transform transform;  // translate, rotate, scale, matrix and transform, composed in order
};

/// Applies a camera statement to `base` the way POV-Ray 3.5+ does (parse.cpp, Parse_Camera):
/// the projection keyword sets the type; location, direction, up, right and sky replace the
/// base's; then `angle` rescales direction to |right| / (2 tan(angle / 2)) for the
/// perspective and orthographic cameras (the others keep it as their field of view); then
/// `look_at` turns direction toward the point (keeping its length), sets right to sky x
/// direction and up to direction x right (keeping their lengths and the handedness of
/// right); an orthographic camera without up and right, or with an angle, scales right and
/// up by |look_at - location| / |direction|; last the transforms move location and turn
/// direction, up and right (not sky).  Errors: an angle outside [0, 180) (perspective and
/// orthographic) and a look_at point equal to the location.
Result<CameraState> apply_camera_statement(const CameraState& base, const CameraModifiers& mods);

/// The camera the scene holds (scene.h) for a parsed camera state.
Camera camera_from_state(const CameraState& state);

/// True when direction, up and right are pairwise perpendicular within POV-Ray's tolerance
/// (POV-Ray warns otherwise).
bool camera_vectors_perpendicular(const CameraState& state);

}  // namespace mirage
