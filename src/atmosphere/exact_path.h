// One interface for exact ray paths in any stratified atmosphere: the exponential profiles'
// closed forms (exact_ray.h, kept as they are) and the piecewise-quadratic engine for every
// other profile (quadratic_path.h), behind two value types.
//
//   Atmosphere: the medium, n(y) over model heights (flattened ones with an Earth radius);
//   ExactPath:  one ray in it, from (y0, i): height and slope at a distance, turning points,
//               ground hit, straight end and the curvature bound max |y''| over a height
//               interval, which is what the sampler's chord bound needs (y'' depends on the
//               height only: y'' = (n^2)'(y) / (2 beta^2)).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "atmosphere/exact_ray.h"
#include "atmosphere/profile.h"
#include "atmosphere/quadratic_path.h"
#include "atmosphere/quadratic_profile.h"
#include "util/result.h"

namespace mirage {

class Atmosphere {
  public:
    /// Homogeneous air of index 1.
    Atmosphere();
    static Atmosphere exponential(const Profile& profile);
    static Atmosphere quadratic(std::shared_ptr<const QuadraticProfile> profile);

    /// The exponential profile, or nullptr.
    const Profile* exponential_profile() const;
    /// The piecewise-quadratic model, or nullptr.
    const QuadraticProfile* quadratic_profile() const;

    double n_sq(double y) const;
    double n(double y) const;
    /// Whether the index changes with height anywhere.
    bool has_gradient() const;
    /// The Earth radius of the flattened frame; 0 for flat ground.
    double earth_radius() const;
    /// The height above which n no longer changes: the fitted model's top; +inf for the
    /// exponential profiles, which approach eta(infinity) without reaching it.
    double constant_above() const;
    /// The smallest and largest index over the heights [ya, yb] (ya <= yb, yb may be +inf).
    void n_range(double ya, double yb, double& lo, double& hi) const;
    /// Whether its paths are in closed form: a point at any distance costs the same, so a
    /// tracer follows them as far as the sampler goes (kMaxSampleDistance), where a path of
    /// the general engine, computed piece by piece, is followed as far as the scene needs.
    bool closed_form() const;

    /// The same medium: the same exponential profile, or the same piecewise-quadratic model
    /// (by identity).
    bool operator==(const Atmosphere& other) const;
    /// The medium by value, for a cache that outlives it: the profile's parameters, or every
    /// knot and value of the model with its Earth radius.  Equal keys, equal media.
    std::vector<double> key() const;

  private:
    std::variant<Profile, std::shared_ptr<const QuadraticProfile>> model_;
};

class ExactPath {
  public:
    /// The ray from y0 >= 0 (model height) at angle i (rad, strictly between 0 and pi) from the
    /// upward vertical.  A path through a quadratic profile refers to the atmosphere's model,
    /// which must outlive it.
    static Result<ExactPath> make(const Atmosphere& atmosphere, double y0, double i_rad);
    /// The same ray from its direction: cos i and sin i of a unit vector with sin i > 0.
    static Result<ExactPath> make_direction(const Atmosphere& atmosphere, double y0, double cos_i,
                                            double sin_i);
    /// The same in a piecewise-quadratic atmosphere, from what every ray from its height shares.
    static Result<ExactPath> make_direction(const Atmosphere& atmosphere,
                                            const QuadraticStart& start, double cos_i,
                                            double sin_i);

    double y0() const;
    double i_rad() const;
    double beta() const;
    double eta_start() const;

    double height_at(double dz) const;
    double slope_at(double dz) const;
    /// The first horizontal distance at which the path reaches height y while still moving
    /// towards it from y0 (before any turning point), or +inf if it never does.
    double distance_to_height(double y) const;
    /// The largest |y''| of this path at any height in [ya, yb] (either order).
    double curvature_bound(double ya, double yb) const;

    /// Turning points ahead: how many (-1: infinitely many), the k-th, and the index of the
    /// first at or after dz (-1 if none).
    int turning_point_count() const;
    TurningPoint turning_point(int k) const;
    int first_turning_point_after(double dz) const;
    /// Whether the k-th turning point lies before dz, and then it in `tp` (computing no more of
    /// the path than that needs).
    bool turning_point_before(int k, double dz, TurningPoint& tp) const;

    bool hits_ground() const;
    double dz_ground() const;  // +inf when never
    /// No index gradient at all: one straight line.
    bool straight() const;
    /// The slope the path ends with when it never reaches the ground and is not trapped; NaN
    /// otherwise.
    double asymptotic_slope() const;
    /// A bound on how far the path beyond dz strays from the line through its point at dz with
    /// the asymptotic slope; +inf when it has no asymptote or dz lies before its last turn.
    double asymptote_departure(double dz) const;

    PathFate fate() const;
    /// The class name: the reference's (inf_turn, sup_trapped_up, ...) for the exponential
    /// profiles, the fate (ground, escape, ducted, level, straight) otherwise.
    std::string class_name() const;

    const ExactRay* exponential() const { return std::get_if<ExactRay>(&path_); }
    const QuadraticPath* quadratic() const { return std::get_if<QuadraticPath>(&path_); }

    /// The storage of a general path's segments, handed from one path to the next so that a
    /// tracer does not allocate it for every ray (empty for an exponential path).
    std::vector<QuadraticSegment> release_storage();
    void adopt_storage(std::vector<QuadraticSegment>&& storage);

  private:
    friend class PathOrigin;
    explicit ExactPath(ExactRay ray) : path_(std::move(ray)) {}
    explicit ExactPath(QuadraticPath path) : path_(std::move(path)) {}
    std::variant<ExactRay, QuadraticPath> path_;
};

/// What every ray from one height of an atmosphere shares, computed once for the many rays a
/// tracer sends from there (a frame's camera rays from the eye, a reflection's): the
/// exponential profiles' constants (ExactRayOrigin) or the general engine's start, and the
/// index's range over the heights a ray reaches without turning.
class PathOrigin {
  public:
    /// From height y0 (finite, >= 0) of the atmosphere, which the origin keeps.
    static Result<PathOrigin> make(const Atmosphere& atmosphere, double y0);

    const Atmosphere& atmosphere() const { return atmosphere_; }
    double y0() const { return y0_; }

    /// Whether the ray from here with sin i = sin_i (rising or not) turns by at most `limit`
    /// (rad) anywhere: from the invariant n(y) sin i(y) = beta over the heights it can reach
    /// without turning (above the start rising, below it descending); false when it can turn.
    bool bends_at_most(double sin_i, bool rising, double limit) const;

    /// The ray along the unit direction (cos i, sin i), sin i > 0, into `path`, whose storage
    /// it reuses (a general path's segments; an exponential ray is written in place).
    void path(double cos_i, double sin_i, std::optional<ExactPath>& path) const;

  private:
    PathOrigin(const Atmosphere& atmosphere, double y0) : atmosphere_(atmosphere), y0_(y0) {}
    Atmosphere atmosphere_;
    double y0_ = 0.0;
    double n_ = 1.0;                      // the index at y0
    double lo_up_ = 1.0, hi_up_ = 1.0;    // bounds of n over the heights a rising ray reaches
    double lo_down_ = 1.0, hi_down_ = 1.0;  // and a descending one
    std::variant<ExactRayOrigin, QuadraticStart> start_;
};

}  // namespace mirage
