// hot_road.pov: a car on a hot road and its mirrored image, from a sounding.  The air's
// temperature over sun-heated asphalt, measured-like, in scenes/hot_road.csv: 55 degC at the
// surface, 40 degC at 5 cm, 32 degC at half a metre, 30 degC above 2 m.  Rays from an eye at
// 1.2 m that leave 0.15 to 0.35 degrees below the horizon are bent back up a few cm above the
// road, 250 to 500 m ahead: through a long lens the road there shows the sky, and the car
// 320 m away and the van at 480 m stand on their own upside-down images (the "wet road").
// The sounding is traced by the general engine, on the curved Earth.
//
//   build/mirage trace scenes/hot_road.pov -W 960 -H 360 -o hot_road.png
//   build/mirage compile scenes/hot_road.pov -W 960 -H 360 -o build/hot_road --render  (POV-Ray)
// Plain POV-Ray (`povray +Lpov_includes scenes/hot_road.pov`) renders it without the mirage,
// with a warning: the bands and the camera that make the mirage are what `mirage compile`
// writes.
#version 3.7;

#declare Mirage_Sounding  = "hot_road.csv";  // beside this file
#declare Mirage_Tolerance = 0.25;            // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.2, 0>               // eye 1.2 m above the road
    look_at  <0, 1.2 - 1000 * tan(radians(0.1)), 1000>
    right    x * image_width / image_height
    angle    2                         // horizontal field; 0.75 degrees vertical at 8:3
}

light_source { <-2000, 3000, -1000>, color rgb <1, 0.98, 0.92> }

// The sky by the direction's height y.  `scale 2.2 translate -1.1 * y` spreads y from -1 to
// 1 over the pattern's 0.05 to 0.95, so it never wraps (plain `gradient y` jumps to the map's
// far end just below the horizontal); the entry for height Y sits at 0.5 + Y / 2.2, and
// below the horizon the sky keeps its haze.
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5               color rgb <0.92, 0.93, 0.96>]
            [0.5 + 0.004 / 2.2 color rgb <0.70, 0.80, 0.95>]
            [0.5 + 0.020 / 2.2 color rgb <0.35, 0.55, 0.90>]
            [0.5 + 1.000 / 2.2 color rgb <0.15, 0.30, 0.75>]
        }
        scale 2.2 translate -1.1 * y
    }
}

// Asphalt, with 10 m squares to read distances, and the verge.
plane {
    y, 0
    pigment { checker color rgb <0.22, 0.22, 0.23>, color rgb <0.27, 0.27, 0.28> scale 10 }
    finish { ambient 0.2 diffuse 0.7 }
}
box { <-60, 0, 0>, <-4, 0.3, 2000> pigment { color rgb <0.45, 0.40, 0.22> } }
box { <4, 0, 0>, <60, 0.3, 2000> pigment { color rgb <0.45, 0.40, 0.22> } }

// A red car at 320 m, coming towards the eye.
#declare Paint = finish { ambient 0.2 diffuse 0.6 specular 0.4 roughness 0.05 reflection 0.1 }
union {
    box { <-0.9, 0.3, -2.2>, <0.9, 1.0, 2.2> pigment { color rgb <0.80, 0.08, 0.06> } }
    box { <-0.8, 1.0, -1.0>, <0.8, 1.45, 1.2> pigment { color rgb <0.15, 0.20, 0.28> } }
    cylinder { <-0.95, 0.32, -1.4>, <0.95, 0.32, -1.4>, 0.32 pigment { color rgb 0.04 } }
    cylinder { <-0.95, 0.32, 1.4>, <0.95, 0.32, 1.4>, 0.32 pigment { color rgb 0.04 } }
    box { <-0.7, 0.55, -2.25>, <-0.4, 0.7, -2.2> pigment { color rgb <1, 1, 0.85> } finish { ambient 1 } }
    box { <0.4, 0.55, -2.25>, <0.7, 0.7, -2.2> pigment { color rgb <1, 1, 0.85> } finish { ambient 1 } }
    finish { Paint }
    translate <-1.6, 0, 320>
}

// A white van at 480 m, going away.
union {
    box { <-1.0, 0.35, -2.6>, <1.0, 2.4, 2.6> pigment { color rgb <0.92, 0.92, 0.90> } }
    box { <-0.9, 1.3, -2.65>, <0.9, 2.2, -2.6> pigment { color rgb <0.20, 0.25, 0.30> } }
    cylinder { <-1.05, 0.35, -1.8>, <1.05, 0.35, -1.8>, 0.35 pigment { color rgb 0.04 } }
    cylinder { <-1.05, 0.35, 1.8>, <1.05, 0.35, 1.8>, 0.35 pigment { color rgb 0.04 } }
    finish { Paint }
    translate <1.8, 0, 480>
}

// Posts along the verge every 50 m.
#declare Post = cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.08 pigment { color rgb <0.95, 0.95, 0.95> } }
#for (D, 150, 700, 50)
    object { Post translate <-4.3, 0.3, D> }
    object { Post translate <4.3, 0.3, D> }
#end
