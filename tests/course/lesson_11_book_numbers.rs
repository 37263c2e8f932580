//! The numbers the book quotes from lesson 11 come from one place: the Markdown
//! fragments the lesson writes next to its charts (`chapters/figures/11_N_name.md`),
//! which the chapters include. These tests keep the committed fragments honest:
//!
//! - every exact part (errors, counts, shares: what depends only on the arithmetic)
//!   of charts 1 to 4 is measured again here and must match the file, so a change
//!   of the code that moves a number fails until the fragments are regenerated
//!   (chart 3's with the release suite below: in a debug build it took 4 s);
//! - the fragments come from a `--full` run, every chart has one, and every timed
//!   table says where and when it was measured;
//! - charts 5, 6 and 8 take minutes to measure at full quality: their exact parts
//!   are compared by an ignored test, run in release by CI
//!   (`cargo test --release --test course --test lessons -- --ignored`).
//!
//! To refresh the fragments (and the charts):
//!
//!     cargo run --release --example 11_speed_vs_accuracy -- --full --out chapters/figures

use std::path::{Path, PathBuf};

use render_lessons::course::measure::{
    ALL, Measure, Quality, monte_carlo, offsets, precision, renderers, sphere, triangle,
};
use render_lessons::course::report::{BookNumbers, Quoted, Run, anchored};

use crate::examples::speed_vs_accuracy as lesson11;

const REFRESH: &str = "cargo run --release --example 11_speed_vs_accuracy -- --full --out chapters/figures";

fn figures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("chapters/figures")
}

/// The committed fragment of chart `stem`.
fn committed(stem: &str) -> String {
    let path = figures().join(format!("{stem}.md"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!("{}: {e} (write it with `{REFRESH}`)", path.display())
    })
}

/// Every exact table and value of `fresh` must read the same in the committed file.
fn same_exact_parts(stem: &str, fresh: &BookNumbers) {
    let text = committed(stem);
    assert!(
        text.contains("(quality: full)"),
        "{stem}.md was not written by a --full run: the book quotes --full numbers ({REFRESH})"
    );
    let exact = fresh.exact();
    assert!(
        !exact.tables.is_empty() || !exact.values.is_empty(),
        "{stem}: nothing exact to compare"
    );
    let mut problems = Vec::new();
    for (anchor, body) in exact.blocks(&Run::here("full")) {
        match anchored(&text, &anchor) {
            None => problems.push(format!("{stem}.md has no anchor `{anchor}`")),
            Some(found) if found != body => problems.push(format!(
                "{stem}.md, `{anchor}` differs from what the lesson measures now:\n\
                 committed:\n{found}measured:\n{body}"
            )),
            Some(_) => {}
        }
    }
    assert!(
        problems.is_empty(),
        "{}\nRegenerate the fragments with `{REFRESH}` (or `--only {stem}`), review and commit them.",
        problems.join("\n")
    );
}

#[test]
fn chart_1_fragment_holds_what_the_lesson_measures() {
    same_exact_parts("11_1_sphere", &sphere::exact_quoted(Quality::Full).unwrap());
}

#[test]
fn chart_2_fragment_holds_what_the_lesson_measures() {
    same_exact_parts(
        "11_2_triangle",
        &triangle::exact_quoted(Quality::Full).unwrap(),
    );
}

/// Chart 3 at full quality: seconds in release, a minute's share of `cargo test` in a
/// debug build, so it runs with the release suite.
#[test]
#[ignore = "slow in a debug build: the release suite runs it (.ci/run: `cargo test --release --test course --test lessons -- --ignored`)"]
fn chart_3_fragment_holds_what_the_lesson_measures() {
    same_exact_parts(
        "11_3_offsets",
        &offsets::exact_quoted(Quality::Full).unwrap(),
    );
}

#[test]
fn chart_4_fragment_holds_what_the_lesson_measures() {
    same_exact_parts(
        "11_4_precision",
        &precision::exact_quoted(Quality::Full).unwrap(),
    );
}

/// Charts 5, 6 and 8 measured again at full quality (minutes in release): only
/// their exact parts are compared.
#[test]
#[ignore = "minutes: the release suite runs it (.ci/run: `cargo test --release --test course --test lessons -- --ignored`)"]
fn charts_5_6_8_fragments_hold_what_the_lesson_measures() {
    let charts: [(&str, Measure); 3] = [
        ("11_5_monte_carlo", monte_carlo::measure),
        ("11_6_renderers", renderers::measure),
        ("11_8_lessons", lesson11::lessons),
    ];
    for (stem, measure) in charts {
        same_exact_parts(stem, &measure(Quality::Full).unwrap().quoted);
    }
}

#[test]
fn every_chart_has_a_fragment_from_a_full_run_and_its_times_say_where() {
    let stems: Vec<&str> = ALL
        .iter()
        .map(|(stem, _)| *stem)
        .chain(["11_8_lessons"])
        .collect();
    for stem in stems {
        let text = committed(stem);
        assert!(text.contains("(quality: full)"), "{stem}.md: not --full");
        let run =
            anchored(&text, "run").unwrap_or_else(|| panic!("{stem}.md: no `run`"));
        assert!(
            run.starts_with("Times from one `--full` run on ")
                && run.contains(" cores of "),
            "{stem}.md: {run}"
        );
        let machine = anchored(&text, "machine")
            .unwrap_or_else(|| panic!("{stem}.md: no `machine`"));
        assert!(
            run.contains(machine.trim_end()),
            "{stem}.md: {machine} is not in {run}"
        );
        // Every timed table ends with the run's line: look at each table's block.
        for block in text.split("<!-- ANCHOR: ").skip(1) {
            let name = block.split_whitespace().next().unwrap_or("");
            let Some(body) = anchored(&text, name) else {
                panic!("{stem}.md: `{name}` has no end")
            };
            let is_table = body.starts_with('|');
            let has_time = body.lines().next().is_some_and(|header| {
                ["ns", "ms", "(s)", "s for", "rays/s"]
                    .iter()
                    .any(|unit| header.contains(unit))
            });
            if is_table && has_time {
                assert!(
                    body.trim_end().ends_with(run.trim_end()),
                    "{stem}.md: the timed table `{name}` does not end with the run's line"
                );
            }
        }
    }
}

