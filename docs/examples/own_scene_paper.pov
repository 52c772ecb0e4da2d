// own_scene.pov in the paper's air (Khote & Howard's exaggerated desert, about 6000 times the
// hot road's n^2 - n(0)^2): the apparent horizon falls below the frame (docs/framing.md).
//   build/mirage frame docs/examples/own_scene_paper.pov
#version 3.7;
#declare Mirage_Preset = "paper";
#include "own_scene.pov"
