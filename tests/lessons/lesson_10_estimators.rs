//! Lesson 10, the estimators (chapters 10_2 to 10_6): the furnace tests (STABILITY
//! S16: the interior furnace is exact at depth 8 for cosine sampling, within 4 sigma
//! for uniform, 1 with Russian roulette; S17: the grey furnace and the ray offsets),
//! the convergence of the pixel error (S18), direct light unbiased for every
//! estimator under a sphere and a quad light (S19), the two lights' sigmas, and the
//! power heuristic.

use crate::common::pages::{assert_quotes, page};
use crate::lesson_10_path_tracing::settings;
use render_lessons::course::chart::log_log_slope;

use glam::{Vec2, Vec3};
use render_lessons::camera::Camera;
use render_lessons::material::Material;
use render_lessons::pathtrace::progressive::rmse;
use render_lessons::pathtrace::{
    Accumulator, PixelSampling, Sampling, Settings, SphereSampling, radiance,
};
use render_lessons::ray::Ray;
use render_lessons::rng::Rng;
use render_lessons::scene::{Object, Scene};
use render_lessons::scenes::path_tracing::{
    Staged, grey_furnace, interior_furnace, look_camera, two_lights,
};
use render_lessons::shapes::{Plane, Quad, Shape, Sphere};
use render_lessons::spawn::Offset;

/// Mean and standard deviation (of one sample) of `n` samples of `f`, in f64.
pub(crate) fn stats(n: u32, mut f: impl FnMut(u32) -> f32) -> (f64, f64) {
    let (mut sum, mut sum2) = (0.0f64, 0.0f64);
    for i in 0..n {
        let x = f64::from(f(i));
        sum += x;
        sum2 += x * x;
    }
    let mean = sum / f64::from(n);
    let var = (sum2 / f64::from(n) - mean * mean).max(0.0);
    (mean, var.sqrt())
}

/// `|mean - exact| <= 4 sigma / sqrt(n)`, with a floor for zero-variance estimators.
pub(crate) fn assert_within_4_sigma(
    label: &str,
    (mean, sigma): (f64, f64),
    n: u32,
    exact: f64,
) {
    let bound = 4.0 * sigma / f64::from(n).sqrt() + 1e-6;
    assert!(
        (mean - exact).abs() <= bound,
        "{label}: mean {mean} vs exact {exact}, 4 sigma/sqrt(N) = {bound}"
    );
}

/// `n` samples of the radiance along pixel rays of `camera`, cycling over pixels.
pub(crate) fn pixel_samples(
    scene: &Scene,
    camera: &Camera,
    s: &Settings,
    n: u32,
    seed: u64,
) -> (f64, f64) {
    let (w, h) = (camera.film().width(), camera.film().height());
    let mut rng = Rng::for_pixel(seed, 0, 0);
    stats(n, |i| {
        let (x, y) = (i % w, (i / w) % h);
        let ray =
            camera.ray_through(Vec2::new(x as f32 + 0.5, y as f32 + 0.5), Vec2::ZERO);
        radiance(scene, ray, &mut rng, s).x
    })
}

// ---------------------------------------------------------------- S16

const S16_DEPTH_8: f64 = 0.998_046_875;

#[test]
fn s16_interior_furnace_cosine_depth_8_is_exact_with_zero_variance() {
    let Staged { scene, camera } = interior_furnace(8, 8).unwrap();
    let s = settings(Sampling::Cosine, Some(8), false);
    let (mean, sigma) = pixel_samples(&scene, &camera, &s, 4096, 1);
    assert!((mean - S16_DEPTH_8).abs() < 1e-6, "mean {mean}");
    assert!(sigma < 1e-6, "sigma {sigma}");
    // The pages' value: rho (1 - rho^9) / (1 - rho) at rho = 0.5, exact in binary.
    assert_eq!(S16_DEPTH_8, 0.5 * (1.0 - 0.5f64.powi(9)) / (1.0 - 0.5));
    assert_eq!(format!("{S16_DEPTH_8}"), "0.998046875");
}

