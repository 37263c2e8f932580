//! Every name the book puts in backticks exists (issue 20, part 5b).
//!
//! Two rules, both over the chapters `SUMMARY.md` lists:
//!
//! * **Captions.** A listing's caption, `*Listing: `file`, `name`*`, names what the
//!   listing shows. Each name in it (several are joined by ", " or " and "; a
//!   `Type::method` is checked by its last part) must be *defined* inside the
//!   fragment the listing includes: `fn name`, `struct name`, `enum name`,
//!   `trait name`, `type name`, `const name`, `static name` or `impl name`. An anchor's
//!   name is not enough: the reader looks for the function.
//! * **Prose.** A Rust-looking name in backticks outside code blocks (an identifier,
//!   or a path of them joined by `::`, optionally ending in `()`) must be declared
//!   somewhere in the crate's sources (`src/`, `examples/`, `book/figures/src/`,
//!   `tests/`, `benches/`): as an item, a module, a field or parameter (`name:`), a
//!   `let` binding, or an enum variant. Names of the standard library and of glam are
//!   listed in [`FOREIGN`]; everything else must resolve.
//!
//! Standard library only.

use crate::common::pages::rust_files;
use std::collections::BTreeSet;
use std::fs;
use std::path::Path;

/// Names from outside the crate that the book may put in backticks: Rust's primitive
/// types and standard library, glam's matrices, and the float methods the lessons
/// discuss.
const FOREIGN: &[&str] = &[
    "f32",
    "f64",
    "i32",
    "i64",
    "u32",
    "u64",
    "usize",
    "bool",
    "Option",
    "Some",
    "None",
    "Result",
    "Ok",
    "Err",
    "Vec",
    "String",
    "std",
    "hint",
    "black_box",
    "cmp",
    "signum",
    "copysign",
    "to_radians",
    "next_up",
    "next_down",
    "mul_add",
    "sqrt",
    "recip",
    "min",
    "max",
    "abs",
    "is_nan",
    "Mat4",
    "Vec3",
    "Vec2",
    "Vec4",
    "DVec3",
    "from_cols_array_2d",
    "from_rotation_x",
    "from_rotation_y",
    "from_rotation_z",
    "from_scale",
    "from_translation",
    "unwrap",
    "todo",
    "panic",
    "assert",
    "assert_eq",
    // The header of a PFM file, which lesson 10 writes.
    "PF",
    // Statements of Wavefront OBJ and MTL files, which lesson 09 reads.
    "vt",
    "vn",
    "mtllib",
    "usemtl",
    "newmtl",
    "map_Kd",
];

/// `text` with its `//` comments removed (strings are kept: a name only in a string
/// still counts, which errs on the side of passing).
fn without_comments(text: &str) -> String {
    text.lines()
        .map(|line| line.find("//").map_or(line, |i| &line[..i]))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The identifiers of `text`, in order, with the character that follows each (after
/// spaces).
fn identifiers(text: &str) -> Vec<(String, Option<char>)> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if chars[i].is_alphabetic() || chars[i] == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            let mut j = i;
            while j < chars.len() && chars[j] == ' ' {
                j += 1;
            }
            out.push((word, chars.get(j).copied()));
        } else {
            i += 1;
        }
    }
    out
}

/// The names `text` defines: items after a keyword, and (when `bindings`) fields,
/// parameters, `let` bindings and enum variants too.
fn declared(text: &str, bindings: bool) -> BTreeSet<String> {
    // `impl Trait for Name` defines behaviour of Name, so "for" counts as an item
    // keyword (a loop's `for x in` adds its variable: more lenient, never wrong).
    const ITEMS: [&str; 9] = [
        "fn", "struct", "enum", "trait", "type", "const", "static", "impl", "for",
    ];
    let words = identifiers(&without_comments(text));
    let mut names = BTreeSet::new();
    for (k, (word, next)) in words.iter().enumerate() {
        let previous = k.checked_sub(1).map(|p| words[p].0.as_str());
        let before = k.checked_sub(2).map(|p| words[p].0.as_str());
        let item =
            previous.is_some_and(|p| ITEMS.contains(&p) || (bindings && p == "mod"));
        let binding = bindings
            && (previous == Some("let")
                || (previous == Some("mut") && before == Some("let"))
                || *next == Some(':')
                || (word.starts_with(char::is_uppercase)
                    && matches!(next, Some('(' | '{' | ','))));
        if item || binding {
            names.insert(word.clone());
        }
    }
    names
}

/// Every name the crate's sources declare, and their file stems (modules).
fn crate_names(root: &Path) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for dir in ["src", "examples", "book/figures/src", "tests", "benches"] {
        for (file, text) in rust_files(root, dir) {
            if let Some(stem) = Path::new(&file).file_stem() {
                names.insert(stem.to_string_lossy().into_owned());
            }
            names.extend(declared(&text, true));
        }
    }
    for entry in fs::read_dir(root.join("src"))
        .into_iter()
        .flatten()
        .flatten()
    {
        if entry.path().is_dir() {
            names.insert(entry.file_name().to_string_lossy().into_owned());
        }
    }
    names
}

/// True for a span that reads as a Rust name or path: `name`, `Type::method`,
/// `module::name()`.
fn is_rust_name(span: &str) -> bool {
    let span = span.strip_suffix("()").unwrap_or(span);
    !span.is_empty()
        && span.split("::").all(|part| {
            part.chars()
                .next()
                .is_some_and(|c| c.is_alphabetic() || c == '_')
                && part.chars().all(|c| c.is_alphanumeric() || c == '_')
        })
}

/// The backticked spans of `line`.
fn code_spans(line: &str) -> Vec<&str> {
    line.split('`').skip(1).step_by(2).collect()
}

