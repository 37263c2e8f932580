//! Lesson 10, sampling the lights (chapters 10_5 and 10_6): direct light against the
//! closed form of a sphere and of a quad light near and far, shadow rays that must not
//! stop at the light they aim at (STABILITY S20), the strategies agreeing with
//! indirect light, a light sample's pdf, and the quad light's hits.

use crate::common;
use crate::common::pages::assert_quotes;
use crate::lesson_10_estimators::{
    pixel_samples, s19_estimators, square_light_exact, square_light_scene, stats,
};
use crate::lesson_10_path_tracing::settings;

use glam::{Vec2, Vec3};
use render_lessons::pathtrace::light::LightShape;
use render_lessons::pathtrace::{Sampling, Settings, SphereSampling, radiance};
use render_lessons::ray::{Interval, Ray};
use render_lessons::rng::Rng;
use render_lessons::sampling::grid;
use render_lessons::scene::Scene;
use render_lessons::scenes::path_tracing::{Staged, two_lights};
use render_lessons::shapes::{Quad, Shape, Sphere};
use render_lessons::spawn::{Offset, SHADOW_EPSILON};

// ---------------------------------------------------------------- S20

/// The light a Lambertian floor point `p` (normal +Y, albedo `rho`) reflects from a
/// uniform sphere light wholly above its horizon: rho L (r/d)^2 cos theta_c, d the
/// distance to the centre and theta_c the angle of the centre from the normal (the
/// sphere's irradiance pi L (r/d)^2 cos theta_c, times rho / pi). In f64.
fn sphere_light_on_floor(
    p: [f64; 3],
    rho: f64,
    centre: [f64; 3],
    r: f64,
    radiance: f64,
) -> f64 {
    let to_c = [centre[0] - p[0], centre[1] - p[1], centre[2] - p[2]];
    let d2 = to_c[0] * to_c[0] + to_c[1] * to_c[1] + to_c[2] * to_c[2];
    let cos_c = to_c[1] / d2.sqrt();
    rho * radiance * r * r / d2 * cos_c
}