#[test]
fn s16_interior_furnace_uniform_hemisphere_within_4_sigma() {
    let Staged { scene, camera } = interior_furnace(8, 8).unwrap();
    let s = settings(Sampling::UniformHemisphere, Some(8), false);
    let n = 40_000;
    let st = pixel_samples(&scene, &camera, &s, n, 2);
    assert!(st.1 > 0.01, "uniform sampling is not zero-variance here");
    assert_within_4_sigma("uniform hemisphere", st, n, S16_DEPTH_8);
}

#[test]
fn s16_interior_furnace_russian_roulette_infinite_depth_gives_1() {
    let Staged { scene, camera } = interior_furnace(8, 8).unwrap();
    let n = 40_000;
    for sampling in [Sampling::Cosine, Sampling::NextEvent, Sampling::Mis] {
        let s = settings(sampling, None, true);
        let st = pixel_samples(&scene, &camera, &s, n, 3);
        assert_within_4_sigma(&format!("{sampling:?} + RR"), st, n, 1.0);
    }
}

#[test]
fn s16_next_event_and_mis_agree_with_the_depth_8_value() {
    // The sphere is its own light: light samples from inside use area sampling.
    let Staged { scene, camera } = interior_furnace(8, 8).unwrap();
    let n = 20_000;
    for sampling in [Sampling::NextEvent, Sampling::Mis] {
        for sphere_lights in [SphereSampling::Area, SphereSampling::Cone] {
            let s = Settings {
                sphere_lights,
                ..settings(sampling, Some(8), false)
            };
            let st = pixel_samples(&scene, &camera, &s, n, 4);
            assert_within_4_sigma(
                &format!("{sampling:?} {sphere_lights:?}"),
                st,
                n,
                S16_DEPTH_8,
            );
        }
    }
}

// ---------------------------------------------------------------- S17

fn grey_furnace_mean(offset: Offset, centre: Vec3) -> (f64, f64) {
    let Staged { scene, camera } = grey_furnace(16, 16, centre).unwrap();
    let s = Settings {
        offset,
        ..settings(Sampling::Cosine, Some(8), false)
    };
    pixel_samples(&scene, &camera, &s, 16_384, 5)
}

#[test]
fn s17_grey_furnace_with_scaled_or_error_bound_offset_is_exactly_one_half() {
    for offset in [Offset::Scaled, Offset::ErrorBound] {
        for centre in [Vec3::ZERO, Vec3::new(1e4, 5e3, 2.5e3)] {
            let (mean, sigma) = grey_furnace_mean(offset, centre);
            // Every path carries exactly 0.5: the mean is 0.5 and the spread 0, not
            // merely close to them.
            assert_eq!((mean, sigma), (0.5, 0.0), "{offset:?} {centre}");
        }
    }
}

#[test]
fn s17_grey_furnace_without_offset_darkens_the_failure_case() {
    let (mean, _) = grey_furnace_mean(Offset::Fixed(0.0), Vec3::ZERO);
    eprintln!("S17 no offset: mean {mean}");
    // Exact is 0.5 with no noise: anything below is self-hits.
    assert!(mean < 0.49, "mean {mean}");
    let (far, _) = grey_furnace_mean(Offset::Fixed(1e-4), Vec3::new(1e4, 5e3, 2.5e3));
    eprintln!("S17 t > 1e-4 at X = 1e4: mean {far}");
    assert!(far < 0.49, "mean {far}");
    let page = "10_7_mirror_glass.md";
    assert_quotes(page, "**0.459**, and with a fixed", mean);
    assert_quotes(page, "to **0.346**.", far);
    assert_quotes(page, "0.459; offset the", mean);
}

// ---------------------------------------------------------------- S18

/// The grey furnace sphere seen whole: with cosine sampling a sample is 0.5 on the
/// sphere and 1 off it, so the only noise is where in the pixel the ray passes, and
/// only the silhouette's pixels are noisy.
fn edge_image(
    pixels: PixelSampling,
    spp: u32,
    seed: u64,
) -> render_lessons::framebuffer::Framebuffer {
    let Staged { scene, .. } = grey_furnace(4, 4, Vec3::ZERO).unwrap();
    let camera = look_camera(24, 24, 3.0 * Vec3::Z, -Vec3::Z, 0.45).unwrap();
    let s = settings(Sampling::Cosine, Some(1), false);
    let mut acc = Accumulator::new(&camera, seed);
    acc.render_pass(&scene, &camera, &s, pixels, spp).unwrap()
}

