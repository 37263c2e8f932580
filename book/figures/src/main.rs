//! The book's production machinery, apart from the lessons: the figures that only
//! the book shows (a recorded path, a convergence strip, a side-by-side panel), each
//! drawn from the core's real code. A student can ignore this crate; `scripts/figures`
//! and CI run it beside the lessons' examples.
//!
//!     cargo run -p book-figures -- --out out

use std::process::ExitCode;

use clap::Parser;
use render_lessons::Result;
use render_lessons::course::lesson::{self, Output};

mod cross_check;
mod lesson09;
mod lesson10;
mod variance;

/// Writes every book-only figure into `--out`.
#[derive(Parser, Debug)]
#[command(about = "Draws the book's own figures (those no lesson draws) into --out")]
struct Args {
    #[command(flatten)]
    output: Output,
}

/// One lesson's book-only figures.
type Figures = fn(&Output) -> Result<()>;

/// Every lesson that has book-only figures, in lesson order.
const LESSONS: &[(&str, Figures)] = &[
    ("lesson 09", lesson09::figures),
    ("lesson 10", lesson10::figures),
    ("lesson 10, variance", variance::figures),
    ("lesson 10, cross-check", cross_check::figures),
];

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        for (name, figures) in LESSONS {
            eprintln!("== {name}");
            figures(&args.output)?;
        }
        Ok(())
    })
}
