// Test helper: the shading survey.  Small scenes, one per supported pattern (as a pigment and
// as a normal), per warp, and per material the standard include files declare (textures,
// woods, stones, skies, metals and glass.inc), each rendered by POV-Ray (`povray -D -A`) and
// by `mirage trace --no-atmosphere` at 160x120 and compared on the 8-bit images.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "image/image_io.h"
#include "pov_text_parity.h"
#include "scene/parser.h"
#include "util/process.h"

namespace mirage::testing {

constexpr int kSurveyWidth = 160;
constexpr int kSurveyHeight = 120;
constexpr double kSurveyPsnrDb = 35.0;

struct SurveyCase {
    std::string group;  // "patterns", "warps", or the include file
    std::string name;   // the pattern, the warp, or the declared identifier (with its kind)
    std::string text;   // the scene
};

inline const char* kSurveyHeader =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 10 }\n";

/// Camera, two lights, a background, a checker floor and a checker wall behind.
inline std::string survey_stage() {
    return std::string(kSurveyHeader) +
           "camera { location <0, 1.3, -4.2> look_at <0, 0.45, 0> angle 48 }\n"
           "light_source { <-4, 7, -6>, rgb 1 }\n"
           "light_source { <5, 3, -4>, rgb 0.35 }\n"
           "background { rgb <0.25, 0.3, 0.45> }\n"
           "plane { y, -0.45 pigment { checker rgb 0.85, rgb 0.35 scale 0.5 } }\n"
           "plane { z, 2.5 pigment { checker rgb <0.8, 0.35, 0.2>, rgb <0.2, 0.35, 0.8> scale "
           "0.5 } }\n";
}

/// A supported pattern: its pigment (the items after `pigment {`) and its normal (after
/// `normal {`; empty where the pattern is shown as a pigment only).
struct PatternSpec {
    const char* name;
    const char* pigment;
    const char* normal;
};

inline const char* kMap =
    " color_map { [0 rgb <0.1, 0.1, 0.3>] [0.5 rgb <0.9, 0.6, 0.2>] [1 rgb 1] }";

