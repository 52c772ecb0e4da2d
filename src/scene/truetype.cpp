// TrueType reading after POV-Ray 3.7's truetype.cpp (see truetype.h).  Its quirks are kept
// where they change the geometry: the character map is chosen by platform only (Macintosh,
// then Microsoft, then Unicode) and the first one of a readable format wins; format 4's
// segments are read once per font; a composite glyph's extent mixes font units with em units
// as POV-Ray's does; kerning takes the coverage of the first kern table.
#include "scene/truetype.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "util/input_file.h"

namespace mirage {

class TrueTypeFont {
  public:
    std::string path;
    std::vector<unsigned char> data;
    std::uint32_t cmap = 0, glyf = 0;
    int units_per_em = 0;
    int index_to_loc = 0;
    int num_glyphs = 0;
    int num_hmetrics = 0;
    std::vector<std::uint32_t> loca;
    struct Metric {
        int advance = 0;
        int lsb = 0;
    };
    std::vector<Metric> hmtx;
    struct KernTable {
        int coverage = 0;
        struct Pair {
            int left, right, value;
        };
        std::vector<Pair> pairs;
        // POV-Ray scans the pairs in order for (left, right) and stops at the first pair whose
        // left is greater (the table is sorted in a well-formed font).  The same answer in
        // O(log pairs) a character, whatever the order: the first pair of each (left, right),
        // and the running maximum of left.
        std::unordered_map<std::uint32_t, int> first;
        std::vector<int> max_left;
        void index() {
            int m = -1;
            for (std::size_t i = 0; i < pairs.size(); ++i) {
                first.try_emplace(key(pairs[i].left, pairs[i].right), static_cast<int>(i));
                m = std::max(m, pairs[i].left);
                max_left.push_back(m);
            }
        }
        static std::uint32_t key(int left, int right) {
            return (static_cast<std::uint32_t>(left) << 16) | static_cast<std::uint32_t>(right);
        }
        /// The pair POV-Ray's scan finds for (left, right), or null.
        const Pair* find(int left, int right) const {
            const auto it = first.find(key(left, right));
            if (it == first.end()) return nullptr;
            const auto stop = std::upper_bound(max_left.begin(), max_left.end(), left);
            return it->second < stop - max_left.begin() ? &pairs[it->second] : nullptr;
        }
    };
    std::vector<KernTable> kern;
    // Format 4 segments, read at the first use (POV-Ray caches them per font).
    bool have_segments = false;
    std::vector<std::uint16_t> end_count, start_count, id_delta, id_range_offset;
    std::uint32_t glyph_id_offset = 0;
    struct Loaded {
        std::shared_ptr<const GlyphData> glyph;
        int metrics = 0;  // POV-Ray's myMetrics: the hmtx entry
    };
    std::map<unsigned, Loaded> by_char;
    std::map<unsigned, Loaded> by_index;

    // Big-endian readers; out of range reads throw, caught by the entry points.
    struct Bad {};
    std::uint32_t u8(std::size_t at) const {
        if (at >= data.size()) throw Bad{};
        return data[at];
    }
    std::uint32_t u16(std::size_t at) const { return (u8(at) << 8) | u8(at + 1); }
    std::int32_t s16(std::size_t at) const { return static_cast<std::int16_t>(u16(at)); }
    std::uint32_t u32(std::size_t at) const { return (u16(at) << 16) | u16(at + 2); }

