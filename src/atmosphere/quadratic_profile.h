// A piecewise-quadratic n^2(y): the model of any stratified atmosphere on which the exact-path
// engine (quadratic_path.h) works.  Between knots y_j < y_{j+1}
//   n^2(y) = n0^2 + e_j + b_j u + c_j u^2,   u = y - y_j,
// continuous everywhere, with a continuous slope except at knots where the profile itself has a
// corner (an inversion without smoothing).  Above the top knot n^2 stays at its top value, so
// rays go straight there.  With an Earth radius R the heights are the conformally flattened
// heights y = R ln(r / R) of earth_flattening.h and n^2 is n*^2 = (n r / R)^2.
//
// A profile given as a function (temperatures, soundings) is fitted by Hermite interpolation
// with a knot in the middle of every interval (Schumaker's C^1 quadratic spline), the
// intervals halved until |n_fit - n| <= tolerance everywhere.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "util/result.h"

namespace mirage {

struct ProfileFunction;
struct FitSettings;
struct FitReport;

/// A coarser piece of a fitted model: one quadratic over several of the fine intervals at once,
/// through the profile at its ends and its middle.  Its ends are knots of the fine model, where
/// both take the same value, so a ray may cross the span in place of the fine pieces and its
/// model stays continuous (with a corner of its slope there; a path's curvature bounds add the
/// slope_slack of the spans it crosses).
/// A ray does so only where its direction is steep enough for the span's larger error to change
/// it by no more than the fine model's own bound (max_beta_sq, see fit_quadratic_profile).
struct CoarseSpan {
    int lo = 0, hi = 0;        // the fine model's knots at its ends
    double b = 0.0;            // d(n^2)/dy at its lower end
    double c = 0.0;            // half the second derivative of n^2
    double root_c = 0.0;       // sqrt(|c|)
    double end_slope = 0.0;    // d(n^2)/dy at its upper end
    double slope_slack = 0.0;  // the largest |d(n^2)/dy| of the span less the fine pieces' below it
    double error_n = 0.0;      // |n_span - n| at most
    double max_beta_sq = -std::numeric_limits<double>::infinity();  // rays with beta^2 <= this
    int finer_same_lo = -1;  // the next finer span starting at the same knot (-1: the fine pieces)
    int finer_same_hi = -1;  // the next finer span ending at the same knot
};

class QuadraticProfile {
  public:
    /// Builds the model from its knots (y[0] = 0, increasing; the last is the top) and per piece
    /// j < knots - 1 the slope b_j and half the second derivative c_j of n^2 at its start; the
    /// values at the knots follow from n0_sq and the pieces (e_0 = 0, e_{j+1} = e_j + b_j h_j +
    /// c_j h_j^2).  Refused: fewer than two knots, knots not increasing, non-finite values,
    /// n^2 <= 0 anywhere.
    static Result<QuadraticProfile> make(std::vector<double> knots, std::vector<double> slopes,
                                         std::vector<double> curvatures, double n0_sq,
                                         double earth_radius);

    int piece_count() const { return static_cast<int>(b_.size()); }
    const std::vector<double>& knots() const { return y_; }
    double knot(int j) const { return y_[j]; }
    double top() const { return y_.back(); }
    double n0_sq() const { return n0_sq_; }
    double earth_radius() const { return earth_radius_; }  // 0: flat
    /// Whether the sky is seen where a ray leaves the model's top (the whole atmosphere
    /// described, to vacuum above: AirSpec::upper_air), rather than where a tracer stops
    /// following it.
    bool sky_at_top() const { return sky_at_top_; }
    void set_sky_at_top(bool at_top) { sky_at_top_ = at_top; }
    /// Piece j's coefficients: n^2 - n0^2 = e + b u + c u^2 on [knot(j), knot(j+1)].
    double e(int j) const { return e_[j]; }
    double b(int j) const { return b_[j]; }
    double c(int j) const { return c_[j]; }
    /// The increment of n^2 over piece j, b_j h_j + c_j h_j^2 (e(j+1) - e(j) by definition).
    double increment(int j) const { return inc_[j]; }

