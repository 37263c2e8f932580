//! Lesson 07, quadrics (chapter 07_5): general quadrics x^T Q x = 0, known answers for
//! the ellipsoid, cylinder and cone, hit points on the surface with the gradient as
//! normal, and the paraboloid ray parallel to its axis (STABILITY S9). Instances are in
//! `lesson_07_instances`, the capped cylinder in `lesson_07_cylinder`.
//!
//! Expected values are worked out by hand in the comments, or in f64 from the same f32
//! inputs; the measured S9 numbers are the snapshot `s9_table` (the page includes it)
//! and are printed with `eprintln!` (run with
//! `cargo test --test lessons lesson_07_quadrics -- --nocapture` to see them).

use crate::common::pages::{assert_page_says, sci};
use crate::common::{ray, unit_sphere};
use glam::{DVec3, Mat4, Vec3, Vec4};
use render_lessons::Error;
use render_lessons::error::Problem;
use render_lessons::ray::{Crossings, Interval, Ray};
use render_lessons::shapes::{Instance, Quadric, Shape};
use render_lessons::transform::Transform;

fn first(r: Crossings) -> Option<f32> {
    r.first_in(Interval::AHEAD)
}

fn rel(got: f32, want: f64) -> f64 {
    ((got as f64 - want) / want).abs()
}

/// x^T Q x in f64 at p, from the f32 entries of Q.
fn value64(q: &Mat4, p: DVec3) -> f64 {
    let m = q.to_cols_array_2d();
    let x = [p.x, p.y, p.z, 1.0];
    let mut s = 0.0;
    for (j, col) in m.iter().enumerate() {
        for (i, &v) in col.iter().enumerate() {
            s += x[i] * v as f64 * x[j];
        }
    }
    s
}

/// The gradient of x^T Q x at p by central differences in f64 (h = 1e-4; exact for a
/// quadratic up to rounding).
pub(crate) fn gradient_fd(f: impl Fn(DVec3) -> f64, p: DVec3) -> DVec3 {
    let h = 1e-4;
    let dx = |e: DVec3| (f(p + h * e) - f(p - h * e)) / (2.0 * h);
    DVec3::new(dx(DVec3::X), dx(DVec3::Y), dx(DVec3::Z))
}

pub(crate) fn p64(v: Vec3) -> DVec3 {
    v.as_dvec3()
}

// ---------------------------------------------------------------- S9

/// The S9 ray: from (0.3, 0.2, 5) along -Z tilted by `theta` towards +X, in the XZ
/// plane: d = (sin theta, 0, -cos theta).
fn s9_ray(theta: f32) -> Ray {
    ray([0.3, 0.2, 5.0], [theta.sin(), 0.0, -theta.cos()])
}

