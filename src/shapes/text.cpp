// Text after POV-Ray 3.7's truetype.cpp: every glyph an extrusion of its quadratic outline
// along z from 0 to the thickness, intersected as POV-Ray does (the front and back faces by
// its crossing test of the outline, the walls by solving the quadratic segments against the
// ray's projection), with its normals.
#include "shapes/text.h"

#include <cmath>

#include "shapes/local_bvh.h"

namespace mirage {
namespace {

constexpr double kTtfTolerance = 1.0e-6;
constexpr double kCoeffLimit = 1.0e-20;
constexpr int kFrontHit = 1, kBackHit = 2, kWallHit = 3;

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

// POV-Ray's TrueType::solve_quad: roots of x0 s^2 + x1 s + x2 in [lo, hi].
int solve_quad(const double* x, double* y, double lo, double hi) {
    const double a = x[0], b = -x[1], c = x[2];
    if (std::abs(a) < kCoeffLimit) {
        if (std::abs(b) < kCoeffLimit) return 0;
        const double q = c / b;
        if (q >= lo && q <= hi) {
            y[0] = q;
            return 1;
        }
        return 0;
    }
    double d = b * b - 4.0 * a * c;
    if (d < kPovEpsilon) return 0;
    d = std::sqrt(d);
    const double t = 2.0 * a;
    double q = (b + d) / t;
    if (q >= lo && q <= hi) {
        y[0] = q;
        q = (b - d) / t;
        if (q >= lo && q <= hi) {
            y[1] = q;
            return 2;
        }
        return 1;
    }
    q = (b - d) / t;
    if (q >= lo && q <= hi) {
        y[0] = q;
        return 1;
    }
    return 0;
}

// POV-Ray's Inside_Glyph.
bool inside_glyph(double x, double y, const GlyphData& glyph) {
    int crossings = 0;
    for (const GlyphData::Contour& c : glyph.contours) {
        const auto& xv = c.x;
        const auto& yv = c.y;
        const auto& fv = c.on_curve;
        double x0 = xv[0], y0 = yv[0];
        const int n1 = static_cast<int>(xv.size()) - 1;
        for (int j = 1; j <= n1; ++j) {
            const double x1 = xv[j], y1 = yv[j];
            if (fv[j]) {
                // A straight line: the crossing test.
                bool cross = false;
                if (y0 != y1) {
                    const bool qi = y0 < y, qj = y1 < y;
                    if (qi != qj) {
                        const bool ri = x0 > x, rj = x1 > x;
                        if (ri && rj) {
                            cross = true;
                        } else if (ri || rj) {
                            const double m = (y1 - y0) / (x1 - x0);
                            const double b = (y1 - y) - m * (x1 - x);
                            if ((b / m) < kPovEpsilon) cross = true;
                        }
                    }
                }
                if (cross) ++crossings;
                x0 = x1;
                y0 = y1;
                continue;
            }
            double x2, y2;
            if (j == n1) {
                x2 = xv[0];
                y2 = yv[0];
            } else {
                x2 = xv[j + 1];
                y2 = yv[j + 1];
                if (!fv[j + 1]) {
                    x2 = 0.5 * (x1 + x2);
                    y2 = 0.5 * (y1 + y2);
                }
            }
            if (!((y0 < y && y1 < y && y2 < y) || (y0 > y && y1 > y && y2 > y))) {
                const double yt[3] = {y0 - 2.0 * y1 + y2, 2.0 * (y1 - y0), y0 - y};
                double roots[2];
                int k = solve_quad(yt, roots, 0.0, 1.0);
                for (int ri = 0; ri < k;) {
                    if (roots[ri] <= kPovEpsilon) {
                        if ((y <= y0 && y < y1) || (y >= y0 && y > y1)) {
                            --k;
                            if (k > ri) roots[ri] = roots[ri + 1];
                            continue;
                        }
                    } else if (roots[ri] >= 1.0 - kPovEpsilon) {
                        if ((y < y2 && y < y1) || (y > y2 && y > y1)) {
                            --k;
                            if (k > ri) roots[ri] = roots[ri + 1];
                            continue;
                        }
                    }
                    ++ri;
                }
                const double xt[3] = {x0 - 2.0 * x1 + x2, 2.0 * (x1 - x0), x0};
                for (int r = 0; r < k && r < 2; ++r) {
                    const double t = roots[r];
                    const double xc = (xt[0] * t + xt[1]) * t + xt[2];
                    if (xc > x) ++crossings;
                }
            }
            x0 = x2;
            y0 = y2;
        }
    }
    return (crossings & 1) != 0;
}

struct PlacedGlyph {
    const GlyphData* glyph;
    glm::dmat4 world_to_glyph;
    glm::dmat3 normal_to_world;
};

class TextShape final : public ComplexShape {
  public:
    TextShape(const Text& text, const Transform& t) : text_(text), depth_(text.thickness) {
        std::vector<Aabb> boxes;
        for (const Text::Placed& g : text_.glyphs) {
            glm::dmat4 to_world = t.matrix;
            to_world = to_world * glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0),
                                             glm::dvec4(0, 0, 1, 0), glm::dvec4(g.offset, 1.0));
            const glm::dmat4 from_world = glm::inverse(to_world);
            glyphs_.push_back(
                PlacedGlyph{g.glyph.get(), from_world, glm::transpose(glm::dmat3(from_world))});
            // POV-Ray's TrueType::Compute_BBox, moved to world space.
            const double f = 1.0 / g.glyph->units_per_em;
            const glm::dvec3 lo(g.glyph->x_min * f, g.glyph->y_min * f, -kTtfTolerance);
            const glm::dvec3 hi(g.glyph->x_max * f, g.glyph->y_max * f, depth_ + kTtfTolerance);
            Aabb box;
            for (int i = 0; i < 8; ++i) {
                box.extend(transform_point(
                    to_world,
                    glm::dvec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z)));
            }
            if (g.glyph->contours.empty()) box = Aabb{};
            boxes.push_back(box.empty() ? box : box.padded(1e-9, 1e-12));
            bounds_.extend(box);
        }
        bvh_ = LocalBvh(boxes);
    }

    void intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                   HitSink& sink) const override {
        bvh_.traverse(
            origin, direction, sink.t_min(), [&] { return sink.t_max(); },
            [&](int k) { glyph_hits(k, origin, direction, sink); });
    }

    bool inside(const glm::dvec3& point) const override {
        for (const PlacedGlyph& g : glyphs_) {
            const glm::dvec3 p = transform_point(g.world_to_glyph, point);
            if (p.z >= 0.0 && p.z <= depth_ && inside_glyph(p.x, p.y, *g.glyph)) return true;
        }
        return false;
    }

    glm::dvec3 normal(const glm::dvec3&, const ShapeHit& hit) const override {
        const PlacedGlyph& g = glyphs_[hit.index];
        glm::dvec3 n(0.0, 0.0, hit.part == kFrontHit ? -1.0 : 1.0);
        if (hit.part == kWallHit) n = glm::dvec3(hit.uv, 0.0);
        return glm::normalize(g.normal_to_world * n);
    }

    Aabb bounds() const override { return bounds_; }

  private:
    // POV-Ray's GlyphIntersect: the direction is not normalised, so depths are world ones.
    void glyph_hits(int k, const glm::dvec3& origin, const glm::dvec3& direction,
                    HitSink& sink) const {
        const PlacedGlyph& pg = glyphs_[k];
        const GlyphData& glyph = *pg.glyph;
        const glm::dvec3 P = transform_point(pg.world_to_glyph, origin);
        const glm::dvec3 D = glm::dmat3(pg.world_to_glyph) * direction;
        const double lo = sink.t_min() < 0.0 ? sink.t_min() : kTtfTolerance;
        // The front (z = 0) and back (z = depth) faces.
        if (std::abs(D.z) >= kPovEpsilon) {
            double t = -P.z / D.z;
            if (inside_glyph(P.x + t * D.x, P.y + t * D.y, glyph) && t > lo) {
                sink.add(t, kFrontHit, k);
            }
            t += depth_ / D.z;
            if (inside_glyph(P.x + t * D.x, P.y + t * D.y, glyph) && t > lo) {
                sink.add(t, kBackHit, k);
            }
        }
        bool dirflag;
        if (std::abs(D.x) < kPovEpsilon) {
            if (std::abs(D.y) < kPovEpsilon) return;  // parallel to the walls
            dirflag = false;
        } else {
            dirflag = true;
        }
        const double a = D.y, b = -D.x, c = P.y * D.x - P.x * D.y;
        const auto wall = [&](double t, const glm::dvec2& n) {
            const double z = P.z + t * D.z;
            if (z >= 0.0 && z <= depth_ && t > lo) sink.add(t, kWallHit, k, n);
        };
        for (const GlyphData::Contour& contour : glyph.contours) {
            const auto& xv = contour.x;
            const auto& yv = contour.y;
            const auto& fv = contour.on_curve;
            double x0 = xv[0], y0 = yv[0];
            const int m = static_cast<int>(xv.size()) - 1;
            for (int j = 1; j <= m; ++j) {
                const double x1 = xv[j], y1 = yv[j];
                if (fv[j]) {
                    const double d0 = x1 - x0, d1 = y1 - y0;
                    const double t0 = d1 * D.x - d0 * D.y;
                    if (std::abs(t0) >= kPovEpsilon) {
                        double t = (D.x * (P.y - y0) - D.y * (P.x - x0)) / t0;
                        if (t >= 0.0 && t <= 1.0) {
                            t = dirflag ? ((x0 + t * d0) - P.x) / D.x : ((y0 + t * d1) - P.y) / D.y;
                            wall(t, glm::dvec2(d1, -d0));
                        }
                    }
                    x0 = x1;
                    y0 = y1;
                    continue;
                }
                double x2, y2;
                if (j == m) {
                    x2 = xv[0];
                    y2 = yv[0];
                } else {
                    x2 = xv[j + 1];
                    y2 = yv[j + 1];
                    if (!fv[j + 1]) {
                        x2 = 0.5 * (x1 + x2);
                        y2 = 0.5 * (y1 + y2);
                    }
                }
                const double xt2 = x0 - 2.0 * x1 + x2, xt1 = 2.0 * (x1 - x0), xt0 = x0;
                const double yt2 = y0 - 2.0 * y1 + y2, yt1 = 2.0 * (y1 - y0), yt0 = y0;
                const double C[3] = {a * xt2 + b * yt2, a * xt1 + b * yt1, a * xt0 + b * yt0 + c};
                double S[2];
                const int n = solve_quad(C, S, 0.0, 1.0);
                for (int l = 0; l < n; ++l) {
                    const double s = S[l];
                    const double t = dirflag ? ((s * s * xt2 + s * xt1 + xt0) - P.x) / D.x
                                             : ((s * s * yt2 + s * yt1 + yt0) - P.y) / D.y;
                    wall(t, glm::dvec2(2.0 * yt2 * s + yt1, -2.0 * xt2 * s - xt1));
                }
                x0 = x2;
                y0 = y2;
            }
        }
    }

    Text text_;
    double depth_;
    std::vector<PlacedGlyph> glyphs_;
    LocalBvh bvh_;
    Aabb bounds_;
};

}  // namespace

Result<std::shared_ptr<const ComplexShape>> prepare_text(const Text& text, const Primitive& p) {
    return std::shared_ptr<const ComplexShape>(std::make_shared<TextShape>(text, p.transform));
}

}  // namespace mirage
