//! Lesson 07: ray / primitive intersection. The lesson's own table (its snapshots),
//! the naive and the robust method on its rays, every shape's hit points on their
//! surface (a property over random rays), bad input, and the numbers the pages work
//! out. The shapes one by one, with the STABILITY cases of each: `lesson_07_sphere`
//! (S1, S2), `lesson_07_plane` (S3), `lesson_07_box` (S6, S8), `lesson_07_triangle`
//! (S4, S5, S7), `lesson_07_quadrics` (S9), `lesson_07_instances`,
//! `lesson_07_cylinder`.
//!
//! Expected values are worked out by hand (or in f64 from the same f32 inputs), not
//! by the code under test. Failure rates are measured, never hard-coded: the tests
//! assert that the naive method is wrong often and the robust one (almost) never.

use crate::common;
use crate::common::pages::assert_quotes;

use crate::examples::intersections as lesson;

use glam::{DVec3, Vec3};
use render_lessons::Error;
use render_lessons::course::diagram::cross_section;
use render_lessons::error::Problem;
use render_lessons::ray::{ClosedSpan, Interval, Ray};
use render_lessons::shapes::{Aabb, Plane, Shape, Sphere, Triangle};

// ---------------------------------------------------------------- bad input

#[test]
fn bad_input_names_the_parameter() {
    for r in [0.0, -1.0] {
        assert_eq!(
            Sphere::new(Vec3::ZERO, r),
            Err(Error::Value {
                param: "radius",
                problem: Problem::NotPositive { value: r }
            })
        );
    }
    assert_eq!(
        Sphere::new(Vec3::ZERO, f32::NAN).unwrap_err().param(),
        "radius"
    );
    assert_eq!(Sphere::new(Vec3::NAN, 1.0).unwrap_err().param(), "centre");
    assert_eq!(
        Plane::new(Vec3::ZERO, Vec3::ZERO),
        Err(Error::Value {
            param: "normal",
            problem: Problem::ZeroLength
        })
    );
    assert_eq!(
        Plane::new(Vec3::INFINITY, Vec3::Y).unwrap_err().param(),
        "point"
    );
    assert_eq!(
        Aabb::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, 1.0, 1.0)),
        Err(Error::Value {
            param: "box",
            problem: Problem::EmptyRange { min: 2.0, max: 1.0 }
        })
    );
    assert_eq!(Aabb::new(Vec3::ZERO, Vec3::NAN).unwrap_err().param(), "max");
    // Zero thickness is allowed.
    assert!(Aabb::new(Vec3::ZERO, Vec3::new(1.0, 0.0, 1.0)).is_ok());
    // Degenerate triangles: collinear, and two equal corners.
    let collinear = Triangle::new(Vec3::ZERO, Vec3::X, 2.0 * Vec3::X);
    assert_eq!(
        collinear,
        Err(Error::Value {
            param: "area",
            problem: Problem::NotPositive { value: 0.0 }
        })
    );
    assert_eq!(
        Triangle::new(Vec3::Y, Vec3::Y, Vec3::X)
            .unwrap_err()
            .param(),
        "area"
    );
    assert_eq!(
        Triangle::new(Vec3::ZERO, Vec3::X, Vec3::NAN)
            .unwrap_err()
            .param(),
        "v2"
    );
}

// ---------------------------------------------------------------- properties

/// A ray from a random point aimed at another, so that many of them hit the shapes
/// near the origin; directions with exact zero components are mixed in on purpose.
/// None where the two points coincide.
fn aimed_ray(rng: &mut common::Rng) -> Option<Ray> {
    let (o, target, zero_mask) = (rng.point(50.0), rng.point(50.0), rng.below(0, 8));
    let mut d = target - o;
    for i in 0..3 {
        if zero_mask & (1 << i) != 0 {
            d[i] = 0.0;
        }
    }
    Ray::new(o, d).ok()
}