/// The reference of [`convergence`]: 9216 jittered samples per pixel, a 96 x 96 grid.
fn converged() -> render_lessons::framebuffer::Framebuffer {
    edge_image(PixelSampling::Jittered, 9216, 99)
}

fn convergence(
    pixels: PixelSampling,
    reference: &render_lessons::framebuffer::Framebuffer,
) -> Vec<(f64, f64)> {
    [4u32, 16, 64, 256]
        .iter()
        .map(|&spp| {
            let mse: f64 = (0..6)
                .map(|seed| rmse(&edge_image(pixels, spp, seed), reference).powi(2))
                .sum::<f64>()
                / 6.0;
            (f64::from(spp), mse.sqrt())
        })
        .collect()
}

#[test]
#[ignore = "over 1 s in a debug build: the release suite runs it (.ci/run: `cargo test --release --test course --test lessons -- --ignored`)"]
fn s18_rmse_slope_independent_is_minus_one_half_jittered_steeper() {
    // The reference once (it is four fifths of the work), for both samplings.
    let reference = converged();
    let independent = convergence(PixelSampling::Independent, &reference);
    let jittered = convergence(PixelSampling::Jittered, &reference);
    let (a, b) = (
        log_log_slope(&independent).unwrap(),
        log_log_slope(&jittered).unwrap(),
    );
    eprintln!("S18 independent {independent:?} slope {a}");
    eprintln!("S18 jittered {jittered:?} slope {b}");
    assert!((a + 0.5).abs() <= 0.05, "independent slope {a}");
    assert!(b < -0.55, "jittered slope {b}");
    // "Close to" the N^(-3/4) of the theory: within 0.05 of -0.75.
    assert!((b + 0.75).abs() < 0.05, "jittered slope {b}");
    let page = "10_path_tracing.md";
    assert_quotes(page, "**−0.487** for independent", a);
    assert_quotes(page, "**−0.764** for jittered", b);
    assert_quotes(page, "two slopes, −0.487 and", a);
    assert_quotes(page, "and −0.764.\n", b);
}

// ---------------------------------------------------------------- S19

/// A white Lambertian floor under a sphere light of radius `r` and radiance 1 whose
/// centre is at height 1: the floor point below it reflects exactly r^2.
fn s19_scene(r: f32) -> Scene {
    let floor = Object::new(
        Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Y).unwrap()),
        Material::diffuse(Vec3::ONE).unwrap(),
    );
    let light = Object::emitting(
        Shape::Sphere(Sphere::new(Vec3::Y, r).unwrap()),
        Material::BLACK,
        Vec3::ONE,
    );
    Scene::new(vec![floor, light], Vec3::ZERO).unwrap()
}

pub(crate) fn s19_estimators() -> Vec<(&'static str, Settings)> {
    let with = |sampling, sphere_lights| Settings {
        sphere_lights,
        ..settings(sampling, Some(1), false)
    };
    vec![
        (
            "uniform hemisphere",
            with(Sampling::UniformHemisphere, SphereSampling::Cone),
        ),
        ("cosine", with(Sampling::Cosine, SphereSampling::Cone)),
        (
            "light area",
            with(Sampling::NextEvent, SphereSampling::Area),
        ),
        (
            "light cone",
            with(Sampling::NextEvent, SphereSampling::Cone),
        ),
        ("MIS (area)", with(Sampling::Mis, SphereSampling::Area)),
        ("MIS (cone)", with(Sampling::Mis, SphereSampling::Cone)),
    ]
}

