//! Lesson 07: ray / primitive intersection, and where the naive methods fail
//! (STABILITY S1, S2, S4 to S8).
//!
//! Expected values are worked out by hand (or in f64 from the same f32 inputs), not
//! by the code under test. Failure rates are measured, never hard-coded: the tests
//! assert that the naive method is wrong often and the robust one (almost) never.

use crate::common;

use crate::examples::intersections as lesson;
use render_lessons::course::measure::Quality;
use render_lessons::course::measure::triangle::{BoxCounts, box_cases, box_counts};

use glam::{DVec3, Vec3};
use proptest::prelude::*;
use render_lessons::Error;
use render_lessons::course::diagram::cross_section;
use render_lessons::error::Problem;
use render_lessons::ray::{ClosedSpan, Interval, Ray};
use render_lessons::shapes::{Aabb, Barycentric, Plane, Shape, Sphere, Triangle};

fn ray(o: [f32; 3], d: [f32; 3]) -> Ray {
    Ray::new(Vec3::from(o), Vec3::from(d)).unwrap()
}

fn unit_sphere() -> Sphere {
    Sphere::new(Vec3::ZERO, 1.0).unwrap()
}

/// A pair of roots, or the entry and exit of a slab interval; `None` for a miss.
type Pair = Option<(f32, f32)>;

fn close(a: (f32, f32), b: (f32, f32), tol: f32) -> bool {
    (a.0 - b.0).abs() <= tol && (a.1 - b.1).abs() <= tol
}

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
                (Some(g), Some(e)) => assert!(close(g, e, 1e-6), "{name} {o:?}: {g:?} vs {e:?}"),
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
    // With t_min past the first root, the exit is the nearest crossing; seen from inside.
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
            textbook_wrong +=
                usize::from(sphere.roots_textbook(&r).pair().is_some() != reference.is_some());
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

// ---------------------------------------------------------------- plane

#[test]
fn plane_known_answers() {
    // The plane x + y + z = 3, through (1, 1, 1).
    let p = Plane::new(Vec3::ONE, Vec3::ONE).unwrap();
    // Along +x: x = 3 at t = 3.
    let h = p
        .hit(&ray([0.0; 3], [1.0, 0.0, 0.0]), Interval::AHEAD)
        .unwrap();
    assert!((h.t - 3.0).abs() < 1e-6);
    assert!((h.point - Vec3::new(3.0, 0.0, 0.0)).length() < 1e-6);
    // Along (1, 1, 0)/sqrt 2: x = y = 1.5, at t = 1.5 sqrt 2 = 3 / sqrt 2.
    let h = p
        .hit(&ray([0.0; 3], [1.0, 1.0, 0.0]), Interval::AHEAD)
        .unwrap();
    assert!((h.t - 3.0 / 2f32.sqrt()).abs() < 1e-6);
    assert!((h.point - Vec3::new(1.5, 1.5, 0.0)).length() < 1e-6);
    // The origin lies behind the plane (x + y + z = 0 < 3): seen from the back.
    assert!(!h.front_face);
    assert!((h.normal - Vec3::ONE.normalize()).length() < 1e-6);
    // From the front side.
    let h = p.hit(&ray([5.0; 3], [-1.0; 3]), Interval::AHEAD).unwrap();
    assert!(h.front_face);
    assert!((h.t - 12.0 / 3f32.sqrt()).abs() < 1e-5); // (15 - 3) / sqrt 3
}