fn no_nan(h: &render_lessons::shapes::Hit) -> bool {
    h.t.is_finite() && h.point.is_finite() && h.normal.is_finite()
}

/// Tolerance: 1e-5 times the size of the numbers involved (1 + |o| + |t| + |c|),
/// about 100 f32 roundings; a grazing plane hit can lie 1e4 away.
#[test]
fn hit_points_lie_on_their_surface() {
    common::for_cases(7, 256, |rng| {
        let Some(r) = aimed_ray(rng) else { return };
        let (c, radius, n) = (rng.point(50.0), rng.range(0.1, 20.0), rng.point(50.0));
        let corners = (rng.point(50.0), rng.point(50.0), rng.point(50.0));
        let scale = |t: f32| {
            1.0 + r.origin().abs().max_element() + t.abs() + c.abs().max_element()
        };
        let tol = |t: f32| 1e-5 * scale(t);
        let sphere = Sphere::new(c, radius).unwrap();
        for (t0, t1) in [
            sphere.roots_stable(&r).pair(),
            sphere.roots_textbook(&r).pair(),
        ]
        .into_iter()
        .flatten()
        {
            assert!(t0.is_finite() && t1.is_finite() && t0 <= t1);
        }
        if let Some(h) = sphere.hit(&r, Interval::AHEAD) {
            assert!(no_nan(&h));
            assert!(
                ((h.point - c).length() - radius).abs() < tol(h.t),
                "sphere {:?}",
                h
            );
            assert!((h.normal.length() - 1.0).abs() < 1e-5);
        }
        if let Ok(plane) = Plane::new(c, n)
            && let Some(h) = plane.hit(&r, Interval::AHEAD)
        {
            assert!(no_nan(&h));
            assert!(
                (h.point - c).dot(plane.normal()).abs() < tol(h.t),
                "plane {:?}",
                h
            );
        }
        let (a, b, e) = corners;
        let bx = Aabb::new(a.min(b), a.max(b)).unwrap();
        if let Some(ClosedSpan { t0, t1 }) = bx.slab(&r, Interval::AHEAD) {
            assert!(!t0.is_nan() && !t1.is_nan() && t0 <= t1);
        }
        if let Some(h) = bx.hit(&r, Interval::AHEAD) {
            assert!(no_nan(&h));
            let inside = h.point.cmpge(bx.min() - tol(h.t)).all()
                && h.point.cmple(bx.max() + tol(h.t)).all();
            let on_face =
                (0..3).any(|i| h.point[i] == bx.min()[i] || h.point[i] == bx.max()[i]);
            assert!(inside && on_face, "box {:?}", h);
        }
        if let Ok(tri) = Triangle::new(a, b, e) {
            if let Some(h) = tri.hit(&r, Interval::AHEAD) {
                assert!(no_nan(&h));
                assert!(
                    (h.point - a).dot(tri.normal()).abs() < tol(h.t),
                    "triangle {:?}",
                    h
                );
                assert!((h.point - r.at(h.t)).length() < tol(h.t));
            }
            if let Some(c) = tri.moller_trumbore(&r, Interval::AHEAD) {
                assert!(c.t.is_finite() && c.b.iter().all(|b| b.is_finite()));
            }
        }
    });
}

#[test]
fn numbers() {
    let cases = lesson::cases().unwrap();
    insta::assert_snapshot!("numbers", lesson::numbers(&cases));
}

