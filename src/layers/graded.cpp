#include "layers/graded.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "atmosphere/exact_ray.h"
#include "util/parallel.h"

namespace mirage {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The smooth minimum of x and 1 used for h: x below 1 - w, 1 above 1 + w, and between them
// the quadratic that joins the two with a continuous derivative.
double eased_min(double x, double w) {
    if (w <= 0.0) return std::min(x, 1.0);
    if (x <= 1.0 - w) return x;
    if (x >= 1.0 + w) return 1.0;
    const double u = (x - (1.0 - w)) / (2.0 * w);
    return (1.0 - w) + 2.0 * w * (u - 0.5 * u * u);
}

std::vector<double> radial_nodes(double reach, int count) {
    std::vector<double> r = {0.0};
    const int n = std::max(2, count);
    const double r_min = reach * 1e-4;
    for (int j = 0; j < n - 1; ++j) r.push_back(r_min * std::pow(reach / r_min, j / double(n - 2)));
    return r;
}

}  // namespace

double grading_factor(const GradedSettings& st, double tau) {
    if (st.grading == 0.0 || !(st.saturation > 0.0)) return 1.0;
    return 1.0 + st.grading * eased_min(std::max(0.0, tau) / st.saturation, st.softness);
}

IndexRange graded_index_range(const Profile& p, double eye_y, double top,
                              const GradedSettings& st) {
    (void)eye_y;
    const double h_max = 1.0 + std::max(0.0, st.grading);
    const double a = eta(p, 0.0), b = eta(p, top);
    return {std::min(a, b), std::max(a, b) * h_max};
}

