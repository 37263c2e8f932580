//! The Ray Tracer Challenge's shapes, ported (see `porting` for the conventions that
//! differ): spheres and instances (RTC ch. 5 and 6), planes (ch. 9), cubes (ch. 12),
//! triangles (ch. 15), cylinders and cones (ch. 13) along any axis, quads (by hand),
//! and every shape's crossings agreeing with its hit and normal.

#![allow(
    clippy::approx_constant,
    reason = "RTC's published values are quoted as printed, 0.70711 included"
)]

use crate::common::{assert_close, cube, ray, unit_sphere};
use crate::porting::{RTC_EPSILON, crossings, v};
use std::f32::consts::{FRAC_PI_2, PI};

use glam::Vec3;
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{
    Aabb, Instance, Plane, Quad, Quadric, Shape, Sphere, Triangle,
};
use render_lessons::transform::Transform;

// ---------------------------------------------------------------------------------
// Spheres and instances (RTC ch. 5 and 6).

/// RTC ch. 5: a ray at (0, 0, -5) along +z crosses at 4 and 6; tangent at (0, 1, -5):
/// 5 twice; at (0, 2, -5) misses; from the centre: -1 and 1; sphere behind: -6, -4.
#[test]
fn rtc_sphere_crossings() {
    let s = Shape::from(unit_sphere());
    crossings(&s, &ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]), &[4.0, 6.0]);
    crossings(&s, &ray([0.0, 1.0, -5.0], [0.0, 0.0, 1.0]), &[5.0, 5.0]);
    crossings(&s, &ray([0.0, 2.0, -5.0], [0.0, 0.0, 1.0]), &[]);
    crossings(&s, &ray([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]), &[-1.0, 1.0]);
    crossings(&s, &ray([0.0, 0.0, 5.0], [0.0, 0.0, 1.0]), &[-6.0, -4.0]);
}

/// RTC ch. 6: the normal on a unit sphere at a point on each axis is that axis, and at
/// (sqrt3/3, sqrt3/3, sqrt3/3) is that point, of unit length.
#[test]
fn rtc_sphere_normals() {
    let s = Shape::from(unit_sphere());
    for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
        assert_eq!(s.normal_at(axis), axis);
    }
    let k = 3f32.sqrt() / 3.0;
    let n = s.normal_at(Vec3::splat(k));
    assert_close(n, Vec3::splat(k), 1e-6);
    assert_close(n.length(), 1.0, 1e-6);
}

/// RTC ch. 5: "Intersecting a scaled sphere with a ray" (scaling(2, 2, 2)): 3 and 7;
/// "a translated sphere" (translation(5, 0, 0)): no crossing.
#[test]
fn rtc_transformed_sphere_crossings() {
    let r = ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]);
    let scaled =
        Instance::new(Shape::from(unit_sphere()), Transform::scale(2.0, 2.0, 2.0))
            .unwrap();
    crossings(&Shape::Instance(Box::new(scaled)), &r, &[3.0, 7.0]);
    let moved = Instance::new(
        Shape::from(unit_sphere()),
        Transform::translation(5.0, 0.0, 0.0),
    )
    .unwrap();
    crossings(&Shape::Instance(Box::new(moved)), &r, &[]);
}

/// RTC ch. 6: "Computing the normal on a translated sphere" (translation(0, 1, 0)) at
/// (0, 1.70711, -0.70711): (0, 0.70711, -0.70711); "on a transformed sphere"
/// (scaling(1, 0.5, 1) * rotation_z(pi/5)) at (0, sqrt2/2, -sqrt2/2):
/// (0, 0.97014, -0.24254). The product is written as in the book.
#[test]
fn rtc_transformed_sphere_normals() {
    let moved = Instance::new(
        Shape::from(unit_sphere()),
        Transform::translation(0.0, 1.0, 0.0),
    )
    .unwrap();
    assert_close(
        moved.normal_at(v(0.0, 1.70711, -0.70711)),
        v(0.0, 0.70711, -0.70711),
        RTC_EPSILON,
    );
    let m = Transform::scale(1.0, 0.5, 1.0) * Transform::rotation_z(PI / 5.0);
    let shape = Shape::Instance(Box::new(
        Instance::new(Shape::from(unit_sphere()), m).unwrap(),
    ));
    let h = 2f32.sqrt() / 2.0;
    assert_close(
        shape.normal_at(v(0.0, h, -h)),
        v(0.0, 0.97014, -0.24254),
        RTC_EPSILON,
    );
}

