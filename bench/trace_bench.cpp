// Speed of the built-in tracer: Mrays/s rendering a parity scene (checker plane, shiny and
// reflecting spheres, box, cylinder, disc, gradient sky, two lights), the cost of the scene
// queries alone, and `mirage trace` on scenes/desert.pov with straight rays, per-ray paths
// and per-scanline paths.  Run: build/mirage_bench --benchmark_filter=Trace
#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <thread>

#include "render/render.h"
#include "trace/scene_accel.h"
#include "trace_scene/trace_scene.h"

namespace mirage {
namespace {

Transform make_transform(const glm::dmat4& m) { return Transform{m, glm::inverse(m)}; }

Primitive prim(Shape shape, const glm::dvec3& rgb, const Finish& finish, const Transform& t = {}) {
    Primitive p;
    p.shape = shape;
    p.texture.pigment.colour.rgb = rgb;
    p.texture.finish = finish;
    p.transform = t;
    return p;
}

Scene bench_scene() {
    Scene s;
    s.camera.location = glm::dvec3(0.0, 1.6, -7.0);
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.0, 0.9, 0.0) - s.camera.location);
    s.camera.direction = 1.5 * d;
    s.camera.right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), d)) * (4.0 / 3.0);
    s.camera.up = glm::normalize(glm::cross(d, s.camera.right));
    PointLight a;
    a.location = glm::dvec3(-5.0, 8.0, -6.0);
    PointLight b;
    b.location = glm::dvec3(6.0, 5.0, -3.0);
    b.colour = glm::dvec3(0.5, 0.45, 0.4);
    s.lights = {a, b};

    Finish plain;
    Primitive ground = prim(Plane{{0.0, 1.0, 0.0}, 0.0}, glm::dvec3(1.0), plain);
    ground.texture.pigment.kind = PigmentKind::Checker;
    ground.texture.pigment.checker[0].rgb = glm::dvec3(0.9, 0.9, 0.85);
    ground.texture.pigment.checker[1].rgb = glm::dvec3(0.15, 0.2, 0.35);
    s.primitives.push_back(ground);
    Finish shiny;
    shiny.specular = 0.6;
    shiny.roughness = 0.02;
    shiny.reflection = glm::dvec3(0.25);
    s.primitives.push_back(prim(Sphere{{-1.6, 1.0, 0.5}, 1.0}, {0.8, 0.15, 0.1}, shiny));
    Finish phong;
    phong.phong = 0.9;
    s.primitives.push_back(prim(Sphere{{1.3, 0.7, -0.6}, 0.7}, {0.1, 0.25, 0.85}, phong));
    Finish mirror;
    mirror.reflection = glm::dvec3(0.6);
    s.primitives.push_back(prim(Sphere{{0.1, 0.45, -1.8}, 0.45}, {0.7, 0.7, 0.7}, mirror));
    const glm::dmat4 box_t = glm::translate(glm::dmat4(1.0), glm::dvec3(2.3, 0.0, 1.8)) *
                             glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(0, 1, 0));
    s.primitives.push_back(prim(Box{{-0.5, 0.0, -0.5}, {0.5, 0.8, 0.5}}, {0.2, 0.7, 0.25}, plain,
                                make_transform(box_t)));
    s.primitives.push_back(
        prim(Cylinder{{0.0, 0.0, 2.5}, {0.0, 1.6, 2.5}, 0.3, false}, {0.9, 0.5, 0.1}, plain));
    s.primitives.push_back(
        prim(Disc{{-3.2, 1.2, 2.5}, {0.3, 0.0, -1.0}, 0.9, 0.3}, {0.9, 0.85, 0.1}, plain));
    SkySphere sky;
    Pigment g;
    g.kind = PigmentKind::Gradient;
    g.colour_map = {{0.0, Colour{glm::dvec3(0.9, 0.9, 1.0)}},
                    {1.0, Colour{glm::dvec3(0.2, 0.35, 0.8)}}};
    sky.pigments.push_back(g);
    s.sky_sphere = sky;
    return s;
}