#[test]
fn plane_parallel_ray_misses_without_nan() {
    let p = Plane::new(Vec3::ZERO, Vec3::Y).unwrap();
    for o in [[0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [3.0, -2.0, 1.0]] {
        let r = ray(o, [1.0, 0.0, 1.0]);
        assert_eq!(p.t(&r), None);
        assert!(p.hit(&r, Interval::EVERYWHERE).is_none());
    }
    // Behind the origin: t = -2, outside (0, inf).
    let r = ray([0.0, 2.0, 0.0], [0.0, 1.0, 0.0]);
    assert_eq!(p.t(&r), Some(-2.0));
    assert!(Shape::Plane(p).hit(&r, Interval::AHEAD).is_none());
}

// ---------------------------------------------------------------- box (S8)

fn cube() -> Aabb {
    Aabb::new(Vec3::splat(-1.0), Vec3::splat(1.0)).unwrap()
}

/// A slab test written the naive way round: `t0 = if t0 > t_near { t0 } else { t_near }`
/// lets a NaN from 0 * inf replace the interval (kept to show the failure).
fn naive_slab(b: &Aabb, r: &Ray, range: Interval) -> Slab {
    let (mut t0, mut t1) = (range.min, range.max);
    for i in 0..3 {
        let inv = 1.0 / r.direction()[i];
        let a = (b.min()[i] - r.origin()[i]) * inv;
        let c = (b.max()[i] - r.origin()[i]) * inv;
        let (near, far) = if a < c { (a, c) } else { (c, a) };
        t0 = if t0 > near { t0 } else { near };
        t1 = if t1 < far { t1 } else { far };
        if t0 > t1 {
            return None;
        }
    }
    Some(ClosedSpan { t0, t1 })
}

/// What a slab test returns: the closed span `[t0, t1]` inside the box, or `None`.
type Slab = Option<ClosedSpan>;

/// The closed span `[t0, t1]` a slab test returns.
fn closed(t0: f32, t1: f32) -> Slab {
    Some(ClosedSpan { t0, t1 })
}

#[test]
fn s8_slab_truth_table() {
    let b = cube();
    // (box, origin, direction, expected interval clipped to [0, inf))
    let flat = Aabb::new(Vec3::new(-1.0, 0.0, -1.0), Vec3::new(1.0, 0.0, 1.0)).unwrap();
    let table: [(Aabb, [f32; 3], [f32; 3], Slab); 10] = [
        // In the top face's plane but outside in x: miss.
        (b, [3.0, 1.0, -5.0], [0.0, 0.0, 1.0], None),
        // In the plane z = 3, outside: miss.
        (b, [-5.0, 1.0, 3.0], [1.0, 0.0, 0.0], None),
        // A box of zero thickness, hit head on at y = 0: t = 1.
        (flat, [0.5, 1.0, 0.5], [0.0, -1.0, 0.0], closed(1.0, 1.0)),
        // Origin inside: from 0 to the exit at x = 1.
        (b, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], closed(0.0, 1.0)),
        // Box behind the origin: miss.
        (b, [0.0, 0.0, 5.0], [0.0, 0.0, 1.0], None),
        // Along the top face's plane, over the face: touches from z = -1 to 1.
        (b, [0.0, 1.0, -5.0], [0.0, 0.0, 1.0], closed(4.0, 6.0)),
        // Along an edge (two faces' planes at once).
        (b, [1.0, 1.0, -5.0], [0.0, 0.0, 1.0], closed(4.0, 6.0)),
        // Zero components, straight through.
        (b, [0.5, -0.5, -5.0], [0.0, 0.0, 1.0], closed(4.0, 6.0)),
        // Negative zero components: 1 / -0 = -inf must work too.
        (b, [0.5, 0.5, 5.0], [-0.0, -0.0, -1.0], closed(4.0, 6.0)),
        // Parallel to x, just outside in y: miss.
        (b, [-5.0, 1.0 + 1e-6, 0.0], [1.0, 0.0, 0.0], None),
    ];
    for (bx, o, d, expected) in table {
        let r = ray(o, d);
        let got = bx.slab(&r, Interval::AHEAD);
        assert_eq!(got, expected, "o = {o:?}, d = {d:?}");
        let wide = bx.slab_conservative(&r, Interval::AHEAD);
        assert_eq!(
            wide.is_some(),
            expected.is_some(),
            "conservative, o = {o:?}"
        );
    }
    // The naive comparison order gets the second case wrong: the NaN from the y slab
    // (0 * inf) replaces t0, no later comparison can reject it, and the miss becomes
    // a hit.
    let r = ray([-5.0, 1.0, 3.0], [1.0, 0.0, 0.0]);
    assert!(naive_slab(&b, &r, Interval::AHEAD).is_some());
    assert!(b.slab(&r, Interval::AHEAD).is_none());
}

