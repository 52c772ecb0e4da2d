// Test helper for the shape tests: a scene parsed from SDL text with the tracer's
// acceleration built over it, and the queries those tests make of its first shape.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/parser.h"
#include "trace/scene_accel.h"

namespace mirage::testing {

struct Parsed {
    Scene scene;
    SceneAccel accel;
};

/// POV-Ray's own include files as the library path, for scenes that include them.
inline ParseOptions with_povray_includes() {
    ParseOptions options;
    options.library_paths = {"/usr/share/povray-3.7/include"};
    return options;
}

/// The scene and its acceleration; a parse or build failure fails the test that asked.
inline Parsed build(const std::string& text, const ParseOptions& options = ParseOptions{}) {
    auto scene = parse_scene_text(text, "scene.pov", options);
    EXPECT_TRUE(scene.ok()) << scene.message();
    if (!scene.ok()) return {};
    auto accel = SceneAccel::build(*scene);
    EXPECT_TRUE(accel.ok()) << accel.message();
    if (!accel.ok()) return {};
    return Parsed{std::move(*scene), std::move(*accel)};
}

/// Every hit of the scene's first shape along the ray from `o` towards `d`, nearest first.
inline std::vector<ShapeHit> sorted_hits(const Parsed& p, glm::dvec3 o, glm::dvec3 d) {
    std::vector<ShapeHit> h;
    intersect_shape_all(p.accel.shape(0), o, glm::normalize(d), 1e-4, 1e6, h);
    std::sort(h.begin(), h.end(), [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
    return h;
}

/// The depths of those hits.
inline std::vector<double> hit_depths(const Parsed& p, glm::dvec3 o, glm::dvec3 d) {
    std::vector<double> t;
    for (const auto& h : sorted_hits(p, o, d)) t.push_back(h.t);
    return t;
}

/// The scene's closest hit along the ray.
inline std::optional<SurfaceHit> shoot(const Parsed& p, glm::dvec3 o, glm::dvec3 d) {
    return p.accel.closest_hit(o, glm::normalize(d), 1e-4, 2e10);
}

}  // namespace mirage::testing
