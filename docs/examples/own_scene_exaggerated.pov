// own_scene.pov with the air exaggerated 100 times (NOT AIR: Mirage_Exaggeration), a
// 20 degree lens and the objects moved 60 m farther (docs/framing.md).
//   build/mirage trace docs/examples/own_scene_exaggerated.pov -o own_exaggerated.png
#version 3.7;
#declare Mirage_Exaggeration = 100;
#declare Frame_Angle = 20;
#declare Frame_Far = 60;
#include "own_scene.pov"