#[test]
fn box_hit_normal_is_the_face_axis() {
    let b = cube();
    let h = b
        .hit(&ray([0.2, 0.3, -5.0], [0.0, 0.0, 1.0]), Interval::AHEAD)
        .unwrap();
    assert_eq!(
        (h.t, h.normal, h.front_face),
        (4.0, Vec3::new(0.0, 0.0, -1.0), true)
    );
    assert_eq!(h.point, Vec3::new(0.2, 0.3, -1.0));
    // From inside: the exit face, seen from the back.
    let h = b
        .hit(&ray([0.0; 3], [-1.0, 0.1, 0.0]), Interval::AHEAD)
        .unwrap();
    assert_eq!(h.normal, Vec3::new(-1.0, 0.0, 0.0));
    assert!(!h.front_face);
    assert_eq!(h.point.x, -1.0);
    // Behind: none.
    assert!(
        Shape::Aabb(b)
            .hit(&ray([0.0, 0.0, 5.0], [0.0, 0.0, 1.0]), Interval::AHEAD)
            .is_none()
    );
}

#[test]
fn gamma_matches_pbrt() {
    let eps = f32::EPSILON as f64 / 2.0;
    let g3 = 3.0 * eps / (1.0 - 3.0 * eps);
    assert!((render_lessons::float::gamma(3) as f64 - g3).abs() < 1e-12);
}

// ---------------------------------------------------------------- triangle

/// The closed bumpy sphere of STABILITY S4/S5, `n` x `n` segments: the same mesh
/// lesson 11's chart 2 measures.
fn bumpy_sphere(n: usize) -> (Vec<Vec3>, Vec<[usize; 3]>) {
    render_lessons::course::measure::triangle::bumpy_sphere(n, n)
}

/// How many of the rays from the origin towards `targets` hit no triangle at all, for
/// Möller-Trumbore and for the watertight test.
fn leaks(tris: &[Triangle], targets: &[Vec3]) -> (usize, usize) {
    let (mut mt, mut wt) = (0, 0);
    for &target in targets {
        let r = Ray::new(Vec3::ZERO, target).unwrap();
        mt += usize::from(
            !tris
                .iter()
                .any(|t| t.moller_trumbore(&r, Interval::AHEAD).is_some()),
        );
        wt += usize::from(
            !tris
                .iter()
                .any(|t| t.watertight(&r, Interval::AHEAD).is_some()),
        );
    }
    (mt, wt)
}

fn mesh_triangles() -> (Vec<Vec3>, Vec<[usize; 3]>, Vec<Triangle>) {
    let (vertices, indices) = bumpy_sphere(16);
    let tris = indices
        .iter()
        .map(|&[a, b, c]| Triangle::new(vertices[a], vertices[b], vertices[c]).unwrap())
        .collect();
    (vertices, indices, tris)
}

#[test]
fn bumpy_sphere_is_closed_and_outward() {
    let (vertices, indices, tris) = mesh_triangles();
    assert_eq!(vertices.len(), 2 + 15 * 16);
    assert_eq!(tris.len(), 2 * 16 * 15);
    let mut edges = std::collections::HashMap::new();
    for t in &indices {
        for k in 0..3 {
            *edges
                .entry((t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3])))
                .or_insert(0) += 1;
        }
    }
    assert!(
        edges.values().all(|&c| c == 2),
        "every edge shared by exactly two triangles"
    );
    for t in &tris {
        let centroid = t.vertices().iter().sum::<Vec3>() / 3.0;
        assert!(t.normal().dot(centroid) > 0.0, "wound outwards");
    }
    for v in &vertices {
        assert!((1.0..=1.5).contains(&v.length()));
    }
}

