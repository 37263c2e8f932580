//! Lesson 11's measurements: speed against accuracy, on the machine that runs them.
//!
//! Each file measures one chart of the lesson and returns it with the findings a
//! student should read off it. Times are measured here, in the lesson, never in a
//! test: the tests check only what physics and numerics say must hold.
//!
//! Each chart also returns the numbers the book quotes ([`BookNumbers`]): the lesson
//! writes them as `11_N_name.md` next to the chart, and the chapters include them
//! from there, so a number is measured in one place and printed from one file. The
//! exact parts (errors, counts, shares) come from the `*_quoted` functions, which
//! measure no time, so a test can regenerate them and compare.

pub mod lessons;
pub mod machine;
pub mod monte_carlo;
pub mod offsets;
pub mod plain;
pub mod precision;
pub mod renderers;
pub mod runner;
pub mod scaling;
pub mod sphere;
pub mod tax;
pub mod triangle;
pub mod variance;

use std::time::Instant;

use crate::course::chart::Chart;
use crate::course::report::BookNumbers;
use crate::error::Result;

/// How long to measure: a quick look (about a minute for the whole lesson) or
/// numbers good enough to publish.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quality {
    /// Few samples: the shapes of the curves, noisy times.
    Quick,
    /// Many samples: the charts the book shows.
    Full,
}

impl Quality {
    /// `Full` when `full` (the lesson's `--full`), `Quick` otherwise.
    pub fn full_if(full: bool) -> Quality {
        if full { Quality::Full } else { Quality::Quick }
    }

    /// `quick` or `full`, by quality.
    pub fn pick<T>(self, quick: T, full: T) -> T {
        match self {
            Quality::Quick => quick,
            Quality::Full => full,
        }
    }

    /// `"quick"` or `"full"`, as a fragment records it.
    pub fn name(self) -> &'static str {
        self.pick("quick", "full")
    }
}

/// One chart and what it shows.
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    /// The chart.
    pub chart: Chart,
    /// One line per finding, e.g. "textbook roots: 47% wrong at D/r = 1e4".
    pub findings: Vec<String>,
    /// The numbers the book quotes from this chart, exact and timed.
    pub quoted: BookNumbers,
}

/// A measurement of one chart.
pub type Measure = fn(Quality) -> Result<Measured>;

/// Every chart of the lesson measured here: its file stem and how to measure it, in
/// the order of the chapter (chart 8 is measured in the lesson's example itself).
pub const ALL: &[(&str, Measure)] = &[
    ("11_1_sphere", sphere::measure),
    ("11_2_triangle", triangle::measure),
    ("11_3_offsets", offsets::measure),
    ("11_4_precision", precision::measure),
    ("11_5_monte_carlo", monte_carlo::measure),
    ("11_6_renderers", renderers::measure),
    ("11_7_scaling", scaling::measure),
    ("11_9_tax", tax::measure),
];

/// Nanoseconds per call of `work`, over `calls` calls (after one warm-up round of
/// the same size). The result of every call is kept from the optimiser.
pub fn ns_per_call<T>(calls: u32, mut work: impl FnMut(u32) -> T) -> f64 {
    for i in 0..calls {
        std::hint::black_box(work(i));
    }
    let start = Instant::now();
    for i in 0..calls {
        std::hint::black_box(work(i));
    }
    start.elapsed().as_secs_f64() * 1e9 / f64::from(calls.max(1))
}