/// The first positive root in f64, from the same f32 origin and (normalised) direction.
///
/// Paraboloid x^2 + y^2 - z along o + t d: a = dx^2 + dy^2, b = 2 (ox dx + oy dy) - dz,
/// c = ox^2 + oy^2 - oz. At theta = 0: a = 0, b = 1, c = 0.13 - 5, so t = -c/b = 4.87
/// (the point z = 5 - t = 0.13 = 0.3^2 + 0.2^2 on the bowl).
fn s9_reference(r: &Ray) -> f64 {
    let (o, d) = (p64(r.origin()), p64(r.direction()));
    let a = d.x * d.x + d.y * d.y;
    let b = 2.0 * (o.x * d.x + o.y * d.y) - d.z;
    let c = o.x * o.x + o.y * o.y - o.z;
    if a == 0.0 {
        return -c / b;
    }
    let q = -0.5 * (b + b.signum() * (b * b - 4.0 * a * c).sqrt());
    [c / q, q / a]
        .into_iter()
        .filter(|&t| t > 0.0)
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn s9_paraboloid_ray_parallel_to_axis() {
    let p = Quadric::paraboloid().unwrap();
    assert!((s9_reference(&s9_ray(0.0)) - 4.87).abs() < 1e-6);
    // The page's table, in Markdown: theta, a, the f64 reference, the textbook root and
    // its relative error, the stable root's relative error.
    let mut table = String::from(
        "| $\\theta$ | $a$ | reference $t$ | textbook | its error | stable, error |\n\
         |---|---|---|---|---|---|\n",
    );
    for theta in [1e-3_f32, 1e-4, 1e-5, 1e-6, 0.0] {
        let r = s9_ray(theta);
        let want = s9_reference(&r);
        let (a, b, c) = p.coefficients(&r);
        let textbook = first(p.roots_textbook(&r));
        let stable = first(p.roots_stable(&r));
        let err = |t: Option<f32>| t.map_or(f64::INFINITY, |t| rel(t, want));
        eprintln!(
            "S9 theta = {theta:e}: a = {a:e}, b = {b}, c = {c}; reference t = {want:.9}; \
             textbook {textbook:?} (rel err {:.3e}); stable {stable:?} (rel err {:.3e})",
            err(textbook),
            err(stable)
        );
        let small = |x: f64| if x == 0.0 { "$0$".to_string() } else { sci(x) };
        let exponent = |x: f32| format!("{x:e}").split_once('e').unwrap().1.to_string();
        let theta_shown = match theta {
            0.0 => "$0$".to_string(),
            _ => format!("$10^{{{}}}$", exponent(theta)),
        };
        let (textbook_shown, textbook_err) = match textbook {
            Some(t) if err(textbook) >= 0.01 => {
                (format!("{t:.6}"), format!("${:.2}$", err(textbook)))
            }
            Some(t) => (format!("{t:.6}"), sci(err(textbook))),
            None => ("miss".to_string(), String::new()),
        };
        table += &format!(
            "| {theta_shown} | {} | {want:.6} | {textbook_shown} | {textbook_err} | {} |\n",
            small(f64::from(a)),
            sci(err(stable))
        );
        if theta == 1e-4 {
            let off = format!("The textbook is {:.0} % off", 100.0 * err(textbook));
            assert_page_says("07_5_quadrics.md", &off);
        }
        assert!(err(stable) <= 1e-6, "stable at theta = {theta}");
        if theta == 1e-4 {
            assert!(
                err(textbook) > 0.1,
                "textbook at theta = 1e-4: {textbook:?}"
            );
        }
        if theta <= 1e-5 {
            // Missing, or wildly off (more than 50%).
            assert!(
                err(textbook) > 0.5,
                "textbook at theta = {theta}: {textbook:?}"
            );
        }
        // The hit itself uses the stable roots.
        let h = Shape::Quadric(p).hit(&r, Interval::AHEAD).unwrap();
        assert!(rel(h.t, want) <= 1e-6);
    }
    insta::assert_snapshot!("s9_table", table);
}

// ---------------------------------------------------------------- known answers

/// `hit(ray).t` within `1e-6` relative of the hand-derived `want`.
fn assert_t(q: &Quadric, r: &Ray, t_min: f32, want: f64) {
    let h = q
        .hit(r, Interval::new(t_min, f32::INFINITY))
        .unwrap_or_else(|| panic!("{r:?} missed, expected t = {want}"));
    assert!(
        rel(h.t, want) <= 1e-6,
        "{r:?}: t = {}, expected {want}",
        h.t
    );
    // The textbook agrees wherever a is not small.
    let tb = q
        .roots_textbook(r)
        .first_in(Interval::new(t_min, f32::INFINITY))
        .unwrap();
    assert!(
        rel(tb, want) <= 1e-5,
        "textbook {r:?}: t = {tb}, expected {want}"
    );
}

#[test]
fn ellipsoid_known_answers() {
    // x^2/9 + y^2/4 + z^2 = 1.
    let e = Quadric::ellipsoid(Vec3::new(3.0, 2.0, 1.0)).unwrap();
    // Along +Z from z = -5: z = -1 at t = 4, z = +1 at t = 6.
    assert_t(&e, &ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]), 0.0, 4.0);
    assert_t(&e, &ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]), 5.0, 6.0);
    // Along +X from x = -10: x = -3 at t = 7. Along +Y from y = -10: y = -2 at t = 8.
    assert_t(&e, &ray([-10.0, 0.0, 0.0], [1.0, 0.0, 0.0]), 0.0, 7.0);
    assert_t(&e, &ray([0.0, -10.0, 0.0], [0.0, 1.0, 0.0]), 0.0, 8.0);
    // From the centre along (1, 1, 0)/sqrt 2: (s^2 / 2)(1/9 + 1/4) = 1, s =
    // sqrt(72/13).
    assert_t(
        &e,
        &ray([0.0, 0.0, 0.0], [1.0, 1.0, 0.0]),
        0.0,
        (72.0_f64 / 13.0).sqrt(),
    );
    let h = e
        .hit(&ray([-10.0, 0.0, 0.0], [1.0, 0.0, 0.0]), Interval::AHEAD)
        .unwrap();
    assert_eq!(h.normal, Vec3::new(-1.0, 0.0, 0.0));
    assert!(h.front_face);
    // Passing above the top (z = 1.5): misses.
    assert!(
        e.hit(&ray([0.0, 0.0, 1.5], [1.0, 0.0, 0.0]), Interval::AHEAD)
            .is_none()
    );
}

