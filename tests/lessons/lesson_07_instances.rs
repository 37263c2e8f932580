//! Lesson 07, instances (chapter 07_6): a shape placed by a lesson-01 transform. A
//! scaled and translated sphere is the ellipsoid, the normal is transformed by the
//! inverse transpose, and t stays the world distance.

use crate::common::pages::{assert_page_says, sci};
use crate::common::{ray, unit_sphere};
use crate::lesson_07_quadrics::{gradient_fd, p64};
use glam::{DVec3, Vec3};
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{Instance, Quadric, Shape};
use render_lessons::transform::Transform;

// ---------------------------------------------------------------- instances

#[test]
fn scaled_translated_sphere_is_the_ellipsoid() {
    let shift = Vec3::new(1.0, -2.0, 3.0);
    let m = Transform::scale(2.0, 1.0, 1.0)
        .then(Transform::translation(shift.x, shift.y, shift.z));
    let inst = Shape::Instance(Box::new(
        Instance::new(Shape::from(unit_sphere()), m).unwrap(),
    ));
    let e = Quadric::ellipsoid(Vec3::new(2.0, 1.0, 1.0)).unwrap();
    let mut hits = 0;
    for i in 0..10 {
        for j in 0..10 {
            let (fi, fj) = (i as f32, j as f32);
            // Rays relative to the ellipsoid's centre; the instance's are shifted.
            let o = Vec3::new(-5.0 + 0.3 * fj, 0.5 - 0.1 * fi, -4.0);
            let d = Vec3::new(1.0 - 0.05 * fi, 0.02 * fj - 0.1, 1.0);
            let local = Ray::new(o, d).unwrap();
            let world = Ray::new(o + shift, d).unwrap();
            let (a, b) = (
                inst.hit(&world, Interval::AHEAD),
                e.hit(&local, Interval::AHEAD),
            );
            match (a, b) {
                (Some(a), Some(b)) => {
                    hits += 1;
                    // Where the ray meets the surface at a grazing angle, t is
                    // ill-conditioned (an error in the surface moves the hit along
                    // the ray by 1/cos): the tolerance divides by the cosine.
                    let cos = b.normal.dot(d.normalize()).abs().max(1e-3);
                    let tol = 1e-6 * (1.0 + world.origin().length() + b.t) / cos;
                    assert!((a.t - b.t).abs() <= tol, "{world:?}: {a:?} vs {b:?}");
                    let dp = (a.point - shift - b.point).length();
                    assert!(dp <= tol, "{world:?}: {dp:e} {a:?} vs {b:?}");
                    // The normal turns by at most the curvature (2 here) times the
                    // distance between the two points.
                    assert!((a.normal - b.normal).length() <= 1e-5 + 2.0 * dp);
                    assert_eq!(a.front_face, b.front_face);
                }
                (None, None) => {}
                _ => panic!("{world:?}: instance {a:?}, ellipsoid {b:?}"),
            }
        }
    }
    assert!(hits > 20, "{hits}");
}