    void read_tables() {
        std::size_t at = 0;
        if (data.size() >= 4 && data[0] == 't' && data[1] == 't' && data[2] == 'c' &&
            data[3] == 'f') {
            at = u32(12);  // the first font of a collection
        }
        const int tables = static_cast<int>(u16(at + 4));
        std::uint32_t head = 0, loca_off = 0, maxp = 0, kern_off = 0, hhea = 0, hmtx_off = 0;
        for (int i = 0; i < tables && i < 40; ++i) {
            const std::size_t e = at + 12 + 16 * static_cast<std::size_t>(i);
            if (e + 16 > data.size()) throw Bad{};
            const std::string tag(data.begin() + static_cast<long>(e),
                                  data.begin() + static_cast<long>(e) + 4);
            const std::uint32_t offset = u32(e + 8);
            if (tag == "cmap") cmap = offset;
            if (tag == "glyf") glyf = offset;
            if (tag == "head") head = offset;
            if (tag == "loca") loca_off = offset;
            if (tag == "maxp") maxp = offset;
            if (tag == "kern") kern_off = offset;
            if (tag == "hhea") hhea = offset;
            if (tag == "hmtx") hmtx_off = offset;
        }
        if (!cmap || !glyf || !head || !loca_off || !hhea || !hmtx_off || !maxp) throw Bad{};
        if (u32(head + 12) != 0x5F0F3CF5u) throw Bad{};
        units_per_em = static_cast<int>(u16(head + 18));
        index_to_loc = s16(head + 50);
        num_glyphs = static_cast<int>(u16(maxp + 4));
        if (num_glyphs <= 0 || units_per_em <= 0) throw Bad{};
        loca.resize(static_cast<std::size_t>(num_glyphs));
        for (int i = 0; i < num_glyphs; ++i) {
            loca[i] = index_to_loc == 0 ? u16(loca_off + 2 * static_cast<std::size_t>(i)) << 1
                                        : u32(loca_off + 4 * static_cast<std::size_t>(i));
        }
        num_hmetrics = static_cast<int>(u16(hhea + 34));
        if (num_hmetrics <= 0) throw Bad{};
        hmtx.resize(static_cast<std::size_t>(num_glyphs));
        std::size_t p = hmtx_off;
        int last_advance = 0;
        int i = 0;
        for (; i < num_hmetrics && i < num_glyphs; ++i, p += 4) {
            last_advance = static_cast<int>(u16(p));
            hmtx[i] = Metric{last_advance, s16(p + 2)};
        }
        for (; i < num_glyphs; ++i, p += 2) hmtx[i] = Metric{last_advance, s16(p)};
        if (kern_off) {
            const int n = static_cast<int>(u16(kern_off + 2));
            std::size_t k = kern_off + 4;
            for (int t = 0; t < n; ++t) {
                KernTable table;
                const int length = static_cast<int>(u16(k + 2));
                table.coverage = static_cast<int>(u16(k + 4));
                if ((table.coverage >> 8) == 0) {
                    const int pairs = static_cast<int>(u16(k + 6));
                    std::size_t q = k + 14;
                    for (int j = 0; j < pairs; ++j, q += 6) {
                        table.pairs.push_back(
                            {static_cast<int>(u16(q)), static_cast<int>(u16(q + 2)), s16(q + 4)});
                    }
                    k = q;
                } else {
                    k += static_cast<std::size_t>(length);
                }
                table.index();
                kern.push_back(std::move(table));
            }
        }
    }

