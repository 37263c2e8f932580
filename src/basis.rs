//! Orthonormal bases and the change of coordinates (Lecture 4, "Coordinate System
//! Change").
//!
//! A vector s has coordinates a in the standard basis (e1, e2, e3) and coordinates b
//! in another orthonormal basis (u, v, w). Both describe the same arrow:
//! s = [e1 e2 e3] a = [u v w] b, and since [e1 e2 e3] is the identity, a = B b with
//! B = [u v w]. An orthonormal B has B^T B = I, so the way back is b = B^T a.

use glam::{Mat3, Vec3};

use crate::error::{Error, Problem, Result, finite3};

/// Largest |B^T B - I| entry accepted as orthonormal by [`Basis::new`].
pub const ORTHONORMAL_TOLERANCE: f32 = 1e-4;

/// An orthonormal basis, its vectors the columns of B = [u v w].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Basis {
    u: Vec3,
    v: Vec3,
    w: Vec3,
}

impl Basis {
    /// The standard basis (e1, e2, e3): B is the identity and a = b.
    pub const STANDARD: Basis = Basis {
        u: Vec3::X,
        v: Vec3::Y,
        w: Vec3::Z,
    };

    /// The basis with columns `u`, `v`, `w`, if they are orthonormal within
    /// [`ORTHONORMAL_TOLERANCE`]. Handedness is not required; ask
    /// [`Basis::is_right_handed`].
    pub fn new(u: Vec3, v: Vec3, w: Vec3) -> Result<Basis> {
        let basis = Basis {
            u: finite3("u", u)?,
            v: finite3("v", v)?,
            w: finite3("w", w)?,
        };
        let error = basis.orthonormality_error();
        if error <= ORTHONORMAL_TOLERANCE {
            Ok(basis)
        } else {
            Err(Error::Value {
                param: "basis",
                problem: Problem::NotOrthonormal { error },
            })
        }
    }

    // ANCHOR: around
    /// A right-handed orthonormal basis with `n` (unit) as its third vector w, for
    /// sampling directions around a surface normal: the branchless construction of
    /// Duff, Burgess, Christensen, Hery, Kensler, Liani and Villemin, "Building an
    /// Orthonormal Basis, Revisited", JCGT 6(1), 2017. Accurate for every unit n
    /// (STABILITY S12).
    pub fn around(n: Vec3) -> Basis {
        let sign = 1.0f32.copysign(n.z);
        let a = -1.0 / (sign + n.z);
        let b = n.x * n.y * a;
        let u = Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
        let v = Vec3::new(b, sign + n.y * n.y * a, -n.y);
        Basis { u, v, w: n }
    }
    // ANCHOR_END: around

    /// The same, by Frisvad's earlier method ("Building an Orthonormal Basis from a 3D
    /// Unit Vector Without Normalization", JGT 2012), kept to show its failure: for n
    /// close to -Z but not within its 0.9999999 guard, 1/(1 + n.z) loses almost every
    /// digit and the basis is far from orthonormal (STABILITY S12).
    pub fn around_frisvad(n: Vec3) -> Basis {
        if n.z < -0.999_999_9 {
            return Basis {
                u: Vec3::new(0.0, -1.0, 0.0),
                v: Vec3::new(-1.0, 0.0, 0.0),
                w: n,
            };
        }
        let a = 1.0 / (1.0 + n.z);
        let b = -n.x * n.y * a;
        let u = Vec3::new(1.0 - n.x * n.x * a, b, -n.x);
        let v = Vec3::new(b, 1.0 - n.y * n.y * a, -n.y);
        Basis { u, v, w: n }
    }

    /// Three vectors the caller has built to be orthonormal (e.g. by cross products).
    pub(crate) fn from_orthonormal(u: Vec3, v: Vec3, w: Vec3) -> Basis {
        Basis { u, v, w }
    }

    /// The first basis vector.
    pub fn u(&self) -> Vec3 {
        self.u
    }

    /// The second basis vector.
    pub fn v(&self) -> Vec3 {
        self.v
    }

    /// The third basis vector.
    pub fn w(&self) -> Vec3 {
        self.w
    }

    /// The matrix B = [u v w], basis vectors as columns.
    pub fn matrix(&self) -> Mat3 {
        Mat3::from_cols(self.u, self.v, self.w)
    }

    // ANCHOR: change
    /// a = B b: from coordinates in this basis to standard (world) coordinates.
    #[inline]
    pub fn to_world(&self, b: Vec3) -> Vec3 {
        b.x * self.u + b.y * self.v + b.z * self.w
    }

    /// b = B^T a: from standard coordinates to coordinates in this basis.
    /// Each coordinate is a dot product with one basis vector.
    pub fn to_local(&self, a: Vec3) -> Vec3 {
        Vec3::new(a.dot(self.u), a.dot(self.v), a.dot(self.w))
    }
    // ANCHOR_END: change

    /// The largest entry of |B^T B - I|: 0 for an exactly orthonormal basis.
    pub fn orthonormality_error(&self) -> f32 {
        let m = self.matrix();
        let gram = m.transpose() * m - Mat3::IDENTITY;
        gram.to_cols_array()
            .into_iter()
            .fold(0.0, |acc, x| acc.max(x.abs()))
    }

    /// True when u x v points along w (det B = +1), as in a right-handed world.
    pub fn is_right_handed(&self) -> bool {
        self.u.cross(self.v).dot(self.w) > 0.0
    }
}