inline std::vector<PatternSpec> survey_patterns() {
    return {
        {"agate", "agate scale 0.5", "agate 0.6 scale 0.5"},
        {"average", "average pigment_map { [1 bozo scale 0.2] [2 gradient x scale 0.3] }", ""},
        {"boxed", "boxed scale 0.6 translate <-0.9, 0.45, 0>", "boxed 0.6 scale 0.6"},
        {"bozo", "bozo scale 0.25", "bozo 0.6 scale 0.25"},
        {"brick", "brick rgb 0.5, rgb <0.7, 0.2, 0.1> brick_size <0.4, 0.15, 0.3> mortar 0.03",
         "brick 0.8 brick_size <0.4, 0.15, 0.3> mortar 0.03"},
        {"bumps", "bumps scale 0.2", "bumps 0.8 scale 0.2"},
        {"cells", "cells scale 0.2", "cells 0.6 scale 0.2"},
        {"checker", "checker rgb <1, 0.9, 0.2>, rgb <0.1, 0.3, 0.8> scale 0.3",
         "checker 0.6 scale 0.3"},
        {"crackle", "crackle scale 0.3", "crackle 0.8 scale 0.3"},
        {"crackle_form_metric", "crackle form <1, -1, 0> metric 1 offset 0.1 scale 0.3",
         "crackle 0.8 form <-1, 1, 0> scale 0.3"},
        {"crackle_solid", "crackle solid scale 0.25", ""},
        {"cubic",
         "cubic rgb 1, rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>, rgb <1, 1, 0>, rgb "
         "<0, 1, 1> translate <-0.9, 0.45, 0>",
         ""},
        {"cylindrical", "cylindrical scale 0.7 frequency 3 translate <-0.9, 0.45, 0>",
         "cylindrical 0.6 frequency 3 scale 0.7 translate <0.9, 0.45, 0>"},
        {"dents", "dents scale 0.2", "dents 0.8 scale 0.2"},
        {"gradient", "gradient y frequency 2", "gradient y 0.6 frequency 2"},
        {"granite", "granite scale 1.5", "granite 0.5 scale 1.5"},
        {"hexagon", "hexagon rgb <1, 0.8, 0>, rgb <0.2, 0.4, 1>, rgb 0.3 scale 0.2 rotate x * 90",
         "hexagon 0.6 scale 0.2 rotate x * 90"},
        {"leopard", "leopard scale 0.1", "leopard 0.6 scale 0.1"},
        {"mandel", "mandel 30 scale 0.6 translate <-0.9, 0.45, 0>", "mandel 30 0.6 scale 0.6"},
        {"marble", "marble turbulence 0.8 scale 0.6", "marble 0.6 turbulence 0.8 scale 0.6"},
        {"onion", "onion scale 0.3", "onion 0.6 scale 0.3"},
        {"pigment_pattern", "pigment_pattern { checker rgb 1, rgb 0 scale 0.25 }",
         "pigment_pattern { bozo scale 0.3 } 0.8"},
        {"planar", "planar scale 0.6 translate 0.45 * y",
         "planar 0.6 scale 0.6 translate 0.45 * y"},
        {"quilted", "quilted control0 1 control1 1 scale 0.3", "quilted 0.8 scale 0.3"},
        {"radial", "radial frequency 6", "radial 0.6 frequency 6"},
        {"ripples", "ripples frequency 3 scale 0.5", "ripples 0.8 frequency 3 scale 0.5"},
        {"slope", "slope y", "slope y 0.6"},
        {"spherical", "spherical scale 0.85 translate <-0.9, 0.45, 0>",
         "spherical 0.6 scale 0.85 translate <0.9, 0.45, 0>"},
        {"spiral1", "spiral1 3 scale 0.5", "spiral1 3 0.6 scale 0.5"},
        {"spiral2", "spiral2 4 scale 0.5", "spiral2 4 0.6 scale 0.5"},
        {"spotted", "spotted scale 0.2", "spotted 0.6 scale 0.2"},
        {"square", "square rgb 1, rgb 0, rgb <1, 0, 0>, rgb <0, 0, 1> scale 0.2",
         "square 0.6 scale 0.2"},
        {"triangular",
         "triangular rgb 1, rgb 0, rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>, rgb "
         "<1, 1, 0> scale 0.2",
         "triangular 0.6 scale 0.2"},
        {"waves", "waves frequency 3 scale 0.5", "waves 0.8 frequency 3 scale 0.5"},
        {"wood", "wood turbulence 0.1 scale 0.2 rotate x * 80", "wood 0.6 scale 0.2 rotate x * 80"},
        {"wrinkles", "wrinkles scale 0.3", "wrinkles 0.8 scale 0.3"},
        // The wave types and the noise generators, on one pattern each.
        {"sine_wave", "gradient y frequency 2 sine_wave", "gradient y 0.6 frequency 2 sine_wave"},
        {"triangle_wave", "bozo scale 0.3 triangle_wave frequency 2", ""},
        {"scallop_wave", "onion scale 0.3 scallop_wave", "onion 0.6 scale 0.3 scallop_wave"},
        {"cubic_wave", "gradient y frequency 2 cubic_wave",
         "gradient y 0.6 frequency 2 cubic_wave"},
        {"poly_wave", "gradient y frequency 2 poly_wave 3",
         "gradient y 0.6 frequency 2 poly_wave 3"},
        {"noise_generator_1", "bozo scale 0.25 noise_generator 1",
         "bumps 0.8 scale 0.2 noise_generator 1"},
        {"noise_generator_3", "granite scale 1.5 noise_generator 3",
         "wrinkles 0.8 scale 0.3 noise_generator 3"},
        {"turbulence", "marble turbulence <0.6, 0.3, 0.2> octaves 4 omega 0.6 lambda 2.5 scale 0.6",
         "bumps 0.8 turbulence 0.5 scale 0.3"},
    };
}

/// Patterns POV-Ray 3.7 has that the tracer refuses: one scene each, to show the refusal.
inline std::vector<PatternSpec> survey_refused_patterns() {
    return {
        {"julia", "julia <0.353, 0.288>, 30 scale 0.6", ""},
        {"magnet", "magnet 1 mandel 30 scale 0.6", ""},
        {"function", "function { x * y } scale 0.3", ""},
        {"object", "object { sphere { 0, 0.5 } rgb 0, rgb 1 }", ""},
        {"pavement", "pavement scale 0.3", ""},
        {"tiling", "tiling 1 scale 0.3", ""},
        {"aoi", "aoi", ""},
        {"facets", "", "facets 0.6 size 0.1"},
    };
}

