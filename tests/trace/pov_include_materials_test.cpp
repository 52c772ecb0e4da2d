// The standard include files' materials against POV-Ray 3.7: each include file parses
// completely, and every texture, pigment, colour, finish, normal, interior, material and
// colour map it declares is rendered on a sphere of a grid, by POV-Ray and by the tracer;
// every cell of the grid must match to PSNR >= 35 dB.  The sky spheres of skies.inc are
// rendered one image each.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "pov_text_parity.h"

namespace mirage {
namespace {

using namespace mirage::testing;

constexpr double kRequiredPsnrDb = 35.0;
constexpr int kCell = 24;  // pixels per grid cell

const char* kHeader = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 10 }\n";

/// The materials an include file declares (beyond colors.inc's), by kind.
std::map<std::string, std::string> declared_by(const std::string& include) {
    ParseOptions options;
    options.library_paths = {kPovIncludeDir};
    const std::string base = std::string(kHeader) + "#include \"colors.inc\"\n";
    auto before = parse_scene_text(base, "base.pov", options);
    EXPECT_TRUE(before.ok()) << before.message();
    auto after = parse_scene_text(base + "#include \"" + include + "\"\n", "with.pov", options);
    EXPECT_TRUE(after.ok()) << include << ": " << after.message();
    std::map<std::string, std::string> out;
    if (!before.ok() || !after.ok()) return out;
    for (const auto& [name, kind] : after->material_symbols) {
        if (include != "colors.inc" && before->material_symbols.count(name)) continue;
        out[name] = kind;
    }
    return out;
}

/// The object that shows a declared material of `kind`, at `c`; empty for kinds not shown.
std::string object_for(const std::string& name, const std::string& kind, const std::string& c) {
    const std::string sphere = "sphere { " + c + ", 0.42 ";
    if (kind == "texture") return sphere + "texture { " + name + " } }";
    if (kind == "pigment" || kind == "colour") return sphere + "pigment { " + name + " } }";
    if (kind == "finish") {
        return sphere + "pigment { rgb <0.7, 0.5, 0.3> } finish { " + name + " } }";
    }
    if (kind == "normal") {
        return sphere + "pigment { rgb 0.8 } normal { " + name + " } finish { phong 0.5 } }";
    }
    if (kind == "interior") {
        return sphere + "pigment { rgbf <1, 1, 1, 0.9> } finish { phong 0.5 } interior { " + name +
               " } }";
    }
    if (kind == "material") return sphere + "material { " + name + " } }";
    if (kind == "color_map") {
        return sphere + "pigment { gradient y color_map { " + name + " } scale 0.84 translate " +
               c + " - 0.42 * y } }";
    }
    if (kind == "pigment_map") {
        return sphere + "pigment { gradient y pigment_map { " + name + " } scale 0.84 translate " +
               c + " - 0.42 * y } }";
    }
    return "";
}

struct Cell {
    std::string name;
    std::string kind;
};

/// Renders every shown declaration of an include file in a grid, both ways, and checks
/// every cell.
void check_include(const std::string& include, std::size_t expected_at_least) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const auto declared = declared_by(include);
    std::vector<Cell> cells;
    for (const auto& [name, kind] : declared) {
        if (!object_for(name, kind, "0").empty()) cells.push_back({name, kind});
    }
    ASSERT_GE(cells.size(), expected_at_least) << include;
    const int columns = static_cast<int>(std::ceil(std::sqrt(cells.size() * 4.0 / 3.0)));
    const int rows = static_cast<int>((cells.size() + columns - 1) / columns);
    std::ostringstream text;
    text << kHeader << "#include \"colors.inc\"\n#include \"" << include << "\"\n";
    // A camera far away with a view of exactly one unit per cell at z = 0.
    text << "camera { location <0, 0, -100> direction <0, 0, 100> right <" << columns
         << ", 0, 0> up <0, " << rows << ", 0> }\n";
    text << "light_source { <-30, 40, -100>, rgb 1 }\nlight_source { <50, 10, -60>, rgb 0.4 }\n";
    text << "plane { z, 2 pigment { checker rgb 0.9, rgb 0.3 scale 0.25 } }\n";
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
        char c[80];
        std::snprintf(c, sizeof c, "<%g, %g, 0>", col - (columns - 1) / 2.0,
                      (rows - 1) / 2.0 - row);
        text << object_for(cells[i].name, cells[i].kind, c) << "\n";
    }
    const TextRenders r = render_text_both(text.str(), "pov_include_materials", include,
                                           columns * kCell, rows * kCell);
    ASSERT_TRUE(r.ok) << r.message;
    double worst = INFINITY;
    std::string worst_name;
    int matching = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
        const double psnr = region_psnr(r.povray, r.tracer, col * kCell, row * kCell,
                                        (col + 1) * kCell, (row + 1) * kCell);
        if (psnr >= kRequiredPsnrDb) ++matching;
        EXPECT_GE(psnr, kRequiredPsnrDb)
            << include << ": " << cells[i].kind << " " << cells[i].name;
        if (psnr < worst) {
            worst = psnr;
            worst_name = cells[i].name;
        }
    }
    std::printf(
        "%s: %zu declarations shown, %d of them at >= %.0f dB; whole image %.1f dB, "
        "worst cell %s %.1f dB\n",
        include.c_str(), cells.size(), matching, kRequiredPsnrDb, image_psnr(r.povray, r.tracer),
        worst_name.c_str(), worst);
}

TEST(PovIncludeMaterials, Colors) { check_include("colors.inc", 100); }
TEST(PovIncludeMaterials, Textures) { check_include("textures.inc", 80); }
TEST(PovIncludeMaterials, Finish) { check_include("finish.inc", 8); }
TEST(PovIncludeMaterials, Metals) { check_include("metals.inc", 90); }
TEST(PovIncludeMaterials, Golds) { check_include("golds.inc", 40); }
TEST(PovIncludeMaterials, Glass) { check_include("glass.inc", 60); }
TEST(PovIncludeMaterials, GlassOld) { check_include("glass_old.inc", 4); }
TEST(PovIncludeMaterials, Woods) { check_include("woods.inc", 60); }
TEST(PovIncludeMaterials, Stones) { check_include("stones.inc", 100); }

TEST(PovIncludeMaterials, SkySpheres) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const auto declared = declared_by("skies.inc");
    int skies = 0;
    for (const auto& [name, kind] : declared) {
        if (kind != "sky_sphere") continue;
        ++skies;
        const std::string text = std::string(kHeader) +
                                 "#include \"colors.inc\"\n#include \"skies.inc\"\n"
                                 "camera { location 0 look_at <0, 0.3, 1> angle 100 }\n"
                                 "sky_sphere { " +
                                 name + " }\n";
        const TextRenders r = render_text_both(text, "pov_include_materials", name, 64, 48);
        ASSERT_TRUE(r.ok) << name << ": " << r.message;
        const double psnr = image_psnr(r.povray, r.tracer);
        std::printf("skies.inc %s: %.1f dB\n", name.c_str(), psnr);
        EXPECT_GE(psnr, kRequiredPsnrDb) << name;
    }
    EXPECT_GE(skies, 5);
}

}  // namespace
}  // namespace mirage
