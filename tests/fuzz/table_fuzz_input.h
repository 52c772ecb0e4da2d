// What the fuzz targets of the CSV tables, the soundings and the TrueType fonts do with one
// input, shared by their libFuzzer harnesses (csv_fuzzer.cpp, sounding_fuzzer.cpp,
// truetype_fuzzer.cpp; make fuzz FUZZ_TARGET=...) and the replay of every input that ever
// crashed (fuzz_replay_test.cpp, under CTest with the normal build).
//
// Each input is a file's bytes.  A refusal must name a place ("file: ..." or
// "file:line:column: ..."); everything accepted must give finite numbers.  A crash, a
// sanitizer's report, a hang or an abort is a bug.
#pragma once

#include <cmath>
#include <string>
#include <string_view>

#include "atmosphere/general_profile.h"
#include "atmosphere/path_batch.h"
#include "atmosphere/sounding.h"
#include "scene/truetype.h"
#include "scene_fuzz_input.h"
#include "util/csv.h"

namespace mirage::fuzz {

/// A batch CSV of `mirage path --batch`: parsed, then every row through the exponential
/// profiles' closed forms.
inline void check_csv_input(std::string_view text) {
    auto table = parse_csv(text, "rays.csv");
    if (!table) {
        check_message(table.message());
        return;
    }
    auto out = run_path_batch(*table);
    if (!out) check_message(out.message());
}

/// A sounding: parsed, then its air model made and fitted as a scene's would be (with the
/// coarse spans), on flat ground and on the Earth.
inline void check_sounding_input(std::string_view text) {
    auto sounding = parse_sounding(text, "sounding.csv");
    if (!sounding) {
        check_message(sounding.message());
        return;
    }
    for (const double radius : {0.0, 6371000.0}) {
        AirSpec spec;
        spec.source = AirSpec::Source::Sounding;
        spec.sounding = *sounding;
        spec.earth_radius_m = radius;
        FitSettings fit;
        fit.tolerance_n = 1e-10;
        fit.coarse_spans = true;
        // Fewer pieces than a command allows (2^20), so that each input takes milliseconds:
        // reaching a command's limit takes tens of seconds.
        fit.max_pieces = 20000;
        auto q = fit_air(spec, fit);
        if (!q) {
            check_message(q.message());
            continue;
        }
        for (int j = 0; j <= (*q)->piece_count(); j += 1 + (*q)->piece_count() / 16)
            if (!std::isfinite((*q)->n_sq((*q)->knot(j))))
                broken("a fitted n that is not finite", "");
    }
}

/// A font file: read, then a string of every printable Latin-1 character laid out (its glyphs
/// read, composite ones with their parts).
inline void check_truetype_input(std::string_view bytes) {
    auto font = read_truetype_font("font.ttf", bytes);
    if (!font) {
        check_message(font.message());
        return;
    }
    std::string text;
    for (int c = 32; c < 127; ++c) text += static_cast<char>(c);
    text += "\xc3\xa9\xc3\xbc\xc2\xa9";  // a few Latin-1 letters, as UTF-8
    auto laid = layout_text(**font, text, 0.5, glm::dvec3(0.0));
    if (!laid) {
        check_message(laid.message());
        return;
    }
    for (const auto& g : laid->glyphs) {
        if (!std::isfinite(g.offset.x) || !std::isfinite(g.offset.y))
            broken("a glyph placed at a point that is not finite", "");
        std::size_t points = 0;
        for (const auto& c : g.glyph->contours) points += c.x.size();
        if (points > static_cast<std::size_t>(kMaxGlyphPoints) + g.glyph->contours.size())
            broken("a glyph past the points bound", std::to_string(points));
    }
}

}  // namespace mirage::fuzz
