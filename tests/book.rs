//! Static checks on the book sources in `chapters/`.
//!
//! * every `{{#include …}}`, `{{#rustdoc_include …}}` and `{{#playground …}}`
//!   resolves: the file exists (relative to the `.md` file), a named anchor has
//!   both `ANCHOR: name` and `ANCHOR_END: name`, and numeric line ranges fit;
//! * every relative image (`![..](path)`, `<img src="path">`) exists;
//! * no ```` ```rust ```` block holds pasted code: only include lines are
//!   allowed, so every line of Rust in the book is compiled and tested;
//! * every real (non-draft) chapter listed in `SUMMARY.md` exists.
//!
//! All problems are collected and reported together, as `file:line: message`.
//! Standard library only.

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

/// A `{{#name args}}` directive found in a line of Markdown.
#[derive(Debug, PartialEq, Eq)]
struct Directive<'a> {
    name: &'a str,
    args: &'a str,
}

/// All unescaped `{{#name args}}` directives in `line`, in order.
fn directives(line: &str) -> Vec<Directive<'_>> {
    let mut found = Vec::new();
    let mut rest = line;
    let mut offset = 0;
    while let Some(start) = rest.find("{{") {
        let abs = offset + start;
        let escaped = abs > 0 && line.as_bytes()[abs - 1] == b'\\';
        let after = &rest[start + 2..];
        let Some(end) = after.find("}}") else { break };
        let inner = after[..end].trim_start();
        if !escaped && let Some(body) = inner.strip_prefix('#') {
            let name_len = body
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(body.len());
            let (name, args) = body.split_at(name_len);
            if !name.is_empty() {
                found.push(Directive {
                    name,
                    args: args.trim(),
                });
            }
        }
        let consumed = start + 2 + end + 2;
        offset += consumed;
        rest = &rest[consumed..];
    }
    found
}

/// What part of a file an include selects.
#[derive(Debug, PartialEq, Eq)]
enum Selector<'a> {
    All,
    Anchor(&'a str),
    /// 1-based, inclusive line numbers as mdBook reads them.
    Lines {
        start: Option<usize>,
        end: Option<usize>,
    },
}

/// Split `path[:anchor | :start[:end] | ::end]` the way mdBook does.
fn parse_include(args: &str) -> Result<(&str, Selector<'_>), String> {
    let (path, sel) = match args.split_once(':') {
        None => return Ok((args, Selector::All)),
        Some((path, sel)) => (path, sel.trim()),
    };
    if sel.is_empty() {
        return Ok((path, Selector::All));
    }
    let (first, second) = match sel.split_once(':') {
        None => (sel, None),
        Some((a, b)) => (a, Some(b)),
    };
    let number = |s: &str| -> Result<Option<usize>, String> {
        if s.is_empty() {
            Ok(None)
        } else {
            s.parse::<usize>()
                .map(Some)
                .map_err(|_| format!("bad line number `{s}` in `{args}`"))
        }
    };
    if !first.is_empty() && !first.starts_with(|c: char| c.is_ascii_digit()) {
        if second.is_some() {
            return Err(format!("anchor name with a `:` in `{args}`"));
        }
        return Ok((path, Selector::Anchor(first)));
    }
    let start = number(first)?;
    let end = match second {
        // `path:N` selects the single line N.
        None => start,
        Some(s) => number(s)?,
    };
    Ok((path, Selector::Lines { start, end }))
}

/// Does `text` contain `marker` immediately followed by the identifier `name`?
fn has_marker(text: &str, marker: &str, name: &str) -> bool {
    text.lines().any(|line| {
        let mut rest = line;
        while let Some(i) = rest.find(marker) {
            let after = rest[i + marker.len()..].trim_start();
            let ident_len = after
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '-'))
                .unwrap_or(after.len());
            if &after[..ident_len] == name {
                return true;
            }
            rest = &rest[i + marker.len()..];
        }
        false
    })
}

/// The 1-based line on which an insta snapshot's content starts: the line after the
/// second `---`.
fn snapshot_body_start(text: &str) -> usize {
    text.lines()
        .enumerate()
        .filter(|(_, l)| l.trim_end() == "---")
        .nth(1)
        .map_or(1, |(i, _)| i + 2)
}

fn is_remote_or_absolute(target: &str) -> bool {
    target.is_empty()
        || target.starts_with('#')
        || target.starts_with('/')
        || target.starts_with("data:")
        || target.starts_with("mailto:")
        || target.contains("://")
        || target.starts_with("//")
}

