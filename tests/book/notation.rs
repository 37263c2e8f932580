//! The book's words, checked against their
//! sources (issue 15): the glossary page, the notation table of the introduction,
//! terms defined before they are used, and the pipeline stages as the slides list
//! them. The numbers the early chapters quote are checked in `early_numbers`.
//!
//! Standard library, glam and the crate only; the chapters are read as text.

use crate::common::pages::page as chapter;
use std::collections::HashSet;

// ---- reading the book ----------------------------------------------------------

/// The pages of `SUMMARY.md`, in the order of the book.
pub(crate) fn summary_pages() -> Vec<String> {
    let summary = chapter("SUMMARY.md");
    let mut pages = Vec::new();
    let mut rest = summary.as_str();
    while let Some(i) = rest.find("](") {
        let after = &rest[i + 2..];
        let end = after.find(')').expect("a link in SUMMARY.md is closed");
        let target = after[..end].trim();
        if target.ends_with(".md") && !pages.iter().any(|p| p == target) {
            pages.push(target.to_string());
        }
        rest = &after[end..];
    }
    pages
}

/// Lower case, every run of white space one space: so a phrase may break across lines.
pub(crate) fn flat(text: &str) -> String {
    text.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .to_lowercase()
}

pub(crate) fn assert_says(file: &str, phrase: &str) {
    assert!(
        flat(&chapter(file)).contains(&flat(phrase)),
        "{file} should say `{phrase}`"
    );
}

/// The line of `text` that starts with `start`.
pub(crate) fn line_starting<'a>(text: &'a str, start: &str) -> &'a str {
    text.lines()
        .find(|l| l.starts_with(start))
        .unwrap_or_else(|| panic!("no line starts with `{start}`"))
}

/// The columns of a table row printed with two or more spaces between columns.
pub(crate) fn columns(row: &str) -> Vec<&str> {
    row.split("  ")
        .map(str::trim)
        .filter(|c| !c.is_empty())
        .collect()
}

/// The cell in column `column` of the row whose first column is `name`.
pub(crate) fn cell<'a>(text: &'a str, name: &str, column: usize) -> &'a str {
    let row = text
        .lines()
        .find(|l| columns(l).first() == Some(&name))
        .unwrap_or_else(|| panic!("no row `{name}`"));
    columns(row)[column]
}

// ---- the glossary --------------------------------------------------------------

struct Entry {
    id: String,
    term: String,
    abbreviation: Option<String>,
    definition: String,
    page: String,
}

/// `- <a id="ID"></a>**TERM** (ABBREVIATION): DEFINITION *Introduced in*
/// [TITLE](PAGE).`
fn glossary() -> Vec<Entry> {
    let text = chapter("glossary.md");
    let mut entries = Vec::new();
    for line in text.lines().filter(|l| l.starts_with("- ")) {
        let rest = line.strip_prefix("- <a id=\"").unwrap_or_else(|| {
            panic!("a glossary item starts with its anchor: {line}")
        });
        let (id, rest) = rest
            .split_once("\"></a>**")
            .expect("anchor, then the bold term");
        let (term, rest) = rest.split_once("**").expect("the term is bold");
        let (abbreviation, rest) = match rest.strip_prefix(" (") {
            Some(r) => {
                let (a, r) = r.split_once(')').expect("a closed bracket");
                (Some(a.to_string()), r)
            }
            None => (None, rest),
        };
        let rest = rest.strip_prefix(": ").expect("`: ` after the term");
        let (definition, link) = rest
            .split_once(" *Introduced in* [")
            .unwrap_or_else(|| panic!("`{term}` names the page that introduces it"));
        let page = link
            .split_once("](")
            .and_then(|(_, p)| p.strip_suffix(")."))
            .unwrap_or_else(|| {
                panic!("`{term}`: one link to a page, then a full stop")
            });
        entries.push(Entry {
            id: id.to_string(),
            term: term.to_string(),
            abbreviation,
            definition: definition.to_string(),
            page: page.to_string(),
        });
    }
    entries
}

/// The anchor a term gets: lower case, every other character a hyphen.
fn slug(text: &str) -> String {
    let mut out = String::new();
    for c in text.replace('ö', "o").to_lowercase().chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c);
        } else if !out.is_empty() && !out.ends_with('-') {
            out.push('-');
        }
    }
    out.trim_end_matches('-').to_string()
}

/// How a term is sorted and compared: no TeX, no umlaut, lower case.
fn key(term: &str) -> String {
    term.replace(['$', '\\'], "")
        .replace('ö', "o")
        .to_lowercase()
}

#[test]
fn the_glossary_is_the_last_page_and_the_introduction_points_to_it() {
    let pages = summary_pages();
    assert_eq!(pages.last().map(String::as_str), Some("glossary.md"));
    assert!(chapter("intro.md").contains("](glossary.md)"));
}

