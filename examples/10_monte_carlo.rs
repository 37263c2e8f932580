//! Lesson 10, step 1: Monte Carlo integration on its own, before any light.
//!
//! pi is the integral of f(x) = 4 sqrt(1 - x^2) over [0, 1] (a quarter disc, times 4).
//! The estimate is the mean of f at N uniform random points, for N = 1, 2, 4, ...,
//! 2^16. One run's error jumps about; the RMSE over many independent runs falls as
//! sigma / sqrt(N), sigma = sqrt(32/3 - pi^2) = 0.8928 being the spread of one sample.
//!
//!     cargo run --release --example 10_monte_carlo
//!     cargo run --release --example 10_monte_carlo -- --runs 256 --max-power 20

use std::f64::consts::PI;
use std::process::ExitCode;

use clap::Parser;
use render_lessons::course::chart::{Chart, Scale, log_log_slope};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::report::{Table, num};
use render_lessons::rng::Rng;

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let rows = study(args.max_power, args.runs, args.seed);
        lesson::print(&numbers(args.runs, &rows));
        for path in chart(args.runs, &rows).save(&args.output.out, "10_monte_carlo")? {
            lesson::wrote(&path);
        }
        Ok(())
    })
}

// ANCHOR: integrand
/// The integrand: a quarter of the unit disc, times 4. Its integral over [0, 1] is pi.
pub fn f(x: f64) -> f64 {
    4.0 * (1.0 - x * x).max(0.0).sqrt()
}

/// The standard deviation of one sample f(U), U uniform in [0, 1):
/// E[f^2] = 16 (1 - 1/3) = 32/3, so sigma^2 = 32/3 - pi^2.
pub fn sigma() -> f64 {
    (32.0 / 3.0 - PI * PI).sqrt()
}
// ANCHOR_END: integrand

// ANCHOR: estimate
/// The Monte Carlo estimate of the integral: the mean of f at `n` uniform points
/// (the density p = 1 on [0, 1], so f / p is f).
pub fn estimate(n: u64, rng: &mut Rng) -> f64 {
    let sum: f64 = (0..n).map(|_| f(f64::from(rng.next_f32()))).sum();
    sum / n as f64
}
// ANCHOR_END: estimate

// ANCHOR: study
/// The lesson's loop: for N = 2^0 .. 2^max_power, `runs` estimates (at least one),
/// each from its own stream (seed, run, power), so every number is the same on every
/// machine.
pub fn study(max_power: u32, runs: u32, seed: u64) -> Vec<Row> {
    let rows = (0..=max_power).map(|k| {
        let n = 1u64 << k;
        let estimates: Vec<f64> = (0..runs.max(1))
            .map(|run| estimate(n, &mut Rng::for_pixel(seed, run, k)))
            .collect();
        let squared: f64 = estimates.iter().map(|e| (e - PI).powi(2)).sum();
        let mse = squared / estimates.len() as f64;
        Row {
            n,
            estimate: estimates[0],
            error: (estimates[0] - PI).abs(),
            rmse: mse.sqrt(),
        }
    });
    rows.collect()
}
// ANCHOR_END: study

/// One line of the table: N, the first run's estimate and error, the RMSE of all runs.
pub struct Row {
    pub n: u64,
    pub estimate: f64,
    pub error: f64,
    pub rmse: f64,
}

/// The table of `rows` (each RMSE over `runs` runs), and the slope of log RMSE
/// against log N (the law says -1/2).
pub fn numbers(runs: u32, rows: &[Row]) -> String {
    let title = format!(
        "Monte Carlo estimates of pi, sigma of one sample = {}",
        num(sigma(), 4)
    );
    let rmse = format!("RMSE ({runs} runs)");
    let mut table =
        Table::new(&title, &["N", "estimate", "error", &rmse, "RMSE x sqrt(N)"]);
    for r in rows {
        let scaled = r.rmse * (r.n as f64).sqrt();
        let cells = [r.estimate, r.error, r.rmse].map(|x| num(x, 5));
        table.row(
            [vec![r.n.to_string()], cells.to_vec(), vec![num(scaled, 4)]].concat(),
        );
    }
    let points: Vec<(f64, f64)> = rows.iter().map(|r| (r.n as f64, r.rmse)).collect();
    let slope = log_log_slope(&points).map_or("-".into(), |s| num(s, 3));
    format!("{table}\nslope of log RMSE against log N: {slope} (the law: -0.5)\n")
}

// ANCHOR: chart
/// The log-log chart: one run's error, the RMSE of all `runs` runs, and sigma /
/// sqrt(N).
pub fn chart(runs: u32, rows: &[Row]) -> Chart {
    let line = |y: fn(&Row) -> f64| rows.iter().map(|r| (r.n as f64, y(r))).collect();
    Chart::new(
        "Monte Carlo estimate of pi: the error falls as 1/sqrt(N)",
        ("N (samples)", Scale::Log),
        ("error", Scale::Log),
    )
    .with("|error| of one run", line(|r| r.error))
    .with(&format!("RMSE of {runs} runs"), line(|r| r.rmse))
    .with("sigma / sqrt(N)", line(|r| sigma() / (r.n as f64).sqrt()))
}
// ANCHOR_END: chart

/// The lesson's parameters; the defaults reproduce the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 10, step 1: Monte Carlo integration of pi, error against N")]
pub struct Args {
    /// N goes 1, 2, 4, ... up to 2^max-power samples (at most 24).
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(0..=24))]
    pub max_power: u32,
    /// Independent runs at each N, for the RMSE (1 to 4096).
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub runs: u32,
    /// Seed of the random streams (one per run and N).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    #[command(flatten)]
    pub output: Output,
}
