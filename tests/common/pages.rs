//! The book's pages and the tests' insta snapshots, read as text from the root of
//! the crate, and the numbers a page quotes from them.

use std::fs;
use std::path::{Path, PathBuf};

/// The root of the crate (where `Cargo.toml` is).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The file at `relative` to the root; panics naming it if it cannot be read.
pub fn read(relative: &str) -> String {
    fs::read_to_string(root().join(relative))
        .unwrap_or_else(|e| panic!("{relative}: {e}"))
}

/// A page of the book (`chapters/NAME`), as written.
pub fn page(name: &str) -> String {
    read(&format!("chapters/{name}"))
}

/// Where insta keeps the snapshot `name` of a test in the module `module` (as
/// `module_path!()` gives it, e.g. `lessons::lesson_10_path_tracing`) of a test
/// crate in `tests/CRATE/`: `tests/CRATE/snapshots/CRATE__MODULE__NAME.snap`.
pub fn snapshot_path(module: &str, name: &str) -> String {
    let krate = module.split("::").next().unwrap_or(module);
    format!(
        "tests/{krate}/snapshots/{}__{name}.snap",
        module.replace("::", "__")
    )
}

/// The snapshot `name` of the module `module` (see [`snapshot_path`]), header
/// included.
pub fn snapshot(module: &str, name: &str) -> String {
    read(&snapshot_path(module, name))
}

/// The snapshot `name` of the module `module` after its insta header: what the
/// test asserted.
pub fn snapshot_body(module: &str, name: &str) -> String {
    after_header(&snapshot(module, name)).to_string()
}

/// A snapshot's text after its insta header (the second `---` line).
pub fn after_header(snapshot: &str) -> &str {
    let mut parts = snapshot.splitn(3, "---\n");
    parts.next();
    parts.next();
    parts.next().expect("an insta snapshot has a header")
}

/// The first number in `phrase`, as printed: digits with an optional sign (`-` or
/// `−`) and decimal point.
pub fn first_number(phrase: &str) -> &str {
    let is_sign = |c: char| c == '-' || c == '−';
    let start = phrase
        .char_indices()
        .find(|&(i, c)| {
            c.is_ascii_digit()
                || (is_sign(c)
                    && phrase[i + c.len_utf8()..]
                        .starts_with(|d: char| d.is_ascii_digit()))
        })
        .map(|(i, _)| i)
        .unwrap_or_else(|| panic!("no number in {phrase:?}"));
    let len = phrase[start..]
        .char_indices()
        .skip(1)
        .find(|&(_, c)| !(c.is_ascii_digit() || c == '.'))
        .map_or(phrase.len() - start, |(i, _)| i);
    phrase[start..start + len].trim_end_matches('.')
}

/// The page `name` contains `phrase`, and the first number in it is `value` rounded
/// to the decimals it shows ("0.07" for 0.06995, "−0.487" for -0.4871).
pub fn assert_quotes(name: &str, phrase: &str, value: f64) {
    let text = page(name);
    assert!(
        text.contains(phrase),
        "chapters/{name} no longer says {phrase:?}"
    );
    let quoted = first_number(phrase);
    let plain = quoted.replace('−', "-");
    let decimals = plain.split_once('.').map_or(0, |(_, d)| d.len());
    assert_eq!(
        format!("{value:.decimals$}"),
        plain,
        "chapters/{name} quotes {quoted} in {phrase:?}; the value is {value}"
    );
}

/// The number in `column` (0: the first after the label) of the row of a snapshot's
/// table whose label is `label` (followed by at least two spaces).
pub fn cell(snap: &str, label: &str, column: usize) -> f64 {
    snap.lines()
        .find_map(|line| {
            let rest = line.strip_prefix(label)?;
            rest.starts_with("  ").then_some(())?;
            rest.split_whitespace().nth(column)?.parse().ok()
        })
        .unwrap_or_else(|| panic!("no row {label:?} with a column {column}"))
}

/// The number that follows `before` in a snapshot (up to a space or `;`).
pub fn after(snap: &str, before: &str) -> f64 {
    let start =
        snap.find(before).unwrap_or_else(|| panic!("no {before:?}")) + before.len();
    let rest = &snap[start..];
    let end = rest.find([' ', ';', '\n', ')']).unwrap_or(rest.len());
    rest[..end].parse().unwrap()
}

/// A number as the pages print it in math: `$3.2\cdot 10^{-7}$`.
pub fn sci(x: f64) -> String {
    let s = format!("{x:.1e}");
    let (mantissa, exponent) = s.split_once('e').unwrap();
    format!("${mantissa}\\cdot 10^{{{exponent}}}$")
}

/// Panics unless the page `name` contains `phrase`: a measured number the page quotes,
/// formatted from this file's measurement.
pub fn assert_page_says(name: &str, phrase: &str) {
    let text = std::fs::read_to_string(format!("chapters/{name}")).unwrap();
    assert!(
        text.contains(phrase),
        "chapters/{name} no longer says {phrase:?}: the measurement changed, or the text"
    );
}

/// Every `.rs` file under `root/dir`, recursively, in order, as (its path from `root`
/// with `/` between the parts, its text); `target` and `node_modules` folders are not
/// sources and are skipped.
pub fn rust_files(root: &Path, dir: &str) -> Vec<(String, String)> {
    fn walk(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
        let Ok(entries) = fs::read_dir(root.join(dir)) else {
            return;
        };
        let mut paths: Vec<_> = entries.flatten().map(|e| e.path()).collect();
        paths.sort();
        for path in paths {
            let name = path.file_name().unwrap_or_default();
            let relative = dir.join(name);
            if path.is_dir() {
                if name != "target" && name != "node_modules" {
                    walk(root, &relative, out);
                }
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = fs::read_to_string(&path).unwrap_or_default();
                out.push((relative.to_string_lossy().replace('\\', "/"), text));
            }
        }
    }
    let mut out = Vec::new();
    walk(root, Path::new(dir), &mut out);
    out
}
