//! Printing numbers so that they read the same on every machine: fixed precision,
//! and -0 written as 0. Lessons print their tables with these, and the tests
//! snapshot exactly what the lessons print.

use std::fmt;

use glam::Vec3;

/// `x` with `decimals` digits after the point; a value that rounds to zero is
/// written without a sign.
pub fn num(x: f64, decimals: usize) -> String {
    let s = format!("{x:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// A vector as `(x, y, z)` with `decimals` digits each.
pub fn vec3(v: Vec3, decimals: usize) -> String {
    let [x, y, z] = v.to_array().map(|c| num(c as f64, decimals));
    format!("({x}, {y}, {z})")
}

/// Numbers as `a, b, c`, each with `decimals` digits (see [`num`]).
pub fn nums(values: &[f32], decimals: usize) -> String {
    let cells: Vec<String> = values.iter().map(|&x| num(x as f64, decimals)).collect();
    cells.join(", ")
}

/// A small text table: a header row and rows of cells, columns padded to align.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Table {
    title: String,
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Table {
    /// An empty table with a title line and column names.
    pub fn new(title: &str, header: &[&str]) -> Table {
        Table {
            title: title.to_string(),
            header: header.iter().map(|h| h.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Adds one row.
    pub fn row(&mut self, cells: Vec<String>) {
        self.rows.push(cells);
    }
}

impl fmt::Display for Table {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let columns = self.header.len();
        let mut widths: Vec<usize> = self.header.iter().map(|h| h.chars().count()).collect();
        for row in &self.rows {
            for (i, cell) in row.iter().enumerate().take(columns) {
                widths[i] = widths[i].max(cell.chars().count());
            }
        }
        let line = |f: &mut fmt::Formatter<'_>, cells: &[String]| {
            let padded: Vec<String> = cells
                .iter()
                .zip(&widths)
                .map(|(c, w)| format!("{c:<w$}"))
                .collect();
            writeln!(f, "{}", padded.join("  ").trim_end())
        };
        writeln!(f, "{}", self.title)?;
        line(f, &self.header)?;
        let rule: Vec<String> = widths.iter().map(|w| "-".repeat(*w)).collect();
        line(f, &rule)?;
        for row in &self.rows {
            line(f, row)?;
        }
        Ok(())
    }
}

/// Wall-clock times of a lesson's steps, for the terminal only: they differ from run
/// to run and machine to machine, so they never reach a snapshot or a test.
#[derive(Clone, Debug, Default)]
pub struct Timings(pub Vec<(&'static str, f64)>);

impl Timings {
    /// Runs `work`, noting how long it took as `what`.
    pub fn time<T>(&mut self, what: &'static str, work: impl FnOnce() -> T) -> T {
        let start = std::time::Instant::now();
        let result = work();
        self.0.push((what, start.elapsed().as_secs_f64()));
        result
    }

    /// The times as a table, in seconds.
    pub fn table(&self) -> Table {
        let mut table = Table::new("Time on this machine", &["step", "seconds"]);
        for (what, seconds) in &self.0 {
            table.row(vec![what.to_string(), num(*seconds, 3)]);
        }
        table
    }
}
