//! Lesson 07, the sphere (chapter 07_1): known answers for both root finders, the
//! nearest hit in range, and where the textbook formula fails (STABILITY S1: a small
//! sphere far away; S2: a ray from the centre or the surface).
//!
//! Expected values are worked out by hand, or in f64 from the same f32 inputs.

use crate::common::{close, ray, unit_sphere};
use glam::{DVec3, Vec3};
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{Shape, Sphere};

/// A pair of roots, or the entry and exit of a slab interval; `None` for a miss.
type Pair = Option<(f32, f32)>;

// ---------------------------------------------------------------- sphere

#[test]
fn sphere_known_answers_both_root_finders() {
    let s = unit_sphere();
    let cases: [([f32; 3], Pair); 4] = [
        // Straight through: |z| = 1 at z = -5 + t, so t = 4 and 6.
        ([0.0, 0.0, -5.0], Some((4.0, 6.0))),
        // Tangent at (0, 1, 0): a double root at t = 5.
        ([0.0, 1.0, -5.0], Some((5.0, 5.0))),
        // Passes at distance 2: misses.
        ([0.0, 2.0, -5.0], None),
        // From the centre: one root behind, one ahead.
        ([0.0, 0.0, 0.0], Some((-1.0, 1.0))),
    ];
    for (o, expected) in cases {
        let r = ray(o, [0.0, 0.0, 1.0]);
        for (name, got) in [
            ("textbook", s.roots_textbook(&r).pair()),
            ("stable", s.roots_stable(&r).pair()),
        ] {
            match (got, expected) {
                (Some(g), Some(e)) => {
                    assert!(close(g, e, 1e-6), "{name} {o:?}: {g:?} vs {e:?}")
                }
                (None, None) => {}
                _ => panic!("{name} {o:?}: got {got:?}, expected {expected:?}"),
            }
        }
    }
}

#[test]
fn sphere_hit_nearest_in_range_and_normal() {
    let s = unit_sphere();
    let h = s
        .hit(&ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]), Interval::AHEAD)
        .unwrap();
    assert_eq!(h.t, 4.0);
    assert_eq!(h.point, Vec3::new(0.0, 0.0, -1.0));
    assert_eq!(h.normal, Vec3::new(0.0, 0.0, -1.0));
    assert!(h.front_face);
    // With t_min past the first root, the exit is the nearest crossing; seen from
    // inside.
    let h = s
        .hit(
            &ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]),
            Interval::new(4.5, 100.0),
        )
        .unwrap();
    assert_eq!(h.t, 6.0);
    assert_eq!(h.normal, Vec3::new(0.0, 0.0, 1.0));
    assert!(!h.front_face);
    // t_max before the sphere: no hit.
    assert!(
        s.hit(
            &ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]),
            Interval::new(0.0, 3.0)
        )
        .is_none()
    );
}

#[test]
fn sphere_behind_the_ray_is_not_hit() {
    let s = unit_sphere();
    let r = ray([0.0, 0.0, 5.0], [0.0, 0.0, 1.0]);
    let (t0, t1) = s.roots_stable(&r).pair().unwrap();
    assert!(close((t0, t1), (-6.0, -4.0), 1e-6));
    assert!(s.hit(&r, Interval::AHEAD).is_none());
    assert!(Shape::Sphere(s).hit(&r, Interval::AHEAD).is_none());
}

/// Hit/miss disagreements with the f64 reference, for both root finders, and the
/// median |t - t_ref| / r of the stable near root, over an n x n grid of rays from the
/// origin aimed over a 2.4 r square around a unit sphere at distance `dist` (S1).
fn s1_disagreements(dist: f32, n: usize) -> (f64, f64, f64) {
    let w = Vec3::new(0.3, 0.2, -1.0).normalize();
    let centre = dist * w;
    let sphere = Sphere::new(centre, 1.0).unwrap();
    let u = w.cross(Vec3::Y).normalize();
    let v = u.cross(w);
    let (mut textbook_wrong, mut stable_wrong) = (0usize, 0usize);
    let mut errors = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let su = -1.2 + 2.4 * (i as f32 + 0.5) / n as f32;
            let sv = -1.2 + 2.4 * (j as f32 + 0.5) / n as f32;
            let r = Ray::new(Vec3::ZERO, centre + su * u + sv * v).unwrap();
            let reference = reference_roots(&r, centre, 1.0);
            textbook_wrong += usize::from(
                sphere.roots_textbook(&r).pair().is_some() != reference.is_some(),
            );
            let stable = sphere.roots_stable(&r).pair();
            stable_wrong += usize::from(stable.is_some() != reference.is_some());
            if let (Some(s), Some(e)) = (stable, reference) {
                errors.push((s.0 as f64 - e.0).abs());
            }
        }
    }
    errors.sort_by(f64::total_cmp);
    let total = (n * n) as f64;
    let median = errors.get(errors.len() / 2).copied().unwrap_or(0.0);
    (
        textbook_wrong as f64 / total,
        stable_wrong as f64 / total,
        median,
    )
}

