//! Where lesson 09 puts a model read from a file: standing on the floor at the
//! front right of lesson 08's still life, tilted towards the camera, as large as the
//! torus it stands in for and no larger than the frame allows, whatever the model's
//! size and place in its file. A speck far from the rest (a stray triangle a
//! modelling tool left behind) does not count.

use glam::{DVec3, Vec3};

use crate::camera::Camera;
use crate::error::{Result, finite};
use crate::mesh::Mesh;
use crate::transform::Transform;

/// Which axis of a model's file points up. Most modelling tools write y up; scans,
/// CAD and 3D-printing files write z up.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Up {
    /// y up (the default).
    #[default]
    Y,
    /// z up.
    Z,
}

impl Up {
    /// `p` turned so that y is up: z up turns a quarter turn about x,
    /// (x, y, z) -> (x, z, -y), which puts the file's front (-y) towards +z, the
    /// still life's camera. Exact: the coordinates are only swapped and negated.
    pub fn to_y_up(self, p: Vec3) -> Vec3 {
        match self {
            Up::Y => p,
            Up::Z => Vec3::new(p.x, p.z, -p.y),
        }
    }
}

/// The half side that the longest side of a model's box is scaled to: the torus's.
pub const HALF_SIDE: f32 = 1.4;

/// The point of the floor the model stands on, under its box's centre.
pub const STAND: Vec3 = Vec3::new(2.2, 0.0, 1.6);

/// The tilt towards the camera, a turn about x in radians.
pub const TILT: f32 = -0.5;

/// The share of the frame's width and height kept free on each side of the model.
pub const MARGIN: f64 = 0.01;

/// The share of the frame's width and height on each side that the point the model
/// stands on must keep clear of ([`stand`]).
pub const STAND_INSET: f64 = 0.1;

/// The share of the area below and above the box of a model's bulk, along each axis
/// ([`bulk`]).
pub const BULK_TAIL: f64 = 0.01;

/// What fitting a model did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    /// Triangles left out of the fit, far from the model's bulk ([`bulk`]): they
    /// are drawn, but the model is placed and sized without them.
    pub left_out: usize,
    /// Their share of the model's area, 0 to 1.
    pub left_out_area: f64,
    /// What the frame took off the model's size: 1 when the model, at the torus's
    /// size, fits the frame.
    pub frame_scale: f32,
}

// ANCHOR: place
/// Places `mesh` (y up) where lesson 09 shows it through `camera`: moves and scales
/// its positions so that the box of its bulk ([`bulk`]) is centred on the origin
/// with a longest half side of [`HALF_SIDE`], or less where the frame asks
/// ([`frame_scale`] about the [`stand`], [`MARGIN`] inside the frame); returns the
/// model transform that tilts it by [`TILT`] and stands it over the stand with the
/// lowest corner of its bulk on the floor, and what the fit did. Scaling about a
/// point of the floor keeps the model standing on it.
pub fn place(mesh: &mut Mesh, camera: &Camera) -> Result<(Transform, Fit)> {
    let in_bulk = bulk(mesh);
    let bulk_corners: Vec<Vec3> = (mesh.triangles.iter().zip(&in_bulk))
        .filter(|&(_, &kept)| kept)
        .flat_map(|(t, _)| t.map(|i| mesh.positions[i as usize]))
        .collect();
    let (lo, hi) = bulk_corners
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    let centre = (lo + hi) * 0.5;
    let full = finite("scale", HALF_SIDE / ((hi - lo) * 0.5).max_element())?;
    let (tilt, stand) = (Transform::rotation_x(TILT), stand(camera));
    let standing = |scale: f32| {
        let lowest = (bulk_corners.iter())
            .map(|&p| tilt.point((p - centre) * scale).y)
            .fold(f32::INFINITY, f32::min);
        tilt.then(Transform::translation(stand.x, -lowest, stand.z))
    };
    let at_full = standing(full);
    let placed = bulk_corners
        .iter()
        .map(|&p| at_full.point((p - centre) * full));
    let frame = frame_scale(camera, stand, MARGIN, placed);
    let scale = full * frame;
    for p in &mut mesh.positions {
        *p = (*p - centre) * scale;
    }
    let areas: Vec<f64> = mesh.triangles.iter().map(|t| twice_area(mesh, t)).collect();
    let left_out = || areas.iter().zip(&in_bulk).filter(|&(_, &kept)| !kept);
    let fit = Fit {
        left_out: left_out().count(),
        left_out_area: left_out().map(|(a, _)| a).sum::<f64>()
            / areas.iter().sum::<f64>(),
        frame_scale: frame,
    };
    Ok((standing(scale), fit))
}
// ANCHOR_END: place