// ---------------------------------------------------------------------------------
// Planes (RTC ch. 9).

/// RTC's plane is y = 0 with normal +y. Its normal is constant; a ray parallel to it
/// or in it has no crossing; from above (0, 1, 0) going down, and from below
/// (0, -1, 0) going up, the crossing is at t = 1.
#[test]
fn rtc_plane() {
    let p = Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Y).unwrap());
    for q in [v(0.0, 0.0, 0.0), v(10.0, 0.0, -10.0), v(-5.0, 0.0, 150.0)] {
        assert_eq!(p.normal_at(q), Vec3::Y);
    }
    crossings(&p, &ray([0.0, 10.0, 0.0], [0.0, 0.0, 1.0]), &[]);
    crossings(&p, &ray([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]), &[]);
    crossings(&p, &ray([0.0, 1.0, 0.0], [0.0, -1.0, 0.0]), &[1.0]);
    crossings(&p, &ray([0.0, -1.0, 0.0], [0.0, 1.0, 0.0]), &[1.0]);
}

// ---------------------------------------------------------------------------------
// Cubes (RTC ch. 12): the box from (-1, -1, -1) to (1, 1, 1).

/// RTC: "A ray intersects a cube": through each face, 4 and 6; from inside, -1 and 1.
#[test]
fn rtc_cube_crossings() {
    let c = Shape::from(cube());
    let cases = [
        ([5.0, 0.5, 0.0], [-1.0, 0.0, 0.0], [4.0, 6.0]),
        ([-5.0, 0.5, 0.0], [1.0, 0.0, 0.0], [4.0, 6.0]),
        ([0.5, 5.0, 0.0], [0.0, -1.0, 0.0], [4.0, 6.0]),
        ([0.5, -5.0, 0.0], [0.0, 1.0, 0.0], [4.0, 6.0]),
        ([0.5, 0.0, 5.0], [0.0, 0.0, -1.0], [4.0, 6.0]),
        ([0.5, 0.0, -5.0], [0.0, 0.0, 1.0], [4.0, 6.0]),
        ([0.0, 0.5, 0.0], [0.0, 0.0, 1.0], [-1.0, 1.0]),
    ];
    for (o, d, want) in cases {
        crossings(&c, &ray(o, d), &want);
    }
}

/// RTC: "A ray misses a cube".
#[test]
fn rtc_cube_misses() {
    let c = Shape::from(cube());
    let cases = [
        ([-2.0, 0.0, 0.0], [0.2673, 0.5345, 0.8018]),
        ([0.0, -2.0, 0.0], [0.8018, 0.2673, 0.5345]),
        ([0.0, 0.0, -2.0], [0.5345, 0.8018, 0.2673]),
        ([2.0, 0.0, 2.0], [0.0, 0.0, -1.0]),
        ([0.0, 2.0, 2.0], [0.0, -1.0, 0.0]),
        ([2.0, 2.0, 0.0], [-1.0, 0.0, 0.0]),
    ];
    for (o, d) in cases {
        crossings(&c, &ray(o, d), &[]);
    }
}

/// RTC: "The normal on the surface of a cube", corners included ((1, 1, 1) -> +x,
/// (-1, -1, -1) -> -x: ties go to x).
#[test]
fn rtc_cube_normals() {
    let c = Shape::from(cube());
    let cases = [
        (v(1.0, 0.5, -0.8), v(1.0, 0.0, 0.0)),
        (v(-1.0, -0.2, 0.9), v(-1.0, 0.0, 0.0)),
        (v(-0.4, 1.0, -0.1), v(0.0, 1.0, 0.0)),
        (v(0.3, -1.0, -0.7), v(0.0, -1.0, 0.0)),
        (v(-0.6, 0.3, 1.0), v(0.0, 0.0, 1.0)),
        (v(0.4, 0.4, -1.0), v(0.0, 0.0, -1.0)),
        (v(1.0, 1.0, 1.0), v(1.0, 0.0, 0.0)),
        (v(-1.0, -1.0, -1.0), v(-1.0, 0.0, 0.0)),
    ];
    for (p, n) in cases {
        assert_eq!(c.normal_at(p), n, "at {p}");
    }
}