#[test]
fn s19_direct_lighting_estimators_are_unbiased() {
    let n = 50_000;
    let radii = [0.1f32, 0.5];
    let mut sigma = vec![[0.0; 2]; s19_estimators().len()];
    for (column, r) in radii.into_iter().enumerate() {
        let scene = s19_scene(r);
        let ray = Ray::new(Vec3::new(0.0, 0.5 * (1.0 - r), 0.0), -Vec3::Y).unwrap();
        for (row, (label, s)) in s19_estimators().into_iter().enumerate() {
            let mut rng = Rng::for_pixel(7, 0, 0);
            let st = stats(n, |_| radiance(&scene, ray, &mut rng, &s).x);
            eprintln!("S19 R = {r} {label}: mean {:.6} sigma {:.4}", st.0, st.1);
            assert_within_4_sigma(
                &format!("R = {r}, {label}"),
                st,
                n,
                f64::from(r * r),
            );
            sigma[row][column] = st.1;
        }
    }
    // Step 5's table, a Markdown table the page includes.
    let mut table = String::from(
        "| estimator | $\\sigma$ of one sample, $R = 0.1$ | $\\sigma$, $R = 0.5$ |\n\
         |-----------|-----------:|----------:|\n",
    );
    for ((label, _), [small, large]) in s19_estimators().iter().zip(&sigma) {
        table += &format!("| {label} | {small:.4} | {large:.4} |\n");
    }
    insta::assert_snapshot!("s19_sigmas", table);
    // Step 6 says MIS is not always the best: at R = 0.5 the cone alone has a smaller
    // sigma than MIS with the cone (rows 3 and 5).
    assert!(sigma[3][1] < sigma[5][1], "{sigma:?}");
    // The page's prose divides the table's numbers: R = 0.1, cosine and uniform
    // against light area (rows 1, 0 and 2).
    let page = "10_5_next_event.md";
    // The ratio of the numbers as the table prints them, to 4 decimals.
    let shown = |row: usize| format!("{:.4}", sigma[row][0]).parse::<f64>().unwrap();
    let ratio = |row: usize| (shown(row) / shown(2)).powi(2);
    assert_quotes(
        page,
        &format!("({:.4}/{:.4})^2 \\approx", sigma[1][0], sigma[2][0]),
        sigma[1][0],
    );
    assert_quotes(
        page,
        &format!("({:.4}/{:.4})^2 \\approx", sigma[0][0], sigma[2][0]),
        sigma[0][0],
    );
    let says =
        |row: usize| format!("/{:.4})^2 \\approx {:.0}$", sigma[2][0], ratio(row));
    assert_quotes(page, &says(1), sigma[2][0]);
    assert_quotes(page, &says(0), sigma[2][0]);
}

/// The S19 check for a quad light: a white floor point under the centre of a square
/// light of side `side` at height `h`, radiance 1, reflects the form factor
/// F = 4 F_corner(X, Y), X = Y = side / 2h, with the corner-rectangle form factor
/// F_corner = (1 / 2 pi) [X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2)) + (X <-> Y)]
/// (Howell's catalogue of configuration factors, case B-3).
pub(crate) fn square_light_exact(side: f64, h: f64) -> f64 {
    let x = side / (2.0 * h);
    let a = (1.0 + x * x).sqrt();
    let corner = 2.0 * (x / a) * (x / a).atan() / (2.0 * std::f64::consts::PI);
    4.0 * corner
}

/// A white Lambertian floor under a two-sided unit square light of radiance 1 at
/// height 1, centred over the origin (corners at x, z = -0.5 and 0.5).
pub(crate) fn square_light_scene() -> Scene {
    let floor = Object::new(
        Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Y).unwrap()),
        Material::diffuse(Vec3::ONE).unwrap(),
    );
    let quad = Quad::new(Vec3::new(-0.5, 1.0, -0.5), Vec3::Z, Vec3::X).unwrap();
    let light = Object::emitting(Shape::Quad(quad), Material::BLACK, Vec3::ONE);
    Scene::new(vec![floor, light], Vec3::ZERO).unwrap()
}

