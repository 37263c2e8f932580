//! Lesson 10's page "How we know the path tracer is right", its chart of error against
//! time: what the page says of the committed run (`chapters/figures/10_9_error_time.csv`,
//! written by `scripts/cross-check --time --update`) holds of that run's numbers.

use std::collections::BTreeMap;

/// One measured point: samples per pixel, seconds, RMS error.
struct Point {
    spp: f64,
    seconds: f64,
    error: f64,
}

/// The committed points of each renderer.
fn committed() -> BTreeMap<String, Vec<Point>> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/chapters/figures/10_9_error_time.csv"
    );
    let text = std::fs::read_to_string(path).expect("the committed error-time data");
    let mut runs: BTreeMap<String, Vec<Point>> = BTreeMap::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let fields: Vec<&str> = line.split(',').collect();
        let number = |k: usize| fields[k].parse::<f64>().expect(line);
        runs.entry(fields[0].to_string()).or_default().push(Point {
            spp: number(1),
            seconds: number(2),
            error: number(3),
        });
    }
    runs
}

/// The least-squares slope of log y against log x.
fn slope(points: &[(f64, f64)]) -> f64 {
    let logs: Vec<(f64, f64)> = points.iter().map(|(x, y)| (x.ln(), y.ln())).collect();
    let n = logs.len() as f64;
    let (mx, my) = logs
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let sxy: f64 = logs.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = logs.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

#[test]
fn in_the_committed_run_every_error_falls_as_one_over_root_time() {
    let runs = committed();
    assert!(runs.contains_key("crate") && runs.contains_key("Mitsuba scalar_rgb"));
    for (renderer, points) in &runs {
        let xy: Vec<(f64, f64)> = points.iter().map(|p| (p.seconds, p.error)).collect();
        let k = slope(&xy);
        // -1/2 within what eight points of one image each leave (about 0.05 here).
        assert!((-0.62..=-0.40).contains(&k), "{renderer}: slope {k}");
    }
}

#[test]
fn in_the_committed_run_both_renderers_have_one_error_per_sample() {
    // The page's "error x sqrt(samples per pixel)": the geometric mean from 4 spp on.
    let per_sample = |points: &[Point]| {
        let logs: Vec<f64> = points
            .iter()
            .filter(|p| p.spp >= 4.0)
            .map(|p| (p.error * p.spp.sqrt()).ln())
            .collect();
        (logs.iter().sum::<f64>() / logs.len() as f64).exp()
    };
    let runs = committed();
    let crate_sigma = per_sample(&runs["crate"]);
    for (renderer, points) in &runs {
        let ratio = per_sample(points) / crate_sigma;
        // One estimator: the same sigma, up to the noise of each point's error.
        assert!((0.9..=1.1).contains(&ratio), "{renderer}: {ratio}");
    }
}
