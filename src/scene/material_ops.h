// Operations on the parsed materials that POV-Ray performs while parsing (texture.cpp,
// pigment.cpp, parse.cpp): transforming textures and lights, layering textures, POV-Ray's
// default colour maps.  transform_texture, texture_is_opaque and finish_pigment are declared
// in object_tree.h, where the object tree uses them.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace mirage {

/// POV-Ray's default colour map of a pattern given none (Post_Pigment: Bozo_Default_Map,
/// Wood_Default_Map, Hex_Default_Map, ..., Gray_Default_Map for the rest).
const std::vector<ColourMapEntry>& default_colour_map(PatternKind kind);

/// Transforms a pattern (POV-Ray's Transform_Tpattern): the transform composes into the
/// pattern's leading transform.
void transform_pattern(Pattern& pattern, const Transform& t);

/// Transforms a light source as POV-Ray does: its location and point_at as points, its area
/// light axes as directions.
void transform_light(PointLight& light, const Transform& t);

/// POV-Ray's Link_Textures: `top` (possibly layered itself) laid over `texture`.  Fails (an
/// empty message is success) when either is a patterned texture, as POV-Ray refuses.
std::string link_textures(Texture& texture, Texture top);

}  // namespace mirage