/// Drop `#fragment` and `?query` from a link target.
fn strip_fragment(target: &str) -> &str {
    let end = target.find(['#', '?']).unwrap_or(target.len());
    &target[..end]
}

/// Remove inline code spans so that examples like `` `![x](y)` `` are ignored.
fn without_code_spans(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut in_code = false;
    for c in line.chars() {
        if c == '`' {
            in_code = !in_code;
        } else if !in_code {
            out.push(c);
        }
    }
    out
}

/// Image targets in a line: `![alt](path "title")` and `<img ... src="path">`.
fn image_targets(line: &str) -> Vec<String> {
    let line = without_code_spans(line);
    let mut found = Vec::new();
    let mut rest = line.as_str();
    while let Some(i) = rest.find("![") {
        rest = &rest[i + 2..];
        let Some(close) = rest.find("](") else { break };
        let after = &rest[close + 2..];
        let Some(end) = after.find(')') else { break };
        let inside = after[..end].trim();
        let target = inside
            .strip_prefix('<')
            .and_then(|s| s.split_once('>').map(|(t, _)| t))
            .unwrap_or_else(|| inside.split_whitespace().next().unwrap_or(""));
        found.push(target.to_string());
        rest = &after[end..];
    }
    let lower = line.to_ascii_lowercase();
    let mut from = 0;
    while let Some(i) = lower[from..].find("<img") {
        let tag_start = from + i;
        let tag_end = lower[tag_start..]
            .find('>')
            .map_or(lower.len(), |e| tag_start + e);
        let tag = &line[tag_start..tag_end];
        let tag_lower = &lower[tag_start..tag_end];
        if let Some(s) = tag_lower.find("src=") {
            let value = &tag[s + 4..];
            let target = match value.chars().next() {
                Some(q @ ('"' | '\'')) => value[1..].split(q).next().unwrap_or(""),
                _ => value
                    .split_whitespace()
                    .next()
                    .unwrap_or("")
                    .trim_end_matches('/'),
            };
            found.push(target.to_string());
        }
        from = tag_end;
    }
    found
}

/// An opening or closing code fence: (fence char, run length, info string).
fn fence(line: &str) -> Option<(char, usize, &str)> {
    let trimmed = line.trim_start();
    let c = trimmed.chars().next()?;
    if c != '`' && c != '~' {
        return None;
    }
    let len = trimmed.chars().take_while(|&x| x == c).count();
    (len >= 3).then(|| (c, len, trimmed[len..].trim()))
}

fn is_rust_info(info: &str) -> bool {
    info.split([',', ' ', '\t'])
        .next()
        .is_some_and(|lang| lang == "rust")
}

const INCLUDE_DIRECTIVES: [&str; 3] = ["include", "rustdoc_include", "playground"];

