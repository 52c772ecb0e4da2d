// The general engine against independent high-precision integration of the ray equation
// (tests/data/general_paths.csv, written by tools/gen_general_paths.py at 32 digits from the
// profiles' definitions in tests/data/general_profiles.json).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "air_fixtures.h"
#include "util/csv.h"

namespace mirage {
namespace {

// One comparison of every reference ray against the engine: every profile fitted to |dn| <=
// fit_tolerance (soundings of n on flat ground are their own model), each output held to the
// first-order bound of a model within |dn| <= bound_tolerance (below).  Each failed check is a
// message; `largest` is each quantity's largest error as a share of its first-order bound.
struct Comparison {
    std::vector<std::string> failures;
    std::map<std::string, double> largest;
    std::map<std::string, int> fates;
    int rows = 0, ducted_after_six_turns = 0;
    int rows_with_spans = 0;  // rays that crossed a coarse span somewhere
};

// `spans`: the models fitted with their coarse spans (FitSettings::coarse_spans), a span allowed
// `span_allowance` of the fine model's bound on directions.
Comparison compare_with_reference(double fit_tolerance, double bound_tolerance, bool spans = false,
                                  double span_allowance = 1.0, double turn_margin = 4.0) {
    Comparison out;
    const auto profiles = testing::load_general_profiles();
    auto table = read_csv_file(std::string(MIRAGE_REFERENCE_DIR) + "/general_paths.csv");
    if (!table.ok()) {
        out.failures.push_back(table.message());
        return out;
    }
    auto col = [&](const CsvRow& r, const char* c) { return r.fields[table->column(c)]; };
    auto num = [&](const CsvRow& r, const std::string& c) {
        const std::string s = r.fields[table->column(c)];
        return s == "nan" ? NAN : std::stod(s);
    };
    std::map<std::string, std::shared_ptr<const QuadraticProfile>> fits;
    constexpr double kMargin = 4.0, kFloor = 1e-12;
    for (const auto& r : table->rows) {
        const std::string name = col(r, "profile"), id = col(r, "case_id");
        const auto& pj = profiles.at(name);
        const bool exact = pj.at("kind") == "n_sounding" && !pj.contains("earth_radius_m");
        if (!fits.count(name))
            fits[name] = testing::fit_or_die(testing::spec_from_json(pj), fit_tolerance, spans,
                                             span_allowance);
        const auto& q = fits[name];
        if (!q) {
            out.failures.push_back(name + ": not fitted");
            continue;
        }
        const Atmosphere atm = Atmosphere::quadratic(q);
        auto path = ExactPath::make(atm, num(r, "y0"), num(r, "i_rad"));
        if (!path.ok()) {
            out.failures.push_back(id + ": " + path.message());
            continue;
        }
        ++out.rows;
        const std::string fate = col(r, "fate");
        ++out.fates[fate];
        if (path->class_name() != fate ||
            std::to_string(path->turning_point_count()) != col(r, "turns")) {
            out.failures.push_back(id + ": " + path->class_name() + " with " +
                                   std::to_string(path->turning_point_count()) +
                                   " turning points, the reference " + fate + " with " +
                                   col(r, "turns"));
            continue;
        }

        const double eps = exact ? 1e-15 : 4.0 * bound_tolerance, root = std::sqrt(eps);
        auto curvature = [&](double y) { return path->curvature_bound(y, y); };
        auto check = [&](const std::string& what, double got, double want, double first_order) {
            const double err = std::fabs(got - want);
            double& share = out.largest[what];
            share = std::max(share, err / first_order);
            const bool turn = what == "distances to turning points" || what == "half periods";
            if (!(err <= kFloor + (turn ? turn_margin : kMargin) * first_order)) {
                std::ostringstream m;
                m.precision(17);
                m << id << " " << what << ": " << got << " against " << want << " (bound "
                  << kFloor + kMargin * first_order << ")";
                out.failures.push_back(m.str());
            }
        };
        if (path->turning_point_count() != 0) {
            const TurningPoint t = path->turning_point(0);
            check("turning heights", t.y, num(r, "y_turn1"), eps / std::fabs(q->slope(t.y)));
            check("distances to turning points", t.dz, num(r, "dz_turn1"), root / curvature(t.y));
        }
        if (path->turning_point_count() < 0) {  // trapped: turns for ever
            const TurningPoint t0 = path->turning_point(0), t1 = path->turning_point(1);
            check("turning heights", t1.y, num(r, "y_turn2"), eps / std::fabs(q->slope(t1.y)));
            check("half periods", t1.dz - t0.dz, num(r, "half_period"),
                  root / curvature(t0.y) + root / curvature(t1.y));
        }
        if (path->hits_ground()) {
            const double d = path->dz_ground();
            check("ground hits", d, num(r, "dz_ground"), d * root / std::fabs(path->slope_at(d)));
        }
        for (int k = 1; k <= 4; ++k) {
            const std::string n = std::to_string(k);
            const double d = num(r, "d" + n);
            if (std::isnan(d)) continue;
            check("heights at distance d", path->height_at(d), num(r, "y_d" + n), d * root);
            check("slopes", path->slope_at(d), num(r, "dydz_d" + n), root);
            if (fate == "ducted" && k == 4) ++out.ducted_after_six_turns;
        }
        if (path->quadratic() && path->quadratic()->spans_crossed() > 0) ++out.rows_with_spans;
    }
    return out;
}

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
// fate and the number of turning points must agree exactly.  The largest error of each quantity,
// as a share of its first-order bound, is printed (docs/atmospheres.md quotes it).
TEST(GeneralPaths, MatchTheHighPrecisionIntegrationOfEveryProfileForm) {
    const Comparison c = compare_with_reference(1e-13, 1e-13);
    for (const auto& f : c.failures) ADD_FAILURE() << f;
    EXPECT_GE(c.rows, 180);
    EXPECT_GE(c.fates.count("ducted") ? c.fates.at("ducted") : 0, 40);
    EXPECT_GE(c.fates.count("ground") ? c.fates.at("ground") : 0, 30);
    EXPECT_GE(c.fates.count("escape") ? c.fates.at("escape") : 0, 40);
    EXPECT_GE(c.ducted_after_six_turns, 40);
    std::printf("%d rays (%d escape, %d ground, %d ducted); largest error / first-order bound:\n",
                c.rows, c.fates.count("escape") ? c.fates.at("escape") : 0,
                c.fates.count("ground") ? c.fates.at("ground") : 0,
                c.fates.count("ducted") ? c.fates.at("ducted") : 0);
    for (const auto& [what, share] : c.largest) std::printf("  %-28s %.2g\n", what.c_str(), share);
}

// The comparison can fail: a model a thousand times coarser in n (|dn| <= 1e-10), held to the
// bounds of |dn| <= 1e-13, is caught by many checks; held to its own bounds it passes them.
TEST(GeneralPaths, ACoarserModelFailsTheFineModelsBounds) {
    const Comparison coarse = compare_with_reference(1e-10, 1e-13);
    EXPECT_GE(coarse.failures.size(), 50u);
    std::printf("fitted to 1e-10, held to the bounds of 1e-13: %zu failed checks\n",
                coarse.failures.size());
    const Comparison own = compare_with_reference(1e-10, 1e-10);
    for (const auto& f : own.failures) ADD_FAILURE() << f;
}

// Coarse spans (FitSettings::coarse_spans) change a ray's model only where its direction is
// steep enough to keep the fine model's bound on directions at every height, pi sqrt(eps): the
// rays that cross them keep the fine model's first-order bounds on heights, slopes, turning
// heights and ground hits (with its margin of 4), the same fates and turning points.  Distances
// along the path to a turning point are not held to the fine model's sqrt(eps) / |y''|: each
// span on the way changes dz/dy = 1 / tan e by up to pi sqrt(eps) / sin^2 e, and the spans
// toward a turning point, where sin^2 e grows with the height above it, add up to about
// (pi / 2) ln(the ratio of their heights above it) times that bound; they are held to 12 times
// it (3 times the margin).  The check can fail: spans allowed 1000 times the bound fail many.
TEST(GeneralPaths, CoarseSpansKeepTheFineModelsBounds) {
    const Comparison spans = compare_with_reference(1e-10, 1e-10, true, 1.0, 12.0);
    for (const auto& f : spans.failures) ADD_FAILURE() << f;
    EXPECT_GE(spans.rows, 180);
    EXPECT_GE(spans.rows_with_spans, spans.rows / 4);
    std::printf(
        "fitted to 1e-10 with coarse spans: %d of %d rays crossed spans; largest error / "
        "first-order bound:\n",
        spans.rows_with_spans, spans.rows);
    for (const auto& [what, share] : spans.largest)
        std::printf("  %-28s %.2g\n", what.c_str(), share);
    const Comparison loose = compare_with_reference(1e-10, 1e-10, true, 1000.0, 12.0);
    EXPECT_GE(loose.failures.size(), 10u);
    std::printf("spans allowed 1000 times the bound: %zu failed checks\n", loose.failures.size());
}

}  // namespace
}  // namespace mirage