/// The lesson's loop: the naive and the robust method agree on the five rays of the
/// lesson, and part on the two hard rays (S1: the textbook roots of a sphere 10^4
/// radii away merge into one; S9: 22 % off near the paraboloid's axis).
#[test]
fn naive_and_robust() {
    let (cases, hard) = (lesson::cases().unwrap(), lesson::hard_cases().unwrap());
    let table = lesson::naive_and_robust(cases.iter().chain(&hard));
    insta::assert_snapshot!("naive_and_robust", table);
    let agree = |a: &[f32], b: &[f32]| {
        a.len() == b.len()
            && a.iter()
                .zip(b)
                .all(|(x, y)| (x - y).abs() <= 1e-5 * y.abs())
    };
    for case in &cases {
        let [(_, naive), (_, robust)] = lesson::methods(&case.shape, &case.ray);
        assert!(
            agree(&naive, &robust),
            "{}: {naive:?} {robust:?}",
            case.name
        );
        assert!(!robust.is_empty(), "{}", case.name);
    }
    for case in &hard {
        let [(_, naive), (_, robust)] = lesson::methods(&case.shape, &case.ray);
        assert!(
            !agree(&naive, &robust),
            "{}: {naive:?} {robust:?}",
            case.name
        );
        // The robust nearest root ahead is the exact one, to f32's rounding.
        let exact = match case.name {
            "sphere 10^4 away" => {
                let aim = case.ray.direction().as_dvec3();
                (1e4 * aim.z.abs() - (1.0 - (1e4 * aim.x).powi(2)).sqrt()) as f32
            }
            _ => 4.869708,
        };
        let ahead = robust.iter().copied().find(|&t| t > 0.0).unwrap();
        assert!(
            (ahead - exact).abs() <= 1e-6 * exact,
            "{}: {robust:?}",
            case.name
        );
    }
}

#[test]
fn lesson_crossings_lie_on_their_surfaces() {
    // Each crossing the lesson lists, put back into r(t), is on the surface: checked
    // with each shape's own implicit equation, written here independently.
    for case in lesson::cases().unwrap() {
        for &t in case.shape.crossings(&case.ray).iter() {
            let p = case.ray.at(t);
            let residual = match case.name {
                "sphere" => p.length() - 1.0,
                "plane" => (p - Vec3::new(0.0, -0.5, 0.0))
                    .dot(Vec3::new(1.0, 2.0, 0.0).normalize()),
                "box" => p.abs().max_element() - 1.0,
                "triangle" => p.x - 1.0,
                "paraboloid" => p.x * p.x + p.y * p.y - p.z,
                other => panic!("unknown case {other}"),
            };
            assert!(
                residual.abs() < 1e-5,
                "{}: t = {t}, residual {residual}",
                case.name
            );
        }
    }
}

#[test]
fn lesson_crossings_are_each_shapes_own_roots() {
    // `crossings` asks `hit` again and again; it must list exactly the roots of each
    // shape's own root finder over the whole line, the box's entry and exit included.
    let all = (f32::NEG_INFINITY, f32::INFINITY);
    for case in lesson::cases().unwrap() {
        let (shape, ray) = (&case.shape, &case.ray);
        let roots = match shape {
            Shape::Sphere(s) => s.roots_stable(ray).to_vec(),
            Shape::Plane(p) => p.t(ray).into_iter().collect(),
            Shape::Aabb(b) => b
                .slab(ray, Interval::new(all.0, all.1))
                .map_or(vec![], |s| vec![s.t0, s.t1]),
            Shape::Triangle(t) => t
                .watertight(ray, Interval::new(all.0, all.1))
                .map(|h| vec![h.t])
                .unwrap_or_default(),
            Shape::Quadric(q) => q.roots_stable(ray).to_vec(),
            _ => panic!("{}: no root finder listed", case.name),
        };
        assert_eq!(shape.crossings(ray).as_slice(), roots, "{}", case.name);
        assert!(
            !roots.is_empty(),
            "{}: the lesson's ray crosses its shape",
            case.name
        );
    }
}

#[test]
fn figures_draw() {
    for case in lesson::cases().unwrap() {
        let rgba = cross_section(case.name, &case.shape, &case.ray)
            .unwrap()
            .rgba();
        assert!(common::blue_pixels(&rgba) > 200, "{}: the ray", case.name);
        assert!(
            common::red_pixels(&rgba) > 200,
            "{}: the surface and hits",
            case.name
        );
    }
}

