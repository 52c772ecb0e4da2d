#include "animate/marked.h"

#include <cmath>
#include <map>
#include <tuple>

#include "atmosphere/exact_path.h"
#include "atmosphere/general_profile.h"
#include "atmosphere/vanishing.h"
#include "load/atmosphere_settings.h"
#include "scene/camera.h"
#include "trace/curved_propagator.h"
#include "util/format.h"

namespace mirage {

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::string where(const Declared& d) { return to_string(d.loc) + ": "; }

}  // namespace

Result<std::vector<MarkedSphere>> read_marked_spheres(const Scene& scene) {
    std::vector<MarkedSphere> out;
    for (int n = 1;; ++n) {
        const std::string suffix = n == 1 ? "" : "_" + std::to_string(n);
        const auto c = scene.symbols.find("Marked_Center" + suffix);
        const auto r = scene.symbols.find("Marked_Radius" + suffix);
        const auto name = scene.symbols.find("Marked_Name" + suffix);
        if (c == scene.symbols.end() && r == scene.symbols.end()) {
            if (name != scene.symbols.end())
                return make_error(where(name->second) + "Marked_Name" + suffix +
                                  " names no sphere: declare Marked_Center" + suffix +
                                  " and Marked_Radius" + suffix);
            break;
        }
        if (c == scene.symbols.end() || r == scene.symbols.end()) {
            const auto& have = c == scene.symbols.end() ? r->second : c->second;
            return make_error(where(have) + "a marked sphere needs both Marked_Center" + suffix +
                              " and Marked_Radius" + suffix);
        }
        const auto* centre = std::get_if<glm::dvec3>(&c->second.value);
        if (!centre)
            return make_error(where(c->second) + "Marked_Center" + suffix +
                              " must be a vector, e.g. <0, 4.5, 60>");
        const auto* radius = std::get_if<double>(&r->second.value);
        if (!radius || !(*radius > 0.0) || !std::isfinite(*radius))
            return make_error(where(r->second) + "Marked_Radius" + suffix +
                              " must be a number > 0");
        MarkedSphere m;
        m.centre = *centre;
        m.radius = *radius;
        m.loc = c->second.loc;
        m.name = "marked sphere " + std::to_string(n);
        if (name != scene.symbols.end()) {
            const auto* text = std::get_if<std::string>(&name->second.value);
            if (!text)
                return make_error(where(name->second) + "Marked_Name" + suffix +
                                  " must be a string");
            m.name = *text;
        }
        out.push_back(m);
    }
    return out;
}

Result<std::vector<MarkedView>> view_marked_spheres(const Scene& scene, int width, int height,
                                                    VanishingCache* cache) {
    auto marked = read_marked_spheres(scene);
    if (!marked) return marked.error();
    std::vector<MarkedView> out;
    if (marked->empty()) return out;
    auto settings = read_atmosphere_settings(scene);
    if (!settings) return settings.error();
    const double unit = settings->unit_m;
    const double pixel_rad = pixel_angle_rad(scene.camera, width, height);
    // The scene's atmosphere as the tracer has it: the closed forms, or real air's fitted model
    // (fitted for the scene's own path tolerance), in scene units.
    auto atmosphere = scene_atmosphere(
        *settings, fit_angle_rad(PixelFootprint{0.0, pixel_rad}, settings->tolerance_px, 0.0));
    if (!atmosphere) return atmosphere.error();
    const double R = atmosphere->earth_radius();
    // What the distances depend on besides the heights: the profile's parameters, or every
    // knot and value of the fitted model (the air may change from frame to frame).
    const std::vector<double> air_key = atmosphere->key();
    // Heights above the atmosphere's ground (Mirage_Ground_Height): the scene as parsed is not
    // lowered here, so the eye and the spheres are.  On the curved Earth the heights are the
    // flattened frame's and the distances along the sphere, as the tracer reads the scene.
    const double ground = settings->declared ? settings->ground_height : 0.0;
    glm::dvec3 eye = scene.camera.location;
    eye.y = flattened_height(eye.y - ground, R);
    for (MarkedSphere m : *marked) {
        m.centre.y = flattened_height(m.centre.y - ground, R);
        const std::string at = to_string(m.loc) + ": " + m.name + ": ";
        std::vector<double> key = {eye.y, m.centre.y, m.radius};
        key.insert(key.end(), air_key.begin(), air_key.end());
        Result<double> vanish = make_error("");
        if (cache && cache->count(key)) {
            vanish = cache->at(key);
        } else {
            vanish = sphere_vanishing_distance(*atmosphere, eye.y, m.centre.y, m.radius);
            if (!vanish) return make_error(at + vanish.message());
            if (cache) (*cache)[key] = *vanish;
        }
        MarkedView v;
        v.name = m.name;
        const double d = std::hypot(m.centre.x - eye.x, m.centre.z - eye.z);
        v.eye_distance = d * unit;
        v.vanishing_distance = *vanish * unit;
        const SphereMirror image =
            mirrored_image_of_sphere(*atmosphere, eye.y, d, m.centre.y, m.radius);
        v.mirrored = image.visible;
        v.angular_size_deg = image.angular_size_rad * kDeg;
        v.angular_size_px = pixel_rad > 0.0 ? image.angular_size_rad / pixel_rad : 0.0;
        v.elevation_low_deg = image.elevation_low_rad * kDeg;
        v.elevation_high_deg = image.elevation_high_rad * kDeg;
        out.push_back(v);
    }
    return out;
}

}  // namespace mirage
