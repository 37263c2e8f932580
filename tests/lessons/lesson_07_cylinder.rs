//! The capped cylinder (issue 21, item 9.8): hits through the side and through a
//! cap, rays grazing the rim or tangent to the side, rays from inside, normals,
//! error bounds that put every hit within them of the surface, bounds that hold
//! every hit, and The Ray Tracer Challenge's closed-cylinder cases.

use crate::common::{self, close, ray};
use glam::Vec3;
use render_lessons::error::Error;
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{Cylinder, CylinderPart, Instance, Shape};
use render_lessons::transform::Transform;

/// Radius 1 from z = 0 to z = 2.
fn can() -> Cylinder {
    Cylinder::new(1.0, 0.0, 2.0).unwrap()
}

/// Every component within this puts the whole vector within 1e-5 of the other
/// (1e-5 / sqrt 3).
const TOL: f64 = 5.7e-6;

#[test]
fn through_the_side() {
    let r = ray([-5.0, 0.5, 1.0], [1.0, 0.0, 0.0]);
    let h = can().hit(&r, Interval::AHEAD).unwrap();
    let x = 0.75f32.sqrt();
    assert!((h.t - (5.0 - x)).abs() < 1e-6, "{}", h.t);
    assert!(close(h.point, Vec3::new(-x, 0.5, 1.0), TOL), "{}", h.point);
    assert!(
        close(h.normal, Vec3::new(-x, 0.5, 0.0), TOL),
        "{}",
        h.normal
    );
    assert!(h.front_face);
    // It leaves through the side opposite.
    assert_eq!(can().crossings(&r).len(), 2);
    assert!((can().crossings(&r)[1] - (5.0 + x)).abs() < 1e-6);
}

#[test]
fn through_a_cap() {
    let down = ray([0.3, 0.2, 5.0], [0.0, 0.0, -1.0]);
    let h = can().hit(&down, Interval::AHEAD).unwrap();
    assert_eq!(
        (h.t, h.point, h.normal),
        (3.0, Vec3::new(0.3, 0.2, 2.0), Vec3::Z)
    );
    assert!(h.front_face);
    assert_eq!(can().crossings(&down).as_slice(), [3.0, 5.0]);
    let up = ray([0.3, 0.2, -1.0], [0.0, 0.0, 1.0]);
    let h = can().hit(&up, Interval::AHEAD).unwrap();
    assert_eq!(
        (h.t, h.point, h.normal),
        (1.0, Vec3::new(0.3, 0.2, 0.0), -Vec3::Z)
    );
    // Slanted: in through the top, out through the side.
    let slant = ray([0.0, 0.0, 3.0], [0.6, 0.0, -0.8]);
    let entry = can().nearest(&slant, Interval::AHEAD).unwrap();
    assert_eq!(entry.part, CylinderPart::Top);
    assert!((entry.t - 1.25).abs() < 1e-6);
    let t1 = can().crossings(&slant)[1];
    assert!(
        (slant.at(t1).x - 1.0).abs() < 1e-6,
        "leaves through the side"
    );
}

#[test]
fn beyond_the_caps_the_infinite_cylinder_is_not_there() {
    // The infinite cylinder x^2 + y^2 = 1 would be hit at x = -1.
    for z in [-0.5, 2.5] {
        let r = ray([-5.0, 0.0, z], [1.0, 0.0, 0.0]);
        assert!(can().hit(&r, Interval::AHEAD).is_none(), "z = {z}");
        assert!(can().crossings(&r).is_empty());
    }
    // Parallel to the axis outside the radius: nothing; inside: both caps.
    assert!(
        can()
            .crossings(&ray([1.5, 0.0, 5.0], [0.0, 0.0, -1.0]))
            .is_empty()
    );
    let inside = ray([0.5, -0.5, 5.0], [0.0, 0.0, -1.0]);
    assert_eq!(can().crossings(&inside).as_slice(), [3.0, 5.0]);
}

