//! Lesson 11: the closest-hit loop over the shapes stored in runs of one kind
//! (`Scene::closest`, `ShapesByKind`) finds what asking every shape for `Shape::hit`
//! in turn finds, bit for bit; `Scene::closest_object` and `Scene::occluded` agree
//! with it; and lesson 08's shadowless image, made row by row (`render`,
//! `Camera::row`), is the pixel loop of the lecture (`PinholeCamera::ray`, then the
//! closest hit) bit for bit.
//!
//! The camera's row of rays (`Camera::row`) is checked against `PinholeCamera::ray`
//! in `tests/lessons/lesson_06_pinhole_camera.rs`.

use crate::common;
use common::{Rng, bits};
use glam::Vec3;
use render_lessons::ray::{Interval, Ray};
use render_lessons::raycast::shadowless;
use render_lessons::render::render;
use render_lessons::scene::{Intersect, Object, Scene, SceneHit};
use render_lessons::scenes::{still_life, still_life_pinhole};
use render_lessons::shapes::{
    Aabb, Cylinder, Instance, Plane, Quad, Quadric, Shape, Sphere, Triangle,
};
use render_lessons::transform::Transform;

/// The lecture's loop, written out: every shape asked for its hit in the list's
/// order, each hit shrinking the range, so the first of equal hits wins.
fn each_in_turn(scene: &Scene, ray: &Ray, range: Interval) -> Option<SceneHit> {
    let mut range = range;
    let mut closest = None;
    for (object, o) in scene.objects().iter().enumerate() {
        if let Some(hit) = o.shape.hit(ray, range) {
            range.max = hit.t;
            closest = Some(SceneHit { hit, object });
        }
    }
    closest
}

fn same(a: Option<SceneHit>, b: Option<SceneHit>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => a.object == b.object && bits(&a.hit) == bits(&b.hit),
        _ => false,
    }
}

/// Every kind of shape, in runs of one kind and alone, with exact copies (ties: the
/// earlier copy must win) and a box lying on a plane (ties along the plane).
fn mixed_scene(rng: &mut Rng) -> Scene {
    let mut shapes: Vec<Shape> = vec![Plane::new(Vec3::ZERO, Vec3::Y).unwrap().into()];
    for k in 0..40 {
        let c = rng.point(6.0);
        let shape: Shape = match k % 8 {
            0 | 1 => Sphere::new(c, rng.range(0.1, 1.5)).unwrap().into(),
            2 => Aabb::new(c - rng.point(1.0).abs(), c + rng.point(1.0).abs())
                .unwrap()
                .into(),
            3 => Aabb::new(
                Vec3::new(c.x, 0.0, c.z),
                Vec3::new(c.x + 1.0, 1.0, c.z + 1.0),
            )
            .unwrap()
            .into(),
            4 => loop {
                if let Ok(t) = Triangle::new(c, c + rng.point(1.5), c + rng.point(1.5))
                {
                    break t.into();
                }
            },
            5 => Quad::new(c, Vec3::X, Vec3::new(0.0, 0.5, 1.0))
                .unwrap()
                .into(),
            6 => Cylinder::new(rng.range(0.1, 1.0), -0.5, 0.5)
                .and_then(|cyl| {
                    Instance::new(cyl.into(), Transform::translation(c.x, c.y, c.z))
                })
                .unwrap()
                .into(),
            _ if k % 16 == 7 => Quadric::cylinder(0.2).unwrap().into(),
            _ => Quadric::ellipsoid(Vec3::new(0.5, 1.0, 0.7))
                .and_then(|q| {
                    Instance::new(q.into(), Transform::translation(c.x, c.y, c.z))
                })
                .unwrap()
                .into(),
        };
        // Every fifth shape twice in a row, a tie for every ray that meets it.
        if k % 5 == 0 {
            shapes.push(shape.clone());
        }
        shapes.push(shape);
    }
    let objects = shapes
        .into_iter()
        .enumerate()
        .map(|(i, s)| Object::diffuse(s, Vec3::splat(i as f32 / 100.0)))
        .collect();
    Scene::new(objects, Vec3::ZERO).unwrap()
}

/// Rays from around the scene towards it, and a few along the axes.
fn rays(rng: &mut Rng, n: usize) -> Vec<Ray> {
    let mut rays: Vec<Ray> = (0..n)
        .filter_map(|_| {
            let o = rng.point(12.0);
            Ray::new(o, rng.point(4.0) - o).ok()
        })
        .collect();
    for d in [Vec3::X, Vec3::NEG_Y, Vec3::Z] {
        rays.push(Ray::new(Vec3::new(-9.0, 0.5, 0.25), d).unwrap());
        rays.push(Ray::new(Vec3::new(0.3, 0.0, -9.0), d).unwrap());
    }
    rays
}

#[test]
fn the_closest_hit_over_runs_of_one_kind_is_every_shape_asked_in_turn_bit_for_bit() {
    let mut rng = Rng::seeded(0x5eed_cafe);
    let scenes = [still_life(Vec3::ZERO).unwrap(), mixed_scene(&mut rng)];
    let mut ties = 0;
    for scene in &scenes {
        for ray in rays(&mut rng, 4000) {
            for range in [
                Interval::AHEAD,
                Interval::EVERYWHERE,
                Interval::new(0.5, 6.0),
                Interval::new(-3.0, 2.0),
            ] {
                let readable = each_in_turn(scene, &ray, range);
                let fast = scene.closest(&ray, range);
                assert!(
                    same(readable, fast),
                    "{ray:?} {range:?}: {readable:?} {fast:?}"
                );
                assert_eq!(
                    scene.closest_object(&ray, range),
                    readable.map(|f| f.object)
                );
                assert_eq!(
                    Intersect::closest_object(scene, &ray, range),
                    readable.map(|f| f.object)
                );
                let any = scene
                    .objects()
                    .iter()
                    .any(|o| o.shape.hit(&ray, range).is_some());
                assert_eq!(scene.occluded(&ray, range), any, "{ray:?} {range:?}");
                if let Some(found) = readable {
                    let next = &scene.objects()
                        [(found.object + 1).min(scene.objects().len() - 1)];
                    ties +=
                        usize::from(next.shape == scene.objects()[found.object].shape);
                }
            }
        }
    }
    assert!(ties > 100, "only {ties} rays met a shape listed twice");
}

#[test]
fn the_still_lifes_image_made_row_by_row_is_the_lectures_pixel_loop_bit_for_bit() {
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(192, 108).unwrap();
    let pinhole = camera.pinhole().unwrap();
    let fast = render(&camera, |r| shadowless(&scene, r)).unwrap();
    for y in 0..108 {
        for x in 0..192 {
            let readable =
                match each_in_turn(&scene, &pinhole.ray(x, y), Interval::AHEAD) {
                    Some(found) => scene.object(&found).colour(),
                    None => scene.background(),
                };
            let pixel = fast.get(x, y).unwrap();
            assert_eq!(bits(&pixel), bits(&readable), "pixel ({x}, {y})");
        }
    }
}