/// The light a Lambertian floor point `p` (normal +Y, albedo `rho`) reflects from a
/// two-sided uniform polygon light of radiance L with the corners `poly`: Lambert's
/// formula for a polygon, E = (L / 2) |sum_i Theta_i n . g_i|, Theta_i the angle
/// that edge i subtends at p and g_i the unit normal of the plane through p and that
/// edge (Arvo 1995, "Applications of Irradiance Tensors", eq. 4), times rho / pi.
pub(crate) fn polygon_light_on_floor(
    p: [f64; 3],
    rho: f64,
    poly: &[[f64; 3]],
    radiance: f64,
) -> f64 {
    let sub = |a: [f64; 3]| [a[0] - p[0], a[1] - p[1], a[2] - p[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let mut sum = 0.0;
    for i in 0..poly.len() {
        let (a, b) = (sub(poly[i]), sub(poly[(i + 1) % poly.len()]));
        let c = cross(a, b);
        let theta = dot(c, c).sqrt().atan2(dot(a, b));
        sum += theta * c[1] / dot(c, c).sqrt();
    }
    rho / std::f64::consts::PI * radiance / 2.0 * sum.abs()
}

/// The light-sampling estimators of S20, every strategy that traces a shadow ray to
/// a point on a light, with both sphere samplers: S19's less the two that sample no
/// light (light area, light cone, MIS with each, in that order).
fn s20_estimators() -> Vec<(&'static str, Settings)> {
    s19_estimators()
        .into_iter()
        .filter(|(_, s)| matches!(s.sampling, Sampling::NextEvent | Sampling::Mis))
        .collect()
}

/// Mean and sigma of `n` samples of direct light (depth 1) at the floor point
/// (x, 0, z), seen by a ray straight down from 0.5 above it.
fn floor_point_samples(
    scene: &Scene,
    s: &Settings,
    x: f32,
    z: f32,
    n: u32,
) -> (f64, f64) {
    let ray = Ray::new(Vec3::new(x, 0.5, z), -Vec3::Y).unwrap();
    let mut rng = Rng::for_pixel(20, x.to_bits(), z.to_bits());
    stats(n, |_| radiance(scene, ray, &mut rng, s).x)
}

/// Direct light at each floor point (x, 0, z) of `points`, by each of `estimators`,
/// against `exact` at that point: within 3 sigma / sqrt(N) for N = 40 000 samples.
pub(crate) fn assert_floor_matches(
    scene: &Scene,
    name: &str,
    points: &[(f32, f32)],
    estimators: &[(&str, Settings)],
    exact: impl Fn([f64; 3]) -> f64,
) {
    let n = 40_000;
    for &(x, z) in points {
        let exact = exact([f64::from(x), 0.0, f64::from(z)]);
        for (label, s) in estimators {
            let st = floor_point_samples(scene, s, x, z, n);
            eprintln!(
                "S20 {name} ({x}, 0, {z}) {label}: mean {:.6e} exact {exact:.6e} ({:+.3} %)",
                st.0,
                100.0 * (st.0 / exact - 1.0)
            );
            assert_within_3_sigma(
                &format!("{name} ({x}, 0, {z}), {label}"),
                st,
                n,
                exact,
            );
        }
    }
}

/// `|mean - exact| <= 3 sigma / sqrt(n)`, relative error in the message.
fn assert_within_3_sigma(label: &str, (mean, sigma): (f64, f64), n: u32, exact: f64) {
    let bound = 3.0 * sigma / f64::from(n).sqrt() + 1e-7 * exact;
    assert!(
        (mean - exact).abs() <= bound,
        "{label}: mean {mean} vs exact {exact} ({:+.3} %), 3 sigma/sqrt(N) = {bound}",
        100.0 * (mean / exact - 1.0)
    );
}

/// STABILITY S20: a shadow ray aimed at a point sampled on a light must not be
/// stopped by that light. The two-light scene's floor (albedo 0.5) near its lights
/// and far from them, against the closed form of each sphere's light.
#[test]
fn s20_direct_light_on_the_two_light_floor_matches_the_closed_form_near_and_far() {
    let Staged { scene, .. } = two_lights(8, 6).unwrap();
    let lights = [([-1.5, 1.0, 0.0], 0.05, 400.0), ([1.5, 1.5, 0.0], 1.0, 1.0)];
    let points = [(0.0, 3.0), (0.0, -5.0), (-10.0, -20.0), (0.0, -40.0)];
    assert_floor_matches(&scene, "two lights", &points, &s20_estimators(), |p| {
        lights
            .iter()
            .map(|&(c, r, l)| sphere_light_on_floor(p, 0.5, c, r, l))
            .sum()
    });
}

/// S20 for the other light shape: a two-sided unit square light at height 1 over a
/// white floor, near and far, against Lambert's polygon formula (the sphere sampler
/// does not reach a quad, so the area rows are enough).
#[test]
fn s20_direct_light_from_a_quad_matches_the_closed_form_near_and_far() {
    let scene = square_light_scene();
    let corners = [
        [-0.5, 1.0, -0.5],
        [-0.5, 1.0, 0.5],
        [0.5, 1.0, 0.5],
        [0.5, 1.0, -0.5],
    ];
    // Under the centre, Lambert's polygon formula is S19's form factor.
    let centre = polygon_light_on_floor([0.0; 3], 1.0, &corners, 1.0);
    assert!(
        (centre - square_light_exact(1.0, 1.0)).abs() < 1e-12,
        "{centre}"
    );
    let points = [
        (0.0, 0.0),
        (0.0, 3.0),
        (0.0, -5.0),
        (-10.0, -20.0),
        (0.0, -40.0),
    ];
    // The sphere sampler does not reach a quad: the area rows are enough.
    let estimators: Vec<_> = s20_estimators().into_iter().step_by(2).collect();
    assert_floor_matches(&scene, "quad", &points, &estimators, |p| {
        polygon_light_on_floor(p, 1.0, &corners, 1.0)
    });
}

/// S20's table: the share of light samples on the cap of the sphere that the floor
/// point sees whose shadow ray is stopped, on the two-light floor where nothing
/// stands between floor and lights, so that every stopped ray was stopped by the
/// light it aims at. The shadow ray ends at the
/// light point's error bound alone, or `SHADOW_EPSILON` of the way short of it
/// (`Start::ray_to`); 64 x 64 light samples per row, both offsets, both samplers.
#[test]
fn s20_shadow_rays_ended_at_the_error_bound_alone_find_their_own_light() {
    let Staged { scene, .. } = two_lights(8, 6).unwrap();
    let mut table = String::from(
        "| floor point | light | sampler | error-bound offset, end at the bound | with `SHADOW_EPSILON` | scaled offset, end at the bound | with `SHADOW_EPSILON` |\n\
         |---|---|---|---:|---:|---:|---:|\n",
    );
    let mut worst = [0.0f64; 4];
    for (x, z) in [(0.0f32, 3.0f32), (0.0, -5.0), (-10.0, -20.0), (0.0, -40.0)] {
        let down = Ray::new(Vec3::new(x, 0.5, z), -Vec3::Y).unwrap();
        let hit = scene.closest(&down, Interval::AHEAD).unwrap().hit;
        for (light, name) in [(1, "small"), (2, "large")] {
            for (sampler, sampler_name) in [
                (SphereSampling::Area, "area"),
                (SphereSampling::Cone, "cone"),
            ] {
                let shape =
                    LightShape::new(&scene.objects()[light].shape, sampler).unwrap();
                let mut cells = [0.0f64; 4];
                for (k, (offset, share)) in [
                    (Offset::ErrorBound, 0.0),
                    (Offset::ErrorBound, SHADOW_EPSILON),
                    (Offset::Scaled, 0.0),
                    (Offset::Scaled, SHADOW_EPSILON),
                ]
                .into_iter()
                .enumerate()
                {
                    let from = offset.start(hit.point, hit.error, Vec3::Y);
                    let (mut aimed, mut stopped) = (0u32, 0u32);
                    for u in grid(64) {
                        let Some(y) = shape.sample(from.point, u) else {
                            continue;
                        };
                        // Area samples on the far side of a sphere are blocked by
                        // its near side, rightly: only the cap the point sees counts.
                        if y.normal.dot(from.point - y.point) <= 0.0 {
                            continue;
                        }
                        let to = offset.start(y.point, y.error, y.normal);
                        let shadow = from.ray_to_short_by(to, share).unwrap();
                        aimed += 1;
                        stopped += u32::from(scene.occluded(&shadow.ray, shadow.range));
                    }
                    cells[k] = 100.0 * f64::from(stopped) / f64::from(aimed);
                    worst[k] = worst[k].max(cells[k]);
                }
                table += &format!(
                    "| ({x}, 0, {z}) | {name} | {sampler_name} | {:.2} % | {:.2} % | {:.2} % | {:.2} % |\n",
                    cells[0], cells[1], cells[2], cells[3]
                );
            }
        }
    }
    insta::assert_snapshot!("s20_shadow_ray_far_end", table);
    // Ended at the error bound alone, the error-bound offset loses samples to the
    // light itself; ended SHADOW_EPSILON short, neither offset loses any.
    assert!(worst[0] > 1.0, "{worst:?}");
    assert_eq!((worst[1], worst[3]), (0.0, 0.0), "{table}");
    // The summary of "Where methods fail" quotes the worst row of the first column.
    assert_quotes(
        "where_methods_fail.md",
        &format!("ended at its error bound: {:.2} % stopped by it", worst[0]),
        worst[0],
    );
}

#[test]
fn strategies_agree_on_the_two_light_scene_with_indirect_light() {
    let Staged { scene, camera } = two_lights(8, 6).unwrap();
    let n = 30_000;
    let estimates: Vec<(Sampling, (f64, f64))> =
        [Sampling::Cosine, Sampling::NextEvent, Sampling::Mis]
            .into_iter()
            .map(|sampling| {
                let s = settings(sampling, Some(4), true);
                (sampling, pixel_samples(&scene, &camera, &s, n, 9))
            })
            .collect();
    for (a, (ma, sa)) in &estimates {
        for (b, (mb, sb)) in &estimates {
            let bound = 4.0 * (sa * sa + sb * sb).sqrt() / f64::from(n).sqrt();
            assert!(
                (ma - mb).abs() <= bound,
                "{a:?} {ma} vs {b:?} {mb} (bound {bound})"
            );
        }
    }
}

/// MIS needs the density a light sample reports and the density recomputed for
/// the same point (as when a BRDF sample hits it) to agree.
#[test]
fn light_sample_pdf_matches_light_pdf() {
    common::for_cases(11, 256, |rng| {
        let (p, u) = (rng.point(3.0), Vec2::new(rng.next_f32(), rng.next_f32()));
        let (area, quad) = (rng.coin(), rng.coin());
        let strategy = if area {
            SphereSampling::Area
        } else {
            SphereSampling::Cone
        };
        let shape = if quad {
            Shape::Quad(
                Quad::new(Vec3::new(-0.5, 1.0, -0.5), Vec3::Z, Vec3::X).unwrap(),
            )
        } else {
            Shape::Sphere(Sphere::new(Vec3::new(0.2, 0.5, -0.1), 0.7).unwrap())
        };
        let light = LightShape::new(&shape, strategy).unwrap();
        if let Some(y) = light.sample(p, u) {
            let again = light.pdf(p, y.point, y.normal);
            assert!(y.pdf.is_finite() && y.pdf > 0.0);
            assert!(
                (again - y.pdf).abs() <= 1e-3 * y.pdf,
                "{} vs {}",
                again,
                y.pdf
            );
        }
    });
}

#[test]
fn cone_samples_almost_never_miss_the_sphere() {
    // A cone direction that misses by rounding at the rim gives no sample (a tiny
    // bias); count how often.
    let sphere = Sphere::new(Vec3::new(0.0, 5.0, 0.0), 0.01).unwrap();
    let cone = LightShape::Sphere(sphere, SphereSampling::Cone);
    let mut rng = Rng::for_pixel(1, 2, 3);
    let n = 200_000;
    let misses = (0..n)
        .filter(|_| cone.sample(Vec3::ZERO, rng.next_vec2()).is_none())
        .count();
    eprintln!("cone misses: {misses} of {n}");
    assert!(misses * 10_000 < n, "{misses} of {n}");
}