#[test]
fn a_fragment_is_markdown_between_anchors() {
    let run = Run {
        quality: "full",
        machine: "2 cores of a test CPU".into(),
        date: "2026-01-02".into(),
    };
    let fragment = BookNumbers::default()
        .table(
            Quoted::new("errors", false, &["x", "error"])
                .row(vec!["1e3".into(), "3.7e-5".into()])
                .row(vec!["1e4".into(), "0.52".into()]),
        )
        .table(
            Quoted::new("times", true, &["method", "ns"])
                .row(vec!["a".into(), "7.1".into()]),
        )
        .value("worst", false, "6.3e-8".into());
    let text = fragment.markdown("11_9_test", &run);
    assert_eq!(
        anchored(&text, "errors").unwrap(),
        "| x | error |\n|---:|---:|\n<!-- ANCHOR: errors_rows -->\n| 1e3 | 3.7e-5 |\n\
         | 1e4 | 0.52 |\n<!-- ANCHOR_END: errors_rows -->\n"
    );
    assert_eq!(
        anchored(&text, "times_rows").unwrap(),
        "| a | 7.1 |\n",
        "the rows alone, to add to a chapter's table"
    );
    assert!(
        anchored(&text, "times")
            .unwrap()
            .ends_with("\nTimes from one `--full` run on 2 cores of a test CPU, 2026-01-02: they change with the machine and its load.\n")
    );
    assert_eq!(anchored(&text, "worst").unwrap(), "6.3e-8\n");
    assert_eq!(fragment.exact().tables.len(), 1);
    assert_eq!(
        fragment.get("errors").unwrap().cell("1e4", "error"),
        Some("0.52")
    );
    assert!(anchored(&text, "missing").is_none());
}

/// Chart 5's light, as `11_speed_vs_accuracy.md` states it: radius R = 0.25 at height
/// 1 above the shading point, so sin^2 of the cone's half-angle, and the exact answer
/// every estimator estimates, is R^2 = 0.0625.
#[test]
fn chart_5_light_has_the_radius_and_exact_answer_the_page_states() {
    use render_lessons::course::measure::monte_carlo;
    let (radius, height) = (0.25, 1.0);
    assert_eq!(f64::from(monte_carlo::RADIUS), radius);
    assert_eq!(monte_carlo::exact(), (radius / height) * (radius / height));
    assert_eq!(monte_carlo::exact(), 0.0625);
}

/// `11_speed_vs_accuracy.md`'s exercise on chart 5: at equal error, cosine sampling
/// needs the ratio of the two variances in the committed fragment, about 1.7e5,
/// more samples than the light cone.
#[test]
fn chart_5_exercise_ratio_follows_the_fragment() {
    let fragment = committed("11_5_monte_carlo");
    let variance = |row: &str| -> f64 {
        let line = fragment
            .lines()
            .find(|l| l.starts_with(&format!("| {row} |")))
            .unwrap_or_else(|| panic!("no row {row}"));
        line.trim_end_matches('|')
            .rsplit('|')
            .next()
            .unwrap()
            .trim()
            .parse()
            .unwrap()
    };
    let ratio = variance("cosine") / variance("light cone");
    assert_eq!(format!("{ratio:.1e}"), "1.7e5");
}

/// Page 11_2 reads chart 9's fit through the committed run's first and last rows as
/// it comes out: the robust caster's per-ray cost positive, the plain caster's
/// negative, because a primitive adds less to a plain ray between the first two rows
/// than between the last two (the plain time is not quite a line).
#[test]
fn chart_9s_per_ray_costs_are_what_page_11_2_reads_from_them() {
    let fragment = crate::common::pages::read("chapters/figures/11_9_tax.md");
    let between = |anchor: &str| {
        let start = format!("ANCHOR: {anchor} -->");
        let rest = fragment.split(start.as_str()).nth(1).unwrap();
        rest.split("<!--").next().unwrap().trim().to_string()
    };
    let number = |anchor: &str| between(anchor).parse::<f64>().unwrap();
    let page = crate::common::pages::page("11_2_robustness_tax.md");
    assert!(page.contains("A negative time is no cost"));
    assert!(
        number("per_ray_plain") < 0.0,
        "{}",
        between("per_ray_plain")
    );
    assert!(
        number("per_ray_robust") > 0.0,
        "{}",
        between("per_ray_robust")
    );
    // (primitives, plain ns per ray) of each row.
    let rows: Vec<(f64, f64)> = between("tax_rows")
        .lines()
        .filter(|l| l.starts_with('|'))
        .map(|row| {
            let cells: Vec<&str> = row.split('|').map(str::trim).collect();
            (cells[1].parse().unwrap(), cells[3].parse().unwrap())
        })
        .collect();
    let per_primitive = |a: (f64, f64), b: (f64, f64)| (b.1 - a.1) / (b.0 - a.0);
    let n = rows.len();
    assert!(n >= 3, "{rows:?}");
    assert!(
        per_primitive(rows[0], rows[1]) < per_primitive(rows[n - 2], rows[n - 1]),
        "{rows:?}"
    );
}
