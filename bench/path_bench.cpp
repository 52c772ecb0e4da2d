// Benchmarks of the path kernels: one exact evaluation, one sampled polyline, and the number
// of samples per ray at each tolerance (reported as a counter).
#include <benchmark/benchmark.h>

#include <cmath>

#include "atmosphere/exact_ray.h"
#include "atmosphere/sampler.h"

namespace {

using namespace mirage;

// A fan of camera rays of the desert scene (paper profile, eye 1.5 m, 47 degrees).
std::vector<ExactRay> fan(const char* preset, double y0, double from, double to, int n) {
    std::vector<ExactRay> rays;
    for (int j = 0; j < n; ++j) {
        const double e = from + (to - from) * (j + 0.5) / n;
        rays.push_back(*make_exact_ray(*preset_profile(preset), y0, M_PI / 2 - e));
    }
    return rays;
}

void BM_MakeExactRay(benchmark::State& state) {
    const Profile p = *preset_profile("paper");
    double e = -0.2;
    for (auto _ : state) {
        auto r = make_exact_ray(p, 1.5, M_PI / 2 - e);
        benchmark::DoNotOptimize(r);
        e = e < 0.2 ? e + 1e-4 : -0.2;
    }
}
BENCHMARK(BM_MakeExactRay);

void BM_HeightAt(benchmark::State& state) {
    const auto rays = fan("paper", 1.5, -0.4, 0.4, 256);
    size_t k = 0;
    double dz = 0.0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(height_at(rays[k], dz));
        k = (k + 1) & 255;
        dz = dz < 50.0 ? dz + 0.37 : 0.0;
    }
}
BENCHMARK(BM_HeightAt);

// One sampled polyline per iteration; the tolerance is an angle seen from the eye in
// micro-radians (one pixel of the desert scene at 320x240 is 3400 urad).
void BM_SamplePath(benchmark::State& state, const char* preset, double from, double to,
                   double max_dz) {
    const auto rays = fan(preset, 1.5, from, to, 240);
    SampleSettings st;
    st.tolerance_rad = state.range(0) * 1e-6;
    st.max_dz = max_dz;
    size_t k = 0;
    double samples = 0.0;
    for (auto _ : state) {
        auto p = sample_path(rays[k], st);
        samples += p.points.size();
        benchmark::DoNotOptimize(p);
        k = (k + 1) % rays.size();
    }
    state.counters["samples_per_ray"] = samples / state.iterations();
}
BENCHMARK_CAPTURE(BM_SamplePath, desert, "paper", -0.41, 0.41, 60.0)
    ->Arg(10000)
    ->Arg(1700)
    ->Arg(340)
    ->Arg(34)
    ->Arg(3);
BENCHMARK_CAPTURE(BM_SamplePath, road, "hot-road", -0.0087, 0.0087, 500.0)
    ->Arg(100)
    ->Arg(18)
    ->Arg(3)
    ->Arg(1);

}  // namespace
