// Height fields after POV-Ray 3.7's hfield.cpp.  The shape's own space is POV-Ray's: grid
// units along x and z (0 .. width - 1, 0 .. depth - 1) and heights 0 .. 65535 along y, scaled
// into <0,0,0>..<1,1,1> (Parse_HField's scale: 1 / (width - 1), 1 / 65536, 1 / (depth - 1)).
// Each cell holds two triangles split along the diagonal from (x + 1, z) to (x, z + 1)
// (intersect_pixel), with its tolerances; a water level and the bounding box's offset cut the
// ray as Compute_HField's box does; smooth normals are Compute_HField's per-point normals,
// stored as shorts, interpolated bilinearly in the cell (HField::Normal).  The cells along the
// ray are visited in order in the x-z plane (a 2D DDA, where POV-Ray walks blocks and cells:
// the same cells, the same triangle tests).
#include "shapes/height_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace mirage {
namespace {

constexpr double kOffset = 0.001;      // HFIELD_OFFSET
constexpr double kTolerance = 1.0e-6;  // HFIELD_TOLERANCE
constexpr int kLower = 1, kUpper = 2;

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

class HeightFieldShape final : public ComplexShape {
  public:
    HeightFieldShape(const HeightFieldData& data, const Transform& t) : smooth_(data.smooth) {
        width_ = data.width;
        depth_ = data.depth;
        max_x_ = width_ - 2;
        max_z_ = depth_ - 2;
        heights_.resize(data.heights.size());
        double min_y = 65535.0, max_y = 0.0;
        for (std::size_t i = 0; i < heights_.size(); ++i) {
            heights_[i] = data.heights[i] * 65536.0;  // POV-Ray's HF_VAL
            min_y = std::min(min_y, heights_[i]);
            max_y = std::max(max_y, heights_[i]);
        }
        corner1_ = glm::dvec3(0.0, std::max(min_y, 65536.0 * data.water_level) - kOffset, 0.0);
        corner2_ = glm::dvec3(width_ - 1.0, max_y + kOffset, depth_ - 1.0);
        const glm::dvec3 scale(1.0 / (width_ - 1.0), 1.0 / 65536.0, 1.0 / (depth_ - 1.0));
        glm::dmat4 s(1.0), s_inv(1.0);
        for (int i = 0; i < 3; ++i) {
            s[i][i] = scale[i];
            s_inv[i][i] = 1.0 / scale[i];
        }
        local_to_world_ = t.matrix * s;
        world_to_local_ = s_inv * t.inverse;
        normal_to_world_ = glm::transpose(glm::dmat3(world_to_local_));
        if (smooth_) smooth_normals();
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        // The local ray is not normalised, so its depths are the world ray's.
        const glm::dvec3 P = transform_point(world_to_local_, origin);
        const glm::dvec3 D = glm::dmat3(world_to_local_) * direction;
        // hfield.cpp: Box::Intersect on the bounding box in the shape's space.
        double depth1, depth2;
        int side1, side2;
        if (!box_roots(corner1_, corner2_, P, D, 0.0, depth1, side1, depth2, side2)) return;
        if (depth1 < kTolerance) {
            depth1 = kTolerance;
            if (depth1 > depth2) return;
        }
        const double lo = std::max(depth1, sink.t_min());
        const double hi = std::min(depth2, kPovMaxDistance);
        if (lo > hi) return;
        // The cells the ray crosses between depth1 and depth2, nearest first.
        const glm::dvec3 start = P + depth1 * D;
        int cx = std::clamp(static_cast<int>(std::floor(start.x)), 0, max_x_);
        int cz = std::clamp(static_cast<int>(std::floor(start.z)), 0, max_z_);
        const double inf = std::numeric_limits<double>::infinity();
        const int step_x = D.x > 0.0 ? 1 : -1, step_z = D.z > 0.0 ? 1 : -1;
        const double delta_x = D.x != 0.0 ? std::abs(1.0 / D.x) : inf;
        const double delta_z = D.z != 0.0 ? std::abs(1.0 / D.z) : inf;
        double next_x = D.x > 0.0 ? (cx + 1 - P.x) / D.x : D.x < 0.0 ? (cx - P.x) / D.x : inf;
        double next_z = D.z > 0.0 ? (cz + 1 - P.z) / D.z : D.z < 0.0 ? (cz - P.z) / D.z : inf;
        double entry = depth1;
        while (true) {
            if (sink.t_max() < entry) break;  // a nearer hit is kept already
            intersect_cell(cx, cz, P, D, lo, hi, sink);
            const double exit = std::min(next_x, next_z);
            if (!(exit <= depth2)) break;
            entry = exit;
            if (next_x <= next_z) {
                cx += step_x;
                next_x += delta_x;
                if (cx < 0 || cx > max_x_) break;
            } else {
                cz += step_z;
                next_z += delta_z;
                if (cz < 0 || cz > max_z_) break;
            }
        }
    }

