// fata_morgana.pov: a Fata Morgana over a cold sea.  Warm air lies over the sea air in a
// thin inversion, 2 K warmer between 50 and 60 m (Andrew T. Young's case, over the standard
// atmosphere's lapse of 6.5 K/km, its corners smoothed by 0.85 m), and makes a duct: rays
// from an eye at 54 m, on a cliff or a ship's mast, are trapped between 45.8 and 59.6 m and
// bend up and down through it.  A coast 40 km away, its chalk and rock in bands, is seen
// several times over, stacked: the band from 47 to 69 m of it appears erect, inverted, erect
// and inverted again, one image above the other (the transfer curve, docs/atmospheres.md),
// and its tops vanish.  On the curved Earth (the default for real air).
//
//   build/mirage trace scenes/fata_morgana.pov -W 900 -H 300 -o fata_morgana.png
#version 3.7;

#declare Mirage_Air_Temperature     = 288.15;        // K at sea level, below the inversion
#declare Mirage_Lapse               = 6.5;           // K per km
#declare Mirage_Inversion           = <50, 60, 2>;   // from 50 m to 60 m, 2 K warmer
#declare Mirage_Inversion_Smoothing = 0.85;          // m
#declare Mirage_Index               = "ciddor";
#declare Mirage_Earth_Radius        = 6371000;       // m
#declare Mirage_Tolerance           = 0.1;           // pixels: the duct magnifies path errors
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

// A long lens, a panorama 3 times wider than high: 1.2 x 0.4 degrees at -W 900 -H 300,
// looking 0.08 degrees down.
camera {
    location <0, 54, 0>
    look_at  <0, 54 - 40000 * tan(radians(0.08)), 40000>
    right    x * image_width / image_height
    angle    1.2
}

light_source { <-30000, 20000, -10000>, color rgb <1, 0.96, 0.90> }

sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.000 color rgb <0.86, 0.88, 0.92>]
            [0.004 color rgb <0.66, 0.76, 0.90>]
            [1.000 color rgb <0.25, 0.40, 0.75>]
        }
    }
}

// The cold sea, with long swells.
plane {
    y, 0
    pigment { gradient z color_map { [0 color rgb <0.10, 0.22, 0.30>] [1 color rgb <0.14, 0.28, 0.36>] } scale 400 }
    finish { ambient 0.3 diffuse 0.5 }
}

// The coast at 40 km: cliffs in bands (dark rock, white chalk, red sandstone, green turf),
// with white houses and a lighthouse on top.
#declare Bands = pigment {
    gradient y
    color_map {
        [0.00 color rgb <0.25, 0.22, 0.20>]
        [0.46 color rgb <0.25, 0.22, 0.20>]
        [0.46 color rgb <0.95, 0.95, 0.90>]
        [0.52 color rgb <0.95, 0.95, 0.90>]
        [0.52 color rgb <0.65, 0.25, 0.15>]
        [0.58 color rgb <0.65, 0.25, 0.15>]
        [0.58 color rgb <0.95, 0.95, 0.90>]
        [0.62 color rgb <0.95, 0.95, 0.90>]
        [0.62 color rgb <0.30, 0.45, 0.20>]
        [1.00 color rgb <0.30, 0.45, 0.20>]
    }
    scale 100
}
#declare Rock = finish { ambient 0.35 diffuse 0.6 }
#declare Cliff = pigment { Bands }
// Headlands of several heights along 1.6 km of coast, and a low beach between them.
box { <-800, 0, 40000>, <-420, 70, 40300> pigment { Cliff } finish { Rock } }
box { <-420, 0, 40060>, <-200, 30, 40300> pigment { color rgb <0.70, 0.62, 0.45> } finish { Rock } }
box { <-200, 0, 40000>, <150, 66, 40300> pigment { Cliff } finish { Rock } }
box { <150, 0, 39990>, <420, 74, 40300> pigment { Cliff } finish { Rock } }
box { <420, 0, 40080>, <800, 40, 40300> pigment { color rgb <0.70, 0.62, 0.45> } finish { Rock } }
// White houses with red roofs on the middle headland, a lighthouse on the high one.
#for (X, -180, 120, 40)
    box { <X, 66, 40020>, <X + 16, 76, 40036> pigment { color rgb <0.92, 0.90, 0.85> } finish { Rock } }
    box { <X - 1, 76, 40019>, <X + 17, 80, 40037> pigment { color rgb <0.60, 0.15, 0.10> } finish { Rock } }
#end
cylinder { <300, 74, 40020>, <300, 104, 40020>, 5
    pigment { gradient y color_map { [0.5 color rgb <0.95, 0.95, 0.95>] [0.5 color rgb <0.75, 0.10, 0.10>] } scale 10 }
    finish { Rock } }
// A tower of the left headland.
box { <-700, 70, 40010>, <-680, 95, 40030> pigment { color rgb <0.55, 0.55, 0.58> } finish { Rock } }
