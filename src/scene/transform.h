// POV-Ray's transformations (translate, rotate, scale, matrix, axis rotation) as 4x4 matrices
// acting on column vectors, with their inverses kept exact where POV-Ray keeps them exact.
//
// POV-Ray stores row-vector matrices (p' = p M, translation in the last row); here
// p' = M p, so `matrix` is the transpose of POV-Ray's.  Rotations follow POV-Ray's
// left-handed convention: `rotate <a, b, c>` turns a degrees about x, then b about y, then c
// about z, each by the usual formula (rotate 90*y takes +x to -z).
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace mirage {

/// The identity.
Transform identity_transform();

/// `translate v`.
Transform make_translation(const glm::dvec3& v);

/// `rotate degrees`: about x, then y, then z.
Transform make_rotation(const glm::dvec3& degrees);

/// `scale s`; every component must be non-zero (the parser replaces zeros by 1 as POV-Ray does).
Transform make_scaling(const glm::dvec3& s);

/// Rotation by `degrees` about `axis` (POV-Ray's vaxis_rotate): positive angles turn the way
/// `rotate` does about x, y and z.
Transform make_axis_rotation(const glm::dvec3& axis, double degrees);

/// `matrix <m00, m01, m02, m10, m11, m12, m20, m21, m22, m30, m31, m32>` as POV-Ray reads it:
/// the point p goes to (p.x m00 + p.y m10 + p.z m20 + m30, ...).  The matrix must be
/// invertible.
Transform make_matrix_transform(const std::array<double, 12>& m);

/// The transform that applies `first`, then `second` (POV-Ray's Compose_Transforms).
Transform compose_transforms(const Transform& first, const Transform& second);

/// The inverse transform.
Transform invert_transform(const Transform& t);

/// Applies t to a point (with translation).
glm::dvec3 transform_point(const Transform& t, const glm::dvec3& p);

/// Applies t to a direction (without translation).
glm::dvec3 transform_direction(const Transform& t, const glm::dvec3& d);

/// Applies t to a surface normal (inverse transpose); the result is not normalised.
glm::dvec3 transform_normal(const Transform& t, const glm::dvec3& n);

/// Applies the inverse of t to a point: world space to object or pattern space.
glm::dvec3 inverse_transform_point(const Transform& t, const glm::dvec3& p);

/// Applies the inverse of t to a direction.
glm::dvec3 inverse_transform_direction(const Transform& t, const glm::dvec3& d);

}  // namespace mirage
