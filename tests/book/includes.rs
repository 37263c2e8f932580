//! Static checks on the book sources in `chapters/`.
//!
//! * every `{{#include …}}`, `{{#rustdoc_include …}}` and `{{#playground …}}`
//!   resolves: the file exists (relative to the `.md` file), a named anchor has
//!   both `ANCHOR: name` and `ANCHOR_END: name`, and numeric line ranges fit;
//! * every relative image (`![..](path)`, `<img src="path">`) exists;
//! * no ```` ```rust ```` block holds pasted code: only include lines are
//!   allowed, so every line of Rust in the book is compiled and tested;
//! * every real (non-draft) chapter listed in `SUMMARY.md` exists;
//! * every line included into a code block fits the book's code column,
//!   [`CODE_COLUMN`] characters, so no listing is cut at the right edge.
//!
//! All problems are collected and reported together, as `file:line: message`.
//! Standard library only.

use crate::markdown::{
    Selector, directives, fence, has_marker, image_targets, is_remote_or_absolute,
    is_rust_info, parse_include, snapshot_body_start, strip_fragment,
};
use crate::printed::anchored_lines;

use std::collections::HashMap;
use std::fmt;
use std::fs;
use std::path::{Component, Path, PathBuf};

/// Where the checker reads files from: the real disk, or a map in the self-test.
trait Files {
    fn read(&self, path: &Path) -> Option<String>;
    fn exists(&self, path: &Path) -> bool;
}

struct Disk;

impl Files for Disk {
    fn read(&self, path: &Path) -> Option<String> {
        fs::read_to_string(path).ok()
    }
    fn exists(&self, path: &Path) -> bool {
        path.exists()
    }
}

struct Memory(HashMap<PathBuf, String>);

impl Files for Memory {
    fn read(&self, path: &Path) -> Option<String> {
        self.0.get(&normalize(path)).cloned()
    }
    fn exists(&self, path: &Path) -> bool {
        let path = normalize(path);
        self.0.keys().any(|k| *k == path || k.starts_with(&path))
    }
}

/// Lexically resolve `.` and `..` (no filesystem access).
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            other => out.push(other.as_os_str()),
        }
    }
    out
}

#[derive(Debug, Clone, PartialEq, Eq)]
struct Problem {
    file: PathBuf,
    line: usize,
    message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file.display(), self.line, self.message)
    }
}

/// How many characters of a code block the book's column shows without scrolling
/// (measured in Chromium at 1280 px: about 88). `rustfmt.toml` lays code out to it.
const CODE_COLUMN: usize = 88;

const INCLUDE_DIRECTIVES: [&str; 3] = ["include", "rustdoc_include", "playground"];

