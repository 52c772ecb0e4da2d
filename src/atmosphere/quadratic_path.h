// Exact ray paths in a piecewise-quadratic n^2(y) (quadratic_profile.h), in closed form in every
// piece, with every turning point, ground hit and trapped (ducted) ray found.
//
// In a stratified medium beta = n(y) sin i(y) is invariant, (dy/dz)^2 = (n^2 - beta^2) / beta^2
// and y'' = (n^2)'(y) / (2 beta^2).  Inside a piece (n^2)' is linear in y, so the ray equation is
// linear: y'' = a + kappa (y - y_a) with kappa = c / beta^2.  From an anchor (y_a, slope s_a,
// curvature a) the path is, with x = lambda tau, lambda = sqrt|kappa|, tau = z - z_a,
//   y = y_a + tau (s_a S1(x) + a tau S2(x)),   y' = s_a C(x) + a tau S1(x),
//   kappa > 0: S1 = sinh x / x, S2 = (cosh x - 1) / x^2, C = cosh x
//   kappa < 0: S1 = sin x / x,  S2 = (1 - cos x) / x^2,  C = cos x
//   kappa = 0: S1 = 1, S2 = 1/2, C = 1 (a parabola),
// one family continuous in kappa (quadratic_path.cpp gives the crossing times, the asinh/asin
// forms from a turning point and the log1p/atan2 forms between knots).  A path is a sequence of
// sweeps: monotone runs between turning points, the ground or the top.  After a turning point
// the ray retraces the run it came by (the path is symmetric about every turning point), and
// after a second one it is trapped between the two for ever: its path is periodic.
#pragma once

#include <vector>

#include "atmosphere/quadratic_profile.h"
#include "util/result.h"

namespace mirage {

/// What becomes of a ray.
enum class PathFate {
    Straight,  ///< homogeneous air: a straight line
    Ground,    ///< reaches the ground (after at most one turning point)
    Escape,    ///< rises above the profile's top and goes on straight
    Ducted,    ///< trapped between two turning heights for ever
    Level,     ///< stays level at an extremum of n^2 (beta = n there and (n^2)' = 0)
};

std::string_view path_fate_name(PathFate f);

/// One piece of a sweep, evaluated from its anchor (a turning point when it has one).
struct QuadraticSegment {
    double t0 = 0.0, t1 = 0.0;  // sweep distance at its ends, m
    double ta = 0.0;            // sweep distance of the anchor
    double ya = 0.0;            // anchor height
    double sa = 0.0;            // slope dy/dz at the anchor (0 at a turning point)
    double aa = 0.0;            // y'' at the anchor
    double kappa = 0.0;         // c / beta^2, 1/m^2
    double lambda = 0.0;        // sqrt(|kappa|)
    double y1 = 0.0;            // height at t1
    int piece = 0;              // the profile piece (piece_count() above the top)
};

enum class SweepEnd { Vertex, Ground, Top };

/// A monotone run of the path from its origin (a turning point or the ray's start).
struct Sweep {
    std::vector<QuadraticSegment> segments;
    int dir = 1;  // +1 rising, -1 descending
    SweepEnd end = SweepEnd::Top;
    double length = 0.0;  // horizontal distance from the origin to the end
    double y_start = 0.0;
    double y_end = 0.0;
    double end_slope = 0.0;  // at the end (Top: the straight path's slope beyond)
};

/// A turning point: where the path is level and turns back.
struct TurningPoint {
    double dz = 0.0;     // horizontal distance from the start
    double y = 0.0;      // height
    bool lowest = true;  // a lowest point (the path is concave up there) or an apex
};

/// What every ray from one height shares (a tracer's eye): made once by quadratic_start.
struct QuadraticStart {
    double y0 = 0.0;
    double e0 = 0.0;     // n^2 - n0^2 at y0
    int piece_up = 0;    // the piece a run leaves y0 by going up (piece_count(): above the top)
    int piece_down = 0;  // and going down (-1: at the ground)
};
QuadraticStart quadratic_start(const QuadraticProfile& profile, double y0);

class QuadraticPath {
  public:
    /// The ray from height y0 >= 0 at angle i from the upward vertical (strictly between 0 and
    /// pi).  The path refers to the profile, which must outlive it.  Where the ray turns, meets
    /// the ground or leaves the top is found at once (O(log pieces)); the crossing of each
    /// piece is computed when a query first needs it, so a path is cheap however many pieces
    /// the profile has.  Queries extend the path in place: a path is not to be shared between
    /// threads (copy it).
    static Result<QuadraticPath> make(const QuadraticProfile& profile, double y0, double i_rad);
    /// The same ray from its direction's cosine and sine of i (a unit vector, sin i > 0): for
    /// a tracer that has the direction, not the angle.
    static Result<QuadraticPath> make_direction(const QuadraticProfile& profile,
                                                const QuadraticStart& start, double cos_i,
                                                double sin_i);

    double y0() const { return y0_; }
    double i_rad() const;
    double cos_i() const { return cos_i_; }
    double beta() const { return beta_; }
    double eta_start() const { return eta_p_; }
    int start_direction() const { return sg_; }  // +1 up or level, -1 down
    PathFate fate() const { return fate_; }
    const QuadraticProfile& profile() const { return *profile_; }

