// What a path can meet, as one ray's vertical plane sees a scene: rectangles (the cuts of boxes),
// counting the questions asked.  For the tests of both near samplers (sampler.h, path_sampler.h).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "atmosphere/sampler.h"

namespace mirage::testing {

class Rectangles final : public PathObstacles {
  public:
    struct Rect {
        double dz_lo, dz_hi, y_lo, y_hi;
    };
    /// knows_reach: the rectangles tell how far they reach (reach()), as a scene does.
    explicit Rectangles(std::vector<Rect> rects, bool ground = false, bool knows_reach = false)
        : rects_(std::move(rects)), ground_(ground), knows_reach_(knows_reach) {}
    bool may_meet(const PathRegion& region) const override {
        ++asked_;
        for (const Rect& r : rects_) {
            if (region_meets_rectangle(region, r.dz_lo, r.dz_hi, r.y_lo, r.y_hi)) return true;
        }
        return false;
    }
    bool ground() const override { return ground_; }
    double reach() const override {
        if (!knows_reach_) return PathObstacles::reach();
        double r = 0.0;
        for (const Rect& rect : rects_) r = std::max(r, rect.dz_hi);
        return r;
    }
    const std::vector<Rect>& rects() const { return rects_; }
    int asked() const { return asked_; }

  private:
    std::vector<Rect> rects_;
    bool ground_;
    bool knows_reach_;
    mutable int asked_ = 0;
};

}  // namespace mirage::testing