/// Not a cube, nor centred: the face nearest the point wins by distance, not by the
/// largest coordinate. Box [0, 10] x [0, 1] x [0, 1]: (9, 0.5, 0.9) is nearest the
/// z = 1 face (0.1 away), although its x is the largest coordinate.
#[test]
fn box_normal_picks_the_nearest_face() {
    let b = Aabb::new(Vec3::ZERO, v(10.0, 1.0, 1.0)).unwrap();
    assert_eq!(b.normal_at(v(9.0, 0.5, 0.9)), Vec3::Z);
    assert_eq!(b.normal_at(v(10.0, 0.5, 0.5)), Vec3::X);
    assert_eq!(b.normal_at(v(3.0, 0.0, 0.5)), Vec3::NEG_Y);
}

// ---------------------------------------------------------------------------------
// Triangles (RTC ch. 15): p1 = (0, 1, 0), p2 = (-1, 0, 0), p3 = (1, 0, 0).

const P1: Vec3 = Vec3::new(0.0, 1.0, 0.0);
const P2: Vec3 = Vec3::new(-1.0, 0.0, 0.0);
const P3: Vec3 = Vec3::new(1.0, 0.0, 0.0);

/// RTC: "Constructing a triangle": e1 = (-1, -1, 0), e2 = (1, -1, 0), normal
/// (0, 0, -1) = normalize(e2 x e1). Here the normal is e1 x e2 = (0, 0, 1); listing
/// the corners p1, p3, p2 gives RTC's normal back.
#[test]
fn rtc_triangle_normal_flips_with_the_winding() {
    let same_order = Triangle::new(P1, P2, P3).unwrap();
    assert_eq!(same_order.normal_at(Vec3::ZERO), Vec3::Z);
    let rtc_normal = Shape::Triangle(Triangle::new(P1, P3, P2).unwrap());
    for p in [v(0.0, 0.5, 0.0), v(-0.5, 0.75, 0.0), v(0.5, 0.25, 0.0)] {
        assert_eq!(rtc_normal.normal_at(p), Vec3::NEG_Z, "RTC: normal_at({p})");
    }
}

/// RTC: "Intersecting a ray parallel to the triangle", "A ray misses the p1-p3 edge",
/// "... p1-p2 edge", "... p2-p3 edge", and "A ray strikes a triangle": t = 2. The
/// winding does not change where the ray crosses.
#[test]
fn rtc_triangle_crossings() {
    for tri in [Triangle::new(P1, P2, P3), Triangle::new(P1, P3, P2)] {
        let tri = Shape::Triangle(tri.unwrap());
        crossings(&tri, &ray([0.0, -1.0, -2.0], [0.0, 1.0, 0.0]), &[]);
        crossings(&tri, &ray([1.0, 1.0, -2.0], [0.0, 0.0, 1.0]), &[]);
        crossings(&tri, &ray([-1.0, 1.0, -2.0], [0.0, 0.0, 1.0]), &[]);
        crossings(&tri, &ray([0.0, -1.0, -2.0], [0.0, 0.0, 1.0]), &[]);
        crossings(&tri, &ray([0.0, 0.5, -2.0], [0.0, 0.0, 1.0]), &[2.0]);
    }
}

// ---------------------------------------------------------------------------------
// Quads (no RTC counterpart; by hand).

/// The square q = (-1, -1, 0), a = (2, 0, 0), b = (0, 2, 0): normal a x b = +z.
/// From (0.5, 0.5, 3) down -z: t = 3. From (0, 0, 2) up +z the crossing is behind the
/// origin, t = -2. Outside the square, at x = 1.5: none.
#[test]
fn quad_crossings_and_normal() {
    let q = Shape::Quad(
        Quad::new(v(-1.0, -1.0, 0.0), v(2.0, 0.0, 0.0), v(0.0, 2.0, 0.0)).unwrap(),
    );
    assert_eq!(q.normal_at(v(0.3, -0.2, 0.0)), Vec3::Z);
    crossings(&q, &ray([0.5, 0.5, 3.0], [0.0, 0.0, -1.0]), &[3.0]);
    crossings(&q, &ray([0.0, 0.0, 2.0], [0.0, 0.0, 1.0]), &[-2.0]);
    crossings(&q, &ray([1.5, 0.0, 2.0], [0.0, 0.0, -1.0]), &[]);
}

