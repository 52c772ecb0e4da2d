// own_scene.pov: a scene as a user might write one, with a camera at eye height (1.7 m), a house
// of boxes, a car and a ball on a pole over a hot road.  In real air (hot-road) the mirage is
// there but a fraction of a degree tall: `mirage frame` says how large it is in this frame and
// what would show it (docs/framing.md; own_scene_far.pov and own_scene_exaggerated.pov follow
// its advice).  Declare before including this file:
//   Frame_Angle, Frame_Eye (m), Frame_Far (how far the objects are moved back, m)
//   build/mirage frame docs/examples/own_scene.pov
//   build/mirage trace docs/examples/own_scene.pov -o own.png
#version 3.7;

#ifndef (Mirage_Preset) #declare Mirage_Preset = "hot-road"; #end
#include "mirage.inc"

#ifndef (Frame_Angle) #declare Frame_Angle = 50; #end
#ifndef (Frame_Eye)   #declare Frame_Eye = 1.7; #end
#ifndef (Frame_Far)   #declare Frame_Far = 0; #end

global_settings { assumed_gamma 1.0 }

camera {
    location <0, Frame_Eye, 0>
    look_at  <0, Frame_Eye, 100>
    right    x * image_width / image_height
    angle    Frame_Angle
}

light_source { <-3000, 5000, -2000>, color rgb <1, 0.97, 0.9> }

// A sky that darkens upwards; directions below the horizontal (the mirrored sky) keep the
// colour near the horizon (gradient y over [-1, 1], not wrapped).
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.000 color rgb <0.85, 0.88, 0.95>]
            [0.500 color rgb <0.85, 0.88, 0.95>]
            [0.505 color rgb <0.62, 0.74, 0.95>]
            [0.520 color rgb <0.45, 0.60, 0.92>]
            [0.600 color rgb <0.30, 0.50, 0.90>]
            [1.000 color rgb <0.12, 0.25, 0.70>]
        }
        scale 2
        translate -y
    }
}

// The road, 8 m wide, dark asphalt on sand (one period of the gradient spans 10 km).
plane {
    y, 0
    pigment {
        gradient x
        color_map {
            [0.0000 color rgb <0.75, 0.65, 0.45>]
            [0.4996 color rgb <0.75, 0.65, 0.45>]
            [0.4996 color rgb <0.16, 0.16, 0.17>]
            [0.5004 color rgb <0.16, 0.16, 0.17>]
            [0.5004 color rgb <0.75, 0.65, 0.45>]
            [1.0000 color rgb <0.75, 0.65, 0.45>]
        }
        scale 10000 translate -5000 * x
    }
    finish { ambient 0.25 diffuse 0.7 }
}

#declare Paint = finish { ambient 0.25 diffuse 0.6 specular 0.3 roughness 0.05 }

// The house: walls, a roof, a door, 40 m ahead on the left.
#declare House = union {
    box { <-14, 0, 40>, <-6, 3.2, 48> pigment { color rgb <0.90, 0.85, 0.75> } finish { Paint } }
    box {
        <-14.3, -2, -2>, <-5.7, 2, 2>
        rotate 45 * x scale <1, 0.6, 1.45> translate <0, 3.2, 44>
        pigment { color rgb <0.65, 0.15, 0.10> } finish { Paint }
    }
    box { <-5.99, 0, 42>, <-5.9, 2.1, 43.2> pigment { color rgb <0.30, 0.18, 0.10> } }
}
object { House translate Frame_Far * z }

// The car, 25 m ahead in the right lane.
#declare Car = union {
    box { <1.0, 0.3, 25>, <2.8, 1.0, 29.4> pigment { color rgb <0.10, 0.25, 0.70> } finish { Paint } }
    box { <1.15, 1.0, 26.2>, <2.65, 1.45, 28.4> pigment { color rgb <0.15, 0.20, 0.25> } finish { Paint } }
    cylinder { <0.95, 0.3, 26>, <2.85, 0.3, 26>, 0.3 pigment { color rgb 0.05 } }
    cylinder { <0.95, 0.3, 28.4>, <2.85, 0.3, 28.4>, 0.3 pigment { color rgb 0.05 } }
}
object { Car translate Frame_Far * z }

// A ball on a pole, 60 m ahead on the right verge.
cylinder { <6, 0, 60 + Frame_Far>, <6, 2.6, 60 + Frame_Far>, 0.05 pigment { color rgb 0.8 } }
sphere { <6, 3, 60 + Frame_Far>, 0.4 pigment { color rgb <1.0, 0.55, 0.05> } finish { Paint } }