/// Renders the scene at 320x240; reports rays (camera + reflected + shadow) per second.
void BM_TraceRender(benchmark::State& state) {
    const Scene scene = bench_scene();
    RenderSettings settings;
    settings.width = 320;
    settings.height = 240;
    settings.threads = static_cast<int>(state.range(0));
    settings.progress = false;
    std::uint64_t rays = 0;
    double seconds = 0.0;
    for (auto _ : state) {
        auto result = render(scene, settings);
        if (!result.ok()) {
            state.SkipWithError(result.message().c_str());
            return;
        }
        rays += result->stats.all_rays();
        seconds += result->stats.seconds;
        benchmark::DoNotOptimize(result->image.pixels.data());
    }
    state.counters["Mrays/s"] = benchmark::Counter(static_cast<double>(rays) / seconds * 1e-6);
    state.counters["rays/frame"] =
        benchmark::Counter(static_cast<double>(rays) / static_cast<double>(state.iterations()));
    state.counters["threads"] = settings.threads;
}
BENCHMARK(BM_TraceRender)
    ->Arg(1)
    ->Arg(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// Random closest-hit queries against the scene, as a propagator issues them per segment.
void BM_TraceClosestHit(benchmark::State& state) {
    const Scene scene = bench_scene();
    auto accel = SceneAccel::build(scene);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> rays(4096);
    for (auto& [o, d] : rays) {
        o = glm::dvec3(3.0 * u(rng), 1.0 + u(rng), -6.0 + u(rng));
        d = glm::normalize(glm::dvec3(0.4 * u(rng), 0.3 * u(rng) - 0.1, 1.0));
    }
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& [o, d] = rays[i++ & 4095];
        benchmark::DoNotOptimize(accel->closest_hit(o, d, 1e-4, 2e10));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TraceClosestHit);

/// `mirage trace scenes/desert.pov -W W -H H` with straight rays (--no-atmosphere), per-ray
/// paths or per-scanline paths (--scanline-paths), on all cores; reports Mrays/s of the
/// render (camera, reflected and shadow rays over the tracing's wall-clock time, parsing
/// excluded) and the segments per propagated ray.
void BM_TraceDesert(benchmark::State& state) {
    TraceOptions o;
    o.scene = std::string(MIRAGE_SOURCE_DIR) + "/scenes/desert.pov";
    o.width = static_cast<int>(state.range(1));
    o.height = o.width * 3 / 4;
    o.progress = false;
    const int mode = static_cast<int>(state.range(0));
    o.atmosphere = mode != 0;
    o.scanline_paths = mode == 2;
    std::uint64_t rays = 0;
    double seconds = 0.0;
    double segments = 0.0;
    for (auto _ : state) {
        auto traced = trace_scene(o);
        if (!traced.ok()) {
            state.SkipWithError(traced.message().c_str());
            return;
        }
        const RenderStats& st = traced->render.stats;
        rays += st.all_rays();
        seconds += st.seconds;
        segments = st.segments_per_ray();
        state.SetIterationTime(st.seconds);
    }
    state.SetLabel(mode == 0 ? "straight" : mode == 1 ? "per-ray paths" : "scanline paths");
    state.counters["Mrays/s"] = benchmark::Counter(static_cast<double>(rays) / seconds * 1e-6);
    state.counters["rays/frame"] =
        benchmark::Counter(static_cast<double>(rays) / static_cast<double>(state.iterations()));
    state.counters["segments/ray"] = segments;
}
BENCHMARK(BM_TraceDesert)
    ->ArgNames({"mode", "width"})
    ->Args({0, 640})
    ->Args({1, 640})
    ->Args({2, 640})
    ->Args({1, 320})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();

}  // namespace
}  // namespace mirage
