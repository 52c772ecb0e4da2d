#include "render/render.h"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "trace/scene_accel.h"
#include "util/check.h"
#include "util/progress.h"

namespace mirage {

namespace {

/// Processor time of the calling thread, seconds.
double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

double RenderStats::segments_per_ray() const {
    return rays() > 0 ? static_cast<double>(counters.segments) / static_cast<double>(rays()) : 0.0;
}

double RenderStats::queries_per_ray() const {
    return rays() > 0 ? static_cast<double>(counters.segment_queries) / static_cast<double>(rays())
                      : 0.0;
}

double RenderStats::mrays_per_second() const {
    return seconds > 0.0 ? static_cast<double>(all_rays()) / seconds * 1e-6 : 0.0;
}

Result<RenderResult> render(const Scene& scene, const RenderSettings& settings,
                            const Propagator& propagator, const PixelRayFunction& pixel_ray) {
    if (settings.width <= 0 || settings.height <= 0) {
        return make_error("image size must be positive, got " + std::to_string(settings.width) +
                          "x" + std::to_string(settings.height));
    }
    if (settings.tile_size <= 0) return make_error("tile size must be positive");
    if (auto s = check_antialias(settings.antialias); !s) return s.error();
    if (auto s = check_supported(scene); !s) return s.error();
    auto accel = SceneAccel::build(scene);
    if (!accel) return accel.error();
    // A degenerate camera would give NaN rays: refuse it before tracing.
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, std::pair{1.0 * settings.width, 0.0},
                               std::pair{0.0, 1.0 * settings.height},
                               std::pair{1.0 * settings.width, 1.0 * settings.height},
                               std::pair{0.5 * settings.width, 0.5 * settings.height}}) {
        const CameraRay r = pixel_ray(scene.camera, x, y, settings.width, settings.height);
        if (!r.traced) continue;  // a fisheye's corner: no ray there
        const bool finite = std::isfinite(r.origin.x) && std::isfinite(r.origin.y) &&
                            std::isfinite(r.origin.z) && std::isfinite(r.direction.x) &&
                            std::isfinite(r.direction.y) && std::isfinite(r.direction.z);
        if (!finite || std::abs(glm::length(r.direction) - 1.0) > 1e-9) {
            return make_error(scene.camera.loc,
                              "camera: its vectors give no ray direction (zero or "
                              "parallel direction, right and up?)");
        }
    }

    const auto start = std::chrono::steady_clock::now();
    const Shader shader(scene, *accel, propagator);
    const AntialiasSettings& aa = settings.antialias;
    // Antialiasing renders POV-Ray's blocks: method 1's comparisons at a block's edges depend
    // on where the blocks are.
    const int tile_size = aa.enabled() ? aa.block_size : settings.tile_size;
    const double aa_exponent = antialias_exponent(scene.global, aa.gamma);
    const int tiles_x = (settings.width + tile_size - 1) / tile_size;
    const int tiles_y = (settings.height + tile_size - 1) / tile_size;
    const int tile_count = tiles_x * tiles_y;
    int threads = settings.threads > 0 ? settings.threads
                                       : static_cast<int>(std::thread::hardware_concurrency());
    threads = std::clamp(threads, 1, std::max(1, tile_count));

    RenderResult result;
    result.image = Image(settings.width, settings.height);
    std::vector<TraceCounters> counters(threads);
    std::vector<AntialiasCounters> aa_counters(threads);
    std::vector<double> cpu(threads, 0.0);
    std::atomic<int> next_tile{0};
    ProgressBar progress("trace", tile_count, settings.progress);

    // Every pixel depends on nothing but its position, so the tiles can go in any order on
    // any thread and the image is the same.
    const auto work = [&](int thread) {
        const double cpu_start = thread_cpu_seconds();
        TraceCounters& mine = counters[thread];
        // The colour seen through an image position (pixels from the top-left corner), and
        // its transmit: 1 where the camera gives no ray, as POV-Ray marks it.
        const auto shade = [&](double x, double y) {
            const CameraRay ray = pixel_ray(scene.camera, x, y, settings.width, settings.height);
            if (!ray.traced) return glm::dvec4(0.0, 0.0, 0.0, 1.0);  // POV-Ray leaves it black
            RayStart start;
            start.origin = ray.origin;
            start.direction = ray.direction;
            start.image_position = glm::dvec2(x, y);
            const glm::dvec3 c = shader.trace_camera_ray(start, mine);
            MIRAGE_CHECK(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
            return glm::dvec4(c, 0.0);
        };
        const SampleFunction sample = shade;
        for (int tile = next_tile++; tile < tile_count; tile = next_tile++) {
            const int x0 = (tile % tiles_x) * tile_size;
            const int y0 = (tile / tiles_x) * tile_size;
            const int x1 = std::min(x0 + tile_size, settings.width);
            const int y1 = std::min(y0 + tile_size, settings.height);
            if (aa.enabled()) {
                antialias_block(aa, aa_exponent, {x0, y0, x1, y1}, sample, result.image,
                                aa_counters[thread]);
            } else {
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x)
                        result.image.set(x, y, glm::vec3(shade(x + 0.5, y + 0.5)));
            }
            progress.advance();
        }
        cpu[thread] = thread_cpu_seconds() - cpu_start;
    };
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (auto& t : pool) t.join();

    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.stats.threads = threads;
    for (const auto& c : counters) result.stats.counters.add(c);
    result.stats.antialiased = aa.enabled();
    for (const auto& c : aa_counters) result.stats.antialias.add(c);
    for (const double c : cpu) result.stats.cpu_seconds += c;
    return result;
}

Result<RenderResult> render(const Scene& scene, const RenderSettings& settings) {
    const StraightPropagator straight;
    return render(scene, settings, straight, camera_ray);
}

std::string format_stats(const RenderStats& stats, int width, int height) {
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(3);
    out << width << "x" << height << ": " << stats.rays() << " rays (" << stats.counters.camera_rays
        << " camera, " << stats.counters.reflected_rays << " reflected) + "
        << stats.counters.shadow_rays << " shadow, " << stats.segments_per_ray()
        << " segments/ray, " << stats.queries_per_ray() << " tested/ray, " << stats.seconds
        << " s, " << stats.cpu_seconds << " s CPU, " << stats.mrays_per_second() << " Mrays/s on "
        << stats.threads << " thread" << (stats.threads == 1 ? "" : "s");
    if (stats.antialiased) {
        out.precision(1);
        out << "; antialiased: " << stats.antialias.pixels_supersampled << " pixels supersampled ("
            << 100.0 * stats.antialias.supersampled_share() << " %), " << stats.antialias.samples
            << " positions sampled";
    }
    return out.str();
}

}  // namespace mirage
