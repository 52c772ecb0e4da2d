#include "compare/tradeoff.h"

#include <algorithm>
#include <cmath>

namespace mirage {

std::vector<TradeoffPoint> pareto_front(std::vector<TradeoffPoint> points) {
    std::erase_if(points, [](const TradeoffPoint& p) {
        return !(std::isfinite(p.seconds) && p.seconds > 0.0 && std::isfinite(p.error) &&
                 p.error >= 0.0);
    });
    // By time, and at equal time the smaller error first, so that it is the one kept.
    std::stable_sort(
        points.begin(), points.end(), [](const TradeoffPoint& x, const TradeoffPoint& y) {
            return x.seconds < y.seconds || (x.seconds == y.seconds && x.error < y.error);
        });
    std::vector<TradeoffPoint> front;
    for (const auto& p : points)
        if (front.empty() || p.error < front.back().error * (1.0 - kMinErrorGain))
            front.push_back(p);
    return front;
}

std::optional<TimeAtError> seconds_at_error(const std::vector<TradeoffPoint>& front, double error) {
    if (front.empty() || !(error >= front.back().error)) return std::nullopt;
    if (error >= front.front().error) {
        const TradeoffPoint& p = front.front();
        return TimeAtError{p.seconds, p.label, p.label, error > p.error};
    }
    // front[i - 1].error > error >= front[i].error.
    size_t i = 1;
    while (front[i].error > error) ++i;
    const TradeoffPoint& coarse = front[i - 1];
    const TradeoffPoint& fine = front[i];
    if (error == fine.error) return TimeAtError{fine.seconds, fine.label, fine.label, false};
    const double u = fine.error > 0.0
                         ? std::log(coarse.error / error) / std::log(coarse.error / fine.error)
                         : (coarse.error - error) / coarse.error;
    const double seconds =
        std::exp(std::log(coarse.seconds) + u * std::log(fine.seconds / coarse.seconds));
    return TimeAtError{seconds, coarse.label, fine.label, false};
}

std::optional<EqualError> compare_at_equal_error(const std::vector<TradeoffPoint>& a,
                                                 const std::vector<TradeoffPoint>& b) {
    if (a.empty() || b.empty()) return std::nullopt;
    const double error = std::max(a.back().error, b.back().error);
    auto ta = seconds_at_error(a, error);
    auto tb = seconds_at_error(b, error);
    if (!ta || !tb) return std::nullopt;
    return EqualError{error, *ta, *tb};
}

}  // namespace mirage
