// trace(), inside(), min_extent() and max_extent() while parsing (scene/parse_queries.cpp).
#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::float_symbol;
using testing::parse_ok;
using testing::vector_symbol;

TEST(Queries, TraceFindsTheSurfaceAndItsNormal) {
    Scene s = parse_ok(R"(
#declare S = difference { sphere { <0, 1, 0>, 1 } box { <-2, 1, -2>, <2, 3, 2> } }
#declare N = <9, 9, 9>;
#declare P = trace(S, <0, 0.5, -5>, z, N);
#declare Miss = trace(S, <0, 1.5, -5>, z);
)");
    const glm::dvec3 p = vector_symbol(s, "P");
    EXPECT_NEAR(p.z, -std::sqrt(0.75), 1e-12);
    EXPECT_NEAR(p.y, 0.5, 1e-12);
    const glm::dvec3 n = vector_symbol(s, "N");
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    EXPECT_LT(n.z, -0.8);
    // Above the cut the hemisphere is gone: no hit, <0, 0, 0> as POV-Ray returns.
    EXPECT_EQ(vector_symbol(s, "Miss"), glm::dvec3(0.0));
}

TEST(Queries, InsideAndTheExtents) {
    Scene s = parse_ok(R"(
#declare S = sphere { <0, 1, 0>, 1 clipped_by { plane { y, 1.2 } } }
#declare In = inside(S, <0, 1.1, 0>);
#declare Clipped = inside(S, <0, 1.5, 0>);
#declare Out = inside(S, <0, 2.5, 0>);
#declare Lo = min_extent(S);
#declare Hi = max_extent(S);
)");
    EXPECT_EQ(float_symbol(s, "In"), 1.0);
    EXPECT_EQ(float_symbol(s, "Clipped"), 0.0);
    EXPECT_EQ(float_symbol(s, "Out"), 0.0);
    EXPECT_NEAR(vector_symbol(s, "Lo").x, -1.0, 1e-6);
    EXPECT_NEAR(vector_symbol(s, "Hi").y, 1.2, 1e-6);  // the clip's half-space bounds it
}

TEST(Queries, AnObjectIdentifierIsRequired) {
    const std::string e = testing::parse_error("#declare P = trace(3, 0, z);\n");
    EXPECT_EQ(e.rfind("scene.pov:1:20: expected an object identifier in 'trace'", 0), 0u) << e;
}

TEST(Queries, WithoutTheTracerTheyAreRefusedByName) {
    // The scene module stands below the tracer: a parse given no object queries says so.
    auto r = parse_scene_text("#declare S = sphere { 0, 1 }\n#declare Lo = min_extent(S);\n",
                              "scene.pov", ParseOptions{});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message().rfind("scene.pov:2:15: 'min_extent' asks the tracer about an object", 0),
              0u)
        << r.message();
}

}  // namespace
}  // namespace mirage