/// Check one Markdown file. `path` is used for resolving relative paths and
/// for reporting; `text` is its content.
fn check_markdown(files: &dyn Files, path: &Path, text: &str, problems: &mut Vec<Problem>) {
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
                    // An insta snapshot starts with a `---` ... `---` header; an include
                    // of one must start on the first line after it, so the book shows
                    // exactly the pinned numbers and none of the metadata.
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
                            format!("image `{target}` not found (`{}`)", file.display()),
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
fn check_summary(files: &dyn Files, summary: &Path, text: &str, problems: &mut Vec<Problem>) {
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
                        message: format!("chapter `{target}` not found (`{}`)", file.display()),
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

#[test]
fn include_syntax_is_parsed_like_mdbook() {
    assert_eq!(parse_include("a.rs"), Ok(("a.rs", Selector::All)));
    assert_eq!(parse_include("a.rs:x"), Ok(("a.rs", Selector::Anchor("x"))));
    assert_eq!(
        parse_include("a.rs:3"),
        Ok((
            "a.rs",
            Selector::Lines {
                start: Some(3),
                end: Some(3)
            }
        ))
    );
    assert_eq!(
        parse_include("a.rs::7"),
        Ok((
            "a.rs",
            Selector::Lines {
                start: None,
                end: Some(7)
            }
        ))
    );
    assert_eq!(
        parse_include("a.rs:2:"),
        Ok((
            "a.rs",
            Selector::Lines {
                start: Some(2),
                end: None
            }
        ))
    );
    assert_eq!(
        directives(r"x {{#include a.rs:b}} \{{#include c}} {{ #title T }}"),
        vec![
            Directive {
                name: "include",
                args: "a.rs:b"
            },
            Directive {
                name: "title",
                args: "T"
            },
        ]
    );
}

// ---------------------------------------------------------------- quoted numbers

/// A number a chapter prints inside a sentence, and the fragment that holds it:
/// lesson 11 writes the numbers the book quotes to `chapters/figures/11_N_name.md`
/// (tables and single values between mdBook anchors), and a sentence that cannot
/// include a whole table quotes the number by hand. This pins each such number to
/// its source: the chapter's number must equal the fragment's, rounded as the
/// chapter prints it.
struct Quote {
    /// The chapter, under `chapters/`.
    chapter: &'static str,
    /// The text around the number, `{}` standing for it (e.g. `"**{} %** at"`).
    context: &'static str,
    /// The fragment, under `chapters/`.
    fragment: &'static str,
    /// The table's or value's anchor in the fragment.
    anchor: &'static str,
    /// The table row's first cell, and the column's header ("" for a value).
    cell: (&'static str, &'static str),
    /// Which number of the cell (a cell such as "12 (4.96%)" holds two).
    index: usize,
}

/// A shorthand for a [`Quote`] of a table's cell.
const fn quote(
    chapter: &'static str,
    context: &'static str,
    fragment: &'static str,
    anchor: &'static str,
    cell: (&'static str, &'static str),
    index: usize,
) -> Quote {
    Quote {
        chapter,
        context,
        fragment,
        anchor,
        cell,
        index,
    }
}

/// A shorthand for a [`Quote`] of a single value.
const fn value(
    chapter: &'static str,
    context: &'static str,
    fragment: &'static str,
    anchor: &'static str,
) -> Quote {
    quote(chapter, context, fragment, anchor, ("", ""), 0)
}

const S1: &str = "figures/11_1_sphere.md";
const S4: &str = "figures/11_2_triangle.md";
const S13: &str = "figures/11_3_offsets.md";
const S15: &str = "figures/11_4_precision.md";
const MC: &str = "figures/11_5_monte_carlo.md";
const BVH: &str = "figures/11_7_scaling.md";
const LESSONS: &str = "figures/11_8_lessons.md";

const CH07_1: &str = "07_1_sphere.md";
const CH07_3: &str = "07_3_box.md";
const CH07_4: &str = "07_4_triangle.md";
const FAIL: &str = "where_methods_fail.md";
const ROOTS: &str = "where_methods_fail_roots.md";
const TRIS: &str = "where_methods_fail_triangles.md";
const OFFSETS: &str = "where_methods_fail_offsets.md";
const CH11: &str = "11_speed_vs_accuracy.md";
const CH11_1: &str = "11_1_bvh.md";

const TB: &str = "textbook f32";
const TB_WRONG: &str = "% wrong, textbook f32";
const MT: &str = "Moller-Trumbore";
const AT_V: &str = "vertices (S4)";
const AT_E: &str = "edge midpoints (S5)";
const FIXED: &str = "fixed t > 1e-4 (%)";
const SIZE: &str = "scaled offset's size";
const WORLD: &str = "f32 world space";
const RELATIVE: &str = "f32 camera-relative";
const VAR: &str = "variance of one sample";
const SLOPE: &str = "slope of log RMSE";
const DIFFER: &str = "pixels differing (%)";

/// Every number the chapters quote inline from lesson 11's fragments (one a line).
#[rustfmt::skip]
const QUOTES: &[Quote] = &[
    // S1, chart 1: lesson 07, "Where methods fail", lesson 11.
    quote(CH07_1, "textbook's $t$ is off by ${}$", S1, "accuracy", ("1e3", TB), 0),
    quote(CH07_1, "$D/r = 3\\cdot 10^3$, **{} %**", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(CH07_1, "at $D/r = 10^4$ **{} %**", S1, "accuracy", ("1e4", TB_WRONG), 0),
    value(CH07_1, "never exceeds ${}$", S1, "stable_f32_max"),
    quote(ROOTS, "${}$ of $t$ on average", S1, "accuracy", ("1e3", TB), 0),
    quote(ROOTS, "at $3\\cdot 10^3$ **{} %**", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(ROOTS, "$10^4$ **{} %**: at ten", S1, "accuracy", ("1e4", TB_WRONG), 0),
    value(ROOTS, "at most ${}$, the rounding", S1, "stable_f32_max"),
    quote(FAIL, "$10^4$ | {} %, ", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(FAIL, ", {} % wrong | 0 %, 0 %", S1, "accuracy", ("1e4", TB_WRONG), 0),
    quote(CH11, "grows with $D/r$: ${}$ at", S1, "accuracy", ("1e3", TB), 0),
    quote(CH11, "falls apart: {} % of the rays", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(CH11, "$3\\cdot 10^3$, {} % at $10^4$", S1, "accuracy", ("1e4", TB_WRONG), 0),
    value(CH11, "stay below ${}$", S1, "stable_f32_max"),
    quote(CH11, "lower floor (${}$ at $10^6$)", S1, "accuracy", ("1e6", "textbook f64"), 0),
    // S4, S5, S6, chart 2.
    quote(CH07_4, "leaks **{} of 242** vertex", S4, "leaks", (AT_V, MT), 0),
    quote(CH07_4, "**12 of {}** vertex", S4, "leaks", (AT_V, "rays"), 0),
    quote(CH07_4, "({} %) and **52 of 720**", S4, "leaks", (AT_V, MT), 1),
    quote(CH07_4, "**{} of 720** edge", S4, "leaks", (AT_E, MT), 0),
    quote(CH07_4, "**52 of {}** edge", S4, "leaks", (AT_E, "rays"), 0),
    quote(CH07_4, "edge rays ({} %)", S4, "leaks", (AT_E, MT), 1),
    quote(TRIS, "leaks **{} of 242** vertex", S4, "leaks", (AT_V, MT), 0),
    quote(TRIS, "({} %) and\n**52 of 720**", S4, "leaks", (AT_V, MT), 1),
    quote(TRIS, "**{} of 720** edge", S4, "leaks", (AT_E, MT), 0),
    quote(TRIS, "edge rays ({} %)", S4, "leaks", (AT_E, MT), 1),
    quote(FAIL, "rays at vertices | {} / 242", S4, "leaks", (AT_V, MT), 0),
    quote(FAIL, "| 12 / {} leak", S4, "leaks", (AT_V, "rays"), 0),
    quote(FAIL, "shared edges | {} / 720", S4, "leaks", (AT_E, MT), 0),
    quote(FAIL, "| 52 / {} leak", S4, "leaks", (AT_E, "rays"), 0),
    quote(CH11, "at the {} vertices", S4, "leaks", (AT_V, "rays"), 0),
    quote(CH11, "each of its {}", S4, "leaks", (AT_E, "rays"), 0),
    quote(CH11, "lets {} % of them", S4, "leaks", ("vertices + 7 per edge", MT), 1),
    quote(CH11, "hence its {} % and", S4, "leaks", (AT_V, MT), 1),
    quote(CH11, "% and {} %:", S4, "leaks", (AT_E, MT), 1),
    quote(CH11, "slivers it leaks {} %", S4, "leaks", ("a mesh of slivers", "widened by 1e-6"), 1),
    quote(CH07_3, "test hits: {} of them", S4, "boxes", ("plain", "rays at a vertex"), 0),
    quote(CH07_3, "box for\n**{}**", S4, "boxes", ("plain", "rejected"), 0),
    quote(CH07_3, "**11 326** ({} %)", S4, "boxes", ("plain", "rejected"), 1),
    quote(CH07_3, "rejects about {} % of", S4, "boxes", ("plain", "rejected"), 1),
    quote(TRIS, "run, the {} in", S4, "boxes", ("plain", "rays at a vertex"), 0),
    quote(TRIS, "box in **{}** of the", S4, "boxes", ("plain", "rejected"), 0),
    quote(TRIS, "{} cases (", S4, "boxes", ("plain", "rays at a vertex"), 0),
    quote(TRIS, "cases ({} %)", S4, "boxes", ("plain", "rejected"), 1),
    quote(FAIL, "hit triangle | {} % rejected", S4, "boxes", ("plain", "rejected"), 1),
    quote(CH11, "slab test rejects {} % of", S4, "boxes", ("plain", "rejected"), 1),
    // S13, S14, chart 3.
    quote(OFFSETS, "but **{} %** at $10^4$", S13, "self_hits", ("1e4", FIXED), 0),
    quote(OFFSETS, "$10^4$ and {} % at", S13, "self_hits", ("1e5", FIXED), 0),
    quote(FAIL, "$t > 10^{-4}$: {} % self-hits", S13, "self_hits", ("1e4", FIXED), 0),
    quote(CH11, "{} % of the rays hit themselves", S13, "self_hits", ("1", "no offset (%)"), 0),
    quote(CH11, "on: {} % at $10^4$", S13, "self_hits", ("1e4", FIXED), 0),
    quote(CH11, "$10^4$, {} % at $10^5$", S13, "self_hits", ("1e5", FIXED), 0),
    quote(CH11, "(${}$ at 1,", S13, "self_hits", ("1", SIZE), 0),
    quote(CH11, "${}$ at $10^3$, $0.51", S13, "self_hits", ("1e3", SIZE), 0),
    quote(CH11, "${}$ at $10^5$), keeps", S13, "self_hits", ("1e5", SIZE), 0),
    // S15, chart 4.
    quote(OFFSETS, "${}$ at $X = 1$", S15, "errors", ("1", WORLD), 0),
    quote(OFFSETS, "${}$ at $10^4$ and", S15, "errors", ("1e4", WORLD), 0),
    quote(OFFSETS, "**${}$** at $10^6$", S15, "errors", ("1e6", WORLD), 0),
    quote(OFFSETS, "every $X$**, ${}$ at $10^6$", S15, "errors", ("1e6", RELATIVE), 0),
    quote(OFFSETS, "gives ${}$ there", S15, "errors", ("1e6", "f64 world space"), 0),
    quote(FAIL, "world `f32`: ${}$", S15, "errors", ("1e6", WORLD), 0),
    quote(FAIL, "camera-relative: ${}$", S15, "errors", ("1e6", RELATIVE), 0),
    quote(CH11, "at $X$: ${}$ at", S15, "errors", ("1", WORLD), 0),
    quote(CH11, "$X = 1$, ${}$ at $10^4$", S15, "errors", ("1e4", WORLD), 0),
    quote(CH11, "$10^4$, ${}$ at $10^6$ (STABILITY S15)", S15, "errors", ("1e6", WORLD), 0),
    quote(CH11, "error at ${}$ at $10^6$, as near", S15, "errors", ("1e6", RELATIVE), 0),
    quote(CH11, "start\n(${}$ at", S15, "errors", ("1e6", "f64 world space"), 0),
    // S18, S19, chart 5.
    quote(CH11, "line has slope ${}$", MC, "estimators", ("cosine", SLOPE), 0),
    quote(CH11, "${}$ for uniform directions", MC, "estimators", ("uniform hemisphere", VAR), 0),
    quote(CH11, "${}$ for cosine", MC, "estimators", ("cosine", VAR), 0),
    quote(CH11, "${}$ for sampling the light's area", MC, "estimators", ("light area", VAR), 0),
    quote(CH11, "${}$ for sampling the cone", MC, "estimators", ("light cone", VAR), 0),
    quote(CH11, "with the cone, slope ${}$", MC, "estimators", ("light cone, jittered", SLOPE), 0),
    quote(CH11, "has variance ${}$ and one cone", MC, "estimators", ("cosine", VAR), 0),
    quote(CH11, "${}$. How many", MC, "estimators", ("light cone", VAR), 0),
    // Chart 6: its errors are included from the fragment, not quoted in a sentence.
    // Chart 7: the largest scene.
    value(CH11, "scenes of 1 to {} triangles", BVH, "largest"),
    value(CH11_1, "from 1 to {}", BVH, "largest"),
    value(TRIS, "rays per second through {}", BVH, "largest"),
    // Chart 8.
    quote(CH11, "rasterizer gets {} % of its", LESSONS, "errors", ("rasterized, no shadows", DIFFER), 0),
    quote(CH11, "agrees to {} %", LESSONS, "errors", ("64 segments, 1024^2 map", DIFFER), 0),
    quote(CH11, "(8 segments: {} % wrong)", LESSONS, "errors", ("8 segments, 1024^2 map", DIFFER), 0),
];

/// A number as a chapter or a fragment prints it: its value and the size of one
/// unit of its last digit (0.01 for "4.96", 1e-6 for "3.7e-5", 1e-6 for
/// `3.7\cdot 10^{-5}`). Digits may be grouped by single spaces ("10 939").
#[derive(Clone, Copy, Debug, PartialEq)]
struct Printed {
    value: f64,
    unit: f64,
}

/// The number at the start of `text`, and the rest of the text after it.
fn printed(text: &str) -> Option<(Printed, &str)> {
    let bytes = text.as_bytes();
    let mut i = 0;
    let mut digits = String::new();
    if bytes.first() == Some(&b'-') || text.starts_with('−') {
        digits.push('-');
        i += if bytes[0] == b'-' {
            1
        } else {
            '−'.len_utf8()
        };
    }
    let start = i;
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_digit() {
            digits.push(c as char);
            i += 1;
        } else if c == b' '
            && i > start
            && bytes.len() >= i + 4
            && bytes[i + 1..i + 4].iter().all(u8::is_ascii_digit)
            && bytes.get(i + 4).is_none_or(|b| !b.is_ascii_digit())
            && bytes.get(i + 4) != Some(&b'.')
        {
            i += 1; // a digit group: "10 939"
        } else {
            break;
        }
    }
    if i == start {
        return None;
    }
    let mut decimals = 0i32;
    if bytes.get(i) == Some(&b'.') && bytes.get(i + 1).is_some_and(u8::is_ascii_digit) {
        digits.push('.');
        i += 1;
        while let Some(c) = bytes.get(i).filter(|c| c.is_ascii_digit()) {
            digits.push(*c as char);
            decimals += 1;
            i += 1;
        }
    }
    let mut exponent = 0i32;
    let rest = &text[i..];
    let exp_text = if let Some(r) = rest.strip_prefix('e') {
        Some((r, ""))
    } else {
        rest.strip_prefix("\\cdot 10^{")
            .or_else(|| rest.strip_prefix("\\cdot10^{"))
            .map(|r| (r, "}"))
    };
    let mut rest = rest;
    if let Some((r, close)) = exp_text {
        let end = r
            .char_indices()
            .find(|&(k, c)| !(c.is_ascii_digit() || (k == 0 && c == '-')))
            .map_or(r.len(), |(k, _)| k);
        if let Ok(e) = r[..end].parse::<i32>()
            && r[end..].starts_with(close)
        {
            exponent = e;
            rest = &r[end + close.len()..];
        }
    }
    let mantissa: f64 = digits.parse().ok()?;
    let scale = 10f64.powi(exponent);
    Some((
        Printed {
            value: mantissa * scale,
            unit: scale * 10f64.powi(-decimals),
        },
        rest,
    ))
}

/// Every number in a table cell, in order ("12 (4.96%)" holds 12 and 4.96).
fn numbers(cell: &str) -> Vec<Printed> {
    let mut out = Vec::new();
    let mut rest = cell;
    while !rest.is_empty() {
        let at_start = rest.len() == cell.len()
            || !cell.as_bytes()[cell.len() - rest.len() - 1].is_ascii_alphanumeric();
        match printed(rest).filter(|_| at_start) {
            Some((p, after)) => {
                out.push(p);
                rest = after;
            }
            None => {
                let next = rest.chars().next().map_or(1, char::len_utf8);
                rest = &rest[next..];
            }
        }
    }
    out
}

/// The lines between `ANCHOR: name` and `ANCHOR_END: name` of `text`, other anchor
/// lines left out (what mdBook includes).
fn anchored_lines(text: &str, name: &str) -> Option<Vec<String>> {
    let marker = |line: &str, m: &str| {
        line.split_once(m)
            .is_some_and(|(_, r)| r.trim().trim_end_matches("-->").trim() == name)
    };
    let mut lines = text.lines();
    lines.by_ref().find(|l| marker(l, "ANCHOR:"))?;
    let mut out = Vec::new();
    for line in lines {
        if marker(line, "ANCHOR_END:") {
            return Some(out);
        }
        if !line.contains("ANCHOR:") && !line.contains("ANCHOR_END:") {
            out.push(line.to_string());
        }
    }
    None
}

/// The cells of a Markdown table row.
fn cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    inner.split('|').map(|c| c.trim().to_string()).collect()
}

/// The number `quote` names in the fragment's text, or why it cannot be found.
fn source(quote: &Quote, fragment: &str) -> Result<Printed, String> {
    let lines = anchored_lines(fragment, quote.anchor)
        .ok_or_else(|| format!("no anchor `{}`", quote.anchor))?;
    let cell = if quote.cell.0.is_empty() {
        lines.join(" ")
    } else {
        let header = cells(lines.first().ok_or("an empty table")?);
        let column = header
            .iter()
            .position(|h| h == quote.cell.1)
            .ok_or_else(|| format!("no column `{}` in {header:?}", quote.cell.1))?;
        let row = lines
            .iter()
            .map(|l| cells(l))
            .find(|c| c.first().is_some_and(|k| k == quote.cell.0))
            .ok_or_else(|| format!("no row `{}`", quote.cell.0))?;
        row.get(column).cloned().unwrap_or_default()
    };
    numbers(&cell)
        .get(quote.index)
        .copied()
        .ok_or_else(|| format!("no number {} in `{cell}`", quote.index))
}

/// Does the chapter's number agree with the fragment's, each rounded as printed?
fn agrees(chapter: Printed, fragment: Printed) -> bool {
    let slack = 0.5 * chapter.unit + 0.5 * fragment.unit;
    (chapter.value - fragment.value).abs() <= slack * (1.0 + 1e-9)
}

/// The problems of `quotes` with the chapters and fragments that `read` returns.
fn check_quotes(read: &dyn Fn(&str) -> Option<String>, quotes: &[Quote]) -> Vec<String> {
    let mut problems = Vec::new();
    for q in quotes {
        let here = format!("{} `{}`", q.chapter, q.context);
        let Some(chapter) = read(q.chapter) else {
            problems.push(format!("{here}: cannot read the chapter"));
            continue;
        };
        let Some((before, after)) = q.context.split_once("{}") else {
            problems.push(format!("{here}: the context has no {{}}"));
            continue;
        };
        let found: Vec<Printed> = chapter
            .match_indices(before)
            .filter_map(|(i, _)| printed(&chapter[i + before.len()..]))
            .filter(|(_, rest)| rest.starts_with(after))
            .map(|(p, _)| p)
            .collect();
        let Some(&number) = found.first() else {
            problems.push(format!("{here}: not found in the chapter"));
            continue;
        };
        let fragment_path = q.fragment.to_string();
        let Some(fragment) = read(&fragment_path) else {
            problems.push(format!("{here}: cannot read {}", q.fragment));
            continue;
        };
        match source(q, &fragment) {
            Err(e) => problems.push(format!("{here}: {}: {e}", q.fragment)),
            Ok(source) if !agrees(number, source) => problems.push(format!(
                "{here}: the chapter prints {}, {} holds {} (`{}` {:?})",
                number.value, q.fragment, source.value, q.anchor, q.cell
            )),
            Ok(_) => {}
        }
    }
    problems
}

#[test]
fn quoted_numbers_agree_with_the_fragments_that_hold_them() {
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).join("chapters");
    let read = |rel: &str| fs::read_to_string(chapters.join(rel)).ok();
    let problems = check_quotes(&read, QUOTES);
    assert!(
        problems.is_empty(),
        "{} quoted number(s) disagree with their source:\n  {}\n(the fragments are \
         written by `cargo run --release --example 11_speed_vs_accuracy -- --full --out \
         chapters/figures`; fix the sentence, or the quote in tests/book.rs)",
        problems.len(),
        problems.join("\n  ")
    );
}

#[test]
fn the_quote_checker_reads_numbers_as_printed_and_can_fail() {
    let p = |s: &str| printed(s).map(|(p, _)| p);
    assert_eq!(
        p("4.96%"),
        Some(Printed {
            value: 4.96,
            unit: 0.01
        })
    );
    assert_eq!(p("10 939 rays").map(|x| x.value), Some(10939.0));
    assert_eq!(p("12 of 242").map(|x| x.value), Some(12.0));
    let sci = p("3.7\\cdot 10^{-5}$").unwrap();
    assert!((sci.value - 3.7e-5).abs() < 1e-12 && (sci.unit - 1e-6).abs() < 1e-15);
    assert!((p("3.76e-5").unwrap().value - 3.76e-5).abs() < 1e-12);
    assert_eq!(
        numbers("12 (4.96%)")
            .iter()
            .map(|x| x.value)
            .collect::<Vec<_>>(),
        vec![12.0, 4.96]
    );
    assert_eq!(
        numbers("f32 world space"),
        vec![],
        "digits inside a word are no number"
    );
    assert!(agrees(p("5.0").unwrap(), p("4.96").unwrap()));
    assert!(!agrees(p("5.1").unwrap(), p("4.96").unwrap()));
    assert!(agrees(
        p("3.8\\cdot 10^{-5}").unwrap(),
        p("3.76e-5").unwrap()
    ));
    assert!(!agrees(
        p("3.7\\cdot 10^{-5}").unwrap(),
        p("3.76e-5").unwrap()
    ));

    let fragment = "\
<!-- ANCHOR: t -->
| x | a | b |
|---|---:|---:|
<!-- ANCHOR: t_rows -->
| 1e3 | 12 (4.96%) | 3.76e-5 |
<!-- ANCHOR_END: t_rows -->
<!-- ANCHOR_END: t -->
<!-- ANCHOR: v -->
6.3e-8
<!-- ANCHOR_END: v -->
";
    let chapter = "Leaks **12** rays (5.0 %), off by $3.8\\cdot 10^{-5}$, at most 7e-8.";
    let read = |rel: &str| match rel {
        "ch.md" => Some(chapter.to_string()),
        "f.md" => Some(fragment.to_string()),
        _ => None,
    };
    let good = [
        quote("ch.md", "Leaks **{}** rays", "f.md", "t", ("1e3", "a"), 0),
        quote("ch.md", "rays ({} %)", "f.md", "t", ("1e3", "a"), 1),
        quote("ch.md", "off by ${}$", "f.md", "t", ("1e3", "b"), 0),
    ];
    assert_eq!(check_quotes(&read, &good), Vec::<String>::new());
    let bad = [
        value("ch.md", "at most {}.", "f.md", "v"),
        quote("ch.md", "Leaks **{}** rays", "f.md", "t", ("1e3", "b"), 0),
        quote("ch.md", "Leaks **{}** rays", "f.md", "t", ("1e4", "a"), 0),
        quote("ch.md", "not there {}", "f.md", "t", ("1e3", "a"), 0),
        quote("ch.md", "Leaks **{}** rays", "g.md", "t", ("1e3", "a"), 0),
    ];
    let problems = check_quotes(&read, &bad);
    assert_eq!(problems.len(), bad.len(), "{problems:#?}");
    assert!(problems[0].contains("prints 7e-8") || problems[0].contains("0.00000007"));
    assert!(problems[2].contains("no row `1e4`"));
    assert!(problems[3].contains("not found"));
}

/// The chapters whose times come from lesson 11's fragments.
const TIMED_CHAPTERS: [&str; 11] = [
    CH07_1,
    CH07_3,
    CH07_4,
    FAIL,
    ROOTS,
    TRIS,
    OFFSETS,
    "where_methods_fail_cameras.md",
    "where_methods_fail_monte_carlo.md",
    CH11,
    CH11_1,
];

/// The times typed by hand in `text` (outside code blocks), as "number unit": a
/// number followed by ns, ms or "million", in a paragraph that does not name
/// `cargo bench` (whose times `BENCHMARKS.md` records, by hand, for the cases
/// lesson 11 does not time).
fn typed_times(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut in_code = false;
    let mut paragraph = Vec::new();
    let flush = |paragraph: &mut Vec<&str>, found: &mut Vec<String>| {
        let joined = paragraph.join(" ");
        paragraph.clear();
        if joined.contains("cargo bench") {
            return;
        }
        let mut rest = joined.as_str();
        while !rest.is_empty() {
            let before_ok = joined.len() == rest.len()
                || !joined.as_bytes()[joined.len() - rest.len() - 1].is_ascii_alphanumeric();
            if let Some((p, after)) = printed(rest).filter(|_| before_ok) {
                let unit = ["ns", "ms", "million"].into_iter().find(|u| {
                    after.trim_start().strip_prefix(u).is_some_and(|r| {
                        r.chars().next().is_none_or(|c| !c.is_ascii_alphanumeric())
                    })
                });
                if let Some(unit) = unit {
                    found.push(format!("{} {unit}", p.value));
                }
                rest = after;
            } else {
                let next = rest.chars().next().map_or(1, char::len_utf8);
                rest = &rest[next..];
            }
        }
    };
    for line in text.lines() {
        if fence(line).is_some() {
            in_code = !in_code;
            flush(&mut paragraph, &mut found);
            continue;
        }
        if in_code {
            continue;
        }
        if line.trim().is_empty() {
            flush(&mut paragraph, &mut found);
        } else {
            paragraph.push(line);
        }
    }
    flush(&mut paragraph, &mut found);
    found
}

#[test]
fn lesson_11_times_are_included_never_typed() {
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).join("chapters");
    let mut problems = Vec::new();
    for name in TIMED_CHAPTERS {
        let text = fs::read_to_string(chapters.join(name)).expect("read chapter");
        for time in typed_times(&text) {
            problems.push(format!("{name}: `{time}` typed by hand"));
        }
    }
    assert!(
        problems.is_empty(),
        "times go stale at the next run of lesson 11: include them from its fragments \
         ({{{{#include figures/11_N_name.md:anchor}}}}), or name `cargo bench` if they are \
         BENCHMARKS.md's:\n  {}",
        problems.join("\n  ")
    );
    assert_eq!(
        typed_times("It takes 7.1 ns, or 2.14 million rays\nper second.\n\n```\n3 ns\n```\n"),
        vec!["7.1 ns", "2.14 million"]
    );
    assert!(typed_times("With `cargo bench`, 28.2 ns.").is_empty());
    assert!(typed_times("{{#include figures/11_7_scaling.md:bvh_mrays}} million").is_empty());
}