    bool inside(const glm::dvec3& point) const override {
        const glm::dvec3 p = transform_point(world_to_local_, point);
        const double water = corner1_.y;
        if (p.x < 0.0 || p.x >= corner2_.x || p.z < 0.0 || p.z >= corner2_.z) return false;
        if (p.y >= corner2_.y) return false;
        if (p.y < water) return true;
        int px = static_cast<int>(p.x), pz = static_cast<int>(p.z);
        const double x = p.x - px, z = p.z - pz;
        glm::dvec3 origin, n;
        if (x + z < 1.0) {
            const double y1 = std::max(height(px, pz), water);
            const double y2 = std::max(height(px + 1, pz), water);
            const double y3 = std::max(height(px, pz + 1), water);
            origin = glm::dvec3(px, y1, pz);
            n = glm::dvec3(y1 - y2, 1.0, y1 - y3);
        } else {
            px = static_cast<int>(std::ceil(p.x));
            pz = static_cast<int>(std::ceil(p.z));
            const double y1 = std::max(height(px, pz), water);
            const double y2 = std::max(height(px - 1, pz), water);
            const double y3 = std::max(height(px, pz - 1), water);
            origin = glm::dvec3(px, y1, pz);
            n = glm::dvec3(y2 - y1, 1.0, y3 - y1);
        }
        return glm::dot(p, n) < glm::dot(origin, n);
    }

    glm::dvec3 normal(const glm::dvec3& point, const ShapeHit& hit) const override {
        if (!smooth_) {
            const int x = hit.index % width_, z = hit.index / width_;
            glm::dvec3 n;
            if (hit.part == kLower) {
                const double y1 = height(x, z), y2 = height(x + 1, z), y3 = height(x, z + 1);
                n = glm::dvec3(y1 - y2, 1.0, y1 - y3);
            } else {
                const double y2 = height(x + 1, z), y3 = height(x, z + 1),
                             y4 = height(x + 1, z + 1);
                n = glm::dvec3(y3 - y4, 1.0, y2 - y4);
            }
            return glm::normalize(normal_to_world_ * n);
        }
        const glm::dvec3 p = transform_point(world_to_local_, point);
        const int px = std::min(static_cast<int>(p.x), max_x_);
        const int pz = std::min(static_cast<int>(p.z), max_z_);
        const double x = p.x - px, z = p.z - pz;
        glm::dvec3 n[4];
        for (int i = 0; i < 4; ++i) {
            const std::array<short, 3>& s = normals_[index(px + (i & 1), pz + (i >> 1))];
            n[i] = glm::normalize(normal_to_world_ * glm::dvec3(s[0], s[1], s[2]));
        }
        const double u = 1.0 - x, v = 1.0 - z;
        return glm::normalize(v * (u * n[0] + x * n[1]) + z * (u * n[2] + x * n[3]));
    }

    Aabb bounds() const override {
        Aabb box;
        for (int i = 0; i < 8; ++i) {
            box.extend(transform_point(
                local_to_world_,
                glm::dvec3(i & 1 ? corner2_.x : corner1_.x, i & 2 ? corner2_.y : corner1_.y,
                           i & 4 ? corner2_.z : corner1_.z)));
        }
        return box;
    }

  private:
    std::size_t index(int x, int z) const { return static_cast<std::size_t>(z) * width_ + x; }
    double height(int x, int z) const { return heights_[index(x, z)]; }

