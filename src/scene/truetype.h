// TrueType fonts read the way POV-Ray 3.7 reads them (backend/shape/truetype.cpp): the tables
// it uses (head, maxp, loca, hhea, hmtx, cmap formats 0, 4 and 6, kern format 0, glyf with
// composite glyphs), its choice of character map and its placement of the glyphs of a string,
// so that text has POV-Ray's geometry point for point.
#pragma once

#include <memory>
#include <string>

#include "scene/shapes.h"
#include "util/result.h"

namespace mirage {

class TrueTypeFont;

/// Opens and reads a font file (the glyphs are read when a string needs them).
Result<std::shared_ptr<TrueTypeFont>> load_truetype_font(const std::string& path);

/// The text object POV-Ray's ProcessNewTTF builds: one placed glyph per character of the
/// string (Latin-1 code points), `thickness` deep, `offset` added after each character.
Result<Text> layout_text(TrueTypeFont& font, const std::string& text, double thickness,
                         const glm::dvec3& offset);

}  // namespace mirage
