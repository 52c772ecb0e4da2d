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

#ifndef (Sun_Elevation) #declare Sun_Elevation = -0.7; #end  // true, degrees
#ifndef (Angle) #declare Angle = 0.8; #end                   // the lens: horizontal field, degrees
#ifndef (View) #declare View = 0; #end                       // the camera's elevation, degrees
#declare Eye = 15;                                           // m above the sea

camera {
    location <0, Eye, 0>
    look_at  <0, Eye + 1000 * tan(radians(View)), 1000>
    right    x * image_width / image_height
    angle    Angle
}

// The sky by the direction's height y (`scale 2.2 translate -1.1 * y`, as in
// fata_morgana.pov: the entry for height Y at 0.5 + Y / 2.2), dim and red low down; over it
// the sun, a disc of the `spherical` pattern about its direction (the pattern falls from 1 at
// the centre to 0 at the disc's angular radius; transparent outside), limb-darkened and
// reddened by the long path through the air (little blue is left).  Its limb fades in over a
// thousandth of its radius (1"), so that the sky's colour stays continuous
// (tests/scenes/shipped_sky_test.cpp), far finer than the colours' rims.
#declare Sun_Radius = radians(0.2667);
#declare Sun_Direction = <0, sin(radians(Sun_Elevation)), cos(radians(Sun_Elevation))>;
sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.5 - 0.02 / 2.2 color rgb <0.16, 0.05, 0.025>]
            [0.5              color rgb <0.12, 0.045, 0.025>]
            [0.5 + 0.02 / 2.2 color rgb <0.06, 0.035, 0.04>]
            [0.5 + 1 / 2.2    color rgb <0.03, 0.04, 0.10>]
        }
        scale 2.2 translate -1.1 * y
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

// The calm sea, dark.
plane { y, 0 pigment { color rgb <0.015, 0.02, 0.035> } finish { ambient 1 diffuse 0 } }