// ---------------------------------------------------------------------------------
// Cylinders and cones along any axis (RTC ch. 13, uncapped: along y, radius 1).

fn rtc_cylinder() -> Shape {
    Shape::Quadric(Quadric::cylinder_along(Vec3::Y, 1.0).unwrap())
}

/// RTC: "A ray misses a cylinder" and "A ray strikes a cylinder" (directions
/// normalised, as RTC does).
#[test]
fn rtc_cylinder_crossings() {
    let c = rtc_cylinder();
    crossings(&c, &ray([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]), &[]);
    crossings(&c, &ray([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), &[]);
    crossings(&c, &ray([0.0, 0.0, -5.0], [1.0, 1.0, 1.0]), &[]);
    crossings(&c, &ray([1.0, 0.0, -5.0], [0.0, 0.0, 1.0]), &[5.0, 5.0]);
    crossings(&c, &ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]), &[4.0, 6.0]);
    crossings(
        &c,
        &ray([0.5, 0.0, -5.0], [0.1, 1.0, 1.0]),
        &[6.80798, 7.08872],
    );
}

/// RTC: "Normal vector on a cylinder".
#[test]
fn rtc_cylinder_normals() {
    let c = rtc_cylinder();
    let cases = [
        (v(1.0, 0.0, 0.0), v(1.0, 0.0, 0.0)),
        (v(0.0, 5.0, -1.0), v(0.0, 0.0, -1.0)),
        (v(0.0, -2.0, 1.0), v(0.0, 0.0, 1.0)),
        (v(-1.0, 1.0, 0.0), v(-1.0, 0.0, 0.0)),
    ];
    for (p, n) in cases {
        assert_close(c.normal_at(p), n, 1e-7);
    }
}

/// A cylinder along x, two ways: `cylinder_along(Vec3::X, r)`, and lesson 07's
/// cylinder about z placed by rotation_y(pi/2), which turns +z into +x. RTC's oblique
/// case with y and x swapped (a reflection, which keeps distances): origin
/// (0, 0.5, -5), direction (1, 0.1, 1) -> 6.80798 and 7.08872. And by hand, with an
/// axis given as (-3, 0, 0) and radius 2: the ray from (-5, 0, 3) along -z crosses
/// y^2 + z^2 = 4 at z = 2 and z = -2, so t = 1 and 5.
#[test]
fn cylinder_along_x_two_ways() {
    let along = Shape::Quadric(Quadric::cylinder_along(Vec3::X, 1.0).unwrap());
    let placed = Shape::Instance(Box::new(
        Instance::new(
            Shape::Quadric(Quadric::cylinder(1.0).unwrap()),
            Transform::rotation_y(FRAC_PI_2),
        )
        .unwrap(),
    ));
    let r = ray([0.0, 0.5, -5.0], [1.0, 0.1, 1.0]);
    for c in [&along, &placed] {
        crossings(c, &r, &[6.80798, 7.08872]);
        let hit = c.hit(&r, Interval::AHEAD).unwrap();
        assert_close(hit.t, 6.80798, RTC_EPSILON);
        // On the surface: y^2 + z^2 = 1, and the normal is (0, y, z).
        let p = hit.point;
        assert_close(p.y * p.y + p.z * p.z, 1.0, 1e-5);
        assert_close(c.normal_at(p), v(0.0, p.y, p.z), 1e-5);
    }

    let wide = Shape::Quadric(Quadric::cylinder_along(v(-3.0, 0.0, 0.0), 2.0).unwrap());
    crossings(&wide, &ray([-5.0, 0.0, 3.0], [0.0, 0.0, -1.0]), &[1.0, 5.0]);
}

