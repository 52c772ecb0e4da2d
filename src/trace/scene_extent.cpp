#include "trace/scene_extent.h"

#include "shapes/shape_intersect.h"

namespace mirage {
namespace {}  // namespace

SceneExtent scene_extent(const Scene& scene, const SceneAccel& accel) {
    SceneExtent e;
    e.finite = accel.finite_bounds();
    for (const UnknownObject& u : scene.unknown_objects) {
        // POV-Ray's bounds of a bounded or clipped object: the bounding objects' boxes
        // intersected (each object's box is the union of its primitives').
        Aabb box;
        bool have = false;
        for (const auto& bound : u.bounds) {
            Aabb b;
            bool finite = true;
            for (const Primitive& p : bound) {
                auto s = prepare_shape(p);
                if (!s) {
                    finite = false;
                    break;
                }
                const Aabb pb = shape_bounds(*s);
                if (!pb.finite()) {
                    finite = false;
                    break;
                }
                b.extend(pb);
            }
            if (!finite || b.empty()) continue;
            if (!have) {
                box = b;
                have = true;
            } else {
                box.lo = glm::max(box.lo, b.lo);
                box.hi = glm::min(box.hi, b.hi);
            }
        }
        const std::string what = u.what + " at " + to_string(u.loc);
        if (have && !box.empty()) {
            e.finite.extend(box);
            e.bounded.push_back(what + ": bounded by its bounded_by or clipped_by");
        } else {
            e.unbounded.push_back(what +
                                  ": mirage cannot compute its extent, taken as unbounded (the "
                                  "atmosphere reaches the other objects; declare Mirage_Extent "
                                  "if it lies farther away)");
            if (!e.first_unbounded) {
                e.first_unbounded = u.loc;
                e.first_unbounded_what = u.what;
            }
        }
    }
    return e;
}

}  // namespace mirage