#[test]
fn cylinder_known_answers() {
    // x^2 + y^2 = 4.
    let c = Quadric::cylinder(2.0).unwrap();
    // Along +X at height z = 7 from x = -5: x = -2 at t = 3, x = 2 at t = 7.
    assert_t(&c, &ray([-5.0, 0.0, 7.0], [1.0, 0.0, 0.0]), 0.0, 3.0);
    assert_t(&c, &ray([-5.0, 0.0, 7.0], [1.0, 0.0, 0.0]), 4.0, 7.0);
    // From the axis along (1, 0, 1)/sqrt 2: x = s / sqrt 2 = 2 at s = 2 sqrt 2.
    assert_t(
        &c,
        &ray([0.0, 0.0, 0.0], [1.0, 0.0, 1.0]),
        0.0,
        2.0 * 2.0_f64.sqrt(),
    );
    // Parallel to the axis, inside or outside: a = b = 0, never a crossing, no NaN.
    for x in [1.0, 3.0] {
        let r = ray([x, 0.0, 0.0], [0.0, 0.0, 1.0]);
        assert!(c.roots_stable(&r).is_empty());
        assert!(c.roots_textbook(&r).is_empty());
        assert!(c.hit(&r, Interval::AHEAD).is_none());
    }
    // The normal is radial, outward: at (-2, 0, 7) it is -X, and from inside the
    // ray meets its back.
    let h = c
        .hit(
            &ray([-5.0, 0.0, 7.0], [1.0, 0.0, 0.0]),
            Interval::new(4.0, f32::INFINITY),
        )
        .unwrap();
    assert_eq!(h.normal, Vec3::X);
    assert!(!h.front_face);
}

#[test]
fn cone_known_answers_and_generator_parallel_ray() {
    // x^2 + y^2 = (z / 2)^2.
    let k = Quadric::cone(0.5).unwrap();
    // Along +X at z = 4 from x = -5: |x| = 2 at t = 3 and t = 7.
    assert_t(&k, &ray([-5.0, 0.0, 4.0], [1.0, 0.0, 0.0]), 0.0, 3.0);
    assert_t(&k, &ray([-5.0, 0.0, 4.0], [1.0, 0.0, 0.0]), 3.5, 7.0);
    // Slope 1, x^2 + y^2 = z^2, ray from (0, 0, 1) along (1, 0, -1)/sqrt 2: parallel to
    // a generator, so a = dx^2 - dz^2 = 0 exactly; b = 2 (-oz dz) = sqrt 2, c = -1, one
    // root t = -c/b = 1/sqrt 2, at (1/2, 0, 1/2).
    let k1 = Quadric::cone(1.0).unwrap();
    let r = ray([0.0, 0.0, 1.0], [1.0, 0.0, -1.0]);
    assert_eq!(k1.coefficients(&r).0, 0.0);
    let want = 0.5_f64.sqrt();
    match *k1.roots_stable(&r) {
        [t] => assert!(rel(t, want) <= 1e-6, "{t}"),
        ref other => panic!("expected one root, got {other:?}"),
    }
    assert!(k1.roots_textbook(&r).is_empty(), "the textbook loses it");
    let h = k1.hit(&r, Interval::AHEAD).unwrap();
    assert!((h.point - Vec3::new(0.5, 0.0, 0.5)).length() < 1e-6);
}

