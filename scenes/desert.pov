// desert.pov: the paper's colour slides 5.1/5.2 (Khote & Howard), two identical partially
// reflective spheres at the same height and distance over hot sand.  The `paper` atmosphere
// exaggerates the index of air about 360 times so that the inferior mirage shows within a few
// metres: every ray from the eye that leaves less than 24.3 degrees below the horizon turns
// above the sand and rises again, so the sand shows only within 4 m of the eye, below that
// depression, and above it lies the sky mirrored like water.  The camera looks 12 degrees
// down to take in the sand, the mirrored sky and the spheres.  Each sphere stands on its own
// inverted, stretched image: the rays that reach 14 m lowest pass 1.34 m above the sand
// (mirage path --preset paper --eye-height 1.5 --elevation-deg -7), the spheres' bottoms are
// at 1.2 m, and above that fold every height is seen twice, erect above and inverted below.
//
//   make render                          (this scene is the default; POV-Ray through the bands)
//   build/mirage compile scenes/desert.pov -W 640 -H 480 -o build/desert --render
//   build/mirage trace scenes/desert.pov -W 640 -H 480 -o desert.png   (the exact paths)
// Plain POV-Ray (`povray +Lpov_includes scenes/desert.pov`) renders it without the mirage,
// with a warning: the bands and the camera that make the mirage are what `mirage compile`
// writes.
#version 3.7;

#declare Mirage_Preset    = "paper";
#declare Mirage_Tolerance = 0.5;    // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.5, 0>            // eye 1.5 m above the sand
    look_at  <0, 0, 7>              // 12 degrees down
    right    x * image_width / image_height
    angle    60
}

light_source { <-30, 60, -20>, color rgb <1, 0.97, 0.9> }

// The sky by the direction's height y, pale at the horizon and deep blue at the zenith.
// `scale 2.2 translate -1.1 * y` spreads y from -1 to 1 over the pattern's 0.05 to 0.95, so
// it never wraps (plain `gradient y` jumps to the map's far end just below the horizontal);
// the entry for height Y is at 0.5 + Y / 2.2, and below the horizon the sky is its haze.
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

// Sand: a warm checker of half-metre squares, so that distances can be read off the picture.
plane {
    y, 0
    pigment { checker color rgb <0.85, 0.72, 0.50>, color rgb <0.70, 0.55, 0.35> scale 0.5 }
    finish { ambient 0.25 diffuse 0.7 }
}

#declare Ball_Finish = finish { ambient 0.15 diffuse 0.6 specular 0.6 roughness 0.02 reflection 0.25 }

sphere { <-2.5, 2.2, 14>, 1 pigment { color rgb <0.80, 0.15, 0.10> } finish { Ball_Finish } }
sphere { < 2.5, 2.2, 14>, 1 pigment { color rgb <0.15, 0.35, 0.80> } finish { Ball_Finish } }

// A post 2.6 m high, 20 m away: only its top 0.6 m is seen, over its own inverted image;
// the rest stands below the fold (2 m there), where no ray from the eye reaches.
cylinder { <6, 0, 20>, <6, 2.6, 20>, 0.08 pigment { color rgb <0.2, 0.2, 0.2> } }
