//! The checks of the coding exercises of lessons 08 and 09, themselves checked (run by
//! the default test suite): each check must pass the crate's reference and an
//! independent answer, and must fail wrong answers, each with a hint that names the
//! mistake, so that a wrong check fails CI. The mistakes the chapters warn about, as a
//! student writes them, are in `pitfalls_08_09.rs`; the student's own tests in
//! `tests/exercises.rs`.

use glam::Vec3;
use render_lessons::course::exercises::check::*;
use render_lessons::raster::ScreenVertex;
use render_lessons::ray::Ray;
use render_lessons::scene::PointLight;
use render_lessons::shapes::Shape;

use crate::common::{fails_hinting, fails_with, reference_closest};

// Chapter 08.

#[test]
fn closest_accepts_the_reference() {
    assert_eq!(check_closest(reference_closest), Outcome::Pass);
    assert_eq!(check_closest(closest_solution), Outcome::Pass);
    // Every hit, then the smallest t: no shrinking of range.max.
    let min_of_all = |ray: &Ray, shapes: &[Shape], range| {
        each_hit(ray, shapes, range).min_by(|a, b| a.hit.t.total_cmp(&b.hit.t))
    };
    assert_eq!(check_closest(min_of_all), Outcome::Pass);
}

#[test]
fn closest_rejects_mistakes() {
    fails_with(
        check_closest(|ray: &Ray, shapes: &[Shape], range| {
            each_hit(ray, shapes, range).next_back()
        }),
        "shrink range.max",
    );
}

#[test]
fn lambert_accepts_the_reference() {
    use render_lessons::lighting::lambert;
    assert_eq!(
        check_lambert(|p, n, albedo, light: &PointLight, visible| {
            lambert(p, n, albedo, light, || visible)
        }),
        Outcome::Pass
    );
    // Independently, in f64 and with the cosine as a ratio of lengths.
    let by_hand =
        |p: Vec3, n: Vec3, albedo: Vec3, light: &PointLight, visible: bool| {
            let to_light = (light.position - p).as_dvec3();
            let cos = n.as_dvec3().dot(to_light) / to_light.length();
            let direct = if visible && cos > 0.0 {
                light.intensity.as_dvec3() * cos / to_light.length_squared()
            } else {
                glam::DVec3::ZERO
            };
            let ambient = f64::from(render_lessons::lighting::AMBIENT);
            (albedo.as_dvec3() * (direct + ambient)).as_vec3()
        };
    assert_eq!(check_lambert(by_hand), Outcome::Pass);
}

/// Lambert's law with switches for the typical mistakes.
#[derive(Clone, Copy, Default)]
struct LambertMistakes {
    no_ambient: bool,
    black_shadow: bool,
    ignore_shadow: bool,
    no_falloff: bool,
    over_d: bool,
    not_unit: bool,
    unclamped: bool,
    no_albedo: bool,
}

fn lambert_with(
    m: LambertMistakes,
) -> impl Fn(Vec3, Vec3, Vec3, &PointLight, bool) -> Vec3 {
    move |p, n, albedo, light, visible| {
        let to_light = light.position - p;
        let d = to_light.length();
        let cos = n.dot(if m.not_unit { to_light } else { to_light / d });
        let falloff = match (m.no_falloff, m.over_d) {
            (true, _) => 1.0,
            (_, true) => d,
            _ => d * d,
        };
        let seen = visible || m.ignore_shadow;
        let lit = seen && (cos > 0.0 || m.unclamped);
        let direct = if lit {
            light.intensity * cos / falloff
        } else {
            Vec3::ZERO
        };
        if m.black_shadow && !seen {
            return Vec3::ZERO;
        }
        let ambient = if m.no_ambient {
            0.0
        } else {
            render_lessons::lighting::AMBIENT
        };
        let albedo = if m.no_albedo { Vec3::ONE } else { albedo };
        albedo * (Vec3::splat(ambient) + direct)
    }
}

