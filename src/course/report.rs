//! Printing numbers so that they read the same on every machine: fixed precision,
//! and -0 written as 0. Lessons print their tables with these, and the tests
//! snapshot exactly what the lessons print.

use std::fmt;
use std::sync::OnceLock;

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
        let mut widths: Vec<usize> =
            self.header.iter().map(|h| h.chars().count()).collect();
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

/// The numbers of one lesson-11 chart that the book quotes, written as a Markdown
/// file next to the chart (`chapters/figures/11_N_name.md`) for the chapters to
/// include, so that no chapter types a measured number by hand.
///
/// Every table and value sits between mdBook anchors (`<!-- ANCHOR: name -->`), so a
/// chapter includes exactly the part it quotes:
/// `{{#include figures/11_1_sphere.md:times}}` for a whole table, `:times_rows` for its rows alone
/// (to add them to a table of the chapter), a value's anchor for one number inside a
/// sentence. A table or value is either *exact* (it depends only on the arithmetic:
/// errors, counts, shares; a test regenerates it and compares) or *timed* (it changes
/// with the machine and its load: every timed table ends with the line that says where
/// and when it was measured).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BookNumbers {
    /// The tables, in the file's order.
    pub tables: Vec<Quoted>,
    /// Single numbers for sentences, in the file's order.
    pub values: Vec<Value>,
}

/// One table of a [`BookNumbers`].
#[derive(Clone, Debug, PartialEq)]
pub struct Quoted {
    /// The anchor it is included by.
    pub anchor: String,
    /// Its numbers are times (they change from machine to machine).
    pub timed: bool,
    /// Column names (with units).
    pub header: Vec<String>,
    /// Rows of cells.
    pub rows: Vec<Vec<String>>,
}

/// One number of a [`BookNumbers`], for a sentence.
#[derive(Clone, Debug, PartialEq)]
pub struct Value {
    /// The anchor it is included by.
    pub anchor: String,
    /// It is a time, or computed from times.
    pub timed: bool,
    /// The number as printed.
    pub text: String,
}

impl Quoted {
    /// An empty table: `timed` if its numbers are times.
    pub fn new(anchor: &str, timed: bool, header: &[&str]) -> Quoted {
        Quoted {
            anchor: anchor.to_string(),
            timed,
            header: header.iter().map(|h| h.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// The table with one more row.
    pub fn row(mut self, cells: Vec<String>) -> Quoted {
        self.rows.push(cells);
        self
    }

    /// The cell in the row whose first cell is `key`, column `column`.
    pub fn cell(&self, key: &str, column: &str) -> Option<&str> {
        let c = self.header.iter().position(|h| h == column)?;
        let row = self
            .rows
            .iter()
            .find(|r| r.first().is_some_and(|k| k == key))?;
        row.get(c).map(String::as_str)
    }
}

/// Where and when the times of a [`BookNumbers`] were measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// `"full"` (`--full`), `"quick"`, or the command that made the run (a bench's,
    /// in backticks).
    pub quality: &'static str,
    /// The machine, e.g. "2 cores of AMD EPYC, load average 1.5".
    pub machine: String,
    /// The day and minute the run started, `YYYY-MM-DD hh:mm UTC`.
    pub date: String,
}

impl Run {
    /// This machine, as it was when this program first asked: every table of one
    /// program names the same run, its load average at the start and the start's
    /// minute, so tables from different runs can be told apart.
    pub fn here(quality: &'static str) -> Run {
        static START: OnceLock<(String, String)> = OnceLock::new();
        let (machine, date) = START.get_or_init(|| {
            let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
            let cpu = std::fs::read_to_string("/proc/cpuinfo")
                .ok()
                .and_then(|text| {
                    text.lines()
                        .find(|l| l.starts_with("model name"))
                        .and_then(|l| l.split_once(':'))
                        .map(|(_, name)| {
                            name.split_whitespace().collect::<Vec<_>>().join(" ")
                        })
                })
                .unwrap_or_else(|| "an unnamed CPU".to_string());
            let load = std::fs::read_to_string("/proc/loadavg")
                .ok()
                .and_then(|text| text.split_whitespace().next().map(str::to_string))
                .map_or(String::new(), |l| {
                    format!(", load average {l} at its start")
                });
            let seconds = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs());
            let minute = (seconds % 86_400) / 60;
            let date = format!(
                "{} {:02}:{:02} UTC",
                civil_date((seconds / 86_400) as i64),
                minute / 60,
                minute % 60
            );
            (format!("{cores} cores of {cpu}{load}"), date)
        });
        Run {
            quality,
            machine: machine.clone(),
            date: date.clone(),
        }
    }

    /// The run in a few words, for a sentence: "`--full` run on 2 cores of ...,
    /// 2026-11-23".
    pub fn short(&self) -> String {
        let how = match self.quality {
            "full" => "`--full`",
            "quick" => "`quick`",
            command => command,
        };
        format!("{how} run on {}, {}", self.machine, self.date)
    }

    /// The line under every timed table.
    pub fn line(&self) -> String {
        format!(
            "Times from one {}: they change with the machine and its load.",
            self.short()
        )
    }
}

/// Days since 1970-01-01 as `YYYY-MM-DD` (the proleptic Gregorian calendar).
fn civil_date(days: i64) -> String {
    // Howard Hinnant's days_from_civil, inverted.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}")
}

/// The lines `<!-- ANCHOR: name -->` and `<!-- ANCHOR_END: name -->` around `body`.
fn anchored_block(name: &str, body: &str) -> String {
    format!("<!-- ANCHOR: {name} -->\n{body}<!-- ANCHOR_END: {name} -->\n")
}

impl BookNumbers {
    /// The fragment with one more table.
    pub fn table(mut self, table: Quoted) -> BookNumbers {
        self.tables.push(table);
        self
    }

