// Triangle meshes (mesh, mesh2, triangle, smooth_triangle) and polygons, after POV-Ray 3.7's
// mesh.cpp, triangle.cpp and polygon.cpp: plane hit, then POV-Ray's edge tests on the
// dominant axis's projection (the vertex order fixed when the triangle is prepared), smooth
// normals interpolated as POV-Ray does, the inside test by counting crossings along the
// inside_vector.  Meshes hold their data in single precision as POV-Ray does.
#include "shapes/mesh.h"

#include <cmath>

#include "shapes/local_bvh.h"

namespace mirage {
namespace {

constexpr double kMeshDepthTolerance = 1e-6;     // mesh.cpp and triangle.cpp
constexpr double kPolygonDepthTolerance = 1e-8;  // polygon.cpp
constexpr double kPolygonZeroTolerance = 1e-10;

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

int max3_axis(double x, double y, double z) {
    // POV-Ray's max3_coordinate.
    if (x > y) return x > z ? 0 : 2;
    return y > z ? 1 : 2;
}

double as_float(double v, bool single) {
    return single ? static_cast<double>(static_cast<float>(v)) : v;
}
glm::dvec3 as_float(const glm::dvec3& v, bool single) {
    return glm::dvec3(as_float(v.x, single), as_float(v.y, single), as_float(v.z, single));
}

struct Tri {
    int p[3];
    int n[3];
    glm::dvec3 normal;  // the face's unit normal (POV-Ray's S_Normal)
    double distance;    // -normal . p1
    int dominant;
    bool smooth;
    glm::dvec3 perp;
    int v_axis;
};

class MeshShape final : public ComplexShape {
  public:
    MeshShape(const MeshData& data, const Transform& t) {
        single_ = data.single_precision;
        vertices_ = data.vertices;
        normals_ = data.normals;
        for (const MeshData::Face& f : data.faces) {
            Tri tri{};
            for (int i = 0; i < 3; ++i) {
                tri.p[i] = f.v[i];
                tri.n[i] = f.n[i];
            }
            tri.smooth = f.n[0] >= 0 && f.n[1] >= 0 && f.n[2] >= 0;
            if (tri.smooth) {
                // POV-Ray keeps a triangle whose three normals are equal flat.
                const glm::dvec3 d1 = normals_[f.n[0]] - normals_[f.n[1]];
                const glm::dvec3 d2 = normals_[f.n[0]] - normals_[f.n[2]];
                if (!(std::abs(glm::dot(d1, d1)) > kPovEpsilon ||
                      std::abs(glm::dot(d2, d2)) > kPovEpsilon)) {
                    tri.smooth = false;
                }
            }
            if (prepare_triangle(tri)) tris_.push_back(tri);
        }
        world_to_local_ = t.inverse;
        local_to_world_ = t.matrix;
        normal_to_world_ = glm::transpose(glm::dmat3(t.inverse));
        if (glm::length(data.inside_vector) > kPovEpsilon) {
            inside_vector_ = glm::normalize(data.inside_vector);
            has_inside_ = true;
        }
        std::vector<Aabb> boxes;
        boxes.reserve(tris_.size());
        for (const Tri& tri : tris_) {
            Aabb b;
            for (int i = 0; i < 3; ++i) b.extend(vertices_[tri.p[i]]);
            boxes.push_back(b.padded(1e-9, 1e-12));
            local_bounds_.extend(b);
        }
        bvh_ = LocalBvh(boxes);
    }

    bool empty() const { return tris_.empty(); }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        glm::dvec3 p = transform_point(world_to_local_, origin);
        glm::dvec3 d = glm::dmat3(world_to_local_) * direction;
        const double len = glm::length(d);
        d /= len;
        const double t_lo = sink.t_min() < 0.0 ? sink.t_min() * len : kMeshDepthTolerance;
        bvh_.traverse(
            p, d, sink.t_min() * len, [&] { return sink.t_max() * len; },
            [&](int k) {
                double depth;
                if (hit_triangle(tris_[k], p, d, t_lo, depth)) sink.add(depth / len, 0, k);
            });
    }

