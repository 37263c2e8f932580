//! A small deterministic random number generator: PCG32 (O'Neill, "PCG: A Family of
//! Simple Fast Space-Efficient Statistically Good Algorithms for Random Number
//! Generation", 2014), the `pcg32_random_r` variant with 64 bits of state and a
//! per-stream increment.
//!
//! Each pixel owns one stream, chosen by hashing (seed, x, y) with SplitMix64
//! (Steele, Lea and Flood, "Fast Splittable Pseudorandom Number Generators", 2014), so
//! a pixel's samples never depend on which thread draws them or in which order the
//! pixels are visited.

/// SplitMix64's output function: a bijective 64-bit mixer.
fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

// ANCHOR: rng
/// One PCG32 stream.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rng {
    state: u64,
    increment: u64,
}

impl Rng {
    const MULTIPLIER: u64 = 6_364_136_223_846_793_005;

    /// The stream with initial state `init_state` and stream selector `stream`
    /// (PCG's `pcg32_srandom_r`).
    pub fn new(init_state: u64, stream: u64) -> Rng {
        let mut rng = Rng {
            state: 0,
            increment: (stream << 1) | 1,
        };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(init_state);
        rng.next_u32();
        rng
    }

    /// The stream of pixel (`x`, `y`) for the render seeded with `seed`: (seed, x, y)
    /// hashed twice, once for the state and once for the stream selector.
    pub fn for_pixel(seed: u64, x: u32, y: u32) -> Rng {
        let key = splitmix64(seed) ^ ((u64::from(x) << 32) | u64::from(y));
        let hashed = splitmix64(key);
        Rng::new(hashed, splitmix64(hashed ^ 0x5851_f42d_4c95_7f2d))
    }

    /// The next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old
            .wrapping_mul(Self::MULTIPLIER)
            .wrapping_add(self.increment);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// A uniform number in [0, 1): the top 24 bits times 2^-24, so every value is
    /// an exact f32 and 1.0 can never come out (rounding a 32-bit integer to f32
    /// could give exactly 1.0).
    pub fn next_f32(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
    }

    /// Two uniform numbers in [0, 1), for 2D sampling.
    pub fn next_vec2(&mut self) -> glam::Vec2 {
        let u = self.next_f32();
        glam::Vec2::new(u, self.next_f32())
    }
}
// ANCHOR_END: rng

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rng_streams_differ_between_pixels_and_stay_in_0_1() {
        let mut a = Rng::for_pixel(1, 0, 0);
        let mut b = Rng::for_pixel(1, 1, 0);
        let mut c = Rng::for_pixel(1, 0, 1);
        let xa: Vec<u32> = (0..8).map(|_| a.next_u32()).collect();
        let xb: Vec<u32> = (0..8).map(|_| b.next_u32()).collect();
        let xc: Vec<u32> = (0..8).map(|_| c.next_u32()).collect();
        assert_ne!(xa, xb);
        assert_ne!(xa, xc);
        let mut r = Rng::for_pixel(3, 4, 5);
        let (lo, hi) = (0..100_000)
            .map(|_| r.next_f32())
            .fold((1.0f32, 0.0f32), |(lo, hi), x| (lo.min(x), hi.max(x)));
        assert!(lo >= 0.0 && hi < 1.0 && lo < 1e-3 && hi > 0.999);
    }
}