#[test]
fn grazing_the_side_and_the_rim() {
    // Tangent to the side at (1, 0, 1): a double crossing, the side's normal.
    let tangent = ray([1.0, -5.0, 1.0], [0.0, 1.0, 0.0]);
    assert_eq!(can().crossings(&tangent).as_slice(), [5.0, 5.0]);
    let h = can().hit(&tangent, Interval::AHEAD).unwrap();
    assert_eq!(
        (h.t, h.point, h.normal),
        (5.0, Vec3::new(1.0, 0.0, 1.0), Vec3::X)
    );
    // Along the top cap's plane: the closed solid is touched over a diameter, from
    // the rim at (-1, 0, 2) to (1, 0, 2).
    let skim = ray([-5.0, 0.0, 2.0], [1.0, 0.0, 0.0]);
    assert_eq!(can().crossings(&skim).as_slice(), [4.0, 6.0]);
    let h = can().hit(&skim, Interval::AHEAD).unwrap();
    assert_eq!(h.point, Vec3::new(-1.0, 0.0, 2.0));
    // Just above that plane, nothing; just below, the side.
    let above = ray([-5.0, 0.0, 2.0f32.next_up()], [1.0, 0.0, 0.0]);
    assert!(can().hit(&above, Interval::AHEAD).is_none());
    let below = ray([-5.0, 0.0, 2.0f32.next_down()], [1.0, 0.0, 0.0]);
    let h = can().hit(&below, Interval::AHEAD).unwrap();
    assert_eq!((h.t, h.normal), (4.0, -Vec3::X));
    // Through the rim's corner point (1, 0, 2) at 45 degrees, tangent to the side
    // there: rounding decides hit or miss, but a hit is the rim point.
    let corner = ray([1.0, -5.0, 7.0], [0.0, 1.0, -1.0]);
    if let Some(h) = can().hit(&corner, Interval::AHEAD) {
        assert!(close(h.point, Vec3::new(1.0, 0.0, 2.0), TOL), "{}", h.point);
        assert!(
            h.normal == Vec3::Z || close(h.normal, Vec3::X, TOL),
            "{}",
            h.normal
        );
    }
    // In through the rim itself, from outside and above, at shallow angles: the line
    // enters the solid at the rim and goes on inside. Its origin is rounded, so the
    // f32 line passes a little above or below the rim, and enters by the cap or by
    // the side near it (within 1e-4 at these angles), but never misses.
    for k in 1..50 {
        let s = k as f32 * 1e-3;
        let r = ray([-5.0, 0.0, 2.0 + 4.0 * s], [4.0, 0.0, -4.0 * s]);
        let h = can().hit(&r, Interval::AHEAD).expect("the rim");
        let off = (h.point - Vec3::new(-1.0, 0.0, 2.0)).length();
        assert!(off < 1e-4, "{}", h.point);
    }
}

#[test]
fn from_inside_it_leaves_by_the_back_face() {
    let o = [0.0, 0.0, 1.0];
    let cases = [
        ([1.0, 0.0, 0.0], 1.0, Vec3::X),
        ([0.0, -1.0, 0.0], 1.0, -Vec3::Y),
        ([0.0, 0.0, 1.0], 1.0, Vec3::Z),
        ([0.0, 0.0, -1.0], 1.0, -Vec3::Z),
    ];
    for (d, t, n) in cases {
        let r = ray(o, d);
        let h = can().hit(&r, Interval::AHEAD).unwrap();
        assert!(
            (h.t - t).abs() < 1e-6 && close(h.normal, n, TOL),
            "{d:?}: {h:?}"
        );
        assert!(!h.front_face, "{d:?}");
        assert_eq!(h.facing(), -h.normal);
        // The whole line: behind the origin first, negative.
        let xs = can().crossings(&r);
        assert!(xs[0] < 0.0 && xs[1] > 0.0, "{xs:?}");
    }
}

#[test]
fn normal_at_is_the_nearest_surface_s() {
    let c = can();
    assert_eq!(c.normal_at(Vec3::new(0.3, 0.2, 2.0)), Vec3::Z);
    assert_eq!(c.normal_at(Vec3::new(0.3, 0.2, 0.0)), -Vec3::Z);
    assert!(close(c.normal_at(Vec3::new(0.0, -1.0, 1.0)), -Vec3::Y, TOL));
    assert!(close(
        c.normal_at(Vec3::new(0.6, 0.8, 0.5)),
        Vec3::new(0.6, 0.8, 0.0),
        TOL
    ));
    // On the rim a cap wins, as in The Ray Tracer Challenge.
    assert_eq!(c.normal_at(Vec3::new(1.0, 0.0, 2.0)), Vec3::Z);
}

