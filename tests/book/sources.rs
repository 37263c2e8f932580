//! What a page's stated numbers may come from (for `numbers`): the regions a page
//! includes, the bodies of the functions it names (in backticks or in a
//! `<!-- checked: FILE.rs::name -->` marker) and the snapshots those assert.

use crate::markdown;
use crate::printed::anchored_lines;
use std::collections::HashMap;

use markdown::fence;

/// The body of `fn name(` in a Rust file, braces matched, or a `const name` up to
/// its `;` (a bench's image size, a chart's distances), or `None`.
pub(crate) fn function_body<'a>(code: &'a str, name: &str) -> Option<&'a str> {
    if let Some(at) = code.find(&format!("const {name}: ")) {
        let end = code[at..].find(';').map_or(code.len(), |e| at + e + 1);
        return Some(&code[at..end]);
    }
    let start = code.find(&format!("fn {name}("))?;
    let open = start + code[start..].find('{')?;
    let mut depth = 0;
    for (k, c) in code[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(&code[start..open + k + 1]);
                }
            }
            _ => {}
        }
    }
    None
}

/// The functions a page names: `(None, name)` for a name in backticks (`a::b`
/// counts as `b`), to be found in any test file, and `(Some(file), name)` for a
/// `<!-- checked: FILE.rs::name -->` marker, found in that file (a test, a bench, or
/// the source that defines a scene's numbers; `BENCHMARKS.md::anchor` names a table
/// of the benchmarks).
pub(crate) fn named_functions(text: &str) -> Vec<(Option<String>, String)> {
    let mut names = Vec::new();
    let mut in_code = false;
    for line in text.lines() {
        if fence(line).is_some() {
            in_code = !in_code;
            continue;
        }
        if in_code {
            continue;
        }
        for span in line.split('`').skip(1).step_by(2) {
            let name = span
                .rsplit("::")
                .next()
                .unwrap_or(span)
                .trim_end_matches("()");
            if !name.is_empty()
                && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            {
                names.push((None, name.to_string()));
            }
        }
        for marker in line.split("<!-- checked: ").skip(1) {
            let target = marker.split(" -->").next().unwrap_or("");
            if let Some((file, name)) = target.split_once("::") {
                names.push((Some(file.trim().to_string()), name.trim().to_string()));
            }
        }
    }
    names
}

/// The unit test modules of a source file: everything from its first `#[cfg(test)]`
/// on (the crate keeps them at the end), or nothing.
pub(crate) fn unit_tests(source: &str) -> &str {
    source
        .find("#[cfg(test)]")
        .map_or("", |start| &source[start..])
}

/// Where insta keeps the snapshot `name` asserted in the Rust file `path` (relative
/// to the root): `snapshots/` beside the file, named after the file's module path
/// (`tests/lessons/lesson_07_intersections.rs`, `numbers` ->
/// `tests/lessons/snapshots/lessons__lesson_07_intersections__numbers.snap`; a file of
/// `src/` is a module of `render_lessons`).
pub(crate) fn snapshot_beside(path: &str, name: &str) -> String {
    let (dir, file) = path.rsplit_once('/').unwrap_or(("", path));
    let stem = file.trim_end_matches(".rs");
    let mut modules: Vec<&str> = dir.split('/').skip(1).collect();
    if dir == "src" || dir.starts_with("src/") {
        modules.insert(0, "render_lessons");
    }
    if !["main", "mod", "lib"].contains(&stem) {
        modules.push(stem);
    }
    format!("{dir}/snapshots/{}__{name}.snap", modules.join("__"))
}

/// The project's Rust files (and `BENCHMARKS.md`), with the functions and constants
/// a bare name in backticks may find in each, read once: every item of a file of
/// `tests/`, the unit tests of a file of `src/` (see [`unit_tests`]), nothing of the
/// rest. A page names hundreds of names; looking each up in every file again was
/// most of the checker's time.
pub(crate) struct Code<'a> {
    files: Vec<(&'a str, &'a str, HashMap<&'a str, &'a str>)>,
}

