//! The camera's coordinate system: position p and basis B = [u v w]
//! (Lecture 4, "Constructing the camera's coord. system base").

use glam::Vec3;

use crate::basis::Basis;
use crate::error::{Error, Problem, Result, finite3, unit};
use crate::ray::Ray;
use crate::transform::{Transform, from_rows};

/// Below this sine of the angle between up and the view direction, the up vector no
/// longer fixes the camera's roll and [`camera_basis`] refuses (STABILITY S10).
pub const MIN_UP_SINE: f32 = 1e-6;

// ANCHOR: camera_basis
/// The camera basis from a view direction `d` and an up vector `k`:
///
/// w = -d/|d|,  u = (k x w)/|k x w|,  v = w x u.
///
/// w points from the scene back to the eye, so the camera looks down its local -Z
/// and the local ray direction (0, 0, -1) becomes d in the world. (The slides write
/// w = d/|d|, which makes the camera look backwards: see [`camera_basis_as_on_slide`].)
///
/// u is projected off w once more after the cross product (one Gram-Schmidt step):
/// when k is nearly parallel to d, k x w is tiny and its rounding error would
/// otherwise tilt u out of the plane perpendicular to w.
pub fn camera_basis(d: Vec3, k: Vec3) -> Result<Basis> {
    let w = -unit("direction", d)?;
    let k = unit("up", k)?;
    let k_cross_w = k.cross(w);
    if k_cross_w.length() < MIN_UP_SINE {
        return Err(Error::Value {
            param: "up",
            problem: Problem::UpParallelToDirection,
        });
    }
    let u = k_cross_w.normalize();
    let u = (u - u.dot(w) * w).normalize();
    let v = w.cross(u);
    Ok(Basis::from_orthonormal(u, v, w))
}
// ANCHOR_END: camera_basis

/// The basis exactly as the slides write it: w = d/|d|, u = (k x w)/|k x w|,
/// v = (w x u)/|w x u|. Kept to show two problems in tests and in the book:
/// the camera looks backwards (local -Z maps to -d), and for k nearly parallel to d
/// the basis is no longer orthonormal. Only an exactly zero cross product is refused.
pub fn camera_basis_as_on_slide(d: Vec3, k: Vec3) -> Result<Basis> {
    let w = unit("direction", d)?;
    let u = unit("up", k)?.cross(w);
    if u == Vec3::ZERO {
        return Err(Error::Value {
            param: "up",
            problem: Problem::UpParallelToDirection,
        });
    }
    let u = u.normalize();
    let v = w.cross(u).normalize();
    Ok(Basis::from_orthonormal(u, v, w))
}

/// Where a camera stands and how it is turned: camera space to world space is
/// x_world = B x_cam + p for points and B x_cam for directions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    position: Vec3,
    basis: Basis,
}

impl Frame {
    /// The camera of the first slides: at the origin, looking down -Z, up +Y (B = I).
    pub const AT_ORIGIN: Frame = Frame {
        position: Vec3::ZERO,
        basis: Basis::STANDARD,
    };

    /// A camera at `position` looking along `direction`, with `up` towards the top of
    /// the image.
    pub fn look(position: Vec3, direction: Vec3, up: Vec3) -> Result<Frame> {
        Ok(Frame {
            position: finite3("position", position)?,
            basis: camera_basis(direction, up)?,
        })
    }

    /// A camera at `eye` looking at the point `target`, with `up` towards the top of
    /// the image: [`Frame::look`] with direction `target - eye`, the form of
    /// gluLookAt and of The Ray Tracer Challenge's `view_transform(from, to, up)`.
    ///
    /// Errors name `eye` or `target` (not finite, or `target == eye`: no direction),
    /// `up` (zero, not finite, or parallel to the view direction).
    pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Result<Frame> {
        let eye = finite3("eye", eye)?;
        let target = finite3("target", target)?;
        let direction = target - eye;
        if !direction.is_finite() {
            return Err(Error::Value {
                param: "target",
                problem: Problem::NotFinite,
            });
        }
        if direction.normalize_or_zero() == Vec3::ZERO {
            return Err(Error::Value {
                param: "target",
                problem: Problem::Invalid {
                    reason: "must differ from eye (no view direction)",
                },
            });
        }
        Frame::look(eye, direction, up)
    }