    /// Height at horizontal distance dz >= 0 (beyond a ground hit: the tangent at the hit).
    double height_at(double dz) const;
    /// Slope dy/dz at dz.
    double slope_at(double dz) const;
    /// The first horizontal distance at which the path reaches height y while still moving
    /// towards it from y0 (before any turning point), or +inf if it never does: the closed
    /// form of the piece holding y, after the crossings of the pieces before it.
    double distance_to_height(double y) const;
    /// y'' anywhere on a path of this invariant at height y.
    double curvature_at_height(double y) const;
    /// The largest |y''| at any height in [ya, yb].
    double curvature_bound(double ya, double yb) const;

    /// Turning points ahead (dz > 0): how many (-1: infinitely many, a ducted ray), and the k-th.
    int turning_point_count() const;
    TurningPoint turning_point(int k) const;
    /// The first turning point at or after dz (k >= 0), or -1 if none: for walking them.
    int first_turning_point_after(double dz) const;
    /// Whether the k-th turning point ahead lies before dz, and then it in `tp`.  The run is
    /// computed only as far as the answer needs: a trapped ray's second turning height may lie
    /// far above anything the query reaches (a wide duct), and a ray whose run has already
    /// lasted past dz turns there no more.
    bool turning_point_before(int k, double dz, TurningPoint& tp) const;

    bool hits_ground() const {
        return fate_ == PathFate::Ground || (fate_ == PathFate::Straight && sg_ < 0);
    }
    double dz_ground() const;  // +inf when never
    /// Beyond this distance the path is a straight line of slope asymptotic_slope() (+inf when
    /// never: ground, ducted).
    double dz_straight() const;
    double asymptotic_slope() const { return slope_straight_; }  // NaN when never straight
    /// A bound on |y(z) - L(z)| for every z >= dz, where L is the line through (dz, y(dz)) with
    /// the asymptotic slope; +inf when the path never goes straight or dz is before its turn.
    /// With s the slope at height y and s_inf the slope above the top, L departs from the path
    /// by int_y^top |1 - s_inf / s| dy' at most, bounded from the range of n^2 over [y, top].
    double asymptote_departure(double dz) const;

    /// Bounds lo <= |dy/dz| <= hi wherever the path is at a height in [ya, yb] (ya <= yb): from
    /// the range of n^2 - beta^2 there, widened where the ray may cross spans.
    void abs_slope_bounds(double ya, double yb, double& lo, double& hi) const;

    /// The path's monotone run, completed: from the first turning point (or from the start when
    /// there is none ahead) to the next turning point, the ground or the top.
    const Sweep& sweep() const;
    /// Distance to the first turning point (0 when none ahead).
    double first_turn_dz() const;

    /// How many coarse spans the path has crossed so far (in place of fine pieces).
    int spans_crossed() const { return spans_crossed_; }

    /// The segments' storage, emptied (the path is left without it: to be discarded), and a
    /// fresh path taking such storage over before any query (its capacity reused).
    std::vector<QuadraticSegment> release_storage();
    void adopt_storage(std::vector<QuadraticSegment>&& storage);

  private:
    const QuadraticProfile* profile_ = nullptr;
    mutable double i_ = 0.0;  // NaN until asked for, when made from a direction
    double y0_ = 0.0, cos_i_ = 0.0, sin_i_ = 1.0, slope0_ = 0.0;
    double eta_p_ = 1.0, beta_ = 1.0, inv_beta_ = 1.0, inv_beta_sq_ = 1.0;
    double e0_ = 0.0, Q0_ = 0.0;  // n^2 - n0^2 and n^2 - beta^2 at the start
    int sg_ = 1;
    PathFate fate_ = PathFate::Straight;
    bool vertex_ahead_ = false;
    bool periodic_ = false;  // a second turning point: trapped
    double slope_straight_ = 0.0;

    // The run, extended lazily: its origin (the first turning point, or the start), its end
    // (known from the start) and how far its segments have been computed.
    int end_piece_ = 0;  // the piece of the end turning point
    struct Cursor {
        int j = 0;       // the next piece to cross
        double y = 0.0;  // height where it is entered
        double Q = 0.0;  // n^2 - beta^2 there
        double t = 0.0;  // run distance there
        double slope = 0.0;
        bool at_vertex = false;
        bool first = true;  // the origin's piece (entered at the origin, not at a knot)
        bool done = false;
    };
    mutable Sweep sweep_;
    mutable Cursor cur_;
    mutable double t1_ = 0.0;  // the run's distance at the start height (= first turn dz)
    mutable bool t1_known_ = true;
    mutable int hint_a_ = -1, hint_b_ = -1;  // pieces of the last curvature bound's heights
    mutable size_t seg_hint_ = 0;            // the segment of the last height query
    mutable double span_slack_ = 0.0;        // the largest slope_slack of the spans crossed so far
    mutable int spans_crossed_ = 0;

    const QuadraticSegment& segment_for(double t) const;

    bool extend() const;  // one more segment; false when the run is complete
    /// Segments from knot to knot, as extend() computes them, while the run's distance is
    /// below t_stop and nothing else happens in the piece.
    void cross_pieces(double t_stop) const;
    void complete() const;
    void ensure_time(double t) const;
    void ensure_t1() const;
    double run_time(double dz, int& sign) const;
    /// The range of n^2 - beta^2 over the heights [ya, yb], widened where the ray may cross
    /// spans (QuadraticProfile::kSpanShareOfQ).
    void q_range(double ya, double yb, double& q_lo, double& q_hi) const;
};

/// Height and slope of a sweep at distance t from its origin (0 <= t <= length; beyond, the
/// end's straight continuation).
double sweep_height(const Sweep& s, double t);
double sweep_slope(const Sweep& s, double t);

}  // namespace mirage
