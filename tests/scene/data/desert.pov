// A mirage scene as a user writes it; parsed by parser_test.cpp.
#version 3.7;
#include "colors.inc"

// The atmosphere, read by mirage from the scene's declarations.
#ifndef (Mirage_Profile) #declare Mirage_Profile = "paper"; #end
#declare Mirage_Eye_Height = 1.5;

global_settings { assumed_gamma 1.0 max_trace_level 256 }

camera {
    location <0, Mirage_Eye_Height, 0>
    look_at <0, Mirage_Eye_Height, 10>
    right x * image_width / image_height
    angle 46.8
}

light_source { <-100, 200, -100>, White * 1.2 }

sky_sphere {
    pigment {
        gradient y
        color_map { [0 color rgb <0.9, 0.9, 1>] [1 color rgb <0.2, 0.3, 0.8>] }
    }
}

plane {
    y, 0
    pigment { checker color rgb <0.9, 0.8, 0.6>, color rgb <0.7, 0.6, 0.4> scale 2 }
    finish { ambient 0.2 diffuse 0.8 }
}

#macro Ball(Z, Colour)
    sphere { <0, 1, Z>, 1 texture { pigment { color Colour } finish { phong 0.5 } } }
#end

#for (I, 1, 5)
    Ball(10 * I, (I = 3 ? Red : Orange))
#end
