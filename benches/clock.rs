//! The core's clock rate, measured, so that a time per ray can be given in cycles
//! and an instruction count in instructions per cycle (`scripts/instructions-per-ray
//! --clock`). The machine's nominal rate (`/proc/cpuinfo`) says nothing of the boost a
//! virtual machine's core runs at, and this machine has no cycle counters to read.
//!
//! The measurement: a chain of integer additions, each one using the result of the
//! one before, retires one addition a cycle on every x86-64 core (the latency of
//! `add` is one cycle; a chain cannot go faster, and the loop's own counter runs
//! beside it on another port). The rate is the chain's length over its time, the
//! fastest of several rounds.

/// Additions in one pass of the loop.
#[cfg(target_arch = "x86_64")]
const CHAIN: u64 = 100;

/// One chain of `passes` x [`CHAIN`] dependent additions.
#[cfg(target_arch = "x86_64")]
fn chain(passes: u64) -> u64 {
    let mut x: u64 = 0;
    for _ in 0..passes {
        // SAFETY: additions to one register; no memory, no stack, no flags that the
        // compiler relies on.
        unsafe {
            std::arch::asm!(".rept {n}", "add {x}, 1", ".endr", n = const CHAIN,
                x = inout(reg) x, options(nomem, nostack));
        }
    }
    x
}

/// The clock rate in cycles per second: the fastest of `rounds` chains of 200
/// million additions each.
#[cfg(target_arch = "x86_64")]
pub fn cycles_per_second(rounds: u32) -> Option<f64> {
    use std::time::{Duration, Instant};
    const PASSES: u64 = 2_000_000;
    let mut best = Duration::MAX;
    for _ in 0..rounds.max(1) {
        let start = Instant::now();
        std::hint::black_box(chain(std::hint::black_box(PASSES)));
        best = best.min(start.elapsed());
    }
    Some((PASSES * CHAIN) as f64 / best.as_secs_f64())
}

/// `None`: the chain is written in x86-64 instructions.
#[cfg(not(target_arch = "x86_64"))]
pub fn cycles_per_second(_rounds: u32) -> Option<f64> {
    None
}

/// One line for a benchmark's output: the clock rate measured before the timed
/// part and after it (three chains each), which shows whether the core slowed down
/// under the sustained load.
pub fn line(before: Option<f64>, after: Option<f64>) -> String {
    match (before, after) {
        (Some(b), Some(a)) => format!(
            "core clock: {:.2} GHz before the one run, {:.2} GHz after (a chain of dependent additions, one a cycle)",
            b / 1e9,
            a / 1e9
        ),
        _ => "core clock: not measured (x86-64 only)".into(),
    }
}
