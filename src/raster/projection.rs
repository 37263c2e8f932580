//! Transform (Lecture 2, "Rasterization Pipeline: Transform"): every vertex goes
//! model -> world -> camera -> clip space by 4x4 matrices, then through the
//! perspective divide to normalised device coordinates (NDC) and by the viewport to
//! pixels.
//!
//! Conventions: camera space looks down -Z (as the cameras of lesson 05/06); NDC is
//! the cube [-1, 1]^3 with the near plane at z = -1 and the far plane at z = +1 (the
//! OpenGL convention); pixels count columns from the left and rows from the top, and
//! the centre of pixel (i, j) is (i + 0.5, j + 0.5), as in [`Film::plane_to_pixel`].
//! So a vertex lands on exactly the continuous pixel position that
//! `PinholeCamera::project` and `OrthoCamera::project` give it.

use glam::{Vec3, Vec4};

use crate::camera::{Camera, Film, Frame};
use crate::error::{Error, Problem, Result, finite, positive};
use crate::transform::{Transform, from_rows};

/// Where the depth range starts and ends, as distances in front of the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthRange {
    /// Distance to the near plane (> 0 for a pinhole camera, >= 0 for orthographic).
    pub near: f32,
    /// Distance to the far plane (> near).
    pub far: f32,
}

/// The three matrices of one camera, and the film they map onto.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraTransforms {
    view: Transform,
    projection: Transform,
    viewport: Transform,
    film: Film,
}

impl CameraTransforms {
    /// The view, projection and viewport matrices that reproduce `camera`.
    pub fn new(camera: &Camera, depth: DepthRange) -> Result<CameraTransforms> {
        let film = *camera.film();
        let projection = match camera.pinhole() {
            Some(c) => perspective(&film, c.screen_distance(), depth)?,
            None => orthographic(&film, depth)?,
        };
        Ok(CameraTransforms {
            view: view(camera.frame())?,
            projection,
            viewport: viewport(&film)?,
            film,
        })
    }

    /// World to camera space.
    pub fn view(&self) -> Transform {
        self.view
    }

    /// Camera to clip space.
    pub fn projection(&self) -> Transform {
        self.projection
    }

    /// NDC to pixels (and depth in [0, 1]).
    pub fn viewport(&self) -> Transform {
        self.viewport
    }

    /// The film the viewport maps onto.
    pub fn film(&self) -> &Film {
        &self.film
    }

    // ANCHOR: to_clip
    /// A model-space point in clip space: P V M (x, y, z, 1).
    pub fn to_clip(&self, model: &Transform, p: Vec3) -> Vec4 {
        let world = model.point(p);
        self.projection.apply(self.view.apply(world.extend(1.0)))
    }
    // ANCHOR_END: to_clip

    // ANCHOR: to_screen
    /// A clip-space point in pixels: divide by w (clip -> NDC), then the viewport.
    /// The result is (column, row from the top, depth in [0, 1]), or `None` when
    /// w <= 0: such a point is not in front of the camera and must be clipped first.
    pub fn to_screen(&self, clip: Vec4) -> Option<Vec3> {
        if clip.w <= 0.0 || !clip.is_finite() {
            return None;
        }
        let ndc = clip.truncate() / clip.w;
        Some(self.viewport.point(ndc))
    }
    // ANCHOR_END: to_screen
}

// ANCHOR: view
/// World to camera space for a camera with position p and basis [u v w]: the inverse
/// of x_world = B x_cam + p, i.e. x_cam = B^T (x_world - p). Row by row:
///
/// ```text
/// | u_x u_y u_z  -u.p |
/// | v_x v_y v_z  -v.p |
/// | w_x w_y w_z  -w.p |
/// |  0   0   0     1  |
/// ```
///
/// The matrix belongs to the camera, so the frame builds it
/// ([`Frame::world_to_camera`]); the pipeline only asks for it.
pub fn view(frame: &Frame) -> Result<Transform> {
    frame.world_to_camera()
}
// ANCHOR_END: view

