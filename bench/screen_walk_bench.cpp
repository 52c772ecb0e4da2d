// Benchmarks of the turbulent air's screens (docs/turbulence.md): one screen's tilt at
// independent points (throughput), and one ray walked through the whole stack, whose every
// crossing depends on the turns before it (the tracer's case: latency).  The air is
// scenes/shimmer_road.pov's: C_n^2 1e-12, l0 5 mm, L0 1 m, a 10 cm aperture, 16 screens over
// 3.6 km.
#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>
#include <vector>

#include "atmosphere/phase_screens.h"

namespace {

using namespace mirage;

PhaseScreens road_screens() {
    TurbulenceSettings ts;
    ts.cn2 = 1e-12;
    ts.inner_scale_m = 0.005;
    ts.outer_scale_m = 1.0;
    ts.wind = glm::dvec3(1.0, 0.2, 0.0);
    ts.seed = 3;
    ScreenLayout layout;
    layout.origin = glm::dvec3(0.0, 1.5, 0.0);
    layout.axis = glm::dvec3(0.0, 0.0, 1.0);
    layout.reach_m = 3610.0;
    layout.aperture_m = 0.1;
    return *PhaseScreens::make(ts, layout);
}

void BM_ScreenTilt(benchmark::State& state) {
    const PhaseScreens screens = road_screens();
    glm::dvec3 p(0.0, 1.5, screens.distance(7));
    glm::dvec3 sum(0.0);
    for (auto _ : state) {
        sum += screens.tilt(7, p, 0.5);
        p.x = p.x < 30.0 ? p.x + 0.0137 : -30.0;
    }
    benchmark::DoNotOptimize(sum);
    state.counters["modes"] = static_cast<double>(screens.modes(7).size());
}
BENCHMARK(BM_ScreenTilt);

// A camera ray of the road's 1.2-degree view, walked from the eye through all 16 screens.
void BM_ScreenWalk(benchmark::State& state) {
    const PhaseScreens screens = road_screens();
    std::vector<glm::dvec3> points;
    double x = -0.01;
    for (auto _ : state) {
        ScreenWalk walk(screens, 0.5, glm::dvec3(0.0, 1.5, 0.0));
        walk.ray(glm::normalize(glm::dvec3(x, 0.001, 1.0)), points);
        benchmark::DoNotOptimize(points.data());
        x = x < 0.01 ? x + 3.3e-5 : -0.01;
    }
    state.counters["screens"] = static_cast<double>(points.size());
}
BENCHMARK(BM_ScreenWalk);

}  // namespace
