//! The tables the book quotes from chart 11.1: each method's error at the distances
//! of the book's table and the stable methods' worst error, exact and measured
//! without a clock; and the times, which only the lesson measures.

use super::{Curve, SphereMethod, data};
use crate::course::measure::Quality;
use crate::course::report::{BookNumbers, Quoted};
use crate::error::Result;

/// The value of `points` at `x`, or NaN.
pub(super) fn at(points: &[(f64, f64)], x: f64) -> f64 {
    points.iter().find(|p| p.0 == x).map_or(f64::NAN, |p| p.1)
}

/// The distances D/r of the book's table.
pub const QUOTED_DISTANCES: [f64; 7] = [1e1, 1e2, 1e3, 3e3, 1e4, 1e5, 1e6];

/// The exact numbers the book quotes from chart 1: at each of [`QUOTED_DISTANCES`],
/// every method's mean relative error and the f32 methods' shares of wrong answers
/// (table `accuracy`); the largest error of each stable method anywhere on the chart
/// (values `stable_f32_max`, `stable_f64_max`).
pub fn quoted(curves: &[Curve]) -> BookNumbers {
    let curve = |m: SphereMethod| curves.iter().find(|c| c.method == m);
    let error = |m, x| curve(m).map_or(f64::NAN, |c| at(&c.errors, x));
    let wrong = |m, x| curve(m).map_or(f64::NAN, |c| 100.0 * at(&c.wrong, x));
    let worst = |m| {
        curve(m).map_or(f64::NAN, |c| {
            c.errors.iter().map(|p| p.1).fold(0.0, f64::max)
        })
    };
    let mut table = Quoted::new(
        "accuracy",
        false,
        &[
            "D/r",
            "textbook f32",
            "stable f32",
            "textbook f64",
            "stable f64",
            "% wrong, textbook f32",
            "% wrong, stable f32",
        ],
    );
    for x in QUOTED_DISTANCES {
        let mut cells = vec![format!("{x:.0e}")];
        cells.extend(SphereMethod::ALL.map(|m| format!("{:.2e}", error(m, x))));
        cells.push(format!("{:.2}", wrong(SphereMethod::TextbookF32, x)));
        cells.push(format!("{:.2}", wrong(SphereMethod::StableF32, x)));
        table = table.row(cells);
    }
    BookNumbers::default()
        .table(table)
        .value(
            "stable_f32_max",
            false,
            format!("{:.1e}", worst(SphereMethod::StableF32)),
        )
        .value(
            "stable_f64_max",
            false,
            format!("{:.1e}", worst(SphereMethod::StableF64)),
        )
}

/// The exact part of chart 1's numbers, measured at `quality` (no timing).
pub fn exact_quoted(quality: Quality) -> Result<BookNumbers> {
    Ok(quoted(&data(quality)?))
}

/// The times the book quotes from chart 1 (`ns`, in the order of
/// [`SphereMethod::ALL`]): table `times`, and the row `cost` for the cost table of
/// "Where methods fail".
pub fn quoted_times(ns: [f64; 4]) -> BookNumbers {
    let mut times = Quoted::new(
        "times",
        true,
        &["root finder", "ns per test", "x textbook f32"],
    );
    for (m, t) in SphereMethod::ALL.iter().zip(ns) {
        times = times.row(vec![
            m.name().to_string(),
            format!("{t:.1}"),
            format!("{:.2}", t / ns[0]),
        ]);
    }
    let cost = Quoted::new(
        "cost",
        true,
        &["case", "naive / robust", "ns per test", "robust / naive"],
    )
    .row(vec![
        "S1".into(),
        "textbook / stable roots, f32".into(),
        format!("{:.1} / {:.1}", ns[0], ns[1]),
        format!("{:.2}x", ns[1] / ns[0]),
    ]);
    BookNumbers::default().table(times).table(cost)
}
