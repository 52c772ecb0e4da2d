#include "trace/object_query.h"

#include "trace/scene_accel.h"

namespace mirage {
namespace {

struct Prepared {
    Scene scene;
    SceneAccel accel;
};

Result<Prepared> prepare(const ObjectNode& object) {
    Prepared p;
    flatten_object(object, Texture{}, p.scene);
    auto accel = SceneAccel::build(p.scene);
    if (!accel) return accel.error();
    p.accel = std::move(*accel);
    return p;
}

}  // namespace

Result<std::optional<ObjectTraceHit>> trace_object(const ObjectNode& object,
                                                   const glm::dvec3& origin,
                                                   const glm::dvec3& direction) {
    const double length = glm::length(direction);
    if (!(length > 0.0)) return std::optional<ObjectTraceHit>();
    auto p = prepare(object);
    if (!p) return p.error();
    auto hit = p->accel.closest_hit(origin, direction / length, 1e-4, 2e10);
    if (!hit) return std::optional<ObjectTraceHit>();
    return std::optional<ObjectTraceHit>(ObjectTraceHit{hit->point, hit->normal});
}

Result<bool> point_inside_object(const ObjectNode& object, const glm::dvec3& point) {
    auto p = prepare(object);
    if (!p) return p.error();
    // The object is its primitives of their own (a union) and its compounds.
    for (int i = 0; i < p->accel.primitive_count(); ++i) {
        if (p->scene.primitives[i].compound < 0 && inside_shape(p->accel.shape(i), point)) {
            return true;
        }
    }
    for (std::size_t c = 0; c < p->scene.compounds.size(); ++c) {
        std::vector<PreparedShape> shapes;
        for (int i = 0; i < p->accel.primitive_count(); ++i) shapes.push_back(p->accel.shape(i));
        const PreparedCompound compound = prepare_compound(p->scene.compounds[c], shapes);
        if (inside_compound(compound, shapes, point)) return true;
    }
    return false;
}

Result<Aabb> object_extent(const ObjectNode& object) {
    auto p = prepare(object);
    if (!p) return p.error();
    Aabb box = p->accel.finite_bounds();
    if (!p->accel.unbounded().empty()) {
        box.lo = glm::dvec3(-kPovBoundHuge / 2);
        box.hi = glm::dvec3(kPovBoundHuge / 2);
    }
    return box;
}

ObjectQueries tracer_object_queries() {
    ObjectQueries q;
    q.trace = trace_object;
    q.inside = point_inside_object;
    q.extent =
        [](const ObjectNode& object) -> Result<std::optional<std::pair<glm::dvec3, glm::dvec3>>> {
        auto box = object_extent(object);
        if (!box) return box.error();
        if (box->empty()) return std::optional<std::pair<glm::dvec3, glm::dvec3>>{};
        return std::optional<std::pair<glm::dvec3, glm::dvec3>>{std::pair{box->lo, box->hi}};
    };
    return q;
}

}  // namespace mirage
