// mirage trace for any profile: scenes of real air go through the general engine's exact
// paths, with the sampling near surfaces and the tolerance kept.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"
#include "load/mirage_scene.h"
#include "scene/camera.h"
#include "scene/parser.h"
#include "trace/curved_propagator.h"
#include "trace/scene_accel.h"
#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

namespace fs = std::filesystem;

std::string scene_path(const std::string& name) {
    return std::string(MIRAGE_SOURCE_DIR) + "/scenes/" + name + ".pov";
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

class RealAirTrace : public ::testing::Test {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_real_air_trace_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }

    /// A copy of a shipped scene with one line replaced.
    fs::path edited(const std::string& name, const std::string& from, const std::string& to) {
        std::string text = read_text(scene_path(name));
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
        const fs::path p = dir_ / (name + "-edited.pov");
        std::ofstream(p) << text;
        return p;
    }

    Result<TraceReport> trace(const fs::path& scene, int w, int h, int threads = 0,
                              bool atmosphere = true) {
        TraceOptions o;
        o.scene = scene.string();
        o.width = w;
        o.height = h;
        o.threads = threads;
        o.progress = false;
        o.atmosphere = atmosphere;
        return trace_scene(o);
    }
};

// The share of pixels whose colours differ by more than 2/255 in some channel.
double differing_share(const Image& a, const Image& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    size_t differ = 0;
    for (size_t p = 0; p + 2 < a.pixels.size(); p += 3) {
        bool d = false;
        for (int c = 0; c < 3; ++c)
            d = d || std::abs(a.pixels[p + c] - b.pixels[p + c]) > 2.0 / 255;
        differ += d;
    }
    return static_cast<double>(differ) / (a.pixels.size() / 3);
}

TEST_F(RealAirTrace, ASoundingOfTheExponentialProfileRendersTheExponentialScene) {
    // The hot road's exponential profile written as a sounding of n, every mm up to 2 m and
    // every 4 mm up to 10 m (above, the exponential's change is below 1e-14).
    auto hot = preset_profile("hot-road");
    ASSERT_TRUE(hot.ok());
    {
        std::ofstream csv(dir_ / "road_n.csv");
        csv << "height_m,n\n";
        char line[64];
        for (int k = 0; k <= 4000; ++k) {
            const double y = k <= 2000 ? 0.001 * k : 2.0 + 0.004 * (k - 2000);
            std::snprintf(line, sizeof line, "%.3f,%.17g\n", y, eta(*hot, y));
            csv << line;
        }
    }
    const fs::path sounding = edited("road", "#declare Mirage_Preset    = \"hot-road\";",
                                     "#declare Mirage_Sounding = \"road_n.csv\";\n"
                                     "#declare Mirage_Earth_Radius = 0;");
    // The model of the sounding keeps |n - eta| <= 1e-10 at every height: ray directions
    // within pi sqrt(1e-10) = 31 urad of the exponential's, under the 1-pixel tolerance
    // (145 urad at 160x120).
    SceneLoadOptions lo = scene_load_options(sounding.string(), 160, 120, {});
    auto loaded = load_mirage_scene(lo);
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    auto atm = scene_atmosphere(loaded->settings, 1.45e-4);
    ASSERT_TRUE(atm.ok()) << atm.message();
    double worst = 0.0;
    for (int k = 0; k <= 20000; ++k) {
        const double y = 12.0 * k / 20000.0;
        worst = std::max(worst, std::abs(atm->n(y) - eta(*hot, y)));
    }
    EXPECT_LT(worst, 1e-10);

    auto general = trace(sounding, 160, 120);
    ASSERT_TRUE(general.ok()) << general.message();
    EXPECT_GT(general->model_pieces, 0);
    auto closed = trace(scene_path("road"), 160, 120);
    ASSERT_TRUE(closed.ok()) << closed.message();
    auto straight = trace(scene_path("road"), 160, 120, 0, false);
    ASSERT_TRUE(straight.ok()) << straight.message();
    // Both renders keep the tolerance of the exact paths, which differ by less than it: the
    // pixels differ only where a ray passes within the tolerance of an edge.
    const double same_air = differing_share(general->render.image, closed->render.image);
    const double no_air = differing_share(straight->render.image, closed->render.image);
    std::printf(
        "pixels differing from the closed forms' render: %.3f %% (straight rays: %.1f %%); "
        "|n_model - eta| <= %.2g\n",
        100.0 * same_air, 100.0 * no_air, worst);
    EXPECT_LT(same_air, 0.01) << "no atmosphere differs in " << no_air;
    EXPECT_GT(no_air, 0.05);  // the mirage is no small part of the image
}

