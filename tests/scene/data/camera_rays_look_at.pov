// Rendered by POV-Ray 3.7.0.10 into camera_rays_look_at.png with
//   povray -D -A +W32 +H24 +FN16 File_Gamma=1.0 +Ocamera_rays_look_at.png camera_rays_look_at.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Eye = <1, 2, -3>;
camera {
    location Eye
    look_at <0.5, 1, 2>
    angle 50
    right x * image_width / image_height
}
#include "direction_sphere.inc"
