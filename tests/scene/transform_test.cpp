#include "scene/transform.h"

#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace mirage {
namespace {

using testing::expect_vec;

TEST(Transform, TranslateMovesPointsNotDirections) {
    Transform t = make_translation(glm::dvec3(1, -2, 3));
    expect_vec(transform_point(t, glm::dvec3(1, 1, 1)), glm::dvec3(2, -1, 4));
    expect_vec(transform_direction(t, glm::dvec3(1, 1, 1)), glm::dvec3(1, 1, 1));
    expect_vec(inverse_transform_point(t, glm::dvec3(2, -1, 4)), glm::dvec3(1, 1, 1));
}

TEST(Transform, RotateYTakesXToMinusZ) {
    // POV-Ray's left-handed rule: rotate 90*y turns +x toward -z.
    Transform t = make_rotation(glm::dvec3(0, 90, 0));
    expect_vec(transform_point(t, glm::dvec3(1, 0, 0)), glm::dvec3(0, 0, -1));
    expect_vec(transform_point(t, glm::dvec3(0, 0, 1)), glm::dvec3(1, 0, 0));
    Transform rx = make_rotation(glm::dvec3(90, 0, 0));
    expect_vec(transform_point(rx, glm::dvec3(0, 1, 0)), glm::dvec3(0, 0, 1));
    Transform rz = make_rotation(glm::dvec3(0, 0, 90));
    expect_vec(transform_point(rz, glm::dvec3(1, 0, 0)), glm::dvec3(0, 1, 0));
}

TEST(Transform, RotateAppliesXThenYThenZ) {
    // x first takes y to z, then y takes z to x; in the order z, y, x the result would be -z.
    Transform t = make_rotation(glm::dvec3(90, 90, 0));
    expect_vec(transform_point(t, glm::dvec3(0, 1, 0)), glm::dvec3(1, 0, 0));
    Transform x_then_y = compose_transforms(make_rotation(glm::dvec3(90, 0, 0)),
                                            make_rotation(glm::dvec3(0, 90, 0)));
    EXPECT_EQ(t.matrix, x_then_y.matrix);
}

TEST(Transform, RotateMatchesPovRayVrotate) {
    // POV-Ray 3.7.0.10: #debug vstr(3, vrotate(<1,2,3>, <10,20,30>), ",", 0, 9)
    //   printed 1.067425379,2.289059483,2.760581414
    expect_vec(transform_point(make_rotation(glm::dvec3(10, 20, 30)), glm::dvec3(1, 2, 3)),
               glm::dvec3(1.067425379, 2.289059483, 2.760581414), 1e-9);
}

TEST(Transform, AxisRotationMatchesPovRayVaxisRotate) {
    // POV-Ray 3.7.0.10: #debug vstr(3, vaxis_rotate(<1,2,3>, <1,1,0>, 33), ",", 0, 9)
    //   printed 2.236018581,0.763981419,2.901129659
    expect_vec(transform_point(make_axis_rotation(glm::dvec3(1, 1, 0), 33), glm::dvec3(1, 2, 3)),
               glm::dvec3(2.236018581, 0.763981419, 2.901129659), 1e-9);
    // About x it is the same as rotate.
    Transform a = make_axis_rotation(glm::dvec3(2, 0, 0), 37);
    Transform r = make_rotation(glm::dvec3(37, 0, 0));
    expect_vec(transform_point(a, glm::dvec3(0.3, -1, 2)),
               transform_point(r, glm::dvec3(0.3, -1, 2)));
}

TEST(Transform, RotationInverseIsExactTranspose) {
    Transform t = make_rotation(glm::dvec3(10, 20, 30));
    EXPECT_EQ(t.inverse, glm::transpose(t.matrix));
    expect_vec(inverse_transform_point(t, transform_point(t, glm::dvec3(1, 2, 3))),
               glm::dvec3(1, 2, 3));
}

TEST(Transform, ScaleAndNormals) {
    Transform t = make_scaling(glm::dvec3(2, 1, 4));
    expect_vec(transform_point(t, glm::dvec3(1, 1, 1)), glm::dvec3(2, 1, 4));
    // A normal goes by the inverse transpose: the plane x + y = 1 becomes x/2 + y = 1.
    expect_vec(transform_normal(t, glm::dvec3(1, 1, 0)), glm::dvec3(0.5, 1, 0));
    EXPECT_EQ(t.inverse[0][0], 0.5);
    EXPECT_EQ(t.inverse[2][2], 0.25);
}

TEST(Transform, MatrixKeywordIsRowVectorForm) {
    // matrix <1,0,0, 1,1,0, 0,0,1, 5,6,7>: x' = x + y + 5 (a shear of x by y, then a move).
    Transform t = make_matrix_transform({1, 0, 0, 1, 1, 0, 0, 0, 1, 5, 6, 7});
    expect_vec(transform_point(t, glm::dvec3(1, 2, 3)), glm::dvec3(8, 8, 10));
    expect_vec(transform_direction(t, glm::dvec3(1, 2, 3)), glm::dvec3(3, 2, 3));
    glm::dmat4 product = t.matrix * t.inverse;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(product[c][r], c == r ? 1.0 : 0.0, 1e-14);
    }
}

TEST(Transform, ComposeAppliesFirstThenSecond) {
    Transform move = make_translation(glm::dvec3(1, 0, 0));
    Transform grow = make_scaling(glm::dvec3(2, 2, 2));
    expect_vec(transform_point(compose_transforms(move, grow), glm::dvec3(0, 0, 0)),
               glm::dvec3(2, 0, 0));
    expect_vec(transform_point(compose_transforms(grow, move), glm::dvec3(0, 0, 0)),
               glm::dvec3(1, 0, 0));
    Transform both = compose_transforms(move, grow);
    expect_vec(inverse_transform_point(both, glm::dvec3(2, 0, 0)), glm::dvec3(0, 0, 0));
    Transform inv = invert_transform(both);
    expect_vec(transform_point(inv, glm::dvec3(2, 0, 0)), glm::dvec3(0, 0, 0));
}

}  // namespace
}  // namespace mirage