inline std::string pattern_scene(const PatternSpec& p) {
    const std::string pigment = p.pigment;
    const bool list = pigment.rfind("checker", 0) == 0 || pigment.rfind("brick", 0) == 0 ||
                      pigment.rfind("hexagon", 0) == 0 || pigment.rfind("square", 0) == 0 ||
                      pigment.rfind("triangular", 0) == 0 || pigment.rfind("cubic ", 0) == 0 ||
                      pigment.rfind("average", 0) == 0 || pigment.rfind("object", 0) == 0;
    std::string text = survey_stage();
    if (!pigment.empty()) {
        text += "sphere { <-0.9, 0.45, 0>, 0.8 pigment { " + pigment + (list ? "" : kMap) +
                " } finish { phong 0.4 } }\n";
    }
    if (*p.normal) {
        text += "sphere { <0.9, 0.45, 0>, 0.8 pigment { rgb <0.8, 0.75, 0.7> } normal { " +
                std::string(p.normal) + " } finish { phong 0.6 specular 0.3 } }\n";
    }
    return text;
}

/// The warps, on a bozo pigment and a bumps normal.
inline std::vector<std::pair<std::string, std::string>> survey_warps() {
    return {
        {"turbulence", "warp { turbulence 0.6 octaves 3 omega 0.5 lambda 2 }"},
        {"repeat", "warp { repeat x * 0.3 offset y * 0.1 flip x }"},
        {"black_hole", "warp { black_hole <-0.9, 0.6, -0.5>, 0.6 strength 2 falloff 1.5 }"},
        {"black_hole_repeat", "warp { black_hole 0, 0.3 repeat <0.5, 0.5, 0.5> turbulence 0.1 }"},
        {"cylindrical", "warp { cylindrical orientation y dist_exp 0.5 }"},
        {"spherical", "warp { spherical orientation z dist_exp 0 }"},
        {"toroidal", "warp { toroidal major_radius 0.5 orientation y }"},
        {"planar", "warp { planar z, 0.2 }"},
        {"cubic", "warp { cubic }"},
    };
}

inline std::string warp_scene(const std::string& warp) {
    return survey_stage() + "sphere { <-0.9, 0.45, 0>, 0.8 pigment { bozo " + warp + " scale 0.25" +
           kMap + " } finish { phong 0.4 } }\n" +
           "sphere { <0.9, 0.45, 0>, 0.8 pigment { rgb <0.8, 0.75, 0.7> } normal { bumps 0.8 " +
           warp + " scale 0.2 } finish { phong 0.6 } }\n";
}

/// The object showing a declared material of `kind`; empty for kinds not shown.
inline std::string survey_object(const std::string& name, const std::string& kind) {
    const std::string sphere = "sphere { <0, 0.45, 0>, 0.85 ";
    if (kind == "texture") return sphere + "texture { " + name + " } }";
    if (kind == "pigment" || kind == "colour") return sphere + "pigment { " + name + " } }";
    if (kind == "finish")
        return sphere + "pigment { rgb <0.7, 0.5, 0.3> } finish { " + name + " } }";
    if (kind == "normal") {
        return sphere + "pigment { rgb 0.8 } normal { " + name + " } finish { phong 0.5 } }";
    }
    if (kind == "interior") {
        return sphere + "pigment { rgbf <1, 1, 1, 0.9> } finish { phong 0.5 } interior { " + name +
               " } }";
    }
    if (kind == "material") return sphere + "material { " + name + " } }";
    if (kind == "color_map" || kind == "pigment_map") {
        return sphere + "pigment { gradient y " + kind + " { " + name +
               " } scale 1.7 translate -0.4 * y } }";
    }
    return "";
}

/// The materials an include file declares beyond those of colors.inc, by kind.
inline std::map<std::string, std::string> survey_declared_by(const std::string& include) {
    ParseOptions options;
    options.library_paths = {kPovIncludeDir};
    const std::string base = std::string(kSurveyHeader) + "#include \"colors.inc\"\n";
    std::map<std::string, std::string> out;
    auto before = parse_scene_text(base, "base.pov", options);
    auto after = parse_scene_text(base + "#include \"" + include + "\"\n", "with.pov", options);
    if (!before.ok() || !after.ok()) {
        ADD_FAILURE() << include << ": " << (before.ok() ? after.message() : before.message());
        return out;
    }
    for (const auto& [name, kind] : after->material_symbols) {
        if (!before->material_symbols.count(name)) out[name] = kind;
    }
    return out;
}

inline const std::vector<std::string>& survey_include_files() {
    static const std::vector<std::string> files{"textures.inc", "woods.inc",  "stones.inc",
                                                "skies.inc",    "metals.inc", "glass.inc"};
    return files;
}