// ---------------------------------------------------------------- residual and normal

/// A hyperboloid of one sheet x^2 + y^2 - z^2 = 1, rotated and moved: a Q with every
/// entry non-zero, Q' = M^-T Q M^-1 (computed in f32, so symmetric only to rounding).
fn general_quadric() -> Quadric {
    let m = Transform::rotation_x(0.3)
        .then(Transform::rotation_z(0.7))
        .then(Transform::translation(0.5, -0.25, 1.0));
    let mi = m.inverse().unwrap().matrix();
    let q = Mat4::from_diagonal(Vec4::new(1.0, 1.0, -1.0, -1.0));
    Quadric::new(mi.transpose() * q * mi).unwrap()
}

#[test]
fn hit_points_on_surface_and_normals_are_gradients() {
    let shapes = [
        (
            "ellipsoid",
            Quadric::ellipsoid(Vec3::new(3.0, 2.0, 1.0)).unwrap(),
        ),
        ("cylinder", Quadric::cylinder(2.0).unwrap()),
        ("cone", Quadric::cone(0.5).unwrap()),
        ("paraboloid", Quadric::paraboloid().unwrap()),
        ("hyperboloid", general_quadric()),
    ];
    // Tolerances: the first-order distance |f| / |grad f| of the hit point from the
    // surface is at most 1e-5 (1 + |o| + t), a few f32 ulps of the numbers involved;
    // the unit normal is within 1e-4 of the finite-difference gradient's direction.
    let mut worst_distance = 0.0_f64;
    let mut worst_normal = 0.0_f64;
    let mut hits = 0;
    for (name, q) in shapes {
        let mq = q.matrix();
        for i in 0..12 {
            for j in 0..12 {
                let fi = i as f32;
                let fj = j as f32;
                let o = Vec3::new(-6.0 + 0.37 * fj, -4.0 + 0.61 * fi, 5.0 - 0.83 * fi);
                let d = Vec3::new(1.0 + 0.1 * fi, 0.35 * fj - 1.9, 0.45 * fi - 2.0);
                let r = Ray::new(o, d).unwrap();
                let Some(h) = q.hit(&r, Interval::AHEAD) else {
                    continue;
                };
                assert!(h.t.is_finite() && h.point.is_finite() && h.normal.is_finite());
                let p = p64(h.point);
                let g = gradient_fd(|x| value64(&mq, x), p);
                if g.length() < 1e-3 {
                    continue; // the cone's apex: no normal there
                }
                hits += 1;
                let dist = value64(&mq, p).abs() / g.length();
                let scale = 1.0 + o.length() as f64 + h.t as f64;
                worst_distance = worst_distance.max(dist / scale);
                assert!(dist <= 1e-5 * scale, "{name} {r:?}: distance {dist:e}");
                let n_err = (p64(h.normal) - g.normalize()).length();
                worst_normal = worst_normal.max(n_err);
                assert!(
                    n_err <= 1e-4,
                    "{name} {r:?}: normal {:?} vs {g:?}",
                    h.normal
                );
                assert!((h.normal.length() - 1.0).abs() < 1e-6);
                assert_eq!(h.front_face, r.direction().dot(h.normal) < 0.0);
            }
        }
    }
    eprintln!(
        "quadric hits: {hits}; worst |f|/|grad f| / (1 + |o| + t) = {worst_distance:e}; \
         worst normal error = {worst_normal:e}"
    );
    assert!(hits > 100, "too few hits ({hits}) to mean anything");
    let page = "07_5_quadrics.md";
    assert_page_says(page, &format!("Over {hits} hits"));
    assert_page_says(
        page,
        &format!("within {} of the scale", sci(worst_distance)),
    );
    assert_page_says(page, &format!("within {} of the true", sci(worst_normal)));
    // The three numbers as the page prints them.
    let printed = format!("{hits} {worst_distance:.1e} {worst_normal:.1e}");
    assert_eq!(printed, "288 1.7e-8 1.5e-7");
}

