//! Chart 8's book-keeping, apart from the lesson that measures it
//! (`examples/11_speed_vs_accuracy.rs`, `lessons`): the timing of a frame, and the
//! numbers the book quotes from the chart.

use crate::course::report::{BookNumbers, Quoted};
use crate::error::{Error, Result};
use std::time::Instant;

/// The best of `repeats` wall times of `work`, in milliseconds, and its last result.
pub fn best_ms<T>(repeats: u32, mut work: impl FnMut() -> Result<T>) -> Result<(f64, T)> {
    let mut best = f64::INFINITY;
    let mut result = None;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        result = Some(work()?);
        best = best.min(start.elapsed().as_secs_f64() * 1e3);
    }
    let result = result.ok_or(Error::TooFew {
        param: "repeats",
        value: 0,
        min: 1,
    })?;
    Ok((best, result))
}

/// The numbers the book quotes from chart 8: table `errors` (exact: the share of
/// pixels that differ from the ray-traced image, for each setting) and table `times`
/// (the time per frame of each).
pub fn lessons_quoted(
    traced_ms: f64,
    segments: &[(f64, f64)],
    maps: &[(f64, f64)],
    no_shadows: (f64, f64),
) -> BookNumbers {
    let mut settings = vec![("ray cast with shadow rays".to_string(), (traced_ms, 0.0))];
    settings.push(("rasterized, no shadows".into(), no_shadows));
    for (n, &p) in [8, 16, 32, 64, 128].iter().zip(segments) {
        settings.push((format!("{n} segments, 1024^2 map"), p));
    }
    // The 1024^2 map of 64 segments is a row of both sweeps: listed once.
    for (size, &p) in [128, 256, 512, 1024, 2048, 4096].iter().zip(maps) {
        if *size != 1024 {
            settings.push((format!("64 segments, {size}^2 map"), p));
        }
    }
    let mut errors = Quoted::new("errors", false, &["setting", "pixels differing (%)"]);
    let mut times = Quoted::new("times", true, &["setting", "ms per frame"]);
    // Both side by side, for the chapter (timed: a test compares `errors`).
    let mut summary = Quoted::new(
        "summary",
        true,
        &["setting", "pixels differing (%)", "ms per frame"],
    );
    for (name, (ms, differ)) in settings {
        errors = errors.row(vec![name.clone(), format!("{differ:.2}")]);
        times = times.row(vec![name.clone(), format!("{ms:.0}")]);
        summary = summary.row(vec![name, format!("{differ:.2}"), format!("{ms:.0}")]);
    }
    BookNumbers::default()
        .table(errors)
        .table(times)
        .table(summary)
}