    unsigned format4(std::size_t table, unsigned c) {
        if (!have_segments) {
            const int segs = static_cast<int>(u16(table + 6) >> 1);
            std::size_t p = table + 14;
            for (int i = 0; i < segs; ++i, p += 2)
                end_count.push_back(static_cast<std::uint16_t>(u16(p)));
            p += 2;  // reservedPad
            for (int i = 0; i < segs; ++i, p += 2)
                start_count.push_back(static_cast<std::uint16_t>(u16(p)));
            for (int i = 0; i < segs; ++i, p += 2)
                id_delta.push_back(static_cast<std::uint16_t>(u16(p)));
            glyph_id_offset = static_cast<std::uint32_t>(p);
            for (int i = 0; i < segs; ++i, p += 2) {
                id_range_offset.push_back(static_cast<std::uint16_t>(u16(p)));
            }
            have_segments = true;
        }
        unsigned index = 0;
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t i = 0; i < end_count.size(); ++i) {
                if (c <= end_count[i]) {
                    if (c >= start_count[i]) {
                        if (id_range_offset[i] == 0) {
                            index = c + id_delta[i];
                        } else {
                            index = u16(glyph_id_offset + 2 * i + id_range_offset[i] +
                                        2 * (c - start_count[i]));
                            if (index != 0) index += id_delta[i];
                        }
                    }
                    break;
                }
            }
            // Symbol fonts keep their characters in the Unicode user area (POV-Ray looks there).
            if (index == 0 && c < 0x100) {
                c += 0xF000;
                continue;
            }
            break;
        }
        return index & 0xFFFFu;
    }

    // POV-Ray's ProcessCharMap with the ASCII encoding's platform order.
    unsigned char_to_glyph(unsigned c) {
        const int count = static_cast<int>(u16(cmap + 2));
        for (const unsigned platform : {1u, 3u, 0u, 3u}) {
            for (int i = 0; i < count; ++i) {
                const std::size_t e = cmap + 4 + 8 * static_cast<std::size_t>(i);
                if (u16(e) != platform) continue;
                const std::size_t table = cmap + u32(e + 4);
                const unsigned format = u16(table);
                if (format == 0) return c < 256 ? u8(table + 6 + c) : 0;
                if (format == 4) return format4(table, c);
                if (format == 6) {
                    const unsigned first = u16(table + 6), n = u16(table + 8);
                    return c >= first && c < first + n ? u16(table + 10 + 2 * (c - first)) : 0;
                }
            }
        }
        return 0;
    }

    struct Outline {
        int contours = 0;
        int x_min = 0, y_min = 0, x_max = 0, y_max = 0;
        std::vector<int> end_points;
        std::vector<unsigned char> flags;
        std::vector<double> x, y;
        int metrics = 0;
    };

    // A glyph too large to trace: its points (with every part of a composite glyph) or the
    // parts read for it.
    struct TooLarge {
        std::string what;
    };
    // What reading the current glyph has cost: parts read (a composite glyph names others,
    // which may name others, up to 8 deep) and points kept.
    int parts_read = 0;

    // POV-Ray's ExtractGlyphOutline.
    Outline outline(unsigned index, unsigned c, int depth) {
        Outline o;
        o.metrics = static_cast<int>(index);
        if (depth > 8 || index >= loca.size()) return o;
        if (++parts_read > kMaxGlyphParts)
            throw TooLarge{"is made of more than " + std::to_string(kMaxGlyphParts) + " parts"};
        std::size_t p = glyf + loca[index];
        if (c != ' ') {
            o.contours = s16(p);
            o.x_min = s16(p + 2);
            o.y_min = s16(p + 4);
            o.x_max = s16(p + 6);
            o.y_max = s16(p + 8);
            p += 10;
        }
        const double em = units_per_em;
        if (o.contours > 0) {
            for (int i = 0; i < o.contours; ++i, p += 2) {
                o.end_points.push_back(static_cast<int>(u16(p)));
                // Each contour ends after the last one (a contour of one point at least).
                if (i > 0 && o.end_points[i] <= o.end_points[i - 1]) throw Bad{};
            }
            p += 2 + u16(p);  // instructions
            const int n = o.end_points.back() + 1;
            if (n > kMaxGlyphPoints) throw too_many_points(n);
            o.flags.assign(static_cast<std::size_t>(n), 0);
            for (int i = 0; i < n; ++i) {
                o.flags[i] = static_cast<unsigned char>(u8(p++));
                if (o.flags[i] & 8) {  // REPEAT_FLAGS
                    int repeat = static_cast<int>(u8(p++));
                    for (; repeat > 0; --repeat, ++i) {
                        if (i + 1 < n) o.flags[i + 1] = o.flags[i];
                    }
                }
            }
            o.x.resize(static_cast<std::size_t>(n));
            o.y.resize(static_cast<std::size_t>(n));
            int coord = 0;
            for (int i = 0; i < n; ++i) {
                const unsigned f = o.flags[i];
                if (f & 2) {  // XSHORT
                    const int d = static_cast<int>(u8(p++));
                    coord += (f & 16) ? d : -d;
                } else if (!(f & 16)) {
                    coord += s16(p);
                    p += 2;
                }
                if (coord > o.x_max) o.x_max = coord;
                if (coord < o.x_min) o.x_min = coord;
                o.x[i] = coord / em;
            }
            coord = 0;
            for (int i = 0; i < n; ++i) {
                const unsigned f = o.flags[i];
                if (f & 4) {  // YSHORT
                    const int d = static_cast<int>(u8(p++));
                    coord += (f & 32) ? d : -d;
                } else if (!(f & 32)) {
                    coord += s16(p);
                    p += 2;
                }
                if (coord > o.y_max) o.y_max = coord;
                if (coord < o.y_min) o.y_min = coord;
                o.y[i] = coord / em;
            }
        } else if (o.contours < 0) {
            o.contours = 0;
            unsigned flags;
            do {
                flags = u16(p);
                const unsigned sub = u16(p + 2);
                p += 4;
                int arg1, arg2;
                if (flags & 1) {  // ARG_1_AND_2_ARE_WORDS
                    arg1 = s16(p);
                    arg2 = s16(p + 2);
                    p += 4;
                } else {
                    // POV-Ray reads the two bytes unsigned (and signed in its SHORT).
                    const unsigned a = u16(p);
                    p += 2;
                    arg2 = static_cast<std::int16_t>(a & 0xFF);
                    arg1 = static_cast<std::int16_t>((a >> 8) & 0xFF);
                }
                double xs = 1, ys = 1, s01 = 0, s10 = 0;
                if (flags & 8) {  // WE_HAVE_A_SCALE
                    xs = ys = s16(p) / 16384.0;
                    p += 2;
                } else if (flags & 64) {  // WE_HAVE_AN_X_AND_Y_SCALE
                    xs = s16(p) / 16384.0;
                    ys = s16(p + 2) / 16384.0;
                    p += 4;
                } else if (flags & 128) {  // WE_HAVE_A_TWO_BY_TWO
                    xs = s16(p) / 16384.0;
                    s01 = s16(p + 2) / 16384.0;
                    s10 = s16(p + 4) / 16384.0;
                    ys = s16(p + 6) / 16384.0;
                    p += 8;
                }
                if (!(flags & 2)) continue;  // point matching: POV-Ray skips the part
                const double xoff = arg1 / em, yoff = arg2 / em;
                if (flags & 512) o.metrics = static_cast<int>(sub);  // USE_MY_METRICS
                const Outline s = outline(sub, c, depth + 1);
                if (s.contours == 0) continue;
                const int n = static_cast<int>(o.x.size());
                if (n + static_cast<long>(s.x.size()) > kMaxGlyphPoints)
                    throw too_many_points(n + static_cast<long>(s.x.size()));
                for (int e : s.end_points) o.end_points.push_back(e + n);
                o.contours += s.contours;
                for (std::size_t i = 0; i < s.x.size(); ++i) {
                    o.flags.push_back(s.flags[i]);
                    const double x = xs * s.x[i] + s01 * s.y[i] + xoff;
                    const double y = s10 * s.x[i] + ys * s.y[i] + yoff;
                    o.x.push_back(x);
                    o.y.push_back(y);
                    // POV-Ray compares these em values with the font-unit header (FWord).
                    if (x < o.x_min) o.x_min = static_cast<std::int16_t>(x);
                    if (x > o.x_max) o.x_max = static_cast<std::int16_t>(x);
                    if (y < o.y_min) o.y_min = static_cast<std::int16_t>(y);
                    if (y > o.y_max) o.y_max = static_cast<std::int16_t>(y);
                }
            } while (flags & 32);  // MORE_COMPONENTS
        }
        return o;
    }

    static TooLarge too_many_points(long n) {
        return TooLarge{"has " + std::to_string(n) + " points, more than the " +
                        std::to_string(kMaxGlyphPoints) + " mirage traces in a glyph"};
    }

    // POV-Ray's ProcessCharacter: glyphs are shared by character and by glyph index.
    Loaded glyph_for(unsigned c) {
        if (auto it = by_char.find(c); it != by_char.end()) return it->second;
        const unsigned index = char_to_glyph(c);
        if (auto it = by_index.find(index); it != by_index.end()) return it->second;
        parts_read = 0;
        const Outline o = outline(index, c, 0);
        auto g = std::make_shared<GlyphData>();
        g->x_min = o.x_min;
        g->y_min = o.y_min;
        g->x_max = o.x_max;
        g->y_max = o.y_max;
        g->units_per_em = units_per_em;
        int last = 0;
        for (int i = 0; i < o.contours; ++i) {
            GlyphData::Contour k;
            const int first = last, count = o.end_points[i] - last + 1;
            for (int j = 0; j < count; ++j) {
                k.x.push_back(o.x[first + j]);
                k.y.push_back(o.y[first + j]);
                k.on_curve.push_back(o.flags[first + j] & 1);
            }
            k.x.push_back(o.x[first]);
            k.y.push_back(o.y[first]);
            k.on_curve.push_back(o.flags[first] & 1);
            g->contours.push_back(std::move(k));
            last = o.end_points[i] + 1;
        }
        Loaded l{g, o.metrics};
        by_char[c] = l;
        by_index[index] = l;
        glyph_indices[c] = index;
        return l;
    }
    std::map<unsigned, unsigned> glyph_indices;
};

