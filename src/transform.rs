//! Geometric transformations in homogeneous coordinates (Lecture 3).
//!
//! A 3-D point (x, y, z) becomes the 4-vector (x, y, z, 1) and a direction becomes
//! (x, y, z, 0). With the fourth coordinate, translation is a matrix too (a 4-D
//! shear), so scale, rotation and translation all compose by multiplication.
//!
//! Every matrix below is written out row by row, exactly as the slides print it;
//! `tests/lessons/lesson_01_transforms.rs` checks each one against glam's own
//! constructors.

use std::ops::Mul;

use glam::{Mat4, Vec3, Vec4};

use crate::error::{Error, Problem, Result, finite3};

/// An affine transformation: one 4x4 matrix acting on homogeneous coordinates,
/// always finite.
///
/// The slide constructors (scale, the three rotations, translation) cannot fail: a
/// finite number always gives a finite matrix, so they return the `Transform`
/// itself. A NaN or infinite parameter is a bug in the caller, and they panic naming
/// it rather than build a matrix full of NaN. A value a user types is checked where
/// it is read, with an error naming the flag, as the lessons do.
/// Angles are in radians, as `angle_radians` says; a lesson that reads degrees
/// converts once, with `to_radians`.
///
/// ```
/// use glam::Vec3;
/// use render_lessons::transform::Transform;
///
/// let turn = Transform::rotation_z(90f32.to_radians());
/// assert!(turn.point(Vec3::X).abs_diff_eq(Vec3::Y, 1e-6));
/// let moved = turn.then(Transform::translation(1.0, 0.0, 0.0));
/// assert!(moved.point(Vec3::X).abs_diff_eq(Vec3::new(1.0, 1.0, 0.0), 1e-6));
/// assert!(std::panic::catch_unwind(|| Transform::rotation_x(f32::NAN)).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    matrix: Mat4,
}

/// `value` itself if it is finite; a panic naming `param` otherwise (see
/// [`Transform`]: the slide constructors take finite numbers only).
fn finite(param: &str, value: f32) -> f32 {
    assert!(
        value.is_finite(),
        "{param} must be a finite number (got {value})"
    );
    value
}

/// The homogeneous point (x, y, z, 1): translations move it.
pub fn point(x: f32, y: f32, z: f32) -> Vec4 {
    Vec4::new(x, y, z, 1.0)
}

/// The homogeneous vector (x, y, z, 0): translations leave it alone.
pub fn vector(x: f32, y: f32, z: f32) -> Vec4 {
    Vec4::new(x, y, z, 0.0)
}

/// A matrix given row by row, the way it is printed on a slide.
///
/// glam stores matrices column by column, so the rows are transposed once here.
pub fn from_rows(rows: [[f32; 4]; 4]) -> Mat4 {
    Mat4::from_cols_array_2d(&rows).transpose()
}

impl Transform {
    /// The transformation that changes nothing.
    pub const IDENTITY: Transform = Transform {
        matrix: Mat4::IDENTITY,
    };

    /// Wraps a matrix the caller built; it must be finite.
    pub fn from_matrix(matrix: Mat4) -> Result<Transform> {
        if matrix.is_finite() {
            Ok(Transform { matrix })
        } else {
            Err(Error::Value {
                param: "matrix",
                problem: Problem::NotFinite,
            })
        }
    }

