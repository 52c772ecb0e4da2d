// Where the inferior mirage of an object vanishes.  A ray from the eye that turns (its lowest
// point) at height y_t and rises again reaches height h at the horizontal distance
// L(y_t) = X(y_t -> y0) + X(y_t -> h), X the distance from a turning point up to a height
// (the path is symmetric about its turning point).  A point at height h therefore has a
// mirrored image only for eye distances in [min L, max L] over the turning heights between
// the ground and min(y0, h): walking closer than min L, its mirrored image is gone.
//
// For any stratified atmosphere (atmosphere/exact_path.h: the exponential closed forms or the
// general engine's fitted model): the eye's ray turns at y_t, and not higher, when the ray
// level at y_t rises to the eye before it turns again; it reaches h when that ray rises to h
// too.  Turning heights where either fails (a ray that turns higher, in a duct, or n falling
// with height at y_t) give no L.  Heights and distances in the model's units (on the curved Earth the flattened
// frame's: heights y = R ln(1 + h / R), distances along the sphere).

#pragma once

#include "atmosphere/exact_path.h"
#include "atmosphere/profile.h"
#include "util/result.h"

namespace mirage {

/// Horizontal distance from the turning point of a ray that turns at height y_turn to where
/// it has risen to height y >= y_turn (inferior profile).
/// +inf when the ray level at y_turn does not rise to y.
double turn_to_height_distance(const Atmosphere& atmosphere, double y_turn, double y);
double turn_to_height_distance(const Profile& profile, double y_turn, double y);

/// The eye distances from which a point is seen after a turning point.
struct MirrorReach {
    double nearest = 0.0;              // the nearest horizontal eye distance with a mirrored image
    double farthest = 0.0;             // the farthest one (beyond it the turned rays pass above it)
    double nearest_turn_height = 0.0;  // turning height of the ray that reaches it from there
    double nearest_elevation_rad = 0.0;  // that ray's elevation at the eye (< 0)
    bool grazing = false;  // the nearest distance is the limit of rays grazing the ground
                           // (turning at y -> 0), approached but not reached
};

/// For an eye at `eye_height` and a point at `object_height` (both > 0), over an inferior
/// profile.  An error names the bad value (a non-positive height, another profile kind).
/// In any atmosphere: an error also when no ray from the eye turns below both and rises to the
/// point.
Result<MirrorReach> mirror_reach(const Atmosphere& atmosphere, double eye_height,
                                 double object_height);
Result<MirrorReach> mirror_reach(const Profile& profile, double eye_height, double object_height);

/// The mirrored image of a sphere seen from an eye, in the vertical plane through the eye and
/// the sphere's centre (the plane where it is tallest): the elevations of the camera rays
/// whose first hit on the sphere comes after their turning point.
struct SphereMirror {
    bool visible = false;
    double elevation_low_rad = 0.0, elevation_high_rad = 0.0;  // its lowest and highest ray
    double angular_size_rad = 0.0;  // elevation_high - elevation_low (0 when not visible)
};

/// `distance` is the horizontal distance from the eye to the sphere's centre.  Other objects
/// are not considered (nothing else blocks the rays); rays that reach the ground end there.
SphereMirror mirrored_image_of_sphere(const Atmosphere& atmosphere, double eye_height,
                                      double distance, double centre_height, double radius);
SphereMirror mirrored_image_of_sphere(const Profile& profile, double eye_height, double distance,
                                      double centre_height, double radius);

/// The nearest eye distance (to the sphere's centre, horizontally) at which the sphere still
/// has a mirrored image: the minimum over its section's points (d, h) of mirror_reach(h).nearest
/// minus their distance behind the centre.  Exact when every ray's first hit on the sphere
/// comes after its turn, as for a sphere above the eye; an error names a sphere that touches
/// the ground or a bad value.
Result<double> sphere_vanishing_distance(const Atmosphere& atmosphere, double eye_height,
                                         double centre_height, double radius);
Result<double> sphere_vanishing_distance(const Profile& profile, double eye_height,
                                         double centre_height, double radius);

}  // namespace mirage