#[test]
fn s4_s5_watertight_never_leaks_moller_trumbore_does() {
    let (vertices, indices, tris) = mesh_triangles();
    let (mt_v, wt_v) = leaks(&tris, &vertices);
    let mut edges = std::collections::BTreeSet::new();
    for t in &indices {
        for k in 0..3 {
            edges.insert((t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3])));
        }
    }
    let midpoints: Vec<Vec3> = edges
        .iter()
        .map(|&(a, b)| (vertices[a] + vertices[b]) * 0.5)
        .collect();
    let (mt_e, wt_e) = leaks(&tris, &midpoints);
    let pct = |k: usize, n: usize| 100.0 * k as f64 / n as f64;
    eprintln!(
        "S4 vertices: {} rays, Möller-Trumbore leaks {mt_v} ({:.1}%), watertight {wt_v}",
        vertices.len(),
        pct(mt_v, vertices.len())
    );
    eprintln!(
        "S5 edge midpoints: {} rays, Möller-Trumbore leaks {mt_e} ({:.1}%), watertight {wt_e}",
        midpoints.len(),
        pct(mt_e, midpoints.len())
    );
    assert_eq!(wt_v, 0);
    assert_eq!(wt_e, 0);
    assert!(
        pct(mt_v, vertices.len()) > 1.0,
        "Möller-Trumbore should leak at vertices"
    );
    assert!(
        pct(mt_e, midpoints.len()) > 1.0,
        "Möller-Trumbore should leak at edges"
    );
}

#[test]
fn triangle_known_answers() {
    // The unit right triangle in z = 0, seen from z = 5 looking down -z.
    let t = Triangle::new(Vec3::ZERO, Vec3::X, Vec3::Y).unwrap();
    let r = ray([0.25, 0.5, 5.0], [0.0, 0.0, -1.0]);
    // b1 = x = 0.25, b2 = y = 0.5, b0 = 0.25, t = 5.
    let crossing = Barycentric {
        t: 5.0,
        b: [0.25, 0.25, 0.5],
    };
    assert_eq!(t.moller_trumbore(&r, Interval::AHEAD), Some(crossing));
    assert_eq!(t.watertight(&r, Interval::AHEAD), Some(crossing));
    let h = t.hit(&r, Interval::AHEAD).unwrap();
    assert_eq!(h.point, Vec3::new(0.25, 0.5, 0.0));
    assert_eq!(h.normal, Vec3::Z);
    assert!(h.front_face);
    // Outside (x + y > 1), behind, and parallel: misses.
    let outside = ray([0.75, 0.5, 5.0], [0.0, 0.0, -1.0]);
    let behind = ray([0.25, 0.5, 5.0], [0.0, 0.0, 1.0]);
    let parallel = ray([0.25, 0.25, 0.0], [1.0, 0.0, 0.0]);
    for r in [outside, behind, parallel] {
        assert!(t.moller_trumbore(&r, Interval::AHEAD).is_none());
        assert!(t.watertight(&r, Interval::AHEAD).is_none());
        assert!(Shape::Triangle(t).hit(&r, Interval::AHEAD).is_none());
    }
    // From below: back face, normal still +z.
    let h = t
        .hit(&ray([0.25, 0.5, -5.0], [0.0, 0.0, 1.0]), Interval::AHEAD)
        .unwrap();
    assert!(!h.front_face);
    assert_eq!(h.normal, Vec3::Z);
}

