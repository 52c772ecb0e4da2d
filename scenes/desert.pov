// desert.pov: the paper's colour slides 5.1/5.2 (Khote & Howard), two identical partially
// reflective spheres at the same height and distance over hot sand.  The `paper` atmosphere
// exaggerates the index of air about 360 times so that the inferior mirage (the inverted,
// stretched copy of the spheres and the sky below the horizon) shows within a few metres.
//
//   make render                          (this scene is the default)
//   povray -D +Lpov_includes scenes/desert.pov  (plain POV-Ray: no atmosphere, a warning)
#version 3.7;

#declare Mirage_Preset    = "paper";
#declare Mirage_Tolerance = 0.5;    // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.5, 0>            // eye 1.5 m above the sand, level
    look_at  <0, 1.5, 10>
    right    x * image_width / image_height
    angle    60
}

light_source { <-30, 60, -20>, color rgb <1, 0.97, 0.9> }

sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.00 color rgb <0.85, 0.88, 0.95>]
            [0.35 color rgb <0.35, 0.55, 0.90>]
            [1.00 color rgb <0.10, 0.25, 0.70>]
        }
    }
}

// Sand: a warm checker, so that distances can be read off the picture.
plane {
    y, 0
    pigment { checker color rgb <0.85, 0.72, 0.50>, color rgb <0.70, 0.55, 0.35> scale 2 }
    finish { ambient 0.25 diffuse 0.7 }
}

#declare Ball_Finish = finish { ambient 0.15 diffuse 0.6 specular 0.6 roughness 0.02 reflection 0.25 }

sphere { <-2.5, 1.6, 14>, 1 pigment { color rgb <0.80, 0.15, 0.10> } finish { Ball_Finish } }
sphere { < 2.5, 1.6, 14>, 1 pigment { color rgb <0.15, 0.35, 0.80> } finish { Ball_Finish } }

// Posts marking distance: 5, 20 and 40 m.
#declare Post = cylinder { <0, 0, 0>, <0, 2.2, 0>, 0.08 pigment { color rgb <0.2, 0.2, 0.2> } }
object { Post translate <-6, 0, 5> }
object { Post translate < 6, 0, 20> }
object { Post translate <-9, 0, 40> }
