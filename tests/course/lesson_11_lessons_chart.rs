//! Lesson 11, chart 8: the renderers of lessons 08 and 09 on lesson 08's scene.
//! No time is asserted; the errors must behave as the chapter says. About 30 renders
//! at 480 x 270: 6 s of a debug build's `cargo test`, so it runs with the release suite.

use crate::examples::speed_vs_accuracy as lesson;

use render_lessons::course::measure::Quality;

#[test]
#[ignore = "slow in a debug build: the release suite runs it (.ci/run: `cargo test --release --test course --test lessons -- --ignored`)"]
fn the_rasterizer_approaches_the_ray_traced_image_as_its_knobs_are_turned_up() {
    let measured = lesson::lessons(Quality::Quick).unwrap();
    let chart = &measured.chart;
    let series = |prefix: &str| {
        chart
            .series
            .iter()
            .find(|s| s.name.starts_with(prefix))
            .map(|s| s.points.clone())
            .unwrap()
    };
    let segments = series("rasterized + 1024^2 shadow map");
    let maps = series("rasterized, 64 segments");
    let none = series("rasterized, no shadows")[0];
    let reference = series("ray cast with shadow rays")[0];
    assert_eq!((segments.len(), maps.len()), (5, 6));
    // The reference differs from itself nowhere.
    assert_eq!(reference.1, 0.0);
    // Finer spheres and finer maps get closer (first against last), and any shadow
    // map is closer than no shadows at all.
    assert!(segments[4].1 < segments[0].1, "{segments:?}");
    assert!(maps[5].1 < maps[0].1, "{maps:?}");
    assert!(maps.iter().all(|m| m.1 < none.1), "{maps:?} vs {none:?}");
    // The lesson's own setting (64 segments, 1024^2) agrees on at least 99%.
    assert!(segments[3].1 <= 1.0, "{segments:?}");
    assert_eq!(segments[3].1, maps[3].1, "the same image twice");
    assert!(chart.csv().starts_with("# x: time per frame (ms)"));
    assert_eq!(measured.findings.len(), 3);
}
