// sunset.pov: the sun setting over a calm sea, flattened and with a green rim, in colour.
// Real air on the curved Earth, followed to its top: 10 degC at sea level, the standard lapse
// of 6.5 K/km, and a 3 K inversion from 10 to 20 m (warm air over a cool sea, its corners
// smoothed by 0.5 m) that makes a duct; above 1 km (Mirage_Top's default here) the standard
// atmosphere to 47 km (Mirage_Upper_Air), so that the sun's rays are refracted all the way
// out, about 35' at the horizon, as the refraction tables say (docs/colour.md).  The eye is
// 15 m up, in the duct: below the horizon the sky is seen again in bands, and the sun's lower
// limb spreads along the horizon.  Each colour channel is traced through the air at its own
// wavelength (Mirage_Wavelengths, Ciddor's index): blue and green are lifted more than red,
// about 30" apart at the horizon, and the upper limb shows a green rim.  The sun is a disc
// of the sky (the sky is where the rays go when they leave the air), 0.53 degrees across,
// reddened; its true elevation is Sun_Elevation degrees (-0.7 by default: the disc's centre
// 0.7 degrees below the true horizon, seen as a flattened half sun spread along the sea).
//
//   build/mirage trace scenes/sunset.pov -W 640 -H 480 -o sunset.png
//   build/mirage trace scenes/sunset.pov -W 640 -H 480 --declare Sun_Elevation=-0.6 -o higher.png
//   build/mirage trace scenes/sunset.pov -W 640 -H 480 --declare Sun_Elevation=-0.84 \
//       --declare Angle=0.2 -o flash.png          (the last strip through a longer lens)
//   build/mirage animate scenes/sunset.pov --model trace --frames 120 --fps 24 -W 640 -H 480 \
//       -o build/animate/sunset                    (the sun setting: docs/sunset.mp4)
// Only the tracer renders this mirage: `mirage compile` refuses it (POV-Ray would see the sky
// of a curved Earth 220 km wide 34.5 mrad off), and plain POV-Ray
// (`povray +Lpov_includes scenes/sunset.pov`) renders it without the atmosphere.
#version 3.7;

#declare Mirage_Air_Temperature     = 283.15;           // K at sea level, under the inversion
#declare Mirage_Lapse               = 6.5;              // K per km
#declare Mirage_Inversion           = <10, 20, 3>;      // from 10 to 20 m, 3 K warmer
#declare Mirage_Inversion_Smoothing = 0.5;              // m
#declare Mirage_Index               = "ciddor";
#declare Mirage_Wavelengths         = <610, 550, 465>;  // nm: the red, green and blue channels
#declare Mirage_Upper_Air           = "standard";       // to 47 km, then vacuum
#declare Mirage_Extent              = 200000;           // m: paths followed 200 km over the sea
#declare Mirage_Tolerance           = 0.25;             // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

// The still: the sun's centre 0.7 degrees below the true horizon, through a 0.8 degree lens.
// Animated (`mirage animate`, clock from 0 to 1), the sun sets from -0.5 to -0.885 degrees,
// slowing towards the end (the clock eased out: the last fifth of the frames covers the last
// 0.034 degrees, the last sliver and its green rim) through a 0.6 degree lens looking 0.08
// degrees up, so that the 5" rim is 1.5 pixels at 640x480 rather than 1 (a video's 4:2:0
// colour, at half the resolution, loses most of a one-pixel rim).  A declared value wins.
#ifndef (Sun_Elevation)                                      // true, degrees
    #declare Sun_Elevation = (clock_on ? -0.5 - 0.385 * (1 - pow(1 - clock, 1.5)) : -0.7);
#end
#ifndef (Angle) #declare Angle = (clock_on ? 0.6 : 0.8); #end  // the lens: horizontal, degrees
#ifndef (View) #declare View = (clock_on ? 0.08 : 0); #end      // the camera's elevation, degrees
#declare Eye = 15;                                           // m above the sea

camera {
    location <0, Eye, 0>
    look_at  <0, Eye + 1000 * tan(radians(View)), 1000>
    right    x * image_width / image_height
    angle    Angle
}

