// Test helpers: the scenes the tracer is held to POV-Ray on (pov_parity_test.cpp, and
// antialiased in antialias_parity_test.cpp), built in C++ and written out by pov_writer.h.
#pragma once

#include "scene/scene.h"
#include "scene_builders.h"

namespace mirage::testing {

inline Finish finish_with(double ambient, double diffuse) {
    Finish f;
    f.ambient = glm::dvec3(ambient);
    f.diffuse = diffuse;
    return f;
}

/// Checker plane, spheres with specular, phong and reflection, a rotated box, a capped
/// cylinder, a disc with a hole, a gradient sky_sphere, two lights and their shadows.
inline Scene showcase_scene() {
    Scene s;
    s.file = "showcase.pov";
    s.camera = look_at_camera({0.0, 1.6, -7.0}, {0.0, 0.9, 0.0}, 4.0 / 3.0, 1.5);
    s.has_camera = true;
    s.global.max_trace_level = 5;
    s.lights.push_back(light({-5.0, 8.0, -6.0}, glm::dvec3(1.0)));
    s.lights.push_back(light({6.0, 5.0, -3.0}, glm::dvec3(0.5, 0.45, 0.4)));

    Finish ground = finish_with(0.1, 0.7);
    s.primitives.push_back(
        primitive(Plane{{0.0, 1.0, 0.0}, 0.0},
                  texture(checker(rgb(0.9, 0.9, 0.85), rgb(0.15, 0.2, 0.35)), ground)));

    Finish shiny = finish_with(0.1, 0.6);
    shiny.specular = 0.6;
    shiny.roughness = 0.02;
    shiny.reflection = glm::dvec3(0.25);
    s.primitives.push_back(
        primitive(Sphere{{-1.6, 1.0, 0.5}, 1.0}, texture(solid(rgb(0.8, 0.15, 0.1)), shiny)));

    Finish phong = finish_with(0.1, 0.6);
    phong.phong = 0.9;
    phong.phong_size = 80.0;
    s.primitives.push_back(
        primitive(Sphere{{1.3, 0.7, -0.6}, 0.7}, texture(solid(rgb(0.1, 0.25, 0.85)), phong)));

    Finish mirror = finish_with(0.0, 0.2);
    mirror.reflection = glm::dvec3(0.6, 0.6, 0.55);
    mirror.specular = 0.3;
    s.primitives.push_back(
        primitive(Sphere{{0.1, 0.45, -1.8}, 0.45}, texture(solid(rgb(0.7, 0.7, 0.7)), mirror)));

    Finish matte = finish_with(0.15, 0.8);
    matte.brilliance = 2.0;
    s.primitives.push_back(primitive(Box{{-0.5, 0.0, -0.5}, {0.5, 0.8, 0.5}},
                                     texture(solid(rgb(0.2, 0.7, 0.25)), matte),
                                     then(rotate({0.0, 30.0, 0.0}), translate({2.3, 0.0, 1.8}))));

    s.primitives.push_back(primitive(Cylinder{{0.0, 0.0, 0.0}, {0.0, 1.6, 0.0}, 0.3, false},
                                     texture(solid(rgb(0.9, 0.5, 0.1)), finish_with(0.1, 0.7)),
                                     translate({0.0, 0.0, 2.5})));

    s.primitives.push_back(primitive(Disc{{-3.2, 1.2, 2.5}, {0.3, 0.0, -1.0}, 0.9, 0.3},
                                     texture(solid(rgb(0.9, 0.85, 0.1)), finish_with(0.1, 0.7))));

    SkySphere sky;
    sky.pigments.push_back(
        gradient({0.0, 1.0, 0.0}, {{0.0, rgb(0.9, 0.9, 1.0)}, {1.0, rgb(0.2, 0.35, 0.8)}}));
    s.sky_sphere = sky;
    return s;
}

/// Transformed shapes and patterns: an ellipsoid, a tilted cylinder and disc, a sheared box,
/// a rotated and scaled checker, a gradient with a three-colour map on an object, a layered
/// and rotated sky, emission, ambient_light, a shadowless light and a no_shadow object.
inline Scene transforms_scene() {
    Scene s;
    s.file = "transforms.pov";
    s.camera = look_at_camera({1.5, 2.5, -6.0}, {0.0, 0.7, 0.5}, 4.0 / 3.0, 1.2);
    s.global.ambient_light = glm::dvec3(0.8, 0.9, 1.0);
    s.lights.push_back(light({-4.0, 6.0, -5.0}, glm::dvec3(0.9)));
    s.lights.push_back(light({4.0, 3.0, -4.0}, glm::dvec3(0.3, 0.3, 0.5), /*shadowless=*/true));

    s.primitives.push_back(
        primitive(Plane{{0.0, 1.0, 0.0}, 0.0},
                  texture(checker(rgb(1.0, 1.0, 1.0), rgb(0.3, 0.1, 0.1),
                                  then(scale({0.7, 0.7, 0.7}), rotate({0.0, 25.0, 0.0}))),
                          finish_with(0.2, 0.6))));

    Finish f = finish_with(0.1, 0.7);
    f.specular = 0.4;
    f.roughness = 0.1;
    s.primitives.push_back(primitive(
        Sphere{{0.0, 0.0, 0.0}, 1.0},
        texture(
            gradient(
                {0.0, 2.0, 0.0},
                {{0.0, rgb(1.0, 0.0, 0.0)}, {0.5, rgb(1.0, 1.0, 0.0)}, {1.0, rgb(0.0, 0.3, 1.0)}},
                then(scale({1.0, 0.5, 1.0}), translate({-1.5, 0.6, 0.5}))),
            f),
        then(scale({1.0, 0.6, 0.8}), then(rotate({0.0, 0.0, 20.0}), translate({-1.5, 0.6, 0.5})))));

    Finish glow = finish_with(0.0, 0.3);
    glow.emission = glm::dvec3(0.4, 0.3, 0.1);
    Primitive cyl = primitive(Cylinder{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.5}, 0.35, true},
                              texture(solid(rgb(0.6, 0.9, 0.3)), glow),
                              then(rotate({-30.0, 40.0, 0.0}), translate({1.2, 0.4, 0.0})));
    s.primitives.push_back(cyl);

