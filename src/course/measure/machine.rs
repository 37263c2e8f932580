//! What a benchmark prints about where it ran: the machine, and whether the CPU was
//! quiet while it measured.
//!
//! Quiet means that other processes used little CPU time during the run. Linux
//! counts, in `/proc/stat`, the time every CPU spent busy since boot, and in
//! `/proc/self/stat` the time this process used; the difference over the run is
//! what everything else took. A figure measured while a compiler ran beside it can be
//! half the quiet one, so every benchmark states this next to its numbers.

use std::fs;
use std::time::{Duration, Instant};

/// Other processes may take up to this share of one core before a run counts as
/// noisy.
pub const QUIET_SHARE: f64 = 0.05;

/// The CPU model and the number of cores, e.g. "2 x AMD EPYC 7B13".
pub fn machine() -> String {
    let model = fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!("{cores} x {model}")
}

/// Clock ticks (USER_HZ) per second, as Linux reports CPU time in /proc.
const TICKS_PER_SECOND: f64 = 100.0;

/// Busy ticks of all CPUs since boot: user + nice + system + irq + softirq + steal.
fn busy_ticks() -> Option<u64> {
    let stat = fs::read_to_string("/proc/stat").ok()?;
    let cpu = stat.lines().next()?.strip_prefix("cpu ")?;
    let f: Vec<u64> = cpu
        .split_whitespace()
        .filter_map(|x| x.parse().ok())
        .collect();
    // user nice system idle iowait irq softirq steal
    Some(f.first()? + f.get(1)? + f.get(2)? + f.get(5)? + f.get(6)? + f.get(7)?)
}

/// Ticks this process used (user + system), from /proc/self/stat fields 14 and 15.
fn own_ticks() -> Option<u64> {
    let stat = fs::read_to_string("/proc/self/stat").ok()?;
    // The command name (field 2) may hold spaces; the fields after its ')' are plain.
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    Some(f.get(11)?.parse::<u64>().ok()? + f.get(12)?.parse::<u64>().ok()?)
}

/// A stopwatch on the CPU time other processes use.
#[derive(Clone, Copy, Debug)]
pub struct CpuWatch {
    start: Instant,
    busy: Option<u64>,
    own: Option<u64>,
}

impl CpuWatch {
    /// Starts watching.
    pub fn start() -> CpuWatch {
        CpuWatch {
            start: Instant::now(),
            busy: busy_ticks(),
            own: own_ticks(),
        }
    }

    /// The share of one core that other processes used since [`CpuWatch::start`]
    /// (0.5 = half a core on average), or `None` where /proc cannot tell.
    pub fn others_share(&self) -> Option<f64> {
        let elapsed = self.start.elapsed().max(Duration::from_millis(1));
        let busy = busy_ticks()?.checked_sub(self.busy?)?;
        let own = own_ticks()?.checked_sub(self.own?)?;
        let others = busy.saturating_sub(own) as f64 / TICKS_PER_SECOND;
        Some(others / elapsed.as_secs_f64())
    }

    /// One line for a benchmark's output: the machine, and how much CPU other
    /// processes took during the run, with the verdict quiet or NOISY.
    pub fn report(&self) -> String {
        let verdict = match self.others_share() {
            Some(s) if s <= QUIET_SHARE => {
                format!("quiet: other processes used {:.1}% of a core", 100.0 * s)
            }
            Some(s) => format!(
                "NOISY: other processes used {:.0}% of a core; the absolute figures are low, compare ratios only",
                100.0 * s
            ),
            None => "CPU load unknown (no /proc)".into(),
        };
        format!(
            "machine: {}; {} over {:.0} s",
            machine(),
            verdict,
            self.start.elapsed().as_secs_f64()
        )
    }
}

/// The fastest of `rounds` timings of each of `work`'s entries, taken interleaved
/// (round 1 of every entry, then round 2, ...), so that a change in the machine's
/// load affects them all alike and their ratios stay fair.
pub fn interleaved_min(rounds: u32, work: &mut [&mut dyn FnMut()]) -> Vec<Duration> {
    let mut best = vec![Duration::MAX; work.len()];
    for _ in 0..rounds.max(1) {
        for (f, b) in work.iter_mut().zip(best.iter_mut()) {
            let start = Instant::now();
            f();
            *b = (*b).min(start.elapsed());
        }
    }
    best
}

/// True when this benchmark runs under `cargo bench`, which passes `--bench`; false
/// when `cargo test --benches` runs it once as a test (`--test`) or lists it
/// (`--list`). Benchmarks run their long measurements only then.
pub fn benchmarking() -> bool {
    let args: Vec<String> = std::env::args().skip(1).collect();
    args.iter().any(|a| a == "--bench")
        && !args.iter().any(|a| a == "--test" || a == "--list")
}
