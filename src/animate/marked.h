// The objects a scene marks for the vanishing report of `mirage animate`, and what the exact
// paths say of their mirrored images in one frame.  The convention (pov_includes/mirage.inc):
//   #declare Marked_Center = <x, y, z>;  #declare Marked_Radius = r;  #declare Marked_Name = "..";
// for a sphere, then Marked_Center_2, Marked_Radius_2, Marked_Name_2 and so on, numbered
// without gaps.  (Names beginning Mirage_ are the atmosphere's own and are checked as such.)
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "util/result.h"

namespace mirage {

struct MarkedSphere {
    std::string name;  // Marked_Name, or "marked sphere N"
    glm::dvec3 centre{0.0};
    double radius = 0.0;
    FileLoc loc;  // of its Marked_Center
};

/// The marked spheres of a parsed scene.  An error names the declaration at fault (a centre
/// that is not a vector, a radius that is not a positive number, one without the other).
Result<std::vector<MarkedSphere>> read_marked_spheres(const Scene& scene);

/// One marked sphere in one frame, from the exact paths of the scene's atmosphere.
struct MarkedView {
    std::string name;
    double eye_distance = 0.0;        // horizontal, eye to centre, metres
    double vanishing_distance = 0.0;  // nearest eye distance with a mirrored image, metres
    bool mirrored = false;            // it has a mirrored image from here
    double angular_size_deg = 0.0;    // of that image, vertically, degrees
    double angular_size_px = 0.0;     // the same in pixels at the image centre
    double elevation_low_deg = 0.0, elevation_high_deg = 0.0;
};

/// The marked spheres of `scene` (parsed for this frame) as seen from its camera through its
/// atmosphere (heights above its ground, Mirage_Ground_Height), for an image of width x
/// height.  No marked spheres: an empty list.  A scene
/// without an inferior atmosphere, or a sphere reaching the ground, is an error naming it.
/// `cache` (may be null) keeps the vanishing distances already found, by eye height, centre
/// height, radius and profile, for the frames of one animation.
using VanishingCache = std::map<std::vector<double>, double>;
Result<std::vector<MarkedView>> view_marked_spheres(const Scene& scene, int width, int height,
                                                    VanishingCache* cache = nullptr);

}  // namespace mirage
