//! Lesson 10's pages against the numbers: the chapter quotes the snapshots of
//! `lesson_10_path_tracing` (the test-sized run and the default run), the light-sample
//! exercises are the crate's numbers, and the numbers the pages work out by hand are
//! computed again.

use crate::common::pages::{after, assert_quotes, cell, first_number, page, snapshot};

use glam::Vec3;
use render_lessons::pathtrace::light::LightShape;
use render_lessons::scenes::path_tracing::{Staged, cornell};
use render_lessons::shapes::Shape;

// ---------------------------------------------------------------- the pages' numbers

/// The module whose snapshots hold the lesson's runs.
const PATH_TRACING: &str = "lessons::lesson_10_path_tracing";

#[test]
fn the_page_helpers_read_numbers_as_printed() {
    assert_eq!(first_number("is **−0.487** for"), "−0.487");
    assert_eq!(first_number("at $N = 2$"), "2");
    assert_eq!(first_number("close to the 0.7567 in the table."), "0.7567");
    assert_eq!(first_number("about 3700."), "3700");
    let snap = "spp  RMSE\n1    0.69119  0.6912\n16   0.18918  0.7567\nmean 0.33415; x";
    assert_eq!(cell(snap, "1", 1), 0.6912);
    assert_eq!(cell(snap, "16", 0), 0.18918);
    assert_eq!(after(snap, "mean "), 0.33415);
}

#[test]
fn the_chapter_quotes_the_numbers_snapshot() {
    let snap = snapshot(PATH_TRACING, "numbers");
    let page = "10_path_tracing.md";
    let at_1 = cell(&snap, "1", 1);
    let at_16 = cell(&snap, "16", 1);
    // The 16-sample error, inflated by a 64-sample reference: sqrt(1 + 16/64).
    let inflation = (1.0 + 16.0 / 64.0f64).sqrt();
    assert_quotes(page, "1.118$ times its true one", inflation);
    assert_quotes(page, "rise from\n0.5028 to", at_1);
    assert_quotes(page, "to 0.7417; the rest", at_16);
    assert_quotes(page, "(0.5028, 0.7417, 0.332)", at_1);
    assert_quotes(page, "reference's 0.332", after(&snap, "reference mean "));
}

#[test]
fn the_pages_quote_the_default_run_snapshot() {
    let snap = snapshot(PATH_TRACING, "default_run");
    let rmse = |label: &str| cell(&snap, label, 0);
    let (uniform, cosine) = (rmse("uniform hemisphere"), rmse("cosine"));
    let (nee, mis) = (rmse("next event"), rmse("MIS"));
    assert_eq!(rmse("64"), mis, "the ladder's top is the MIS render");
    let gain = |worse: f64, better: f64| (worse / better).powi(2);
    let page = "10_path_tracing.md";
    assert_quotes(page, "(0.21934/0.17323)^2", uniform);
    assert_quotes(page, "0.17323)^2 \\approx 1.6$", cosine);
    assert_quotes(page, "1.6$ times fewer", gain(uniform, cosine));
    assert_quotes(page, "(0.17323/0.07479)^2", cosine);
    assert_quotes(page, "0.07479)^2 \\approx 5.4$", nee);
    assert_quotes(page, "5.4$ times fewer", gain(cosine, nee));
    // MIS gains nothing over NEE on this box: the page says so with the ratio 1.0.
    assert_quotes(page, "(0.07479/0.07479)^2", nee);
    assert_quotes(page, "0.07479)^2 \\approx 1.0$", mis);
    assert_quotes(page, "1.0$: its lamp", gain(nee, mis));
    assert_quotes(page, "0.07479 at 64 samples", mis);
    assert_quotes(page, "64\\cdot(0.07479/0.01)^2", 64.0);
    assert_quotes(page, "0.07479/0.01)^2 \\approx 64", mis);
    assert_quotes(page, "55.9", (mis / 0.01).powi(2));
    assert!(
        (64.0 * (mis / 0.01).powi(2) - 3600.0).abs() < 50.0,
        "about 3600"
    );
    assert!(
        self::page(page).contains("3600$ samples"),
        "the page says 3600"
    );
    assert_quotes(page, "0.07479\\cdot\\sqrt{64/512} \\approx 0.026", mis);
    assert_quotes(page, "0.026$", mis * (64.0f64 / 512.0).sqrt());
    let page = "10_3_cosine.md";
    assert_quotes(page, "0.21934 (uniform)", uniform);
    assert_quotes(page, "0.17323 (cosine): $1.6", cosine);
    assert_quotes(page, "1.6$ times fewer", gain(uniform, cosine));
    let page = "10_5_next_event.md";
    assert_quotes(page, "0.17323 (cosine) to", cosine);
    assert_quotes(page, "0.07479: $5.4", nee);
    assert_quotes(page, "5.4$ times fewer", gain(cosine, nee));
    let page = "10_6_mis.md";
    assert_quotes(page, "0.07479 with NEE", nee);
    assert_quotes(page, "0.07479 with MIS", mis);
    assert_quotes(page, "errors of $1.0$", gain(nee, mis));
}