#[test]
fn lambert_rejects_mistakes() {
    let with = |m| check_lambert(lambert_with(m));
    let no = LambertMistakes::default();
    assert_eq!(with(no), Outcome::Pass);
    for (m, hint) in [
        (
            LambertMistakes {
                no_ambient: true,
                ..no
            },
            "ambient share is missing",
        ),
        (
            LambertMistakes {
                black_shadow: true,
                ..no
            },
            "ambient share",
        ),
        (
            LambertMistakes {
                ignore_shadow: true,
                ..no
            },
            "visible = false",
        ),
        (
            LambertMistakes {
                no_falloff: true,
                ..no
            },
            "spreads over a sphere",
        ),
        (LambertMistakes { over_d: true, ..no }, "1/d here"),
        (
            LambertMistakes {
                not_unit: true,
                ..no
            },
            "1/d here",
        ),
        (
            LambertMistakes {
                unclamped: true,
                ..no
            },
            "facing away",
        ),
        (
            LambertMistakes {
                no_albedo: true,
                ..no
            },
            "by the albedo",
        ),
    ] {
        fails_with(with(m), hint);
    }
    assert_eq!(check_lambert(|_, _, _, _, _| todo!()), Outcome::NotStarted);
}

// Chapter 09.

/// A pixel position, in whole pixels.
pub(crate) type P = (i64, i64);

pub(crate) fn edge(u: P, v: P, q: P) -> i64 {
    (q.0 - u.0) * (v.1 - u.1) - (q.1 - u.1) * (v.0 - u.0)
}

fn top_left(u: P, v: P) -> bool {
    v.1 > u.1 || (v.1 == u.1 && v.0 < u.0)
}

/// The edges b -> c, c -> a, a -> b, with b and c swapped if the area is
/// negative; `None` if it is zero.
pub(crate) fn edges(a: P, b: P, c: P) -> Option<[(P, P); 3]> {
    let area = edge(a, b, c);
    let (b, c) = if area < 0 { (c, b) } else { (b, c) };
    (area != 0).then_some([(b, c), (c, a), (a, b)])
}

/// The right rule with the arithmetic done in the type `to` converts to.
pub(crate) fn covers_in<T>(to: fn(i64) -> T, a: P, b: P, c: P, p: P) -> bool
where
    T: Copy
        + Default
        + PartialOrd
        + std::ops::Sub<Output = T>
        + std::ops::Mul<Output = T>,
{
    let e = |u: P, v: P, q: P| {
        (to(q.0) - to(u.0)) * (to(v.1) - to(u.1))
            - (to(q.1) - to(u.1)) * (to(v.0) - to(u.0))
    };
    let zero = T::default();
    let area = e(a, b, c);
    if area == zero {
        return false;
    }
    let (b, c) = if area < zero { (c, b) } else { (b, c) };
    [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
        let e = e(u, v, p);
        e > zero || (e == zero && top_left(u, v))
    })
}

#[test]
fn covers_accepts_the_reference() {
    use render_lessons::raster::rasterize::covers;
    assert_eq!(check_covers(covers), Outcome::Pass);
    // No swap: for a clockwise triangle every edge is turned round, in i128.
    let independent = |a: P, b: P, c: P, p: P| {
        let e = |u: P, v: P, q: P| {
            let w = |x: i64| i128::from(x);
            (w(q.0) - w(u.0)) * (w(v.1) - w(u.1))
                - (w(q.1) - w(u.1)) * (w(v.0) - w(u.0))
        };
        let area = e(a, b, c);
        area != 0
            && [(a, b), (b, c), (c, a)].into_iter().all(|(u, v)| {
                let (u, v) = if area > 0 { (u, v) } else { (v, u) };
                let e = e(u, v, p);
                e > 0 || (e == 0 && top_left(u, v))
            })
    };
    assert_eq!(check_covers(independent), Outcome::Pass);
    // On the diagonal the two triangles of the check share, away from its far
    // end, exactly one of them covers each point, whatever their winding.
    let lower = ((0, 0), (0, 8), (8, 8));
    let upper = ((0, 0), (8, 8), (8, 0));
    for i in 0..8 {
        let p = (i, i);
        assert_ne!(
            covers(lower.0, lower.1, lower.2, p),
            covers(upper.0, upper.1, upper.2, p),
            "{p:?}"
        );
        assert_eq!(
            covers(lower.0, lower.1, lower.2, p),
            covers(lower.0, lower.2, lower.1, p)
        );
    }
}

