// Rendered by POV-Ray 3.7.0.10 into camera_rays_tilted.png with
//   povray -D -A +W40 +H30 +FN16 File_Gamma=1.0 +Ocamera_rays_tilted.png camera_rays_tilted.pov
// A right-handed camera (right along -x) with a tilted sky, an explicit direction length that
// look_at keeps, modifiers in an order POV-Ray does not follow, and a rotation at the end.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Eye0 = <0.5, 1.5, -2>;
camera {
    look_at <2, 0.5, 3>
    direction 1.7 * z
    right -1.2 * x
    up 0.9 * y
    sky <0.3, 1, 0.1>
    location Eye0
    rotate <5, 10, -3>
}
// Where the rotation puts the eye.
#declare Eye = vrotate(Eye0, <5, 10, -3>);
#include "direction_sphere.inc"