    bool inside(const glm::dvec3& point) const override {
        if (!has_inside_) return false;
        // POV-Ray counts the triangles a ray along the inside_vector meets (every one of them,
        // without merging hits on shared edges).
        glm::dvec3 p = transform_point(world_to_local_, point);
        glm::dvec3 d = glm::dmat3(world_to_local_) * inside_vector_;
        d /= glm::length(d);
        int found = 0;
        bvh_.traverse(
            p, d, 0.0, [] { return kPovBoundHuge; },
            [&](int k) {
                double depth;
                if (hit_triangle(tris_[k], p, d, kMeshDepthTolerance, depth)) ++found;
            });
        return (found & 1) != 0;
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit& hit) const override {
        const Tri& tri = tris_[hit.index];
        glm::dvec3 n;
        if (tri.smooth) {
            const glm::dvec3 ip = transform_point(world_to_local_, point);
            const glm::dvec3 n1 = normals_[tri.n[0]], n2 = normals_[tri.n[1]],
                             n3 = normals_[tri.n[2]];
            const glm::dvec3 pm = ip - vertices_[tri.p[0]];
            const double u = glm::dot(pm, tri.perp);
            if (u < kPovEpsilon) {
                n = n1;
            } else {
                const int axis = tri.v_axis;
                const double k1 = vertices_[tri.p[0]][axis], k2 = vertices_[tri.p[1]][axis],
                             k3 = vertices_[tri.p[2]][axis];
                const double v = (pm[axis] / u + k1 - k2) / (k3 - k2);
                n = n1 + u * (n2 - n1 + v * (n3 - n2));
            }
        } else {
            n = tri.normal;
        }
        return glm::normalize(normal_to_world_ * n);
    }

    Aabb bounds() const override {
        Aabb box;
        if (local_bounds_.empty()) return box;
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 c((i & 1) ? local_bounds_.hi.x : local_bounds_.lo.x,
                               (i & 2) ? local_bounds_.hi.y : local_bounds_.lo.y,
                               (i & 4) ? local_bounds_.hi.z : local_bounds_.lo.z);
            box.extend(transform_point(local_to_world_, c));
        }
        return box;
    }

  private:
    // POV-Ray's Compute_Mesh_Triangle: the face normal and distance, the dominant axis and
    // the vertex order its edge tests expect, and the smooth interpolation's perpendicular.
    bool prepare_triangle(Tri& tri) const {
        glm::dvec3 P1 = vertices_[tri.p[0]], P2 = vertices_[tri.p[1]], P3 = vertices_[tri.p[2]];
        glm::dvec3 n = glm::cross(P3 - P1, P2 - P1);
        const double length = glm::length(n);
        if (length == 0.0) return false;
        n /= length;
        tri.distance = as_float(-glm::dot(n, P1), single_);
        tri.normal = as_float(n, single_);
        tri.dominant = max3_axis(std::abs(n.x), std::abs(n.y), std::abs(n.z));
        const int a = tri.dominant == 0 ? 1 : 0;
        const int b = tri.dominant == 2 ? 1 : 2;
        if ((P2[a] - P3[a]) * (P2[b] - P1[b]) < (P2[b] - P3[b]) * (P2[a] - P1[a])) {
            std::swap(tri.p[0], tri.p[1]);
            std::swap(tri.n[0], tri.n[1]);
            std::swap(P1, P2);
        }
        // compute_smooth_triangle.
        const glm::dvec3 d32 = P3 - P2;
        tri.v_axis = max3_axis(std::abs(d32.x), std::abs(d32.y), std::abs(d32.z));
        glm::dvec3 t1 = glm::normalize(P2 - P3);
        const glm::dvec3 t2 = P1 - P3;
        t1 *= glm::dot(t2, t1);
        glm::dvec3 perp = glm::normalize(t1 - t2);
        perp /= -glm::dot(t2, perp);
        tri.perp = as_float(perp, single_);
        return true;
    }

    // POV-Ray's intersect_mesh_triangle.
    bool hit_triangle(const Tri& tri, const glm::dvec3& o, const glm::dvec3& d, double t_lo,
                      double& depth) const {
        const double nd = glm::dot(tri.normal, d);
        if (std::abs(nd) < kPovEpsilon) return false;
        depth = -(tri.distance + glm::dot(tri.normal, o)) / nd;
        if (depth < t_lo || depth > kPovMaxDistance) return false;
        const glm::dvec3& P1 = vertices_[tri.p[0]];
        const glm::dvec3& P2 = vertices_[tri.p[1]];
        const glm::dvec3& P3 = vertices_[tri.p[2]];
        const int a = tri.dominant == 0 ? 1 : 0;
        const int b = tri.dominant == 2 ? 1 : 2;
        const double s = o[a] + depth * d[a];
        const double t = o[b] + depth * d[b];
        if ((P2[a] - s) * (P2[b] - P1[b]) < (P2[b] - t) * (P2[a] - P1[a])) return false;
        if ((P3[a] - s) * (P3[b] - P2[b]) < (P3[b] - t) * (P3[a] - P2[a])) return false;
        if ((P1[a] - s) * (P1[b] - P3[b]) < (P1[b] - t) * (P1[a] - P3[a])) return false;
        return true;
    }