    // ANCHOR: scale
    /// Scale along X, Y and Z: x' = x s_x, y' = y s_y, z' = z s_z (Lecture 3, "3D
    /// Scale").
    pub fn scale(sx: f32, sy: f32, sz: f32) -> Transform {
        let (sx, sy, sz) = (finite("sx", sx), finite("sy", sy), finite("sz", sz));
        Transform::from_finite_matrix(from_rows([
            [sx, 0.0, 0.0, 0.0],
            [0.0, sy, 0.0, 0.0],
            [0.0, 0.0, sz, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]))
    }
    // ANCHOR_END: scale

    // ANCHOR: rotation_x
    /// Rotation by `angle_radians` about the X axis (Lecture 3, "3D Rotation about X"):
    /// y' = y cos - z sin, z' = y sin + z cos.
    pub fn rotation_x(angle_radians: f32) -> Transform {
        let (s, c) = finite("angle_radians", angle_radians).sin_cos();
        Transform::from_finite_matrix(from_rows([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, c, -s, 0.0],
            [0.0, s, c, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]))
    }
    // ANCHOR_END: rotation_x

    // ANCHOR: rotation_y
    /// Rotation by `angle_radians` about the Y axis (Lecture 3, "3D Rotation about Y"):
    /// x' = x cos + z sin, z' = -x sin + z cos.
    ///
    /// The minus sign sits bottom-left, not top-right as for X and Z: the rotation
    /// turns Z towards X (the cyclic order x -> y -> z -> x), and in the matrix's
    /// rows X comes before Z.
    pub fn rotation_y(angle_radians: f32) -> Transform {
        let (s, c) = finite("angle_radians", angle_radians).sin_cos();
        Transform::from_finite_matrix(from_rows([
            [c, 0.0, s, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [-s, 0.0, c, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]))
    }
    // ANCHOR_END: rotation_y

    // ANCHOR: rotation_z
    /// Rotation by `angle_radians` about the Z axis (Lecture 3, "3D Rotation about Z"):
    /// x' = x cos - y sin, y' = x sin + y cos.
    pub fn rotation_z(angle_radians: f32) -> Transform {
        let (s, c) = finite("angle_radians", angle_radians).sin_cos();
        Transform::from_finite_matrix(from_rows([
            [c, -s, 0.0, 0.0],
            [s, c, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]))
    }
    // ANCHOR_END: rotation_z

    // ANCHOR: translation
    /// Translation by (d_x, d_y, d_z) (Lecture 3, "3D Translation"): in homogeneous
    /// coordinates a translation is a shear of the fourth dimension.
    pub fn translation(dx: f32, dy: f32, dz: f32) -> Transform {
        let (dx, dy, dz) = (finite("dx", dx), finite("dy", dy), finite("dz", dz));
        Transform::from_finite_matrix(from_rows([
            [1.0, 0.0, 0.0, dx],
            [0.0, 1.0, 0.0, dy],
            [0.0, 0.0, 1.0, dz],
            [0.0, 0.0, 0.0, 1.0],
        ]))
    }
    // ANCHOR_END: translation

    // ANCHOR: then
    /// First `self`, then `next`: the matrix `next * self`.
    ///
    /// Matrices act on the column vector to their right, so the transformation applied
    /// first stands rightmost in the product.
    pub fn then(self, next: Transform) -> Transform {
        Transform {
            matrix: next.matrix * self.matrix,
        }
    }
    // ANCHOR_END: then

    /// Wraps a matrix the crate has built from finite parts and knows to be finite
    /// (checked in debug builds only).
    pub(crate) fn from_finite_matrix(matrix: Mat4) -> Transform {
        debug_assert!(matrix.is_finite());
        Transform { matrix }
    }

    /// The transformation that undoes this one, or [`Problem::Singular`] (e.g. a scale
    /// by 0).
    pub fn inverse(self) -> Result<Transform> {
        let det = self.matrix.determinant();
        if det == 0.0 || !det.is_finite() {
            return Err(Error::Value {
                param: "transform",
                problem: Problem::Singular,
            });
        }
        Transform::from_matrix(self.matrix.inverse()).map_err(|_| Error::Value {
            param: "transform",
            problem: Problem::Singular,
        })
    }

    /// The 4x4 matrix.
    pub fn matrix(&self) -> Mat4 {
        self.matrix
    }

    // ANCHOR: apply
    /// The matrix times a homogeneous 4-vector: points (w = 1) and vectors (w = 0)
    /// alike.
    pub fn apply(&self, h: Vec4) -> Vec4 {
        self.matrix * h
    }

    /// Transforms the point `p` (w = 1); translation moves it.
    pub fn point(&self, p: Vec3) -> Vec3 {
        self.apply(p.extend(1.0)).truncate()
    }

    /// Transforms the direction `v` (w = 0); translation does not touch it.
    pub fn vector(&self, v: Vec3) -> Vec3 {
        self.apply(v.extend(0.0)).truncate()
    }
    // ANCHOR_END: apply

    /// Transforms a surface normal: by the inverse transpose, so that it stays
    /// perpendicular to the transformed surface under non-uniform scale.
    pub fn normal(&self, n: Vec3) -> Result<Vec3> {
        let inv = self.inverse()?;
        finite3("normal", inv.matrix.transpose().transform_vector3(n))
    }
}

// ANCHOR: mul
/// `a * b` is the matrix product A B, written in the order of the paper: applied to
/// a point, `b` acts first and `a` last, so `c * b * a` means "first a, then b,
/// then c", and `a * b == b.then(a)`. This is how most books write chains of
/// transforms (The Ray Tracer Challenge, ch. 4, "Chaining Transformations":
/// T = C B A). There is no `Transform * Vec3`: say [`Transform::point`] or
/// [`Transform::vector`], so that a translation's effect is never a guess.
impl Mul for Transform {
    type Output = Transform;

    fn mul(self, rhs: Transform) -> Transform {
        rhs.then(self)
    }
}
// ANCHOR_END: mul

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mul_is_then_reversed_bit_for_bit() {
        let a = Transform::rotation_y(0.3);
        let b = Transform::translation(1.0, -2.0, 3.5);
        assert_eq!((a * b).matrix(), b.then(a).matrix());
        assert_eq!((a * b).matrix(), a.matrix() * b.matrix());
        assert_ne!(a * b, b * a, "translation and rotation do not commute");
    }
}