TEST_F(RealAirTrace, RaysTrappedInADuctFollowTheExactPathThroughEveryTurn) {
    // Young's 2 K inversion between 50 and 60 m over the standard lapse, on the curved Earth.
    AirSpec spec;
    spec.column.ground_temperature_k = 288.15;
    spec.column.lapse_k_per_m = 6.5e-3;
    spec.column.inversions.push_back({50.0, 60.0, 2.0, 0.85});
    spec.index.formula = IndexFormula::Ciddor;
    spec.earth_radius_m = 6371000.0;
    FitSettings fs;
    fs.tolerance_n = 1e-12;
    auto q = fit_air(spec, fs);
    ASSERT_TRUE(q.ok()) << q.message();
    CurvedSettings cs;
    cs.atmosphere = Atmosphere::quadratic(*q);
    cs.tolerance_rad = 2e-6;
    cs.max_dz = 60000.0;
    const glm::dvec3 eye(0.0, 54.0, 0.0);
    cs.eye = eye;
    for (const double elev : {0.0, 0.01, -0.02}) {  // degrees
        const double e = elev * M_PI / 180.0;
        const glm::dvec3 dir(0.0, std::sin(e), std::cos(e));
        const auto cp = curved_path(cs, eye, dir, 0.0);
        ASSERT_TRUE(cp && cp->exact) << elev;
        const ExactPath& exact = *cp->exact;
        ASSERT_EQ(exact.fate(), PathFate::Ducted) << elev;
        int turns = 0;
        for (int k = 0; exact.turning_point(k).dz < 60000.0; ++k) ++turns;
        EXPECT_GE(turns, 3) << elev;
        EXPECT_EQ(cp->path.end, PathEnd::Cut);
        EXPECT_DOUBLE_EQ(cp->path.points.back().x, 60000.0);
        // The polyline keeps the tolerance everywhere (no scene: nothing is coarse).
        SampleSettings st;
        st.tolerance_rad = cs.tolerance_rad;
        double worst = 0.0;
        for (int k = 1; k <= 6000; ++k) {
            const double dz = 10.0 * k;
            const double y = exact.height_at(dz);
            worst = std::max(worst, std::abs(polyline_height(cp->path, dz) - y) /
                                        allowed_error(exact, st, dz, y));
        }
        EXPECT_LE(worst, 1.0) << elev;
        EXPECT_GT(worst, 0.05) << elev;  // sampled to the tolerance, not far finer
    }

    // Through a scene: a wall 40 km away is met where the exact path meets it.
    std::ofstream(dir_ / "wall.pov") << "box { <-500, 0, 40000>, <500, 200, 40010> }\n";
    auto scene = parse_scene_file((dir_ / "wall.pov").string(), ParseOptions{});
    ASSERT_TRUE(scene.ok()) << scene.message();
    auto accel = SceneAccel::build(*scene);
    ASSERT_TRUE(accel.ok()) << accel.message();
    const CurvedPropagator propagator(cs);
    for (const double elev : {0.0, 0.01, -0.02}) {
        const double e = elev * M_PI / 180.0;
        RayStart start;
        start.origin = eye;
        start.direction = glm::dvec3(0.0, std::sin(e), std::cos(e));
        const PathHit hit = propagator.propagate(*accel, start);
        ASSERT_TRUE(hit.hit) << elev;
        auto exact = ExactPath::make(cs.atmosphere, 54.0, M_PI / 2 - e);
        ASSERT_TRUE(exact.ok());
        const double y = exact->height_at(40000.0);
        EXPECT_NEAR(hit.surface.point.y, y, cs.tolerance_rad * 40000.0 * 1.01) << elev;
        EXPECT_NEAR(hit.surface.point.z, 40000.0, 1e-6);
    }
}

TEST_F(RealAirTrace, TheSameBytesAtAnyThreadCount) {
    std::ofstream(dir_ / "road.csv") << "height_m,temperature_c\n0,60\n0.05,48\n0.2,38\n0.5,"
                                        "33\n1,31\n2,30.2\n5,30\n";
    const fs::path scene = edited("road", "#declare Mirage_Preset    = \"hot-road\";",
                                  "#declare Mirage_Sounding = \"road.csv\";");
    auto one = trace(scene, 96, 72, 1);
    ASSERT_TRUE(one.ok()) << one.message();
    EXPECT_NE(one->atmosphere.find("sounding road.csv"), std::string::npos) << one->atmosphere;
    for (int threads : {2, 3}) {
        auto many = trace(scene, 96, 72, threads);
        ASSERT_TRUE(many.ok()) << many.message();
        ASSERT_EQ(many->render.image.pixels.size(), one->render.image.pixels.size());
        EXPECT_EQ(std::memcmp(many->render.image.pixels.data(), one->render.image.pixels.data(),
                              one->render.image.pixels.size() * sizeof(float)),
                  0)
            << threads;
    }
    // Not the image without the air.
    auto none = trace(scene, 96, 72, 1, false);
    ASSERT_TRUE(none.ok());
    EXPECT_GT(differing_share(one->render.image, none->render.image), 0.02);
}

}  // namespace
}  // namespace mirage
