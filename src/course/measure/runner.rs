//! Running lesson 11's charts: measure each chosen chart, write it as SVG, CSV and
//! Markdown (the numbers the book quotes), and sum up what each one found.

use std::time::Instant;

use super::{Measure, Quality};
use crate::course::failure::{Failure, LessonResult};
use crate::course::lesson::{self, Output};
use crate::course::report::Run;
use crate::files::write_atomically;

/// Measures every chart of `charts` (file stem, measurement) whose stem starts with
/// `only` (all of them without it) at `quality`, writing each to `out` as soon as it
/// is measured; stops between charts on Ctrl-C ([`lesson::check_interrupt`]).
/// Returns the summary: each chart's title, its time, and its findings. An error
/// naming `--only` if no stem starts with it.
pub fn run_charts(
    charts: &[(&str, Measure)],
    only: Option<&str>,
    quality: Quality,
    out: &Output,
) -> LessonResult<String> {
    let chosen: Vec<_> = charts
        .iter()
        .filter(|(stem, _)| only.is_none_or(|o| stem.starts_with(o)))
        .collect();
    if chosen.is_empty() {
        return Err(Failure::NoMatch {
            param: "--only",
            value: only.unwrap_or_default().to_string(),
            choices: charts.iter().map(|(stem, _)| stem.to_string()).collect(),
        });
    }
    let mut summary = String::new();
    for (stem, measure) in chosen {
        lesson::check_interrupt()?;
        let start = Instant::now();
        let run = Run::here(quality.name());
        let measured = measure(quality)?;
        for path in measured.chart.save(&out.out, stem)? {
            lesson::wrote(&path);
        }
        let md = out.file(&format!("{stem}.md"));
        write_atomically(&md, measured.quoted.markdown(stem, &run).as_bytes())?;
        lesson::wrote(&md);
        summary.push_str(&format!(
            "{} ({:.1} s)\n",
            measured.chart.title,
            start.elapsed().as_secs_f64()
        ));
        for finding in &measured.findings {
            summary.push_str(&format!("  - {finding}\n"));
        }
    }
    Ok(summary)
}
