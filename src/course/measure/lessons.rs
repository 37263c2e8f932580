//! Chart 8's book-keeping, apart from the lesson that measures it
//! (`examples/11_speed_vs_accuracy.rs`, `lessons`): the timing of a frame, and the
//! chart, findings and quoted numbers made from what it measured.

use std::time::Instant;

use super::Measured;
use crate::course::chart::{Chart, Scale};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::{Error, Problem, Result};

/// The best of `repeats` wall times of `work`, in milliseconds, and its last result.
pub fn best_ms<T>(
    repeats: u32,
    mut work: impl FnMut() -> Result<T>,
) -> Result<(f64, T)> {
    let mut best = f64::INFINITY;
    let mut result = None;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        result = Some(work()?);
        best = best.min(start.elapsed().as_secs_f64() * 1e3);
    }
    let result = result.ok_or(Error::Value {
        param: "repeats",
        problem: Problem::TooFew { value: 0, min: 1 },
    })?;
    Ok((best, result))
}

/// One knob of the rasterizer swept: its values and, for each, (ms per frame, share
/// of pixels differing in percent). `fixed` is the other knob's value meanwhile.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// The value of the knob not swept.
    pub fixed: u32,
    /// Each value of the swept knob and what it measured.
    pub points: Vec<(u32, (f64, f64))>,
}

impl Sweep {
    /// The knob swept over `values` by `at`, the other one at `fixed`.
    pub fn measure(
        fixed: u32,
        values: &[u32],
        mut at: impl FnMut(u32) -> Result<(f64, f64)>,
    ) -> Result<Sweep> {
        let points = values.iter().map(|&v| Ok((v, at(v)?)));
        Ok(Sweep {
            fixed,
            points: points.collect::<Result<_>>()?,
        })
    }

    fn line(&self) -> Vec<(f64, f64)> {
        self.points.iter().map(|&(_, p)| p).collect()
    }

    fn range(&self) -> (u32, u32) {
        let first = self.points.first().map_or(0, |p| p.0);
        (first, self.points.last().map_or(first, |p| p.0))
    }

    fn at(&self, value: u32) -> (f64, f64) {
        let found = self.points.iter().find(|p| p.0 == value);
        found.map_or((f64::NAN, f64::NAN), |p| p.1)
    }
}

/// Chart 8 from its measurements: the ray caster with shadow rays (`traced_ms`, the
/// reference), the tessellation swept with a fixed map (`segments`), the map swept
/// with a fixed tessellation (`maps`), and no shadows at all; the findings a student
/// reads off it, and the numbers the book quotes.
pub fn lessons_measured(
    (width, height): (u32, u32),
    traced_ms: f64,
    segments: &Sweep,
    maps: &Sweep,
    no_shadows: (f64, f64),
) -> Measured {
    let (few, many) = segments.range();
    let (small, large) = maps.range();
    let (map, n) = (segments.fixed, maps.fixed);
    let chart = Chart::new(
        &format!(
            "Lessons 08 and 09 on lesson 08's scene, {width} x {height}, every core"
        ),
        ("time per frame (ms)", Scale::Log),
        (
            "pixels differing from the ray-traced image (%)",
            Scale::Linear,
        ),
    )
    .with(
        &format!(
            "rasterized + {map}^2 shadow map, spheres of {few} to {many} segments"
        ),
        segments.line(),
    )
    .with(
        &format!("rasterized, {n} segments, shadow map of {small}^2 to {large}^2"),
        maps.line(),
    )
    .with("rasterized, no shadows", vec![no_shadows])
    .with(
        "ray cast with shadow rays (the reference)",
        vec![(traced_ms, 0.0)],
    );
    let both = segments.at(n);
    let (first, last) = (maps.at(small), maps.at(large));
    let findings = vec![
        format!(
            "ray cast with shadow rays: {traced_ms:.0} ms; rasterized with {n} segments and a \
             {map}^2 map: {:.0} ms, {:.2}% of pixels differ",
            both.0, both.1
        ),
        format!(
            "no shadows: {:.2}% differ; a {small}^2 map: {:.2}%, a {large}^2 map: {:.2}% ({:.0} ms)",
            no_shadows.1, first.1, last.1, last.0
        ),
        "lesson 10 is not on this chart: it solves the whole rendering equation (indirect light, \
         area lights), so against this direct-lighting image its difference would be the light \
         the others leave out; chart 6 is its time against error"
            .to_string(),
    ];
    let quoted = lessons_quoted(traced_ms, segments, maps, no_shadows);
    Measured {
        chart,
        findings,
        quoted,
    }
}

/// The numbers the book quotes from chart 8: table `errors` (exact: the share of
/// pixels that differ from the ray-traced image, for each setting) and table `times`
/// (the time per frame of each).
fn lessons_quoted(
    traced_ms: f64,
    segments: &Sweep,
    maps: &Sweep,
    no_shadows: (f64, f64),
) -> BookNumbers {
    let mut settings =
        vec![("ray cast with shadow rays".to_string(), (traced_ms, 0.0))];
    settings.push(("rasterized, no shadows".into(), no_shadows));
    let map = segments.fixed;
    for &(n, p) in &segments.points {
        settings.push((format!("{n} segments, {map}^2 map"), p));
    }
    // The map of the segments' sweep is a row of both sweeps: listed once.
    for &(size, p) in &maps.points {
        if size != map {
            settings.push((format!("{} segments, {size}^2 map", maps.fixed), p));
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
