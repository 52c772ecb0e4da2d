#include "atmosphere/quadratic_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "air_fixtures.h"
#include "atmosphere/exact_path.h"
#include "atmosphere/quadratic_path.h"

namespace mirage {
namespace {

// A random C^0 model with corners, for the range queries.
QuadraticProfile random_model(std::mt19937_64& rng, int pieces) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> y{0.0}, b, c;
    for (int j = 0; j < pieces; ++j) {
        y.push_back(y.back() + 0.01 + unit(rng));
        b.push_back(1e-4 * (unit(rng) - 0.5));
        c.push_back(1e-4 * (unit(rng) - 0.5));
    }
    return *QuadraticProfile::make(y, b, c, 1.0006, 0.0);
}

TEST(QuadraticProfile, RangeQueriesAgreeWithADenseScan) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const QuadraticProfile p = random_model(rng, 300);
    for (int trial = 0; trial < 300; ++trial) {
        double a = p.top() * 1.05 * unit(rng), b = p.top() * 1.05 * unit(rng);
        if (a > b) std::swap(a, b);
        double slope_max = 0.0, lo = 1e300, hi = -1e300;
        for (int k = 0; k <= 4000; ++k) {
            const double y = a + (b - a) * k / 4000.0;
            slope_max = std::max(slope_max, std::fabs(p.slope(y)));
            lo = std::min(lo, p.n_sq(y));
            hi = std::max(hi, p.n_sq(y));
        }
        const double got = p.max_abs_slope(a, b);
        // The bound may exceed the scan (both sides of a corner count) but never falls short.
        EXPECT_GE(got, slope_max * (1.0 - 1e-12));
        EXPECT_LE(got, slope_max + 2e-4 * (b - a) / 4000.0 + 1e-4);
        double rlo, rhi;
        p.n_sq_range(a, b, rlo, rhi);
        EXPECT_LE(rlo, lo + 1e-15);
        EXPECT_GE(rhi, hi - 1e-15);
        // ... and the scan misses at most one step's change.
        const double step_change = slope_max * (b - a) / 4000.0;
        EXPECT_GE(rlo, lo - step_change - 1e-15);
        EXPECT_LE(rhi, hi + step_change + 1e-15);
    }
    // find_piece_reaching against a linear search.
    for (int trial = 0; trial < 500; ++trial) {
        const int j = static_cast<int>(unit(rng) * p.piece_count());
        const int dir = unit(rng) < 0.5 ? -1 : 1;
        const double level = p.e(j) + 1e-3 * (unit(rng) - 0.7);
        int expect = dir > 0 ? p.piece_count() : -1;
        for (int k = j; k >= 0 && k < p.piece_count(); k += dir) {
            double l, h;
            p.excess_range(p.knot(k), p.knot(k + 1), l, h);
            if (l <= level) {
                expect = k;
                break;
            }
        }
        EXPECT_EQ(p.find_piece_reaching(j, dir, level), expect) << j << " " << dir;
    }
}

TEST(QuadraticProfile, BadModelsAreRefused) {
    EXPECT_EQ(QuadraticProfile::make({0.0, 1.0, 1.0}, {0, 0}, {0, 0}, 1.0, 0.0).message(),
              "knots of a quadratic profile must increase: 1 m then 1 m");
    EXPECT_EQ(QuadraticProfile::make({0.5, 1.0}, {0}, {0}, 1.0, 0.0).message(),
              "the first knot of a quadratic profile must be at 0 m");
    EXPECT_EQ(QuadraticProfile::make({0.0, 1.0}, {0}, {-2.0}, 1.0, 0.0).message(),
              "the quadratic profile's n^2 falls to -1: it must stay positive");
    EXPECT_EQ(QuadraticProfile::make({0.0, 1.0}, {0}, {NAN}, 1.0, 0.0).message(),
              "piece 0 of a quadratic profile is not finite");
}

struct Form {
    const char* name;
    AirSpec spec;
};

