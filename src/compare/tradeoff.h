// Error against run time: the settings of one model as a curve, and two models compared at
// the same error by interpolating each curve in log-log between neighbouring points.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mirage {

/// One setting of a model: how long it took and how wrong it was.
struct TradeoffPoint {
    double seconds = 0.0;
    double error = 0.0;  // RMSE against the reference, or any error where lower is better
    std::string label;   // the setting, for messages ("64 layers", "0.5 px")
};

/// A slower setting must lower the error by more than this share to stay on a front: on the
/// flat tail of a curve, differences of a few pixels out of tens of thousands would otherwise
/// decide which time is quoted for the lowest error.
constexpr double kMinErrorGain = 0.01;

/// The points that no other point beats in both time and error, sorted by time (so their
/// error falls strictly).  A setting that took longer for no less error, or for less than
/// kMinErrorGain less, is dropped: it is not how anyone would reach that error.  Points with a
/// non-finite or negative value, or no time, are dropped too.
std::vector<TradeoffPoint> pareto_front(std::vector<TradeoffPoint> points);

/// The time a curve needs to reach `error`.
struct TimeAtError {
    double seconds = 0.0;
    std::string from, to;  // the neighbouring points interpolated between (equal at a point)
    bool at_most = false;  // the curve's fastest point is already below `error`: its time is
                           // an upper bound, the curve does not say how much less would do
};

/// Interpolates log(seconds) linearly in log(error) between the two neighbouring points of a
/// Pareto front (from `pareto_front`) that bracket `error`; linearly in error when the finer
/// point has error 0.  Nothing when the front never gets down to `error`.
std::optional<TimeAtError> seconds_at_error(const std::vector<TradeoffPoint>& front, double error);

/// Two models at the same error: the lowest error both fronts reach.
struct EqualError {
    double error = 0.0;
    TimeAtError a, b;
    double speedup() const { return a.seconds / b.seconds; }  // how many times faster b is
};

/// Compares fronts `a` and `b` at the lowest error both reach (the larger of their smallest
/// errors); nothing when either is empty.
std::optional<EqualError> compare_at_equal_error(const std::vector<TradeoffPoint>& a,
                                                 const std::vector<TradeoffPoint>& b);

}  // namespace mirage
