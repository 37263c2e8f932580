//! The pages of lessons 07 and 10 link a stability case's section of *Where methods
//! fail* where they first name it (S1 to S20), with mdBook's heading ids.

use crate::common::pages::page;

// ---------------------------------------------------------------- the pages' links

/// The pages of lessons 07 and 10 this file checks for links to the stability cases.
const CASE_PAGES: [&str; 14] = [
    "07_intersections.md",
    "07_2_plane.md",
    "07_5_quadrics.md",
    "07_6_instances.md",
    "07_7_exercises.md",
    "10_path_tracing.md",
    "10_1_monte_carlo.md",
    "10_2_naive.md",
    "10_3_cosine.md",
    "10_4_roulette.md",
    "10_5_next_event.md",
    "10_6_mis.md",
    "10_7_mirror_glass.md",
    "10_8_thin_lens.md",
];

/// The stability cases a text names: `S` and a number, not inside a word.
fn case_numbers(text: &str) -> Vec<u32> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    for (i, _) in text.match_indices('S') {
        if i > 0 && bytes[i - 1].is_ascii_alphanumeric() {
            continue;
        }
        let digits: String = text[i + 1..]
            .chars()
            .take_while(char::is_ascii_digit)
            .collect();
        let next = text[i + 1 + digits.len()..].chars().next();
        if !digits.is_empty() && !next.is_some_and(|c| c.is_ascii_alphabetic()) {
            found.push(digits.parse().unwrap());
        }
    }
    found
}

/// mdBook's id of a heading: lower case; letters, digits, `-` and `_` kept; spaces
/// become `-`; everything else is dropped.
fn heading_id(heading: &str) -> String {
    heading
        .trim()
        .chars()
        .filter_map(|c| {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                Some(c.to_ascii_lowercase())
            } else if c.is_whitespace() {
                Some('-')
            } else {
                None
            }
        })
        .collect()
}

/// The prose of a page as paragraphs (blocks of lines without a blank one): fenced
/// code blocks, headings and code spans left out.
fn prose_paragraphs(text: &str) -> Vec<String> {
    let mut paragraphs = vec![String::new()];
    let mut in_fence = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_fence = !in_fence;
            continue;
        }
        if in_fence || line.starts_with('#') {
            continue;
        }
        if line.trim().is_empty() {
            paragraphs.push(String::new());
            continue;
        }
        let mut kept = String::new();
        for (k, piece) in line.split('`').enumerate() {
            if k % 2 == 0 {
                kept += piece;
            }
        }
        let last = paragraphs.last_mut().unwrap();
        *last += &kept;
        *last += "\n";
    }
    paragraphs.retain(|p| !p.is_empty());
    paragraphs
}

/// Does `paragraph` link to the section of case `n` in a *Where methods fail* page:
/// to the page that has the case's heading, and to that heading if it names one?
fn links_case(paragraph: &str, n: u32) -> bool {
    paragraph.split("](").skip(1).any(|rest| {
        let target = &rest[..rest.find(')').unwrap_or(rest.len())];
        let (file, fragment) = target.split_once('#').unwrap_or((target, ""));
        if !file.starts_with("where_methods_fail") {
            return false;
        }
        let Ok(text) = std::fs::read_to_string(format!("chapters/{file}")) else {
            return false;
        };
        let ids: Vec<String> = text
            .lines()
            .filter_map(|l| l.strip_prefix("## "))
            .filter(|h| case_numbers(h.split('.').next().unwrap_or("")).contains(&n))
            .map(heading_id)
            .collect();
        !ids.is_empty() && (fragment.is_empty() || ids.iter().any(|id| id == fragment))
    })
}

#[test]
fn the_link_checker_finds_cases_and_ids_as_mdbook_does() {
    assert_eq!(
        case_numbers("STABILITY S1 to S9; S4 and S5. x"),
        [1, 9, 4, 5]
    );
    assert_eq!(case_numbers("SS3 S3x s3 MS4 (S17)"), [17]);
    assert_eq!(
        heading_id("S3. smallpt's walls in `f32`"),
        "s3-smallpts-walls-in-f32"
    );
    let par = "([STABILITY S3](where_methods_fail_roots.md#s3-smallpts-walls-in-f32))";
    assert!(links_case(par, 3));
    assert!(!links_case(par, 1), "S1 has another heading");
    assert!(!links_case(
        "(S3, [x](where_methods_fail_roots.md#s3-wrong))",
        3
    ));
    assert!(links_case("[S1 to S3](where_methods_fail_roots.md)", 2));
    assert!(!links_case("[S1 to S3](where_methods_fail_roots.md)", 4));
    let text = "```text\nS1\n```\n## S2 heading\nsee `S5` and\nS7 here\n\nS8\n";
    assert_eq!(prose_paragraphs(text), ["see  and\nS7 here\n", "S8\n"]);
}

#[test]
fn each_page_links_a_stability_case_where_it_first_names_it() {
    let mut missing = Vec::new();
    for name in CASE_PAGES {
        let mut seen = std::collections::HashSet::new();
        for paragraph in prose_paragraphs(&page(name)) {
            for n in case_numbers(&paragraph) {
                if seen.insert(n) && !links_case(&paragraph, n) {
                    missing.push(format!("{name}: S{n} in {paragraph:?}"));
                }
            }
        }
    }
    assert!(
        missing.is_empty(),
        "a page names a stability case first without linking its section of \
         Where methods fail:\n{}",
        missing.join("\n")
    );
}
