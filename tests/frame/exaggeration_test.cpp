// Mirage_Exaggeration: 1 changes nothing (renders byte-identical); k multiplies n^2 - n0^2 at
// every height, so the grazing ray's n(y0)^2 sin^2 e and the rays' curvature are k times as
// large and the grazing vanishing distance 1 / sqrt(k) times as long; range checked with its
// place.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "../cli/run_tool.h"
#include "../test_temp.h"
#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"
#include "atmosphere/vanishing.h"
#include "frame/frame.h"
#include "load/mirage_scene.h"

namespace mirage {
namespace {

using testing::read_bytes;
using testing::run_tool;
using testing::test_temp_path;

std::string write_scene(const std::string& name, const std::string& settings) {
    const auto p = test_temp_path(name);
    std::ofstream(p) << "#version 3.7;\n"
                     << settings << "\n#include \"mirage.inc\"\n"
                     << "global_settings { assumed_gamma 1.0 }\n"
                        "camera { location <0, 1.2, 0> look_at <0, 1.2, 100> right x * 4 / 3 "
                        "angle 8 }\n"
                        "light_source { <-100, 300, -100>, color rgb 1 }\n"
                        "sky_sphere { pigment { gradient y scale 2 translate -y color_map { [0 "
                        "color rgb <0.9, 0.9, 1>] [1 color rgb <0.1, 0.2, 0.7>] } } }\n"
                        "plane { y, 0 pigment { checker color rgb 0.2, color rgb 0.4 scale 5 } }\n"
                        "box { <-2, 0, 60>, <2, 3, 62> pigment { color rgb <0.8, 0.2, 0.1> } }\n";
    return p.string();
}

Result<MirageScene> load(const std::string& scene) {
    return load_mirage_scene(scene_load_options(scene, 80, 60, {}));
}

TEST(Exaggeration, OneLeavesTheRenderByteIdentical) {
    const std::string plain = write_scene("plain.pov", "#declare Mirage_Preset = \"hot-road\";");
    const std::string one = write_scene(
        "one.pov", "#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Exaggeration = 1;");
    const std::string ten = write_scene(
        "ten.pov", "#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Exaggeration = 30;");
    const auto a = test_temp_path("plain.png"), b = test_temp_path("one.png"),
               c = test_temp_path("ten.png");
    for (const auto& [scene, out] : {std::pair{plain, a}, std::pair{one, b}, std::pair{ten, c}}) {
        const auto run = run_tool("trace " + testing::quoted(scene) + " -o " +
                                  testing::quoted(out) + " -W 80 -H 60 -q --threads 1");
        ASSERT_EQ(run.exit_code, 0) << run.err;
    }
    EXPECT_FALSE(read_bytes(a).empty());
    EXPECT_EQ(read_bytes(a), read_bytes(b));
    EXPECT_NE(read_bytes(a), read_bytes(c));  // and a factor does change the render
}

TEST(Exaggeration, CompileBandsTheExaggeratedAir) {
    const std::string plain = write_scene("cplain.pov", "#declare Mirage_Preset = \"hot-road\";");
    const std::string one = write_scene(
        "cone.pov", "#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Exaggeration = 1;");
    const std::string k30 = write_scene(
        "ck30.pov", "#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Exaggeration = 30;");
    std::vector<std::string> layers, reports;
    for (const std::string& scene : {plain, one, k30}) {
        const auto dir = test_temp_path("compiled_" + std::to_string(layers.size()));
        const auto run = run_tool("compile " + testing::quoted(scene) + " -W 64 -H 48 -o " +
                                  testing::quoted(dir));
        ASSERT_EQ(run.exit_code, 0) << run.err;
        layers.push_back(read_bytes(dir / "layers.csv"));
        reports.push_back(read_bytes(dir / "report.json"));
    }
    EXPECT_FALSE(layers[0].empty());
    EXPECT_EQ(layers[0], layers[1]);
    EXPECT_NE(layers[0], layers[2]);
    EXPECT_EQ(reports[0].find("not air"), std::string::npos);
    EXPECT_NE(reports[2].find("hot-road (inferior), exaggerated 30 times (not air)"),
              std::string::npos);
}

TEST(Exaggeration, ScalesTheIndexExcessOverTheGround) {
    auto base = load(write_scene("base.pov", "#declare Mirage_Preset = \"paper\";"));
    auto k4 = load(write_scene(
        "k4.pov", "#declare Mirage_Preset = \"paper\";\n#declare Mirage_Exaggeration = 0.04;"));
    ASSERT_TRUE(base.ok()) << base.message();
    ASSERT_TRUE(k4.ok()) << k4.message();
    const Profile& p = base->settings.profile;
    const Profile& q = k4->settings.profile;
    EXPECT_EQ(q.eta0, p.eta0);
    EXPECT_EQ(q.alpha, p.alpha);
    EXPECT_DOUBLE_EQ(q.eta1 * q.eta1, 0.04 * p.eta1 * p.eta1);
    EXPECT_DOUBLE_EQ(k4->settings.exaggeration, 0.04);
    EXPECT_NE(k4->settings.profile_label.find("exaggerated 0.04 times (not air)"),
              std::string::npos)
        << k4->settings.profile_label;
    for (double y : {0.1, 0.5, 2.0, 10.0})
        EXPECT_NEAR(eta_sq(q, y) - eta_sq(q, 0.0), 0.04 * (eta_sq(p, y) - eta_sq(p, 0.0)), 1e-15);
    // 1 is no exaggeration at all: the same profile to the bit, and no word of it.
    auto one = load(write_scene(
        "k1.pov", "#declare Mirage_Preset = \"paper\";\n#declare Mirage_Exaggeration = 1;"));
    ASSERT_TRUE(one.ok()) << one.message();
    EXPECT_EQ(one->settings.profile.eta1, p.eta1);
    EXPECT_EQ(one->settings.profile_label, base->settings.profile_label);
}

TEST(Exaggeration, GrazingRayAndVanishingDistanceScaleAsTheyShould) {
    // Through the frame reading: n(y0)^2 sin^2 e of the grazing ray is n(y0)^2 - n(0)^2, which
    // the factor multiplies; a grazing ray's distances X(0 -> y) go as 1 / sqrt(k) (beta = n(0)
    // stays), so the grazing vanishing distance does.
    const double k = 25.0;
    const std::string a = write_scene("ga.pov", "#declare Mirage_Preset = \"hot-road\";");
    const std::string b = write_scene(
        "gb.pov", "#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Exaggeration = 25;");
    FrameOptions o;
    o.width = 320;
    o.height = 240;
    o.advise = false;
    o.scene = a;
    auto fa = frame_scene(o);
    o.scene = b;
    auto fb = frame_scene(o);
    ASSERT_TRUE(fa.ok()) << fa.message();
    ASSERT_TRUE(fb.ok()) << fb.message();
    auto pa = load(a), pb = load(b);
    const Profile& p = pa->settings.profile;
    const Profile& q = pb->settings.profile;
    const double sa = std::sin(fa->apparent_horizon_rad), sb = std::sin(fb->apparent_horizon_rad);
    EXPECT_NEAR(eta_sq(q, 1.2) * sb * sb / (eta_sq(p, 1.2) * sa * sa), k, 1e-8 * k);
    EXPECT_NEAR(fb->ground_ends * std::sqrt(k), fa->ground_ends, 1e-9 * fa->ground_ends);
    ASSERT_EQ(fa->objects.size(), 1u);
    ASSERT_EQ(fb->objects.size(), 1u);
    auto ra = mirror_reach(p, 1.2, 3.0);
    ASSERT_TRUE(ra.ok());
    ASSERT_TRUE(ra->grazing);
    EXPECT_NEAR(fa->objects[0].vanishing, ra->nearest, 1e-9 * ra->nearest);
    EXPECT_NEAR(fb->objects[0].vanishing * std::sqrt(k), ra->nearest, 1e-6 * ra->nearest);
    // The curvature of a ray, y'' = (n^2)' / (2 beta^2), at any height for the same invariant.
    auto ea = ExactPath::make(Atmosphere::exponential(p), 1.2, 1.5);
    auto eb = ExactPath::make(Atmosphere::exponential(q), 1.2, 1.5);
    ASSERT_TRUE(ea.ok() && eb.ok());
    const double ca = ea->curvature_bound(0.7, 0.7), cb = eb->curvature_bound(0.7, 0.7);
    const double beta_ratio = eb->beta() / ea->beta();
    EXPECT_NEAR(cb * beta_ratio * beta_ratio / ca, k, 1e-9 * k);
}

TEST(Exaggeration, RealAirIsScaledBeforeTheEarthIsFlattened) {
    const std::string air =
        "#declare Mirage_Air_Temperature = 300;\n#declare Mirage_Ground_Temperature = 320;\n"
        "#declare Mirage_Scale_Height = 0.3;\n#declare Mirage_Lapse = 6.5;\n"
        "#declare Mirage_Earth_Radius = 0;\n";
    auto a = load(write_scene("ra.pov", air));
    auto b = load(write_scene("rb.pov", air + "#declare Mirage_Exaggeration = 8;\n"));
    ASSERT_TRUE(a.ok()) << a.message();
    ASSERT_TRUE(b.ok()) << b.message();
    ASSERT_TRUE(a->settings.air && b->settings.air);
    EXPECT_EQ(b->settings.air->exaggeration, 8.0);
    auto ma = scene_atmosphere(a->settings, 1e-6), mb = scene_atmosphere(b->settings, 1e-6);
    ASSERT_TRUE(ma.ok() && mb.ok());
    for (double y : {0.05, 0.3, 1.0, 3.0}) {
        const double da = ma->n_sq(y) - ma->n_sq(0.0), db = mb->n_sq(y) - mb->n_sq(0.0);
        // Each within the fit's |n_fit - n| bound (1e-13 here) of k times the other.
        EXPECT_NEAR(db, 8.0 * da, 1e-11) << "y " << y;
        EXPECT_GT(std::abs(db), 1e-6);
    }
}

TEST(Exaggeration, RangeAndPlaceAreChecked) {
    auto zero = load(write_scene(
        "z.pov", "#declare Mirage_Preset = \"hot-road\";\n#declare Mirage_Exaggeration = 0;"));
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(
        zero.message().find("z.pov:3:10: Mirage_Exaggeration = 0 must be from 0.001 to 10000"),
        std::string::npos)
        << zero.message();
    auto none = load(write_scene("n.pov", "#declare Mirage_Exaggeration = 10;"));
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.message().find("n.pov:2:10: Mirage_Exaggeration = 10: there is no index "
                                  "gradient to exaggerate"),
              std::string::npos)
        << none.message();
    // The paper's profile 1000 times: eta1 past the profiles' range, named as the factor's.
    auto big = load(write_scene(
        "b.pov", "#declare Mirage_Preset = \"paper\";\n#declare Mirage_Exaggeration = 1000;"));
    ASSERT_FALSE(big.ok());
    EXPECT_NE(big.message().find("b.pov:3:10: Mirage_Exaggeration = 1000: the exaggerated "
                                 "profile's eta1 = "),
              std::string::npos)
        << big.message();
}

}  // namespace
}  // namespace mirage
