//! Lesson 11: speed against accuracy, measured on the machine that runs it.
//!
//! Every chart of the lesson is measured here and now: how much each robust method
//! of lessons 07-10 costs and how much accuracy it buys, where a naive method fails,
//! and when an acceleration structure starts to pay. Each chart is written as SVG
//! (to look at) and CSV (to plot again), and a summary is printed.
//!
//!     cargo run --release --example 11_speed_vs_accuracy            # about a minute
//!     cargo run --release --example 11_speed_vs_accuracy -- --full  # publication quality
//!     cargo run --release --example 11_speed_vs_accuracy -- --only 11_1_sphere

use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use render_lessons::error::Error;
use render_lessons::lesson::{self, Output};
use render_lessons::measure::{ALL, Quality};

/// The lesson's parameters.
#[derive(Parser, Debug)]
#[command(about = "Lesson 11: speed against accuracy, charted on this machine")]
pub struct Args {
    /// Measure longer, for charts good enough to publish (several minutes).
    #[arg(long)]
    pub full: bool,
    /// Measure only the charts whose name starts with this (e.g. 11_5).
    #[arg(long)]
    pub only: Option<String>,
    #[command(flatten)]
    pub output: Output,
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        let quality = if args.full {
            Quality::Full
        } else {
            Quality::Quick
        };
        let chosen: Vec<_> = ALL
            .iter()
            .filter(|(stem, _)| {
                args.only
                    .as_ref()
                    .is_none_or(|o| stem.starts_with(o.as_str()))
            })
            .collect();
        if chosen.is_empty() {
            return Err(Error::TooFew {
                param: "charts matching --only",
                value: 0,
                min: 1,
            });
        }
        let mut summary = String::new();
        for (stem, measure) in chosen {
            let start = Instant::now();
            let measured = measure(quality)?;
            for path in measured.chart.save(&args.output.out, stem)? {
                lesson::wrote(&path);
            }
            summary.push_str(&format!(
                "{} ({:.1} s)\n",
                measured.chart.title,
                start.elapsed().as_secs_f64()
            ));
            for finding in &measured.findings {
                summary.push_str(&format!("  - {finding}\n"));
            }
        }
        lesson::print(&summary);
        Ok(())
    })
}