/// The lines of `file` between `ANCHOR: name` and `ANCHOR_END: name`.
fn anchored(file: &str, name: &str) -> Option<String> {
    let start = file.find(&format!("ANCHOR: {name}\n"))?;
    let end = file.find(&format!("ANCHOR_END: {name}\n"))?;
    (start < end).then(|| file[start..end].to_string())
}

/// One chapter's problems: `read` gives a file by its path relative to the chapter,
/// `known` holds the crate's names.
fn check_chapter(
    page: &str,
    text: &str,
    read: &dyn Fn(&str) -> Option<String>,
    known: &BTreeSet<String>,
) -> Vec<String> {
    let mut problems = Vec::new();
    let lines: Vec<&str> = text.lines().collect();
    let mut in_code = false;
    for (i, line) in lines.iter().enumerate() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
            continue;
        }
        if in_code {
            continue;
        }
        if let Some(caption) = line.trim().strip_prefix("*Listing: ") {
            check_caption(page, i, caption, &lines[i + 1..], read, &mut problems);
            continue;
        }
        for span in code_spans(line) {
            if !is_rust_name(span) {
                continue;
            }
            let path = span.strip_suffix("()").unwrap_or(span);
            for part in path.split("::") {
                if !known.contains(part) && !FOREIGN.contains(&part) {
                    problems.push(format!(
                        "{page}:{}: `{span}`: no `{part}` in the crate's sources",
                        i + 1
                    ));
                }
            }
        }
    }
    problems
}

/// Checks one caption against the fragment the listing after it includes.
fn check_caption(
    page: &str,
    i: usize,
    caption: &str,
    after: &[&str],
    read: &dyn Fn(&str) -> Option<String>,
    problems: &mut Vec<String>,
) {
    let Some(include) = after.iter().take(4).find_map(|l| {
        let rest = l.trim().strip_prefix("{{#include ")?;
        rest.strip_suffix("}}")
    }) else {
        return; // a caption over a picture or a table: nothing to resolve
    };
    let Some((file, anchor)) = include.rsplit_once(':') else {
        return; // a whole file, or a line range: no fragment to look into
    };
    if anchor.chars().any(|c| c.is_ascii_digit())
        && !anchor.chars().any(char::is_alphabetic)
    {
        return;
    }
    let Some(text) = read(file) else {
        return; // tests/book/includes.rs reports a broken include
    };
    let Some(fragment) = anchored(&text, anchor) else {
        return;
    };
    // What the fragment defines, and the function it is a part of (a listing may
    // show the middle of one, captioned with its name).
    let mut defined = declared(&fragment, false);
    let before = &text[..text.find(&format!("ANCHOR: {anchor}\n")).unwrap_or(0)];
    if let Some((_, rest)) = before.rsplit_once("fn ") {
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        defined.insert(name);
    }
    let spans = code_spans(caption);
    for name in spans
        .iter()
        .skip(1)
        .flat_map(|s| s.split(", "))
        .flat_map(|s| s.split(" and "))
    {
        let last = name
            .strip_suffix("()")
            .unwrap_or(name)
            .rsplit("::")
            .next()
            .unwrap_or(name);
        if is_rust_name(last) && !defined.contains(last) {
            problems.push(format!(
                "{page}:{}: the caption names `{name}`, but {file}:{anchor} defines no `{last}`",
                i + 1
            ));
        }
    }
}

/// The pages `SUMMARY.md` lists.
fn pages(chapters: &Path) -> Vec<String> {
    let summary = fs::read_to_string(chapters.join("SUMMARY.md")).expect("SUMMARY.md");
    summary
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .filter(|p| p.ends_with(".md"))
        .map(str::to_string)
        .collect()
}

#[test]
fn every_name_in_backticks_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let chapters = root.join("chapters");
    let known = crate_names(root);
    let mut problems = Vec::new();
    for page in pages(&chapters) {
        let text = fs::read_to_string(chapters.join(&page)).expect("chapter");
        let read = |file: &str| fs::read_to_string(chapters.join(file)).ok();
        problems.extend(check_chapter(&page, &text, &read, &known));
    }
    assert!(
        problems.is_empty(),
        "{} name(s) in backticks that the code does not have:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn the_name_checker_can_fail() {
    let code = "// ANCHOR: walk\nfn walk() {}\n// ANCHOR_END: walk\n\
                // ANCHOR: traverse\nfn walk_again() {}\n// ANCHOR_END: traverse\n";
    let read = |file: &str| (file == "../src/x.rs").then(|| code.to_string());
    let known: BTreeSet<String> = ["walk", "Bvh", "x"].map(String::from).into();
    let good = "*Listing: `src/x.rs`, `walk`*\n\n```rust\n{{#include ../src/x.rs:walk}}\n```\n\
                `Bvh::walk` and `f32::signum`, `--flag`, `t > 0`.\n";
    assert_eq!(
        check_chapter("good.md", good, &read, &known),
        Vec::<String>::new()
    );
    // A caption that names its anchor instead of the function it shows.
    let caption = "*Listing: `src/x.rs`, `traverse`*\n\n```rust\n{{#include ../src/x.rs:traverse}}\n```\n";
    let found = check_chapter("bad.md", caption, &read, &known);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("defines no `traverse`"), "{found:?}");
    // A sentence that names a function the crate does not have.
    let prose = "The loop calls `edge_function` and `Bvh::walk`.\n";
    let found = check_chapter("bad.md", prose, &read, &known);
    assert_eq!(
        found,
        ["bad.md:1: `edge_function`: no `edge_function` in the crate's sources"]
    );
    // Code blocks are not prose.
    let block = "```text\n`edge_function`\n```\n";
    assert!(check_chapter("ok.md", block, &read, &known).is_empty());
}
