#include "scene/ground.h"

#include <cmath>

#include "scene/material_ops.h"
#include "scene/object_tree.h"
#include "scene/transform.h"
#include "util/format.h"

namespace mirage {
namespace {

void lower_primitive(Primitive& p, const Transform& down) {
    p.transform = compose_transforms(p.transform, down);
    transform_texture(p.texture, down);
    if (p.interior_texture) transform_texture(*p.interior_texture, down);
}

}  // namespace

void lower_scene(Scene& scene, double height) {
    if (height == 0.0) return;
    const Transform down = make_translation(glm::dvec3(0.0, -height, 0.0));
    scene.camera.location.y -= height;
    for (PointLight& l : scene.lights) transform_light(l, down);
    for (Fog& f : scene.fogs) {
        // A ground fog's heights are along its up vector; its turbulence stays where it was.
        f.offset -= height * f.up.y;
        f.lowered_by.y += height;
    }
    for (Primitive& p : scene.primitives) lower_primitive(p, down);
    for (UnknownObject& u : scene.unknown_objects) {
        for (auto& bound : u.bounds) {
            for (Primitive& p : bound) lower_primitive(p, down);
        }
    }
}

PlanesBelow horizontal_planes_below(const Scene& scene, double below_y) {
    PlanesBelow out;
    for (const Primitive& p : scene.primitives) {
        const auto* plane = std::get_if<Plane>(&p.shape);
        if (!plane) continue;
        const glm::dvec3 n = glm::normalize(transform_normal(p.transform, plane->normal));
        if (std::abs(n.x) > 1e-9 || std::abs(n.z) > 1e-9) continue;
        const glm::dvec3 on = transform_point(p.transform, plane->normal * plane->distance);
        if (!(on.y < below_y)) continue;
        if (!out.lowest || on.y < out.lowest->height) out.lowest = HorizontalPlane{on.y, p.loc};
        if (!out.highest || on.y > out.highest->height) out.highest = HorizontalPlane{on.y, p.loc};
    }
    return out;
}

std::string camera_below_ground_message(const Scene& scene, double ground_height,
                                        std::optional<double> lowest_object_y) {
    const Camera& cam = scene.camera;
    const std::string at = place_prefix(cam.loc, scene.file);
    std::string m =
        at + "the camera at y = " + shortest(cam.location.y) +
        " is not above the ground of the atmosphere (y = " + shortest(ground_height) +
        (ground_height == 0.0 ? "; Mirage_Ground_Height moves it" : ", Mirage_Ground_Height") + ")";
    const PlanesBelow planes = horizontal_planes_below(scene, cam.location.y);
    if (planes.highest) {
        const HorizontalPlane& floor = *planes.highest;
        m += "; the scene's horizontal plane under the camera, at y = " + shortest(floor.height) +
             " (" + to_string(floor.loc) +
             "), is a likely ground: #declare Mirage_Ground_Height = " + shortest(floor.height) +
             ";";
        if (planes.lowest->height < floor.height) {
            m += " (its lowest horizontal plane is at y = " + shortest(planes.lowest->height) +
                 ", " + to_string(planes.lowest->loc) + ")";
        }
    } else if (lowest_object_y && *lowest_object_y < cam.location.y) {
        m += "; the scene has no horizontal plane below the camera; its objects reach down to "
             "y = " +
             sig(*lowest_object_y, 6) +
             ": #declare Mirage_Ground_Height = " + sig(*lowest_object_y, 6) +
             "; puts the ground there";
    } else {
        m += "; the scene has no horizontal plane below the camera: declare Mirage_Ground_Height "
             "below it";
    }
    return m;
}

}  // namespace mirage
