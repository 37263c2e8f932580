//! Lesson 10, step 1 (chapter 10_1, `examples/10_monte_carlo.rs`): Monte Carlo
//! integration on its own. Its numbers (snapshot), the error falling as 1/sqrt(N), its
//! flags, its chart, and the page quoting its snapshot.

use crate::common::pages::{after, assert_quotes, cell, snapshot};

use crate::examples::monte_carlo;

use clap::Parser;

// Step 1: Monte Carlo integration on its own (examples/10_monte_carlo.rs).

fn monte_carlo_args(extra: &[&str]) -> monte_carlo::Args {
    let mut argv = vec!["10_monte_carlo", "--out", "target/test-out/10"];
    argv.extend(extra);
    monte_carlo::Args::parse_from(argv)
}

/// The example's study at the flags' values.
fn monte_carlo_rows(args: &monte_carlo::Args) -> Vec<monte_carlo::Row> {
    monte_carlo::study(args.max_power, args.runs, args.seed)
}

#[test]
fn monte_carlo_numbers() {
    let args = monte_carlo_args(&[]);
    let rows = monte_carlo_rows(&args);
    insta::assert_snapshot!("monte_carlo", monte_carlo::numbers(args.runs, &rows));
}

#[test]
fn monte_carlo_rmse_falls_as_one_over_sqrt_n() {
    let args = monte_carlo_args(&[]);
    let rows = monte_carlo_rows(&args);
    assert_eq!(rows.len(), 17);
    let points: Vec<(f64, f64)> = rows.iter().map(|r| (r.n as f64, r.rmse)).collect();
    let slope = render_lessons::course::chart::log_log_slope(&points).unwrap();
    assert!((slope + 0.5).abs() < 0.05, "slope {slope}");
    // sigma = sqrt(32/3 - pi^2): RMSE x sqrt(N) stays near it at every N.
    let sigma = monte_carlo::sigma();
    assert!((sigma - 0.892_8).abs() < 1e-4, "{sigma}");
    for r in &rows {
        let scaled = r.rmse * (r.n as f64).sqrt();
        assert!((scaled / sigma - 1.0).abs() < 0.2, "N = {}: {scaled}", r.n);
    }
}

#[test]
fn monte_carlo_refuses_bad_flags() {
    for flags in [["--runs", "0"], ["--runs", "4097"], ["--max-power", "25"]] {
        let argv = [&["10_monte_carlo"], &flags[..]].concat();
        match monte_carlo::Args::try_parse_from(argv) {
            Err(e) => assert!(e.to_string().contains(flags[0]), "{flags:?}: {e}"),
            Ok(_) => panic!("{flags:?} accepted"),
        }
    }
}

#[test]
fn the_monte_carlo_chart_is_the_committed_figure() {
    let args = monte_carlo_args(&[]);
    let rows = monte_carlo_rows(&args);
    let svg = monte_carlo::chart(args.runs, &rows).svg().unwrap();
    let committed =
        std::fs::read_to_string("chapters/figures/10_monte_carlo.svg").unwrap();
    assert!(
        svg == committed,
        "chapters/figures/10_monte_carlo.svg is stale: run the example and copy out/10_monte_carlo.svg"
    );
}

#[test]
fn the_monte_carlo_page_quotes_its_snapshot() {
    let snap = snapshot(module_path!(), "monte_carlo");
    let page = "10_1_monte_carlo.md";
    // Columns after N: estimate, error, RMSE, RMSE x sqrt(N).
    assert_quotes(page, "0.07 at $N = 2$", cell(&snap, "2", 1));
    assert_quotes(page, "0.56 at $N = 8$", cell(&snap, "8", 1));
    assert_quotes(page, "0.0012 at $N = 8192$", cell(&snap, "8192", 1));
    assert_quotes(page, "0.0038 at $N = 65536$", cell(&snap, "65536", 1));
    let ns = [
        1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192,
    ];
    let ns = ns.iter().chain(&[16384, 32768, 65536]);
    let scaled: Vec<f64> = ns.map(|n| cell(&snap, &n.to_string(), 3)).collect();
    let lo = scaled.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = scaled.iter().copied().fold(0.0, f64::max);
    assert_quotes(page, "stays between 0.7451 and", lo);
    assert_quotes(page, "and 0.9493 around", hi);
    assert_quotes(
        page,
        "$\\sigma = 0.8928$ (an RMSE over 64 runs",
        after(&snap, "sample = "),
    );
    assert_quotes(page, "fitted slope is −0.511", after(&snap, "log N: "));
    assert_quotes(page, "from 0.88 at N = 1", cell(&snap, "1", 2));
    assert_quotes(page, "to 0.0035 at\nN = 65536", cell(&snap, "65536", 2));
}
