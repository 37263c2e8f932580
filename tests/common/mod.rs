//! Helpers shared by the lesson tests.
#![allow(dead_code)]

use glam::Vec3;
use proptest::prelude::*;

/// Random directions, none shorter than 0.05.
pub fn direction() -> impl Strategy<Value = Vec3> {
    (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0)
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
        .prop_filter("long enough", |v| v.length() > 0.05)
}

/// How many RGBA pixels are clearly blue (rays are drawn in blue).
pub fn blue_pixels(rgba: &[u8]) -> usize {
    rgba.chunks(4)
        .filter(|p| p[2] as i32 > p[0] as i32 + 60)
        .count()
}

/// How many RGBA pixels are clearly red or orange (hit points, planes).
pub fn red_pixels(rgba: &[u8]) -> usize {
    rgba.chunks(4)
        .filter(|p| p[0] as i32 > p[2] as i32 + 60)
        .count()
}

/// The crate's random stream (PCG32, `render_lessons::rng::Rng`) with the helpers
/// the tests use, seeded so that every run tests the same cases.
pub struct Rng(render_lessons::rng::Rng);

impl Rng {
    /// The stream for `seed`.
    pub fn seeded(seed: u64) -> Rng {
        Rng(render_lessons::rng::Rng::new(seed, 0x7e57))
    }

    pub fn next_f32(&mut self) -> f32 {
        self.0.next_f32()
    }

    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next_f32()
    }

    pub fn point(&mut self, half: f32) -> Vec3 {
        Vec3::new(
            self.range(-half, half),
            self.range(-half, half),
            self.range(-half, half),
        )
    }
}
