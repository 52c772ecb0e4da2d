// Test helper: the POV-Ray 3.7 scene file of a Scene of the supported subset, written with
// explicit camera vectors and matrices, so POV-Ray renders exactly the scene the tracer sees.
#pragma once

#include <cstdio>
#include <sstream>
#include <string>
#include <variant>

#include "scene/scene.h"

namespace mirage::testing {

inline std::string num(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}
inline std::string vec(const glm::dvec3& v) {
    return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">";
}
inline std::string colour(const Colour& c) {
    return "rgbft <" + num(c.rgb.x) + ", " + num(c.rgb.y) + ", " + num(c.rgb.z) + ", " +
           num(c.filter) + ", " + num(c.transmit) + ">";
}
/// POV-Ray's matrix keyword: <m00, m01, m02, ..., m30, m31, m32> with p' = p M (row vector);
/// its m[i][j] is glm's m[i][j] (column i, row j).
inline std::string matrix(const glm::dmat4& m) {
    std::string out = "matrix <";
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 3; ++j) {
            out += num(m[i][j]);
            if (i != 3 || j != 2) out += ", ";
        }
    }
    return out + ">";
}

/// The shortest exact form: nothing for the identity, `translate` for a translation (POV-Ray
/// then keeps spheres and planes untransformed, as the tracer does), else `matrix`.
inline std::string transform_text(const glm::dmat4& m) {
    bool identity_linear = true;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) identity_linear &= m[i][j] == (i == j ? 1.0 : 0.0);
    }
    if (!identity_linear) return matrix(m);
    if (m[3][0] == 0.0 && m[3][1] == 0.0 && m[3][2] == 0.0) return "";
    return "translate " + vec(glm::dvec3(m[3]));
}

inline std::string pigment_text(const Pigment& p) {
    std::ostringstream out;
    out << "pigment { ";
    switch (p.kind) {
        case PigmentKind::Solid:
            out << colour(p.colour);
            break;
        case PigmentKind::Checker:
            out << "checker " << colour(p.checker[0]) << " " << colour(p.checker[1]) << " "
                << transform_text(p.transform.matrix);
            break;
        case PigmentKind::Gradient:
            out << "gradient " << vec(p.gradient_axis) << " ";
            if (!p.colour_map.empty()) {
                out << "color_map { ";
                for (const auto& e : p.colour_map) {
                    out << "[" << num(e.position) << " " << colour(e.colour) << "] ";
                }
                out << "} ";
            }
            out << transform_text(p.transform.matrix);
            break;
        default:
            out << "/* pattern not written */";
            break;
    }
    out << " }";
    return out.str();
}

inline std::string finish_text(const Finish& f) {
    std::ostringstream out;
    out << "finish { ambient rgb " << vec(f.ambient) << " emission rgb " << vec(f.emission)
        << " diffuse " << num(f.diffuse) << " brilliance " << num(f.brilliance) << " specular "
        << num(f.specular) << " roughness " << num(f.roughness) << " phong " << num(f.phong)
        << " phong_size " << num(f.phong_size) << " reflection rgb " << vec(f.reflection) << " }";
    return out.str();
}

inline std::string scene_to_pov(const Scene& s) {
    std::ostringstream out;
    out << "#version 3.7;\n";
    out << "global_settings { assumed_gamma 1.0 max_trace_level " << s.global.max_trace_level
        << " ambient_light rgb " << vec(s.global.ambient_light) << " }\n";
    const Camera& c = s.camera;
    out << "camera { perspective location " << vec(c.location) << " direction " << vec(c.direction)
        << " right " << vec(c.right) << " up " << vec(c.up) << " }\n";
    out << "background { " << colour(s.background) << " }\n";
    if (s.sky_sphere) {
        out << "sky_sphere {\n";
        for (const auto& p : s.sky_sphere->pigments) out << "  " << pigment_text(p) << "\n";
        out << "  emission rgb " << vec(s.sky_sphere->emission) << "\n";
        out << "  " << transform_text(s.sky_sphere->transform.matrix) << "\n}\n";
    }
    for (const auto& l : s.lights) {
        out << "light_source { " << vec(l.location) << " color rgb " << vec(l.colour)
            << (l.shadowless ? " shadowless" : "") << " }\n";
    }
    for (const auto& p : s.primitives) {
        std::visit(
            [&](const auto& shape) {
                using T = std::decay_t<decltype(shape)>;
                if constexpr (std::is_same_v<T, Sphere>) {
                    out << "sphere { " << vec(shape.center) << ", " << num(shape.radius);
                } else if constexpr (std::is_same_v<T, Plane>) {
                    out << "plane { " << vec(shape.normal) << ", " << num(shape.distance);
                } else if constexpr (std::is_same_v<T, Box>) {
                    out << "box { " << vec(shape.corner1) << ", " << vec(shape.corner2);
                } else if constexpr (std::is_same_v<T, Cylinder>) {
                    out << "cylinder { " << vec(shape.base) << ", " << vec(shape.cap) << ", "
                        << num(shape.radius) << (shape.open ? " open" : "");
                } else if constexpr (std::is_same_v<T, Disc>) {
                    out << "disc { " << vec(shape.center) << ", " << vec(shape.normal) << ", "
                        << num(shape.radius) << ", " << num(shape.hole_radius);
                } else if constexpr (std::is_same_v<T, Cone>) {
                    out << "cone { " << vec(shape.base) << ", " << num(shape.base_radius) << ", "
                        << vec(shape.cap) << ", " << num(shape.cap_radius)
                        << (shape.open ? " open" : "");
                } else if constexpr (std::is_same_v<T, Torus>) {
                    out << "torus { " << num(shape.major) << ", " << num(shape.minor)
                        << (shape.sturm ? " sturm" : "");
                } else if constexpr (std::is_same_v<T, Quadric>) {
                    out << "quadric { " << vec(shape.square) << ", " << vec(shape.mixed) << ", "
                        << vec(shape.linear) << ", " << num(shape.constant);
                } else {
                    ADD_FAILURE() << "pov_writer: no writer for " << shape_keyword(shape);
                    out << "sphere { 0, 1";
                }
            },
            p.shape);
        // The object's transform first, then the texture: its pigment transform is the whole
        // of it, as the Scene holds it.
        out << "\n  " << transform_text(p.transform.matrix) << "\n  texture { "
            << pigment_text(p.texture.pigment) << "\n    " << finish_text(p.texture.finish) << " }"
            << (p.no_shadow ? " no_shadow" : "") << (p.inverse ? " inverse" : "") << "\n}\n";
    }
    return out.str();
}

}  // namespace mirage::testing