#[test]
fn instance_normal_is_the_inverse_transpose_one() {
    // Unit sphere stretched to x^2/4 + y^2 + z^2 = 1. From (1, 5, 0) along -Y it is hit
    // at y = sqrt(1 - 1/4) = sqrt 3 / 2, t = 5 - sqrt 3 / 2.
    let m = Transform::scale(2.0, 1.0, 1.0);
    let inst = Instance::new(Shape::from(unit_sphere()), m).unwrap();
    let h = inst
        .hit(&ray([1.0, 5.0, 0.0], [0.0, -1.0, 0.0]), Interval::AHEAD)
        .unwrap();
    let y = 3.0_f32.sqrt() / 2.0;
    assert!((h.t - (5.0 - y)).abs() <= 1e-6, "{}", h.t);
    assert!((h.point - Vec3::new(1.0, y, 0.0)).length() <= 1e-6);
    // The true normal: the gradient (x/2, 2y, 2z) of x^2/4 + y^2 + z^2.
    let want = Vec3::new(0.5, 2.0 * y, 0.0).normalize();
    assert!((h.normal - want).length() <= 1e-6, "{:?}", h.normal);
    // It is what Transform::normal gives for the object-space normal (1/2, sqrt 3/2,
    // 0).
    let n_obj = Vec3::new(0.5, y, 0.0);
    assert!((m.normal(n_obj).unwrap().normalize() - h.normal).length() <= 1e-6);
    // A tangent of the sphere there, carried by M, is a tangent of the ellipsoid: the
    // inverse-transpose normal is perpendicular to it, the naive M n is not.
    let tangent = m.vector(Vec3::new(-y, 0.5, 0.0)).normalize();
    let naive = m.vector(n_obj).normalize();
    eprintln!(
        "non-uniform scale: n . tangent = {:e} (inverse transpose), {:e} (naive M n)",
        h.normal.dot(tangent),
        naive.dot(tangent)
    );
    assert!(h.normal.dot(tangent).abs() <= 1e-6);
    assert!(naive.dot(tangent).abs() > 0.3);
    let page = "07_6_instances.md";
    let along = f64::from(h.normal.dot(tangent));
    assert_page_says(
        page,
        &format!("\\boldsymbol{{\\tau}} = {}", &sci(along)[1..]),
    );
    assert_page_says(page, &format!("${:.3}$, far from", naive.dot(tangent)));
    // The two numbers as the page prints them (no sine or cosine: the same everywhere).
    let printed = format!("{along:.1e} {:.3}", naive.dot(tangent));
    assert_eq!(printed, "3.0e-8 -0.545");
    // Finite-difference check against the world-space implicit function.
    let f = |p: DVec3| p.x * p.x / 4.0 + p.y * p.y + p.z * p.z - 1.0;
    let g = gradient_fd(f, p64(h.point)).normalize();
    assert!((p64(h.normal) - g).length() <= 1e-6);
}

#[test]
fn instance_t_is_world_distance() {
    // Rotate, scale non-uniformly, and move: the object-space direction is far from
    // unit length, yet t must stay a world-space distance along the unit ray.
    let m = Transform::scale(3.0, 0.5, 1.5)
        .then(Transform::rotation_y(0.4))
        .then(Transform::translation(0.0, 1.0, -2.0));
    let inst = Instance::new(Shape::from(unit_sphere()), m).unwrap();
    let ellipsoid = Instance::new(
        Shape::Quadric(Quadric::ellipsoid(Vec3::new(3.0, 0.5, 1.5)).unwrap()),
        Transform::rotation_y(0.4).then(Transform::translation(0.0, 1.0, -2.0)),
    )
    .unwrap();
    let mut hits = 0;
    for i in 0..8 {
        let fi = i as f32;
        let r = ray([-10.0, 1.0 + 0.05 * fi, -2.5 + 0.2 * fi], [1.0, 0.0, 0.1]);
        let Some(h) = inst.hit(&r, Interval::AHEAD) else {
            continue;
        };
        hits += 1;
        // t is the distance from the origin to the hit point, and r(t) is that point.
        assert!(((h.point - r.origin()).length() - h.t).abs() <= 1e-5 * h.t);
        assert!((r.at(h.t) - h.point).length() <= 1e-5 * h.t);
        // The same placement of the quadric ellipsoid agrees (a rigid instance).
        let h2 = ellipsoid.hit(&r, Interval::AHEAD).unwrap();
        assert!((h.t - h2.t).abs() <= 1e-5 * h.t, "{} vs {}", h.t, h2.t);
        // The range is in world units too: just short of t, nothing; past the entry,
        // the exit.
        assert!(inst.hit(&r, Interval::new(0.0, h.t * 0.999)).is_none());
        let exit = inst
            .hit(&r, Interval::new(h.t * 1.001, f32::INFINITY))
            .unwrap();
        assert!(exit.t > h.t && !exit.front_face);
        assert!(((exit.point - r.origin()).length() - exit.t).abs() <= 1e-5 * exit.t);
    }
    assert!(hits >= 4, "{hits}");
}