/// The numbers lesson 07's pages work out by hand for the lesson's five rays, and its
/// exercises' answers, computed again (in `f64` where the page's steps are exact).
#[test]
fn lesson_07_worked_numbers() {
    let f3 = |v: DVec3| format!("{:.4} {:.4} {:.4}", v.x, v.y, v.z);
    // The sphere: o = (-3, 0.5, 0), d = (1, 0, 0), a unit sphere at the origin.
    let o = DVec3::new(-3.0, 0.5, 0.0);
    let (b, c) = (2.0 * o.x, o.length_squared() - 1.0);
    assert_eq!(
        (0.5f64 * 0.5, b, c, b * b - 4.0 * c),
        (0.25, -6.0, 8.25, 3.0)
    );
    let sphere = common::unit_sphere();
    let ray = common::ray([-3.0, 0.5, 0.0], Vec3::X);
    let (t0, t1) = sphere.roots_stable(&ray).pair().unwrap();
    assert_eq!(
        format!("{t0:.3} {t1:.3} {:.3}", 0.75f64.sqrt()),
        "2.134 3.866 0.866"
    );
    // The plane: (p0 - o) . n and d . n with n = (1, 2, 0)/sqrt 5, d = (1, -1, 0)/sqrt
    // 2.
    let n = DVec3::new(1.0, 2.0, 0.0).normalize();
    let d = DVec3::new(1.0, -1.0, 0.0).normalize();
    let along = DVec3::new(2.0, -2.5, 0.0).dot(n);
    assert!((along + 3.0 / 5f64.sqrt()).abs() < 1e-12);
    assert_eq!(
        format!("{:.3} {:.4}", d.dot(n), along / d.dot(n)),
        "-0.316 4.2426"
    );
    // The box [-1, 1]^3: o = (-3, -0.5, 0), d = (2, 1, 0)/sqrt 5.
    let d = DVec3::new(2.0, 1.0, 0.0).normalize();
    assert_eq!(format!("{:.3} {:.3}", d.x, d.y), "0.894 0.447");
    let x_slab = format!("{:.3} {:.3}", 2.0 / d.x, 4.0 / d.x);
    let y_slab = format!("{:.3} {:.3}", -0.5 / d.y, 1.5 / d.y);
    assert_eq!(
        (x_slab.as_str(), y_slab.as_str()),
        ("2.236 4.472", "-1.118 3.354")
    );
    // The triangle, Möller and Trumbore's steps: v0 = (1, -1, -1), v1 = (1, 1.5, 0),
    // v2 = (1, -1, 1), o = (-2, 0.2, 0), d = (1, 0.1, 0)/sqrt 1.01.
    let (v0, v1, v2) = (
        DVec3::new(1.0, -1.0, -1.0),
        DVec3::new(1.0, 1.5, 0.0),
        DVec3::new(1.0, -1.0, 1.0),
    );
    let (e1, e2) = (v1 - v0, v2 - v0);
    assert_eq!(
        (e1, e2, e1.cross(e2)),
        (DVec3::new(0.0, 2.5, 1.0), 2.0 * DVec3::Z, 5.0 * DVec3::X)
    );
    let d = DVec3::new(1.0, 0.1, 0.0).normalize();
    assert_eq!(f3(d), "0.9950 0.0995 0.0000");
    assert_eq!(format!("{:.5} {:.5}", d.x, d.y), "0.99504 0.09950");
    let p = d.cross(e2);
    let det = e1.dot(p);
    assert_eq!(f3(p), "0.1990 -1.9901 0.0000");
    assert_eq!(format!("{det:.4}"), "-4.9752");
    let t_vec = DVec3::new(-2.0, 0.2, 0.0) - v0;
    let q = t_vec.cross(e1);
    assert_eq!(f3(t_vec), "-3.0000 1.2000 1.0000");
    assert_eq!(f3(q), "-1.3000 3.0000 -7.5000");
    let parts = format!("{:.4} {:.4}", t_vec.x * p.x, t_vec.y * p.y);
    assert_eq!(parts, "-0.5970 -2.3881");
    let parts = format!("{:.4} {:.4}", d.x * q.x, d.y * q.y);
    assert_eq!(parts, "-1.2935 0.2985");
    let (b1, b2, t) = (t_vec.dot(p) / det, d.dot(q) / det, e2.dot(q) / det);
    assert_eq!(
        format!("{b1:.4} {b2:.4} {t:.3} {:.3}", 3.0 / d.x),
        "0.6000 0.2000 3.015 3.015"
    );
    // Exercise 7.10, on the triangle: b1 = 0.75 and b2 = 0.5 sum to 1.25.
    assert_eq!(0.75 + 0.5, 1.25);
    // The paraboloid's gradient (2x, 2y, -1) at x = -1.618.
    let x = -(1.0 + 5f64.sqrt()) / 2.0;
    assert_eq!(format!("{x:.3} {:.3}", 2.0 * x), "-1.618 -3.236");
    // S9's paraboloid ray from (0.3, 0.2, 5): o_x^2 + o_y^2 = 0.13.
    assert_eq!(format!("{:.2}", 0.3f64 * 0.3 + 0.2 * 0.2), "0.13");
    // S9 at theta = 1e-4 in f32 (where_methods_fail_roots.md): a = sin^2 theta,
    // b = 2 o_x sin theta + cos theta, c = -4.87. The exact numerator -2ac/b is
    // 9.74e-8, below the spacing 2^-23 = 1.1920929e-7 of floats near 1, to which the
    // difference rounds; divided by 2a, the textbook's 5.960465.
    let theta = 1e-4f32;
    let a = theta.sin() * theta.sin();
    let b = 2.0 * 0.3 * theta.sin() + theta.cos();
    let exact = -2.0 * f64::from(a) * -4.87 / f64::from(b);
    assert_eq!(
        format!("{a:e} {b:.5} {exact:.2e} {:.1e}", 2.0 * a),
        "9.999999e-9 1.00006 9.74e-8 2.0e-8"
    );
    let spacing = 2f32.powi(-23);
    assert_eq!(
        format!("{spacing:.7e} {:.7e}", 2.0 * a),
        "1.1920929e-7 1.9999998e-8"
    );
    assert_eq!(format!("{:.6}", spacing / (2.0 * a)), "5.960465");
    assert_eq!(format!("{:.1e}", exact), "9.7e-8");
    // S3: f . f of about 1e10 lies between 2^33 and 2^34, where floats are 2^10 apart.
    assert_eq!(2f64.powi(33 - 23), 1024.0);
    // ... and the hit distance inherits about eps R = 2^-24 1e5, sixty times 1e-4.
    let eps_r = f64::from(f32::EPSILON) / 2.0 * 1e5;
    assert_eq!(format!("{eps_r:.0e} {:.0}", eps_r / 1e-4), "6e-3 60");
    // Exercise 7.17's far case, as its check builds it: a unit sphere 1e4 away along
    // (0.3, 0.2, -1), the ray aimed at its centre. The roots are 9999 and 10001; the
    // school formula in f32 rounds b^2 - 4ac to 0 and gives a double root at 10000.001.
    let aim = Vec3::new(0.3, 0.2, -1.0).normalize();
    let centre = 1e4 * aim;
    let f = -centre;
    let (a, b, c) = (aim.dot(aim), 2.0 * f.dot(aim), f.dot(f) - 1.0);
    let school =
        |sign: f32| (-b + sign * (b * b - 4.0 * a * c).max(0.0).sqrt()) / (2.0 * a);
    assert_eq!(b * b - 4.0 * a * c, 0.0);
    assert_eq!(
        format!("{:.3} {:.3}", school(-1.0), school(1.0)),
        "10000.001 10000.001"
    );
    let far = Sphere::new(centre, 1.0).unwrap();
    let (t0, t1) = far
        .roots_stable(&Ray::new(Vec3::ZERO, aim).unwrap())
        .pair()
        .unwrap();
    assert_eq!(format!("{t0:.0} {t1:.0}"), "9999 10001");
}

