//! A claim quantified over measurements is checked by a test (issue 20, part 5c).
//!
//! The rule: a paragraph of a chapter (outside code blocks) that quantifies over a
//! measured table or chart with one of the phrases in [`QUANTIFIERS`] ("at every
//! distance", "to the bit", "within the noise", ...) must name the test that checks
//! it: either a marker `<!-- checked: tests/FILE.rs::test_name -->` in the paragraph,
//! or, as the "How we know" lists do, the test's name in backticks. Either way the
//! test function must exist in that file (for a bare name: in some file of `tests/`,
//! or in a unit test module of `src/`).
//! A sentence that cannot name its test is reworded.
//!
//! And a test the book, the README or BENCHMARKS.md names by its path is there:
//! `tests/FILE.rs` exists, `tests/FILE.rs::name` defines `fn name(`, and an included
//! or named snapshot `tests/.../NAME.snap` exists (`scripts/test-refs --fix` rewrites
//! such references after a test moves).
//!
//! Standard library only.

use crate::common::pages::rust_files;
use crate::printed::anchored_lines;
use crate::sources::unit_tests;
use std::fs;
use std::path::Path;

/// Phrases that claim something of every row of a measurement (matched in lower case).
const QUANTIFIERS: &[&str] = &[
    "at every distance",
    "at any distance",
    "every size",
    "at every $",
    "at any $",
    "to the bit",
    "within the noise",
    "is noise",
    "the noise of the timing",
];

/// True if `file` (a test file's text) defines `fn name`.
fn defines(file: &str, name: &str) -> bool {
    file.contains(&format!("fn {name}("))
}

/// The problems of one page: `tests` gives a test file's text by its path
/// (`tests/x.rs`), and `all_tests` is the text of every test file, joined.
fn check_page(
    page: &str,
    text: &str,
    tests: &dyn Fn(&str) -> Option<String>,
    all_tests: &str,
) -> Vec<String> {
    let mut problems = Vec::new();
    let mut in_code = false;
    let mut paragraph = String::new();
    let mut first_line = 0;
    for (i, line) in text.lines().chain(std::iter::once("")).enumerate() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
            continue;
        }
        if in_code {
            continue;
        }
        if !line.trim().is_empty() {
            if paragraph.is_empty() {
                first_line = i + 1;
            }
            paragraph.push_str(line);
            paragraph.push('\n');
            continue;
        }
        if let Some(problem) = check_paragraph(&paragraph, tests, all_tests) {
            problems.push(format!("{page}:{first_line}: {problem}"));
        }
        paragraph.clear();
    }
    problems
}

/// `None` if the paragraph makes no quantified claim or names a test that exists.
fn check_paragraph(
    paragraph: &str,
    tests: &dyn Fn(&str) -> Option<String>,
    all_tests: &str,
) -> Option<String> {
    let low = paragraph.to_lowercase();
    let phrase = QUANTIFIERS.iter().find(|q| low.contains(*q))?;
    if let Some(rest) = paragraph.split("<!-- checked: ").nth(1) {
        let target = rest.split(" -->").next().unwrap_or("").trim();
        let Some((file, name)) = target.split_once("::") else {
            return Some(format!("marker `{target}` is not tests/FILE.rs::test_name"));
        };
        return match tests(file) {
            Some(code) if defines(&code, name) => None,
            _ => Some(format!(
                "`{phrase}`: the marker's test {target} does not exist"
            )),
        };
    }
    let names_a_test = paragraph
        .split('`')
        .skip(1)
        .step_by(2)
        .map(|span| span.rsplit("::").next().unwrap_or(span))
        .any(|name| !name.is_empty() && defines(all_tests, name));
    if names_a_test {
        None
    } else {
        Some(format!(
            "`{phrase}` claims something of every measurement, but no test is named \
             (add <!-- checked: tests/FILE.rs::test_name -->, or reword)"
        ))
    }
}