    Primitive disc = primitive(
        Disc{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.8, 0.35},
        texture(solid(rgb(0.2, 0.6, 0.9)), finish_with(0.1, 0.8)),
        then(scale({1.5, 1.0, 1.0}), then(rotate({10.0, -20.0, 0.0}), translate({0.3, 1.6, 2.5}))));
    disc.no_shadow = true;
    s.primitives.push_back(disc);

    glm::dmat4 shear(1.0);
    shear[1][0] = 0.5;  // x += 0.5 y
    Finish bright = finish_with(0.1, 0.9);
    bright.brilliance = 0.5;
    s.primitives.push_back(primitive(Box{{0.5, 0.0, -0.4}, {-0.5, 1.0, 0.4}},
                                     texture(solid(rgb(0.9, 0.4, 0.6)), bright),
                                     then(make_transform(shear), translate({2.4, 0.0, 1.5}))));

    SkySphere sky;
    sky.pigments.push_back(gradient(
        {0.0, 1.0, 0.0},
        {{0.0, rgb(1.0, 0.8, 0.6)}, {0.4, rgb(0.4, 0.6, 0.9)}, {1.0, rgb(0.1, 0.2, 0.6)}}));
    Colour clear{glm::dvec3(1.0), 0.0, 1.0};
    Colour cloud{glm::dvec3(1.0, 1.0, 1.0), 0.0, 0.3};
    sky.pigments.push_back(checker(clear, cloud, scale({0.15, 0.15, 0.15})));
    sky.transform = rotate({0.0, 0.0, 15.0});
    sky.emission = glm::dvec3(0.8, 0.9, 1.1);
    s.sky_sphere = sky;
    return s;
}

/// Two facing mirrors: reflections cut off by max_trace_level and by adc_bailout.
inline Scene mirrors_scene(int max_trace_level) {
    Scene s;
    s.file = "mirrors.pov";
    s.camera = look_at_camera({0.3, 1.2, -2.0}, {0.0, 1.0, 3.0}, 4.0 / 3.0, 1.0);
    s.global.max_trace_level = max_trace_level;
    s.lights.push_back(light({0.0, 3.0, 0.0}));
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0},
                                     texture(checker(rgb(0.8, 0.8, 0.8), rgb(0.1, 0.1, 0.1)))));
    Finish mirror = finish_with(0.0, 0.05);
    mirror.reflection = glm::dvec3(0.9, 0.85, 0.8);
    s.primitives.push_back(
        primitive(Plane{{0.0, 0.0, -1.0}, -3.0}, texture(solid(rgb(1.0, 1.0, 1.0)), mirror)));
    Finish weak = finish_with(0.0, 0.1);
    weak.reflection = glm::dvec3(0.3);
    s.primitives.push_back(
        primitive(Plane{{0.0, 0.0, 1.0}, -3.0}, texture(solid(rgb(1.0, 1.0, 1.0)), weak)));
    s.primitives.push_back(primitive(Sphere{{0.5, 0.5, 1.0}, 0.5},
                                     texture(solid(rgb(0.9, 0.2, 0.2)), finish_with(0.2, 0.7))));
    s.background = Colour{glm::dvec3(0.6, 0.8, 1.0), 0.2, 0.4};  // precomposed by POV-Ray
    return s;
}

/// A checker plane to the horizon seen through a narrow field: every pixel samples a tiny
/// patch of far-away checks, so the camera rays and the plane must match POV-Ray's bits.
inline Scene horizon_scene() {
    Scene s;
    s.file = "horizon.pov";
    s.camera = look_at_camera({0.0, 1.5, 0.0}, {0.0, 1.2, 40.0}, 4.0 / 3.0, 3.0);
    s.lights.push_back(light({100.0, 100.0, -50.0}));
    s.primitives.push_back(primitive(Plane{{0.0, 1.0, 0.0}, 0.0},
                                     texture(checker(rgb(0.9, 0.9, 0.9), rgb(0.1, 0.1, 0.1)))));
    s.background = Colour{glm::dvec3(0.7, 0.8, 1.0), 0.2, 0.3};  // precomposed by POV-Ray
    return s;
}

