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

sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.000 color rgb <0.84, 0.87, 0.92>]
            [0.006 color rgb <0.62, 0.74, 0.90>]
            [1.000 color rgb <0.25, 0.40, 0.75>]
        }
    }
}

// The cold sea.
plane {
    y, 0
    pigment { gradient z color_map { [0 color rgb <0.08, 0.20, 0.30>] [1 color rgb <0.12, 0.26, 0.36>] } scale 300 }
    finish { ambient 0.3 diffuse 0.5 }
}

#declare Wall = finish { ambient 0.35 diffuse 0.6 }
// Green hills behind the coast, 60 to 120 m high.
box { <-600, 0, 30400>, <-150, 90, 31000> pigment { color rgb <0.28, 0.42, 0.22> } finish { Wall } }
box { <-150, 0, 30500>, <250, 120, 31000> pigment { color rgb <0.24, 0.38, 0.20> } finish { Wall } }
box { <250, 0, 30350>, <600, 60, 31000> pigment { color rgb <0.30, 0.44, 0.24> } finish { Wall } }
// The harbour town at sea level: a quay, houses 8 to 20 m high, a church tower.
box { <-500, 0, 29990>, <500, 3, 30100> pigment { color rgb <0.55, 0.52, 0.48> } finish { Wall } }
#for (K, 0, 23)
    #declare X = -460 + 40 * K;
    #declare H = 8 + 12 * mod(K * 7, 5) / 4;
    box { <X, 3, 30010 + 20 * mod(K, 3)>, <X + 28, H, 30030 + 20 * mod(K, 3)>
          pigment { color rgb <0.95, 0.92, 0.85> - 0.25 * mod(K, 2) * <0, 0.3, 0.4> } finish { Wall } }
    box { <X - 1, H, 30009 + 20 * mod(K, 3)>, <X + 29, H + 3, 30031 + 20 * mod(K, 3)>
          pigment { color rgb <0.65, 0.18, 0.12> } finish { Wall } }
#end
box { <80, 3, 30060>, <95, 45, 30075> pigment { color rgb <0.70, 0.68, 0.62> } finish { Wall } }
box { <82, 45, 30062>, <93, 52, 30073> pigment { color rgb <0.25, 0.30, 0.35> } finish { Wall } }
// A lighthouse on the breakwater, 25 m.
cylinder { <-300, 0, 29900>, <-300, 25, 29900>, 3
    pigment { gradient y color_map { [0.5 color rgb <0.95, 0.95, 0.95>] [0.5 color rgb <0.75, 0.10, 0.10>] } scale 5 }
    finish { Wall } }
box { <-340, 0, 29890>, <-260, 2, 29910> pigment { color rgb <0.5, 0.5, 0.5> } finish { Wall } }
