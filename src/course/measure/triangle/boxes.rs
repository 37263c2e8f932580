//! STABILITY S6, the finding below chart 11.2: rays aimed exactly at a vertex of
//! random triangles, kept when the watertight test hits the triangle. How often does
//! the plain slab test, and how often the conservative one, reject the triangle's
//! own bounding box, which a ray that hits the triangle must enter; and what does
//! the conservative test cost?

use glam::Vec3;

use crate::course::measure::sphere::fastest;
use crate::course::measure::{Quality, ns_per_call};
use crate::error::Result;
use crate::ray::{Interval, Ray};
use crate::rng::Rng;
use crate::shapes::{Aabb, Triangle};

/// STABILITY S6: rays aimed exactly at a vertex of random triangles, kept when the
/// watertight test hits, each with the triangle's f32 bounding box.
pub fn box_cases(quality: Quality) -> Result<Vec<(Aabb, Ray)>> {
    let mut rng = Rng::new(12345, 6);
    let mut p = || {
        10.0 * Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32())
            - Vec3::splat(5.0)
    };
    let mut cases = Vec::new();
    for _ in 0..quality.pick(20_000, 200_000) {
        let Ok(t) = Triangle::new(p(), p(), p()) else {
            continue;
        };
        let o = 20.0 * p();
        let [v0, v1, v2] = t.vertices();
        let Ok(r) = Ray::new(o, v0 - o) else { continue };
        if t.watertight(&r, Interval::AHEAD).is_none() {
            continue;
        }
        cases.push((Aabb::new(v0.min(v1).min(v2), v0.max(v1).max(v2))?, r));
    }
    Ok(cases)
}

/// How many of the S6 rays ([`box_cases`]) each slab test turns away from their
/// own triangle's box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BoxCounts {
    /// The rays, each with its triangle's box.
    pub rays: usize,
    /// The boxes [`Aabb::slab`] rejects.
    pub plain: usize,
    /// The boxes [`Aabb::slab_conservative`] rejects (none, if it is right).
    pub conservative: usize,
}

/// [`BoxCounts`], and what each slab test costs, in nanoseconds per test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxRejects {
    /// How many boxes each test rejects.
    pub counts: BoxCounts,
    /// [`Aabb::slab`]'s time per test.
    pub plain_ns: f64,
    /// [`Aabb::slab_conservative`]'s time per test.
    pub conservative_ns: f64,
}

/// How often the plain and the conservative slab test reject the boxes of `cases`.
pub fn box_counts(cases: &[(Aabb, Ray)]) -> BoxCounts {
    let plain = cases
        .iter()
        .filter(|(b, r)| b.slab(r, Interval::AHEAD).is_none())
        .count();
    let conservative = cases
        .iter()
        .filter(|(b, r)| b.slab_conservative(r, Interval::AHEAD).is_none())
        .count();
    BoxCounts {
        rays: cases.len(),
        plain,
        conservative,
    }
}

/// STABILITY S6: rays aimed exactly at a vertex of random triangles, kept when the
/// watertight test hits; how often the plain and the conservative slab test on the
/// triangle's f32 bounding box reject it, and their times per test.
pub fn box_rejects(quality: Quality) -> Result<BoxRejects> {
    let cases = box_cases(quality)?;
    let counts = box_counts(&cases);
    let n = cases.len().max(1);
    let calls = quality.pick(300_000, 3_000_000);
    let [plain_ns, conservative_ns] = fastest(
        quality.pick(5, 9),
        [
            &mut || {
                ns_per_call(calls, |i| {
                    let (b, r) = &cases[i as usize % n];
                    b.slab(r, Interval::AHEAD)
                })
            },
            &mut || {
                ns_per_call(calls, |i| {
                    let (b, r) = &cases[i as usize % n];
                    b.slab_conservative(r, Interval::AHEAD)
                })
            },
        ],
    );
    Ok(BoxRejects {
        counts,
        plain_ns,
        conservative_ns,
    })
}
