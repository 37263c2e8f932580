//! Russian roulette (Arvo and Kirk, "Particle Transport and Image Synthesis", 1990):
//! ending long paths at random without bias.

use glam::Vec3;

use crate::pathtrace::settings::Settings;
use crate::rng::Rng;

/// Russian roulette starts after this many bounces.
pub const RR_START: u32 = 3;

/// The largest survival probability of Russian roulette: a white furnace (albedo 1)
/// would otherwise never end a path.
pub const RR_MAX_SURVIVAL: f32 = 0.95;

// ANCHOR: roulette
/// Russian roulette: from bounce [`RR_START`] on, the path survives with probability
/// q = min(max channel of beta, [`RR_MAX_SURVIVAL`]) and beta is divided by q, so the
/// expected value is unchanged (Arvo and Kirk 1990). `false` when the path ends, also
/// when beta has become zero.
pub(super) fn survives_roulette(
    beta: &mut Vec3,
    bounce: u32,
    rng: &mut Rng,
    s: &Settings,
) -> bool {
    if beta.max_element() <= 0.0 {
        return false;
    }
    if !s.russian_roulette || bounce < RR_START {
        return true;
    }
    let q = beta.max_element().min(RR_MAX_SURVIVAL);
    if rng.next_f32() >= q {
        return false;
    }
    *beta /= q;
    true
}
// ANCHOR_END: roulette