#[test]
fn bad_cylinders_name_their_parameter() {
    let param = |r: Result<Cylinder, Error>| r.unwrap_err().param().to_string();
    assert_eq!(param(Cylinder::new(0.0, 0.0, 1.0)), "radius");
    assert_eq!(param(Cylinder::new(f32::NAN, 0.0, 1.0)), "radius");
    assert_eq!(param(Cylinder::new(1e20, 0.0, 1.0)), "radius"); // r^2 overflows
    assert_eq!(param(Cylinder::new(1.0, f32::NEG_INFINITY, 1.0)), "z_min");
    assert_eq!(param(Cylinder::new(1.0, 0.0, f32::NAN)), "z_max");
    assert_eq!(param(Cylinder::new(1.0, 1.0, 1.0)), "z range");
}

/// The Ray Tracer Challenge's closed cylinder: radius 1 about y, from y = 1 to 2 (an
/// instance of ours about z, turned by -90 degrees about x and moved up by 1).
fn rtc_closed_cylinder() -> Shape {
    let turn = Transform::rotation_x(-std::f32::consts::FRAC_PI_2);
    let m = turn.then(Transform::translation(0.0, 1.0, 0.0));
    let inner = Shape::from(Cylinder::new(1.0, 0.0, 1.0).unwrap());
    Shape::from(Instance::new(inner, m).unwrap())
}

#[test]
fn rtc_intersecting_the_caps_of_a_closed_cylinder() {
    // Each ray meets the solid twice (two corner cases among them).
    let c = rtc_closed_cylinder();
    let cases = [
        ([0.0, 3.0, 0.0], [0.0, -1.0, 0.0]),
        ([0.0, 3.0, -2.0], [0.0, -1.0, 2.0]),
        ([0.0, 4.0, -2.0], [0.0, -1.0, 1.0]),
        ([0.0, 0.0, -2.0], [0.0, 1.0, 2.0]),
        ([0.0, -1.0, -2.0], [0.0, 1.0, 1.0]),
    ];
    for (o, d) in cases {
        assert_eq!(c.crossings(&ray(o, d)).len(), 2, "{o:?} {d:?}");
    }
    // The normals on the caps.
    let normals = [
        ([0.0, 1.0, 0.0], -Vec3::Y),
        ([0.5, 1.0, 0.0], -Vec3::Y),
        ([0.0, 1.0, 0.5], -Vec3::Y),
        ([0.0, 2.0, 0.0], Vec3::Y),
        ([0.5, 2.0, 0.0], Vec3::Y),
        ([0.0, 2.0, 0.5], Vec3::Y),
    ];
    for (p, n) in normals {
        assert!(close(c.normal_at(Vec3::from(p)), n, TOL), "{p:?}");
    }
}

/// Every hit lies on the surface within its error bound (in f64), its normal is
/// the surface's there, its point is inside the bounds, and `hit` agrees with
/// the first crossing ahead.
#[test]
fn hits_lie_on_the_surface_within_their_error_bound() {
    common::for_cases(72, 2000, |rng| {
        let o = rng.vec3(Vec3::new(-6.0, -6.0, -4.0), Vec3::new(6.0, 6.0, 7.0));
        let aim = rng.vec3(Vec3::new(-1.2, -1.2, -0.5), Vec3::new(1.2, 1.2, 3.5));
        let c = Cylinder::new(1.1, -0.5, 3.0).unwrap();
        let Ok(r) = Ray::new(o, aim - o) else { return };
        let Some(h) = c.hit(&r, Interval::AHEAD) else {
            return;
        };
        let first = c.crossings(&r).iter().copied().find(|&t| t > 0.0);
        assert_eq!(Some(h.t), first);
        let bounds = c.bounds().unwrap();
        assert!(h.point.cmpge(bounds.min()).all() && h.point.cmple(bounds.max()).all());
        let p = h.point.as_dvec3();
        let e = h.error.as_dvec3();
        let rho = p.truncate().length();
        let (r, lo, hi) = (1.1f64, -0.5f64, 3.0f64);
        // Some point of the surface within p +- e: on the side, or on a cap.
        let on_side =
            (rho - r).abs() <= e.truncate().length() + 1e-12 && p.z >= lo && p.z <= hi;
        let on_cap = (p.z == lo || p.z == hi) && rho <= r + e.truncate().length();
        assert!(on_side || on_cap, "{} (error {})", h.point, h.error);
        assert!((h.normal.length() - 1.0).abs() < 1e-6);
        if on_cap && !on_side {
            assert_eq!(h.normal.z.abs(), 1.0);
        }
    });
}