#[test]
fn covers_rejects_mistakes() {
    fails_with(
        check_covers(|a, b, c, p| {
            edges(a, b, c)
                .is_some_and(|es| es.into_iter().all(|(u, v)| edge(u, v, p) >= 0))
        }),
        "double",
    );
    fails_with(
        check_covers(|a, b, c, p| {
            edges(a, b, c)
                .is_some_and(|es| es.into_iter().all(|(u, v)| edge(u, v, p) > 0))
        }),
        "cracks",
    );
    fails_with(
        check_covers(|a, b, c, p| {
            edge(a, b, c) != 0
                && [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
                    let e = edge(u, v, p);
                    e > 0 || (e == 0 && top_left(u, v))
                })
        }),
        "nothing is covered",
    );
    fails_with(
        check_covers(|a, b, c, p| {
            let sign = edge(a, b, c).signum();
            sign != 0
                && [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
                    let e = sign * edge(u, v, p);
                    e > 0 || (e == 0 && top_left(u, v))
                })
        }),
        "flip the signs",
    );
    fails_with(
        check_covers(|a, b, c, p| covers_in(|x| x as f64, a, b, c, p)),
        "not in floating point",
    );
    fails_with(
        check_covers(|a, b, c, p| {
            covers_in(|x| std::num::Wrapping(x as i32), a, b, c, p)
        }),
        "overflow i32",
    );
    // Plain i32 panics on overflow in a debug build and wraps in a release build:
    // either way the hint says i64.
    fails_hinting(
        check_covers(|a, b, c, p| covers_in(|x| x as i32, a, b, c, p)),
        "i64",
    );
}

#[test]
fn perspective_weights_accepts_the_reference() {
    use render_lessons::raster::rasterize::perspective_weights;
    let crate_answer =
        |b, v: &[ScreenVertex; 3]| perspective_weights(b, v.map(|v| v.inv_w));
    assert_eq!(check_perspective_weights(crate_answer), Outcome::Pass);
    // Independently, with w itself and in f64: (b_k / w_k) / sum_j (b_j / w_j).
    let with_w = |b: [f32; 3], v: &[ScreenVertex; 3]| {
        let over = [0, 1, 2].map(|k| f64::from(b[k]) * f64::from(v[k].inv_w));
        let sum: f64 = over.iter().sum();
        over.map(|o| (o / sum) as f32)
    };
    assert_eq!(check_perspective_weights(with_w), Outcome::Pass);
    // Exercise 9.4: halfway from w = 1 to w = 4 on the screen, the far
    // end weighs 0.2, not 0.5.
    let weights = perspective_weights([0.5, 0.5, 0.0], [1.0, 0.25, 1.0]);
    assert!(weights.close(&[0.8, 0.2, 0.0]), "{weights:?}");
}

#[test]
fn perspective_weights_rejects_mistakes() {
    let inv_w = |v: &[ScreenVertex; 3]| v.map(|v| v.inv_w);
    fails_with(
        check_perspective_weights(move |b, v: &[ScreenVertex; 3]| {
            let w = inv_w(v).map(|i| 1.0 / i);
            let sum: f32 = (0..3).map(|k| b[k] * w[k]).sum();
            [0, 1, 2].map(|k| b[k] * w[k] / sum)
        }),
        "multiply by it",
    );
    fails_with(
        check_perspective_weights(move |b, v: &[ScreenVertex; 3]| {
            let i = inv_w(v);
            [0, 1, 2].map(|k| b[k] * i[k])
        }),
        "sum to 1",
    );
    fails_with(
        check_perspective_weights(move |b, v: &[ScreenVertex; 3]| {
            let i = inv_w(v);
            let sum: f32 = i.iter().sum();
            [0, 1, 2].map(|k| b[k] * i[k] / sum)
        }),
        "not by the sum of the vertices' 1/w",
    );
    assert_eq!(
        check_perspective_weights(|_, _| todo!()),
        Outcome::NotStarted
    );
}
