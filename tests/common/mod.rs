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

/// A small deterministic generator (xorshift64*), so every run tests the same rays.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_f32(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (x >> 40) as f32 / (1u64 << 24) as f32
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
