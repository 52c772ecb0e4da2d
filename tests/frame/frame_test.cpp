// The framing report's figures against the exact paths: the mirage band's rows against every
// row's own exact ray, the apparent horizon against the closed form, each object's vanishing
// distance against `mirage path --object-height`, and the advice's figures against the same
// reading redone with the advice followed.
#include "frame/frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../cli/run_tool.h"
#include "../test_temp.h"
#include "atmosphere/exact_path.h"
#include "atmosphere/profile.h"
#include "frame/frame_output.h"
#include "scene/camera.h"
#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

using testing::run_tool;
using testing::test_temp_path;

constexpr double kPi = 3.14159265358979323846;

// A level camera at `eye` m with horizontal angle `angle`, a ground plane and objects.
std::string write_scene(const std::string& name, const std::string& settings, double eye,
                        double angle, const std::string& objects) {
    const auto p = test_temp_path(name);
    std::ofstream(p) << "#version 3.7;\n"
                     << settings << "\n#include \"mirage.inc\"\n"
                     << "camera { location <0, " << eye << ", 0> look_at <0, " << eye
                     << ", 100> right x * 4 / 3 angle " << angle << " }\n"
                     << "plane { y, 0 pigment { color rgb 0.3 } }\n"
                     << objects;
    return p.string();
}

Result<FrameReading> read(const std::string& scene, bool advise = false, int w = 320, int h = 240) {
    FrameOptions o;
    o.scene = scene;
    o.width = w;
    o.height = h;
    o.advise = advise;
    return frame_scene(o);
}

// Whether the exact ray of centre-column row r turns low before meeting the ground, followed
// here on its own (camera_ray, ExactPath), not through the frame module.
bool row_turns_low(const Atmosphere& atm, const Camera& camera, int w, int h, int r,
                   double* turn_dz = nullptr) {
    const glm::dvec3 d = camera_ray(camera, 0.5 * w, r + 0.5, w, h).direction;
    auto p = ExactPath::make(atm, camera.location.y, std::acos(d.y));
    EXPECT_TRUE(p.ok());
    if (p->turning_point_count() == 0) return false;
    const TurningPoint tp = p->turning_point(0);
    if (!tp.lowest) return false;
    if (p->hits_ground() && p->dz_ground() < tp.dz) return false;
    if (turn_dz) *turn_dz = tp.dz;
    return true;
}

TEST(Frame, MirageBandRowsAreTheRowsWhoseExactRayTurns) {
    // Hot road at 1.7 m through a 4 degree lens: the band is some tens of rows.
    const std::string scene = write_scene("band.pov", "#declare Mirage_Preset = \"hot-road\";", 1.7,
                                          4, "box { <-1, 0, 700>, <1, 2, 702> }\n");
    auto f = read(scene);
    ASSERT_TRUE(f.ok()) << f.message();
    ASSERT_TRUE(f->inferior);
    const Profile p = *preset_profile("hot-road");
    const Atmosphere atm = Atmosphere::exponential(p);
    const Camera& cam = f->view.camera;
    int count = 0, first = -1, last = -1, in_reach = 0;
    for (int r = 0; r < 240; ++r) {
        double dz = 0.0;
        const bool turns = row_turns_low(atm, cam, 320, 240, r, &dz);
        EXPECT_EQ(turns, f->column.rows[r].fate == RayFate::TurnsLow) << "row " << r;
        if (!turns) continue;
        if (first < 0) first = r;
        last = r;
        ++count;
        if (dz <= f->view.reach) ++in_reach;
    }
    EXPECT_GT(count, 10);
    EXPECT_EQ(f->column.turning_low.count, count);
    EXPECT_EQ(f->column.turning_low.first, first);
    EXPECT_EQ(f->column.turning_low.last, last);
    EXPECT_EQ(f->column.turning_low_in_reach.count, in_reach);
    EXPECT_GT(in_reach, 0);
    EXPECT_LT(in_reach, count);  // the box at 700 m: the reach cuts the band
    // The band runs from the true horizon down to the apparent horizon.
    // (the first row whose centre lies below the true horizon, the last above the apparent one)
    EXPECT_EQ(first, static_cast<int>(std::floor(f->true_horizon_row - 0.5)) + 1);
    EXPECT_EQ(last, static_cast<int>(std::floor(f->apparent_horizon_row - 0.5)));
    // The apparent horizon is the grazing ray, n(y0) cos e = n(0), to the bisection's precision.
    const double grazing = -std::acos(eta(p, 0.0) / eta(p, 1.7));
    EXPECT_NEAR(f->apparent_horizon_rad, grazing, 1e-12);
    // ... and where it touches the ground, the closed form's X(0 -> y0).
    const double beta = p.eta0;
    const double x =
        2.0 * beta / (p.alpha * p.eta1) * std::atanh(std::sqrt(-std::expm1(-p.alpha * 1.7)));
    EXPECT_NEAR(f->ground_ends, x, 1e-6 * x);
}

