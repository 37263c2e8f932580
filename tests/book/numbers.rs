//! Every number the book states in prose is checked (issue 20, part 5a).
//!
//! Two checks live here:
//!
//! * **quotes**: a sentence that cannot include a whole table quotes one of its
//!   numbers by hand; [`QUOTES`] pins each such number to the fragment lesson 11
//!   writes, rounded as the chapter prints it;
//! * **stated numbers**: every other number a page states as a result (see
//!   [`is_a_result`]) must agree, to the digits it prints, with a number of what the
//!   page includes, of a test the page names (in backticks or in a
//!   `<!-- checked: tests/F.rs::name -->` marker), or of a snapshot such a test
//!   asserts. A marker may also name a bench, a source file's function or
//!   constant (a scene's numbers), or an anchored table of `BENCHMARKS.md`. The Rust
//!   comments a page includes are prose too, checked against the code beside them.
//!
//! A number measured by a run is pinned by the test that measures it; a number a
//! page works out by hand is computed again by its lesson's `lesson_NN_worked_numbers`
//! test. A stale number then fails. The check is necessary, not sufficient: a wrong
//! number that happens to equal another number of the same sources passes.
//!
//! Standard library only.

use crate::markdown;

use markdown::fence;
use std::fs;
use std::path::Path;

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
const MT: &str = "Möller-Trumbore";
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
        let power = rest
            .strip_prefix("\\cdot 10^")
            .or_else(|| rest.strip_prefix("\\cdot10^"));
        // `10^{-5}`, or `10^8` with a single digit.
        power.map(|r| r.strip_prefix('{').map_or((r, "\u{0}"), |r| (r, "}")))
    };
    let mut rest = rest;
    if let Some((r, close)) = exp_text {
        let single = close == "\u{0}";
        let end = r
            .char_indices()
            .find(|&(k, c)| !(c.is_ascii_digit() || (k == 0 && c == '-')) || (single && k == 1))
            .map_or(r.len(), |(k, _)| k);
        let close = if single { "" } else { close };
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
            Ok(source) if !supports(source, number) => problems.push(format!(
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
         chapters/figures`; fix the sentence, or the quote in tests/book/numbers.rs)",
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
    assert_eq!(p("1.3\\cdot 10^8$").map(|x| x.value), Some(1.3e8));
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
    // supports(source, stated)
    assert!(supports(p("4.96").unwrap(), p("5.0").unwrap()));
    assert!(!supports(p("4.96").unwrap(), p("5.1").unwrap()));
    assert!(supports(
        p("3.76e-5").unwrap(),
        p("3.8\\cdot 10^{-5}").unwrap()
    ));
    assert!(!supports(
        p("3.76e-5").unwrap(),
        p("3.7\\cdot 10^{-5}").unwrap()
    ));
    // The same digits must be equal: a count off by one, or a last digit off by one.
    assert!(!supports(p("2797").unwrap(), p("2798").unwrap()));
    assert!(!supports(
        p("2.0e-2").unwrap(),
        p("1.9\\cdot 10^{-2}").unwrap()
    ));
    // A coarser source supports nothing finer.
    assert!(!supports(p("1e4").unwrap(), p("10000.5").unwrap()));

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
                && before.is_none_or(|b| !(b.is_alphanumeric() || b == '.' || b == '_'));
            let parsed = starts.then(|| printed(rest)).flatten();
            let Some((p, after)) = parsed else {
                i += rest.chars().next().map_or(1, char::len_utf8);
                continue;
            };
            let digits = &rest[..rest.len() - after.len()];
            // "exercises 7.1 to 7.3": a naming word before a run of numbers names them all.
            let mut before = lower[..i].trim_end();
            while let Some(rest) = ["to", "and", "or", ","]
                .iter()
                .find_map(|c| before.strip_suffix(c))
            {
                let rest = rest.trim_end();
                let number = rest.trim_end_matches(|c: char| c.is_ascii_digit() || c == '.');
                if number.len() == rest.len() {
                    break;
                }
                before = number.trim_end();
            }
            let before = format!("{before} ");
            let named = NAMING_WORDS
                .iter()
                .any(|w| lower[..i].ends_with(w) || before.ends_with(w));
            let version =
                after.starts_with('.') && after[1..].starts_with(|c: char| c.is_ascii_digit());
            let percent = after.trim_start().starts_with('%') || after.starts_with("\\%");
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

/// The body of `fn name(` in a Rust file, braces matched, or a `const name` up to
/// its `;` (a bench's image size, a chart's distances), or `None`.
fn function_body<'a>(code: &'a str, name: &str) -> Option<&'a str> {
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
fn named_functions(text: &str) -> Vec<(Option<String>, String)> {
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
            if !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
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

/// Where insta keeps the snapshot `name` asserted in the Rust file `path` (relative
/// to the root): `snapshots/` beside the file, named after the file's module path
/// (`tests/lessons/lesson_07_intersections.rs`, `numbers` ->
/// `tests/lessons/snapshots/lessons__lesson_07_intersections__numbers.snap`; a file of
/// `src/` is a module of `render_lessons`).
fn snapshot_path(path: &str, name: &str) -> String {
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

/// What a page's numbers may come from in code: the body of each function it
/// names (see [`named_functions`]) and the snapshots that body asserts. `code`
/// holds (path, text) for every Rust file of the project; `snapshot`
/// reads a snapshot by its path (see [`snapshot_path`]).
fn test_sources(
    text: &str,
    code: &[(String, String)],
    snapshot: &dyn Fn(&str) -> Option<String>,
) -> String {
    let mut out = String::new();
    for (file, name) in named_functions(text) {
        for (path, source) in code {
            let wanted = match &file {
                Some(f) => f == path,
                None => path.starts_with("tests/"),
            };
            let region = if path.ends_with(".md") {
                anchored_lines(source, &name).map(|lines| lines.join("\n"))
            } else {
                function_body(source, &name).map(str::to_string)
            };
            let Some(body) = region.filter(|_| wanted) else {
                continue;
            };
            out.push_str(&body);
            for call in body.split("assert_snapshot!(").skip(1) {
                let quoted = call.trim_start().strip_prefix('"');
                if let Some(snap) = quoted.and_then(|q| q.split('"').next())
                    && let Some(s) = snapshot(&snapshot_path(path, snap))
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
struct Included {
    args: String,
    code: String,
    comments: String,
}

/// The includes of a page, read by `read` relative to `chapters/`.
fn included(text: &str, read: &dyn Fn(&str) -> Option<String>) -> Vec<Included> {
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
fn included_text(text: &str, read: &dyn Fn(&str) -> Option<String>) -> String {
    included(text, read)
        .into_iter()
        .map(|i| i.code + &i.comments)
        .collect()
}

/// Does a source's number support a stated one? They agree, each rounded as
/// printed, and the source is printed at least as finely as the statement: `1e4`
/// in code does not support a stated 5008.
///
/// Printed to the same digits, they must be equal: 2797 does not support 2798. A
/// finer source may itself be rounded from the value the page rounds, so it gets
/// half its own unit more (a snapshot's 2.165 of 2.1649 supports a stated 2.16).
fn supports(source: Printed, stated: Printed) -> bool {
    let finer = if source.unit < stated.unit {
        0.5 * source.unit
    } else {
        0.0
    };
    let slack = 0.5 * stated.unit + finer;
    (source.value - stated.value).abs() <= slack * (1.0 + 1e-9)
}

/// The numbers a page states that agree with none of its sources: what it
/// includes, the tests it names, and the fragment values [`QUOTES`] pins for it.
fn unsourced(page: &str, text: &str, sources: &str, quoted: &[Printed]) -> Vec<String> {
    let known: Vec<Printed> = source_numbers(sources)
        .into_iter()
        .chain(quoted.iter().copied())
        .map(|p| Printed {
            value: p.value.abs(),
            unit: p.unit,
        })
        .collect();
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

/// Every `.rs` file under `root/dir`, as (path relative to `root`, text).
fn rust_files(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
    let Ok(entries) = fs::read_dir(root.join(dir)) else {
        return;
    };
    let mut paths: Vec<_> = entries.flatten().map(|e| e.path()).collect();
    paths.sort();
    for path in paths {
        let relative = dir.join(path.file_name().unwrap_or_default());
        if path.is_dir() {
            rust_files(root, &relative, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = fs::read_to_string(&path).unwrap_or_default();
            out.push((relative.to_string_lossy().replace('\\', "/"), text));
        }
    }
}

#[test]
fn every_number_the_book_states_comes_from_a_source() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let chapters = root.join("chapters");
    let read = |rel: &str| fs::read_to_string(chapters.join(rel)).ok();
    let mut code = Vec::new();
    for dir in ["tests", "benches", "src", "examples"] {
        rust_files(root, Path::new(dir), &mut code);
    }
    // The measurements of `cargo bench`, by their anchors.
    let benchmarks = fs::read_to_string(root.join("BENCHMARKS.md")).unwrap_or_default();
    code.push(("BENCHMARKS.md".to_string(), benchmarks));
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
        let tests = test_sources(&text, &code, &snapshot);
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
        for include in &includes {
            let label = format!("{page}, the comments of {}, line", include.args);
            problems.extend(unsourced(&label, &include.comments, &sources, &quoted));
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
    let found =
        |text: &str| -> Vec<String> { stated_numbers(text).into_iter().map(|s| s.text).collect() };
    assert_eq!(
        found("A sphere at $t = 2.134$, 28 % of 16 384 rays, $1.2\\cdot 10^{-7}$ off, 1e-4."),
        vec!["2.134", "28", "16 384", "1.2\\cdot 10^{-7}", "1e-4"]
    );
    assert_eq!(
        found("Radius 0.5, Pharr (2016), exercises 7.1 to 7.3, S13, pbrt-v4 6.8.4, `0.866`."),
        Vec::<String>::new(),
        "parameters, years, names, versions and code are no stated results"
    );
    assert_eq!(
        found("```text\n2.134\n```\n<!-- 2.134 -->\n{{#include f.md:a}} 2.134\n[link](x/2.134.md)"),
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
        (path == "tests/snapshots/07_x__numbers.snap").then(|| "sigma 0.101".to_string())
    };
    let check = |page: &str| {
        let sources = included_text(page, &read) + &test_sources(page, &tests, &snapshot);
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
    let sources = "let x = 1e4;".to_string() + &test_sources(marker, &tests, &snapshot);
    assert_eq!(
        unsourced("p.md", marker, &sources, &[]),
        vec!["p.md:1: `5008`"]
    );
    // Where insta keeps a test's snapshots: beside its file, named by module path.
    assert_eq!(
        snapshot_path("tests/lessons/lesson_07_intersections.rs", "numbers"),
        "tests/lessons/snapshots/lessons__lesson_07_intersections__numbers.snap"
    );
    assert_eq!(
        snapshot_path("tests/lessons/main.rs", "a"),
        "tests/lessons/snapshots/lessons__a.snap"
    );
    assert_eq!(
        snapshot_path("src/course/report.rs", "a"),
        "src/course/snapshots/render_lessons__course__report__a.snap"
    );
}