/// Check one Markdown file. `path` is used for resolving relative paths and
/// for reporting; `text` is its content.
fn check_markdown(
    files: &dyn Files,
    path: &Path,
    text: &str,
    problems: &mut Vec<Problem>,
) {
    let dir = path.parent().unwrap_or(Path::new(""));
    let mut report = |line: usize, message: String| {
        problems.push(Problem {
            file: path.to_path_buf(),
            line,
            message,
        })
    };
    // (fence char, fence length, is rust) of the code block we are in, if any.
    let mut open: Option<(char, usize, bool)> = None;

    for (index, line) in text.lines().enumerate() {
        let lineno = index + 1;

        if let Some((c, len, info)) = fence(line) {
            match open {
                None => {
                    open = Some((c, len, is_rust_info(info)));
                    continue;
                }
                Some((oc, olen, _)) if c == oc && len >= olen && info.is_empty() => {
                    open = None;
                    continue;
                }
                Some(_) => {}
            }
        }

        let found = directives(line);
        for d in &found {
            if !INCLUDE_DIRECTIVES.contains(&d.name) {
                continue;
            }
            let (rel, selector) = match parse_include(d.args) {
                Ok(parsed) => parsed,
                Err(e) => {
                    report(lineno, format!("{{{{#{}}}}}: {e}", d.name));
                    continue;
                }
            };
            let target = dir.join(rel);
            let Some(content) = files.read(&target) else {
                report(
                    lineno,
                    format!(
                        "{{{{#{} {}}}}}: cannot read `{}`",
                        d.name,
                        d.args,
                        target.display()
                    ),
                );
                continue;
            };
            if open.is_some() {
                for shown in shown_lines(&content, &selector) {
                    let width = shown.chars().count();
                    if width > CODE_COLUMN {
                        report(
                            lineno,
                            format!(
                                "{{{{#{} {}}}}}: a line of {width} characters, wider \
                                 than the code column ({CODE_COLUMN}): `{}`",
                                d.name,
                                d.args,
                                shown.trim()
                            ),
                        );
                    }
                }
            }
            match selector {
                Selector::All => {}
                Selector::Anchor(name) => {
                    for marker in ["ANCHOR:", "ANCHOR_END:"] {
                        if !has_marker(&content, marker, name) {
                            report(
                                lineno,
                                format!(
                                    "{{{{#{} {}}}}}: `{}` has no `{marker} {name}`",
                                    d.name,
                                    d.args,
                                    target.display()
                                ),
                            );
                        }
                    }
                }
                Selector::Lines { start, end } => {
                    let count = content.lines().count();
                    let first = start.unwrap_or(1);
                    let last = end.unwrap_or(count);
                    // An insta snapshot starts with a `---` ... `---` header; an
                    // include of one must start on the first line after it, so the book
                    // shows exactly the pinned numbers and none of the metadata.
                    let is_snapshot = target.extension().is_some_and(|e| e == "snap");
                    let body = snapshot_body_start(&content);
                    if is_snapshot && start != Some(body) {
                        report(
                            lineno,
                            format!(
                                "{{{{#{} {}}}}}: a snapshot's numbers start on line {body} of `{}`: include it as `:{body}:`",
                                d.name,
                                d.args,
                                target.display()
                            ),
                        );
                    }
                    if first == 0 || first > count || last > count || first > last {
                        report(
                            lineno,
                            format!(
                                "{{{{#{} {}}}}}: line range {first}..={last} does not fit `{}` ({count} lines)",
                                d.name,
                                d.args,
                                target.display()
                            ),
                        );
                    }
                }
            }
        }

        match open {
            Some((_, _, true)) => {
                let trimmed = line.trim();
                let only_include = found.len() == 1
                    && matches!(found[0].name, "include" | "rustdoc_include")
                    && trimmed.starts_with("{{")
                    && trimmed.ends_with("}}");
                if !trimmed.is_empty() && !only_include {
                    report(
                        lineno,
                        format!(
                            "pasted code in a ```rust block: `{trimmed}` \
                             (include it from a compiled file with {{{{#include file.rs:anchor}}}})"
                        ),
                    );
                }
            }
            Some((_, _, false)) => {}
            None => {
                for target in image_targets(line) {
                    if is_remote_or_absolute(&target) {
                        continue;
                    }
                    let file = dir.join(strip_fragment(&target));
                    if !files.exists(&file) {
                        report(
                            lineno,
                            format!(
                                "image `{target}` not found (`{}`)",
                                file.display()
                            ),
                        );
                    }
                }
            }
        }
    }
    if open.is_some() {
        report(text.lines().count(), "unclosed code fence".to_string());
    }
}

/// Check that every non-draft chapter in SUMMARY.md exists.
fn check_summary(
    files: &dyn Files,
    summary: &Path,
    text: &str,
    problems: &mut Vec<Problem>,
) {
    let dir = summary.parent().unwrap_or(Path::new(""));
    for (index, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(end) = after.find(')') else { break };
            let target = after[..end].trim();
            // `[Title]()` is an mdBook draft chapter: planned, not written.
            if !is_remote_or_absolute(target) {
                let file = dir.join(strip_fragment(target));
                if !files.exists(&file) {
                    problems.push(Problem {
                        file: summary.to_path_buf(),
                        line: index + 1,
                        message: format!(
                            "chapter `{target}` not found (`{}`)",
                            file.display()
                        ),
                    });
                }
            }
            rest = &after[end..];
        }
    }
}

fn markdown_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            markdown_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "md") {
            out.push(path);
        }
    }
}

fn render(problems: &[Problem]) -> String {
    problems
        .iter()
        .map(|p| format!("  {p}\n"))
        .collect::<String>()
}

#[test]
fn chapters_are_consistent() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let chapters = root.join("chapters");
    let mut md = Vec::new();
    markdown_files(&chapters, &mut md);
    assert!(
        !md.is_empty(),
        "no Markdown files under {}",
        chapters.display()
    );

    let mut problems = Vec::new();
    for path in &md {
        let text = fs::read_to_string(path).expect("read chapter");
        let shown = path.strip_prefix(root).unwrap_or(path);
        let before = problems.len();
        check_markdown(&Disk, path, &text, &mut problems);
        if path.file_name().is_some_and(|n| n == "SUMMARY.md") {
            check_summary(&Disk, path, &text, &mut problems);
        }
        for p in &mut problems[before..] {
            p.file = shown.to_path_buf();
        }
    }
    assert!(
        chapters.join("SUMMARY.md").exists(),
        "chapters/SUMMARY.md is missing"
    );
    assert!(
        problems.is_empty(),
        "{} problem(s) in the book sources:\n{}",
        problems.len(),
        render(&problems)
    );
}

