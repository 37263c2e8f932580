//! Turning uniform random numbers into directions, each beside its density.
//!
//! Every sampling function `name(u)` has a `name_pdf` giving the density of the
//! samples it draws, per unit solid angle for directions and per unit area for
//! points of the disc, and 0 outside the function's domain (pbrt-v4 section A.5).
//! `tests/lessons/lesson_10_densities.rs` checks each one: it integrates to 1 over its
//! domain, and it matches a histogram of a million samples.
//!
//! ```
//! use glam::Vec2;
//! use render_lessons::sampling::*;
//!
//! let u = Vec2::new(0.36, 0.7);
//! let w = cosine_hemisphere(u);
//! assert_eq!(cosine_hemisphere_pdf(w.z), w.z / std::f32::consts::PI); // 0.8 / pi
//! assert_eq!(uniform_hemisphere_pdf(uniform_hemisphere(u).z), 0.5 / std::f32::consts::PI);
//! assert_eq!(uniform_hemisphere_pdf(-0.1), 0.0); // below the horizon: never drawn
//! assert_eq!(uniform_sphere_pdf(), 0.25 / std::f32::consts::PI);
//! assert_eq!(uniform_disc_pdf(uniform_disc(u)), 1.0 / std::f32::consts::PI);
//! assert_eq!(uniform_disc_pdf(Vec2::new(0.8, 0.8)), 0.0); // outside the disc
//! ```

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};

// ANCHOR: cosine_hemisphere
/// A direction in the hemisphere around +Z with density cos(theta) / pi, from a
/// uniform point `u` of the unit square (Malley's method: a uniform point on the unit
/// disc, lifted up to the hemisphere).
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let r = u.x.sqrt();
    let phi = TAU * u.y;
    let (s, c) = phi.sin_cos();
    Vec3::new(r * c, r * s, (1.0 - u.x).max(0.0).sqrt())
}

/// The density of [`cosine_hemisphere`] per unit solid angle, at a direction whose
/// cosine with +Z is `cos_theta`: cos(theta) / pi above the horizon, 0 below it.
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    if cos_theta > 0.0 { cos_theta / PI } else { 0.0 }
}
// ANCHOR_END: cosine_hemisphere

// ANCHOR: uniform_hemisphere
/// A direction in the hemisphere around +Z with constant density 1 / (2 pi): the
/// height z = cos(theta) is uniform in [0, 1] (Archimedes' hat-box theorem).
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    let z = u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

/// The density of [`uniform_hemisphere`] per unit solid angle, at a direction whose
/// cosine with +Z is `cos_theta`: 1 / (2 pi) on the hemisphere (z >= 0), 0 below it.
pub fn uniform_hemisphere_pdf(cos_theta: f32) -> f32 {
    if cos_theta >= 0.0 { 1.0 / TAU } else { 0.0 }
}
// ANCHOR_END: uniform_hemisphere

/// A direction on the whole unit sphere with constant density 1 / (4 pi).
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

/// The density of [`uniform_sphere`] per unit solid angle: 1 / (4 pi) in every
/// direction.
pub fn uniform_sphere_pdf() -> f32 {
    1.0 / (2.0 * TAU)
}

/// A point of the unit disc with constant density 1 / pi (polar map: r = sqrt(u)).
pub fn uniform_disc(u: Vec2) -> Vec2 {
    let r = u.x.sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec2::new(r * c, r * s)
}

/// The density of [`uniform_disc`] per unit area at the point `p`: 1 / pi on the
/// unit disc (|p| <= 1), 0 outside it.
pub fn uniform_disc_pdf(p: Vec2) -> f32 {
    if p.length_squared() <= 1.0 {
        1.0 / PI
    } else {
        0.0
    }
}

// ANCHOR: uniform_cone
/// A direction uniform inside the cone around +Z of half-angle theta_max, given as
/// `one_minus_cos` = 1 - cos theta_max (so that a narrow cone does not cancel): with
/// 1 - cos theta = u.x (1 - cos theta_max), the solid angle below theta grows with
/// u.x linearly, so the direction is uniform in solid angle (pbrt-v3 section 13.6.4).
pub fn uniform_cone(one_minus_cos: f32, u: Vec2) -> Vec3 {
    let h = u.x * one_minus_cos;
    let cos = 1.0 - h;
    let sin = (h * (2.0 - h)).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(sin * c, sin * s, cos)
}

/// The density of [`uniform_cone`] for every direction inside the cone (it draws
/// none outside): 1 / (2 pi (1 - cos theta_max)), one over the cone's solid angle.
pub fn uniform_cone_pdf(one_minus_cos: f32) -> f32 {
    1.0 / (TAU * one_minus_cos)
}
// ANCHOR_END: uniform_cone

// ANCHOR: strata
/// The largest float below 1, 1 - 2^-24: where a point of [0, 1) that rounding could
/// carry up to 1 is held.
pub const BELOW_ONE: f32 = 1.0 - f32::EPSILON / 2.0;

/// A grid of `cols` x `rows` cells over the unit square, one sample in each
/// (stratified, or jittered, sampling).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Strata {
    /// Cells across.
    pub cols: u32,
    /// Cells down.
    pub rows: u32,
}

/// The grid of `n` strata, as square as `n` allows: `rows` the largest divisor of n
/// not above sqrt(n), `cols` = n / rows, so a square number gives a square grid
/// (1 x 1 for n = 0).
///
/// ```
/// use render_lessons::sampling::{Strata, strata};
///
/// assert_eq!(strata(16), Strata { cols: 4, rows: 4 });
/// assert_eq!(strata(8), Strata { cols: 4, rows: 2 });
/// assert_eq!(strata(7), Strata { cols: 7, rows: 1 }); // a prime: one row
/// assert!(strata(u32::MAX - 1).cols > 0);
/// ```
pub fn strata(n: u32) -> Strata {
    let mut rows = floor_sqrt(n).max(1);
    while rows > 1 && !n.is_multiple_of(rows) {
        rows -= 1;
    }
    Strata {
        cols: n.max(1) / rows,
        rows,
    }
}

impl Strata {
    /// Whether the grid is square (`n` a square number).
    pub fn is_square(self) -> bool {
        self.cols == self.rows
    }

    /// Sample `i`'s point: the uniform point `u` of the unit square moved into cell
    /// (i mod cols, i div cols), kept below 1 (dividing a number just below a whole
    /// one can round up to it).
    pub fn point(self, i: u32, u: Vec2) -> Vec2 {
        let cell = Vec2::new((i % self.cols) as f32, (i / self.cols) as f32);
        let size = Vec2::new(self.cols as f32, self.rows as f32);
        ((cell + u) / size).min(Vec2::splat(BELOW_ONE))
    }
}

/// floor(sqrt(n)), exactly.
fn floor_sqrt(n: u32) -> u32 {
    let mut r = f64::from(n).sqrt() as u32;
    while u64::from(r) * u64::from(r) > u64::from(n) {
        r -= 1;
    }
    while u64::from(r + 1) * u64::from(r + 1) <= u64::from(n) {
        r += 1;
    }
    r
}
// ANCHOR_END: strata

/// An `n` x `n` grid of points at the centres of the cells of the unit square: evenly
/// spread "random" numbers for tests that must not depend on a generator.
pub fn grid(n: u32) -> impl Iterator<Item = Vec2> {
    let step = 1.0 / n as f32;
    (0..n).flat_map(move |i| {
        (0..n).map(move |j| Vec2::new((i as f32 + 0.5) * step, (j as f32 + 0.5) * step))
    })
}
