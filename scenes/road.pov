// road.pov: a realistic hot road.  Air over sun-heated asphalt, T = 300 K + 20 K exp(-y/0.3 m),
// bends rays up by a few tenths of a degree: through a long lens the road ahead shows the
// sky and the cars mirrored in it (the "wet road" inferior mirage).  The index differences
// are those of real air (n - 1 = 2.8e-4, steps of 1e-11 between layers), so the view is a
// narrow one: about one degree high, objects 150 to 450 m away.
//
//   make render SCENE=scenes/road.pov W=640 H=480
#version 3.7;

#declare Mirage_Preset    = "hot-road";
#declare Mirage_Tolerance = 1.0;    // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.5, 0>            // eye 1.5 m above the road, level
    look_at  <0, 1.5, 100>
    right    x * image_width / image_height
    angle    1.3334                 // horizontal field; 1 degree vertical at 4:3
}

light_source { <-2000, 3000, -1000>, color rgb <1, 0.98, 0.92> }

sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.000 color rgb <0.92, 0.93, 0.96>]
            [0.004 color rgb <0.70, 0.80, 0.95>]
            [0.020 color rgb <0.35, 0.55, 0.90>]
            [1.000 color rgb <0.15, 0.30, 0.75>]
        }
    }
}

// Asphalt, with 10 m squares to read distances.
plane {
    y, 0
    pigment { checker color rgb <0.22, 0.22, 0.23>, color rgb <0.27, 0.27, 0.28> scale 10 }
    finish { ambient 0.2 diffuse 0.7 }
}

// A car at 200 m, a cyclist at 300 m, a lorry at 450 m.
#declare Paint = finish { ambient 0.2 diffuse 0.6 specular 0.4 roughness 0.05 reflection 0.1 }
box { <-3.0, 0.3, 198>, <-1.2, 1.1, 202> pigment { color rgb <0.75, 0.10, 0.08> } finish { Paint } }
box { <-2.8, 1.1, 199>, <-1.4, 1.5, 201> pigment { color rgb <0.20, 0.25, 0.30> } finish { Paint } }
cylinder { <-2.9, 0.3, 198.5>, <-1.3, 0.3, 198.5>, 0.3 pigment { color rgb 0.05 } }
cylinder { <-2.9, 0.3, 201.5>, <-1.3, 0.3, 201.5>, 0.3 pigment { color rgb 0.05 } }

cylinder { <1.6, 0, 300>, <1.6, 1.7, 300>, 0.25 pigment { color rgb <0.15, 0.45, 0.20> } }
sphere { <1.6, 1.85, 300>, 0.15 pigment { color rgb <0.80, 0.65, 0.50> } }

box { <2.2, 0.5, 445>, <4.8, 3.8, 455> pigment { color rgb <0.90, 0.90, 0.85> } finish { Paint } }
box { <2.2, 0.5, 442>, <4.8, 2.6, 445> pigment { color rgb <0.15, 0.30, 0.60> } finish { Paint } }

// Posts along the verge every 50 m.
#declare Post = cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.1 pigment { color rgb <0.95, 0.95, 0.95> } }
#for (D, 150, 450, 50)
    object { Post translate <-0.015 * D, 0, D> }
#end
