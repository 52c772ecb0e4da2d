// The compiler's extent of objects it cannot represent (trace/scene_extent.h): bounded by
// their bounded_by or clipped_by, by Mirage_Extent, or taken as unbounded, and said so.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "compile/compile.h"
#include "test_temp.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::string temp_dir(const std::string& name) {
    const fs::path d = mirage::testing::test_temp_path("extent_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d.string();
}

Result<CompileReport> compile_text(const std::string& name, const std::string& body) {
    const std::string dir = temp_dir(name);
    const std::string path = dir + "/" + name + ".pov";
    std::ofstream(path) << "#version 3.7;\n#declare Mirage_Preset = \"hot-road\";\n"
                           "#include \"mirage.inc\"\n"
                           "camera { location <0, 1.5, 0> look_at <0, 1.4, 100> angle 5 }\n"
                        << body;
    CompileOptions o;
    o.scene = path;
    o.width = 32;
    o.height = 24;
    o.out_dir = dir + "/out";
    return compile_scene(o);
}

bool any_contains(const std::vector<std::string>& lines, const std::string& text) {
    for (const auto& l : lines) {
        if (l.find(text) != std::string::npos) return true;
    }
    return false;
}

constexpr const char* kJulia =
    "julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 ";

TEST(Extent, AnUnknownObjectIsBoundedByItsBoundedBy) {
    auto r = compile_text("bounded", std::string("sphere { <0, 1, 40>, 1 pigment { rgb 1 } }\n") +
                                         kJulia +
                                         "bounded_by { box { -1, 1 } } translate <0, 1, 300> }\n");
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_GT(r->extent, 300.0);  // reaches the fractal, not only the sphere at 40
    EXPECT_TRUE(any_contains(r->left_out, "object 'julia_fractal'"));
    EXPECT_TRUE(any_contains(r->left_out, "bounded by its bounded_by or clipped_by"));
}

TEST(Extent, WithoutABoundItIsTakenAsUnboundedAndTheReportSaysSo) {
    auto r = compile_text("unbounded", std::string("sphere { <0, 1, 40>, 1 pigment { rgb 1 } }\n") +
                                           kJulia + "translate <0, 1, 300> }\n");
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_LT(r->extent, 100.0);  // the sphere's
    EXPECT_TRUE(any_contains(r->warnings, "taken as unbounded"));
}

TEST(Extent, WithNothingBoundingTheSceneTheAtmosphereReachesFarAndSaysSo) {
    auto r = compile_text("alone", std::string(kJulia) + "translate <0, 1, 300> }\n" +
                                       "plane { y, 0 pigment { rgb 1 } }\n");
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_DOUBLE_EQ(r->extent, 1500.0);  // 1000 camera heights
    EXPECT_TRUE(any_contains(r->warnings, "no object bounds the scene"));
    EXPECT_TRUE(any_contains(r->warnings, "object 'julia_fractal'"));
    auto declared = compile_text("alone_extent", std::string("#declare Mirage_Extent = 400;\n") +
                                                     kJulia + "translate <0, 1, 300> }\n");
    ASSERT_TRUE(declared.ok()) << declared.message();
    EXPECT_DOUBLE_EQ(declared->extent, 400.0);
}

TEST(Extent, WhatTheCompilerDoesNotNeedIsNoError) {
    // Textures, patterns and finishes of the standard includes, and a texture mirage cannot
    // read, on an object whose extent it knows.
    if (!fs::exists("/usr/share/povray-3.7/include/textures.inc")) GTEST_SKIP();
    auto r = compile_text("textures", R"(#include "textures.inc"
#include "stones.inc"
#include "woods.inc"
sphere { <0, 1, 40>, 1 texture { T_Stone1 } }
box { <-1, 0, 60>, <1, 2, 62> texture { T_Wood3 } normal { bumps 0.3 } }
)");
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_GT(r->extent, 60.0);
    EXPECT_TRUE(r->warnings.empty() || !any_contains(r->warnings, "taken as unbounded"));
}

}  // namespace
}  // namespace mirage
