//! Every number the book states in prose is checked (issue 20, part 5a).
//!
//! Every number a page states as a result (see [`is_a_result`]), unless `quotes`
//! pins it to a fragment of lesson 11, must agree, to the digits it prints, with a
//! number of what the page includes, of a test the page names (in backticks or in a
//! `<!-- checked: tests/F.rs::name -->` marker), or of a snapshot such a test
//! asserts (see `sources`). A marker may also name a bench, a source file's function
//! or constant (a scene's numbers), or an anchored table of `BENCHMARKS.md`. The Rust
//! comments a page includes are prose too, checked against the code beside them.
//!
//! A number measured by a run is pinned by the test that measures it; a number a
//! page works out by hand is computed again by its lesson's `lesson_NN_worked_numbers`
//! test. A stale number then fails. The check is necessary, not sufficient: a wrong
//! number that happens to equal another number of the same sources passes.
//!
//! Standard library only.

use crate::common::pages::rust_files;
use crate::markdown;
use crate::printed::{Printed, numbers, printed, supports};
use crate::quotes::{QUOTES, source};
use crate::sources::{Code, included, included_text, snapshot_beside, test_sources};

use markdown::fence;
use std::fs;
use std::path::Path;

// ---------------------------------------------------------------- stated numbers

/// Words after which a number names a thing (a section, an exercise, a version)
/// rather than states a result. Matched in lower case, right before the number.
const NAMING_WORDS: &[&str] = &[
    "exercise ",
    "exercises ",
    "section ",
    "sections ",
    "§",
    "version ",
    "chapter ",
    "lesson ",
    "step ",
    "steps ",
    "figure ",
    "page ",
    "slide ",
    "lecture ",
    "equation ",
    "edition ",
    "ed. ",
    "eq. ",
    "fig. ",
    "recipes ",
];

/// A number a page states in its prose, as printed, and the line it is on.
#[derive(Debug)]
struct Stated {
    line: usize,
    text: String,
    printed: Printed,
    /// Printed with a `%`: a source may hold it as a fraction (20 % as 0.2).
    percent: bool,
}

/// Is this number, printed as `digits` (sign left out), a stated result rather
/// than a count or a parameter too plain to drift? A percentage, a number in
/// scientific notation, a decimal with two significant digits or more, or an
/// integer of four digits or more that is not a year (1900 to 2030, as a citation
/// writes it).
fn is_a_result(digits: &str, percent: bool, scientific: bool) -> bool {
    if percent || scientific {
        return true;
    }
    let plain: String = digits.chars().filter(char::is_ascii_digit).collect();
    if digits.contains('.') {
        return plain.trim_start_matches('0').len() >= 2;
    }
    let year = !digits.contains(' ')
        && plain.len() == 4
        && plain
            .parse::<u32>()
            .is_ok_and(|y| (1900..=2030).contains(&y));
    plain.len() >= 4 && !year
}

/// `line` with what is not prose blanked out: code spans, the targets of links
/// and images, and HTML tags. (Code blocks, include lines and comments are left
/// out by the caller.)
fn prose_of(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut chars = line.chars().peekable();
    let mut skip_until: Option<char> = None;
    let mut previous = ' ';
    while let Some(c) = chars.next() {
        if let Some(end) = skip_until {
            if c == end {
                skip_until = None;
            }
            out.push(' ');
            continue;
        }
        match c {
            '`' => skip_until = Some('`'),
            '(' if previous == ']' => skip_until = Some(')'),
            '<' if chars
                .peek()
                .is_some_and(|n| n.is_ascii_alphabetic() || *n == '/') =>
            {
                skip_until = Some('>')
            }
            _ => {}
        }
        out.push(if skip_until.is_some() { ' ' } else { c });
        previous = c;
    }
    out
}

/// The prose lines of a page (1-based line numbers): code blocks, include lines
/// and HTML comments left out, and each line passed through [`prose_of`].
fn prose_lines(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut fence_open: Option<(char, usize)> = None;
    let mut in_comment = false;
    for (i, line) in text.lines().enumerate() {
        if let Some((c, n, _)) = fence(line) {
            match fence_open {
                None => fence_open = Some((c, n)),
                Some((open, m)) if open == c && n >= m => fence_open = None,
                _ => {}
            }
            continue;
        }
        if fence_open.is_some() || line.contains("{{#") {
            continue;
        }
        let mut kept = String::new();
        let mut rest = line;
        loop {
            if in_comment {
                match rest.find("-->") {
                    Some(end) => {
                        rest = &rest[end + 3..];
                        in_comment = false;
                    }
                    None => break,
                }
            } else {
                match rest.find("<!--") {
                    Some(start) => {
                        kept.push_str(&rest[..start]);
                        rest = &rest[start + 4..];
                        in_comment = true;
                    }
                    None => {
                        kept.push_str(rest);
                        break;
                    }
                }
            }
        }
        out.push((i + 1, prose_of(&kept)));
    }
    out
}