Result<std::shared_ptr<TrueTypeFont>> load_truetype_font(const std::string& path) {
    auto bytes = read_input_file(path, InputKind{"a font", "fonts", kMaxFontBytes});
    if (!bytes) return bytes.error();
    return read_truetype_font(path, *bytes);
}

Result<std::shared_ptr<TrueTypeFont>> read_truetype_font(const std::string& name,
                                                         std::string_view bytes) {
    auto font = std::make_shared<TrueTypeFont>();
    font->path = name;
    font->data.assign(bytes.begin(), bytes.end());
    try {
        font->read_tables();
    } catch (const TrueTypeFont::Bad&) {
        return make_error(name + ": not a TrueType font mirage can read");
    }
    return font;
}

namespace {

// UTF-8 to code points; bytes that are not UTF-8 stand for themselves (Latin-1).
std::vector<unsigned> code_points(const std::string& s) {
    std::vector<unsigned> out;
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        int n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
        if (n > 0 && i + static_cast<std::size_t>(n) < s.size() + 0) {
            unsigned cp = c & (0x3F >> n);
            bool ok = i + static_cast<std::size_t>(n) < s.size() + 1;
            for (int k = 1; k <= n && ok; ++k) {
                if (i + static_cast<std::size_t>(k) >= s.size()) {
                    ok = false;
                    break;
                }
                const unsigned char cc =
                    static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
                ok = (cc >> 6) == 2;
                cp = (cp << 6) | (cc & 0x3F);
            }
            if (ok) {
                out.push_back(cp);
                i += static_cast<std::size_t>(n) + 1;
                continue;
            }
        }
        out.push_back(c);
        ++i;
    }
    return out;
}

}  // namespace

