// The general engine against independent high-precision integration of the ray equation
// (tests/data/general_paths.csv, written by tools/gen_general_paths.py at 32 digits from the
// profiles' definitions in tests/data/general_profiles.json).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "air_fixtures.h"
#include "util/csv.h"

namespace mirage {
namespace {

// The model's n^2 and beta^2 differ from the reference's by at most eps/2 each:
// * soundings of n on flat ground are their own model (the spline of n^2), off only by the rows'
//   n rounded to doubles: eps = 1e-15;
// * every other profile is fitted to |dn| <= 1e-13: eps = 4e-13.
// Then n cos(e) = beta keeps the directions at every height within sqrt(eps) of the reference
// (quadratic_profile_test), and to first order the outputs within:
//   slopes                           sqrt(eps)
//   heights at distance d            d sqrt(eps)
//   a turning height                 eps / |(n^2)'| there (where n^2 = beta^2 moves to)
//   a turning point's distance       sqrt(eps) / |y''| there (where the slope crosses 0)
//   a half period                    the sum of its two turning points'
//   the ground hit                   d sqrt(eps) / |slope| there
// each with a margin of 4 and a floor of 1e-12 (the binary64 accuracy of the closed forms
// themselves is checked against the ray equation of the model in quadratic_path_test).  The
// fate and the number of turning points must agree exactly.
TEST(GeneralPaths, MatchTheHighPrecisionIntegrationOfEveryProfileForm) {
    const auto profiles = testing::load_general_profiles();
    auto table = read_csv_file(std::string(MIRAGE_REFERENCE_DIR) + "/general_paths.csv");
    ASSERT_TRUE(table.ok()) << table.message();
    auto col = [&](const CsvRow& r, const char* c) { return r.fields[table->column(c)]; };
    auto num = [&](const CsvRow& r, const std::string& c) {
        const std::string s = r.fields[table->column(c)];
        return s == "nan" ? NAN : std::stod(s);
    };
    std::map<std::string, std::shared_ptr<const QuadraticProfile>> fits;
    std::map<std::string, int> fates;
    int rows = 0, ducted_after_six_turns = 0;
    constexpr double kMargin = 4.0, kFloor = 1e-12;
    for (const auto& r : table->rows) {
        const std::string name = col(r, "profile"), id = col(r, "case_id");
        const auto& pj = profiles.at(name);
        const bool exact = pj.at("kind") == "n_sounding" && !pj.contains("earth_radius_m");
        if (!fits.count(name)) fits[name] = testing::fit_or_die(testing::spec_from_json(pj), 1e-13);
        const auto& q = fits[name];
        ASSERT_TRUE(q) << name;
        const Atmosphere atm = Atmosphere::quadratic(q);
        auto path = ExactPath::make(atm, num(r, "y0"), num(r, "i_rad"));
        ASSERT_TRUE(path.ok()) << id << ": " << path.message();
        ++rows;
        const std::string fate = col(r, "fate");
        ++fates[fate];
        ASSERT_EQ(path->class_name(), fate) << id;
        ASSERT_EQ(std::to_string(path->turning_point_count()), col(r, "turns")) << id;

        const double eps = exact ? 1e-15 : 4e-13, root = std::sqrt(eps);
        auto tol = [&](double first_order) { return kFloor + kMargin * first_order; };
        auto curvature = [&](double y) { return path->curvature_bound(y, y); };
        if (path->turning_point_count() != 0) {
            const TurningPoint t = path->turning_point(0);
            EXPECT_NEAR(t.y, num(r, "y_turn1"), tol(eps / std::fabs(q->slope(t.y)))) << id;
            EXPECT_NEAR(t.dz, num(r, "dz_turn1"), tol(root / curvature(t.y))) << id;
        }
        if (path->turning_point_count() < 0) {
            const TurningPoint t0 = path->turning_point(0), t1 = path->turning_point(1);
            EXPECT_NEAR(t1.y, num(r, "y_turn2"), tol(eps / std::fabs(q->slope(t1.y)))) << id;
            EXPECT_NEAR(t1.dz - t0.dz, num(r, "half_period"),
                        tol(root / curvature(t0.y) + root / curvature(t1.y)))
                << id << " half period";
        }
        if (path->hits_ground()) {
            const double d = path->dz_ground();
            EXPECT_NEAR(d, num(r, "dz_ground"), tol(d * root / std::fabs(path->slope_at(d))))
                << id << " ground hit";
        }
        for (int k = 1; k <= 4; ++k) {
            const std::string n = std::to_string(k);
            const double d = num(r, "d" + n);
            if (std::isnan(d)) continue;
            EXPECT_NEAR(path->height_at(d), num(r, "y_d" + n), tol(d * root))
                << id << " height at d" << n;
            EXPECT_NEAR(path->slope_at(d), num(r, "dydz_d" + n), tol(root))
                << id << " slope at d" << n;
            if (fate == "ducted" && k == 4) ++ducted_after_six_turns;
        }
    }
    EXPECT_GE(rows, 180);
    EXPECT_GE(fates["ducted"], 40);
    EXPECT_GE(fates["ground"], 30);
    EXPECT_GE(fates["escape"], 40);
    EXPECT_GE(ducted_after_six_turns, 40);
}

}  // namespace
}  // namespace mirage