/// The roots for the same f32 inputs, computed in f64 (independent code).
fn reference_roots(r: &Ray, centre: Vec3, radius: f32) -> Option<(f64, f64)> {
    let o = r.origin().as_dvec3();
    let d = r.direction().as_dvec3();
    let f = o - centre.as_dvec3();
    let a = d.dot(d);
    let t_mid = -f.dot(d) / a;
    let l: DVec3 = f + t_mid * d;
    let rr = radius as f64 * radius as f64;
    let h2 = rr - l.dot(l);
    if h2 < 0.0 {
        return None;
    }
    let h = (h2 / a).sqrt();
    Some((t_mid - h, t_mid + h))
}

#[test]
fn s1_small_sphere_far_away_textbook_fails_stable_holds() {
    let (tb3, st3, med3) = s1_disagreements(1e3, 100);
    let (tb4, st4, med4) = s1_disagreements(1e4, 100);
    eprintln!(
        "S1 D/r=1e3: textbook wrong {:.3}%, stable wrong {:.3}%, stable median |dt| {med3:.2e}",
        tb3 * 100.0,
        st3 * 100.0
    );
    eprintln!(
        "S1 D/r=1e4: textbook wrong {:.3}%, stable wrong {:.3}%, stable median |dt| {med4:.2e}",
        tb4 * 100.0,
        st4 * 100.0
    );
    assert!(
        tb3 > 0.01,
        "textbook should be wrong on > 1% at 1e3, was {tb3}"
    );
    assert!(
        st3 < 1e-4,
        "stable should be wrong on < 0.01% at 1e3, was {st3}"
    );
    assert!(med3 < 1e-3, "stable median error at 1e3: {med3}");
    assert!(
        tb4 > 0.2,
        "textbook should be wrong on > 20% at 1e4, was {tb4}"
    );
    assert!(
        st4 < 5e-3 && st4 * 50.0 < tb4,
        "stable at 1e4: {st4} vs textbook {tb4}"
    );
}

#[test]
fn s2_origin_at_centre_and_on_surface() {
    let c = Vec3::new(1.0, 2.0, 3.0);
    let s = Sphere::new(c, 2.0).unwrap();
    for d in [[0.0, 0.0, 1.0], [1.0, -2.0, 0.5], [-0.3, 0.0, 0.0]] {
        // At the centre b = 0 exactly: sign(0) must be +1 or q = 0 and c/q = NaN.
        let r = Ray::new(c, Vec3::from(d)).unwrap();
        for roots in [s.roots_stable(&r).pair(), s.roots_textbook(&r).pair()] {
            let (t0, t1) = roots.unwrap();
            assert!(t0.is_finite() && t1.is_finite());
            assert!(close((t0, t1), (-2.0, 2.0), 1e-6), "{d:?}: {t0} {t1}");
        }
    }
    let on_surface = Vec3::new(1.0, 2.0, 1.0); // c - 2 z
    // Towards the centre: 0 and 2r; away from it: -2r and 0.
    let towards = Ray::new(on_surface, Vec3::Z).unwrap();
    assert_eq!(s.roots_stable(&towards).pair(), Some((0.0, 4.0)));
    let away = Ray::new(on_surface, -Vec3::Z).unwrap();
    assert_eq!(s.roots_stable(&away).pair(), Some((-4.0, 0.0)));
    // Tangent at the surface: b = 0 and c = 0, a double root at 0, no NaN.
    let tangent = Ray::new(on_surface, Vec3::X).unwrap();
    assert_eq!(s.roots_stable(&tangent).pair(), Some((0.0, 0.0)));
    assert_eq!(s.roots_textbook(&tangent).pair(), Some((0.0, 0.0)));
}