#[test]
fn s7_barycentric_point_stays_on_the_plane() {
    // The unit triangle in the plane x + y + z = 1, hit from distance about 1e4.
    let t = Triangle::new(Vec3::X, Vec3::Y, Vec3::Z).unwrap();
    let off_plane = |p: Vec3| ((p.x as f64 + p.y as f64 + p.z as f64) - 1.0).abs() / 3f64.sqrt();
    let mut rng = common::Rng::seeded(0x9E37_79B9_7F4A_7C15);
    let (mut bary, mut ray_point) = (Vec::new(), Vec::new());
    for _ in 0..1000 {
        let (u, v) = (rng.next_f32(), rng.next_f32());
        let (u, v) = if u + v > 1.0 {
            (1.0 - u, 1.0 - v)
        } else {
            (u, v)
        };
        let aim = (1.0 - u - v) * Vec3::X + u * Vec3::Y + v * Vec3::Z;
        let dir = Vec3::new(rng.next_f32() - 0.5, rng.next_f32() - 0.5, 0.0) + Vec3::ONE;
        let o = aim + 1e4 * dir.normalize();
        let r = Ray::new(o, aim - o).unwrap();
        if let Some(h) = t.hit(&r, Interval::AHEAD) {
            bary.push(off_plane(h.point));
            ray_point.push(off_plane(r.at(h.t)));
        }
    }
    assert!(
        bary.len() > 900,
        "most rays aimed inside should hit: {}",
        bary.len()
    );
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (bary_max, ray_max) = (
        bary.iter().cloned().fold(0.0, f64::max),
        ray_point.iter().cloned().fold(0.0, f64::max),
    );
    let (bary_med, ray_med) = (median(&mut bary), median(&mut ray_point));
    eprintln!(
        "S7: barycentric off-plane median {bary_med:.1e} max {bary_max:.1e}; o + t d median {ray_med:.1e} max {ray_max:.1e}"
    );
    assert!(
        bary_max < 1e-6,
        "barycentric point off the plane by {bary_max}"
    );
    assert!(
        ray_med > 1e-5,
        "o + t d should be visibly off the plane: {ray_med}"
    );
    assert!(ray_med > 100.0 * bary_med.max(1e-9));
    // The numbers the S7 pages print: o + t d's median and worst distance from the
    // plane, then the barycentric point's (no sine or cosine: the same everywhere).
    let printed = format!("{ray_med:.1e} {ray_max:.1e} {bary_med:.1e} {bary_max:.1e}");
    assert_eq!(printed, "2.8e-4 2.3e-3 9.7e-9 4.3e-8");
    // "About 29 000 times closer": the ratio of the two medians, to two digits.
    let ratio = format!("{:.1e}", ray_med / bary_med);
    assert!(ratio == "2.8e4" || ratio == "2.9e4", "{ratio}");
    let printed_ratio = 2.8e-4 / 9.7e-9;
    assert_eq!((printed_ratio / 1000.0f64).round() * 1000.0, 29_000.0);
    // The exercise on S6's conservative slab: gamma_3, the factor 1 + 2 gamma_3, and
    // how far it moves a t_far of 100.
    let g3 = render_lessons::float::gamma(3);
    assert_eq!(
        format!("{g3:.2e} {:.1e} {:.1e}", 2.0 * g3, 200.0 * g3),
        "1.79e-7 3.6e-7 3.6e-5"
    );
}

#[test]
fn s6_conservative_box_never_rejects_its_own_triangle() {
    // The cases of lesson 11's S6 finding: rays aimed exactly at a vertex of random
    // triangles, kept when the watertight test hits, with the triangle's f32 box.
    let cases = box_cases(Quality::Quick).unwrap();
    let BoxCounts {
        rays: tested,
        plain: naive_miss,
        conservative: conservative_miss,
    } = box_counts(&cases);
    eprintln!(
        "S6: {tested} vertex hits; plain slab rejects {naive_miss}, conservative {conservative_miss}"
    );
    assert!(tested > 1000);
    assert_eq!(conservative_miss, 0);
    assert!(
        naive_miss > 0,
        "plain slab should reject some of its own triangles"
    );
}

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

fn coord() -> impl Strategy<Value = f32> {
    -50.0f32..50.0
}