/// Along a coordinate axis, the general constructors give lesson 07's matrices.
#[test]
fn along_z_is_the_lesson_07_quadric() {
    assert_eq!(
        Quadric::cylinder_along(Vec3::Z, 1.5).unwrap().matrix(),
        Quadric::cylinder(1.5).unwrap().matrix()
    );
    assert_eq!(
        Quadric::cone_along(Vec3::Z, 0.7).unwrap().matrix(),
        Quadric::cone(0.7).unwrap().matrix()
    );
    let err = |r: render_lessons::Result<Quadric>| r.unwrap_err().param().to_string();
    assert_eq!(err(Quadric::cylinder_along(Vec3::ZERO, 1.0)), "axis");
    assert_eq!(err(Quadric::cylinder_along(Vec3::Y, 0.0)), "radius");
    assert_eq!(err(Quadric::cone_along(v(f32::NAN, 0.0, 0.0), 1.0)), "axis");
    assert_eq!(err(Quadric::cone_along(Vec3::Y, -1.0)), "slope");
}

fn rtc_cone() -> Shape {
    Shape::Quadric(Quadric::cone_along(Vec3::Y, 1.0).unwrap())
}

/// RTC: "Intersecting a cone with a ray" (x^2 + z^2 = y^2). The first two rays meet
/// the cone in a double root: by hand, along (0, 0, 1) from (0, 0, -5) the value
/// x^2 + z^2 - y^2 is (t - 5)^2, through the apex at t = 5 (coefficients exactly 1,
/// -10, 25: the discriminant is exactly 0); along (1, 1, 1)/sqrt3 it is
/// (t/sqrt3 - 5)^2, a ray tangent to the cone at (5, 5, 0), t = 5 sqrt3 = 8.66025.
///
/// A tangent ray is the grazing case: in f32 the direction's components are rounded,
/// and the discriminant b^2 - 4ac of the rounded coefficients comes out a few ulps of
/// b^2 below 0, so the crossing is reported as a miss (RTC, in f64, finds 8.66025
/// twice). The test pins what a port must expect: the discriminant is 0 to within
/// rounding, the tangent point lies on the ray at 5 sqrt3, and any crossing reported
/// is there.
#[test]
fn rtc_cone_crossings() {
    let c = rtc_cone();
    let Shape::Quadric(q) = &c else {
        unreachable!()
    };
    crossings(&c, &ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]), &[5.0, 5.0]);

    let r = ray([0.0, 0.0, -5.0], [1.0, 1.0, 1.0]);
    let (a, b, cc) = q.coefficients(&r);
    let disc = b as f64 * b as f64 - 4.0 * a as f64 * cc as f64;
    assert!(
        disc.abs() < 1e-6 * (b as f64).powi(2),
        "discriminant {disc}"
    );
    assert_close(r.at(5.0 * 3f32.sqrt()), v(5.0, 5.0, 0.0), 1e-5);
    for &t in c.crossings(&r).iter() {
        assert_close(t, 8.66025, 1e-3);
    }

    crossings(
        &c,
        &ray([1.0, 1.0, -5.0], [-0.5, -1.0, 1.0]),
        &[4.55006, 49.44994],
    );
}

/// RTC: "Intersecting a cone with a ray parallel to one of its halves": from
/// (0, 0, -1) along (0, 1, 1)/sqrt2, one crossing. RTC prints t = 0.35355, which its
/// code gets from t = -c/(2b); the root of the linear equation b t + c = 0 is -c/b.
/// By hand: x^2 + z^2 - y^2 = (t/sqrt2 - 1)^2 - t^2/2 = 1 - sqrt2 t, so
/// t = 1/sqrt2 = 0.70711, at (0, 0.5, -0.5), which lies on the cone; RTC's point
/// (0, 0.25, -0.75) does not.
#[test]
fn rtc_cone_parallel_to_a_generator_one_crossing_corrected() {
    let c = rtc_cone();
    let r = ray([0.0, 0.0, -1.0], [0.0, 1.0, 1.0]);
    crossings(&c, &r, &[0.70711]);
    let p = r.at(c.crossings(&r)[0]);
    assert_close(p, v(0.0, 0.5, -0.5), 1e-6);
    let Shape::Quadric(q) = &c else {
        unreachable!()
    };
    assert_close(q.value(p), 0.0, 1e-6);
    assert_close(q.value(r.at(0.35355)).abs(), 0.5, 1e-4);
}

