//! Random cases: the crate's own stream (PCG32, `render_lessons::rng::Rng`) for every
//! case a test draws itself, seeded so that every run tests the same cases; and the
//! strategies of the proptest properties.

use glam::Vec3;
use proptest::prelude::*;

/// The crate's random stream with the helpers the tests use.
pub struct Rng(render_lessons::rng::Rng);

impl Rng {
    /// The stream for `seed`.
    pub fn seeded(seed: u64) -> Rng {
        Rng(render_lessons::rng::Rng::new(seed, 0x7e57))
    }

    /// Uniform in [0, 1).
    pub fn next_f32(&mut self) -> f32 {
        self.0.next_f32()
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next_f32()
    }

    /// Uniform in the cube [-half, half)^3.
    pub fn point(&mut self, half: f32) -> Vec3 {
        Vec3::new(
            self.range(-half, half),
            self.range(-half, half),
            self.range(-half, half),
        )
    }
}

/// Random directions, none shorter than 0.05.
pub fn direction() -> impl Strategy<Value = Vec3> {
    (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0)
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
        .prop_filter("long enough", |v| v.length() > 0.05)
}
