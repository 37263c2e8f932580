//! Lesson 07, the plane (chapter 07_2): known answers, parallel rays without NaN,
//! and STABILITY S3: a wall modelled as a huge sphere hits itself in f32, a plane
//! does not.

use crate::common::ray;
use glam::Vec3;
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{Plane, Shape, Sphere};

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
            let bounce =
                Ray::new(hit.point, frame.to_world(cosine_hemisphere(u))).unwrap();
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
    let off_plane =
        |points: &[Vec3]| points.iter().map(|p| (p.x - 1.0).abs()).fold(0.0, f32::max);
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
