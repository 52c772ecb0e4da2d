// The path command's engine at its own interface: one driver, whose numbers are the closed
// forms' for an exponential profile and the general engine's for any other air, and whose
// errors come back as Results naming the bad value.
#include "paths/path_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "atmosphere/exact_ray.h"
#include "atmosphere/general_profile.h"
#include "atmosphere/path_sampler.h"
#include "atmosphere/quadratic_path.h"
#include "atmosphere/sampler.h"
#include "atmosphere/vanishing.h"

namespace mirage {
namespace {

constexpr double kPi = 3.14159265358979323846;

PathOptions ray_options(double eye_height, double elevation_deg) {
    PathOptions o;
    o.eye_height = eye_height;
    o.elevation_deg = elevation_deg;
    o.json = true;
    return o;
}

// run_path's JSON report (the test fails when it returns an error).
nlohmann::json report_json(const PathOptions& o) {
    std::ostringstream out;
    const Status s = run_path(o, out);
    EXPECT_TRUE(s.ok()) << s.message();
    return s.ok() ? nlohmann::json::parse(out.str()) : nlohmann::json();
}

SampleSettings sampling(const PathOptions& o) {
    SampleSettings st;
    st.tolerance_rad = o.tolerance_rad;
    st.tolerance_m = o.tolerance_m;
    st.max_dz = o.max_distance;
    return st;
}

void expect_samples(const nlohmann::json& j, const std::vector<glm::dvec2>& points) {
    ASSERT_EQ(j["samples"].size(), points.size());
    for (size_t k = 0; k < points.size(); ++k) {
        EXPECT_EQ(j["samples"][k][0].get<double>(), points[k].x) << k;
        EXPECT_EQ(j["samples"][k][1].get<double>(), points[k].y) << k;
    }
}

TEST(PathReport, AnExponentialProfileAloneGivesTheClosedFormsNumbers) {
    for (const double elevation : {-10.0, -45.0, 2.0}) {
        PathOptions o = ray_options(1.5, elevation);
        o.air.preset = "paper";
        const nlohmann::json j = report_json(o);
        const double i = kPi / 2 - elevation * kPi / 180;
        auto ray = make_exact_ray(*preset_profile("paper"), 1.5, i);
        ASSERT_TRUE(ray.ok());
        EXPECT_EQ(j["profile"]["kind"], "inferior");
        EXPECT_EQ(j["beta"].get<double>(), ray->beta);
        EXPECT_EQ(j["eta_eye"].get<double>(), ray->eta_p);
        EXPECT_EQ(j["k2"].get<double>(), ray->k2);
        EXPECT_EQ(j["ray_class"], ray_class_name(ray->ray_class));
        EXPECT_EQ(j["turn_kind"], turn_kind_name(ray->turn_kind));
        EXPECT_EQ(j["hits_ground"].get<bool>(), ray->hits_ground);
        if (ray->hits_ground) {
            EXPECT_EQ(j["dz_ground"].get<double>(), ray->dz_ground);
        }
        EXPECT_FALSE(j.contains("engine"));
        // The closed forms' own sampler (sampler.h), not the general one, gives the same points.
        expect_samples(j, sample_path(*ray, sampling(o)).points);
    }
}

TEST(PathReport, TheSameProfileInTheGeneralFormIsTheSamePath) {
    PathOptions o = ray_options(1.5, -0.2);
    o.air.preset = "hot-road";
    const nlohmann::json reference = report_json(o);
    o.ducts = true;  // the general form, the closed forms kept
    const nlohmann::json general = report_json(o);
    EXPECT_EQ(general["engine"], "general");
    EXPECT_FALSE(general.contains("k2"));
    EXPECT_TRUE(reference.contains("k2"));
    EXPECT_EQ(general["profile"]["legend"].back(), "closed forms");
    for (const char* key : {"beta", "eta_eye", "ray_class", "hits_ground", "dz_ground", "samples",
                            "end", "end_slope"})
        EXPECT_EQ(general[key], reference[key]) << key;
    ASSERT_EQ(general["turning_points"].size(), 1u);
    EXPECT_EQ(general["turning_points"][0]["dz"], reference["dz_turn"]);
    EXPECT_EQ(general["turning_points"][0]["y"], reference["y_turn"]);
}

TEST(PathReport, RealAirGivesTheGeneralEnginesPathAboveTheSphere) {
    // Hot ground under a lapse, on the curved Earth: the model fitted by hand here.
    PathOptions o = ray_options(1.5, -0.2);
    o.air.air_temperature_c = 30.0;
    o.air.surface_layers = {"12,0.4"};
    o.air.top = 100.0;
    o.air.earth_radius = 6371000.0;
    const nlohmann::json j = report_json(o);

    AirSpec spec;
    spec.column.ground_temperature_k = 303.15;
    spec.column.layers = {{12.0, 0.4}};
    spec.top_m = 100.0;
    spec.earth_radius_m = 6371000.0;
    auto q = fit_air(spec, FitSettings{});
    ASSERT_TRUE(q.ok()) << q.message();
    const Atmosphere atm = Atmosphere::quadratic(*q);
    const double R = spec.earth_radius_m;
    const double i = kPi / 2 + 0.2 * kPi / 180;
    auto path = ExactPath::make(atm, flattened_height(1.5, R), i);
    ASSERT_TRUE(path.ok());
    ASSERT_TRUE(path->quadratic() != nullptr);
    EXPECT_EQ(j["engine"], "general");
    EXPECT_EQ(j["beta"].get<double>(), path->beta());
    EXPECT_EQ(j["ray_class"], path->class_name());
    ASSERT_EQ(j["turning_points"].size(), 1u);  // the mirage's ray turns above the road
    EXPECT_EQ(j["turning_points"][0]["dz"].get<double>(), path->turning_point(0).dz);
    EXPECT_EQ(j["turning_points"][0]["y"].get<double>(),
              height_above_sphere(path->turning_point(0).y, R));
    // The samples: the general sampler's, their heights above the sphere.
    SampledPath s = sample_exact_path(*path, sampling(o));
    for (auto& p : s.points) p.y = height_above_sphere(p.y, R);
    expect_samples(j, s.points);
}

TEST(PathReport, TheTextReportShowsEachFormsOwnLines) {
    PathOptions o = ray_options(1.5, -10.0);
    o.json = false;
    o.air.preset = "paper";
    std::ostringstream reference, general;
    ASSERT_TRUE(run_path(o, reference).ok());
    o.air.general = true;
    ASSERT_TRUE(run_path(o, general).ok());
    EXPECT_EQ(reference.str().rfind(
                  "profile     paper (inferior): eta0 = 1.000233, eta1 = 0.4584, alpha = 2.303 /m\n"
                  "eye         y0 = 1.5 m, elevation -10 deg (i = 1.7453292519943295 rad)\n"
                  "invariant   beta = eta(y0) sin i = ",
                  0),
              0u)
        << reference.str();
    EXPECT_NE(reference.str().find("(ahead)\n"), std::string::npos);
    EXPECT_EQ(general.str().rfind("profile     paper (inferior)\n"
                                  "            exponential n^2, eta0 = 1.000233, eta1 = 0.4584, "
                                  "alpha = 2.303 /m\n"
                                  "            fitted: ",
                                  0),
              0u)
        << general.str();
    EXPECT_NE(general.str().find("invariant   beta = n(y0) sin i = "), std::string::npos);
}

TEST(PathReport, ErrorsComeBackNamingTheBadValueAndPrintNothing) {
    auto error_of = [](const PathOptions& o) {
        std::ostringstream out;
        const Status s = run_path(o, out);
        EXPECT_EQ(out.str(), "");
        return s.ok() ? std::string("(no error)") : s.message();
    };
    PathOptions o = ray_options(0.0, 1.0);
    o.air.preset = "paper";
    EXPECT_EQ(error_of(o),
              "--eye-height 0: the eye must be above the ground (> 0 m) and at most 1e+09 m");
    o.eye_height = 1.0;
    o.tolerance_rad = 1e-12;
    EXPECT_EQ(error_of(o), "--tolerance 1e-12: must be 0 or from 1e-10 to 1 rad");
    o.tolerance_rad = 1e-3;
    o.air.preset = "sahara";
    EXPECT_EQ(error_of(o),
              "--preset: unknown preset 'sahara' (known: paper, paper-superior, hot-road, "
              "cold-sea)");
    o.air.preset.clear();
    o.air.inversions = {"50,60"};
    EXPECT_EQ(error_of(o), "--inversion 50,60: expected BOTTOM_M,TOP_M,DT_K[,SMOOTHING_M]");
    o.air.inversions = {"50,60,2"};
    o.air.fit_tolerance = 0.0;
    EXPECT_EQ(error_of(o), "--fit-tolerance 0: must be > 0");
    o.air.fit_tolerance = 1e-10;
    o.png = "x.png";
    EXPECT_EQ(error_of(o), "--png draws the transfer diagram: give --transfer DIST");
    o.png.clear();
    o.object_distance = 5.0;
    EXPECT_EQ(error_of(o), "--object-distance needs the point's height: --object-height M");
}

TEST(PathReport, TheVanishingOfAPointIsTheSameInBothForms) {
    PathOptions o;
    o.air.preset = "hot-road";
    o.eye_height = 1.7;
    o.object_height = 2.5;
    o.json = true;
    const nlohmann::json reference = report_json(o);
    auto reach = mirror_reach(*preset_profile("hot-road"), 1.7, 2.5);
    ASSERT_TRUE(reach.ok());
    EXPECT_EQ(reference["nearest_eye_distance"].get<double>(), reach->nearest);
    EXPECT_EQ(reference["farthest_eye_distance"].get<double>(), reach->farthest);
    EXPECT_EQ(reference["profile"]["kind"], "inferior");
    o.ducts = true;
    const nlohmann::json general = report_json(o);
    EXPECT_EQ(general["air"]["label"], "hot-road (inferior)");
    EXPECT_EQ(general["nearest_eye_distance"], reference["nearest_eye_distance"]);
}

}  // namespace
}  // namespace mirage