    /// The fragment with one more value.
    pub fn value(mut self, anchor: &str, timed: bool, text: String) -> BookNumbers {
        self.values.push(Value {
            anchor: anchor.to_string(),
            timed,
            text,
        });
        self
    }

    /// The fragment's other tables and values appended to this one's.
    pub fn merge(mut self, other: BookNumbers) -> BookNumbers {
        self.tables.extend(other.tables);
        self.values.extend(other.values);
        self
    }

    /// The table included by `anchor`.
    pub fn get(&self, anchor: &str) -> Option<&Quoted> {
        self.tables.iter().find(|t| t.anchor == anchor)
    }

    /// The fragment without its timed tables and values: what a test can regenerate.
    pub fn exact(&self) -> BookNumbers {
        BookNumbers {
            tables: self.tables.iter().filter(|t| !t.timed).cloned().collect(),
            values: self.values.iter().filter(|v| !v.timed).cloned().collect(),
        }
    }

    /// Each table's and value's anchor and the Markdown between its anchor lines, as
    /// [`BookNumbers::markdown`] writes it (`run` only matters for timed parts).
    pub fn blocks(&self, run: &Run) -> Vec<(String, String)> {
        let mut out = Vec::new();
        for t in &self.tables {
            let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
            // Columns of numbers are right-aligned, so their digits line up; a cell
            // that says a number is missing ("-", "not run") does not count.
            let numeric = |c: usize| {
                let cells = t.rows.iter().filter_map(|r| r.get(c));
                let mut numbers =
                    cells.filter(|cell| !matches!(cell.as_str(), "-" | "not run"));
                numbers.all(|cell| {
                    cell.trim_start_matches('-')
                        .chars()
                        .next()
                        .is_some_and(|ch| ch.is_ascii_digit())
                })
            };
            let rule: Vec<&str> = (0..t.header.len())
                .map(|c| if numeric(c) { "---:" } else { "---" })
                .collect();
            let rows: String = t.rows.iter().map(|r| line(r)).collect();
            let mut body = format!(
                "{}|{}|\n{}",
                line(&t.header),
                rule.join("|"),
                anchored_block(&format!("{}_rows", t.anchor), &rows)
            );
            if t.timed {
                body.push_str(&format!("\n{}\n", run.line()));
            }
            out.push((t.anchor.clone(), body));
        }
        for v in &self.values {
            out.push((v.anchor.clone(), format!("{}\n", v.text)));
        }
        out
    }

    /// The whole file: a comment saying where it comes from, then every table and
    /// value between its anchors, the run's line under the anchor `run` and its few
    /// words ([`Run::short`]) under `machine`.
    pub fn markdown(&self, stem: &str, run: &Run) -> String {
        let writer = format!(
            "examples/11_speed_vs_accuracy.rs (quality: {})",
            run.quality
        );
        self.markdown_by(
            stem,
            run,
            &writer,
            "rerun the lesson (--full --out chapters/figures)",
        )
    }

    /// [`BookNumbers::markdown`] for a fragment that `writer` writes (a bench), its
    /// comment saying how to write it again (`again`).
    pub fn markdown_by(
        &self,
        stem: &str,
        run: &Run,
        writer: &str,
        again: &str,
    ) -> String {
        let mut out = format!(
            "<!-- {stem}.md: the numbers of chart {stem} that the book quotes, written by \
             {writer}. Do not edit: {again}. -->\n\n"
        );
        for (anchor, body) in self.blocks(run) {
            out.push_str(&anchored_block(&anchor, &body));
            out.push('\n');
        }
        out.push_str(&anchored_block("run", &format!("{}\n", run.line())));
        out.push('\n');
        out.push_str(&anchored_block("machine", &format!("{}\n", run.short())));
        out
    }
}

/// The lines strictly between `ANCHOR: name` and `ANCHOR_END: name` in `text` (nested
/// anchor lines included, unlike mdBook, which drops them), each ending in a newline;
/// `None` if either marker is missing.
pub fn anchored(text: &str, name: &str) -> Option<String> {
    let is = |line: &str, marker: &str| {
        line.split_once(marker).is_some_and(|(_, rest)| {
            rest.trim_start().trim_end_matches("-->").trim().eq(name)
        })
    };
    let mut lines = text.lines();
    lines.by_ref().find(|l| is(l, "ANCHOR:"))?;
    let mut out = String::new();
    for line in lines {
        if is(line, "ANCHOR_END:") {
            return Some(out);
        }
        out.push_str(line);
        out.push('\n');
    }
    None
}
