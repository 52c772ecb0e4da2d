#include "patterns/single_precision.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

// Kept out of line so the compiler vectorises it the way it would in the shader.
__attribute__((noinline)) glm::dvec3 scaled(const glm::dvec3& a, const glm::dvec3& b) {
    return a * to_single(b);
}

TEST(SinglePrecision, RoundsEveryLaneEvenWhenVectorised) {
    volatile double tenth = 0.1;  // not a constant the compiler could fold
    const glm::dvec3 r = scaled(glm::dvec3(1.0), glm::dvec3(tenth, 2.0 * tenth, 3.0 * tenth));
    EXPECT_EQ(r.x, static_cast<double>(0.1f));
    EXPECT_EQ(r.y, static_cast<double>(static_cast<float>(2.0 * tenth)));
    EXPECT_EQ(r.z, static_cast<double>(static_cast<float>(3.0 * tenth)));
    EXPECT_EQ(to_single(0.5), 0.5);
}

}  // namespace
}  // namespace mirage
