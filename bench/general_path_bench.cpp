// The general (piecewise-quadratic) exact-path engine against the exponential closed forms on
// the same air: a whole fan of 240 camera rays built, or built and sampled, per iteration (every
// case traces the same rays; `ray` is the time per ray, and instruction counts per ray under
// callgrind divide by a whole number of fans).  The road: hot-road air (eye 1.5 m, -0.5 to +0.5
// degrees, to 500 m), its exponential profile through the closed forms (exact_ray.h + sampler.h,
// today's path) and the same exponential fitted by the general engine (quadratic_path.h +
// path_sampler.h) at the default |dn| <= 1e-10 and at 1e-12 (the _fine cases); and the temperature
// profile it was fitted to, T = 300 K + 20 K exp(-y/0.3 m) by Gladstone-Dale with the hydrostatic
// pressure, through the general engine.  The desert: the paper's profile, eye 1.5 m, +-23.5
// degrees, to 60 m.  The tolerance is an angle seen from the eye in micro-radians.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "atmosphere/exact_path.h"
#include "atmosphere/exact_ray.h"
#include "atmosphere/general_profile.h"
#include "atmosphere/path_sampler.h"
#include "atmosphere/sampler.h"

namespace {

using namespace mirage;

struct Fan {
    double y0, from, to, max_dz;
};

const Fan kRoad{1.5, -0.0087, 0.0087, 500.0};
const Fan kDesert{1.5, -0.41, 0.41, 60.0};

double elevation(const Fan& f, int j, int n) { return f.from + (f.to - f.from) * (j + 0.5) / n; }

std::shared_ptr<const QuadraticProfile> fitted(const AirSpec& spec, double tolerance_n,
                                               bool spans) {
    FitSettings fs;
    fs.tolerance_n = tolerance_n;
    fs.coarse_spans = spans;
    return *fit_air(spec, fs);
}

Atmosphere exponential_fitted(const char* preset, double tolerance_n = FitSettings{}.tolerance_n,
                              bool spans = false) {
    AirSpec spec;
    spec.source = AirSpec::Source::Exponential;
    spec.exponential = *preset_profile(preset);
    return Atmosphere::quadratic(fitted(spec, tolerance_n, spans));
}

Atmosphere hot_road_temperatures(double tolerance_n = FitSettings{}.tolerance_n,
                                 bool spans = false) {
    AirSpec spec;
    spec.column.ground_temperature_k = 300.0;
    spec.column.layers.push_back({20.0, 0.3});
    return Atmosphere::quadratic(fitted(spec, tolerance_n, spans));
}

constexpr int kFanRays = 240;

void per_ray_counters(benchmark::State& state, double samples) {
    const double rays = double(state.iterations()) * kFanRays;
    state.counters["ray"] =
        benchmark::Counter(rays, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["samples_per_ray"] = samples / rays;
}

// Today's path: closed forms and sampler.h.
void BM_ClosedForm(benchmark::State& state, const char* preset, Fan fan, bool sample) {
    const Profile p = *preset_profile(preset);
    SampleSettings st;
    st.tolerance_rad = state.range(0) * 1e-6;
    st.max_dz = fan.max_dz;
    double samples = 0.0;
    for (auto _ : state) {
        for (int j = 0; j < kFanRays; ++j) {
            auto ray = make_exact_ray(p, fan.y0, M_PI / 2 - elevation(fan, j, kFanRays));
            if (sample) {
                auto path = sample_path(*ray, st);
                samples += path.points.size();
                benchmark::DoNotOptimize(path);
            }
            benchmark::DoNotOptimize(ray);
        }
    }
    per_ray_counters(state, samples);
}

// The common interface (exact_path.h) and path_sampler.h, on any atmosphere.
void BM_General(benchmark::State& state, Atmosphere (*make)(), Fan fan, bool sample) {
    const Atmosphere atm = make();
    SampleSettings st;
    st.tolerance_rad = state.range(0) * 1e-6;
    st.max_dz = fan.max_dz;
    double samples = 0.0;
    for (auto _ : state) {
        for (int j = 0; j < kFanRays; ++j) {
            auto path = ExactPath::make(atm, fan.y0, M_PI / 2 - elevation(fan, j, kFanRays));
            if (sample) {
                auto poly = sample_exact_path(*path, st);
                samples += poly.points.size();
                benchmark::DoNotOptimize(poly);
            }
            benchmark::DoNotOptimize(path);
        }
    }
    per_ray_counters(state, samples);
    if (auto q = atm.quadratic_profile()) state.counters["pieces"] = q->piece_count();
}

// The tracer's way in (trace/curved_propagator.cpp): one PathOrigin per start height, each
// ray's path written into the same storage, and sample_path over ExactPath, which samples an
// exponential ray with sampler.h's closed-form sampler.  On the exponential profiles this is
// to be as fast as BM_ClosedForm, the closed forms called directly.
void BM_OneInterface(benchmark::State& state, Atmosphere (*make)(), Fan fan) {
    const Atmosphere atm = make();
    SampleSettings st;
    st.tolerance_rad = state.range(0) * 1e-6;
    st.max_dz = fan.max_dz;
    const PathOrigin origin = *PathOrigin::make(atm, fan.y0);
    std::optional<ExactPath> path;
    double samples = 0.0;
    for (auto _ : state) {
        for (int j = 0; j < kFanRays; ++j) {
            const double e = elevation(fan, j, kFanRays);
            origin.path(std::sin(e), std::cos(e), path);
            auto poly = sample_path(*path, st);
            samples += poly.points.size();
            benchmark::DoNotOptimize(poly);
        }
    }
    per_ray_counters(state, samples);
}

Atmosphere road_exponential() { return Atmosphere::exponential(*preset_profile("hot-road")); }
Atmosphere road_fitted() { return exponential_fitted("hot-road"); }
Atmosphere road_fitted_fine() { return exponential_fitted("hot-road", 1e-12); }
Atmosphere road_temperatures() { return hot_road_temperatures(); }
Atmosphere road_temperatures_fine() { return hot_road_temperatures(1e-12); }
Atmosphere road_fitted_spans() { return exponential_fitted("hot-road", 1e-10, true); }
Atmosphere road_temperatures_spans() { return hot_road_temperatures(1e-10, true); }
Atmosphere road_fitted_fine_spans() { return exponential_fitted("hot-road", 1e-12, true); }
Atmosphere road_temperatures_fine_spans() { return hot_road_temperatures(1e-12, true); }
Atmosphere desert_fitted_spans() { return exponential_fitted("paper", 1e-10, true); }
Atmosphere desert_exponential() { return Atmosphere::exponential(*preset_profile("paper")); }
Atmosphere desert_fitted() { return exponential_fitted("paper"); }

BENCHMARK_CAPTURE(BM_ClosedForm, road_build, "hot-road", kRoad, false)->Arg(18);
BENCHMARK_CAPTURE(BM_General, road_fitted_build, road_fitted, kRoad, false)->Arg(18);
BENCHMARK_CAPTURE(BM_General, road_temperatures_build, road_temperatures, kRoad, false)->Arg(18);

BENCHMARK_CAPTURE(BM_ClosedForm, road_sampled, "hot-road", kRoad, true)->Arg(100)->Arg(18)->Arg(3);
BENCHMARK_CAPTURE(BM_General, road_closed_form_via_interface, road_exponential, kRoad, true)
    ->Arg(100)
    ->Arg(18)
    ->Arg(3);
BENCHMARK_CAPTURE(BM_General, road_fitted_sampled, road_fitted, kRoad, true)
    ->Arg(100)
    ->Arg(18)
    ->Arg(3);
BENCHMARK_CAPTURE(BM_General, road_temperatures_sampled, road_temperatures, kRoad, true)
    ->Arg(100)
    ->Arg(18)
    ->Arg(3);
BENCHMARK_CAPTURE(BM_General, road_fitted_fine_sampled, road_fitted_fine, kRoad, true)->Arg(18);
BENCHMARK_CAPTURE(BM_General, road_temperatures_fine_sampled, road_temperatures_fine, kRoad, true)
    ->Arg(18);

// The same with the coarse spans a steep ray crosses in place of the fine pieces (what
// mirage trace fits).
BENCHMARK_CAPTURE(BM_General, road_fitted_spans_sampled, road_fitted_spans, kRoad, true)
    ->Arg(100)
    ->Arg(18)
    ->Arg(3);
BENCHMARK_CAPTURE(BM_General, road_temperatures_spans_sampled, road_temperatures_spans, kRoad, true)
    ->Arg(100)
    ->Arg(18)
    ->Arg(3);
BENCHMARK_CAPTURE(BM_General, road_fitted_fine_spans_sampled, road_fitted_fine_spans, kRoad, true)
    ->Arg(18);
BENCHMARK_CAPTURE(BM_General, road_temperatures_fine_spans_sampled, road_temperatures_fine_spans,
                  kRoad, true)
    ->Arg(18);

BENCHMARK_CAPTURE(BM_ClosedForm, desert_sampled, "paper", kDesert, true)->Arg(1700)->Arg(340);
BENCHMARK_CAPTURE(BM_General, desert_fitted_sampled, desert_fitted, kDesert, true)
    ->Arg(1700)
    ->Arg(340);
BENCHMARK_CAPTURE(BM_General, desert_fitted_spans_sampled, desert_fitted_spans, kDesert, true)
    ->Arg(1700)
    ->Arg(340);
BENCHMARK_CAPTURE(BM_General, desert_closed_form_via_interface, desert_exponential, kDesert, true)
    ->Arg(1700)
    ->Arg(340);

BENCHMARK_CAPTURE(BM_OneInterface, road_exponential, road_exponential, kRoad)
    ->Arg(100)
    ->Arg(18)
    ->Arg(3);
BENCHMARK_CAPTURE(BM_OneInterface, desert_exponential, desert_exponential, kDesert)
    ->Arg(1700)
    ->Arg(340);
BENCHMARK_CAPTURE(BM_OneInterface, road_fitted_spans, road_fitted_spans, kRoad)->Arg(18);

}  // namespace