fn point() -> impl Strategy<Value = Vec3> {
    (coord(), coord(), coord()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// Rays aimed at a random point near the shape, so that many of them hit. Directions
/// with exact zero components are mixed in on purpose.
fn aimed_ray() -> impl Strategy<Value = Ray> {
    (point(), point(), 0u8..8).prop_filter_map("origin != target", |(o, target, zero_mask)| {
        let mut d = target - o;
        for i in 0..3 {
            if zero_mask & (1 << i) != 0 {
                d[i] = 0.0;
            }
        }
        Ray::new(o, d).ok()
    })
}

fn no_nan(h: &render_lessons::shapes::Hit) -> bool {
    h.t.is_finite() && h.point.is_finite() && h.normal.is_finite()
}

proptest! {
    /// Tolerance: 1e-5 times the size of the numbers involved (1 + |o| + |t| + |c|),
    /// about 100 f32 roundings; a grazing plane hit can lie 1e4 away.
    #[test]
    fn hit_points_lie_on_their_surface(
        r in aimed_ray(),
        c in point(),
        radius in 0.1f32..20.0,
        n in point(),
        corners in (point(), point(), point()),
    ) {
        let scale = |t: f32| 1.0 + r.origin().abs().max_element() + t.abs() + c.abs().max_element();
        let tol = |t: f32| 1e-5 * scale(t);
        let sphere = Sphere::new(c, radius).unwrap();
        for (t0, t1) in [sphere.roots_stable(&r).pair(), sphere.roots_textbook(&r).pair()].into_iter().flatten() {
            prop_assert!(t0.is_finite() && t1.is_finite() && t0 <= t1);
        }
        if let Some(h) = sphere.hit(&r, Interval::AHEAD) {
            prop_assert!(no_nan(&h));
            prop_assert!(((h.point - c).length() - radius).abs() < tol(h.t), "sphere {:?}", h);
            prop_assert!((h.normal.length() - 1.0).abs() < 1e-5);
        }
        if let Ok(plane) = Plane::new(c, n)
            && let Some(h) = plane.hit(&r, Interval::AHEAD)
        {
            prop_assert!(no_nan(&h));
            prop_assert!((h.point - c).dot(plane.normal()).abs() < tol(h.t), "plane {:?}", h);
        }
        let (a, b, e) = corners;
        let bx = Aabb::new(a.min(b), a.max(b)).unwrap();
        if let Some(ClosedSpan { t0, t1 }) = bx.slab(&r, Interval::AHEAD) {
            prop_assert!(!t0.is_nan() && !t1.is_nan() && t0 <= t1);
        }
        if let Some(h) = bx.hit(&r, Interval::AHEAD) {
            prop_assert!(no_nan(&h));
            let inside = h.point.cmpge(bx.min() - tol(h.t)).all() && h.point.cmple(bx.max() + tol(h.t)).all();
            let on_face = (0..3).any(|i| h.point[i] == bx.min()[i] || h.point[i] == bx.max()[i]);
            prop_assert!(inside && on_face, "box {:?}", h);
        }
        if let Ok(tri) = Triangle::new(a, b, e) {
            if let Some(h) = tri.hit(&r, Interval::AHEAD) {
                prop_assert!(no_nan(&h));
                prop_assert!((h.point - a).dot(tri.normal()).abs() < tol(h.t), "triangle {:?}", h);
                prop_assert!((h.point - r.at(h.t)).length() < tol(h.t));
            }
            if let Some(c) = tri.moller_trumbore(&r, Interval::AHEAD) {
                prop_assert!(c.t.is_finite() && c.b.iter().all(|b| b.is_finite()));
            }
        }
    }
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
    let close = |a: &[f32], b: &[f32]| {
        a.len() == b.len()
            && a.iter()
                .zip(b)
                .all(|(x, y)| (x - y).abs() <= 1e-5 * y.abs())
    };
    for case in &cases {
        let [(_, naive), (_, robust)] = lesson::methods(&case.shape, &case.ray);
        assert!(
            close(&naive, &robust),
            "{}: {naive:?} {robust:?}",
            case.name
        );
        assert!(!robust.is_empty(), "{}", case.name);
    }
    for case in &hard {
        let [(_, naive), (_, robust)] = lesson::methods(&case.shape, &case.ray);
        assert!(
            !close(&naive, &robust),
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
                "plane" => {
                    (p - Vec3::new(0.0, -0.5, 0.0)).dot(Vec3::new(1.0, 2.0, 0.0).normalize())
                }
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

/// STABILITY S3: smallpt's left wall, a sphere of radius 1e5 centred at
/// (1e5 + 1, 40.8, 81.6), against the same wall as the plane x = 1. Rays from inside
/// the room hit the wall; cosine-distributed bounce rays leave the hit point with
/// smallpt's t > 1e-4. No bounce can hit a flat wall again; how many do? Returns the
/// self-hits, the bounce rays and the wall's hit points.
fn s3_wall(wall: Shape) -> (u32, u32, Vec<Vec3>) {
    use render_lessons::basis::Basis;
    use render_lessons::sampling::{cosine_hemisphere, grid};
    let eye = Vec3::new(50.0, 40.0, 80.0);
    let (mut self_hits, mut total, mut points) = (0, 0, Vec::new());
    for aim in grid(16) {
        let target = Vec3::new(1.0, 10.0 + 60.0 * aim.x, 20.0 + 120.0 * aim.y);
        let Some(hit) = wall.hit(
            &Ray::new(eye, target - eye).unwrap(),
            Interval::new(1e-4, f32::INFINITY),
        ) else {
            continue;
        };
        points.push(hit.point);
        let frame = Basis::around(hit.normal);
        for u in grid(8) {
            let bounce = Ray::new(hit.point, frame.to_world(cosine_hemisphere(u))).unwrap();
            total += 1;
            self_hits += u32::from(
                wall.hit(&bounce, Interval::new(1e-4, f32::INFINITY))
                    .is_some(),
            );
        }
    }
    (self_hits, total, points)
}

#[test]
fn s3_a_wall_modelled_as_a_huge_sphere_hits_itself_in_f32_a_plane_does_not() {
    let (centre, radius) = (Vec3::new(1e5 + 1.0, 40.8, 81.6), 1e5);
    let sphere = Shape::Sphere(Sphere::new(centre, radius).unwrap());
    let plane = Shape::Plane(Plane::new(Vec3::new(1.0, 0.0, 0.0), Vec3::X).unwrap());
    let (sphere_hits, total, sphere_points) = s3_wall(sphere);
    let (plane_hits, _, plane_points) = s3_wall(plane);
    let off_plane = |points: &[Vec3]| points.iter().map(|p| (p.x - 1.0).abs()).fold(0.0, f32::max);
    let (sphere_off, plane_off) = (off_plane(&sphere_points), off_plane(&plane_points));
    // In f64, how far the exact sphere bulges past x = 1 at the hit points' y and z
    // (curvature, not error), and how far the f32 hit points lie from the exact
    // sphere (the rounding error).
    let c = centre.as_dvec3();
    let r = f64::from(radius);
    let (mut bulge, mut off_sphere) = (0.0f64, 0.0f64);
    for p in sphere_points.iter().map(|p| p.as_dvec3()) {
        let lateral = (p.y - c.y).powi(2) + (p.z - c.z).powi(2);
        bulge = bulge.max(c.x - (r * r - lateral).sqrt() - 1.0);
        off_sphere = off_sphere.max(((p - c).length() - r).abs());
    }
    eprintln!(
        "S3: sphere wall {sphere_hits}/{total} bounces hit their own wall, hit points up to {sphere_off:.1e} off x = 1 \
         (the exact sphere bulges {bulge:.1e} past it there), up to {off_sphere:.1e} off the exact sphere; \
         plane wall {plane_hits}/{total}, up to {plane_off:.1e} off"
    );
    assert_eq!(total, 256 * 64, "16 384 bounce rays");
    // The count the pages print, 1728 (10.5 %), measured on x86-64; another libm's
    // sin and cos may move a few bounce directions, hence the 1 % slack.
    assert!(
        sphere_hits.abs_diff(1728) <= 17,
        "1728 of 16 384 bounces hit the sphere wall again: {sphere_hits}"
    );
    assert_eq!(format!("{:.1}", 100.0 * 1728.0 / 16384.0), "10.5");
    assert!(
        (0.0225..0.0235).contains(&sphere_off),
        "hit points up to 2.3e-2 off x = 1: {sphere_off}"
    );
    assert_eq!(format!("{bulge:.1e}"), "2.1e-2", "the sphere's own bulge");
    // The hit points need no sine or cosine, so this holds on every platform.
    assert_eq!(
        format!("{off_sphere:.1e}"),
        "8.5e-3",
        "f32 hit points off the exact sphere by about eps R"
    );
    assert_eq!(plane_hits, 0);
    assert_eq!(
        plane_off, 0.0,
        "a plane's hit point is projected onto the plane"
    );
}

/// The rays along the six faces of the cube [-1, 1]^3, each with its zero direction
/// components of sign `zero` (+0.0 or -0.0): the origin lies in the face's plane, 5
/// units before the box along the next axis, in the middle of the third.
fn rays_along_faces(zero: f32) -> Vec<Ray> {
    let mut rays = Vec::new();
    for axis in 0..3 {
        for side in [-1.0, 1.0] {
            let (along, across) = ((axis + 1) % 3, (axis + 2) % 3);
            let (mut o, mut d) = (Vec3::ZERO, Vec3::ZERO);
            o[axis] = side;
            o[along] = -5.0;
            d[axis] = zero;
            d[across] = zero;
            d[along] = 1.0;
            rays.push(Ray::new(o, d).unwrap());
        }
    }
    rays
}

#[test]
fn s8_a_ray_along_any_face_hits_for_either_sign_of_zero() {
    // The closed box is hit by a ray running in a face's plane over the face, from
    // t = 4 to 6, whether that direction component is +0 or -0.
    let b = cube();
    for zero in [0.0f32, -0.0] {
        for r in rays_along_faces(zero) {
            let (o, d) = (r.origin(), r.direction());
            assert_eq!(
                b.slab(&r, Interval::AHEAD),
                closed(4.0, 6.0),
                "o {o}, d {d:?}"
            );
            let wide = b.slab_conservative(&r, Interval::AHEAD);
            assert!(wide.is_some(), "conservative, o {o}, d {d:?}");
            let hit = Shape::Aabb(b).hit(&r, Interval::AHEAD);
            assert_eq!(hit.map(|h| h.t), Some(4.0), "hit, o {o}, d {d:?}");
            assert_eq!(b.crossings(&r).as_slice(), [4.0, 6.0], "crossings, o {o}");
        }
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
    let sphere = Sphere::new(Vec3::ZERO, 1.0).unwrap();
    let ray = Ray::new(Vec3::new(-3.0, 0.5, 0.0), Vec3::X).unwrap();
    let (t0, t1) = sphere.roots_stable(&ray).pair().unwrap();
    assert_eq!(
        format!("{t0:.3} {t1:.3} {:.3}", 0.75f64.sqrt()),
        "2.134 3.866 0.866"
    );
    // The plane: (p0 - o) . n and d . n with n = (1, 2, 0)/sqrt 5, d = (1, -1, 0)/sqrt 2.
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
    // Triangle exercise 2: b1 = 0.75 and b2 = 0.5 sum to 1.25.
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
    // Exercise 7.2's far case, as its check builds it: a unit sphere 1e4 away along
    // (0.3, 0.2, -1), the ray aimed at its centre. The roots are 9999 and 10001; the
    // school formula in f32 rounds b^2 - 4ac to 0 and gives a double root at 10000.001.
    let aim = Vec3::new(0.3, 0.2, -1.0).normalize();
    let centre = 1e4 * aim;
    let f = -centre;
    let (a, b, c) = (aim.dot(aim), 2.0 * f.dot(aim), f.dot(f) - 1.0);
    let school = |sign: f32| (-b + sign * (b * b - 4.0 * a * c).max(0.0).sqrt()) / (2.0 * a);
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
