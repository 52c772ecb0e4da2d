// What a path can meet, as one ray's vertical plane sees a scene: rectangles (the cuts of boxes),
// counting the questions asked.  For the tests of both near samplers (sampler.h, path_sampler.h).
#pragma once

#include <utility>
#include <vector>

#include "atmosphere/sampler.h"

namespace mirage::testing {

class Rectangles final : public PathObstacles {
  public:
    struct Rect {
        double dz_lo, dz_hi, y_lo, y_hi;
    };
    explicit Rectangles(std::vector<Rect> rects, bool ground = false)
        : rects_(std::move(rects)), ground_(ground) {}
    bool may_meet(const PathRegion& region) const override {
        ++asked_;
        for (const Rect& r : rects_) {
            if (region_meets_rectangle(region, r.dz_lo, r.dz_hi, r.y_lo, r.y_hi)) return true;
        }
        return false;
    }
    bool ground() const override { return ground_; }
    const std::vector<Rect>& rects() const { return rects_; }
    int asked() const { return asked_; }

  private:
    std::vector<Rect> rects_;
    bool ground_;
    mutable int asked_ = 0;
};

}  // namespace mirage::testing
