// own_scene.pov with the framing advice followed in real air (hot-road): a 3 degree lens
// and the house, the car and the ball moved 900 m farther (docs/framing.md).
//   build/mirage trace docs/examples/own_scene_far.pov -o own_far.png
#version 3.7;
#declare Frame_Angle = 3;
#declare Frame_Far = 900;
#include "own_scene.pov"