#[test]
fn every_glossary_term_is_defined_once_in_alphabetical_order() {
    let entries = glossary();
    assert!(entries.len() >= 60, "only {} terms", entries.len());
    let mut ids = HashSet::new();
    let mut terms = HashSet::new();
    for e in &entries {
        assert!(ids.insert(e.id.clone()), "anchor `{}` twice", e.id);
        assert!(terms.insert(key(&e.term)), "`{}` defined twice", e.term);
        let ok = e.id == slug(&key(&e.term))
            || Some(e.id.clone()) == e.abbreviation.as_deref().map(slug);
        assert!(ok, "`{}` has the anchor `{}`", e.term, e.id);
        assert!(
            e.definition.split_whitespace().count() >= 5 && e.definition.ends_with('.'),
            "`{}` needs a one-line definition",
            e.term
        );
    }
    for pair in entries.windows(2) {
        assert!(
            key(&pair[0].term) < key(&pair[1].term),
            "`{}` should come after `{}`",
            pair[0].term,
            pair[1].term
        );
    }
}

#[test]
fn every_glossary_term_names_a_page_of_the_book_that_uses_it() {
    let pages = summary_pages();
    for e in glossary() {
        assert!(
            pages.contains(&e.page),
            "`{}`: {} is not in SUMMARY.md",
            e.term,
            e.page
        );
        let text = flat(&chapter(&e.page));
        let named = text.contains(&flat(&e.term.replace('$', "")))
            || e.abbreviation
                .as_ref()
                .is_some_and(|a| text.contains(&flat(a)));
        assert!(named, "{} does not mention `{}`", e.page, e.term);
    }
}

#[test]
fn the_glossary_has_the_terms_the_issue_asks_for() {
    let terms: HashSet<String> = glossary()
        .iter()
        .flat_map(|e| [Some(key(&e.term)), e.abbreviation.as_deref().map(key)])
        .flatten()
        .collect();
    for wanted in [
        "texel",
        "bsdf",
        "brdf",
        "whitted ray tracing",
        "ray casting",
        "path tracing",
        "radiance",
        "irradiance",
        "pdf",
        "estimator",
        "variance",
        "nee",
        "mis",
        "sah",
        "bvh",
        "ulp",
        "gamma_n",
        "watertight",
        "shadow acne",
        "shadow map",
        "z-buffer",
        "homogeneous coordinates",
        "srgb",
        "linear rgb",
        "clamping",
    ] {
        assert!(terms.contains(wanted), "the glossary lacks `{wanted}`");
    }
}

// ---- the notation table --------------------------------------------------------

/// The first column of the table in the introduction's "## Notation" section.
fn notation_symbols() -> Vec<String> {
    let intro = chapter("intro.md");
    let section = intro
        .split("\n## Notation\n")
        .nth(1)
        .expect("the introduction has a Notation section");
    let section = section.split("\n## ").next().unwrap();
    section
        .lines()
        .filter(|l| l.starts_with("| $"))
        .map(|l| l.split('|').nth(1).unwrap().trim().to_string())
        .collect()
}

#[test]
fn the_notation_table_lists_each_symbol_once() {
    let rows = notation_symbols();
    assert!(rows.len() >= 30, "only {} rows", rows.len());
    let mut seen = HashSet::new();
    for row in &rows {
        // One row may name a family ($n, f$; $L$; $L_o$, ...): each member counts.
        for symbol in row.replace('$', "").split([',', ';']) {
            let symbol = symbol.trim().to_string();
            assert!(seen.insert(symbol.clone()), "`{symbol}` is listed twice");
        }
    }
    // The symbols the issue found used twice, each now with one meaning, and the
    // names agreed for lessons 07 and 10.
    for wanted in [
        "s",
        "\\mathbf{s}",
        "f",
        "z_f",
        "\\mathbf{T}",
        "k",
        "\\beta",
        "\\mathbf{k}",
        "Q_{ij}",
        "L_e",
        "f_r",
        "\\mathbf{u}",
        "\\mathbf{w}",
        "t",
        "\\mathbf{o}",
        "\\mathbf{d}",
        "\\mathbf{n}",
        "\\mathbf{p}",
    ] {
        assert!(seen.contains(wanted), "the notation table lacks `{wanted}`");
    }
    let intro = flat(&chapter("intro.md"));
    assert!(intro.contains("| $\\beta$ | the path throughput"));
    assert!(intro.contains("**every index starts at 0**"));
    assert!(intro.contains("from $q_{00}$ to $q_{33}$ (lesson 07's quadrics)"));
    assert!(intro.contains(
        "the power heuristic's exponent has no letter: it is written as the number 2"
    ));
}

/// Pages before lesson 10 use none of the symbols lesson 10 keeps for itself.
#[test]
fn lessons_before_10_leave_beta_and_z_f_to_lesson_10() {
    let pages = summary_pages();
    let first_10 = pages.iter().position(|p| p.starts_with("10_")).unwrap();
    for page in &pages[1..first_10] {
        let text = chapter(page);
        for symbol in ["\\beta", "z_f"] {
            assert!(!text.contains(symbol), "{page} uses `{symbol}`");
        }
    }
}