/// Every number the prose of `text` states as a result (see [`is_a_result`]).
fn stated_numbers(text: &str) -> Vec<Stated> {
    let mut out = Vec::new();
    for (line_number, line) in prose_lines(text) {
        // A thin space between digit groups (`13\,300.8`) groups like a space.
        let line = line.replace("\\,", " ");
        let lower = line.to_lowercase();
        let mut i = 0;
        while i < line.len() {
            let rest = &line[i..];
            let before = line[..i].chars().next_back();
            let starts = rest.starts_with(|c: char| c.is_ascii_digit())
                && before
                    .is_none_or(|b| !(b.is_alphanumeric() || b == '.' || b == '_'));
            let parsed = starts.then(|| printed(rest)).flatten();
            let Some((p, after)) = parsed else {
                i += rest.chars().next().map_or(1, char::len_utf8);
                continue;
            };
            let digits = &rest[..rest.len() - after.len()];
            // "exercises 7.1 to 7.3": a naming word before a run of numbers names them
            // all.
            let mut before = lower[..i].trim_end();
            while let Some(rest) = ["to", "and", "or", ","]
                .iter()
                .find_map(|c| before.strip_suffix(c))
            {
                let rest = rest.trim_end();
                let number =
                    rest.trim_end_matches(|c: char| c.is_ascii_digit() || c == '.');
                if number.len() == rest.len() {
                    break;
                }
                before = number.trim_end();
            }
            let before = format!("{before} ");
            let named = NAMING_WORDS
                .iter()
                .any(|w| lower[..i].ends_with(w) || before.ends_with(w));
            let version = after.starts_with('.')
                && after[1..].starts_with(|c: char| c.is_ascii_digit());
            let percent =
                after.trim_start().starts_with('%') || after.starts_with("\\%");
            let scientific = digits.contains('e') || digits.contains("10^");
            if !named && !version && is_a_result(digits, percent, scientific) {
                out.push(Stated {
                    line: line_number,
                    text: digits.trim().to_string(),
                    printed: p,
                    percent,
                });
            }
            i += digits.len().max(1);
        }
    }
    out
}

/// Every number in a source text (code, a snapshot, a fragment), digit
/// separators (`16_384`) removed.
fn source_numbers(text: &str) -> Vec<Printed> {
    let bytes = text.as_bytes();
    let joined: String = text
        .char_indices()
        .filter(|&(k, c)| {
            !(c == '_'
                && k > 0
                && bytes[k - 1].is_ascii_digit()
                && bytes.get(k + 1).is_some_and(u8::is_ascii_digit))
        })
        .map(|(_, c)| c)
        .collect();
    numbers(&joined)
}

/// The numbers a page states that agree with none of its sources: what it
/// includes, the tests it names, and the fragment values [`QUOTES`] pins for it.
fn unsourced(page: &str, text: &str, sources: &str, quoted: &[Printed]) -> Vec<String> {
    unsourced_among(page, text, &known_numbers(sources, quoted))
}

/// The numbers of `sources` and the `quoted` values, without their signs: what a
/// stated number may agree with.
fn known_numbers(sources: &str, quoted: &[Printed]) -> Vec<Printed> {
    source_numbers(sources)
        .into_iter()
        .chain(quoted.iter().copied())
        .map(|p| Printed {
            value: p.value.abs(),
            unit: p.unit,
        })
        .collect()
}

/// [`unsourced`] with the `known` numbers read once (see [`known_numbers`]).
fn unsourced_among(page: &str, text: &str, known: &[Printed]) -> Vec<String> {
    stated_numbers(text)
        .into_iter()
        .filter(|s| {
            let stated = Printed {
                value: s.printed.value.abs(),
                unit: s.printed.unit,
            };
            let fraction = Printed {
                value: stated.value / 100.0,
                unit: stated.unit / 100.0,
            };
            !known
                .iter()
                .any(|&k| supports(k, stated) || (s.percent && supports(k, fraction)))
        })
        .map(|s| format!("{page}:{}: `{}`", s.line, s.text))
        .collect()
}

#[test]
fn every_number_the_book_states_comes_from_a_source() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let chapters = root.join("chapters");
    let read = |rel: &str| fs::read_to_string(chapters.join(rel)).ok();
    let mut code = Vec::new();
    for dir in ["tests", "benches", "src", "examples"] {
        code.extend(rust_files(root, dir));
    }
    // The measurements of `cargo bench`, by their anchors.
    let benchmarks = fs::read_to_string(root.join("BENCHMARKS.md")).unwrap_or_default();
    code.push(("BENCHMARKS.md".to_string(), benchmarks));
    let index = Code::new(&code);
    let snapshot = |path: &str| fs::read_to_string(root.join(path)).ok();
    let summary = read("SUMMARY.md").expect("SUMMARY.md");
    let mut problems = Vec::new();
    for page in summary
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .filter(|p| p.ends_with(".md"))
    {
        let text = read(page).expect("a page SUMMARY.md lists");
        // A quote's value, and the row it is read from (the `3e3` of "at
        // $3\cdot 10^3$, 1.7 %").
        let quoted: Vec<Printed> = QUOTES
            .iter()
            .filter(|q| q.chapter == page)
            .flat_map(|q| {
                let value = read(q.fragment).and_then(|f| source(q, &f).ok());
                value.into_iter().chain(numbers(q.cell.0))
            })
            .collect();
        let includes = included(&text, &read);
        let tests = test_sources(&text, &index, &snapshot);
        let code_included: String = includes.iter().map(|i| i.code.as_str()).collect();
        let sources = code_included.clone() + &tests;
        let everything = sources.clone()
            + &includes
                .iter()
                .map(|i| i.comments.as_str())
                .collect::<String>();
        problems.extend(unsourced(page, &text, &everything, &quoted));
        // The doc comments a page includes are prose too: their numbers come from
        // the code beside them, the page's other includes or its tests.
        let known = known_numbers(&sources, &quoted);
        for include in &includes {
            let label = format!("{page}, the comments of {}, line", include.args);
            problems.extend(unsourced_among(&label, &include.comments, &known));
        }
    }
    assert!(
        problems.is_empty(),
        "{} number(s) stated in the book agree with nothing the page includes, no test \
         it names and no quote of QUOTES: include the number, name the test that checks \
         it (in backticks or <!-- checked: tests/F.rs::name -->), or correct it:\n  {}",
        problems.len(),
        problems.join("\n  ")
    );
}