#[test]
fn s19_for_a_quad_light_every_estimator_is_unbiased() {
    let scene = square_light_scene();
    let exact = square_light_exact(1.0, 1.0);
    assert_quotes("10_5_next_event.md", "exact form factor 0.239456", exact);
    let ray = Ray::new(Vec3::new(0.0, 0.5, 0.0), -Vec3::Y).unwrap();
    let n = 50_000;
    for (label, s) in s19_estimators() {
        let mut rng = Rng::for_pixel(8, 0, 0);
        let st = stats(n, |_| radiance(&scene, ray, &mut rng, &s).x);
        eprintln!(
            "S19 quad {label}: mean {:.6} sigma {:.4} exact {exact:.6}",
            st.0, st.1
        );
        assert_within_4_sigma(&format!("quad, {label}"), st, n, exact);
    }
}

/// Step 6's table: the standard deviation of one sample of direct light (depth 1) at
/// the floor point under each light's centre of the two-light scene, 100 000 samples
/// per estimator, as a Markdown table the page includes.
#[test]
#[ignore = "over 1 s in a debug build: the release suite runs it (.ci/run: `cargo test --release --test course --test lessons -- --ignored`)"]
fn two_lights_direct_light_sigmas() {
    let Staged { scene, .. } = two_lights(8, 6).unwrap();
    let estimators = [
        ("cosine", Sampling::Cosine, SphereSampling::Area),
        ("light area", Sampling::NextEvent, SphereSampling::Area),
        ("MIS (area)", Sampling::Mis, SphereSampling::Area),
        ("light cone", Sampling::NextEvent, SphereSampling::Cone),
        ("MIS (cone)", Sampling::Mis, SphereSampling::Cone),
    ];
    let mut table = String::from(
        "| estimator | $\\sigma$ under the small light | $\\sigma$ under the large light |\n\
         |-----------|-----------:|----------:|\n",
    );
    let mut sigma = Vec::new();
    for (label, sampling, sphere_lights) in estimators {
        let s = Settings {
            sphere_lights,
            ..settings(sampling, Some(1), false)
        };
        let mut row = [0.0; 2];
        for (k, x) in [-1.5f32, 1.5].into_iter().enumerate() {
            let ray = Ray::new(Vec3::new(x, 0.01, 0.0), -Vec3::Y).unwrap();
            let mut rng = Rng::for_pixel(7, 0, 0);
            let n = 100_000;
            let (mean, sd) = stats(n, |_| radiance(&scene, ray, &mut rng, &s).x);
            row[k] = sd;
            eprintln!("two lights, x = {x}, {label}: mean {mean:.4} sigma {sd:.3}");
        }
        table += &format!("| {label} | {:.2} | {:.2} |\n", row[0], row[1]);
        sigma.push(row);
    }
    insta::assert_snapshot!("two_lights_sigmas", table);
    // The page compares MIS (area) with its two parts under the large light.
    assert!(
        sigma[2][1] < sigma[0][1].min(sigma[1][1]) / 3.0,
        "{sigma:?}"
    );
    // Its other claims over the table: under the small light cosine's sigma is about
    // ten times light area's, and MIS keeps light area's; under the large light
    // cosine and light area are "about equally" poor (within a factor 1.5).
    let small_ratio = sigma[0][0] / sigma[1][0];
    assert!((5.0..20.0).contains(&small_ratio), "{sigma:?}");
    assert!(
        (sigma[2][0] - sigma[1][0]).abs() < 0.1 * sigma[1][0],
        "{sigma:?}"
    );
    let large_ratio = sigma[0][1] / sigma[1][1];
    assert!((1.0 / 1.5..1.5).contains(&large_ratio), "{sigma:?}");
    // It also names the other measurement of cosine sampling that the listing's
    // comment quotes.
    let listing = std::fs::read_to_string("src/scenes/path_tracing.rs").unwrap();
    let page = page("10_6_mis.md");
    for (src, book) in [
        ("cosine sampling gives 9.9", "9.9 and"),
        ("cosine 1.69", "and 1.69"),
    ] {
        assert!(
            !page.contains(book) || listing.contains(src),
            "10_6_mis.md quotes the listing's {src:?}, which changed"
        );
    }
}