// ---- terms before their definitions ----------------------------------------------

/// Where `text` first mentions `term` as a word (letters or digits on neither side,
/// but a plural `s` allowed).
fn first_mention(text: &str, term: &str) -> Option<usize> {
    let lower = text.to_lowercase();
    let term = term.to_lowercase();
    let mut from = 0;
    while let Some(i) = lower[from..].find(&term) {
        let at = from + i;
        let before = lower[..at].chars().next_back();
        let rest = &lower[at + term.len()..];
        let after = rest.strip_prefix('s').unwrap_or(rest).chars().next();
        let letter = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric());
        if !letter(before) && !letter(after) {
            return Some(at);
        }
        from = at + term.len();
    }
    None
}

/// The paragraph (text between blank lines) around byte `at`, headings left out.
fn paragraph(text: &str, at: usize) -> &str {
    let start = text[..at].rfind("\n\n").map_or(0, |i| i + 2);
    let end = text[at..].find("\n\n").map_or(text.len(), |i| at + i);
    &text[start..end]
}

#[test]
fn texel_bsdf_and_whitted_are_defined_where_the_book_first_uses_them() {
    let pages: Vec<String> = summary_pages()
        .into_iter()
        .filter(|p| p != "glossary.md")
        .collect();
    for (term, anchor) in [
        ("texel", "texel"),
        ("BSDF", "bsdf"),
        ("Whitted", "whitted-ray-tracing"),
    ] {
        let (page, text) = pages
            .iter()
            .map(|p| (p, chapter(p)))
            .find(|(_, t)| {
                // Headings name a term; the definition is in the text under them.
                let body: String = t
                    .lines()
                    .map(|l| if l.starts_with('#') { "" } else { l })
                    .collect::<Vec<_>>()
                    .join("\n");
                first_mention(&body, term).is_some()
            })
            .unwrap_or_else(|| panic!("no page uses `{term}`"));
        let body: String = text
            .lines()
            .map(|l| if l.starts_with('#') { "" } else { l })
            .collect::<Vec<_>>()
            .join("\n");
        let at = first_mention(&body, term).unwrap();
        let around = paragraph(&body, at).to_lowercase();
        let bold = around.contains(&format!("**{}", term.to_lowercase()));
        let linked = around.contains(&format!("glossary.md#{anchor}"));
        assert!(
            bold || linked,
            "{page} is the first page to use `{term}`: define it there (in bold) or link the \
             glossary (glossary.md#{anchor}); the paragraph is:\n{around}"
        );
    }
}

#[test]
fn the_stability_cases_are_introduced_before_lesson_04_uses_them() {
    let intro = chapter("intro.md");
    assert!(flat(&intro).contains("**s1** to **s20** are the *stability cases*"));
    for page in [
        "where_methods_fail.md",
        "where_methods_fail_roots.md",
        "where_methods_fail_triangles.md",
        "where_methods_fail_cameras.md",
        "where_methods_fail_offsets.md",
        "where_methods_fail_monte_carlo.md",
    ] {
        assert!(
            intro.contains(&format!("]({page})")),
            "the intro links {page}"
        );
    }
    let pages = summary_pages();
    let first = pages
        .iter()
        .find(|p| {
            let t = chapter(p);
            (1..=20).any(|n| first_mention(&t, &format!("S{n}")).is_some())
        })
        .unwrap();
    assert_eq!(
        first, "intro.md",
        "the S-numbering is explained before its first use"
    );
}

// ---- the pipeline of Lecture 2 -------------------------------------------------

/// The bold names of a numbered list `1. **Name**...` in the section after `heading`.
fn numbered_bold(text: &str, heading: &str) -> Vec<String> {
    let section = text.split(heading).nth(1).expect("the heading is there");
    let mut names = Vec::new();
    for line in section.lines() {
        if line.starts_with("#") && !names.is_empty() {
            break;
        }
        let Some((number, rest)) = line.split_once(". **") else {
            continue;
        };
        if number.parse::<u32>().is_ok() {
            let name = rest.split_once("**").unwrap().0;
            names.push(name.trim_end_matches('.').to_string());
        }
    }
    names
}

#[test]
fn the_introduction_and_lesson_09_list_the_slides_four_pipeline_stages() {
    // Lecture 2's slides, in order: Modeling, Transform, Lighting, Primitive
    // rasterization.
    let slides = [
        "Modeling",
        "Transform",
        "Lighting",
        "Primitive rasterization",
    ];
    assert_eq!(
        numbered_bold(&chapter("intro.md"), "### The rasterization pipeline"),
        slides
    );
    assert_eq!(
        numbered_bold(&chapter("09_rasterization.md"), "## The idea"),
        slides
    );
    assert_says(
        "09_rasterization.md",
        "Lecture 2 draws this as a pipeline of four stages",
    );
}