// ---------------------------------------------------------------- bad input

#[test]
fn bad_input_names_its_parameter() {
    let param = |r: Result<Quadric, Error>| r.unwrap_err().param().to_string();
    let mut nan = Mat4::IDENTITY;
    nan.x_axis.x = f32::NAN;
    assert_eq!(param(Quadric::new(nan)), "Q");
    assert_eq!(param(Quadric::new(Mat4::ZERO)), "Q");
    // Only the constant term: x^T Q x = 1 everywhere.
    let constant = Mat4::from_diagonal(Vec4::new(0.0, 0.0, 0.0, 1.0));
    assert_eq!(param(Quadric::new(constant)), "Q");
    // Q_01 = 1 but Q_10 = 0.
    let mut asym = Mat4::from_diagonal(Vec4::new(1.0, 1.0, 1.0, -1.0));
    asym.y_axis.x = 1.0;
    assert_eq!(param(Quadric::new(asym)), "Q");
    // Within rounding of symmetric: accepted. A plane (linear part only): accepted.
    asym.y_axis.x = 1e-7;
    assert!(Quadric::new(asym).is_ok());
    let mut plane = Mat4::ZERO;
    plane.z_axis.w = 0.5;
    plane.w_axis.z = 0.5;
    assert!(Quadric::new(plane).is_ok());

    for radii in [
        Vec3::new(1.0, 0.0, 1.0),
        Vec3::new(-1.0, 1.0, 1.0),
        Vec3::new(1.0, f32::NAN, 1.0),
        Vec3::new(1.0, 1.0, f32::INFINITY),
        Vec3::new(1e-30, 1.0, 1.0), // 1/r^2 overflows
        Vec3::new(1.0, 1e30, 1.0),  // 1/r^2 underflows to 0
    ] {
        assert_eq!(param(Quadric::ellipsoid(radii)), "radii", "{radii:?}");
    }
    for r in [0.0, -1.0, f32::NAN, f32::INFINITY, 1e30] {
        assert_eq!(param(Quadric::cylinder(r)), "radius", "{r}");
        assert_eq!(param(Quadric::cone(r)), "slope", "{r}");
    }
    let sphere = Shape::from(unit_sphere());
    let flat = Transform::scale(1.0, 0.0, 1.0);
    assert_eq!(
        Instance::new(sphere, flat).unwrap_err(),
        Error::Value {
            param: "to_world",
            problem: Problem::Singular
        }
    );
}

#[test]
fn a_ray_tangent_to_a_cone_finds_its_double_root() {
    // The Ray Tracer Challenge (ch. 13): the cone x^2 + z^2 = y^2 and the ray from
    // (0, 0, -5) along (1, 1, 1) touch at t = 15 / sqrt(3) (b^2 = 4ac exactly). In
    // f32 the rounded a, b and c put the discriminant a few ulps below 0.
    let cone = Quadric::cone_along(Vec3::Y, 1.0).unwrap();
    let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::ONE).unwrap();
    let xs = cone.crossings(&ray);
    let exact = 15.0 / 3f32.sqrt();
    assert_eq!(xs.len(), 2, "{:?}", xs.as_slice());
    for t in xs.iter() {
        assert!((t - exact).abs() < 1e-4, "{t} vs {exact}");
    }
}
