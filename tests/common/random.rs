//! Random cases: the crate's own stream (PCG32, `render_lessons::rng::Rng`) for every
//! case a test draws, seeded so that every run tests the same cases. A property is
//! a loop: [`for_cases`] hands each case its own stream, and a failure names the
//! case, so that `Rng::case(seed, k)` draws it again.

use glam::{Quat, Vec3};
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};

/// The crate's random stream with the helpers the tests use.
pub struct Rng(render_lessons::rng::Rng);

impl Rng {
    /// The stream for `seed`.
    pub fn seeded(seed: u64) -> Rng {
        Rng(render_lessons::rng::Rng::new(seed, 0x7e57))
    }

    /// The stream of case `case` of a property seeded with `seed`: one stream per
    /// case, as one per pixel in a render.
    pub fn case(seed: u64, case: u32) -> Rng {
        Rng(render_lessons::rng::Rng::for_pixel(seed, case, 0x7e57))
    }

    /// Uniform in [0, 1).
    pub fn next_f32(&mut self) -> f32 {
        self.0.next_f32()
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next_f32()
    }

    /// Uniform in the box [lo, hi) (per axis).
    pub fn vec3(&mut self, lo: Vec3, hi: Vec3) -> Vec3 {
        Vec3::new(
            self.range(lo.x, hi.x),
            self.range(lo.y, hi.y),
            self.range(lo.z, hi.z),
        )
    }

    /// Uniform in the cube [-half, half)^3.
    pub fn point(&mut self, half: f32) -> Vec3 {
        self.vec3(Vec3::splat(-half), Vec3::splat(half))
    }

    /// Uniform over the integers lo..hi (hi excluded; hi > lo).
    pub fn below(&mut self, lo: u32, hi: u32) -> u32 {
        lo + ((self.0.next_u32() as u64 * (hi - lo) as u64) >> 32) as u32
    }

    /// A fair coin.
    pub fn coin(&mut self) -> bool {
        self.0.next_u32() & 1 == 1
    }

    /// 64 random bits.
    pub fn bits64(&mut self) -> u64 {
        (self.0.next_u32() as u64) << 32 | self.0.next_u32() as u64
    }

    /// A direction none shorter than 0.05, from the cube [-1, 1)^3 (not normalised).
    pub fn direction(&mut self) -> Vec3 {
        loop {
            let v = self.point(1.0);
            if v.length() > 0.05 {
                return v;
            }
        }
    }

    /// A rotation: a quaternion from the cube [-1, 1)^4, none shorter than 0.1,
    /// normalised.
    pub fn rotation(&mut self) -> Quat {
        loop {
            let q = Quat::from_vec4(self.point(1.0).extend(self.range(-1.0, 1.0)));
            if q.length_squared() > 1e-2 {
                return q.normalize();
            }
        }
    }
}

/// Runs `check` on `cases` random cases of the property seeded with `seed`, each
/// with its own stream (`Rng::case`). A case the property does not apply to returns
/// early. A failing case is reported with its number, then fails the test.
pub fn for_cases(seed: u64, cases: u32, mut check: impl FnMut(&mut Rng)) {
    for case in 0..cases {
        let mut rng = Rng::case(seed, case);
        if let Err(panic) = catch_unwind(AssertUnwindSafe(|| check(&mut rng))) {
            eprintln!(
                "case {case} of {cases} failed (Rng::case({seed}, {case}) draws it)"
            );
            resume_unwind(panic);
        }
    }
}