TEST(Frame, VanishingDistanceIsThatOfMiragePathObjectHeight) {
    const std::string scene =
        write_scene("vanish.pov", "#declare Mirage_Preset = \"hot-road\";", 1.7, 10,
                    "box { <-1, 0, 300>, <1, 2.5, 302> }\n"
                    "sphere { <4, 3, 1200>, 0.5 }\n");
    auto f = read(scene);
    ASSERT_TRUE(f.ok()) << f.message();
    ASSERT_EQ(f->objects.size(), 2u);
    for (const ObjectReading& o : f->objects) {
        const auto run = run_tool("path --preset hot-road --eye-height 1.7 --object-height " +
                                  std::to_string(o.top) + " --json");
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const auto j = nlohmann::json::parse(run.out);
        const double nearest = j["nearest_eye_distance"];
        EXPECT_NEAR(o.vanishing, nearest, 1e-9 * nearest) << o.object.name;
        EXPECT_NEAR(o.farthest, double(j["farthest_eye_distance"]), 1e-9 * nearest);
    }
    // The box at 300 m is nearer than its top's vanishing distance (about 800 m): no mirrored
    // image but the sliver at the horizon of rays that turn at once (under half a row); the
    // sphere's top at 3.5 m is mirrored from 1200 m (beyond about 1020 m), rows tall.
    const double row = f->pixel_rad;
    EXPECT_LT(f->objects[0].distance, f->objects[0].vanishing);
    EXPECT_LT(f->objects[0].mirrored.angular_size_rad(), 0.5 * row);
    EXPECT_GT(f->objects[1].distance, f->objects[1].vanishing);
    EXPECT_LT(f->objects[1].distance, f->objects[1].farthest);
    EXPECT_TRUE(f->objects[1].mirrored.visible);
    EXPECT_GT(f->objects[1].mirrored.angular_size_rad(), 2.0 * row);
}

