// shimmer_road.pov: heat shimmer over a hot road, through a long lens.  The road.pov mirage
// (air over sun-heated asphalt, the "hot-road" profile: the road shows the sky, upside down,
// like water) and turbulent air over it: C_n^2 = 1e-12 m^-2/3, the strong turbulence a metre
// above hot asphalt on a sunny day, inner scale 5 mm, outer scale 1 m, a light breeze of 1 m/s
// across the view carrying it (frozen flow), seen through a telescope's lens of 10 cm aperture
// (its average over the aperture keeps the eddies smaller than it from jittering the image).
// The scene is road.pov's, seen through a longer lens (1.2 degrees wide, from an eye 1.5 m
// above the road): a car 600 m away, a van at 900 m, posts every 100 m along both verges and
// trees at 3.2 km.  They tremble, and the mirrored sky and the images in it boil; frame to
// frame the air moves on, so the picture shimmers rather than flickers (docs/turbulence.md).
// The clock is the time in seconds.
//
//   build/mirage trace scenes/shimmer_road.pov -W 640 -H 480 -o shimmer.png      (a still)
//   build/mirage animate scenes/shimmer_road.pov --model trace --frames 60 +KI0 +KF2.4 --fps 25
// Plain POV-Ray renders it without the mirage and without the shimmer, with a warning.
#version 3.7;

#declare Mirage_Preset    = "hot-road";
#declare Mirage_Tolerance = 1.0;    // pixels
#declare Mirage_Turbulence_Cn2      = 1e-12;       // m^-2/3
#declare Mirage_Turbulence_Inner    = 0.005;       // m
#declare Mirage_Turbulence_Outer    = 1;           // m: about the height above the road
#declare Mirage_Turbulence_Aperture = 0.1;         // m: the lens's
#declare Mirage_Wind                = <1, 0.2, 0>; // m/s: across the view, and rising
#declare Mirage_Turbulence_Seed     = 3;
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.5, 0>            // eye 1.5 m above the road, level
    look_at  <0, 1.5, 1000>
    right    x * image_width / image_height
    angle    1.2                    // horizontal field; 0.9 degrees vertical at 4:3
}

light_source { <-2000, 3000, -1000>, color rgb <1, 0.98, 0.92> }

// The sky by the direction's height y: hazy white at the horizon, clear blue a third of a
// degree above it, and low clouds.  `scale 2.2 translate -1.1 * y` spreads y from -1 to 1
// over the pattern's 0.05 to 0.95, so it never wraps (plain `gradient y` jumps to the map's
// far end just below the horizontal); the entry for height Y sits at 0.5 + Y / 2.2.
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5                color rgb <0.90, 0.91, 0.93>]
            [0.5 + 0.002 / 2.2  color rgb <0.62, 0.74, 0.92>]
            [0.5 + 0.0055 / 2.2 color rgb <0.28, 0.48, 0.88>]
            [0.5 + 0.01 / 2.2   color rgb <0.16, 0.32, 0.76>]
        }
        scale 2.2 translate -1.1 * y
    }
    pigment {
        bozo
        turbulence 0.4
        color_map {
            [0.00 color rgbt <1, 1, 1, 1>]
            [0.60 color rgbt <1, 1, 1, 1>]
            [0.80 color rgbt <0.97, 0.97, 0.98, 0.5>]
            [1.00 color rgbt <1, 1, 1, 0.2>]
        }
        scale <0.003, 0.0008, 0.003>
    }
}