Result<RevolutionStack> graded_stack(const Profile& profile, double eye_y, double elevation_lo,
                                     double elevation_hi, double reach, double top,
                                     const GradedSettings& st, const std::vector<double>& levels) {
    if (!(eye_y > 0.0) || !(reach > 0.0) || !(top > eye_y) || !(elevation_hi > elevation_lo))
        return make_error("graded layers: bad eye, reach, top or elevation range");
    for (size_t k = 1; k < levels.size(); ++k)
        if (!(levels[k] > levels[k - 1])) return make_error("graded layers: levels must ascend");
    const int s = profile_sign(profile) >= 0 ? 1 : -1;  // n_eff grows upward (inferior) or down
    RevolutionStack out;
    out.eye_y = eye_y;
    out.radii = radial_nodes(reach, st.radial_nodes);
    const int J = static_cast<int>(out.radii.size());

    // The family of exact camera rays, a little wider than the camera's elevations, and along
    // each the height and the optical path length tau = (1/beta) integral of n^2 dr at every
    // node (Simpson's rule per node interval).
    const int M = std::max(16, st.family_rays);
    const double t_lo = std::tan(std::max(elevation_lo, -1.45)),
                 t_hi = std::tan(std::min(elevation_hi, 1.45));
    const double margin = 0.05 * (t_hi - t_lo);
    std::vector<std::vector<double>> Y(M, std::vector<double>(J, kNaN)),
        T(M, std::vector<double>(J, kNaN));
    parallel_for(
        M,
        [&](long i) {
            const double e = std::atan(t_lo - margin + (t_hi - t_lo + 2.0 * margin) * i / (M - 1));
            auto ray = make_exact_ray(profile, eye_y, M_PI / 2 - e);
            if (!ray) return;
            const double beta = ray->beta;
            auto n2 = [&](double y) { return eta_sq(profile, std::max(0.0, y)); };
            double tau = 0.0, y_prev = eye_y;
            Y[i][0] = eye_y;
            T[i][0] = 0.0;
            for (int j = 1; j < J; ++j) {
                const double r = out.radii[j], r_prev = out.radii[j - 1];
                if (ray->hits_ground && r > ray->dz_ground) break;
                const double y = height_at(*ray, r);
                const double ym = height_at(*ray, 0.5 * (r + r_prev));
                tau += (r - r_prev) / (6.0 * beta) * (n2(y_prev) + 4.0 * n2(ym) + n2(y));
                Y[i][j] = y;
                T[i][j] = tau;
                y_prev = y;
            }
        },
        0, 8);

    // Per node: tau_min over the heights the family covers (the first sheet, where two cross),
    // continued from the nearest covered height elsewhere; n_eff made monotone in y; each
    // level's height where n_eff reaches it.
    const int C = std::max(64, st.column_samples);
    const double y_hi = std::max(top, eye_y + 1.5 * st.saturation);
    const double y_lo = 0.0;
    const int N = static_cast<int>(levels.size());
    out.heights.assign(N, std::vector<double>(J, 0.0));
    parallel_for(
        J,
        [&](long j) {
            std::vector<double> ys(C), tau(C, kInf);
            for (int c = 0; c < C; ++c) ys[c] = y_lo + (y_hi - y_lo) * c / (C - 1);
            if (j == 0) {
                for (int c = 0; c < C; ++c) tau[c] = eta(profile, ys[c]) * std::fabs(ys[c] - eye_y);
            } else {
                for (int i = 0; i + 1 < M; ++i) {
                    const double ya = Y[i][j], yb = Y[i + 1][j];
                    if (!std::isfinite(ya) || !std::isfinite(yb)) continue;
                    const double lo = std::min(ya, yb), hi = std::max(ya, yb);
                    const int c0 = std::max(
                        0, static_cast<int>(std::ceil((lo - y_lo) / (y_hi - y_lo) * (C - 1))));
                    const int c1 = std::min(
                        C - 1, static_cast<int>(std::floor((hi - y_lo) / (y_hi - y_lo) * (C - 1))));
                    for (int c = c0; c <= c1; ++c) {
                        const double w = yb != ya ? (ys[c] - ya) / (yb - ya) : 0.5;
                        tau[c] = std::min(tau[c], T[i][j] + w * (T[i + 1][j] - T[i][j]));
                    }
                }
                // Continue tau from the nearest covered height.
                int first = -1;
                for (int c = 0; c < C; ++c)
                    if (std::isfinite(tau[c])) {
                        first = c;
                        break;
                    }
                if (first < 0) {
                    for (int c = 0; c < C; ++c)
                        tau[c] = eta(profile, ys[c]) * std::hypot(out.radii[j], ys[c] - eye_y);
                } else {
                    for (int c = 0; c < first; ++c) tau[c] = tau[first];
                    for (int c = first + 1; c < C; ++c)
                        if (!std::isfinite(tau[c])) tau[c] = tau[c - 1];
                }
            }
            std::vector<double> ne(C);
            for (int c = 0; c < C; ++c)
                ne[c] = s * eta(profile, ys[c]) * grading_factor(st, tau[c]);
            for (int c = 1; c < C; ++c) ne[c] = std::max(ne[c], ne[c - 1]);
            for (int k = 0; k < N; ++k) {
                const double v = s * levels[s > 0 ? k : N - 1 - k];
                const int kk = k;
                double y;
                if (v <= ne[0]) {
                    // Below the ground here: ordered beneath it.
                    y = -1e-3 * (N - kk);
                } else if (v > ne[C - 1]) {
                    y = y_hi + 1e-3 * (kk + 1);
                } else {
                    const int c =
                        static_cast<int>(std::lower_bound(ne.begin(), ne.end(), v) - ne.begin());
                    const double f =
                        ne[c] > ne[c - 1] ? (v - ne[c - 1]) / (ne[c] - ne[c - 1]) : 1.0;
                    y = ys[c - 1] + f * (ys[c] - ys[c - 1]);
                }
                out.heights[k][j] = y;
            }
            // Strictly ordered: a plateau of n_eff would give coincident boundaries.
            for (int k = 1; k < N; ++k)
                out.heights[k][j] = std::max(
                    out.heights[k][j],
                    out.heights[k - 1][j] + 1e-9 * (1.0 + std::fabs(out.heights[k - 1][j])));
        },
        0, 1);

    // Indices: each layer at the middle of its two levels; the lowest and highest a half step
    // beyond.
    std::vector<double> lv = levels;
    if (s < 0) std::reverse(lv.begin(), lv.end());
    out.index.resize(N + 1);
    for (int k = 0; k <= N; ++k) {
        if (N == 0) {
            out.index[k] = eta(profile, eye_y);
        } else if (k == 0) {
            out.index[k] = lv[0] - 0.5 * (N > 1 ? lv[1] - lv[0] : 0.0);
        } else if (k == N) {
            out.index[k] = lv[N - 1] + 0.5 * (N > 1 ? lv[N - 1] - lv[N - 2] : 0.0);
        } else {
            out.index[k] = 0.5 * (lv[k - 1] + lv[k]);
        }
    }
    if (!well_formed(out)) return make_error("graded layers: the level sets are not ordered");
    return out;
}

}  // namespace mirage