TEST(Frame, MirroredImageIsWhereTheTurnedRaysOfItsColumnMeetIt) {
    // A wide box straight ahead, far enough to be mirrored: the centre column's rays that turn
    // and then meet it span the reported mirrored image.
    const std::string scene = write_scene("image.pov", "#declare Mirage_Preset = \"hot-road\";",
                                          1.2, 3, "box { <-20, 0, 800>, <20, 3, 805> }\n");
    auto f = read(scene);
    ASSERT_TRUE(f.ok()) << f.message();
    ASSERT_EQ(f->objects.size(), 1u);
    const ImageSpan& m = f->objects[0].mirrored;
    ASSERT_TRUE(m.visible);
    const Atmosphere atm = Atmosphere::exponential(*preset_profile("hot-road"));
    const Camera& cam = f->view.camera;
    int lo = 1 << 30, hi = -1;
    for (int r = 0; r < 240; ++r) {
        double turn = 0.0;
        if (!row_turns_low(atm, cam, 320, 240, r, &turn)) continue;
        const glm::dvec3 d = camera_ray(cam, 160, r + 0.5, 320, 240).direction;
        auto p = ExactPath::make(atm, 1.2, std::acos(d.y));
        // It meets the box's front face after its turn, below the top.
        if (turn < 800.0 && p->height_at(800.0) <= 3.0 && p->height_at(800.0) >= 0.0) {
            lo = std::min(lo, r);
            hi = std::max(hi, r);
        }
    }
    ASSERT_GE(hi, lo);
    // Row centres inside the reported span, and the span within a row of them.
    EXPECT_LE(m.row_top, lo + 0.5);
    EXPECT_GE(m.row_bottom, hi + 0.5);
    EXPECT_GT(m.row_top, lo - 0.5);
    EXPECT_LT(m.row_bottom, hi + 1.5);
}

TEST(Frame, LensAdviceFiguresAreTheBandRowsWithThatAngle) {
    const std::string scene = write_scene("lens.pov", "#declare Mirage_Preset = \"hot-road\";", 1.7,
                                          50, "box { <-1, 0, 30>, <1, 1.5, 34> }\n");
    auto f = read(scene, true);
    ASSERT_TRUE(f.ok()) << f.message();
    ASSERT_GE(f->lenses.size(), 3u);
    EXPECT_LT(f->column.turning_low.count, 8);  // hardly visible at angle 50
    for (const LensOption& l : f->lenses) {
        // The same scene written with that angle reads the same band.
        const std::string other =
            write_scene("lens_" + std::to_string(int(l.angle_deg * 10)) + ".pov",
                        "#declare Mirage_Preset = \"hot-road\";", 1.7, l.angle_deg,
                        "box { <-1, 0, 30>, <1, 1.5, 34> }\n");
        auto g = read(other);
        ASSERT_TRUE(g.ok()) << g.message();
        EXPECT_EQ(g->column.turning_low.count, l.band_rows) << "angle " << l.angle_deg;
    }
    // The advice names an angle and the band's rows with it.
    bool named = false;
    for (const std::string& a : f->advice)
        if (a.find("mirage band is") != std::string::npos &&
            a.find("with angle") != std::string::npos)
            named = true;
    EXPECT_TRUE(named) << frame_text(*f);
}

TEST(Frame, CameraHeightAdviceIsTheVanishingDistanceFromThatHeight) {
    const std::string scene = write_scene("height.pov", "#declare Mirage_Preset = \"hot-road\";",
                                          1.7, 10, "sphere { <0, 1, 200>, 0.5 }\n");
    auto f = read(scene, true);
    ASSERT_TRUE(f.ok()) << f.message();
    ASSERT_GE(f->heights.size(), 2u);
    for (const HeightOption& h : f->heights) {
        const auto run = run_tool("path --preset hot-road --eye-height " +
                                  std::to_string(h.eye_height) + " --object-height 1.5 --json");
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const double nearest = nlohmann::json::parse(run.out)["nearest_eye_distance"];
        EXPECT_NEAR(h.vanishing[0], nearest, 1e-9 * nearest) << "eye " << h.eye_height;
    }
    // Lower eyes see the mirage nearer.
    EXPECT_LT(f->heights.back().vanishing[0], f->heights.front().vanishing[0]);
}

