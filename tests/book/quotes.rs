//! Numbers the book quotes by hand from lesson 11's fragments are the fragments'
//! (issue 20, part 5a): a sentence that cannot include a whole table quotes one of its
//! numbers; [`QUOTES`] pins each such number to the fragment lesson 11 writes
//! (`chapters/figures/11_N_name.md`), rounded as the chapter prints it. And lesson
//! 11's times are included, never typed.
//!
//! Standard library only.

use crate::markdown;
use crate::printed::{Printed, anchored_lines, cells, numbers, printed, supports};

use markdown::fence;
use std::fs;
use std::path::Path;

/// A number a chapter prints inside a sentence, and the fragment that holds it:
/// lesson 11 writes the numbers the book quotes to `chapters/figures/11_N_name.md`
/// (tables and single values between mdBook anchors), and a sentence that cannot
/// include a whole table quotes the number by hand. This pins each such number to
/// its source: the chapter's number must equal the fragment's, rounded as the
/// chapter prints it.
pub(crate) struct Quote {
    /// The chapter, under `chapters/`.
    pub(crate) chapter: &'static str,
    /// The text around the number, `{}` standing for it (e.g. `"**{} %** at"`).
    pub(crate) context: &'static str,
    /// The fragment, under `chapters/`.
    pub(crate) fragment: &'static str,
    /// The table's or value's anchor in the fragment.
    pub(crate) anchor: &'static str,
    /// The table row's first cell, and the column's header ("" for a value).
    pub(crate) cell: (&'static str, &'static str),
    /// Which number of the cell (a cell such as "12 (4.96%)" holds two).
    pub(crate) index: usize,
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
pub(crate) const QUOTES: &[Quote] = &[
    // S1, chart 1: lesson 07, "Where methods fail", lesson 11.
    quote(CH07_1, "textbook's $t$ is off by ${}$", S1, "accuracy", ("1e3", TB), 0),
    quote(CH07_1, "$D/r = 3\\cdot 10^3$, **{} %**", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(CH07_1, "at $D/r = 10^4$ **{} %**", S1, "accuracy", ("1e4", TB_WRONG), 0),
    value(CH07_1, "largest mean relative error, ${}$", S1, "stable_f32_max"),
    quote(ROOTS, "${}$ of $t$ on average", S1, "accuracy", ("1e3", TB), 0),
    quote(ROOTS, "at $3\\cdot 10^3$ **{} %**", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(ROOTS, "$10^4$ **{} %**: at ten", S1, "accuracy", ("1e4", TB_WRONG), 0),
    value(ROOTS, "relative error of ${}$, the rounding", S1, "stable_f32_max"),
    quote(FAIL, "$10^4$ | {} %, ", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(FAIL, ", {} % wrong | 0 %, 0 %", S1, "accuracy", ("1e4", TB_WRONG), 0),
    quote(CH11, "grows with $D/r$: ${}$ at", S1, "accuracy", ("1e3", TB), 0),
    quote(CH11, "falls apart: {} % of the rays", S1, "accuracy", ("3e3", TB_WRONG), 0),
    quote(CH11, "$3\\cdot 10^3$, {} % at $10^4$", S1, "accuracy", ("1e4", TB_WRONG), 0),
    value(CH11, "relative error is ${}$", S1, "stable_f32_max"),
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

/// The number `quote` names in the fragment's text, or why it cannot be found.
pub(crate) fn source(quote: &Quote, fragment: &str) -> Result<Printed, String> {
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
fn check_quotes(
    read: &dyn Fn(&str) -> Option<String>,
    quotes: &[Quote],
) -> Vec<String> {
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
    let chapter =
        "Leaks **12** rays (5.0 %), off by $3.8\\cdot 10^{-5}$, at most 7e-8.";
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
                || !joined.as_bytes()[joined.len() - rest.len() - 1]
                    .is_ascii_alphanumeric();
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
        typed_times(
            "It takes 7.1 ns, or 2.14 million rays\nper second.\n\n```\n3 ns\n```\n"
        ),
        vec!["7.1 ns", "2.14 million"]
    );
    assert!(typed_times("With `cargo bench`, 28.2 ns.").is_empty());
    assert!(
        typed_times("{{#include figures/11_7_scaling.md:bvh_mrays}} million")
            .is_empty()
    );
}
