#include "trace/pixel_ray.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

TEST(PovPixelRay, CentresMatchPovRaysArithmeticBitForBit) {
    Camera c;
    c.location = glm::dvec3(0.1, 1.7, -3.3);
    c.direction = glm::dvec3(0.02, -0.3, 1.4);
    c.right = glm::dvec3(1.3, 0.0, -0.02);
    c.up = glm::dvec3(0.0, 0.98, 0.2);
    const int w = 37;
    const int h = 23;
    for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w; ++col) {
            // tracepixel.cpp: x += 0.5; y -= 0.5; x0 = x / width - 0.5;
            // y0 = ((height - 1) - y) / height - 0.5; VLinComb3; VNormalize.
            const double x = col + 0.5;
            const double y = row - 0.5;
            const double x0 = x / w - 0.5;
            const double y0 = ((h - 1) - y) / h - 0.5;
            glm::dvec3 d;
            for (int i = 0; i < 3; ++i)
                d[i] = 1.0 * c.direction[i] + x0 * c.right[i] + y0 * c.up[i];
            const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
            d = d * (1.0 / len);
            const PixelRay r = pov_pixel_ray(c, col + 0.5, row + 0.5, w, h);
            EXPECT_EQ(r.direction, d) << col << "," << row;
            EXPECT_EQ(r.origin, c.location);
        }
    }
}

TEST(PovPixelRay, TopLeftIsUpAndLeft) {
    Camera c;  // POV-Ray's default: direction +z, right 1.33 x, up y
    const PixelRay centre = pov_pixel_ray(c, 2.0, 1.5, 4, 3);
    EXPECT_EQ(centre.direction, glm::dvec3(0.0, 0.0, 1.0));
    const PixelRay corner = pov_pixel_ray(c, 0.0, 0.0, 4, 3);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(-0.5 * 1.33, 0.5, 1.0));
    EXPECT_NEAR(glm::length(corner.direction - expected), 0.0, 1e-15);
}

}  // namespace
}  // namespace mirage