#[test]
fn the_light_sample_exercises_are_the_crates_numbers() {
    // Step 5's exercise: the Cornell box's floor under its ceiling light, through the
    // crate's own scene, light density and BRDF.
    let Staged { scene, .. } = cornell(16, 12).unwrap();
    let light = &scene.objects()[scene.emitters()[0]];
    let Shape::Quad(quad) = &light.shape else {
        panic!("the Cornell light is a quad")
    };
    let floor = scene
        .objects()
        .iter()
        .find(|o| matches!(&o.shape, Shape::Plane(p) if p.normal() == Vec3::Y))
        .unwrap();
    let centre = quad.point(0.5, 0.5);
    assert!(
        (centre - Vec3::new(50.0, 81.55, 81.6)).length() < 1e-4,
        "{centre}"
    );
    assert!((quad.area() - 1017.6).abs() < 0.05, "{}", quad.area());
    let page = "10_5_next_event.md";
    let contribution = |p: Vec3| {
        let pdf = LightShape::Quad(*quad).pdf(p, centre, quad.normal());
        let to_light = (centre - p).normalize();
        let cos = to_light.dot(Vec3::Y);
        let f_r = render_lessons::material::diffuse_brdf(floor.colour()).x;
        (pdf, f_r * light.emission.x * cos / pdf)
    };
    let under = Vec3::new(50.0, 0.0, 81.6);
    let (pdf, value) = contribution(under);
    assert_quotes(page, r"\approx 6.535\ \text{sr}^{-1}", f64::from(pdf));
    assert_quotes(page, "0.438$. At 45°", f64::from(value));
    let at_45 = Vec3::new(50.0, 0.0, 163.15);
    let (pdf_45, value_45) = contribution(at_45);
    let seen_at = (centre - at_45)
        .normalize()
        .dot(Vec3::Y)
        .acos()
        .to_degrees();
    assert!((seen_at - 45.0).abs() < 1e-3, "{seen_at}");
    assert_quotes(page, r"\approx 18.48\ \text{sr}^{-1}", f64::from(pdf_45));
    assert_quotes(page, "0.110$. That is a quarter", f64::from(value_45));
    assert!((value_45 / value - 0.25).abs() < 1e-4, "a quarter");
    // Step 6's exercise: the power-heuristic weights of the same light sample.
    let p_bsdf = 1.0 / std::f32::consts::PI;
    let page = "10_6_mis.md";
    let w_light =
        f64::from(render_lessons::pathtrace::mis::power_heuristic(pdf, p_bsdf));
    let w_bsdf =
        f64::from(render_lessons::pathtrace::mis::power_heuristic(p_bsdf, pdf));
    assert_quotes(page, r"\approx 0.9976$", w_light);
    assert_quotes(page, r"w_\text{bsdf} \approx 0.0024$", w_bsdf);
    assert!((w_light + w_bsdf - 1.0).abs() < 1e-6);
    let w_a = f64::from(render_lessons::pathtrace::mis::power_heuristic(0.2, 0.3));
    assert_quotes(page, r"\approx 0.308$", w_a);
    assert_quotes(page, r"$w_b \approx 0.692$", 1.0 - w_a);
}

