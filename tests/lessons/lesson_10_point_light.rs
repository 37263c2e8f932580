//! Lesson 10, the point light in the path tracer (chapter 10_5): a delta light that
//! every strategy finds by one shadow ray at every diffuse vertex, counted once. A
//! floor under a point light against the closed form, alone and beside a quad light;
//! lesson 08's ray caster and the path tracer at depth 1 on the still life; a shadow;
//! and the sky, which lights the path tracer's surfaces and not the ray caster's.

use crate::lesson_10_estimators::{s19_estimators, stats};
use crate::lesson_10_lights::{assert_floor_matches, polygon_light_on_floor};

use glam::Vec3;
use render_lessons::camera::Camera;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::lighting::AMBIENT;
use render_lessons::material::Material;
use render_lessons::pathtrace::{Sampling, Settings, radiance};
use render_lessons::ray::Ray;
use render_lessons::raycast::{lit, shadowless};
use render_lessons::render::render;
use render_lessons::rng::Rng;
use render_lessons::scene::{Object, PointLight, Scene};
use render_lessons::scenes::{still_life, still_life_pinhole};
use render_lessons::shapes::{Plane, Quad, Sphere};
use render_lessons::spawn::Offset;

/// The floor's albedo and the light of [`floor_under_a_point_light`].
const RHO: [f64; 3] = [0.8, 0.5, 0.25];
const LIGHT_AT: [f64; 3] = [0.5, 2.0, -0.5];
const INTENSITY: [f64; 3] = [3.0, 2.0, 1.0];

/// A floor (y = 0, albedo [`RHO`]) under the point light, in a black sky: no other
/// light at all.
fn floor_under_a_point_light() -> Scene {
    let floor = Object::diffuse(Plane::new(Vec3::ZERO, Vec3::Y).unwrap(), v(RHO));
    let light = PointLight::new(v(LIGHT_AT), v(INTENSITY));
    Scene::new(vec![floor], Vec3::ZERO)
        .and_then(|s| s.with_light(light))
        .unwrap()
}