Result<Text> layout_text(TrueTypeFont& font, const std::string& text, double thickness,
                         const glm::dvec3& offset) {
    Text out;
    out.thickness = thickness;
    unsigned last_char = 0;
    try {
        const double funit = 1.0 / font.units_per_em;
        glm::dvec3 total(0.0);
        unsigned last_index = 0;
        bool first = true;
        for (const unsigned c : code_points(text)) {
            last_char = c;
            const TrueTypeFont::Loaded g = font.glyph_for(c);
            const unsigned index = font.glyph_indices[c];
            const auto& m = font.hmtx.at(static_cast<std::size_t>(g.metrics));
            Text::Placed placed;
            placed.glyph = g.glyph;
            if (first) {
                // The first glyph starts at the origin.
                placed.offset = glm::dvec3(-g.glyph->x_min * funit, 0.0, 0.0);
                total.x = (m.advance - m.lsb) * funit;
                first = false;
            } else {
                int kx = 0, ky = 0;
                int min_x = -font.units_per_em, min_y = -font.units_per_em;
                for (std::size_t t = 0; t < font.kern.size(); ++t) {
                    const int coverage = font.kern[0].coverage;  // POV-Ray reads table 0's
                    if (!(coverage & 1)) continue;               // horizontal kerning only
                    if (const auto* pair =
                            font.kern[t].find(static_cast<int>(last_index), g.metrics)) {
                        if (coverage & 2) {  // minimum
                            (coverage & 4 ? min_y : min_x) = pair->value;
                        } else if (coverage & 4) {  // cross-stream
                            if (pair->value == -32768) {
                                ky = 0;
                            } else {
                                ky = (coverage & 8) ? pair->value : ky + pair->value;
                            }
                        } else {
                            kx = (coverage & 8) ? pair->value : kx + pair->value;
                        }
                    }
                }
                kx = kx > min_x ? kx : min_x;
                ky = ky > min_y ? ky : min_y;
                // POV-Ray moves a glyph in x and y only (the offset's z adds up unused).
                placed.offset = glm::dvec3(total.x + (m.lsb - g.glyph->x_min + kx) * funit,
                                           total.y + ky * funit, 0.0);
                total.x += (m.advance + kx) * funit;
            }
            total += offset;
            out.glyphs.push_back(std::move(placed));
            last_index = index;
        }
    } catch (const TrueTypeFont::Bad&) {
        return make_error(font.path + ": a glyph mirage cannot read");
    } catch (const TrueTypeFont::TooLarge& e) {
        char code[16];
        std::snprintf(code, sizeof code, "U+%04X", last_char);
        return make_error(font.path + ": the glyph of " + code + " " + e.what);
    } catch (const std::out_of_range&) {
        return make_error(font.path + ": a glyph's metrics are missing");
    }
    return out;
}

}  // namespace mirage
