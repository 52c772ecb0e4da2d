// TrueType fonts read the way POV-Ray 3.7 reads them (backend/shape/truetype.cpp): the tables
// it uses (head, maxp, loca, hhea, hmtx, cmap formats 0, 4 and 6, kern format 0, glyf with
// composite glyphs), its choice of character map and its placement of the glyphs of a string,
// so that text has POV-Ray's geometry point for point.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "scene/shapes.h"
#include "util/result.h"

namespace mirage {

class TrueTypeFont;

/// The largest font file read, bytes.
constexpr std::size_t kMaxFontBytes = std::size_t{64} << 20;
/// The most points one glyph may have (with every part of a composite glyph): a ray that
/// meets the glyph tests each of its segments.  Real fonts stay under a few thousand.
constexpr int kMaxGlyphPoints = 20000;
/// The most glyph parts read for one character (a composite glyph and the glyphs it names,
/// at every level): mutated fonts name the same part thousands of times over.
constexpr int kMaxGlyphParts = 1000;

/// Opens and reads a font file (the glyphs are read when a string needs them): a regular file
/// of at most kMaxFontBytes.
Result<std::shared_ptr<TrueTypeFont>> load_truetype_font(const std::string& path);

/// The same from the file's bytes; `name` names it in messages.
Result<std::shared_ptr<TrueTypeFont>> read_truetype_font(const std::string& name,
                                                         std::string_view bytes);

/// The text object POV-Ray's ProcessNewTTF builds: one placed glyph per character of the
/// string (Latin-1 code points), `thickness` deep, `offset` added after each character.
Result<Text> layout_text(TrueTypeFont& font, const std::string& text, double thickness,
                         const glm::dvec3& offset);

}  // namespace mirage