/// The numbers of one row of lesson 07's table (snapshot
/// `lessons__lesson_07_intersections__numbers`): the crossings, the hit point and the
/// outward normal.
fn lesson_07_row(shape: &str) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let snap = common::pages::snapshot(module_path!(), "numbers");
    // The shape's row in the table of rays, then in the table of hits.
    let mut rows = snap
        .lines()
        .filter(|l| l.split_whitespace().next() == Some(shape));
    let (ray, hit) = (rows.next(), rows.next());
    let (Some(ray), Some(hit)) = (ray, hit) else {
        panic!("no rows {shape}");
    };
    let numbers = |s: &str| -> Vec<f64> {
        s.split(|c: char| c == ',' || c.is_whitespace())
            .filter(|x| !x.is_empty())
            .map(|x| x.parse().unwrap())
            .collect()
    };
    // Rays: origin, direction, then the crossings (not in brackets). Hits: the hit
    // point and the normal.
    let crossings = ray.split(')').nth(2).unwrap();
    let tuples: Vec<&str> = hit
        .split('(')
        .skip(1)
        .map(|s| &s[..s.find(')').unwrap()])
        .collect();
    (numbers(crossings), numbers(tuples[0]), numbers(tuples[1]))
}

#[test]
fn lesson_07_pages_quote_the_intersections_snapshot() {
    let (sphere, _, _) = lesson_07_row("sphere");
    let page = "07_intersections.md";
    assert_quotes(page, "2.134$ and $t = 3.866$. Two", sphere[0]);
    assert_quotes(page, "3.866$. Two crossings", sphere[1]);
    assert_quotes(page, "2.134$ and $3.866$ above", sphere[0]);
    assert_quotes(page, "3.866$ above", sphere[1]);
    let (plane, hit, normal) = lesson_07_row("plane");
    assert_quotes(page, r"4.2426$, the box's", plane[0]);
    let (boxed, _, _) = lesson_07_row("box");
    assert_quotes(page, "2.236, 3.354]", boxed[0]);
    assert_quotes(page, "3.354]$", boxed[1]);
    let (triangle, _, _) = lesson_07_row("triangle");
    assert_quotes(page, "3.015$, the paraboloid's", triangle[0]);
    let page = "07_2_plane.md";
    assert_quotes(page, r"4.2426$, at the point", plane[0]);
    assert_quotes(page, "4.243$; the normal", plane[0]);
    assert_quotes(page, "4.243, with the normal", plane[0]);
    assert_quotes(page, "4.2426$ and the hit point", plane[0]);
    assert_eq!(hit, [1.0, -1.0, 0.0], "the page's (1, -1, 0)");
    assert_quotes(page, "-0.4472, -0.8944, 0)$", -normal[0]);
    assert_quotes(page, "-0.8944, 0)$", -normal[1]);
    let (paraboloid, hit, normal) = lesson_07_row("paraboloid");
    let page = "07_5_quadrics.md";
    assert_quotes(page, "0.5402$ and $3.7025$", paraboloid[0]);
    assert_quotes(page, "3.7025$. The first", paraboloid[1]);
    assert_quotes(page, "-1.618, 0, 2.618)$", hit[0]);
    assert_quotes(page, "2.618)$,", hit[2]);
    assert_quotes(page, "-0.9554, 0, -0.2952)$", normal[0]);
    assert_quotes(page, "-0.2952)$: the", normal[2]);
    // The figure's label has 3 decimals, the table 4: round the exact root, which the
    // table agrees with, rather than the table's rounding of it.
    let exact = (3.0 + 5.0f64.sqrt()) / 2.0f64.sqrt();
    assert!((exact - paraboloid[1]).abs() < 1e-4);
    assert_quotes(page, "3.702; the normal", exact);
}
