// walk.pov: walking toward the mirage.  Khote & Howard: "it is possible to walk towards the
// mirage and it will disappear".  Two spheres floating 3.5 m above hot sand (balloons; the
// `paper` atmosphere of desert.pov), approached from 40 m to 5 m as the clock runs from 0 to
// 1.  Far away the spheres show over their own images, upside down below them, in the light
// that dipped toward the hot sand and turned; from about 13.5 m on no ray from the eye
// reaches a sphere's lowest point after a turn, and the mirrored image is gone (mirage path
// --preset paper --eye-height 1.5 --object-height 3.5: mirrored from 37.5 m to 13.5 m).
//
//   make animate                                   (this scene is the default, 24 frames)
//   build/mirage animate scenes/walk.pov --frames 48 -W 320 -H 240 --model trace
//   build/mirage trace scenes/walk.pov -W 640 -H 480 -o walk.png     (clock 0, the first frame)
//   build/mirage compile scenes/walk.pov -W 640 -H 480 -o build/walk --render   (the same, POV-Ray)
// Plain POV-Ray (`povray +KFF24 +Lpov_includes scenes/walk.pov`) renders it without the
// mirage, with a warning: the bands and the camera that make the mirage are what `mirage
// compile` (or `mirage animate`) writes for each frame.
//
// The spheres' bottoms are above the eye: a camera ray that leaves the eye downwards can meet
// them only after its turn, so every pixel of theirs below the horizon is mirrored.  They are
// marked (Marked_Center, Marked_Radius: see mirage.inc) for the animation's vanishing report;
// declared Marked_Flat = 1 draws them in flat, unlit colours whose pixels can be counted.
#version 3.7;

#declare Mirage_Preset    = "paper";
#declare Mirage_Tolerance = 0.5;    // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

#declare Walk_Start  = 40;          // m from the spheres at clock 0
#declare Walk_End    = 5;           // m at clock 1
#declare Eye_Height  = 1.5;
#declare Eye_Distance = Walk_Start + (Walk_End - Walk_Start) * clock;

#declare Ball_Height = 4.5;         // centres, m
#declare Ball_Radius = 1.0;
#declare Ball_Z      = 60;          // the spheres stand here; the walker comes from z = 20
#declare Red_Ball    = <0, Ball_Height, Ball_Z>;
#declare Blue_Ball   = <3.5, Ball_Height, Ball_Z + 8>;

#declare Marked_Center   = Red_Ball;
#declare Marked_Radius   = Ball_Radius;
#declare Marked_Name     = "red sphere";
#declare Marked_Center_2 = Blue_Ball;
#declare Marked_Radius_2 = Ball_Radius;
#declare Marked_Name_2   = "blue sphere";

camera {
    location <0, Eye_Height, Ball_Z - Eye_Distance>
    look_at  <0, 0.5, Ball_Z - Eye_Distance + 10>   // 5.7 degrees down: the mirage in view
    right    x * image_width / image_height
    angle    60
}

light_source { <-30, 60, -20>, color rgb <1, 0.97, 0.9> }

// The sky of desert.pov: `gradient y` over y from -1 to 1 (scale 2.2 translate -1.1 * y),
// so that it never wraps; the entry for height Y is at 0.5 + Y / 2.2.
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5              color rgb <0.85, 0.88, 0.95>]
            [0.5 + 0.35 / 2.2 color rgb <0.35, 0.55, 0.90>]
            [0.5 + 1.00 / 2.2 color rgb <0.10, 0.25, 0.70>]
        }
        scale 2.2 translate -1.1 * y
    }
}

plane {
    y, 0
    pigment { checker color rgb <0.85, 0.72, 0.50>, color rgb <0.70, 0.55, 0.35> scale 2 }
    finish { ambient 0.25 diffuse 0.7 }
}

#ifndef (Marked_Flat)
    #declare Marked_Flat = 0;
#end
#declare Ball_Finish = finish { ambient 0.2 diffuse 0.7 specular 0.3 roughness 0.05 }   // balloons: no mirror finish
#if (Marked_Flat)
    // Flat and unlit: exactly rgb <1, 0, 1> and <0, 1, 1> in the image, nothing else is.
    #declare Red_Texture  = texture { pigment { color rgb <1, 0, 1> } finish { ambient 1 diffuse 0 } }
    #declare Blue_Texture = texture { pigment { color rgb <0, 1, 1> } finish { ambient 1 diffuse 0 } }
#else
    #declare Red_Texture  = texture { pigment { color rgb <0.80, 0.15, 0.10> } finish { Ball_Finish } }
    #declare Blue_Texture = texture { pigment { color rgb <0.15, 0.35, 0.80> } finish { Ball_Finish } }
#end

// Nothing stands under them: the last rays to reach a sphere after their turn rise to its
// lower far side from beneath it (a mast there would hide the mirage before it vanishes).
sphere { Red_Ball, Ball_Radius texture { Red_Texture } }
sphere { Blue_Ball, Ball_Radius texture { Blue_Texture } }

// Posts marking the way, every 10 m.
#declare Post = cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.05 pigment { color rgb <0.2, 0.2, 0.2> } }
#for (Post_Z, 10, 50, 10)
    object { Post translate <-2, 0, Post_Z> }
#end