    /// The piece holding height y: j with knot(j) <= y < knot(j+1); -1 below 0, piece_count()
    /// at or above the top.
    int piece_at(double y) const;
    /// piece_at(y), searched from `hint` outwards (galloping, then halving): O(log) of the
    /// distance from it.
    int piece_at(double y, int hint) const {
        const int m = piece_count();
        if (hint >= 0 && hint < m) {
            if (y >= y_[hint]) {
                if (y < y_[hint + 1]) return hint;
                if (hint + 1 < m && y < y_[hint + 2]) return hint + 1;
            } else if (hint > 0 && y >= y_[hint - 1]) {
                return hint - 1;
            }
            return piece_from(y, hint);
        }
        return piece_at(y);
    }

    /// n^2(y) - n0^2 (the constant top value above the top; the lowest piece continued below 0).
    double excess(double y) const;
    double n_sq(double y) const { return n0_sq_ + excess(y); }
    double n(double y) const;
    /// d(n^2)/dy at y (the right-hand value at a corner).
    double slope(double y) const;
    /// The largest |d(n^2)/dy| over the heights [ya, yb] (in either order): it bounds a ray's
    /// curvature there, |y''| = |d(n^2)/dy| / (2 beta^2), where the ray crosses the pieces.
    double max_abs_slope(double ya, double yb) const;
    /// The same, with the pieces of ya and yb looked for first where `hint_a` and `hint_b` say
    /// (and updated): consecutive queries of a path are mostly in the same pieces.
    double max_abs_slope(double ya, double yb, int& hint_a, int& hint_b) const;
    /// The smallest and largest n^2 over [ya, yb].
    void n_sq_range(double ya, double yb, double& lo, double& hi) const;
    /// The smallest and largest n^2 - n0^2 over [ya, yb].
    void excess_range(double ya, double yb, double& lo, double& hi) const;
    /// The first piece k >= j (dir > 0) or the last k <= j (dir < 0) whose smallest n^2 - n0^2
    /// is at most `level`; piece_count() (dir > 0) or -1 (dir < 0) when there is none.  For
    /// finding where a ray turns (n^2 = beta^2) in O(log pieces).
    int find_piece_reaching(int j, int dir, double level) const;
    /// The slope of n^2 at the end of piece j (at knot j + 1, from below).
    double end_slope(int j) const { return end_slope_[j]; }
    /// sqrt(|c_j|).
    double root_abs_c(int j) const { return root_abs_c_[j]; }
    /// Whether n^2 is the same at every height.
    bool homogeneous() const { return homogeneous_; }

    /// The coarser spans (fit_quadratic_profile with FitSettings::coarse_spans), and the coarsest
    /// one starting (span_up) or ending (span_down) at knot k, -1 when none.
    const std::vector<CoarseSpan>& spans() const { return spans_; }
    bool has_spans() const { return !spans_.empty(); }
    int span_up(int k) const { return span_up_[k]; }
    int span_down(int k) const { return span_down_[k]; }
    /// Where a ray crosses a span, its n^2 - beta^2 is within this share of the fine model's.
    static constexpr double kSpanShareOfQ = 0.25;

    /// The same model with heights in units of `unit` metres (slopes and curvatures rescaled,
    /// the spans with them).
    Result<QuadraticProfile> rescaled(double unit) const;

  private:
    friend Result<QuadraticProfile> fit_quadratic_profile(const ProfileFunction& f,
                                                          const FitSettings& settings,
                                                          FitReport* report);
    /// The coarser spans over the fine model (FitSettings::coarse_spans): `edge_knots` are the
    /// knots at the ends of the profile's smooth stretches, `excess` the profile counted in
    /// `checks`.
    void add_coarse_spans(const ProfileFunction& f, const FitSettings& settings,
                          const std::vector<int>& edge_knots,
                          const std::function<double(double)>& excess, long& checks);

    std::vector<double> y_, e_, b_, c_, inc_, end_slope_, root_abs_c_;
    double n0_sq_ = 1.0;
    double earth_radius_ = 0.0;
    bool sky_at_top_ = false;
    bool homogeneous_ = true;
    std::vector<CoarseSpan> spans_;
    std::vector<int> span_up_, span_down_;
    // Sparse tables (level k covers 2^k entries): the largest |slope| at each knot (either
    // side), and each piece's smallest and largest n^2 - n0^2.
    std::vector<std::vector<double>> knot_slope_max_, piece_min_, piece_max_;

