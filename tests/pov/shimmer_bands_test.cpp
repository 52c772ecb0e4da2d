// POV-Ray's render shimmers as the tracer's does: the corrected camera aims every pixel's ray
// where its exact ray, walked through the scene's turbulent air at the frame's clock, ends
// (docs/turbulence.md).  A frame compiled and rendered by POV-Ray is held to the tracer's
// render of the same clock, and must be nearer it than to the tracer's render of another
// clock (which a camera that ignored the turbulence would match no better).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../trace/povray_runner.h"
#include "compile/compile.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "pov/emit_camera.h"
#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;
using testing::povray_available;
using testing::test_dir;

constexpr int kW = 160, kH = 120;

// A level camera over the paper's hot sand looking along a checkered wall and a row of posts,
// through strong turbulence (about two pixels of shimmer at this size) carried by a breeze.
const char* kScene = R"(#version 3.7;
#declare Mirage_Preset = "paper";
#declare Mirage_Tolerance = 0.5;
#declare Mirage_Turbulence_Cn2 = 3e-10;
#declare Mirage_Turbulence_Inner = 0.005;
#declare Mirage_Turbulence_Outer = 1;
#declare Mirage_Turbulence_Aperture = 0.02;
#declare Mirage_Wind = <2, 0.3, 0>;
#include "mirage.inc"
camera { location <0, 1.5, 0> look_at <0, 1.2, 20> right x * image_width / image_height angle 20 }
light_source { <-30, 60, -20>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.8, color rgb 0.3 scale 0.5 } }
box { <-20, 0, 30>, <20, 6, 30.5> pigment { checker color rgb <0.9, 0.2, 0.1>, color rgb <0.1, 0.2, 0.9> scale 0.4 } }
#for (K, -4, 4)
  cylinder { <K * 1.5, 0, 15>, <K * 1.5, 2.5, 15>, 0.08 pigment { color rgb 1 } }
#end
)";

Result<Image> traced_at(const std::string& scene, const fs::path& png, double clock) {
    TraceOptions o;
    o.scene = scene;
    o.output = png.string();
    o.width = kW;
    o.height = kH;
    o.tolerance_px = 0.1;
    o.clock = clock;
    o.progress = false;
    auto r = trace_scene(o);
    if (!r) return r.error();
    return quantize_srgb8(r->render.image);
}

TEST(ShimmerBands, PovRaysFrameIsTheTracersFrameOfTheSameClock) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = test_dir("shimmer_bands", "frame");
    const std::string scene = (dir / "shimmer.pov").string();
    std::ofstream(scene) << kScene;
    const double clock = 0.4, other = 0.0;
    CompileOptions o;
    o.scene = scene;
    o.width = kW;
    o.height = kH;
    o.clock = clock;
    o.out_dir = (dir / "bands").string();
    o.image = (dir / "bands.png").string();
    o.progress = false;
    auto report = compile_scene(o);
    ASSERT_TRUE(report.ok()) << report.message();
    ASSERT_EQ(report->camera, "corrected");
    const std::string command = "cd '" + dir.string() + "' && povray -D '" + report->ini_path +
                                "' > povray.log 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << "see " << dir / "povray.log";
    ASSERT_TRUE(crop_mesh_camera_render(o.image).ok());
    auto pov = read_image(o.image);
    auto same = traced_at(scene, dir / "trace_same_clock.png", clock);
    auto apart = traced_at(scene, dir / "trace_other_clock.png", other);
    ASSERT_TRUE(pov.ok() && same.ok() && apart.ok());
    auto near = compare_images(*pov, *same, 0.1);
    auto far = compare_images(*pov, *apart, 0.1);
    auto frames = compare_images(*same, *apart, 0.1);
    ASSERT_TRUE(near.ok() && far.ok() && frames.ok());
    std::printf("POV-Ray at clock %g against the tracer: same clock %.2f dB, %lld px over 0.1; "
                "clock %g %.2f dB, %lld px; the tracer's two clocks %lld px apart\n",
                clock, near->psnr_db, static_cast<long long>(near->pixels_over), other,
                far->psnr_db, static_cast<long long>(far->pixels_over),
                static_cast<long long>(frames->pixels_over));
    // The clocks' frames differ (the scene shimmers), and POV-Ray's frame is the tracer's
    // frame of its own clock: less than half as far from it as from the other clock's (a
    // camera that ignored the turbulence, or aimed in the unperturbed rays' vertical planes,
    // is as far from both: 327 and 343 pixels).  What is left is the edges the tracer's 0.1 px
    // tolerance and the band rays' hundredths of a pixel put on the other side of a pixel
    // centre.
    ASSERT_GT(frames->pixels_over, kW * kH / 50) << "the turbulence moves too little to test";
    EXPECT_LE(near->pixels_over * 2, far->pixels_over) << "images in " << dir;
    EXPECT_LE(near->pixels_over * 2, frames->pixels_over) << "images in " << dir;
}

}  // namespace
}  // namespace mirage