    bool single_ = true;
    std::vector<glm::dvec3> vertices_, normals_;
    std::vector<Tri> tris_;
    LocalBvh bvh_;
    Aabb local_bounds_;
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
    glm::dvec3 inside_vector_{0.0};
    bool has_inside_ = false;
};

class PolygonShape final : public ComplexShape {
  public:
    PolygonShape(const Polygon& polygon, const Transform& t) : points_(polygon.points) {
        degenerate_ = polygon.degenerate;
        local_to_world_ = t.matrix * polygon.plane_to_shape;
        world_to_local_ = glm::inverse(local_to_world_);
        normal_ = glm::normalize(glm::transpose(glm::dmat3(world_to_local_)) * glm::dvec3(0, 0, 1));
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        if (degenerate_ || points_.size() < 3) return;
        const glm::dvec3 p = transform_point(world_to_local_, origin);
        glm::dvec3 d = glm::dmat3(world_to_local_) * direction;
        const double len = glm::length(d);
        d /= len;
        if (std::abs(d.z) < kPolygonZeroTolerance) return;
        const double depth = -p.z / d.z;
        const double lo = sink.t_min() < 0.0 ? sink.t_min() * len : kPolygonDepthTolerance;
        if (depth < lo || depth > kPovMaxDistance) return;
        if (in_polygon(p.x + depth * d.x, p.y + depth * d.y)) sink.add(depth / len);
    }

    bool inside(const glm::dvec3&) const override { return false; }
    glm::dvec3 normal(const glm::dvec3&, const ShapeHit&) const override { return normal_; }

    Aabb bounds() const override {
        Aabb box;
        for (const glm::dvec2& q : points_)
            box.extend(transform_point(local_to_world_, glm::dvec3(q, 0.0)));
        return box;
    }

  private:
    // POV-Ray's in_polygon: the crossing test, sub-polygons closed by repeating their first
    // point.
    bool in_polygon(double tx, double ty) const {
        const int number = static_cast<int>(points_.size());
        const glm::dvec2* vtx0 = &points_[0];
        const glm::dvec2* vtx1 = &points_[1];
        const glm::dvec2* first = vtx0;
        bool yflag0 = vtx0->y >= ty;
        bool inside = false;
        for (int i = 1; i < number;) {
            const bool yflag1 = vtx1->y >= ty;
            if (yflag0 != yflag1) {
                if (((vtx1->y - ty) * (vtx0->x - vtx1->x) >=
                     (vtx1->x - tx) * (vtx0->y - vtx1->y)) == yflag1) {
                    inside = !inside;
                }
            }
            if (i < number - 2 && vtx1->x == first->x && vtx1->y == first->y) {
                vtx0 = &points_[++i];
                vtx1 = &points_[++i];
                yflag0 = vtx0->y >= ty;
                first = vtx0;
            } else {
                vtx0 = vtx1;
                ++i;
                if (i >= number) break;
                vtx1 = &points_[i];
                yflag0 = yflag1;
            }
        }
        return inside;
    }

    std::vector<glm::dvec2> points_;
    bool degenerate_ = false;
    glm::dmat4 local_to_world_{1.0}, world_to_local_{1.0};
    glm::dvec3 normal_{0.0, 0.0, 1.0};
};

}  // namespace

Result<std::shared_ptr<const ComplexShape>> prepare_mesh(const Mesh& mesh, const Primitive& p) {
    if (!mesh.data || mesh.data->faces.empty()) {
        return make_error(primitive_place(p) + "mesh: no triangles");
    }
    auto shape = std::make_shared<MeshShape>(*mesh.data, p.transform);
    return std::shared_ptr<const ComplexShape>(std::move(shape));
}

Result<std::shared_ptr<const ComplexShape>> prepare_polygon(const Polygon& polygon,
                                                            const Primitive& p) {
    return std::shared_ptr<const ComplexShape>(
        std::make_shared<PolygonShape>(polygon, p.transform));
}

}  // namespace mirage
