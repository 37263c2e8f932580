//! Checking a rasterized image against the ray caster's: the reference image and
//! its silhouettes from one ray per pixel, and how many pixels agree away from the
//! silhouettes.

use crate::ray::Interval;
use glam::Vec3;
use rayon::prelude::*;

use crate::camera::Camera;
use crate::error::Result;
use crate::framebuffer::Framebuffer;
use crate::lighting;
use crate::render::progress_bar;
use crate::scene::Intersect;

/// Colours more than this apart (linear RGB, in some channel) count as different:
/// about one step of an 8-bit image.
pub const TOLERANCE: f32 = 1.0 / 255.0;

/// The ray caster's image of a scene lit without shadow rays, and which of its
/// pixels lie next to a silhouette.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    /// Colours as [`crate::raycast::lit_unshadowed`] paints them.
    pub image: Framebuffer,
    /// One flag per pixel, row by row: next to a silhouette.
    pub silhouettes: Vec<bool>,
}

// ANCHOR: silhouettes
/// The ray caster's image of `scene` with no shadow rays, and its silhouettes, from
/// one ray per pixel. A pixel lies next to a silhouette where the object its ray
/// sees differs from the one seen at one of its 8 neighbours. There the tessellated
/// outline and the true one may fall on different sides of a pixel centre, so the
/// comparison leaves these pixels out.
pub fn reference(scene: &impl Intersect, camera: &Camera) -> Result<Reference> {
    let (w, h) = (camera.film().width(), camera.film().height());
    let background = scene.objects().len();
    // Each pixel's colour and the number of the object it sees (background: one more).
    let mut pixels = vec![(Vec3::ZERO, background); w as usize * h as usize];
    // Every ray meets every primitive: a big mesh takes minutes, so show the rows.
    let tests = u64::from(w) * u64::from(h) * scene.objects().len() as u64;
    let progress = progress_bar(tests / 64, h);
    pixels
        .par_chunks_mut(w as usize)
        .enumerate()
        .for_each(|(y, row)| {
            let mut rays = camera.row(y as u32);
            for pixel in row.iter_mut() {
                let ray = rays.next_ray();
                *pixel = match scene.closest(&ray, Interval::AHEAD) {
                    Some(found) => (
                        lighting::at_hit(
                            scene.scene(),
                            &found.hit,
                            scene.object(&found),
                            |_| true,
                        ),
                        found.object,
                    ),
                    None => (scene.background(), background),
                };
            }
            progress.inc(1);
        });
    progress.finish_and_clear();
    let id = |x: u32, y: u32| pixels[(y * w + x) as usize].1;
    let around = |c: u32, n: u32| c.saturating_sub(1)..=(c + 1).min(n - 1);
    let silhouettes = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            around(y, h).any(|ny| around(x, w).any(|nx| id(nx, ny) != id(x, y)))
        })
        .collect();
    let colours = pixels.iter().map(|&(colour, _)| colour).collect();
    Ok(Reference {
        image: Framebuffer::from_pixels(w, h, colours)?,
        silhouettes,
    })
}
// ANCHOR_END: silhouettes

/// How two images compare away from silhouettes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Agreement {
    /// Pixels compared (all but the silhouettes).
    pub compared: u32,
    /// Pixels left out as silhouettes.
    pub silhouette: u32,
    /// Compared pixels differing by more than the tolerance.
    pub differing: u32,
    /// The largest difference of a compared pixel, in some channel.
    pub max_difference: f32,
}

impl Agreement {
    /// The share of compared pixels that agree, in percent.
    pub fn percent_agreeing(&self) -> f64 {
        100.0 * (self.compared - self.differing) as f64 / self.compared.max(1) as f64
    }
}

// ANCHOR: agreement
/// Compares `a` and `b` pixel by pixel, skipping the pixels flagged in `skip` (row
/// by row; missing flags count as not skipped): a pixel differs when some channel
/// differs by more than `tolerance`, or when it is missing from one image.
pub fn agreement(
    a: &Framebuffer,
    b: &Framebuffer,
    skip: &[bool],
    tolerance: f32,
) -> Agreement {
    let mut result = Agreement {
        compared: 0,
        silhouette: 0,
        differing: 0,
        max_difference: 0.0,
    };
    for y in 0..a.height() {
        for x in 0..a.width() {
            if skip.get((y * a.width() + x) as usize) == Some(&true) {
                result.silhouette += 1;
                continue;
            }
            let d = match (a.get(x, y), b.get(x, y)) {
                (Some(pa), Some(pb)) => (pa - pb).abs().max_element(),
                _ => f32::INFINITY,
            };
            result.compared += 1;
            result.max_difference = result.max_difference.max(d);
            if d > tolerance {
                result.differing += 1;
            }
        }
    }
    result
}
// ANCHOR_END: agreement

/// |a - b| magnified 10 times, with the pixels flagged in `skip` marked in grey.
pub fn difference(
    a: &Framebuffer,
    b: &Framebuffer,
    skip: &[bool],
) -> Result<Framebuffer> {
    Framebuffer::from_fn(a.width(), a.height(), |x, y| {
        if skip.get((y * a.width() + x) as usize) == Some(&true) {
            return Vec3::splat(0.2);
        }
        let (pa, pb) = (
            a.get(x, y).unwrap_or(Vec3::ZERO),
            b.get(x, y).unwrap_or(Vec3::ZERO),
        );
        ((pa - pb).abs() * 10.0).min(Vec3::ONE)
    })
}