/// Twice the area of triangle `t` of `mesh`, |(b - a) x (c - a)|, in f64.
fn twice_area(mesh: &Mesh, t: &[u32; 3]) -> f64 {
    let [a, b, c] = t.map(|i| mesh.positions[i as usize].as_dvec3());
    (b - a).cross(c - a).length()
}

/// The point of the floor the model stands on: [`STAND`], or, where `camera` does
/// not see it [`STAND_INSET`] inside its frame (a frame narrower than the book's),
/// the last point on the way to it from the floor's origin, below the point the
/// camera looks at, that it sees so.
pub fn stand(camera: &Camera) -> Vec3 {
    STAND * frame_scale(camera, Vec3::ZERO, STAND_INSET, [STAND].into_iter())
}

/// Which triangles of `mesh` make its bulk: those whose corners all lie in the box
/// that holds the middle of its area, grown on every side by that box's longest
/// side. Each triangle's area is shared among its three corners; along each axis
/// the box runs from the coordinate below which [`BULK_TAIL`] of the area lies to
/// the one above which [`BULK_TAIL`] lies (weighted quantiles). A speck far from
/// the model has next to no area: it does not move the box, and it lies outside the
/// grown box; any part of the model within the box's size of the rest is kept. The
/// six tails hold at most 6 % of the corners' weight, so the triangles with a
/// corner outside even the box before it grows hold at most 18 % of the area: the
/// bulk is never empty.
pub fn bulk(mesh: &Mesh) -> Vec<bool> {
    let corner = |t: &[u32; 3], k: usize| mesh.positions[t[k] as usize];
    let weights: Vec<f64> =
        mesh.triangles.iter().map(|t| twice_area(mesh, t)).collect();
    let total: f64 = 3.0 * weights.iter().sum::<f64>();
    let mut lo = DVec3::ZERO;
    let mut hi = DVec3::ZERO;
    for axis in 0..3 {
        let mut along: Vec<(f32, f64)> = (mesh.triangles.iter().zip(&weights))
            .flat_map(|(t, &w)| [0, 1, 2].map(|k| (corner(t, k)[axis], w)))
            .collect();
        along.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let quantile = |share: f64| {
            let mut below = 0.0;
            let found = along.iter().find(|&&(_, w)| {
                below += w;
                below >= share * total
            });
            f64::from(found.map_or(along[along.len() - 1].0, |&(x, _)| x))
        };
        lo[axis] = quantile(BULK_TAIL);
        hi[axis] = quantile(1.0 - BULK_TAIL);
    }
    let grow = DVec3::splat((hi - lo).max_element());
    let (lo, hi) = (lo - grow, hi + grow);
    let inside = |p: Vec3| {
        let p = p.as_dvec3();
        p.cmpge(lo).all() && p.cmple(hi).all()
    };
    (mesh.triangles.iter())
        .map(|t| total == 0.0 || t.iter().all(|&i| inside(mesh.positions[i as usize])))
        .collect()
}

// ANCHOR: frame_scale
/// The largest factor, at most 1, by which the points `world` may be scaled about
/// `anchor` and all be seen by `camera`, `inset` (a share of the frame's width and
/// height) inside the frame. In camera space a point q lies in the frame when
/// x_min d <= q_x <= x_max d and y_min d <= q_y <= y_max d, with d = -q_z / s for a
/// pinhole at screen distance s (1 for an orthographic camera): four margins
/// g(q) <= 0, each linear in q, so along anchor + t (p - anchor) each is
/// g0 + t (g1 - g0), which turns positive only past t = g0 / (g0 - g1). A margin
/// already positive at the anchor cannot be helped by scaling and is left alone.
pub fn frame_scale(
    camera: &Camera,
    anchor: Vec3,
    inset: f64,
    world: impl Iterator<Item = Vec3>,
) -> f32 {
    let shrink = |(min, max): (f32, f32)| {
        let inset = inset * f64::from(max - min);
        (f64::from(min) + inset, f64::from(max) - inset)
    };
    let ((x0, x1), (y0, y1)) = (
        shrink(camera.film().x_extent()),
        shrink(camera.film().y_extent()),
    );
    let margins = |p: Vec3| {
        let q = camera.frame().point_to_camera(p).as_dvec3();
        let d = camera
            .pinhole()
            .map_or(1.0, |c| -q.z / f64::from(c.screen_distance()));
        [q.x - x1 * d, x0 * d - q.x, q.y - y1 * d, y0 * d - q.y, -d]
    };
    let at_anchor = margins(anchor);
    let mut scale = 1.0f64;
    for p in world {
        for (g0, g1) in at_anchor.into_iter().zip(margins(p)) {
            if g0 < 0.0 && g1 > 0.0 {
                scale = scale.min(g0 / (g0 - g1));
            }
        }
    }
    scale as f32
}
// ANCHOR_END: frame_scale