fn v(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

/// The light a Lambertian floor point `p` (normal +Y, albedo `rho`) reflects from a
/// point light of radiant intensity `i_rad` at `light`, in f64: the rendering
/// equation's integral collapses to its one direction, f_r I_rad cos(theta) / d^2
/// with f_r = rho / pi (pbrt-v3 section 12.2).
fn point_light_on_floor(p: [f64; 3], rho: f64, light: [f64; 3], i_rad: f64) -> f64 {
    let to_l = [light[0] - p[0], light[1] - p[1], light[2] - p[2]];
    let d2 = to_l[0] * to_l[0] + to_l[1] * to_l[1] + to_l[2] * to_l[2];
    let cos = to_l[1] / d2.sqrt();
    rho / std::f64::consts::PI * i_rad * cos / d2
}

/// The camera ray straight down onto the floor point (x, 0, z), from 0.5 above.
fn down_at(x: f32, z: f32) -> Ray {
    Ray::new(Vec3::new(x, 0.5, z), -Vec3::Y).unwrap()
}

/// One path's radiance along `ray` (its random numbers seeded from the ray).
fn path_traced(scene: &Scene, ray: &Ray, s: &Settings) -> Vec3 {
    let o = ray.origin();
    let mut rng = Rng::for_pixel(7, o.x.to_bits(), o.z.to_bits());
    radiance(scene, *ray, &mut rng, s)
}

/// The floor lit by the point light alone, at points under it and far from it, by
/// each of the six direct-light estimators: no sample is random here (nothing but a
/// point light shines, and only its shadow ray finds it), so each gives the closed
/// form with `PointLight::radiant_intensity` = pi I, to f32 rounding. The ray caster
/// paints the same term (less its ambient k_a rho). The table is the book's.
#[test]
fn a_floor_under_a_point_light_is_the_closed_form_in_every_strategy() {
    let scene = floor_under_a_point_light();
    let pi = std::f64::consts::PI;
    let mut table = String::from(
        "| floor point (red channel) | $\\rho I\\cos\\theta/d^2$ in f64 | path tracer, 6 estimators | ray caster less $k_a\\rho$ |\n\
         |---|---:|---:|---:|\n",
    );
    for (x, z) in [(0.5f32, -0.5f32), (2.5, 1.5), (-3.5, 3.5), (10.5, -20.5)] {
        let p = [f64::from(x), 0.0, f64::from(z)];
        let exact: [f64; 3] = std::array::from_fn(|c| {
            point_light_on_floor(p, RHO[c], LIGHT_AT, pi * INTENSITY[c])
        });
        let ray = down_at(x, z);
        let mut found = Vec::new();
        for (label, s) in s19_estimators() {
            let l = path_traced(&scene, &ray, &s);
            for c in 0..3 {
                let got = f64::from(l[c]);
                assert!(
                    (got - exact[c]).abs() <= 1e-5 * exact[c],
                    "({x}, 0, {z}) {label}, channel {c}: {got} vs {}",
                    exact[c]
                );
            }
            found.push(format!("{:.6}", l.x));
        }
        found.dedup();
        // The ray caster's sum k_a rho + direct is rounded at the size of k_a rho,
        // and taking k_a rho off again leaves that rounding: a few ulps of it.
        let total = lit(&scene, &ray, Offset::default());
        let cast = total - AMBIENT * v(RHO);
        for c in 0..3 {
            let got = f64::from(cast[c]);
            let ulps = 4.0 * f64::from(f32::EPSILON * total[c]);
            assert!(
                (got - exact[c]).abs() <= 1e-5 * exact[c] + ulps,
                "{got} vs {}",
                exact[c]
            );
        }
        table += &format!(
            "| ({x}, 0, {z}) | {:.6} | {} | {:.6} |\n",
            exact[0],
            found.join(" / "),
            cast.x
        );
    }
    insta::assert_snapshot!("point_light_floor", table);
}

/// Counted once beside an area light: the floor also under S19's unit square light
/// (two-sided, radiance 1, at height 1), and a point light off to the side; each of
/// the six estimators within 3 sigma / sqrt(N) of the sum of the two closed forms
/// (Lambert's polygon formula and the point light's), at points where neither light
/// shadows the other.
#[test]
fn a_point_light_beside_a_quad_light_is_counted_once_in_every_strategy() {
    let floor = Object::diffuse(Plane::new(Vec3::ZERO, Vec3::Y).unwrap(), Vec3::ONE);
    let quad = Quad::new(Vec3::new(-0.5, 1.0, -0.5), Vec3::Z, Vec3::X).unwrap();
    let lamp = Object::emitting(quad, Material::BLACK, Vec3::ONE);
    let (at, intensity) = ([3.0, 2.0, 0.0], 0.5);
    let scene = Scene::new(vec![floor, lamp], Vec3::ZERO)
        .and_then(|s| {
            s.with_light(PointLight::new(v(at), Vec3::splat(intensity as f32)))
        })
        .unwrap();
    let corners = [
        [-0.5, 1.0, -0.5],
        [-0.5, 1.0, 0.5],
        [0.5, 1.0, 0.5],
        [0.5, 1.0, -0.5],
    ];
    let points = [(0.0, 0.0), (0.0, 3.0), (2.0, -1.0)];
    let i_rad = std::f64::consts::PI * intensity;
    assert_floor_matches(&scene, "quad and point", &points, &s19_estimators(), |p| {
        polygon_light_on_floor(p, 1.0, &corners, 1.0)
            + point_light_on_floor(p, 1.0, at, i_rad)
    });
}

/// The still life of lesson 08 under a black sky, ray cast and path traced at depth
/// 1 (direct light only) through the same pixel centres: every pixel of the ray
/// caster is the path tracer's plus k_a rho (rho the albedo `shadowless` paints,
/// 0 for the sky), in every strategy, lit floor, shadows and spheres alike. Both
/// trace the same shadow ray from the same point, so they agree on every shadow.
#[test]
fn the_ray_caster_and_the_path_tracer_at_depth_1_light_the_still_life_alike() {
    let sunny = still_life(Vec3::ZERO).unwrap();
    let scene = Scene::new(sunny.objects().to_vec(), Vec3::ZERO)
        .and_then(|s| s.with_light(sunny.point_light().unwrap()))
        .unwrap();
    let camera: Camera = still_life_pinhole(64, 36).unwrap();
    let cast = render(&camera, |ray| lit(&scene, ray, Offset::default())).unwrap();
    let albedo = render(&camera, |ray| shadowless(&scene, ray)).unwrap();
    for sampling in Sampling::ALL {
        let s = Settings {
            sampling,
            max_depth: Some(1),
            russian_roulette: false,
            ..Settings::default()
        };
        let traced = render(&camera, |ray| path_traced(&scene, ray, &s)).unwrap();
        let (mut lit_pixels, mut shadowed) = (0, 0);
        for (x, y) in pixels(&cast) {
            let (c, t, rho) = (px(&cast, x, y), px(&traced, x, y), px(&albedo, x, y));
            let expected = t + AMBIENT * rho;
            assert!(
                (c - expected).abs().max_element() <= 1e-5 * c.max_element().max(1.0),
                "{sampling:?} pixel ({x}, {y}): ray caster {c} vs path tracer {t} + k_a {rho}"
            );
            if rho != Vec3::ZERO {
                if t == Vec3::ZERO {
                    shadowed += 1
                } else {
                    lit_pixels += 1
                }
            }
        }
        assert!(
            lit_pixels > 500 && shadowed > 50,
            "{lit_pixels} lit, {shadowed} in shadow"
        );
    }
}

fn pixels(image: &Framebuffer) -> impl Iterator<Item = (u32, u32)> {
    let width = image.width();
    (0..image.height()).flat_map(move |y| (0..width).map(move |x| (x, y)))
}

fn px(image: &Framebuffer, x: u32, y: u32) -> Vec3 {
    image.get(x, y).unwrap()
}

/// A ball between the point light and the floor: the floor point on the line from
/// the light through the ball's centre gets no light from it in any strategy, nor
/// from the ray caster (only k_a rho); a point beside the shadow gets the closed form.
#[test]
fn a_point_light_behind_a_ball_casts_a_shadow_in_every_strategy() {
    let ball = Object::diffuse(
        Sphere::new(Vec3::new(0.5, 1.0, -0.5), 0.3).unwrap(),
        Vec3::ONE,
    );
    let mut objects = floor_under_a_point_light().objects().to_vec();
    objects.push(ball);
    let light = PointLight::new(v(LIGHT_AT), v(INTENSITY));
    let scene = Scene::new(objects, Vec3::ZERO)
        .and_then(|s| s.with_light(light))
        .unwrap();
    // Under the light, the ball; a ray from 0.5 above the floor is below the ball.
    let (shadow, beside) = (down_at(0.5, -0.5), down_at(2.5, 1.5));
    let pi = std::f64::consts::PI;
    let exact =
        point_light_on_floor([2.5, 0.0, 1.5], RHO[0], LIGHT_AT, pi * INTENSITY[0]);
    for (label, s) in s19_estimators() {
        assert_eq!(path_traced(&scene, &shadow, &s), Vec3::ZERO, "{label}");
        let got = f64::from(path_traced(&scene, &beside, &s).x);
        assert!(
            (got - exact).abs() <= 1e-5 * exact,
            "{label}: {got} vs {exact}"
        );
    }
    assert_eq!(lit(&scene, &shadow, Offset::default()), AMBIENT * v(RHO));
}

/// The sky is light for the path tracer only: a floor of albedo rho under a uniform
/// sky L and nothing else reflects rho L (the cosine integrates to pi against f_r =
/// rho / pi), which the path tracer finds at depth 1 (exactly with cosine-sampled
/// bounces, whose factor is rho; the uniform hemisphere's mean within 4 sigma); the
/// ray caster shows the sky where its rays escape and paints the floor k_a rho.
#[test]
fn the_sky_lights_the_path_tracers_floor_and_not_the_ray_casters() {
    let (rho, sky) = (Vec3::new(0.8, 0.5, 0.25), Vec3::new(0.6, 0.7, 0.9));
    let floor = Object::diffuse(Plane::new(Vec3::ZERO, Vec3::Y).unwrap(), rho);
    let scene = Scene::new(vec![floor], sky).unwrap();
    let ray = down_at(0.3, -0.7);
    for (label, s) in s19_estimators() {
        if s.sampling == Sampling::UniformHemisphere {
            let (n, mut rng) = (20_000, Rng::for_pixel(7, 0, 0));
            let (mean, sigma) = stats(n, |_| radiance(&scene, ray, &mut rng, &s).x);
            let exact = f64::from(rho.x * sky.x);
            assert!(
                (mean - exact).abs() <= 4.0 * sigma / f64::from(n).sqrt(),
                "{mean}"
            );
        } else {
            let l = path_traced(&scene, &ray, &s);
            assert!((l - rho * sky).abs().max_element() <= 1e-6, "{label}: {l}");
        }
    }
    assert_eq!(lit(&scene, &ray, Offset::default()), AMBIENT * rho);
    let up = Ray::new(Vec3::Y, Vec3::Y).unwrap();
    assert_eq!(lit(&scene, &up, Offset::default()), sky);
}