TEST(Frame, OverlayMarksTheHorizonsAndTheBand) {
    const std::string scene =
        write_scene("overlay.pov", "#declare Mirage_Preset = \"hot-road\";", 1.7, 4, "");
    auto f = read(scene);
    ASSERT_TRUE(f.ok()) << f.message();
    const Image img = frame_overlay(*f, Image());
    const int r0 = static_cast<int>(std::floor(f->true_horizon_row));
    const int rg = static_cast<int>(std::floor(f->apparent_horizon_row));
    const glm::vec3 green = img.at(10, r0), red = img.at(10, rg);
    EXPECT_EQ(green, glm::vec3(OverlayKey::kTrueHorizon[0], OverlayKey::kTrueHorizon[1],
                               OverlayKey::kTrueHorizon[2]));
    EXPECT_EQ(red, glm::vec3(OverlayKey::kApparentHorizon[0], OverlayKey::kApparentHorizon[1],
                             OverlayKey::kApparentHorizon[2]));
    // Between them the band's tint; below, the plain ground.
    EXPECT_NE(img.at(10, (r0 + rg) / 2), img.at(10, rg + 5));
}

TEST(Frame, CommandPrintsTheReadingAsJsonAndWritesTheOverlay) {
    const std::string scene = write_scene("cli.pov", "#declare Mirage_Preset = \"hot-road\";", 1.7,
                                          4, "box { <-1, 0, 900>, <1, 2.5, 902> }\n");
    const auto png = test_temp_path("cli_overlay.png");
    const auto run =
        run_tool("frame " + testing::quoted(scene) + " --json --plain -o " + testing::quoted(png));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    auto f = read(scene);
    ASSERT_TRUE(f.ok()) << f.message();
    EXPECT_EQ(int(j["mirage_band"]["count"]), f->column.turning_low.count);
    EXPECT_DOUBLE_EQ(double(j["apparent_horizon"]["row"]), f->apparent_horizon_row);
    ASSERT_EQ(j["objects"].size(), 1u);
    EXPECT_DOUBLE_EQ(double(j["objects"][0]["vanishing_distance_m"]), f->objects[0].vanishing);
    EXPECT_EQ(j["objects"][0]["place"], to_string(f->objects[0].object.loc));
    EXPECT_FALSE(testing::read_bytes(png).empty());
    EXPECT_NE(std::string(j["overlay_legend"]).find("red line the apparent horizon"),
              std::string::npos);
    // The overlay may not replace the scene it read.
    const std::string before = testing::read_bytes(scene);
    const auto over =
        run_tool("frame " + testing::quoted(scene) + " --plain -o " + testing::quoted(scene));
    EXPECT_EQ(over.exit_code, 1);
    EXPECT_NE(over.err.find("mirage frame: "), std::string::npos) << over.err;
    EXPECT_EQ(testing::read_bytes(scene), before);
}

TEST(Frame, RefusesWhatItCannotRead) {
    auto none = read(write_scene("none.pov", "", 1.7, 10, ""));
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.message().find("declares no atmosphere that bends rays"), std::string::npos)
        << none.message();
    const auto p = test_temp_path("ortho.pov");
    std::ofstream(p) << "#declare Mirage_Preset = \"hot-road\";\n#include \"mirage.inc\"\n"
                        "camera { orthographic location <0, 1, 0> look_at <0, 1, 10> }\n";
    auto ortho = read(p.string());
    ASSERT_FALSE(ortho.ok());
    EXPECT_NE(ortho.message().find("ortho.pov:3:1: mirage frame reads a perspective camera"),
              std::string::npos)
        << ortho.message();
}

// A camera under the ground: refused with the message trace (and compile) give.
TEST(Frame, RefusesACameraUnderTheGroundAsTraceDoes) {
    const std::string scene =
        write_scene("under.pov", "#declare Mirage_Preset = \"hot-road\";", -0.5, 10, "");
    auto under = read(scene);
    ASSERT_FALSE(under.ok());
    TraceOptions t;
    t.scene = scene;
    t.output = test_temp_path("under.png").string();
    t.progress = false;
    auto traced = trace_scene(t);
    ASSERT_FALSE(traced.ok());
    EXPECT_EQ(under.message(), traced.message());
    EXPECT_NE(under.message().find("under.pov:4:1: "), std::string::npos) << under.message();
}

}  // namespace
}  // namespace mirage