/// RTC: "Computing the normal vector on a cone": zero at the apex. RTC's other two
/// points are not on the cone ((1, 1, 1): x^2 + z^2 = 2, y^2 = 1), and its formula
/// (x, -sign(y) sqrt(x^2 + z^2), z) is the gradient only on the surface; on the
/// surface, at (1, sqrt2, 1) and (-1, -1, 0), it gives RTC's (1, -sqrt2, 1) and
/// (-1, 1, 0), normalised here.
#[test]
fn rtc_cone_normals() {
    let c = rtc_cone();
    assert_eq!(c.normal_at(Vec3::ZERO), Vec3::ZERO);
    assert_close(
        c.normal_at(v(1.0, 2f32.sqrt(), 1.0)),
        v(1.0, -(2f32.sqrt()), 1.0) / 2.0,
        1e-6,
    );
    assert_close(
        c.normal_at(v(-1.0, -1.0, 0.0)),
        v(-1.0, 1.0, 0.0).normalize(),
        1e-6,
    );
}

// ---------------------------------------------------------------------------------
// Every shape: the crossings, the nearest hit and the normal agree.

fn every_shape() -> Vec<(&'static str, Shape)> {
    let sphere = Sphere::new(v(0.2, -0.1, -4.0), 1.3).unwrap();
    vec![
        ("sphere", Shape::Sphere(sphere)),
        (
            "plane",
            Shape::Plane(Plane::new(v(0.0, 0.0, -3.0), v(0.1, 0.2, 1.0)).unwrap()),
        ),
        (
            "box",
            Shape::Aabb(Aabb::new(v(-1.0, -0.8, -5.0), v(1.2, 0.9, -3.0)).unwrap()),
        ),
        (
            "triangle",
            Shape::Triangle(
                Triangle::new(
                    v(-2.0, -2.0, -4.0),
                    v(2.0, -2.0, -4.5),
                    v(0.0, 2.0, -4.0),
                )
                .unwrap(),
            ),
        ),
        (
            "quad",
            Shape::Quad(
                Quad::new(v(-2.0, -2.0, -4.0), v(4.0, 0.0, -0.5), v(0.0, 4.0, 0.2))
                    .unwrap(),
            ),
        ),
        (
            "cylinder",
            Shape::Quadric(Quadric::cylinder_along(v(1.0, 2.0, 0.0), 1.0).unwrap()),
        ),
        (
            "cone",
            Shape::Quadric(Quadric::cone_along(v(0.0, 1.0, 0.3), 0.5).unwrap()),
        ),
        (
            "instance",
            Shape::Instance(Box::new(
                Instance::new(
                    Shape::from(unit_sphere()),
                    Transform::translation(0.0, 0.0, -4.0)
                        * Transform::rotation_z(0.4)
                        * Transform::scale(1.5, 0.7, 1.0),
                )
                .unwrap(),
            )),
        ),
    ]
}

#[test]
fn every_shape_crossings_agree_with_hit_and_normal_at() {
    let eye = v(0.1, 0.2, 1.0);
    for (name, shape) in every_shape() {
        let mut hits = 0;
        for (i, j) in (0..9).flat_map(|i| (0..9).map(move |j| (i, j))) {
            let target = v(-0.8 + 0.2 * i as f32, -0.8 + 0.2 * j as f32, -4.0);
            let r = Ray::new(eye, target - eye).unwrap();
            let xs = shape.crossings(&r);
            assert!(xs.windows(2).all(|w| w[0] <= w[1]), "{name}: {:?}", &xs[..]);
            let first_ahead = xs.iter().copied().find(|&t| t > 0.0);
            let hit = shape.hit(&r, Interval::AHEAD);
            assert_eq!(first_ahead.is_some(), hit.is_some(), "{name} {i} {j}");
            let Some(hit) = hit else { continue };
            hits += 1;
            assert_close(hit.t, first_ahead.unwrap(), 1e-5 * hit.t.max(1.0));
            assert_close(shape.normal_at(hit.point), hit.normal, 1e-4);
            assert_close(shape.normal_at(hit.point).length(), 1.0, 1e-5);
        }
        assert!(hits > 0, "{name}: no ray hit; the test would prove nothing");
    }
}