#[test]
fn every_quantified_claim_names_its_test() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let summary =
        fs::read_to_string(root.join("chapters/SUMMARY.md")).expect("SUMMARY.md");
    let pages: Vec<&str> = summary
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .filter(|p| p.ends_with(".md"))
        .collect();
    let read = |file: &str| fs::read_to_string(root.join(file)).ok();
    // The tests: every file of `tests/` and the unit test modules of `src/`.
    let mut all_tests: String = rust_files(root, "tests")
        .into_iter()
        .map(|(_, text)| text)
        .collect();
    for (_, text) in rust_files(root, "src") {
        all_tests += unit_tests(&text);
    }
    let mut problems = Vec::new();
    for page in pages {
        let text =
            fs::read_to_string(root.join("chapters").join(page)).expect("chapter");
        problems.extend(check_page(page, &text, &read, &all_tests));
    }
    assert!(
        problems.is_empty(),
        "{} quantified claim(s) without a test:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The references to tests in `text` that do not resolve: `tests/FILE.rs` that is
/// not a file, `tests/FILE.rs::name` whose file has no `fn name(`, a snapshot
/// `tests/DIR/snapshots/NAME.snap` that is not there. `read` gives a file's text
/// by its path from the root.
fn broken_test_paths(text: &str, read: &dyn Fn(&str) -> Option<String>) -> Vec<String> {
    let mut broken = Vec::new();
    for (i, _) in text.match_indices("tests/") {
        // `src/x/tests/` is not a test; the `../tests/` of an include (made from
        // chapters/) is read from the root like the rest.
        let before = &text[..i];
        if before.ends_with(|c: char| c.is_alphanumeric() || c == '_')
            || (before.ends_with('/') && !before.ends_with("../"))
        {
            continue;
        }
        let rest = &text[i..];
        let end = rest
            .find(|c: char| !(c.is_alphanumeric() || "_-./:".contains(c)))
            .unwrap_or(rest.len());
        let reference = rest[..end].trim_end_matches(['.', ':']);
        let (file, name) = match reference.split_once("::") {
            Some((file, name)) => (file, Some(name)),
            None => (reference.split(':').next().unwrap_or(reference), None),
        };
        let reference = if name.is_some() { reference } else { file };
        if !(file.ends_with(".rs") || file.ends_with(".snap"))
            || file.starts_with("tests/browser/")
        {
            continue;
        }
        match (read(file), name) {
            (None, _) => broken.push(format!("{reference}: no such file")),
            (Some(code), Some(name)) if !defines(&code, name) => {
                broken.push(format!("{reference}: {file} has no fn {name}"))
            }
            _ => {}
        }
    }
    broken
}

#[test]
fn every_test_the_book_names_by_path_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |file: &str| fs::read_to_string(root.join(file)).ok();
    let mut pages: Vec<String> =
        ["README.md", "BENCHMARKS.md"].map(String::from).to_vec();
    for entry in fs::read_dir(root.join("chapters"))
        .expect("chapters/")
        .flatten()
    {
        let name = entry.file_name().to_string_lossy().to_string();
        if name.ends_with(".md") {
            pages.push(format!("chapters/{name}"));
        }
    }
    let mut problems = Vec::new();
    for page in pages {
        let text = read(&page).unwrap_or_default();
        for problem in broken_test_paths(&text, &read) {
            problems.push(format!("{page}: {problem}"));
        }
    }
    assert!(
        problems.is_empty(),
        "{} reference(s) to tests that are not there (scripts/test-refs --fix rewrites \
         those of a moved test):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn the_path_checker_can_fail() {
    let read =
        |file: &str| (file == "tests/a/b.rs").then(|| "fn it_holds() {}".to_string());
    let check = |text: &str| broken_test_paths(text, &read);
    assert!(check("In `tests/a/b.rs`: `it_holds`.").is_empty());
    assert!(check("<!-- checked: tests/a/b.rs::it_holds -->").is_empty());
    assert!(check("see `tests/browser/check.mjs`").is_empty());
    assert_eq!(check("In `tests/b.rs`:"), ["tests/b.rs: no such file"]);
    assert_eq!(
        check("<!-- checked: tests/a/b.rs::gone -->"),
        ["tests/a/b.rs::gone: tests/a/b.rs has no fn gone"]
    );
    assert_eq!(
        check("{{#include ../tests/a/snapshots/a__x.snap:5:}}"),
        ["tests/a/snapshots/a__x.snap: no such file"]
    );
}

#[test]
fn the_claim_checker_can_fail() {
    let tests = "#[test]\nfn holds_everywhere() {}\n";
    let read = |file: &str| (file == "tests/x.rs").then(|| tests.to_string());
    let check = |text: &str| check_page("p.md", text, &read, tests);
    // Checked by a marker, by a named test, or no quantifier at all: fine.
    assert!(
        check(
            "Zero at every distance.\n<!-- checked: tests/x.rs::holds_everywhere -->\n"
        )
        .is_empty()
    );
    assert!(check("- `holds_everywhere`: zero at every distance.\n").is_empty());
    assert!(check("Zero at the distances measured.\n").is_empty());
    assert!(check("```text\nat every distance\n```\n").is_empty());
    // An unchecked claim, and a marker naming a test that does not exist.
    let found = check("First.\n\nThe tree is faster at every size.\n");
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].starts_with("p.md:3: `every size`"), "{found:?}");
    let found =
        check("Equal to the bit.\n<!-- checked: tests/x.rs::no_such_test -->\n");
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("does not exist"), "{found:?}");
}