// The dusk sky by the direction's height y (`scale 2.2 translate -1.1 * y`, as in
// fata_morgana.pov: the entry for height Y at 0.5 + Y / 2.2): deep blue overhead, violet a few
// degrees up, orange along the horizon; below it, dark.  Over it an aureole, the glow of light
// scattered forward about the sun (falling from its centre to nothing 1.2 degrees away), and
// the sun, a disc of the `spherical`
// pattern about its direction (the pattern falls from 1 at the centre to 0 at the disc's
// angular radius; transparent outside), limb-darkened and reddened by the long path through
// the air (little blue is left).  Its limb fades in over a thousandth of its radius (1"), so
// that the sky's colour stays continuous (tests/scenes/shipped_sky_test.cpp), far finer than
// the colours' rims.
#declare Sun_Radius = radians(0.2667);
#declare Sun_Direction = <0, sin(radians(Sun_Elevation)), cos(radians(Sun_Elevation))>;
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5 - 0.06 / 2.2  color rgb <0.006, 0.008, 0.018>]
            [0.5 - 0.03 / 2.2  color rgb <0.08, 0.016, 0.016>]
            [0.5 - 0.012 / 2.2 color rgb <0.30, 0.045, 0.012>]
            [0.5 - 0.004 / 2.2 color rgb <0.20, 0.035, 0.025>]
            [0.5 + 0.004 / 2.2 color rgb <0.11, 0.025, 0.040>]
            [0.5 + 0.04 / 2.2  color rgb <0.05, 0.025, 0.070>]
            [0.5 + 0.3 / 2.2   color rgb <0.015, 0.020, 0.080>]
            [0.5 + 1 / 2.2     color rgb <0.008, 0.012, 0.050>]
        }
        scale 2.2 translate -1.1 * y
    }
    pigment {
        spherical
        color_map {
            [0.0 color rgbt <0.9, 0.25, 0.03, 1>]
            [0.6 color rgbt <0.9, 0.28, 0.04, 0.85>]
            [1.0 color rgbt <1.0, 0.40, 0.06, 0.65>]
        }
        scale radians(1.2)
        translate Sun_Direction
    }
    pigment {
        spherical
        color_map {
            [0.0   color rgbt <0, 0, 0, 1>]
            [0.002 color rgbt <0, 0, 0, 1>]
            [0.003 color rgb <1.0, 0.50, 0.06>]
            [0.4   color rgb <1.0, 0.72, 0.10>]
            [1.0   color rgb <1.0, 0.82, 0.14>]
        }
        scale Sun_Radius
        translate Sun_Direction
    }
}

// The calm sea: dark water that mirrors the sky and the sun dimly far out.  Near the eye (to
// 6 km, blended into the far sea over the next 3 km) it shows its own dark colour: a swell there
// (tried: POV-Ray's `bumps`, 150 m across, with a Fresnel reflection) reflects only the dark
// sky degrees up and rendered as this colour, uniform, at the cost of a reflected ray a pixel.
// Farther out, where the rays meet the sea at a tenth of a degree or less and the duct's paths
// run on for tens of kilometres, it is a flat, dim mirror (15 %): the sun's and the sky's
// reflections below them.  A swell's glitter there is chaos (a path moved within its
// tolerance meets the sea elsewhere along the line of sight, on another slope, so that every
// channel and every sampling of the same ray finds the sun or the sky at random: coloured
// streaks, and the check of the tracer's two samplings, tests/trace/near_sampling_test.cpp,
// fails), while a flat mirror's image moves with the paths as the rest of the picture does.
#declare Near_Sea = texture {
    pigment { color rgb <0.0044, 0.0065, 0.0123> }
    finish { ambient 1 diffuse 0 }
}
#declare Far_Sea = texture {
    pigment { color rgb <0.012, 0.016, 0.028> }
    finish { ambient 1 diffuse 0 reflection 0.15 }
}
plane {
    y, 0
    texture {
        cylindrical  // 1 at the eye's vertical, falling to 0 at 20 km from it
        texture_map { [1 - 9000 / 20000 Far_Sea] [1 - 6000 / 20000 Near_Sea] }
        scale 20000
    }
}