fn depth_range(depth: DepthRange, near_min_exclusive: bool) -> Result<(f32, f32)> {
    let near = finite("near", depth.near)?;
    let far = finite("far", depth.far)?;
    if near_min_exclusive {
        positive("near", near)?;
    } else if near < 0.0 {
        return Err(Error::Value {
            param: "near",
            problem: Problem::NotPositive { value: near },
        });
    }
    if far > near && (far - near).is_finite() {
        Ok((near, far))
    } else {
        Err(Error::Value {
            param: "near .. far",
            problem: Problem::EmptyRange {
                min: near,
                max: far,
            },
        })
    }
}

// ANCHOR: perspective
/// The perspective projection of [`crate::camera::PinholeCamera`]: its screen at
/// z = -s spans [l, r] x [b, t] (the film's extents), depth runs from n to f.
/// A camera-space point (x, y, z) lands on the screen at x s/(-z), which the NDC
/// maps to 2 (x s/(-z) - l)/(r - l) - 1; multiplying through by w = -z gives
///
/// ```text
/// | 2s/(r-l)    0       (r+l)/(r-l)        0       |
/// |    0     2s/(t-b)   (t+b)/(t-b)        0       |
/// |    0        0      -(f+n)/(f-n)   -2fn/(f-n)   |
/// |    0        0           -1             0       |
/// ```
///
/// (the frustum matrix of OpenGL's glFrustum with the screen at distance s instead
/// of the near plane: only the ratio l/s matters, so the image is the same).
pub fn perspective(film: &Film, s: f32, depth: DepthRange) -> Result<Transform> {
    let s = positive("screen distance", s)?;
    let (n, f) = depth_range(depth, true)?;
    let ((l, r), (b, t)) = (film.x_extent(), film.y_extent());
    Transform::from_matrix(from_rows([
        [2.0 * s / (r - l), 0.0, (r + l) / (r - l), 0.0],
        [0.0, 2.0 * s / (t - b), (t + b) / (t - b), 0.0],
        [0.0, 0.0, -(f + n) / (f - n), -2.0 * f * n / (f - n)],
        [0.0, 0.0, -1.0, 0.0],
    ]))
}
// ANCHOR_END: perspective

// ANCHOR: orthographic
/// The orthographic projection of [`crate::camera::OrthoCamera`]: the camera plane's
/// rectangle [l, r] x [b, t] goes to [-1, 1]^2 without any division, depth n .. f
/// to -1 .. 1:
///
/// ```text
/// | 2/(r-l)     0         0       -(r+l)/(r-l) |
/// |    0     2/(t-b)      0       -(t+b)/(t-b) |
/// |    0        0     -2/(f-n)    -(f+n)/(f-n) |
/// |    0        0         0             1      |
/// ```
pub fn orthographic(film: &Film, depth: DepthRange) -> Result<Transform> {
    let (n, f) = depth_range(depth, false)?;
    let ((l, r), (b, t)) = (film.x_extent(), film.y_extent());
    Transform::from_matrix(from_rows([
        [2.0 / (r - l), 0.0, 0.0, -(r + l) / (r - l)],
        [0.0, 2.0 / (t - b), 0.0, -(t + b) / (t - b)],
        [0.0, 0.0, -2.0 / (f - n), -(f + n) / (f - n)],
        [0.0, 0.0, 0.0, 1.0],
    ]))
}
// ANCHOR_END: orthographic

// ANCHOR: viewport
/// NDC to pixels for a `W` x `H` image, rows counted from the top (so NDC y = +1,
/// the top of the film, becomes row 0), and depth from [-1, 1] to [0, 1]:
///
/// ```text
/// | W/2    0     0    W/2 |
/// |  0   -H/2    0    H/2 |
/// |  0     0    1/2   1/2 |
/// |  0     0     0     1  |
/// ```
///
/// x = -1 is the left edge of column 0 and the centre of pixel (i, j) is at
/// (i + 0.5, j + 0.5), the same continuous coordinates as `Film::plane_to_pixel`.
pub fn viewport(film: &Film) -> Result<Transform> {
    let (w, h) = (film.width() as f32, film.height() as f32);
    Transform::from_matrix(from_rows([
        [w / 2.0, 0.0, 0.0, w / 2.0],
        [0.0, -h / 2.0, 0.0, h / 2.0],
        [0.0, 0.0, 0.5, 0.5],
        [0.0, 0.0, 0.0, 1.0],
    ]))
}
// ANCHOR_END: viewport
