// looming_coast.pov: long-range looming of a coast 30 km away, over a cold sea on the
// curved Earth.  From an eye 10 m above the sea the geometric horizon is 11.3 km away, and a
// coast at 30 km hides its lowest 27 m behind the bulge of the sea in the standard
// atmosphere: its harbour town is out of sight.  Here warm air lies over the cold sea, the
// temperature rising by 10 K over the lowest 100 m (0.1 K per metre, near the gradient at
// which rays follow the Earth's curve), and rays bend down around the bulge: the town comes
// into view down to its quays, and the whole coast is lifted by a tenth of a degree.  The
// Earth's radius is the real one (the default for real air).
//
//   build/mirage trace scenes/looming_coast.pov -W 1000 -H 250 -o looming_coast.png
// Only the tracer renders this mirage: `mirage compile` refuses it (POV-Ray would see the sky
// of a curved Earth 30 km wide 6.7 mrad off; the bands reach 6.4 km), and plain POV-Ray
// (`povray +Lpov_includes scenes/looming_coast.pov`) renders it without the mirage, with a
// warning.
#version 3.7;

#declare Mirage_Air_Temperature     = 281.15;      // K at the sea (8 degC)
#declare Mirage_Lapse               = 6.5;         // K per km, the standard lapse
#declare Mirage_Inversion           = <0, 100, 10>; // 10 K warmer from 0 to 100 m
#declare Mirage_Inversion_Smoothing = 5;           // m
#declare Mirage_Earth_Radius        = 6371000;     // m
#declare Mirage_Tolerance           = 0.1;         // pixels: rays graze the sea
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

// A long lens, a panorama 4 times wider than high: 1.4 x 0.35 degrees at -W 1000 -H 250,
// looking 0.075 degrees up.
camera {
    location <0, 10, 0>
    look_at  <0, 10 + 30000 * tan(radians(0.075)), 30000>
    right    x * image_width / image_height
    angle    1.4
}

light_source { <-30000, 25000, -5000>, color rgb <1, 0.96, 0.90> }

// The sky by the direction's height y, its haze low and its blue above.  On the curved Earth
// the rays that leave the air far away point below the eye's horizontal when turned back to
// its frame: the sky in this picture is seen at y from -0.004 to 0.001, and its gradient
// runs there.  `scale 2.2 translate -1.1 * y` spreads y from -1 to 1 over the pattern's 0.05
// to 0.95, so it never wraps; the entry for height Y sits at 0.5 + Y / 2.2, and below the
// first entry the sky keeps its haze.  (Plain `gradient y` jumps to the map's far end just
// below the horizontal: a hard-edged blue band across the picture.)  Over it, a few clouds.
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5 - 0.006 / 2.2 color rgb <0.84, 0.87, 0.92>]
            [0.5 - 0.002 / 2.2 color rgb <0.64, 0.74, 0.89>]
            [0.5 + 0.002 / 2.2 color rgb <0.42, 0.56, 0.84>]
            [0.5 + 0.02 / 2.2  color rgb <0.30, 0.45, 0.80>]
            [0.5 + 1 / 2.2     color rgb <0.20, 0.34, 0.72>]
        }
        scale 2.2 translate -1.1 * y
    }
    pigment {
        bozo
        turbulence 0.3
        color_map {
            [0.00 color rgbt <1, 1, 1, 1>]
            [0.60 color rgbt <1, 1, 1, 1>]
            [0.80 color rgbt <0.96, 0.96, 0.97, 0.4>]
            [1.00 color rgbt <0.90, 0.90, 0.92, 0.15>]
        }
        scale <0.005, 0.0007, 0.005>
    }
}

// The cold sea: long, low swells and wind streaks, elongated across the view.
plane {
    y, 0
    pigment {
        bozo
        color_map {
            [0.0 color rgb <0.06, 0.16, 0.24>]
            [0.5 color rgb <0.10, 0.23, 0.32>]
            [1.0 color rgb <0.16, 0.30, 0.39>]
        }
        scale <40, 1, 700>
    }
    finish { ambient 0.3 diffuse 0.5 }
}

#declare Wall = finish { ambient 0.35 diffuse 0.6 }
// Green hills behind the coast, 60 to 120 m high, a patchwork of fields and woods, their
// faces to the sea.
#declare Fields = pigment {
    cells
    color_map {
        [0.00 color rgb <0.22, 0.36, 0.16>]
        [0.35 color rgb <0.32, 0.46, 0.22>]
        [0.55 color rgb <0.50, 0.52, 0.26>]
        [0.75 color rgb <0.16, 0.28, 0.13>]
        [1.00 color rgb <0.40, 0.50, 0.24>]
    }
    scale <60, 30, 60>
}
box { <-600, 0, 30400>, <-150, 90, 31000> pigment { Fields } finish { Wall } }
box { <-150, 0, 30500>, <250, 120, 31000> pigment { Fields } finish { Wall } }
box { <250, 0, 30350>, <600, 60, 31000> pigment { Fields } finish { Wall } }
// The harbour town at sea level: a stone quay, houses 8 to 20 m high with rows of windows,
// red and slate roofs, a church tower.
#declare Stone = pigment { granite color_map { [0 color rgb <0.45, 0.43, 0.40>] [1 color rgb <0.62, 0.60, 0.56>] } scale 8 }
#declare Window = color rgb <0.16, 0.18, 0.22>;
box { <-500, 0, 29990>, <500, 3, 30100> pigment { Stone } finish { Wall } }
#for (K, 0, 23)
    #declare X = -460 + 40 * K;
    #declare H = 8 + 12 * mod(K * 7, 5) / 4;
    #declare Z = 30010 + 20 * mod(K, 3);
    #declare Paint = color rgb <0.95, 0.92, 0.85> - 0.25 * mod(K, 2) * <0, 0.3, 0.4>;
    #declare Roof = color rgb <0.65, 0.18, 0.12> * (1 - mod(K, 3) / 2) + <0.32, 0.34, 0.38> * mod(K, 3) / 2;
    box { <X, 3, Z>, <X + 28, H, Z + 20>
          pigment { brick Paint, Window brick_size <4, 3.2, 4> mortar 2.6 translate <X + 1, 3.5, 0> }
          finish { Wall } }
    box { <X - 1, H, Z - 1>, <X + 29, H + 3, Z + 21> pigment { Roof } finish { Wall } }
#end
box { <80, 3, 30060>, <95, 45, 30075> pigment { Stone } finish { Wall } }
box { <82, 45, 30062>, <93, 52, 30073> pigment { color rgb <0.25, 0.30, 0.35> } finish { Wall } }
// A lighthouse on the breakwater, 25 m.
cylinder { <-300, 0, 29900>, <-300, 25, 29900>, 3
    pigment { gradient y color_map { [0.5 color rgb <0.95, 0.95, 0.95>] [0.5 color rgb <0.75, 0.10, 0.10>] } scale 5 }
    finish { Wall } }
box { <-340, 0, 29890>, <-260, 2, 29910> pigment { Stone } finish { Wall } }
