// looming.pov: a superior mirage over a frozen lake.  The ice keeps the air next to it
// colder than the air above (T = 275 K - 15 K exp(-y / 3 m)), so the index falls with height
// and rays bend down: far objects, a shore with a cabin and a boat-house 1.5 to 4 km away,
// are lifted above where they would be (looming), the far ice rises into view and the
// nearly level rays are trapped, coming back down to the ice.  Real air, a long lens.
//
//   make render SCENE=scenes/looming.pov W=640 H=480      (POV-Ray through the bands)
//   build/mirage compile scenes/looming.pov -W 640 -H 480 -o build/looming --render
//   build/mirage trace scenes/looming.pov -W 640 -H 480 -o looming.png   (the exact paths)
// Plain POV-Ray (`povray +Lpov_includes scenes/looming.pov`) renders it without the mirage,
// with a warning: the bands and the camera that make the mirage are what `mirage compile`
// writes.
#version 3.7;

#declare Mirage_Air_Temperature    = 275;   // K, aloft
#declare Mirage_Ground_Temperature = 260;   // K, at the ice
#declare Mirage_Scale_Height       = 3;     // m
#declare Mirage_Tolerance          = 1.0;   // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 2, 0>
    look_at  <0, 2, 1000>
    right    x * image_width / image_height
    angle    1.2
}

light_source { <-3000, 2000, -2000>, color rgb <1, 0.97, 0.92> }

// The sky by the direction's height y.  `scale 2.2 translate -1.1 * y` spreads y from -1 to
// 1 over the pattern's 0.05 to 0.95, so it never wraps (plain `gradient y` jumps to the map's
// far end just below the horizontal); the entry for height Y sits at 0.5 + Y / 2.2, and
// below the horizon the sky keeps its haze.
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5               color rgb <0.88, 0.90, 0.94>]
            [0.5 + 0.010 / 2.2 color rgb <0.65, 0.75, 0.92>]
            [0.5 + 1.000 / 2.2 color rgb <0.20, 0.35, 0.75>]
        }
        scale 2.2 translate -1.1 * y
    }
}

// Ice, with 50 m squares.
plane {
    y, 0
    pigment { checker color rgb <0.80, 0.86, 0.92>, color rgb <0.70, 0.78, 0.86> scale 50 }
    finish { ambient 0.3 diffuse 0.6 }
}

// The far shore: a low bank, a red cabin, a boat-house and a row of dark trees.
box { <-40, 0, 3900>, <40, 2, 4000> pigment { color rgb <0.35, 0.30, 0.25> } }
box { <-6, 2, 3905>, <4, 8, 3915> pigment { color rgb <0.70, 0.12, 0.08> } }
box { <-7, 8, 3904>, <5, 10, 3916> pigment { color rgb <0.25, 0.25, 0.28> } }
box { <10, 0, 2400>, <22, 6, 2412> pigment { color rgb <0.85, 0.80, 0.60> } }
#for (X, -38, 38, 6)
    cylinder { <X, 2, 3960>, <X, 14, 3960>, 1.5 pigment { color rgb <0.10, 0.25, 0.12> } }
#end

// A marker pole on the ice at 1500 m.
cylinder { <-8, 0, 1500>, <-8, 4, 1500>, 0.3 pigment { color rgb <0.95, 0.60, 0.05> } }