    /// A frame from a basis built elsewhere (for example [`camera_basis_as_on_slide`]).
    ///
    /// Cannot fail for a finite `position`, so it returns the frame itself, as the
    /// slide transforms do ([`crate::transform::Transform`]); a NaN or infinite one
    /// is the caller's bug and panics naming `position`. A position the user types
    /// goes through [`Frame::look`] or [`Frame::look_at`], which return an error.
    pub fn from_basis(position: Vec3, basis: Basis) -> Frame {
        assert!(
            position.is_finite(),
            "position must be finite (got {position})"
        );
        Frame { position, basis }
    }

    /// The camera position p.
    pub fn position(&self) -> Vec3 {
        self.position
    }

    /// The camera basis B = [u v w].
    pub fn basis(&self) -> Basis {
        self.basis
    }

    // ANCHOR: to_world
    /// A camera-space point in world space: B x + p.
    pub fn point_to_world(&self, x: Vec3) -> Vec3 {
        self.basis.to_world(x) + self.position
    }

    /// A camera-space direction in world space: B x.
    #[inline]
    pub fn vector_to_world(&self, x: Vec3) -> Vec3 {
        self.basis.to_world(x)
    }

    /// A camera-space ray in world space: origin B o + p, direction B d (still unit
    /// length: B is orthonormal).
    pub fn ray_to_world(&self, local: &Ray) -> Ray {
        Ray::from_checked(
            self.point_to_world(local.origin()),
            self.vector_to_world(local.direction()),
        )
    }
    // ANCHOR_END: to_world

    /// A world-space point in camera space: B^T (x - p).
    pub fn point_to_camera(&self, x: Vec3) -> Vec3 {
        self.basis.to_local(x - self.position)
    }

    // ANCHOR: world_to_camera
    /// The view matrix, world to camera space: the inverse of x_world = B x_cam + p,
    /// i.e. x_cam = B^T (x_world - p). Row by row:
    ///
    /// ```text
    /// | u_x u_y u_z  -u.p |
    /// | v_x v_y v_z  -v.p |
    /// | w_x w_y w_z  -w.p |
    /// |  0   0   0     1  |
    /// ```
    ///
    /// B^T undoes B because B is orthonormal (Lecture 4, "Coordinate System Change");
    /// this is the matrix of gluLookAt and of The Ray Tracer Challenge's
    /// `view_transform` (whose u and v rows are not normalised, so they differ from
    /// these by a factor when up is not perpendicular to the view direction).
    ///
    /// Fails, naming `position`, only when a product u.p overflows f32.
    pub fn world_to_camera(&self) -> Result<Transform> {
        let b = self.basis;
        let (u, v, w, p) = (b.u(), b.v(), b.w(), self.position);
        Transform::from_matrix(from_rows([
            [u.x, u.y, u.z, -u.dot(p)],
            [v.x, v.y, v.z, -v.dot(p)],
            [w.x, w.y, w.z, -w.dot(p)],
            [0.0, 0.0, 0.0, 1.0],
        ]))
        .map_err(|_| Error::Value {
            param: "position",
            problem: Problem::NotFinite,
        })
    }
    // ANCHOR_END: world_to_camera

    /// Camera to world space, x_world = B x_cam + p: the columns are u, v, w and p.
    ///
    /// ```text
    /// | u_x v_x w_x p_x |
    /// | u_y v_y w_y p_y |
    /// | u_z v_z w_z p_z |
    /// |  0   0   0   1  |
    /// ```
    ///
    /// The inverse of [`Frame::world_to_camera`]; always finite, so it cannot fail.
    pub fn camera_to_world(&self) -> Transform {
        let b = self.basis;
        let (u, v, w, p) = (b.u(), b.v(), b.w(), self.position);
        Transform::from_finite_matrix(from_rows([
            [u.x, v.x, w.x, p.x],
            [u.y, v.y, w.y, p.y],
            [u.z, v.z, w.z, p.z],
            [0.0, 0.0, 0.0, 1.0],
        ]))
    }
}