/// Every case of the survey: patterns, warps, then each include file's declarations.
inline std::vector<SurveyCase> survey_cases() {
    std::vector<SurveyCase> cases;
    for (const PatternSpec& p : survey_patterns())
        cases.push_back({"patterns", p.name, pattern_scene(p)});
    for (const PatternSpec& p : survey_refused_patterns()) {
        cases.push_back({"patterns (refused)", p.name, pattern_scene(p)});
    }
    for (const auto& [name, warp] : survey_warps())
        cases.push_back({"warps", name, warp_scene(warp)});
    for (const std::string& include : survey_include_files()) {
        const std::string head = "#include \"colors.inc\"\n#include \"" + include + "\"\n";
        for (const auto& [name, kind] : survey_declared_by(include)) {
            std::string text;
            if (kind == "sky_sphere") {
                text = std::string(kSurveyHeader) + head +
                       "camera { location 0 look_at <0, 0.3, 1> angle 100 }\nsky_sphere { " + name +
                       " }\n";
            } else {
                const std::string object = survey_object(name, kind);
                if (object.empty()) continue;
                std::string stage = survey_stage();
                stage.insert(std::string(kSurveyHeader).size(), head);
                text = stage + object + "\n";
            }
            cases.push_back({include, kind + " " + name, text});
        }
    }
    return cases;
}

struct SurveyResult {
    std::string status;  // match, differ, trace_failed, pov_failed
    double psnr = 0.0;
    std::string message;  // the first line of the refusal, for trace_failed and pov_failed
};

inline std::string first_line(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty()) return line;
    }
    return "";
}

/// The last line of POV-Ray's log that names an error (its message is at the end).
inline std::string povray_error(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string line, found;
    while (std::getline(in, line)) {
        if (line.find("Error") != std::string::npos) found = line;
    }
    return found;
}

/// Renders one case both ways in `dir` (POV-Ray's working directory) and compares.
inline SurveyResult run_survey_case(const SurveyCase& c, const std::filesystem::path& dir) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    SurveyResult r;
    {
        std::ofstream out(dir / "scene.pov");
        out << c.text;
    }
    const std::string w = std::to_string(kSurveyWidth), h = std::to_string(kSurveyHeight);
    auto pov = run_process({"timeout", "120", "povray", "-D", "-A", "+FN8", "+W" + w, "+H" + h,
                            "+Iscene.pov", "+Opovray.png"},
                           dir.string(), (dir / "povray.log").string());
    if (!pov.ok() || pov->exit_code != 0 || !std::filesystem::exists(dir / "povray.png")) {
        r.status = "pov_failed";
        r.message = povray_error(dir / "povray.log");
        return r;
    }
    const std::string mirage = std::string(MIRAGE_BINARY_DIR) + "/mirage";
    auto trace = run_process(
        {"timeout", "120", mirage, "trace", "scene.pov", "-W", w, "-H", h, "--no-atmosphere", "-q",
         "--threads", "1", "-L", kPovIncludeDir, "-o", "mirage.png"},
        dir.string(), (dir / "mirage.log").string());
    if (!trace.ok() || trace->exit_code != 0 || !std::filesystem::exists(dir / "mirage.png")) {
        r.status = "trace_failed";
        r.message = first_line(dir / "mirage.log");
        return r;
    }
    auto a = read_image((dir / "povray.png").string());
    auto b = read_image((dir / "mirage.png").string());
    if (!a.ok() || !b.ok() || a->width != b->width || a->height != b->height) {
        r.status = "trace_failed";
        r.message = "images cannot be compared";
        return r;
    }
    r.psnr = image_psnr(*a, *b);
    r.status = r.psnr >= kSurveyPsnrDb ? "match" : "differ";
    return r;
}

/// Runs the cases `jobs` at a time (POV-Ray and the tool each spend most of a render this
/// small starting up), each in out/<index>/.
inline std::vector<SurveyResult> run_survey(const std::vector<SurveyCase>& cases,
                                            const std::filesystem::path& out, int jobs) {
    std::vector<SurveyResult> results(cases.size());
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> workers;
    for (int j = 0; j < jobs; ++j) {
        workers.emplace_back([&] {
            for (std::size_t i = next++; i < cases.size(); i = next++) {
                results[i] = run_survey_case(cases[i], out / std::to_string(i));
            }
        });
    }
    for (std::thread& t : workers) t.join();
    return results;
}

}  // namespace mirage::testing