impl<'a> Code<'a> {
    /// The index of `files`, each (path from the root, text).
    pub(crate) fn new(files: &'a [(String, String)]) -> Code<'a> {
        let files = files
            .iter()
            .map(|(path, text)| {
                let region = if path.starts_with("tests/") {
                    text.as_str()
                } else if path.starts_with("src/") {
                    unit_tests(text)
                } else {
                    ""
                };
                let mut tests = HashMap::new();
                for keyword in ["fn ", "const "] {
                    for (at, _) in region.match_indices(keyword) {
                        let rest = &region[at + keyword.len()..];
                        let end = rest
                            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                            .unwrap_or(rest.len());
                        let name = &rest[..end];
                        if !name.is_empty()
                            && !tests.contains_key(name)
                            && let Some(body) = function_body(region, name)
                        {
                            tests.insert(name, body);
                        }
                    }
                }
                (path.as_str(), text.as_str(), tests)
            })
            .collect();
        Code { files }
    }
}

/// What a page's numbers may come from in code: the body of each function it
/// names (see [`named_functions`]) and the snapshots that body asserts. `code`
/// holds every Rust file of the project; `snapshot` reads a snapshot by its path (see
/// [`snapshot_beside`]).
pub(crate) fn test_sources(
    text: &str,
    code: &Code,
    snapshot: &dyn Fn(&str) -> Option<String>,
) -> String {
    let mut out = String::new();
    let mut names = named_functions(text);
    names.sort();
    names.dedup();
    for (file, name) in names {
        for (path, source, tests) in &code.files {
            // A bare name is a test: in `tests/`, or in a unit test module of `src/`.
            let region = match &file {
                Some(f) if f == path && path.ends_with(".md") => {
                    anchored_lines(source, &name).map(|lines| lines.join("\n"))
                }
                Some(f) if f == path => {
                    function_body(source, &name).map(str::to_string)
                }
                None => tests.get(name.as_str()).map(|body| body.to_string()),
                _ => continue,
            };
            let Some(body) = region else {
                continue;
            };
            out.push_str(&body);
            for call in body.split("assert_snapshot!(").skip(1) {
                let quoted = call.trim_start().strip_prefix('"');
                if let Some(snap) = quoted.and_then(|q| q.split('"').next())
                    && let Some(s) = snapshot(&snapshot_beside(path, snap))
                {
                    out.push_str(&s);
                }
            }
        }
    }
    out
}

/// What one `{{#include path[:selector]}}` line of a page pulls in: the include's
/// arguments, its code (or the whole text, for a fragment or a snapshot), and the
/// text of its Rust comments, which the book shows as prose.
pub(crate) struct Included {
    pub(crate) args: String,
    pub(crate) code: String,
    pub(crate) comments: String,
}

/// The includes of a page, read by `read` relative to `chapters/`.
pub(crate) fn included(
    text: &str,
    read: &dyn Fn(&str) -> Option<String>,
) -> Vec<Included> {
    let mut out = Vec::new();
    for piece in text.split("{{#include ").skip(1) {
        let args = piece.split("}}").next().unwrap_or("").trim();
        let (path, selector) = args.split_once(':').unwrap_or((args, ""));
        let Some(file) = read(path) else { continue };
        let lines: Vec<&str> = file.lines().collect();
        let region = match selector.split_once(':') {
            _ if selector.is_empty() => file.clone(),
            None if !selector.starts_with(|c: char| c.is_ascii_digit()) => {
                anchored_lines(&file, selector)
                    .unwrap_or_default()
                    .join("\n")
            }
            split => {
                let (a, b) = split.unwrap_or((selector, selector));
                let from = a.parse::<usize>().unwrap_or(1).max(1) - 1;
                let to = b.parse::<usize>().unwrap_or(lines.len()).min(lines.len());
                lines.get(from..to).unwrap_or_default().join("\n")
            }
        };
        let (mut code, mut comments) = (String::new(), String::new());
        for line in region.lines() {
            let comment = line
                .trim_start()
                .strip_prefix("//")
                .filter(|_| path.ends_with(".rs"));
            match comment {
                Some(c) => comments.push_str(c.trim_start_matches(['/', '!'])),
                None => code.push_str(line),
            }
            if comment.is_some() {
                comments.push('\n')
            } else {
                code.push('\n')
            }
        }
        out.push(Included {
            args: args.to_string(),
            code,
            comments,
        });
    }
    out
}

/// Everything a page includes, comments and all (the self-test's shorthand).
pub(crate) fn included_text(
    text: &str,
    read: &dyn Fn(&str) -> Option<String>,
) -> String {
    included(text, read)
        .into_iter()
        .map(|i| i.code + &i.comments)
        .collect()
}