    double piece_value(int j, double u) const { return e_[j] + (b_[j] + c_[j] * u) * u; }
    int piece_from(double y, int hint) const;
    void build_tables();
};

/// A profile to fit: n^2(y) - n0^2 and its slope, smooth between breakpoints.
struct ProfileFunction {
    std::function<double(double)> excess;             // n^2(y) - n0^2
    std::function<double(double, int)> excess_slope;  // d/dy; side -1 left, +1 right limit
    double n0_sq = 1.0;                               // n^2 at y = 0
    std::vector<double> breakpoints;  // heights in (0, top) where the smoothness may change
    double top = 1000.0;              // the fit covers [0, top]; constant above
    double earth_radius = 0.0;        // recorded in the model (the function is already flat)
};

struct FitSettings {
    double tolerance_n = 1e-10;  // largest |n_fit - n| over [0, top]
    double min_interval = 1e-6;  // m: a profile that needs finer intervals is refused
    int max_pieces = 1 << 20;    // refused beyond
    bool coarse_spans = false;   // also fit the coarser spans steep rays may cross instead
    // The share of the fine model's bound on directions, pi sqrt(tolerance_n), that crossing a
    // span may cost a ray (1: the bound is kept; larger values trade it for fewer crossings).
    double span_allowance = 1.0;
};

/// What the fit achieved.
struct FitReport {
    int pieces = 0;
    double max_error_n = 0.0;  // the largest |n_fit - n| found at the checked heights
    double worst_height = 0.0;
    long checks = 0;  // the fit's work: evaluations of the profile and comparisons with it
    double failure_height = std::numeric_limits<double>::quiet_NaN();  // where a failed fit stopped
};

/// Fits the C^1 piecewise-quadratic model (C^0 at breakpoints where the slope jumps): Hermite
/// interpolation with a midpoint knot on intervals marched up from the ground, each checked at
/// 23 heights and kept when every error is within 0.9 of the tolerance (the margin covers the
/// errors between the checked heights; the tests check the bound densely).
///
/// With coarse_spans, spans of 1, 2, 4, 8, ... fine intervals start at every fine interval's end
/// (never across a corner of the profile; in a model of more than 2048 intervals those longer
/// than 8 at every (length / 8)-th end, O(m log m) checks for m pieces), each the quadratic
/// through the profile at its ends
/// and its middle, its error checked at 23 heights and at every fine knot inside it and halfway
/// between them (error_n: the largest checked error over 0.9, at least 8 ulps).  The rays that
/// may cross a span: the fine model keeps a ray's direction within B = pi sqrt(eps) of the true
/// one (eps the tolerance).  At a height in a span, n cos e = beta with beta from the fine model at
/// the start gives |cos e - cos e_true| <= D = 1.01 (eps + error_n), and |e - e_true| <= D /
/// sqrt(sin^2 e_true - 3 D); with sin^2 e_true >= (n^2_min - beta^2 - 4.02 eps) / n^2_max over the
/// span, a ray with beta^2 <= n^2_min - 4.02 eps - n^2_max (3 D + D^2 / B^2) stays within B there.
/// A span also needs n^2 - beta^2 >= 2.02 (eps + error_n) / kSpanShareOfQ (8.08 (eps + error_n))
/// over it, so that crossing it changes n^2 - beta^2 by at most kSpanShareOfQ (a quarter): no
/// ray turns in a span, and the bounds on a path's straight continuation (asymptote_departure)
/// widen by that share.
Result<QuadraticProfile> fit_quadratic_profile(const ProfileFunction& f,
                                               const FitSettings& settings,
                                               FitReport* report = nullptr);

/// A height range where level rays are trapped (a duct): around a local maximum of n^2 up to
/// the level at which the maximum's basin spills (towards the ground or the sky).
struct Duct {
    double bottom = 0.0;    // lowest height of a trapped level ray (m, model heights)
    double top = 0.0;       // highest
    double peak = 0.0;      // where n^2 is largest in the duct
    double spill_sq = 0.0;  // n^2 at the duct's edges: rays with beta^2 above it are trapped
    double peak_sq = 0.0;   // n^2 at the peak
};

/// Every duct of the model, lowest first.
std::vector<Duct> find_ducts(const QuadraticProfile& profile);

}  // namespace mirage
