//! The pitfalls lessons 08 and 09 warn about, as a student writes them: each a plain
//! function in an exercise's shape, which the exercise's check must fail with a hint
//! naming the mistake, so that a check that lets a warned mistake through fails CI.
//! The checks' references and their other wrong answers are in `lessons_08_09.rs`.

use glam::Vec3;
use render_lessons::course::exercises::check::*;
use render_lessons::lighting::AMBIENT;
use render_lessons::raster::ScreenVertex;
use render_lessons::ray::{Interval, Ray};
use render_lessons::scene::{PointLight, SceneHit};
use render_lessons::shapes::Shape;

use crate::common::fails_with;
use crate::lessons_08_09::{P, covers_in, edge, edges};

/// Lesson 08, "returning the first hit instead of the closest".
fn closest_first_hit(ray: &Ray, shapes: &[Shape], range: Interval) -> Option<SceneHit> {
    shapes.iter().enumerate().find_map(|(object, shape)| {
        shape.hit(ray, range).map(|hit| SceneHit { hit, object })
    })
}

/// Lesson 08, "accepting t <= 0": every crossing of the line counts, the range unused.
fn closest_anywhere_on_the_line(
    ray: &Ray,
    shapes: &[Shape],
    _: Interval,
) -> Option<SceneHit> {
    let mut range = Interval::EVERYWHERE;
    let mut closest = None;
    for (object, shape) in shapes.iter().enumerate() {
        if let Some(hit) = shape.hit(ray, range) {
            range.max = hit.t;
            closest = Some(SceneHit { hit, object });
        }
    }
    closest
}

/// Lesson 08's step 1 without the fall-off: a point light that does not spread.
fn lambert_without_falloff(
    p: Vec3,
    n: Vec3,
    albedo: Vec3,
    light: &PointLight,
    visible: bool,
) -> Vec3 {
    let l = (light.position - p).normalize();
    let cos = n.dot(l);
    let direct = if visible && cos > 0.0 {
        light.intensity * cos
    } else {
        Vec3::ZERO
    };
    albedo * (AMBIENT + direct)
}

/// Lesson 08: the cosine unclamped, so a surface facing away darkens below ambient.
fn lambert_unclamped(
    p: Vec3,
    n: Vec3,
    albedo: Vec3,
    light: &PointLight,
    visible: bool,
) -> Vec3 {
    let to_light = light.position - p;
    let cos = n.dot(to_light.normalize());
    let direct = if visible {
        light.intensity * cos / to_light.length_squared()
    } else {
        Vec3::ZERO
    };
    albedo * (AMBIENT + direct)
}

/// Lesson 09, "testing coverage in floating point": the right rule, in f32.
fn covers_in_f32(a: P, b: P, c: P, p: P) -> bool {
    covers_in(|x| x as f32, a, b, c, p)
}

/// Lesson 09: E >= 0 on every edge, no top-left rule, so shared edges are drawn twice.
fn covers_both_sides_of_an_edge(a: P, b: P, c: P, p: P) -> bool {
    edges(a, b, c).is_some_and(|es| es.into_iter().all(|(u, v)| edge(u, v, p) >= 0))
}

/// Lesson 09, "interpolating attributes with the screen weights".
fn perspective_weights_of_the_screen(b: [f32; 3], _: &[ScreenVertex; 3]) -> [f32; 3] {
    b
}

#[test]
fn every_exercise_of_lessons_08_and_09_fails_what_its_chapter_warns_about() {
    for (outcome, hint) in [
        (check_closest(closest_first_hit), "first hit in list order"),
        (check_closest(closest_anywhere_on_the_line), "outside range"),
        (
            check_lambert(lambert_without_falloff),
            "spreads over a sphere",
        ),
        (check_lambert(lambert_unclamped), "facing away"),
        (check_covers(covers_in_f32), "not in floating point"),
        (check_covers(covers_both_sides_of_an_edge), "drawn twice"),
        (
            check_perspective_weights(perspective_weights_of_the_screen),
            "screen weights",
        ),
    ] {
        fails_with(outcome, hint);
    }
}
