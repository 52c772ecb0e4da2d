// Rendered by POV-Ray 3.7.0.10 into camera_rays_default.png with
//   povray -D -A +W24 +H24 +FN16 File_Gamma=1.0 +Ocamera_rays_default.png camera_rays_default.pov
// No camera statement: POV-Ray's default camera, and a square image that does not change it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Eye = <0, 0, 0>;
#include "direction_sphere.inc"
