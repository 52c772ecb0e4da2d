#include "scene/value.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

TEST(Value, PromoteRepeatsAFloatAndPadsAVector) {
    Numeric f = promote(Numeric::scalar(2.0), 5);
    EXPECT_EQ(f.size, 5);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(f.v[i], 2.0);
    Numeric uv;
    uv.size = 2;
    uv.v = {1.0, 2.0, 9.0, 9.0, 9.0};
    Numeric v = promote(uv, 3);
    EXPECT_EQ(v.size, 3);
    EXPECT_EQ(v.xyz(), glm::dvec3(1, 2, 0));
    // Never narrows.
    EXPECT_EQ(promote(Numeric::vector3(glm::dvec3(1, 2, 3)), 1).size, 3);
}

TEST(Value, ColourRoundTrip) {
    Colour c{glm::dvec3(0.1, 0.2, 0.3), 0.4, 0.5};
    Colour back = numeric_to_colour(Numeric::colour(c));
    EXPECT_EQ(back.rgb, c.rgb);
    EXPECT_EQ(back.filter, 0.4);
    EXPECT_EQ(back.transmit, 0.5);
    EXPECT_EQ(numeric_type_name(5), "colour");
    EXPECT_EQ(numeric_type_name(3), "vector");
}

TEST(Value, DeepCopyOfAnArraySharesNothing) {
    ArrayValue a;
    a.sizes = {2};
    a.elements = {std::make_shared<Value>(Value{Numeric::scalar(1.0)}), nullptr};
    Value original{a};
    Value copy = deep_copy(original);
    auto& copied = copy.get<ArrayValue>();
    copied.elements[0]->get<Numeric>().v[0] = 5.0;
    const auto& kept = original.get<ArrayValue>();
    EXPECT_EQ(kept.elements[0]->get<Numeric>().v[0], 1.0);
    EXPECT_EQ(copied.elements[1], nullptr);
    EXPECT_EQ(value_type_name(copy), "array");
}

}  // namespace
}  // namespace mirage
