#include "atmosphere/exact_ray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "atmosphere/sampler.h"
#include "util/csv.h"

namespace mirage {
namespace {

struct RefCase {
    std::string id;
    Profile profile;
    double y0, i, d[3];
    double k2, k, y_turn, dz_turn;
    std::string turn_kind, ray_class;
    double y_d[3], dydz_d[3];
    bool hits_ground;
    double dz_ground, tol;
};

std::vector<RefCase> load(const std::string& path) {
    auto table = read_csv_file(path);
    EXPECT_TRUE(table.ok()) << (table.ok() ? "" : table.message());
    std::vector<RefCase> cases;
    if (!table) return cases;
    auto num = [&](const CsvRow& row, const char* name) {
        auto v = csv_number(*table, row, table->column(name));
        EXPECT_TRUE(v.ok()) << name;
        return v.ok() ? *v : NAN;
    };
    for (const auto& row : table->rows) {
        RefCase c;
        c.id = row.fields[table->column("case_id")];
        const auto kind = parse_profile_kind(row.fields[table->column("profile")]);
        c.profile = {*kind, num(row, "eta0"), num(row, "eta1"), num(row, "alpha")};
        c.y0 = num(row, "y0");
        c.i = num(row, "i_rad");
        c.k2 = num(row, "k2");
        c.k = num(row, "k");
        c.y_turn = num(row, "y_turn");
        c.dz_turn = num(row, "dz_turn");
        c.turn_kind = row.fields[table->column("turn_kind")];
        c.ray_class = row.fields[table->column("ray_class")];
        for (int j = 0; j < 3; ++j) {
            const std::string n = std::to_string(j + 1);
            c.d[j] = num(row, ("d" + n).c_str());
            c.y_d[j] = num(row, ("y_d" + n).c_str());
            c.dydz_d[j] = num(row, ("dydz_d" + n).c_str());
        }
        c.hits_ground = num(row, "hits_ground") != 0.0;
        c.dz_ground = num(row, "dz_ground");
        c.tol = num(row, "tol_rel");
        cases.push_back(c);
    }
    return cases;
}

// The reference's scoring rule: heights relative to max(y0, |ref|), the rest relative to
// |ref|; a NaN reference must be matched by "not defined".
void expect_close(const char* what, double got, double ref, double scale, double tol,
                  const std::string& id) {
    if (std::isnan(ref)) {
        EXPECT_TRUE(std::isnan(got) || std::isinf(got)) << id << " " << what << " = " << got;
        return;
    }
    const double err = std::fabs(got - ref) / scale;
    EXPECT_LE(err, tol) << id << " " << what << ": got " << got << ", reference " << ref;
}

void check_reference_file(const std::string& name, size_t expected_cases) {
    const auto cases = load(std::string(MIRAGE_REFERENCE_DIR) + "/" + name);
    ASSERT_EQ(cases.size(), expected_cases);
    for (const auto& c : cases) {
        auto ray = make_exact_ray(c.profile, c.y0, c.i);
        ASSERT_TRUE(ray.ok()) << c.id << ": " << ray.message();
        EXPECT_EQ(ray_class_name(ray->ray_class), c.ray_class) << c.id;
        EXPECT_EQ(turn_kind_name(ray->turn_kind), c.turn_kind) << c.id;
        EXPECT_EQ(ray->hits_ground, c.hits_ground) << c.id;
        expect_close("k2", ray->k2, c.k2, std::fabs(c.k2), c.tol, c.id);
        if (!std::isnan(c.k)) expect_close("k", ray->q, c.k, c.k, c.tol, c.id);
        const double y_turn = ray->y_turn;
        expect_close("y_turn", y_turn, c.y_turn, std::max(c.y0, std::fabs(c.y_turn)), c.tol, c.id);
        expect_close("dz_turn", ray->dz_turn, c.dz_turn, std::fabs(c.dz_turn), c.tol, c.id);
        if (c.hits_ground)
            expect_close("dz_ground", ray->dz_ground, c.dz_ground, c.dz_ground, c.tol, c.id);
        for (int j = 0; j < 3; ++j) {
            expect_close("y_d", height_at(*ray, c.d[j]), c.y_d[j],
                         std::max(c.y0, std::fabs(c.y_d[j])), c.tol,
                         c.id + " d" + std::to_string(j + 1));
            expect_close("dydz_d", slope_at(*ray, c.d[j]), c.dydz_d[j], std::fabs(c.dydz_d[j]),
                         c.tol, c.id + " d" + std::to_string(j + 1));
        }
    }
}

TEST(ExactRay, EveryReferenceCasePassesWithinItsTolerance) {
    check_reference_file("path_public.csv", 25);
}

// Stiff and extreme families beyond the public reference (tools/gen_extreme_paths.py: the
// literal closed forms at 110 digits): eta1 = 1e-6 and 1e-8, grazing at 1e-8 rad,
// alpha y0 = 2000, k^2 = 1 +/- 1e-12, k -> 0, kappa^2 = +/- 1e-8, rays from the ground.
TEST(ExactRay, ExtremeFamiliesPassAsAccuratelyAsTheirConditioningAllows) {
    check_reference_file("path_extreme.csv", 35);
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

struct Case {
    const char* preset;
    double y0, elev;
};

// A ray started at a point of another ray's path, in the direction of that path, is the same
// ray: the invariant and the closed forms agree wherever the second ray starts.
TEST(ExactRay, RayStartedOnAnotherRaysPathContinuesIt) {
    const Case cases[] = {{"paper", 1.5, -0.2},          {"paper", 1.5, 0.1},
                          {"hot-road", 1.5, -2e-3},      {"hot-road", 0.3, -1e-4},
                          {"paper-superior", 1.0, 0.05}, {"paper-superior", 1.0, -0.3},
                          {"cold-sea", 2.0, 1e-3},       {"cold-sea", 2.0, -5e-3}};
    for (const auto& c : cases) {
        auto a = make_exact_ray(*preset_profile(c.preset), c.y0, M_PI / 2 - c.elev);
        ASSERT_TRUE(a.ok());
        const double reach = a->hits_ground ? a->dz_ground : 4.0 / a->c;
        for (double f : {0.1, 0.35, 0.6}) {
            const double d = f * reach;
            const double y = height_at(*a, d);
            const double slope = slope_at(*a, d);
            auto b = make_exact_ray(*preset_profile(c.preset), y, M_PI / 2 - std::atan(slope));
            ASSERT_TRUE(b.ok()) << b.message();
            EXPECT_NEAR(b->beta, a->beta, 1e-13 * a->beta) << c.preset << " " << c.elev;
            EXPECT_EQ(b->hits_ground, a->hits_ground) << c.preset << " " << c.elev;
            if (a->hits_ground) {
                EXPECT_NEAR(b->dz_ground, a->dz_ground - d, 1e-9 * a->dz_ground);
            }
            for (double g : {0.05, 0.2, 0.35}) {
                const double e = g * reach;
                EXPECT_NEAR(height_at(*b, e), height_at(*a, d + e),
                            1e-10 * std::max(c.y0, std::fabs(height_at(*a, d + e))))
                    << c.preset << " " << c.elev << " from " << d << " at +" << e;
            }
        }
    }
}

TEST(ExactRay, PathIsSymmetricAboutItsTurningPoint) {
    const Case cases[] = {{"paper", 1.5, -0.2},
                          {"hot-road", 1.5, -3e-3},
                          {"paper-superior", 1.0, 0.05},
                          {"cold-sea", 2.0, 2e-3}};
    for (const auto& c : cases) {
        auto r = make_exact_ray(*preset_profile(c.preset), c.y0, M_PI / 2 - c.elev);
        ASSERT_TRUE(r.ok());
        ASSERT_EQ(r->turn_kind, TurnKind::Ahead) << c.preset;
        EXPECT_NEAR(height_at(*r, r->dz_turn), r->y_turn, 1e-13 * c.y0);
        EXPECT_NEAR(slope_at(*r, r->dz_turn), 0.0, 1e-9);
        for (double f : {0.1, 0.5, 0.9, 1.0}) {
            const double u = f * r->dz_turn;
            EXPECT_NEAR(height_at(*r, r->dz_turn - u), height_at(*r, r->dz_turn + u), 1e-12 * c.y0)
                << c.preset << " u = " << u;
            EXPECT_NEAR(slope_at(*r, r->dz_turn - u), -slope_at(*r, r->dz_turn + u),
                        1e-10 * std::fabs(slope_at(*r, r->dz_turn + u)))
                << c.preset << " u = " << u;
        }
    }
}

// Rays that just touch the ground: k^2 = 1 separates turning rays from ground hits; both
// sides stay finite and consistent.
TEST(ExactRay, RaysThatJustTouchTheGroundAreConsistent) {
    const Profile p = *preset_profile("paper");
    const double y0 = 1.5;
    const double eta_p = eta(p, y0);
    for (double k2 : {1.0 - 1e-12, 1.0 + 1e-12}) {
        const double cos_i = -std::sqrt(k2 - std::exp(-p.alpha * y0)) * p.eta1 / eta_p;
        auto r = make_exact_ray(p, y0, std::acos(cos_i));
        ASSERT_TRUE(r.ok());
        EXPECT_NEAR(r->k2, k2, 1e-14);
        EXPECT_NEAR(r->y_turn, 0.0, 1e-12);
        EXPECT_EQ(r->hits_ground, k2 > 1.0);
        EXPECT_TRUE(std::isfinite(r->dz_turn));
        if (r->hits_ground) {
            // It hits the ground very close to the vertex it never reaches.
            EXPECT_NEAR(r->dz_ground, r->dz_turn, 1e-5 * r->dz_turn);
            EXPECT_NEAR(height_at(*r, r->dz_ground), 0.0, 1e-12);
        } else {
            EXPECT_GT(height_at(*r, r->dz_turn), 0.0);
        }
    }
}

}  // namespace
}  // namespace mirage

namespace mirage {
namespace {

// distance_to_height inverts height_at on the stretch before any turning point, for every
// class (closed forms for the exponential classes, bisection for the rest).
TEST(ExactRay, DistanceToHeightInvertsTheHeight) {
    struct C {
        const char* preset;
        double y0, elev;
    };
    const C cases[] = {{"paper", 1.5, -0.2},          {"paper", 1.5, 0.2},
                       {"hot-road", 1.5, -0.003},     {"hot-road", 0.3, -0.2},
                       {"paper-superior", 1.5, 0.02}, {"paper-superior", 1.5, -0.05},
                       {"paper-superior", 1.5, 0.3},  {"cold-sea", 2.0, 0.001},
                       {"cold-sea", 2.0, -0.001},     {"cold-sea", 2.0, -0.01}};
    for (const auto& c : cases) {
        auto r = make_exact_ray(*preset_profile(c.preset), c.y0, M_PI / 2 - c.elev);
        ASSERT_TRUE(r.ok());
        const double reach = r->turn_kind == TurnKind::Ahead ? r->dz_turn
                             : r->hits_ground                ? r->dz_ground
                                                             : 10.0;
        for (double f : {0.1, 0.5, 0.9}) {
            const double dz = f * reach;
            EXPECT_NEAR(distance_to_height(*r, height_at(*r, dz)), dz, 1e-9 * reach)
                << c.preset << " " << c.elev << " at " << dz;
        }
        // A height the ray moves away from is never reached.
        const double away = c.elev > 0 ? c.y0 - 0.1 : c.y0 + 0.1;
        EXPECT_TRUE(std::isinf(distance_to_height(*r, away))) << c.preset << " " << c.elev;
    }
}

// Rays of every class: random start heights and elevations in every preset and in
// stiff and tiny-eta1 inferior air.
std::vector<ExactRay> random_rays(std::uint64_t seed, int per_profile) {
    const Profile profiles[] = {*preset_profile("paper"),
                                *preset_profile("hot-road"),
                                *preset_profile("paper-superior"),
                                *preset_profile("cold-sea"),
                                Profile{ProfileKind::Inferior, 1.00026383734375, 5.93e-3, 1000.0},
                                Profile{ProfileKind::Superior, 1.0003, 1e-6, 2.303}};
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<ExactRay> rays;
    for (const Profile& p : profiles) {
        for (int k = 0; k < per_profile; ++k) {
            const double y0 = 0.02 * std::pow(1000.0, unit(rng));
            const double mag = 1e-8 * std::pow(0.5e8, unit(rng));
            const double elev = unit(rng) < 0.5 ? -mag : mag;
            auto r = make_exact_ray(p, y0, M_PI / 2 - elev);
            EXPECT_TRUE(r.ok());
            if (r.ok()) rays.push_back(*r);
        }
    }
    return rays;
}

TEST(ExactRay, StateAtIsTheHeightSlopeAndCurvatureTogether) {
    std::set<RayClass> classes;
    int near_escape = 0, far_escape = 0;
    for (const ExactRay& r : random_rays(20261201, 300)) {
        classes.insert(r.ray_class);
        double reach = r.hits_ground ? r.dz_ground : 50.0 / std::max(r.c, 1e-3);
        if (r.turn_kind == TurnKind::Ahead) reach = std::max(reach, 3.0 * r.dz_turn);
        if (r.hits_ground) reach = r.dz_ground;
        std::vector<double> at = {0.0, reach};
        if (r.turn_kind == TurnKind::Ahead && r.dz_turn < reach) at.push_back(r.dz_turn);
        for (int j = 1; j < 40; ++j) at.push_back(reach * std::pow(j / 40.0, 3.0));
        for (const double dz : at) {
            const PathState st = state_at(r, dz);
            const double y = height_at(r, dz);
            const double slope = slope_at(r, dz);
            const bool on_ground = r.hits_ground && dz == r.dz_ground;
            const double curvature = curvature_at_height(r, on_ground ? 0.0 : y);
            const std::string what =
                std::string(ray_class_name(r.ray_class)) + " y0=" + std::to_string(r.y0) +
                " cos_i=" + std::to_string(r.cos_i) + " dz=" + std::to_string(dz);
            // At the ground and turning points their closed forms: 0 and y_turn.
            if (on_ground) {
                EXPECT_EQ(st.y, 0.0) << what;
                EXPECT_NEAR(y, 0.0, 1e-9 * (1.0 + r.y0)) << what;
            } else if (r.turn_kind == TurnKind::Ahead && dz == r.dz_turn) {
                EXPECT_EQ(st.y, r.y_turn) << what;
                EXPECT_EQ(st.slope, 0.0) << what;
                EXPECT_NEAR(y, r.y_turn, 1e-9 * (1.0 + r.y0)) << what;
                continue;
            } else {
                // Heights to rounding of the path's own scale, slope and curvature relative.
                EXPECT_NEAR(st.y, y, 1e-12 * (1.0 + r.y0 + std::fabs(y))) << what;
            }
            EXPECT_NEAR(st.slope, slope, 1e-9 * std::fabs(slope) + 1e-13) << what;
            EXPECT_NEAR(st.curvature, curvature, 1e-9 * std::fabs(curvature) + 1e-300) << what;
            if (r.ray_class == RayClass::SupEscapeUp || r.ray_class == RayClass::SupEscapeDown) {
                const bool near_form = r.sg > 0 ? r.c * dz < 1.0 : r.q < 0.5 * r.P;
                ++(near_form ? near_escape : far_escape);
            }
        }
    }
    // Every class, and both forms of the escaping rays.
    EXPECT_EQ(classes.size(), 7u);
    EXPECT_GT(near_escape, 100);
    EXPECT_GT(far_escape, 100);
}

TEST(ExactRay, ARayFromItsOriginsConstantsIsTheRayOfItsAngle) {
    for (const ExactRay& r : random_rays(42, 100)) {
        auto o = make_exact_ray_origin(r.profile, r.y0);
        ASSERT_TRUE(o.ok());
        const ExactRay q = make_exact_ray(*o, r.cos_i, r.sin_i);
        EXPECT_EQ(q.ray_class, r.ray_class);
        EXPECT_EQ(q.turn_kind, r.turn_kind);
        EXPECT_EQ(q.hits_ground, r.hits_ground);
        EXPECT_NEAR(q.k2, r.k2, 1e-12 * (std::fabs(r.k2) + r.E * r.E));
        if (r.turn_kind != TurnKind::None && r.turn_kind != TurnKind::BelowGround) {
            EXPECT_NEAR(q.y_turn, r.y_turn, 1e-9 * (1.0 + r.y0));
            EXPECT_NEAR(q.dz_turn, r.dz_turn, 1e-9 * std::fabs(r.dz_turn) + 1e-12);
        }
        if (r.hits_ground) {
            EXPECT_NEAR(q.dz_ground, r.dz_ground, 1e-9 * r.dz_ground);
        }
        const double reach = r.hits_ground ? r.dz_ground : 20.0 / std::max(r.c, 1e-3);
        for (int j = 0; j <= 10; ++j) {
            const double dz = reach * j / 10.0;
            EXPECT_NEAR(height_at(q, dz), height_at(r, dz), 1e-9 * (1.0 + r.y0))
                << ray_class_name(r.ray_class) << " y0=" << r.y0 << " dz=" << dz;
            // The per-ray scales of the slope and the curvature (state_at's) against the
            // ray's own slope and curvature, as for rays built from their angle.
            const PathState a = state_at(q, dz);
            const double slope = slope_at(q, dz);
            const bool on_ground = q.hits_ground && dz == q.dz_ground;
            const double curvature = curvature_at_height(q, on_ground ? 0.0 : height_at(q, dz));
            EXPECT_NEAR(a.slope, slope, 1e-9 * std::fabs(slope) + 1e-13)
                << ray_class_name(r.ray_class) << " y0=" << r.y0 << " dz=" << dz;
            EXPECT_NEAR(a.curvature, curvature, 1e-9 * std::fabs(curvature) + 1e-300)
                << ray_class_name(r.ray_class) << " y0=" << r.y0 << " dz=" << dz;
        }
    }
    EXPECT_FALSE(make_exact_ray_origin(*preset_profile("paper"), -1.0).ok());
    EXPECT_EQ(make_exact_ray_origin(*preset_profile("paper"), 1e308).message(),
              "start height y0 = 1e+308 m must be from 0 to 1e+09 m");
}

// Bit for bit, NaN equal to NaN.
bool same(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

TEST(ExactRay, ARayBuiltInPlaceIsTheRayReturnedWhateverTheStorageHeld) {
    const std::vector<ExactRay> rays = random_rays(7, 100);
    ExactRay reused = rays.back();  // storage last holding a ray of another profile and class
    int ordinary = 0, extreme = 0;
    for (const ExactRay& r : rays) {
        auto o = make_exact_ray_origin(r.profile, r.y0);
        ASSERT_TRUE(o.ok());
        const ExactRay q = make_exact_ray(*o, r.cos_i, r.sin_i);
        make_exact_ray(*o, r.cos_i, r.sin_i, reused);
        const double a[] = {q.y0,      q.cos_i,    q.sin_i,       q.eta_p,
                            q.beta,    q.P,        q.ln_P,        q.ln_E,
                            q.E,       q.ln_w,     q.gamma,       q.k2,
                            q.q,       q.c,        q.slope_scale, q.curvature_scale,
                            q.asinh_w, q.log1p_w2, q.ln_coef_lo,  q.ln_coef_hi,
                            q.theta,   q.y_turn,   q.dz_turn,     q.dz_ground};
        const double b[] = {
            reused.y0,      reused.cos_i,    reused.sin_i,       reused.eta_p,
            reused.beta,    reused.P,        reused.ln_P,        reused.ln_E,
            reused.E,       reused.ln_w,     reused.gamma,       reused.k2,
            reused.q,       reused.c,        reused.slope_scale, reused.curvature_scale,
            reused.asinh_w, reused.log1p_w2, reused.ln_coef_lo,  reused.ln_coef_hi,
            reused.theta,   reused.y_turn,   reused.dz_turn,     reused.dz_ground};
        for (std::size_t k = 0; k < std::size(a); ++k) EXPECT_TRUE(same(a[k], b[k])) << k;
        EXPECT_EQ(reused.ray_class, q.ray_class);
        EXPECT_EQ(reused.turn_kind, q.turn_kind);
        EXPECT_EQ(reused.sg, q.sg);
        EXPECT_EQ(reused.s, q.s);
        EXPECT_EQ(reused.vertex_form, q.vertex_form);
        EXPECT_EQ(reused.hits_ground, q.hits_ground);
        // Inferior rays of ordinary numbers take no ln P; the others keep it.
        if (q.s > 0) ++(std::isnan(q.ln_P) ? ordinary : extreme);
    }
    // Both forms of the inferior constants are exercised (stiff alpha y0 among the profiles).
    EXPECT_GT(ordinary, 50);
    EXPECT_GT(extreme, 5);
}

TEST(ExactRay, SuperiorRaysFromFarAboveTheGradientStayFiniteAndStraight) {
    // alpha y0 = 10^4: exp(-alpha y0) underflows to 0, and the escaping form once multiplied
    // that 0 by an exp(2x) that overflowed on the way down (NaN heights, endless samples).
    const Profile p{ProfileKind::Superior, 1.1, 0.4584, 1000.0};
    const double y0 = 10.0;
    for (const double elevation_deg : {-0.5, -10.0, -60.0}) {
        const double e = elevation_deg * M_PI / 180.0;
        auto ray = make_exact_ray(p, y0, M_PI / 2 - e);
        ASSERT_TRUE(ray.ok()) << ray.message();
        EXPECT_EQ(ray->ray_class, RayClass::SupEscapeDown);
        ASSERT_TRUE(ray->hits_ground && std::isfinite(ray->dz_ground));
        // Above the gradient (0.02 m thick) the index is eta(infinity): a straight line.
        const double straight_ground = y0 / std::tan(-e);
        EXPECT_NEAR(ray->dz_ground, straight_ground, 1e-3 * straight_ground);
        for (int k = 0; k <= 100; ++k) {
            const double dz = ray->dz_ground * k / 100.0;
            const double y = height_at(*ray, dz);
            ASSERT_TRUE(std::isfinite(y)) << "dz = " << dz;
            if (y > 0.05) EXPECT_NEAR(y, y0 + dz * std::tan(e), 1e-9 * y0) << "dz = " << dz;
        }
        SampleSettings st;
        st.tolerance_rad = 1e-6;
        const SampledPath path = sample_path(*ray, st);
        EXPECT_LT(path.points.size(), 100u);
        EXPECT_EQ(path.end, PathEnd::Ground);
        const SampledPath near = sample_path_near(*ray, st, nullptr);
        EXPECT_LT(near.points.size(), 100u);
        EXPECT_EQ(near.end, PathEnd::Ground);
        for (int k = 0; k < 100; ++k) {
            const double dz = ray->dz_ground * k / 100.0;
            const PathState s = state_at(*ray, dz);
            ASSERT_TRUE(std::isfinite(s.y) && std::isfinite(s.slope) && std::isfinite(s.curvature))
                << "dz = " << dz;
            EXPECT_NEAR(s.y, height_at(*ray, dz), 1e-9 * y0) << "dz = " << dz;
        }
    }
}

TEST(ExactRay, StartHeightsBeyondTheLimitAreRefused) {
    const Profile p{ProfileKind::Inferior, 1.000233, 0.4584, 2.303};
    EXPECT_EQ(make_exact_ray(p, 1e308, 1.6).message(),
              "start height y0 = 1e+308 m must be from 0 to 1e+09 m");
    EXPECT_TRUE(make_exact_ray(p, kMaxHeight, 1.6).ok());
}

}  // namespace
}  // namespace mirage