    // intersect_pixel: the cell's two triangles.
    void intersect_cell(int x, int z, const glm::dvec3& P, const glm::dvec3& D, double mindist,
                        double maxdist, HitSink& sink) const {
        const double y1 = height(x, z), y2 = height(x + 1, z), y3 = height(x, z + 1),
                     y4 = height(x + 1, z + 1);
        const int cell = static_cast<int>(index(x, z));
        const auto test = [&](const glm::dvec3& corner, const glm::dvec3& n, int part) {
            const double dot = glm::dot(n, D);
            if (!(dot > kPovEpsilon || dot < -kPovEpsilon)) return;
            const double depth = glm::dot(n, corner - P) / dot;
            if (!(depth >= mindist && depth <= maxdist)) return;
            const double s = P.x + depth * D.x - x, t = P.z + depth * D.z - z;
            const bool in = part == kLower ? s >= -0.0001 && t >= -0.0001 && s + t <= 1.0001
                                           : s <= 1.0001 && t <= 1.0001 && s + t >= 0.9999;
            if (in) sink.add(depth, part, cell, glm::dvec2(0.0));
        };
        test(glm::dvec3(x, y1, z), glm::dvec3(y1 - y2, 1.0, y1 - y3), kLower);
        test(glm::dvec3(x + 1, y4, z + 1), glm::dvec3(y3 - y4, 1.0, y2 - y4), kUpper);
    }

    // smooth_height_field and add_single_normal: each point's normal, the sum of its four
    // neighbouring triangles' unit normals (pointing up), as shorts of 32767 * unit.
    void smooth_normals() {
        normals_.resize(heights_.size());
        const int xsize = width_ - 1, zsize = depth_ - 1;
        const auto add = [&](int x0, int z0, int x1, int z1, int x2, int z2, glm::dvec3& n) {
            if (x0 < 0 || z0 < 0 || x1 < 0 || z1 < 0 || x2 < 0 || z2 < 0 || x0 > xsize ||
                z0 > zsize || x1 > xsize || z1 > zsize || x2 > xsize || z2 > zsize) {
                return;
            }
            const glm::dvec3 v0(x0, height(x0, z0), z0), v1(x1, height(x1, z1), z1),
                v2(x2, height(x2, z2), z2);
            glm::dvec3 nt = pov_normalize(glm::cross(v2 - v0, v1 - v0));
            if (nt.y < 0.0) nt = -nt;
            n += nt;
        };
        for (int i = 0; i <= zsize; ++i) {
            for (int j = 0; j <= xsize; ++j) {
                glm::dvec3 n(0.0);
                add(j, i, j + 1, i, j, i + 1, n);
                add(j, i, j, i + 1, j - 1, i, n);
                add(j, i, j - 1, i, j, i - 1, n);
                add(j, i, j, i - 1, j + 1, i, n);
                n = pov_normalize(n);
                normals_[index(j, i)] = {static_cast<short>(32767 * n.x),
                                         static_cast<short>(32767 * n.y),
                                         static_cast<short>(32767 * n.z)};
            }
        }
    }
    // HField::normalize: <0, 1, 0> for a vector of no length.
    static glm::dvec3 pov_normalize(const glm::dvec3& v) {
        const double length = glm::length(v);
        return std::abs(length) > kPovEpsilon ? v / length : glm::dvec3(0.0, 1.0, 0.0);
    }

    std::vector<double> heights_;
    bool smooth_;
    int width_ = 0, depth_ = 0, max_x_ = 0, max_z_ = 0;
    glm::dvec3 corner1_{0.0}, corner2_{0.0};
    glm::dmat4 world_to_local_{1.0}, local_to_world_{1.0};
    glm::dmat3 normal_to_world_{1.0};
    std::vector<std::array<short, 3>> normals_;
};

}  // namespace

Result<std::shared_ptr<const ComplexShape>> prepare_height_field(const HeightField& hf,
                                                                 const Primitive& p) {
    if (!hf.data || hf.data->width < 2 || hf.data->depth < 2 ||
        hf.data->heights.size() !=
            static_cast<std::size_t>(hf.data->width) * static_cast<std::size_t>(hf.data->depth)) {
        return make_error(primitive_place(p) + "height_field: no grid of at least 2 x 2 heights");
    }
    return std::shared_ptr<const ComplexShape>(
        std::make_shared<HeightFieldShape>(*hf.data, p.transform));
}

}  // namespace mirage