/// The checker must be able to fail: feed it a small book with known faults.
#[test]
fn checker_reports_broken_sources() {
    let code = "\
fn unrelated() {}
// ANCHOR: good
fn good() {}
// ANCHOR_END: good
// ANCHOR: half
fn half() {}
";
    let chapter = "\
# A chapter

```rust
{{#include ../examples/demo.rs:good}}
```

```rust,ignore
{{#rustdoc_include ../examples/demo.rs:missing}}
```

```rust
{{#include ../examples/demo.rs:half}}
fn pasted() {}
```

{{#include ../examples/demo.rs:2:4}}
{{#include ../examples/demo.rs:5:99}}
{{#include ../examples/nope.rs}}
\\{{#include ../examples/escaped_is_not_checked.rs}}

```text
{{#include ../examples/demo.rs:nothere}}
![not an image in a code block](nowhere.png)
```

![ok](figures/ok.png) ![gone](figures/gone.png \"title\")
<img src=\"figures/gone2.png\" alt=\"x\"> <img src=\"https://example.com/x.png\">
`![inline code is ignored](nowhere.png)`
";
    let summary = "\
# Summary

[Intro](ch.md)
- [Missing](missing.md)
- [Draft]()
";
    let files = Memory(
        [
            ("book/ch.md", chapter),
            ("book/SUMMARY.md", summary),
            ("book/figures/ok.png", ""),
            ("examples/demo.rs", code),
        ]
        .into_iter()
        .map(|(p, t)| (PathBuf::from(p), t.to_string()))
        .collect(),
    );

    let mut problems = Vec::new();
    let ch = Path::new("book/ch.md");
    check_markdown(&files, ch, chapter, &mut problems);
    let sm = Path::new("book/SUMMARY.md");
    check_summary(&files, sm, summary, &mut problems);

    let lines: Vec<(String, usize)> = problems
        .iter()
        .map(|p| (p.file.display().to_string(), p.line))
        .collect();
    let expected: Vec<(String, usize)> = [
        ("book/ch.md", 8),  // anchor `missing`: no ANCHOR
        ("book/ch.md", 8),  // ... and no ANCHOR_END
        ("book/ch.md", 12), // anchor `half`: no ANCHOR_END
        ("book/ch.md", 13), // pasted code
        ("book/ch.md", 17), // line range past the end
        ("book/ch.md", 18), // missing file
        ("book/ch.md", 22), // includes in other code blocks are checked too
        ("book/ch.md", 22),
        ("book/ch.md", 26), // figures/gone.png
        ("book/ch.md", 27), // figures/gone2.png
        ("book/SUMMARY.md", 4),
    ]
    .into_iter()
    .map(|(f, l)| (f.to_string(), l))
    .collect();
    assert_eq!(lines, expected, "problems reported:\n{}", render(&problems));

    assert!(problems[5].message.contains("nope.rs"));
    assert!(problems[2].message.contains("ANCHOR_END: half"));
    assert!(problems[3].message.contains("fn pasted"));
}

/// A listing line wider than the code column is reported, one of exactly
/// [`CODE_COLUMN`] characters is not, and lines outside the anchor do not count.
#[test]
fn a_listing_wider_than_the_code_column_is_reported() {
    let wide = format!("    let x = {};", "1".repeat(CODE_COLUMN));
    let fits = "y".repeat(CODE_COLUMN);
    let code = format!("{wide}\n// ANCHOR: a\n{fits}\n{wide}\n// ANCHOR_END: a\n");
    let chapter = "```rust\n{{#include ../examples/w.rs:a}}\n```\n";
    let files = Memory(
        [("book/ch.md", chapter.to_string()), ("examples/w.rs", code)]
            .into_iter()
            .map(|(p, t)| (PathBuf::from(p), t))
            .collect(),
    );
    let mut problems = Vec::new();
    check_markdown(&files, Path::new("book/ch.md"), chapter, &mut problems);
    assert_eq!(problems.len(), 1, "{}", render(&problems));
    assert!(problems[0].message.contains("wider than the code column"));
}

/// The lines an include shows, as mdBook selects them: a whole file, a line range,
/// or an anchor's lines ([`anchored_lines`]; none if the anchor is broken, which the
/// anchor check reports).
fn shown_lines(content: &str, selector: &Selector<'_>) -> Vec<String> {
    let lines = content.lines().map(str::to_string);
    match *selector {
        Selector::All => lines.collect(),
        Selector::Lines { start, end } => {
            let first = start.unwrap_or(1).max(1) - 1;
            let last = end.unwrap_or(usize::MAX);
            lines.skip(first).take(last.saturating_sub(first)).collect()
        }
        Selector::Anchor(name) => anchored_lines(content, name).unwrap_or_default(),
    }
}