// The ground: asphalt 8 m wide with 10 m squares to read distances and a dashed white centre
// line, dry grass on the verges.  One plane, its pigment chosen across the road by x:
// `gradient x scale 200 translate -100 * x` runs from 0 to 1 over x from -100 to 100 m (the
// road's edges at 0.48 and 0.52), and the patterns inside are scaled by the same 200.
#declare Asphalt = pigment { checker color rgb <0.21, 0.21, 0.22>, color rgb <0.24, 0.24, 0.25> scale 10 / 200 }
#declare Centre_Line = pigment {
    gradient z
    color_map { [0.5 color rgb 0.9] [0.5 color rgb <0.21, 0.21, 0.22>] }
    scale 12 / 200
}
#declare Grass = pigment {
    bozo color_map { [0 color rgb <0.55, 0.48, 0.28>] [1 color rgb <0.40, 0.36, 0.20>] }
    scale <8, 1, 40> / 200
}
plane {
    y, 0
    pigment {
        gradient x
        pigment_map {
            [0.48   Grass]
            [0.48   Asphalt]
            [0.4996 Asphalt]
            [0.4996 Centre_Line]
            [0.5004 Centre_Line]
            [0.5004 Asphalt]
            [0.52   Asphalt]
            [0.52   Grass]
        }
        scale 200 translate -100 * x
    }
    finish { ambient 0.2 diffuse 0.7 }
}

// A red car 600 m away, coming towards the eye.
#declare Paint = finish { ambient 0.2 diffuse 0.6 specular 0.4 roughness 0.05 reflection 0.1 }
union {
    box { <-0.9, 0.3, -2.2>, <0.9, 1.0, 2.2> pigment { color rgb <0.80, 0.08, 0.06> } }
    box { <-0.8, 1.0, -1.0>, <0.8, 1.45, 1.2> pigment { color rgb <0.15, 0.20, 0.28> } }
    cylinder { <-0.95, 0.32, -1.4>, <0.95, 0.32, -1.4>, 0.32 pigment { color rgb 0.04 } }
    cylinder { <-0.95, 0.32, 1.4>, <0.95, 0.32, 1.4>, 0.32 pigment { color rgb 0.04 } }
    box { <-0.7, 0.55, -2.25>, <-0.4, 0.7, -2.2> pigment { color rgb <1, 1, 0.85> } finish { ambient 1 } }
    box { <0.4, 0.55, -2.25>, <0.7, 0.7, -2.2> pigment { color rgb <1, 1, 0.85> } finish { ambient 1 } }
    finish { Paint }
    translate <-1.7, 0, 600>
}

// A white van 900 m away, going away.
union {
    box { <-1.0, 0.35, -2.6>, <1.0, 2.4, 2.6> pigment { color rgb <0.92, 0.92, 0.90> } }
    box { <-0.9, 1.3, -2.65>, <0.9, 2.2, -2.6> pigment { color rgb <0.20, 0.25, 0.30> } }
    cylinder { <-1.05, 0.35, -1.8>, <1.05, 0.35, -1.8>, 0.35 pigment { color rgb 0.04 } }
    cylinder { <-1.05, 0.35, 1.8>, <1.05, 0.35, 1.8>, 0.35 pigment { color rgb 0.04 } }
    finish { Paint }
    translate <1.8, 0, 900>
}

// Posts along both verges every 100 m.
#declare Post = cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.08 pigment { color rgb <0.95, 0.95, 0.95> } }
#for (D, 200, 1400, 100)
    object { Post translate <-4.5, 0, D> }
    object { Post translate <4.5, 0, D> }
#end

// A row of trees 3 to 3.6 km away on the horizon, hazy with distance: their trunks are
// hidden below the fold and their crowns mirrored, which draws the "water's" far shore.
#declare Crown = finish { ambient 0.75 diffuse 0 }   // far off: flat, hazy silhouettes
// Undergrowth along the row, up to the crowns.
box { <-100, 0, 3200>, <100, 4, 3210> pigment { color rgb <0.24, 0.33, 0.26> } finish { Crown } }
#for (K, 0, 89)
    #declare X = -90 + 2 * K + 1.3 * mod(K * 7, 3);
    #declare Z = 3200 + 100 * mod(K * 3, 5);
    #declare R = 1.8 + 0.5 * mod(K * 5, 4);
    cylinder { <X, 0, Z>, <X, 3, Z>, 0.3 pigment { color rgb <0.25, 0.22, 0.20> } }
    sphere { <X, 2 + R, Z>, R
        pigment { color rgb <0.22, 0.32, 0.25> + 0.04 * mod(K * 7, 4) * <1, 0.8, 0.9> } finish { Crown } }
#end