std::vector<Form> forms() {
    std::vector<Form> f;
    f.push_back({"paper exponential", testing::exponential_spec("paper")});
    f.push_back({"hot road", testing::hot_road_spec()});
    f.push_back({"road duct", testing::road_duct_spec()});
    f.push_back({"young zigzag", testing::young_spec(0.0)});
    f.push_back({"young smooth", testing::young_spec(0.85)});
    AirSpec sea;
    sea.column.ground_temperature_k = 278.15;
    sea.column.lapse_k_per_m = 0.0065;
    sea.column.layers.push_back({-8.0, 4.0});
    sea.index.formula = IndexFormula::Ciddor;
    sea.relative_humidity = 0.8;
    sea.earth_radius_m = 6371000.0;
    f.push_back({"cold sea, Ciddor, humid, curved", sea});
    AirSpec snd;
    snd.source = AirSpec::Source::Sounding;
    snd.sounding = *parse_sounding(
        "height_m,temperature_c,relative_humidity\n0,8,90\n0.3,9.5,88\n0.8,11,85\n1.5,12.2,82\n"
        "3,13,80\n6,13.4,78\n10,13.2,75\n25,12.9,70\n50,12.7,70\n",
        "t.csv");
    snd.index.formula = IndexFormula::Ciddor;
    f.push_back({"temperature sounding", snd});
    return f;
}

// The fit's stated bound: |n_fit - n| <= tolerance at every height (checked at 100000 random
// heights and at every knot and piece middle), and with it the bound on ray directions: rays
// from one start through the fitted and the true profile have, at every height, directions
// within pi sqrt(eps) of each other (|cos a - cos b| <= 2 eps from n cos(e) = beta, and
// |cos a - cos b| >= 2 (|a - b| / pi)^2 on [0, pi/2]).
TEST(QuadraticProfile, FitKeepsItsBoundOnTheIndexAndOnRayDirections) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& form : forms()) {
        for (double tol : {1e-10, 1e-12}) {
            FitSettings fs;
            fs.tolerance_n = tol;
            FitReport report;
            auto fit = fit_air(form.spec, fs, &report);
            ASSERT_TRUE(fit.ok()) << form.name << ": " << fit.message();
            const QuadraticProfile& q = **fit;
            auto model = make_air_model(form.spec);
            ASSERT_TRUE(model.ok());
            const ProfileFunction f = form.spec.earth_radius_m > 0.0
                                          ? flatten(model->physical, form.spec.earth_radius_m,
                                                    form.spec.earth_extension_m)
                                          : model->physical;
            auto n_true = [&](double y) {
                return std::sqrt(f.n0_sq + f.excess(std::min(y, f.top)));
            };
            double worst = 0.0;
            auto check = [&](double y) {
                const double err = std::fabs(q.n(y) - n_true(y));
                worst = std::max(worst, err);
                EXPECT_LE(err, tol) << form.name << " tol " << tol << " at " << y << " m";
            };
            for (int k = 0; k < 100000; ++k) check(q.top() * unit(rng) * unit(rng));
            for (int j = 0; j < q.piece_count(); ++j) {
                check(q.knot(j));
                check(0.5 * (q.knot(j) + q.knot(j + 1)));
            }
            EXPECT_LE(report.max_error_n, tol) << form.name;
            EXPECT_GT(worst, 0.05 * tol) << form.name << ": the fit is much finer than asked";
            // Directions.
            double worst_angle = 0.0;
            for (int k = 0; k < 20000; ++k) {
                const double y0 = q.top() * 0.2 * unit(rng) * unit(rng);
                const double sin_i = std::cos(0.05 * unit(rng));
                const double y = q.top() * 0.2 * unit(rng) * unit(rng);
                const double cf = q.n(y0) * sin_i / q.n(y), ct = n_true(y0) * sin_i / n_true(y);
                if (cf >= 1.0 || ct >= 1.0) continue;
                const double d = std::fabs(std::acos(cf) - std::acos(ct));
                worst_angle = std::max(worst_angle, d);
                EXPECT_LE(d, M_PI * std::sqrt(tol)) << form.name;
            }
            EXPECT_GT(worst_angle, 0.0) << form.name;
        }
    }
}

