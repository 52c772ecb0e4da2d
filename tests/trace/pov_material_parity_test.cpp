// Materials and lights against POV-Ray 3.7: small scenes of patterns, warps, normals,
// finishes, layered and patterned textures, glass, lights and fog, rendered by POV-Ray
// (`povray -D -A`) and by the tracer, must agree to PSNR >= 35 dB on the 8-bit images.
// The figure reached is printed (most of these are bit-identical: POV-Ray's noise, hashing
// and pattern arithmetic are reproduced in double precision).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "image/image_io.h"
#include "pov_text_parity.h"

namespace mirage {
namespace {

using namespace mirage::testing;

constexpr double kRequiredPsnrDb = 35.0;

/// A stage: camera, two lights, a checker floor and a back wall; `body` adds the objects.
std::string stage(const std::string& body, const std::string& extra_globals = "") {
    return "#version 3.7;\n"
           "global_settings { assumed_gamma 1.0 max_trace_level 10 " +
           extra_globals +
           " }\n"
           "camera { location <0, 2.2, -6.5> look_at <0, 0.6, 0> angle 52 }\n"
           "light_source { <-4, 7, -6>, rgb 1 }\n"
           "light_source { <5, 3, -4>, rgb 0.35 }\n"
           "background { rgb <0.25, 0.3, 0.45> }\n"
           "plane { y, -0.4 pigment { checker rgb 0.85, rgb 0.35 } }\n"
           "plane { z, 3 pigment { rgb <0.6, 0.65, 0.7> } }\n" +
           body;
}

/// Three spheres in a row and a slab behind them, each with the given texture items.
std::string row(const std::string& a, const std::string& b, const std::string& c,
                const std::string& slab) {
    return "sphere { <-1.8, 0.5, 0>, 0.85 " + a + " }\n" + "sphere { <0, 0.5, 0>, 0.85 " + b +
           " }\n" + "sphere { <1.8, 0.5, 0>, 0.85 " + c + " }\n" +
           "box { <-3, -0.4, 1.6>, <3, 2.6, 1.8> " + slab + " }\n";
}

double parity(const std::string& name, const std::string& text, int width = 200, int height = 150) {
    if (!povray_available()) return INFINITY;
    const TextRenders r = render_text_both(text, "pov_material_parity", name, width, height);
    EXPECT_TRUE(r.ok) << name << ": " << r.message;
    if (!r.ok) return 0.0;
    const double psnr = image_psnr(r.povray, r.tracer);
    std::printf("%s: PSNR %.1f dB\n", name.c_str(), psnr);
    return psnr;
}

#define EXPECT_PARITY(name, text)                                         \
    do {                                                                  \
        if (!povray_available()) GTEST_SKIP() << "povray is not on PATH"; \
        EXPECT_GE(parity(name, text), kRequiredPsnrDb) << name;           \
    } while (0)

TEST(PovMaterialParity, NoisePatterns) {
    EXPECT_PARITY("noise_patterns",
                  stage(row("pigment { bozo scale 0.3 }", "pigment { granite scale 1.5 }",
                            "pigment { spotted color_map { [0 rgb 0] [1 rgb <1, 0.8, 0.2>] } "
                            "scale 0.2 }",
                            "pigment { wrinkles color_map { [0 rgb 0] [1 rgb 1] } scale 0.4 }")));
}

TEST(PovMaterialParity, NoiseGenerators) {
    for (int g : {1, 2, 3}) {
        const std::string gen = " noise_generator " + std::to_string(g);
        EXPECT_PARITY("noise_generator_" + std::to_string(g),
                      stage(row("pigment { bozo scale 0.3" + gen + " }",
                                "pigment { granite" + gen + " }", "pigment { agate" + gen + " }",
                                "pigment { marble turbulence 0.8" + gen +
                                    " color_map { [0 rgb 1] [1 rgb <0.3, 0, 0>] } }")));
    }
}

TEST(PovMaterialParity, TurbulentPatterns) {
    EXPECT_PARITY(
        "turbulent_patterns",
        stage(row("pigment { wood turbulence 0.1 octaves 4 omega 0.6 lambda 2.3 scale 0.2 "
                  "rotate x * 80 }",
                  "pigment { marble turbulence 1.2 color_map { [0 rgb <1, 1, 0.9>] [0.6 rgb "
                  "<0.8, 0.2, 0.1>] [1 rgb 0] } }",
                  "pigment { agate agate_turb 0.7 scale 0.6 }",
                  "pigment { spiral1 3 turbulence 0.2 scale 0.5 color_map { [0 rgb 0] [1 rgb "
                  "<0, 0.6, 1>] } }")));
}

TEST(PovMaterialParity, GeometricPatterns) {
    EXPECT_PARITY(
        "geometric_patterns",
        stage(row("pigment { onion scale 0.3 color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } }",
                  "pigment { radial frequency 6 sine_wave }", "pigment { leopard scale 0.1 }",
                  "pigment { hexagon rgb <1, 0.8, 0>, rgb <0.2, 0.4, 1> scale 0.2 rotate x * 90 "
                  "}")) +
            "sphere { <-2.6, 2.2, 0.6>, 0.5 pigment { spherical scale 0.5 translate <-2.6, 2.2, "
            "0.6> color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } } }\n"
            "sphere { <2.6, 2.2, 0.6>, 0.5 pigment { cylindrical scale 0.5 triangle_wave "
            "frequency 3 } }\n"
            "sphere { <0, 2.3, 0.6>, 0.5 pigment { boxed scale 0.5 translate <0, 2.3, 0.6> "
            "scallop_wave } }\n");
}

TEST(PovMaterialParity, ListAndCellPatterns) {
    EXPECT_PARITY(
        "list_patterns",
        stage(row("pigment { brick rgb 0.5, rgb <0.7, 0.2, 0.1> brick_size <0.4, 0.15, 0.3> "
                  "mortar 0.03 }",
                  "pigment { checker pigment { bozo scale 0.1 } pigment { rgb <0, 0, 1> } "
                  "scale 0.5 }",
                  "pigment { cells scale 0.2 }",
                  "pigment { crackle form <1, -1, 0> scale 0.3 color_map { [0 rgb 0] [1 rgb "
                  "1] } }")) +
            "sphere { <-2.6, 2.2, 0.6>, 0.5 pigment { square rgb 1, rgb 0, rgb <1, 0, 0>, rgb "
            "<0, 0, 1> scale 0.2 } }\n"
            "sphere { <2.6, 2.2, 0.6>, 0.5 pigment { triangular scale 0.2 } }\n"
            "sphere { <0, 2.3, 0.6>, 0.5 pigment { crackle solid scale 0.2 } }\n");
}

TEST(PovMaterialParity, FractalQuiltedAndWaves) {
    EXPECT_PARITY("fractal_waves",
                  stage(row("pigment { mandel 40 scale 0.6 }",
                            "pigment { quilted control0 0.3 control1 0.9 scale 0.3 }",
                            "pigment { waves frequency 3 cubic_wave scale 0.5 }",
                            "pigment { ripples frequency 4 poly_wave 2 scale 0.5 }")));
}

TEST(PovMaterialParity, Warps) {
    EXPECT_PARITY(
        "warps",
        stage(row("pigment { checker rgb 1, rgb 0 scale 0.2 warp { turbulence 0.4 octaves 3 } }",
                  "pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } warp { repeat x * 0.3 "
                  "flip x } }",
                  "pigment { checker rgb 1, rgb <1, 0, 0> scale 0.15 warp { black_hole <0, 0.5, "
                  "-0.5>, 0.7 strength 1.5 falloff 2 } }",
                  "pigment { checker rgb 1, rgb <0, 0.5, 0> scale 0.25 warp { cylindrical "
                  "orientation y } }")) +
            "sphere { <0, 2.3, 0.6>, 0.5 pigment { checker rgb 1, rgb 0 scale 0.2 warp { "
            "spherical orientation y dist_exp 1 } } }\n");
}

TEST(PovMaterialParity, MapsLayersAndPatternedTextures) {
    EXPECT_PARITY(
        "maps_and_layers",
        stage(row("pigment { gradient y pigment_map { [0 checker rgb 1, rgb 0 scale 0.1] [1 "
                  "bozo scale 0.2] } scale 1.7 translate -0.35 * y }",
                  "texture { pigment { rgb <0.9, 0.9, 0.2> } } texture { pigment { bozo "
                  "color_map { [0.5 rgbt 1] [0.55 rgbf <0.2, 0.4, 1, 0.3>] } scale 0.3 } "
                  "finish { phong 1 } }",
                  "texture { leopard texture_map { [0 pigment { rgb 1 } finish { phong 1 }] [1 "
                  "pigment { rgb <0.4, 0, 0> } normal { bumps 1 scale 0.1 }] } scale 0.15 }",
                  "texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { "
                  "rgb <0.2, 0.2, 0.8> } finish { reflection 0.4 } } } scale 0.5 }")) +
            "sphere { <0, 2.3, 0.6>, 0.5 pigment { average pigment_map { [1 gradient x] [2 "
            "bozo scale 0.2] } } }\n");
}

TEST(PovMaterialParity, Normals) {
    EXPECT_PARITY(
        "normals",
        stage(row("pigment { rgb 0.8 } normal { bumps 0.8 scale 0.15 } finish { phong 1 }",
                  "pigment { rgb 0.8 } normal { dents 1.5 scale 0.3 } finish { specular 0.6 }",
                  "pigment { rgb 0.8 } normal { wrinkles 0.7 scale 0.3 } finish { phong 0.6 }",
                  "pigment { rgb 0.8 } normal { ripples 0.5 frequency 3 } finish { phong 0.6 "
                  "}")) +
            "sphere { <-2.6, 2.2, 0.6>, 0.5 pigment { rgb 0.8 } normal { waves 0.6 frequency 2 "
            "} finish { phong 1 } }\n"
            "sphere { <2.6, 2.2, 0.6>, 0.5 pigment { rgb 0.8 } normal { quilted 0.7 scale 0.2 "
            "} finish { phong 1 } }\n"
            "sphere { <0, 2.3, 0.6>, 0.5 pigment { rgb 0.8 } normal { granite 0.4 scale 0.5 "
            "accuracy 0.01 } finish { phong 1 } }\n");
}

TEST(PovMaterialParity, NormalMapsAndSlopeMaps) {
    EXPECT_PARITY(
        "normal_maps",
        stage(row("pigment { rgb 0.8 } normal { gradient x normal_map { [0 bumps 0.5 scale 0.1] "
                  "[1 dents 0.8 scale 0.2] } } finish { phong 1 }",
                  "pigment { rgb 0.8 } normal { marble 0.6 turbulence 0.6 slope_map { [0 <0, 1>] "
                  "[0.5 <1, 0>] [1 <0, -1>] } } finish { phong 1 }",
                  "pigment { rgb 0.8 } normal { checker normal { bumps 0.5 scale 0.05 } normal "
                  "{ dents 1 } scale 0.4 } finish { phong 1 }",
                  "pigment { rgb <0.6, 0.7, 0.8> } normal { hexagon 0.5 scale 0.3 rotate x * 90 "
                  "}")));
}

TEST(PovMaterialParity, Finishes) {
    EXPECT_PARITY(
        "finishes",
        stage(row("pigment { rgb <0.9, 0.6, 0.2> } finish { metallic phong 1 specular 0.8 "
                  "roughness 0.01 brilliance 3 }",
                  "pigment { rgb <0.2, 0.3, 0.9> } finish { reflection { 0.05, 0.9 fresnel "
                  "falloff 2 } } interior { ior 1.5 }",
                  "pigment { rgb <0.8, 0.2, 0.2> } finish { reflection { 0.3, 0.8 falloff 3 "
                  "exponent 0.6 metallic 0.7 } conserve_energy }",
                  "pigment { rgb <0.5, 0.5, 0.5> } finish { irid { 0.4 thickness 0.3 "
                  "turbulence 0.5 } phong 1 diffuse 0.5, 0.3 }")));
}

TEST(PovMaterialParity, GlassAndInteriors) {
    EXPECT_PARITY(
        "glass",
        stage(row("pigment { rgbf <0.9, 1, 0.95, 0.95> } finish { phong 1 reflection 0.1 } "
                  "interior { ior 1.5 fade_distance 0.8 fade_power 2 fade_color rgb <0.2, 0.6, "
                  "0.3> }",
                  "pigment { rgbt <1, 1, 1, 0.9> } interior { ior 1.33 fade_distance 1 "
                  "fade_power 1001 fade_color rgb <0, 0, 0.8> caustics 0.8 }",
                  "pigment { rgbf 1 } finish { specular 1 roughness 0.001 } interior { ior 2.4 "
                  "}",
                  "pigment { rgbf <1, 0.8, 0.8, 0.7> } interior { ior 1.2 }")) +
            // A sphere inside a sphere, and a dispersive prism.
            "sphere { <0, 2.3, 0.6>, 0.55 pigment { rgbf 1 } interior { ior 1.5 } }\n"
            "sphere { <0, 2.3, 0.6>, 0.25 pigment { rgbf <1, 0.5, 0.5, 0.9> } interior { ior "
            "1.1 } }\n"
            "box { <-0.4, -0.4, -0.4>, <0.4, 0.4, 0.4> rotate <30, 40, 0> translate <2.5, 2.2, "
            "0.6> pigment { rgbf 1 } interior { ior 1.6 dispersion 1.1 dispersion_samples 5 } "
            "}\n");
}

TEST(PovMaterialParity, InteriorTextures) {
    // Open cylinders seen from above: their inner wall shows the interior_texture, given to
    // the object, by a material, and by a union to its children; through a glass sphere the
    // far side from inside.
    EXPECT_PARITY(
        "interior_texture",
        stage("cylinder { <-1.8, -0.4, 0>, <-1.8, 1.2, 0>, 0.8 open pigment { rgb <0.9, 0.8, "
              "0.2> } interior_texture { pigment { checker rgb <0, 0, 1>, rgb 1 scale 0.2 } "
              "finish { phong 0.6 } } }\n"
              "#declare M = material { texture { pigment { rgb <0.3, 0.8, 0.3> } } "
              "interior_texture { pigment { rgb <1, 0.2, 0.2> } } }\n"
              "cylinder { <0, -0.4, 0>, <0, 1.2, 0>, 0.8 open material { M } }\n"
              "union { cylinder { <1.8, -0.4, 0>, <1.8, 1.2, 0>, 0.8 open } "
              "sphere { <1.8, 2.1, 0.6>, 0.5 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 "
              "} } pigment { rgb <0.5, 0.5, 0.9> } interior_texture { pigment { rgb <1, 0.5, "
              "0> } } }\n"));
}

TEST(PovMaterialParity, GlassCsg) {
    // Interiors and interior_textures of CSG objects: a glass lens (an intersection given its
    // interior as a whole), a glass difference whose child has an interior of its own, a
    // merge of glass spheres (one medium, no inner surfaces), and an open cylinder clipped
    // by a box showing its interior_texture, given by the CSG.
    EXPECT_PARITY(
        "glass_csg",
        stage("intersection { sphere { <-1.8, 0.5, -0.6>, 1 } sphere { <-1.8, 0.5, 0.6>, 1 } "
              "pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { phong 1 } interior { ior 1.5 } "
              "}\n"
              "difference { box { <-0.7, -0.4, -0.5>, <0.7, 1.2, 0.5> } "
              "sphere { <0, 1.2, -0.5>, 0.6 interior { ior 1.1 } } "
              "pigment { rgbf <1, 0.9, 0.9, 0.9> } interior { ior 1.45 fade_distance 1 "
              "fade_power 2 fade_color rgb <0.8, 0.3, 0.3> } }\n"
              "merge { sphere { <1.6, 0.4, 0>, 0.6 } sphere { <2.1, 0.7, 0.2>, 0.5 } "
              "pigment { rgbf 1 } interior { ior 1.3 } }\n"
              "intersection { cylinder { <0, 1.6, 0.8>, <0, 2.6, 0.8>, 0.5 open } "
              "box { <-0.6, 1.5, 0.2>, <0.45, 2.7, 1.4> } pigment { rgb <0.9, 0.8, 0.2> } "
              "interior_texture { pigment { rgb <0.2, 0.3, 1> } } rotate -20*x translate "
              "<0, 0, 0.6> }\n"));
}

TEST(PovMaterialParity, OldGlassAndLegacyGamma) {
    // glass_old.inc's finish ior and a #version 3.6 scene without assumed_gamma, which POV-Ray
    // writes with no gamma handling at all.
    EXPECT_PARITY(
        "legacy",
        "#version 3.6;\n#include \"colors.inc\"\n#include \"textures.inc\"\n#include "
        "\"glass_old.inc\"\n"
        "camera { location <0, 2, -6> look_at <0, 0.6, 0> }\n"
        "light_source { <-4, 7, -6>, 1 }\n"
        "plane { y, -0.4 pigment { checker rgb 0.85, rgb 0.35 } }\n"
        "sphere { <-1, 0.5, 0>, 0.8 texture { Glass3 } }\n"
        "sphere { <1, 0.5, 0>, 0.8 pigment { rgbf <1, 0.3, 0.3, 0.6> } finish { refraction 1 "
        "ior 1.5 } }\n");
    EXPECT_PARITY("gamma_2_2",
                  "#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n"
                  "camera { location <0, 2, -6> look_at <0, 0.6, 0> }\n"
                  "light_source { <-4, 7, -6>, 1 }\n"
                  "plane { y, -0.4 pigment { checker rgb 0.85, rgb 0.35 } }\n"
                  "sphere { <0, 0.5, 0>, 0.8 pigment { granite } finish { phong 1 } }\n");
}

TEST(PovMaterialParity, SpotCylinderAndParallelLights) {
    EXPECT_PARITY("spot_lights",
                  "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
                  "camera { location <0, 4, -7> look_at <0, 0, 0> }\n"
                  "light_source { <-2, 5, -2>, rgb <1, 0.8, 0.6> spotlight point_at <-1, 0, 0> "
                  "radius 12 falloff 20 tightness 10 }\n"
                  "light_source { <3, 5, 0>, rgb <0.4, 0.6, 1> cylinder point_at <2, 0, 0> "
                  "radius 0.6 falloff 1.2 tightness 2 }\n"
                  "light_source { <0, 10, -10>, rgb 0.3 parallel point_at 0 fade_distance 5 "
                  "fade_power 2 }\n"
                  "plane { y, 0 pigment { rgb 0.8 } }\n"
                  "sphere { <0, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.9, 0.3> } finish { phong 1 } "
                  "}\n");
}

TEST(PovMaterialParity, AreaLights) {
    const std::string scene =
        "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 4, -7> look_at <0, 0.5, 0> }\n"
        "plane { y, 0 pigment { rgb 0.8 } }\n"
        "sphere { <0, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.3, 0.3> } finish { phong 1 } }\n"
        "box { <1.5, 0, -0.5>, <2.2, 1.5, 0.3> pigment { rgbf <0.3, 0.6, 1, 0.7> } }\n";
    EXPECT_PARITY(
        "area_light_full",
        scene + "light_source { <-3, 6, -3>, 1 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 }\n");
    EXPECT_PARITY("area_light_adaptive",
                  scene +
                      "light_source { <-3, 6, -3>, 1 area_light <2, 0, 0>, <0, 0, 2>, 9, 9 "
                      "adaptive 1 }\n");
    EXPECT_PARITY("area_light_circular_orient",
                  scene +
                      "light_source { <-3, 6, -3>, 1 area_light <2, 0, 0>, <0, 0, 2>, 6, 6 "
                      "circular orient adaptive 0 }\n");
    EXPECT_PARITY("area_light_illumination",
                  scene +
                      "light_source { <-3, 6, -3>, 1 area_light <3, 0, 0>, <0, 0, 3>, 4, 4 "
                      "area_illumination }\n");
}

TEST(PovMaterialParity, Fog) {
    const std::string scene =
        "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 1.5, -8> look_at <0, 1, 0> }\n"
        "light_source { <-4, 7, -6>, 1 media_attenuation on }\n"
        "sky_sphere { pigment { gradient y color_map { [0 rgb <0.8, 0.8, 1>] [1 rgb <0.1, 0.2, "
        "0.7>] } } }\n"
        "plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }\n"
        "sphere { <0, 1, 6>, 1 pigment { rgb <0.9, 0.4, 0.2> } }\n"
        "sphere { <2, 1, 20>, 1 pigment { rgb <0.2, 0.9, 0.4> } }\n";
    EXPECT_PARITY("fog_constant", scene + "fog { distance 15 rgbt <0.7, 0.7, 0.75, 0.1> }\n");
    EXPECT_PARITY("fog_ground",
                  scene + "fog { fog_type 2 distance 6 fog_alt 0.6 fog_offset 0.2 rgb 0.8 }\n");
    EXPECT_PARITY("fog_turbulent",
                  scene +
                      "fog { distance 12 rgb 0.7 turbulence 0.5 octaves 4 turb_depth 0.4 "
                      "}\nfog { fog_type 2 distance 8 fog_alt 1 rgbf <1, 0.8, 0.6, 0.5> }\n");
}

TEST(PovMaterialParity, ImageMapsAndBumpMaps) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    // A small sRGB PNG with a pattern, mapped four ways.
    const auto dir = test_dir("pov_material_parity", "image_map_source");
    Image img(16, 12);
    for (int y = 0; y < 12; ++y) {
        for (int x = 0; x < 16; ++x) {
            img.set(x, y, glm::vec3(x / 15.0f, y / 11.0f, ((x + y) % 3) / 2.0f));
        }
    }
    const std::string png = (dir / "map.png").string();
    ASSERT_TRUE(write_png(img, png).ok());
    const std::string text =
        stage(row("pigment { image_map { png \"" + png + "\" } translate -0.5 scale 1.7 }",
                  "pigment { image_map { png \"" + png + "\" map_type 1 interpolate 2 } }",
                  "pigment { image_map { png \"" + png + "\" map_type 2 interpolate 4 } }",
                  "pigment { image_map { png \"" + png +
                      "\" once filter all 0.3 } scale 2 } "
                      "normal { bump_map { png \"" +
                      png + "\" bump_size 2 interpolate 2 } scale 0.5 }"));
    EXPECT_GE(parity("image_maps", text), kRequiredPsnrDb);
}

}  // namespace
}  // namespace mirage