/// Phrases that say several measurements were taken together (issue 30, part 3).
const RUN_CLAIMS: &[&str] = &["one run", "same run", "one `--full` run"];

/// The stamp of a fragment file that names its run ("... run on 2 cores of ...,
/// load average 1.16, 2026-11-23"), if it has one.
fn stamp(fragment: &str) -> Option<String> {
    fragment.lines().find_map(|line| {
        let start = line.find(" run on ")?;
        let rest = &line[start..];
        let end = rest.find(": they change").unwrap_or(rest.len());
        Some(rest[..end].to_string())
    })
}

/// The stamp an include shows: the one inside its anchor, or, for a fragment of
/// `chapters/figures/` (each written by one run), the file's.
fn included_stamp(
    args: &str,
    fragment: &dyn Fn(&str) -> Option<String>,
) -> Option<String> {
    let (path, anchor) = args.split_once(':').unwrap_or((args, ""));
    let text = fragment(path)?;
    let shown = anchored_lines(&text, anchor).map(|lines| lines.join("\n"));
    match shown.as_deref().and_then(stamp) {
        Some(found) => Some(found),
        None if path.starts_with("figures/") => stamp(&text),
        None => None,
    }
}

/// The problems of one page's run claims: a paragraph that says its numbers come
/// from one run (or the same run) must include, in its section (from it to the end
/// of the page if it says "below"), only fragments stamped by one run. `fragment`
/// reads an included file by its path relative to `chapters/`.
fn check_runs(
    page: &str,
    text: &str,
    fragment: &dyn Fn(&str) -> Option<String>,
) -> Vec<String> {
    let sections: Vec<&str> = text.split("\n## ").collect();
    let mut problems = Vec::new();
    for (s, section) in sections.iter().enumerate() {
        for paragraph in section.split("\n\n") {
            let low = paragraph.to_lowercase();
            let Some(phrase) = RUN_CLAIMS.iter().find(|p| low.contains(*p)) else {
                continue;
            };
            let scope = if low.contains("below") {
                let from = section.find(paragraph).unwrap_or(0);
                let mut rest = section[from..].to_string();
                for later in &sections[s + 1..] {
                    rest += later;
                }
                rest
            } else {
                section.to_string()
            };
            let mut stamps: Vec<String> = scope
                .split("{{#include ")
                .skip(1)
                .filter_map(|inc| inc.split("}}").next())
                .filter_map(|args| included_stamp(args, fragment))
                .collect();
            stamps.sort();
            stamps.dedup();
            if stamps.len() > 1 {
                problems.push(format!(
                    "{page}: \"{phrase}\", but its section includes {} runs: {}",
                    stamps.len(),
                    stamps.join(" | ")
                ));
            }
        }
    }
    problems
}

#[test]
fn a_sentence_about_one_run_includes_one_runs_stamps() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let chapters = root.join("chapters");
    let fragment = |path: &str| fs::read_to_string(chapters.join(path)).ok();
    let mut problems = Vec::new();
    for entry in fs::read_dir(&chapters).expect("chapters/").flatten() {
        let name = entry.file_name().to_string_lossy().to_string();
        if name.ends_with(".md") {
            let text = fs::read_to_string(entry.path()).expect("page");
            problems.extend(check_runs(&name, &text, &fragment));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_run_checker_can_fail() {
    let stamped = |load: &str| {
        format!(
            "| 1 |\n\nTimes from one `--full` run on 2 cores, load {load}, 2026-11-23: they change.\n"
        )
    };
    let fragment = |path: &str| match path {
        "figures/a.md" => Some(stamped("1.0")),
        "figures/b.md" => Some(stamped("2.0")),
        "figures/c.md" => Some(stamped("1.0")),
        _ => None,
    };
    let one = "## S\n\nFrom one run:\n\n{{#include figures/a.md:t}}\n\n{{#include figures/c.md:t}}\n";
    assert!(check_runs("p.md", one, &fragment).is_empty());
    let two = "## S\n\nFrom one run:\n\n{{#include figures/a.md:t}}\n\n{{#include figures/b.md:t}}\n";
    assert_eq!(check_runs("p.md", two, &fragment).len(), 1);
    // "below" reaches past the section's end; without it, the next section is apart.
    let below = "## S\n\nThe tables below come from one run.\n\n## T\n\n{{#include figures/a.md:t}}\n{{#include figures/b.md:t}}\n";
    assert_eq!(check_runs("p.md", below, &fragment).len(), 1);
    let apart = "## S\n\nOne run.\n\n## T\n\n{{#include figures/a.md:t}}\n{{#include figures/b.md:t}}\n";
    assert!(check_runs("p.md", apart, &fragment).is_empty());
}
