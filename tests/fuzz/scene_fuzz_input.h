// What the fuzz target does with one input, shared by the libFuzzer harness
// (scene_fuzzer.cpp, make fuzz) and the replay of every input that ever crashed
// (fuzz_replay_test.cpp, under CTest with the normal build).
//
// The input is a scene file.  It is parsed strictly, and leniently when the strict parse
// refused something as unsupported; a scene that parses has its Mirage_ settings read and
// its camera checked as every command does (settle_mirage_scene), and a scene whose
// atmosphere is accepted has a few of its camera's exact rays built and sampled at its
// tolerance.  Anything a command would refuse must be
// refused with a message that names a place; everything accepted must give finite paths.
// A crash, a sanitizer report, a hang or an abort here is a bug.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "atmosphere/exact_ray.h"
#include "atmosphere/sampler.h"
#include "load/mirage_scene.h"
#include "scene/camera.h"
#include "scene/parser.h"

namespace mirage::fuzz {

/// The parse's limits, smaller than a command's so that each input runs in milliseconds;
/// what they guard is the same.
inline ParseLimits fuzz_limits() {
    ParseLimits l;
    l.max_loop_passes = 200;
    // A loop whose body is costly (an include file, a macro that calls others) reaches this
    // first: with the sanitizers 200 passes of such a body took 3.7 to 9.5 s.
    l.max_tokens = 100'000;
    l.max_array_elements = 10000;
    l.max_total_array_elements = 100000;
    l.max_objects = 5000;
    l.max_string_bytes = 1 << 16;
    return l;
}

[[noreturn]] inline void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz target: %s\n%s\n", what, detail.c_str());
    std::abort();
}

/// Every refusal names a place: "file: ..." or "file:line:column: ...".
inline void check_message(const std::string& message) {
    const std::string first = message.substr(0, message.find('\n'));
    if (first.empty() || first.find(": ") == std::string::npos)
        broken("an error without a place", message);
}

inline void check_path(const ExactRay& ray, const SampleSettings& st) {
    const SampledPath path = sample_path(ray, st);
    for (const auto& p : path.points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) broken("a sample that is not finite", "");
}

inline void check_scene_input(std::string_view text) {
    const std::string root = MIRAGE_SOURCE_DIR;
    bool strict_refused_unsupported = false;
    for (const bool strict : {true, false}) {
        // Lenient parsing differs from strict only where something is unsupported: it runs
        // when the strict parse refused something as unsupported (half the cost per input).
        if (!strict && !strict_refused_unsupported) break;
        ParseOptions po;
        po.library_paths = {root + "/pov_includes"};
        po.image_width = 64;
        po.image_height = 48;
        po.strict = strict;
        po.limits = fuzz_limits();
        auto parsed = parse_scene_text(text, "fuzz.pov", po);
        if (!parsed) {
            check_message(parsed.message());
            strict_refused_unsupported =
                strict && parsed.message().find(": unsupported ") != std::string::npos;
            continue;
        }
        SceneLoadOptions lo;
        lo.width = po.image_width;
        lo.height = po.image_height;
        auto settings = settle_mirage_scene(*parsed, lo);
        if (!settings) {
            check_message(settings.message());
            continue;
        }
        if (!settings->declared || !strict) continue;
        // The camera's rays through the centre column, as the tracer builds them.
        const Profile profile = profile_in_scene_units(*settings);
        const Camera& camera = parsed->camera;
        if (!(camera.location.y >= 0.0)) continue;
        SampleSettings st;
        st.tolerance_rad = settings->tolerance_px * pixel_angle_rad(camera, lo.width, lo.height);
        if (!(st.tolerance_rad >= kMinToleranceRad)) broken("a tolerance below the floor", "");
        for (const double row : {0.5, 0.5 * lo.height, lo.height - 0.5}) {
            const glm::dvec3 d =
                camera_ray(camera, 0.5 * lo.width, row, lo.width, lo.height).direction;
            const double hl = std::hypot(d.x, d.z);
            if (!(hl > 1e-12)) continue;
            auto ray = make_exact_ray(profile, camera.location.y, std::atan2(hl, d.y));
            if (!ray) broken("an accepted scene whose camera ray cannot be built", ray.message());
            check_path(*ray, st);
        }
    }
}

}  // namespace mirage::fuzz
