// The parser as a whole: POV-Ray's own include files, lenient mode, a complete scene.
#include "scene/parser.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "parse_helpers.h"
#include "scene/transform.h"

namespace mirage {
namespace {

using testing::expect_vec;
using testing::kPovRayIncludes;
using testing::parse_error;
using testing::parse_ok;

bool have_povray_includes() {
    return std::filesystem::exists(std::string(kPovRayIncludes) + "/colors.inc");
}

ParseOptions with_includes(bool strict = true) {
    ParseOptions o;
    o.library_paths = {kPovRayIncludes};
    o.strict = strict;
    return o;
}

TEST(Parser, ColorsIncParsesAndItsColoursWork) {
    if (!have_povray_includes()) GTEST_SKIP() << "POV-Ray's include files are not installed";
    Scene s = parse_ok(R"(
        #version 3.7;
        #include "colors.inc"
        sphere { 0, 1 pigment { White * 0.5 } }
        sphere { 0, 1 pigment { color Red filter 0.25 } }
        light_source { <0, 10, 0>, White }
        #declare Mix = (Red + Blue) / 2;
        #declare MixBlue = Mix.blue;
    )",
                       with_includes());
    ASSERT_EQ(s.primitives.size(), 2u);
    expect_vec(s.primitives[0].texture.pigment.colour.rgb, glm::dvec3(0.5));
    expect_vec(s.primitives[1].texture.pigment.colour.rgb, glm::dvec3(1, 0, 0));
    EXPECT_EQ(s.primitives[1].texture.pigment.colour.filter, 0.25);
    expect_vec(s.lights[0].colour, glm::dvec3(1));
    EXPECT_EQ(testing::float_symbol(s, "MixBlue"), 0.5);
    EXPECT_TRUE(s.skipped.empty());
    EXPECT_TRUE(s.messages.empty());
}

TEST(Parser, LenientModeSkipsWhatItCannotRenderAndKeepsTheRest) {
    const std::string scene = R"(#version 3.7;
camera { location <0, 2, -5> look_at <0, 1, 0> }
julia_fractal {
    <-0.083, 0.0, -0.83, -0.025>
    quaternion sqr
    max_iteration 8
}
#declare Blob = bicubic_patch { type 0 flatness 0 u_steps 2 v_steps 2 <0,0,0> }
light_source { <5, 5, -5>, rgb 1 photons { refraction on } }
sphere {
    <0, 1, 0>, 1
    photons { target }
    pigment { julia <0.3, 0.5>, 30 color_map { [0 rgb 1] [1 rgb 0] } }
    finish { phong 1 subsurface { translucency 0.5 } }
    hollow
    interior { ior 1.5 media { absorption 1 } }
    translate x
}
union { object { Blob } plane { y, 0 } }
media { scattering { 1, 0.1 } }
)";
    auto strict = parse_scene_text(scene, "scene.pov", ParseOptions{});
    ASSERT_FALSE(strict.ok());
    EXPECT_EQ(strict.message(), "scene.pov:3:1: unsupported object 'julia_fractal'\njulia_fractal {\n^");

    ParseOptions lenient;
    lenient.strict = false;
    Scene s = parse_ok(scene, lenient);
    ASSERT_TRUE(s.has_camera);
    expect_vec(s.camera.location, glm::dvec3(0, 2, -5));
    ASSERT_EQ(s.lights.size(), 1u);
    expect_vec(s.lights[0].location, glm::dvec3(5, 5, -5));
    ASSERT_EQ(s.primitives.size(), 2u);  // the sphere and the plane
    expect_vec(transform_point(s.primitives[0].transform, glm::dvec3(0)), glm::dvec3(1, 0, 0));
    EXPECT_EQ(s.primitives[0].texture.finish.phong, 1.0);
    EXPECT_TRUE(std::holds_alternative<Plane>(s.primitives[1].shape));
    std::vector<std::string> skipped;
    for (const Skipped& k : s.skipped) {
        skipped.push_back(k.what + " @" + std::to_string(k.loc.line) + ":" +
                          std::to_string(k.loc.column));
    }
    std::vector<std::string> expected{
        "object 'julia_fractal' @3:1",
        "object 'bicubic_patch' @8:17",
        "light source modifier 'photons' (only point lights) @9:34",
        "modifier 'photons' in 'sphere' @12:5",
        "pattern 'julia' @13:15",
        "finish item 'subsurface' @14:22",
        "interior item 'media' @16:24",
        "atmospheric effect 'media' @20:1",
    };
    EXPECT_EQ(skipped, expected);
}

TEST(Parser, LenientModeStillRefusesWhatIsNotPovRay) {
    ParseOptions lenient;
    lenient.strict = false;
    EXPECT_EQ(parse_error("spere { 0, 1 }", lenient),
              "scene.pov:1:1: unknown keyword 'spere'\nspere { 0, 1 }\n^");
}

TEST(Parser, PovRaysStandardIncludeFilesParseLeniently) {
    if (!have_povray_includes()) GTEST_SKIP() << "POV-Ray's include files are not installed";
    for (const char* inc :
         {"colors.inc", "textures.inc",  "shapes.inc", "shapes2.inc",    "shapes3.inc",
          "metals.inc", "golds.inc",     "glass.inc",  "woods.inc",      "stones.inc",
          "skies.inc",  "functions.inc", "math.inc",   "transforms.inc", "strings.inc",
          "rand.inc",   "arrays.inc",    "consts.inc", "stdinc.inc",     "finish.inc",
          "stars.inc",  "sunpos.inc",    "screen.inc", "chars.inc"}) {
        std::string text =
            "#version 3.7;\n#include \"colors.inc\"\n#include \"" + std::string(inc) + "\"\n";
        auto r = parse_scene_text(text, "scene.pov", with_includes(false));
        EXPECT_TRUE(r.ok()) << inc << ": " << (r.ok() ? "" : r.message());
    }
}

TEST(Parser, ACompleteMirageScene) {
    if (!have_povray_includes()) GTEST_SKIP() << "POV-Ray's include files are not installed";
    ParseOptions o = with_includes();
    o.image_width = 320;
    o.image_height = 240;
    auto r = parse_scene_file(testing::data_dir() + "/desert.pov", o);
    ASSERT_TRUE(r.ok()) << r.message();
    const Scene& s = *r;
    EXPECT_EQ(s.file, testing::data_dir() + "/desert.pov");
    EXPECT_TRUE(s.has_camera);
    EXPECT_EQ(s.global.max_trace_level, 256);
    EXPECT_EQ(testing::string_symbol(s, "Mirage_Profile"), "paper");
    EXPECT_EQ(testing::float_symbol(s, "Mirage_Eye_Height"), 1.5);
    // Ground plane plus a row of five spheres from a #for loop.
    ASSERT_EQ(s.primitives.size(), 6u);
    EXPECT_EQ(s.primitives[0].texture.pigment.kind, PigmentKind::Checker);
    for (int i = 1; i <= 5; ++i) {
        const auto& sphere = std::get<Sphere>(s.primitives[i].shape);
        EXPECT_EQ(sphere.center.z, 10.0 * i);
    }
    ASSERT_TRUE(s.sky_sphere.has_value());
    EXPECT_EQ(s.lights.size(), 1u);
    // The camera is level at eye height, with a 4:3 right vector.
    expect_vec(s.camera.location, glm::dvec3(0, 1.5, 0));
    EXPECT_NEAR(glm::length(s.camera.right) / glm::length(s.camera.up), 320.0 / 240.0, 1e-12);
}

}  // namespace
}  // namespace mirage
