//! Lesson 07, the box (chapter 07_3): the slab test's truth table and rays along a
//! face for either sign of zero (STABILITY S8), the face normal, pbrt's gamma, and
//! the conservative slab that never rejects its own triangle's box (S6).

use crate::common::{cube, ray};
use render_lessons::course::measure::Quality;
use render_lessons::course::measure::triangle::{BoxCounts, box_cases, box_counts};

use glam::Vec3;
use render_lessons::ray::{ClosedSpan, Interval, Ray};
use render_lessons::shapes::{Aabb, Shape};

// ---------------------------------------------------------------- box (S8)

/// A slab test written the naive way round:
/// `t0 = if t0 > t_near { t0 } else { t_near }` lets a NaN from 0 * inf replace the interval (kept to show the failure).
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
