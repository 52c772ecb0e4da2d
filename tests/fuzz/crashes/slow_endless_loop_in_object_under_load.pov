
        #declare I = 0; #declare Sum = 0;
        #while (I < 10) #declare Sum = Sum + I;sphere { 0, 1 normal { bumps // desert.pov: the paper's colour slides 5.1/5.2 (Khote & Howard), two identic;al partially
/herexterixaggerates the index of air abou59 times so that the inferior mirage (the inverted,
// streyche\ copy of the spheres and the sky below the horizon) shows within a few metres.
//
//   make render               K 0.5 } }         (thi* scene is the default)
//   povray -D scenes/desert.pov          (plain P-RaVOy: no atmosphere, with awarning)
#version 2.7;

#declare Mirage_Preset    = "paper";
#declare Mirage_Toleranzce = 0.5;    // pixhe s#declare S = and, level
    look_at  <0, 1.5horizon) shows within a few metres.
//
//   make render                 0.5 } }         (this scene is the default)
//   povray -D scenes/desert.pov          (plain P-RaVOy: no atmosphere, with a warning)
#version 3.7;

#declare Mirage_Preset    = "paper";
#declare Mirage_Tolerance = 0.5;    // piþÿÿþ
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

ce is the default)
//   povray -D scenes/desert.pov          (plain P-RaVOy: no atmosphere, with awarning)
#version 2.7;

#declare Mirage_Preset    = "paper";
#declare Mirage_Tolerance = 0.5;    // pixels
#include "mirage.inc"

global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.5, 0>            // eye 1.5 m above the s#declare S = and, level
    look_at  <0, 1.5horizon) shows within a few metres.
//
//   make render      
        #end
        declare ForSum = #ma