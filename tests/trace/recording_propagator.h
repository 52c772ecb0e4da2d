// Test helper: a propagator that follows rays along curved paths and records every ray the
// shader hands it (the rays in the air) with its hit, so a test can check where the shader
// starts reflected and refracted rays.
#pragma once

#include <mutex>
#include <vector>

#include "trace/curved_propagator.h"

namespace mirage::testing {

class RecordingPropagator final : public Propagator {
  public:
    explicit RecordingPropagator(const CurvedSettings& s) : curved_(s) {}
    PathHit propagate(const SceneAccel& accel, const RayStart& start) const override {
        PathHit hit = curved_.propagate(accel, start);
        std::lock_guard<std::mutex> lock(mutex_);
        starts.push_back(start);
        hits.push_back(hit);
        return hit;
    }
    // In the order propagated (a test tracing one camera ray at a time reads them in order).
    mutable std::vector<RayStart> starts;
    mutable std::vector<PathHit> hits;

  private:
    CurvedPropagator curved_;
    mutable std::mutex mutex_;
};

}  // namespace mirage::testing
