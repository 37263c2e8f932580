//! The check of chapter 08's coding exercise: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch08.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::ray::{Interval, Ray};
use crate::scene::{Object, Scene, SceneHit};
use crate::shapes::{Plane, Shape, Sphere};

/// Coding exercise 8.1.
pub const CLOSEST: Exercise = Exercise {
    number: "8.1",
    chapter: "08",
    chapter_title: "Ray casting",
    function: "closest",
    file: "src/course/exercises/ch08.rs",
};

type ClosestArgs = (Ray, Vec<Shape>, Interval);

// ANCHOR: solution
/// A worked solution of exercise 8.1, written as lesson 08 teaches it: ask every
/// shape for its nearest crossing in `range`, and let each hit shrink `range.max`,
/// so that a later shape counts only if it is nearer.
pub fn closest_solution(ray: &Ray, shapes: &[Shape], range: Interval) -> Option<SceneHit> {
    let mut closest = None;
    let mut range = range;
    for (i, shape) in shapes.iter().enumerate() {
        if let Some(hit) = shape.hit(ray, range) {
            range.max = hit.t;
            closest = Some(SceneHit { hit, object: i });
        }
    }
    closest
}
// ANCHOR_END: solution

impl Answer for SceneHit {
    /// The same object, hit at the same `t`.
    fn close(&self, other: &SceneHit) -> bool {
        self.object == other.object && self.hit.t.close(&other.hit.t)
    }
    fn show(&self) -> String {
        format!("object {} at t = {}", self.object, self.hit.t.show())
    }
}

/// Every hit in list order, as the closest-hit loop would record it without
/// shrinking the range.
fn each_hit<'a>(
    ray: &'a Ray,
    shapes: &'a [Shape],
    range: Interval,
) -> impl DoubleEndedIterator<Item = SceneHit> + 'a {
    shapes
        .iter()
        .enumerate()
        .filter_map(move |(object, s)| s.hit(ray, range).map(|hit| SceneHit { hit, object }))
}

/// Checks `closest(ray, shapes, range)`: the closest hit within `range` over all
/// `shapes`, with the index of the shape hit, or `None`.
pub fn check_closest(f: impl Fn(&Ray, &[Shape], Interval) -> Option<SceneHit>) -> Outcome {
    let sphere =
        |z: f32, r: f32| Shape::Sphere(Sphere::new(v(0.0, 0.0, z), r).expect("valid sphere"));
    let floor = Shape::Plane(Plane::new(v(0.0, -1.0, 0.0), Vec3::Y).expect("valid plane"));
    let down = Ray::new(v(0.0, 0.0, 5.0), -Vec3::Z).expect("valid ray");
    let up = Ray::new(v(0.0, 0.0, 5.0), Vec3::Z).expect("valid ray");
    let slanted = Ray::new(v(0.0, 0.0, 5.0), v(0.0, -1.0, -2.0)).expect("valid ray");
    let on_surface = Ray::new(v(0.0, 0.0, 1.0), -Vec3::Z).expect("valid ray");
    let inf = f32::INFINITY;
    let cases: Vec<Case<ClosestArgs>> = [
        ("ray from (0, 0, 5) along -Z; spheres at z = 0 (r 1) then z = -5 (r 1)", down, vec![sphere(0.0, 1.0), sphere(-5.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along -Z; spheres at z = -5 (r 1) then z = 0 (r 1)", down, vec![sphere(-5.0, 1.0), sphere(0.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along -Z; spheres at z = -5, z = 0, z = -10", down, vec![sphere(-5.0, 1.0), sphere(0.0, 1.0), sphere(-10.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along (0, -1, -2); floor y = -1, sphere at z = 0 (r 1)", slanted, vec![floor.clone(), sphere(0.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along (0, -1, -2); sphere at z = -8 (r 1), floor y = -1", slanted, vec![sphere(-8.0, 1.0), floor.clone()], 0.0, inf),
        ("ray from (0, 0, 5) along +Z, away from both spheres", up, vec![sphere(0.0, 1.0), sphere(-5.0, 1.0)], 0.0, inf),
        ("no shapes at all", down, vec![], 0.0, inf),
        ("ray from (0, 0, 5) along -Z, t_max = 3: the sphere at z = 0 is beyond it", down, vec![sphere(0.0, 1.0)], 0.0, 3.0),
        ("ray from (0, 0, 1), on the sphere at z = 0, along -Z, t_min = 0.001; sphere at z = -5 too", on_surface, vec![sphere(-5.0, 1.0), sphere(0.0, 1.0)], 1e-3, inf),
    ]
    .into_iter()
    .map(|(case, ray, shapes, t_min, t_max)| {
        let range = Interval::new(t_min, t_max);
        let case = format!("{case}; t in ({}, {})", t_min.show(), t_max.show());
        (case, (ray, shapes, range))
    })
    .collect();
    run(
        &cases,
        |(ray, shapes, range)| {
            let objects = shapes
                .iter()
                .map(|shape| Object::diffuse(shape.clone(), Vec3::ONE))
                .collect();
            // A closest-hit query needs no light.
            let scene = Scene::new(objects, Vec3::ZERO).expect("valid scene");
            scene.closest(ray, *range)
        },
        |(ray, shapes, range)| f(&ray, &shapes, range),
        &[
            Mistake {
                looks_like: &gives(&|(ray, shapes, range): &ClosestArgs| {
                    Some(each_hit(ray, shapes, *range).next())
                }),
                hint: "that is the first hit in list order, not the closest: keep looking after a hit, \
                   and shrink range.max to its t so that only nearer hits count",
            },
            Mistake {
                looks_like: &gives(&|(ray, shapes, range): &ClosestArgs| {
                    Some(each_hit(ray, shapes, *range).next_back())
                }),
                hint: "that is the last hit in list order, not the closest: the last hit found is \
                       the closest only if you shrink range.max to each hit's t, so that only \
                       nearer hits count",
            },
        ],
        "test every shape with shape.hit(ray, range); after each hit set range.max = hit.t \
         and remember it with its index; return the last one remembered",
    )
}
