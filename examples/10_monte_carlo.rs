//! Lesson 10, step 1: Monte Carlo integration on its own, before any light.
//!
//! pi is the integral of f(x) = 4 sqrt(1 - x^2) over [0, 1] (a quarter disc, times 4).
//! The estimate is the mean of f at N uniform random points, for N = 1, 2, 4, ..., 2^16.
//! One run's error jumps about; the RMSE over many independent runs falls as
//! sigma / sqrt(N), sigma = sqrt(32/3 - pi^2) = 0.8928 being the spread of one sample.
//!
//!     cargo run --release --example 10_monte_carlo
//!     cargo run --release --example 10_monte_carlo -- --runs 256 --max-power 20

use std::f64::consts::PI;
use std::process::ExitCode;

use clap::Parser;
use render_lessons::Result;
use render_lessons::course::chart::{Chart, Scale, log_log_slope};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::report::{Table, num};
use render_lessons::error::Error;
use render_lessons::pathtrace::Rng;

/// The lesson's parameters; the defaults reproduce the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 10, step 1: Monte Carlo integration of pi, error against N")]
pub struct Args {
    /// N goes 1, 2, 4, ... up to 2^max-power samples (at most 24).
    #[arg(long, default_value_t = 16)]
    pub max_power: u32,
    /// Independent runs at each N, for the RMSE (1 to 4096).
    #[arg(long, default_value_t = 64)]
    pub runs: u32,
    /// Seed of the random streams (one per run and N).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    #[command(flatten)]
    pub output: Output,
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

/// One line of the table: N, the first run's estimate and error, the RMSE of all runs.
pub struct Row {
    pub n: u64,
    pub estimate: f64,
    pub error: f64,
    pub rmse: f64,
}

// ANCHOR: study
/// For N = 2^0 .. 2^max_power: `runs` estimates, each from its own stream
/// (seed, run, power), so every number is the same on every machine.
pub fn study(args: &Args) -> Result<Vec<Row>> {
    if args.max_power > 24 {
        let reason = "must be at most 24 (N = 2^24 samples)";
        return Err(Error::Invalid {
            param: "max power",
            reason,
        });
    }
    if !(1..=4096).contains(&args.runs) {
        let reason = "must be from 1 to 4096";
        return Err(Error::Invalid {
            param: "runs",
            reason,
        });
    }
    let rows = (0..=args.max_power).map(|k| {
        let n = 1u64 << k;
        let runs: Vec<f64> = (0..args.runs)
            .map(|run| estimate(n, &mut Rng::for_pixel(args.seed, run, k)))
            .collect();
        let mse = runs.iter().map(|e| (e - PI).powi(2)).sum::<f64>() / runs.len() as f64;
        let error = (runs[0] - PI).abs();
        Row {
            n,
            estimate: runs[0],
            error,
            rmse: mse.sqrt(),
        }
    });
    Ok(rows.collect())
}
// ANCHOR_END: study

/// The table, and the slope of log RMSE against log N (the law says -1/2).
pub fn numbers(args: &Args, rows: &[Row]) -> String {
    let title = format!(
        "Monte Carlo estimates of pi, sigma of one sample = {}",
        num(sigma(), 4)
    );
    let rmse = format!("RMSE ({} runs)", args.runs);
    let mut table = Table::new(&title, &["N", "estimate", "error", &rmse, "RMSE x sqrt(N)"]);
    for r in rows {
        let scaled = r.rmse * (r.n as f64).sqrt();
        let cells = [r.estimate, r.error, r.rmse].map(|x| num(x, 5));
        table.row([vec![r.n.to_string()], cells.to_vec(), vec![num(scaled, 4)]].concat());
    }
    let points: Vec<(f64, f64)> = rows.iter().map(|r| (r.n as f64, r.rmse)).collect();
    let slope = log_log_slope(&points).map_or("-".into(), |s| num(s, 3));
    format!("{table}\nslope of log RMSE against log N: {slope} (the law: -0.5)\n")
}

// ANCHOR: chart
/// The log-log chart: one run's error, the RMSE of all runs, and sigma / sqrt(N).
pub fn chart(args: &Args, rows: &[Row]) -> Chart {
    let line = |y: fn(&Row) -> f64| rows.iter().map(|r| (r.n as f64, y(r))).collect();
    Chart::new(
        "Monte Carlo estimate of pi: the error falls as 1/sqrt(N)",
        ("N (samples)", Scale::Log),
        ("error", Scale::Log),
    )
    .with("|error| of one run", line(|r| r.error))
    .with(&format!("RMSE of {} runs", args.runs), line(|r| r.rmse))
    .with("sigma / sqrt(N)", line(|r| sigma() / (r.n as f64).sqrt()))
}
// ANCHOR_END: chart

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let rows = study(&args)?;
        lesson::print(&numbers(&args, &rows));
        for path in chart(&args, &rows).save(&args.output.out, "10_monte_carlo")? {
            lesson::wrote(&path);
        }
        Ok(())
    })
}
