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
// Only the tracer renders this mirage: `mirage compile` refuses it (POV-Ray would see the sky
// of a curved Earth 40 km wide 8.7 mrad off; the bands reach 6.4 km), and plain POV-Ray
// (`povray +Lpov_includes scenes/fata_morgana.pov`) renders it without the mirage, with a
// warning.
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

// The sky by the direction's height y, its haze low and its blue above.  On the curved Earth
// the rays that leave the air far away point below the eye's horizontal when turned back to
// its frame (a ray leaving 0.1 degrees up bends down by about as much on its way out of the
// air): the sky in this picture is seen at y from -0.006 to 0, and its gradient runs there.
// `scale 2.2 translate -1.1 * y` spreads y from -1 to 1 over the pattern's 0.05 to 0.95, so
// it never wraps; the entry for height Y sits at 0.5 + Y / 2.2, and below the first entry
// the sky keeps its haze.  (Plain `gradient y` jumps to the map's far end just below the
// horizontal: a hard-edged blue band across the picture.)  Over it, a few low clouds.
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5 - 0.008 / 2.2 color rgb <0.82, 0.85, 0.90>]
            [0.5 - 0.004 / 2.2 color rgb <0.64, 0.73, 0.88>]
            [0.5               color rgb <0.45, 0.58, 0.85>]
            [0.5 + 0.02 / 2.2  color rgb <0.32, 0.47, 0.80>]
            [0.5 + 1 / 2.2     color rgb <0.20, 0.34, 0.72>]
        }
        scale 2.2 translate -1.1 * y
    }
    pigment {
        bozo
        turbulence 0.3
        color_map {
            [0.00 color rgbt <1, 1, 1, 1>]
            [0.62 color rgbt <1, 1, 1, 1>]
            [0.80 color rgbt <0.96, 0.96, 0.97, 0.4>]
            [1.00 color rgbt <0.90, 0.90, 0.92, 0.15>]
        }
        scale <0.004, 0.0006, 0.004>
    }
}

// The cold sea: long, low swells and wind streaks, elongated across the view.
plane {
    y, 0
    pigment {
        bozo
        color_map {
            [0.0 color rgb <0.07, 0.17, 0.24>]
            [0.5 color rgb <0.11, 0.24, 0.32>]
            [1.0 color rgb <0.18, 0.32, 0.40>]
        }
        scale <40, 1, 900>
    }
    finish { ambient 0.3 diffuse 0.5 }
}

// The coast at 40 km: cliffs in strata (dark rock, white chalk, red sandstone, chalk again,
// green turf), the rock mottled, with houses, a lighthouse and a wood on top.
#declare Rock = finish { ambient 0.35 diffuse 0.6 }
// (The strata's own patterns are scaled by the 100 m of the pigment map that holds them.)
#declare Dark_Rock  = pigment { granite color_map { [0 color rgb <0.17, 0.15, 0.13>] [1 color rgb <0.40, 0.36, 0.31>] } scale 0.3 }
#declare Chalk      = pigment { granite color_map { [0 color rgb <0.82, 0.82, 0.76>] [1 color rgb <0.98, 0.98, 0.94>] } scale 0.2 }
#declare Sandstone  = pigment { granite color_map { [0 color rgb <0.50, 0.18, 0.10>] [1 color rgb <0.75, 0.34, 0.20>] } scale 0.2 }
#declare Turf       = pigment { bozo color_map { [0 color rgb <0.20, 0.34, 0.14>] [1 color rgb <0.38, 0.52, 0.24>] } scale <0.2, 0.04, 0.2> }
#declare Cliff = pigment {
    gradient y
    pigment_map {
        [0.00 Dark_Rock]
        [0.46 Dark_Rock]
        [0.46 Chalk]
        [0.52 Chalk]
        [0.52 Sandstone]
        [0.58 Sandstone]
        [0.58 Chalk]
        [0.62 Chalk]
        [0.62 Turf]
        [1.00 Turf]
    }
    scale 100
}
#declare Sand = pigment { granite color_map { [0 color rgb <0.62, 0.55, 0.40>] [1 color rgb <0.76, 0.68, 0.50>] } scale 20 }
// Headlands of several heights along 1.6 km of coast, and a low beach between them.
box { <-800, 0, 40000>, <-420, 70, 40300> pigment { Cliff } finish { Rock } }
box { <-420, 0, 40060>, <-200, 30, 40300> pigment { Sand } finish { Rock } }
box { <-200, 0, 40000>, <150, 66, 40300> pigment { Cliff } finish { Rock } }
box { <150, 0, 39990>, <420, 74, 40300> pigment { Cliff } finish { Rock } }
box { <420, 0, 40080>, <800, 40, 40300> pigment { Sand } finish { Rock } }
// Houses on the middle headland, walls of several colours with rows of dark windows, red and
// slate roofs; a lighthouse on the high one.
#declare Window = color rgb <0.16, 0.18, 0.22>;
#for (K, 0, 7)
    #declare X = -180 + 40 * K;
    #declare Wall = color rgb <0.92, 0.90, 0.85> - mod(K, 3) * <0.0, 0.08, 0.18>;
    #declare Roof = color rgb <0.62, 0.16, 0.10> * (1 - mod(K, 2)) + <0.30, 0.32, 0.36> * mod(K, 2);
    box { <X, 66, 40020>, <X + 16, 76, 40036>
          pigment { brick Wall, Window brick_size <4, 3.3, 4> mortar 2.4 translate <X + 1, 67, 0> }
          finish { Rock } }
    box { <X - 1, 76, 40019>, <X + 17, 80, 40037> pigment { Roof } finish { Rock } }
#end
cylinder { <300, 74, 40020>, <300, 104, 40020>, 5
    pigment { gradient y color_map { [0.5 color rgb <0.95, 0.95, 0.95>] [0.5 color rgb <0.75, 0.10, 0.10>] } scale 10 }
    finish { Rock } }
cylinder { <300, 104, 40020>, <300, 107, 40020>, 3.5 pigment { color rgb <0.95, 0.85, 0.40> } finish { ambient 0.8 } }
// A tower of the left headland, and a wood beyond the lighthouse.
box { <-700, 70, 40010>, <-680, 95, 40030> pigment { granite color_map { [0 color rgb 0.48] [1 color rgb 0.62] } scale 6 } finish { Rock } }
#for (K, 0, 14)
    sphere { <330 + 7 * K, 74 + 3 + mod(K * 3, 4), 40030 + 7 * mod(K, 3)>, 5 + mod(K * 5, 3)
        pigment { bozo color_map { [0 color rgb <0.12, 0.24, 0.12>] [1 color rgb <0.22, 0.36, 0.18>] } scale 3 }
        finish { Rock } }
#end