// The coarse spans (FitSettings::coarse_spans): each keeps its stated error against the true
// profile (checked at 200 heights a span), and a ray it admits (beta^2 <= max_beta_sq, beta from
// the fine model at the start) has, at every height of the span, a direction within the fine
// model's bound pi sqrt(eps) of the true ray's.  The rays are taken at the edge of admission, so
// the check can fail: spans allowed 30 times the bound (FitSettings::span_allowance) admit rays
// that break it.
TEST(QuadraticProfile, SpansKeepTheirErrorAndTheirRaysTheFineBound) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& form : forms()) {
        const double tol = 1e-10;
        auto model = make_air_model(form.spec);
        ASSERT_TRUE(model.ok());
        const ProfileFunction f =
            form.spec.earth_radius_m > 0.0
                ? flatten(model->physical, form.spec.earth_radius_m, form.spec.earth_extension_m)
                : model->physical;
        auto n_true = [&](double y) { return std::sqrt(f.n0_sq + f.excess(std::min(y, f.top))); };
        // The largest direction error of admitted rays at the edge of admission, over every span.
        auto worst_admitted = [&](const QuadraticProfile& q, bool check_error) {
            double worst = 0.0;
            for (const CoarseSpan& sp : q.spans()) {
                const double a = q.knot(sp.lo), h = q.knot(sp.hi) - a;
                auto n_span = [&](double y) {
                    const double u = y - a;
                    return std::sqrt(q.n0_sq() + q.e(sp.lo) + (sp.b + sp.c * u) * u);
                };
                if (check_error) {
                    for (int k = 0; k <= 200; ++k) {
                        const double y = a + h * k / 200.0;
                        EXPECT_LE(std::fabs(n_span(y) - n_true(y)), sp.error_n)
                            << form.name << " span " << sp.lo << "-" << sp.hi << " at " << y;
                    }
                }
                for (int k = 0; k < 20; ++k) {
                    const double y0 = q.top() * 0.2 * unit(rng) * unit(rng);
                    const double beta = std::sqrt(sp.max_beta_sq * (1.0 - 1e-9 * unit(rng)));
                    const double sin_i = beta / q.n(y0);
                    if (!(sin_i < 1.0)) continue;
                    const double y = a + h * unit(rng);
                    const double cf = beta / n_span(y), ct = n_true(y0) * sin_i / n_true(y);
                    if (!(cf < 1.0 && ct < 1.0)) continue;
                    worst = std::max(worst, std::fabs(std::acos(cf) - std::acos(ct)));
                }
            }
            return worst;
        };
        auto q = testing::fit_or_die(form.spec, tol, true);
        ASSERT_TRUE(q);
        ASSERT_TRUE(q->has_spans()) << form.name;
        const double worst = worst_admitted(*q, true);
        EXPECT_LE(worst, M_PI * std::sqrt(tol)) << form.name;
        EXPECT_GT(worst, 0.0) << form.name;
        auto loose = testing::fit_or_die(form.spec, tol, true, 30.0);
        ASSERT_TRUE(loose);
        EXPECT_GT(worst_admitted(*loose, false), M_PI * std::sqrt(tol)) << form.name;
    }
}

// A model in other units (scene units of 1 cm) carries its spans with it: the same rays, the
// same spans crossed, heights the same to rounding.
TEST(QuadraticProfile, RescaledModelKeepsItsSpans) {
    auto q = testing::fit_or_die(testing::hot_road_spec(), 1e-10, true);
    ASSERT_TRUE(q && q->has_spans());
    auto cm = q->rescaled(0.01);
    ASSERT_TRUE(cm.ok()) << cm.message();
    ASSERT_EQ(cm->spans().size(), q->spans().size());
    int crossed = 0;
    for (double elev : {-0.006, -0.003, -0.001, 0.0005, 0.002, 0.006, 0.02}) {
        auto m = QuadraticPath::make(*q, 1.5, M_PI / 2 - elev);
        auto c = QuadraticPath::make(*cm, 150.0, M_PI / 2 - elev);
        ASSERT_TRUE(m.ok() && c.ok());
        EXPECT_EQ(m->fate(), c->fate()) << elev;
        for (double dz : {50.0, 200.0, 600.0, 1500.0}) {
            const double ym = m->height_at(dz), yc = c->height_at(100.0 * dz) / 100.0;
            EXPECT_NEAR(ym, yc, 1e-9 * (1.0 + std::fabs(ym))) << elev << " at " << dz;
        }
        EXPECT_EQ(m->spans_crossed(), c->spans_crossed()) << elev;
        crossed += m->spans_crossed();
    }
    EXPECT_GT(crossed, 0);
}

TEST(QuadraticProfile, FitRefusesWhatItCannotFollow) {
    AirSpec spec = testing::hot_road_spec();
    FitSettings fs;
    fs.tolerance_n = 1e-18;  // below binary64 on n itself
    fs.min_interval = 1e-3;
    auto q = fit_air(spec, fs);
    ASSERT_FALSE(q.ok());
    EXPECT_NE(q.message().find("to be fitted within 1e-18 in n"), std::string::npos) << q.message();
}

}  // namespace
}  // namespace mirage
