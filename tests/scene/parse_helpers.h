// Helpers shared by the scene parser tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "scene/parser.h"
#include "trace/object_query.h"

namespace mirage::testing {

inline std::string data_dir() { return std::string(MIRAGE_SOURCE_DIR) + "/tests/scene/data"; }

inline const char* kPovRayIncludes = "/usr/share/povray-3.7/include";

/// The options with the tracer answering trace() and the like, as the commands give them.
inline ParseOptions with_object_queries(ParseOptions options) {
    if (!options.object_queries.trace) options.object_queries = tracer_object_queries();
    return options;
}

/// Parses `text` as "scene.pov"; fails the test (and returns an empty scene) on an error.
inline Scene parse_ok(const std::string& text, ParseOptions options = {}) {
    auto r = parse_scene_text(text, "scene.pov", with_object_queries(std::move(options)));
    EXPECT_TRUE(r.ok()) << (r.ok() ? std::string() : r.message());
    return r.ok() ? std::move(r).value() : Scene{};
}

/// The error message for `text` parsed as "scene.pov" ("" when it parses).
inline std::string parse_error(const std::string& text, ParseOptions options = {}) {
    auto r = parse_scene_text(text, "scene.pov", with_object_queries(std::move(options)));
    EXPECT_FALSE(r.ok()) << "parsed without error";
    return r.ok() ? std::string() : r.message();
}

inline double float_symbol(const Scene& s, const std::string& name) {
    auto it = s.symbols.find(name);
    if (it == s.symbols.end()) {
        ADD_FAILURE() << "no symbol " << name;
        return 0.0;
    }
    const double* v = std::get_if<double>(&it->second.value);
    if (!v) {
        ADD_FAILURE() << name << " is not a float";
        return 0.0;
    }
    return *v;
}

inline glm::dvec3 vector_symbol(const Scene& s, const std::string& name) {
    auto it = s.symbols.find(name);
    if (it == s.symbols.end()) {
        ADD_FAILURE() << "no symbol " << name;
        return glm::dvec3(0.0);
    }
    const glm::dvec3* v = std::get_if<glm::dvec3>(&it->second.value);
    if (!v) {
        ADD_FAILURE() << name << " is not a vector";
        return glm::dvec3(0.0);
    }
    return *v;
}

inline std::string string_symbol(const Scene& s, const std::string& name) {
    auto it = s.symbols.find(name);
    if (it == s.symbols.end()) {
        ADD_FAILURE() << "no symbol " << name;
        return {};
    }
    const std::string* v = std::get_if<std::string>(&it->second.value);
    if (!v) {
        ADD_FAILURE() << name << " is not a string";
        return {};
    }
    return *v;
}

/// Value of one float expression.
inline double eval(const std::string& expression) {
    Scene s = parse_ok("#declare R = " + expression + ";");
    return s.symbols.count("R") ? float_symbol(s, "R") : 0.0;
}

/// One string expression.
inline std::string eval_string(const std::string& expression) {
    Scene s = parse_ok("#declare R = " + expression + ";");
    return s.symbols.count("R") ? string_symbol(s, "R") : std::string();
}

inline void expect_vec(const glm::dvec3& got, const glm::dvec3& want, double tol = 1e-12) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

}  // namespace mirage::testing