#[test]
fn the_stated_number_checker_reads_prose_and_can_fail() {
    // What counts as a stated result.
    let found = |text: &str| -> Vec<String> {
        stated_numbers(text).into_iter().map(|s| s.text).collect()
    };
    assert_eq!(
        found(
            "A sphere at $t = 2.134$, 28 % of 16 384 rays, $1.2\\cdot 10^{-7}$ off, 1e-4."
        ),
        vec!["2.134", "28", "16 384", "1.2\\cdot 10^{-7}", "1e-4"]
    );
    assert_eq!(
        found(
            "Radius 0.5, Pharr (2016), exercises 7.1 to 7.3, S13, pbrt-v4 6.8.4, `0.866`."
        ),
        Vec::<String>::new(),
        "parameters, years, names, versions and code are no stated results"
    );
    assert_eq!(
        found(
            "```text\n2.134\n```\n<!-- 2.134 -->\n{{#include f.md:a}} 2.134\n[link](x/2.134.md)"
        ),
        Vec::<String>::new()
    );
    assert_eq!(found("$r^2 = 13\\,300.8$"), vec!["13 300.8"]);
    let percent = stated_numbers("within 20 % of it");
    assert!(percent[0].percent && percent[0].printed.value == 20.0);

    // Sources: an included region, a named test's body and the snapshot it asserts.
    let fragment = "<!-- ANCHOR: a -->\nt = 2.1340\n<!-- ANCHOR_END: a -->\nt = 9.75\n";
    let read = |rel: &str| (rel == "f.md").then(|| fragment.to_string());
    let tests = vec![(
        "tests/07_x.rs".to_string(),
        "#[test]\nfn pins_it() {\n    assert_eq!(n, 16_384);\n    insta::assert_snapshot!(\"numbers\", s);\n}\nfn other() { let x = 0.0145; }\n".to_string(),
    )];
    let snapshot = |path: &str| {
        (path == "tests/snapshots/07_x__numbers.snap")
            .then(|| "sigma 0.101".to_string())
    };
    let check = |page: &str| {
        let sources = included_text(page, &read)
            + &test_sources(page, &Code::new(&tests), &snapshot);
        unsourced("p.md", page, &sources, &[])
    };
    let good = "{{#include f.md:a}}\n\nHits at $t = 2.134$ (2.13), sigma 0.101 of\n16 384 rays.\n\n\
                - `pins_it`: the numbers.\n";
    assert_eq!(check(good), Vec::<String>::new());
    // A stale number, one outside the included region, one only an unnamed fn holds,
    // and one printed more finely than its source.
    let bad = "{{#include f.md:a}}\n\nHits at $t = 2.135$, 9.75, 0.0145, 16 384.\n\n\
               - `pins_it`: sigma 0.1012.\n";
    assert_eq!(
        check(bad),
        vec![
            "p.md:3: `2.135`",
            "p.md:3: `9.75`",
            "p.md:3: `0.0145`",
            "p.md:5: `0.1012`"
        ]
    );
    // `1e4` in code does not support a stated 5008; the marker names a test too.
    let marker = "5008 rays.\n<!-- checked: tests/07_x.rs::pins_it -->\n";
    let sources = "let x = 1e4;".to_string()
        + &test_sources(marker, &Code::new(&tests), &snapshot);
    assert_eq!(
        unsourced("p.md", marker, &sources, &[]),
        vec!["p.md:1: `5008`"]
    );
    // Where insta keeps a test's snapshots: beside its file, named by module path.
    assert_eq!(
        snapshot_beside("tests/lessons/lesson_07_intersections.rs", "numbers"),
        "tests/lessons/snapshots/lessons__lesson_07_intersections__numbers.snap"
    );
    assert_eq!(
        snapshot_beside("tests/lessons/main.rs", "a"),
        "tests/lessons/snapshots/lessons__a.snap"
    );
    assert_eq!(
        snapshot_beside("src/course/report.rs", "a"),
        "src/course/snapshots/render_lessons__course__report__a.snap"
    );
}