/// A scene file written as a POV-Ray user writes it (look_at, rotate, scale, textures
/// before transforms, an unnormalised gradient vector, a layered sky), and the Scene the
/// parser must build from it: checks how the tracer reads the Scene's fields.
inline const char* const kHandwrittenPov = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> }
light_source { <-4, 7, -5> color rgb 1 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <1, 0.9, 0.8>] [1 rgb <0.3, 0.4, 0.9>] } }
  pigment { checker rgbt <1, 1, 1, 1> rgbt <1, 1, 1, 0.6> scale 0.2 }
  rotate z*10
}
plane { y, 0
  pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.2, 0.4> scale 0.5 rotate y*20 }
  finish { diffuse 0.7 }
}
sphere { 0, 1
  pigment { gradient <0, 3, 0> color_map { [0 rgb <1, 0, 0>] [0.5 rgb <1, 1, 0>] [1 rgb <0, 0, 1>] }
            translate -0.5*y }
  finish { specular 0.5 roughness 0.03 phong 0.3 }
  scale <1.2, 0.8, 1> rotate z*15 translate <-1, 0.8, 0>
}
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgb <0.2, 0.8, 0.3> } rotate y*35 translate <1.5, 0, 0.5> }
cylinder { <0, 0, 0>, <0, 0, 1.2>, 0.3 open
  pigment { rgb <0.9, 0.6, 0.2> } finish { reflection 0.3 }
  rotate x*-60 translate <0.3, 0.3, -1.5>
}
disc { <0, 0, 0>, z, 0.7, 0.2 pigment { checker rgb 1 rgb <0.8, 0, 0> scale 0.25 } translate <-2.5, 1.2, 2> }
)";

inline Scene handwritten_scene() {
    Scene s;
    s.file = "handwritten.pov";
    s.camera = look_at_camera({0.0, 2.0, -6.0}, {0.0, 0.6, 0.0}, 1.33, 1.0);  // POV-Ray's defaults
    s.lights.push_back(light({-4.0, 7.0, -5.0}));
    SkySphere sky;
    sky.pigments.push_back(
        gradient({0, 1, 0}, {{0.0, rgb(1.0, 0.9, 0.8)}, {1.0, rgb(0.3, 0.4, 0.9)}}));
    sky.pigments.push_back(checker(Colour{glm::dvec3(1.0), 0.0, 1.0},
                                   Colour{glm::dvec3(1.0), 0.0, 0.6}, scale({0.2, 0.2, 0.2})));
    sky.transform = rotate({0.0, 0.0, 10.0});
    s.sky_sphere = sky;
    s.primitives.push_back(primitive(
        Plane{{0, 1, 0}, 0.0}, texture(checker(rgb(0.9, 0.9, 0.9), rgb(0.2, 0.2, 0.4),
                                               then(scale({0.5, 0.5, 0.5}), rotate({0, 20, 0}))),
                                       finish_with(0.1, 0.7))));
    const Transform sphere_t =
        then(scale({1.2, 0.8, 1.0}), then(rotate({0, 0, 15}), translate({-1.0, 0.8, 0.0})));
    Finish shiny;
    shiny.specular = 0.5;
    shiny.roughness = 0.03;
    shiny.phong = 0.3;
    s.primitives.push_back(primitive(
        Sphere{{0, 0, 0}, 1.0},
        texture(gradient({0, 3, 0}, {{0.0, rgb(1, 0, 0)}, {0.5, rgb(1, 1, 0)}, {1.0, rgb(0, 0, 1)}},
                         then(translate({0.0, -0.5, 0.0}), sphere_t)),
                shiny),
        sphere_t));
    s.primitives.push_back(primitive(Box{{-0.5, 0, -0.5}, {0.5, 1, 0.5}},
                                     texture(solid(rgb(0.2, 0.8, 0.3))),
                                     then(rotate({0, 35, 0}), translate({1.5, 0.0, 0.5}))));
    Finish mirror;
    mirror.reflection = glm::dvec3(0.3);
    s.primitives.push_back(primitive(Cylinder{{0, 0, 0}, {0, 0, 1.2}, 0.3, true},
                                     texture(solid(rgb(0.9, 0.6, 0.2)), mirror),
                                     then(rotate({-60, 0, 0}), translate({0.3, 0.3, -1.5}))));
    const Transform disc_t = translate({-2.5, 1.2, 2.0});
    s.primitives.push_back(primitive(
        Disc{{0, 0, 0}, {0, 0, 1}, 0.7, 0.2},
        texture(checker(rgb(1, 1, 1), rgb(0.8, 0, 0), then(scale({0.25, 0.25, 0.25}), disc_t))),
        disc_t));
    return s;
}

}  // namespace mirage::testing