/// The numbers lesson 10's pages work out by hand, computed again: each
/// `assert_quotes` finds the phrase on the page and checks its number against the
/// value to the digits the page prints.
#[test]
fn lesson_10_worked_numbers() {
    use render_lessons::pathtrace::roulette::RR_MAX_SURVIVAL;
    use std::f64::consts::PI;
    // Step 2's convergence table: a 64-sample reference inflates the error.
    let one = (1.0f64 + 1.0 / 64.0).sqrt();
    let sixteen = (1.0f64 + 16.0 / 64.0).sqrt();
    assert_quotes("10_path_tracing.md", r"\approx 1.008$ times", one);
    assert_quotes(
        "10_path_tracing.md",
        "about 1.11 of the rise",
        sixteen / one,
    );
    // 10_1's exercises: samples for an RMSE, and the quarter disc's sigma.
    let sigma = 0.8928f64;
    let spacing = 2f64.powi(-22);
    assert_eq!(format!("{spacing:.1e}"), "2.4e-7");
    assert_eq!(
        ((sigma / 0.001).powi(2) / 1000.0).round() * 1000.0,
        797_000.0
    );
    assert_eq!(format!("{:.1e}", (sigma / spacing).powi(2)), "1.4e13");
    let variance = 4.0 * PI - PI * PI;
    assert_quotes("10_1_monte_carlo.md", "= 2.697$ and", variance);
    assert_quotes("10_1_monte_carlo.md", r"$\sigma = 1.642$", variance.sqrt());
    assert_quotes(
        "10_1_monte_carlo.md",
        r"\approx 3.4$ times",
        (1.642f64 / 0.893).powi(2),
    );
    // 10_2's exercise: the naive sample's sigma.
    assert_quotes("10_2_naive.md", r"\approx 0.577\rho$", 1.0 / 3f64.sqrt());
    assert_quotes(
        "10_2_naive.md",
        r"$\sigma \approx 0.289$",
        0.5 / 3f64.sqrt(),
    );
    // 10_3: the interior furnace, 1 - 0.5^(d+1) at depth d.
    let furnace = |d: i32| 1.0 - 0.5f64.powi(d + 1);
    assert_eq!(format!("{}", furnace(8)), "0.998046875");
    assert_eq!(format!("{}", furnace(3)), "0.9375");
    assert_eq!(format!("{}", furnace(9)), "0.9990234375");
    assert_quotes("10_4_roulette.md", "$0.998$ where", furnace(8));
    // 10_4: the cap, and the exercise's game with beta = (0.3, 0.2, 0.1).
    assert_eq!(RR_MAX_SURVIVAL, 0.95);
    let q = 0.3f64.min(f64::from(RR_MAX_SURVIVAL));
    assert_quotes("10_4_roulette.md", "0.667, 0.333)$; with", 0.2 / q);
    assert_quotes("10_4_roulette.md", "0.667, 0.333) = (0.3", 0.2 / q);
    assert_quotes("10_4_roulette.md", "0.333)$; with", 0.1 / q);
    // 10_5's exercise: the light's centre is 81.55 above the floor.
    let h = 81.55f64;
    assert_quotes("10_5_next_event.md", "= 6650.4/1017.6", h * h);
    assert_eq!(
        format!("{:.1}", 2.0 * h * h),
        "13300.8",
        "the page's 13 300.8"
    );
    assert_quotes("10_5_next_event.md", r"0.7071)", 0.5f64.sqrt());
    // 10_6's exercise: the cosine density of the light sample's direction.
    assert_quotes("10_6_mis.md", "= 0.3183/6.535", 1.0 / PI);
    let ratio = (1.0 / PI) / 6.535;
    assert_quotes("10_6_mis.md", "= 0.0487$, squared", ratio);
    assert_quotes("10_6_mis.md", "squared $0.00237$", ratio * ratio);
    // 10_7: the critical angle of glass, and the lamp that replaces smallpt's sphere.
    assert_quotes(
        "10_7_mirror_glass.md",
        r"\approx 41.8°$",
        (1.0f64 / 1.5).asin().to_degrees(),
    );
    let poke = 0.27f64;
    let cap = PI * (2.0 * 600.0 * poke - poke * poke);
    assert_quotes("10_7_mirror_glass.md", "= 1017.6$, so", cap);
    let side = f64::from(render_lessons::scenes::path_tracing::CORNELL_LIGHT_SIDE);
    assert_quotes("10_7_mirror_glass.md", "Its side, 31.9002, gives", side);
    assert!(
        (side * side - cap).abs() < 0.05,
        "the lamp's area is the cap's"
    );
    // S19: one light-area sample is 1 with probability R^2, else 0.
    let r2 = 0.1f64 * 0.1;
    let page = "where_methods_fail_monte_carlo.md";
    assert_quotes(
        page,
        r"\approx 0.0995$ for $R = 0.1$",
        (r2 * (1.0 - r2)).sqrt(),
    );
}
