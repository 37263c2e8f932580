//! The checks of chapter 08's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch08.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::lighting::AMBIENT;
use crate::ray::{Interval, Ray};
use crate::scene::{Object, PointLight, Scene, SceneHit};
use crate::shapes::{Plane, Shape, Sphere};

/// Coding exercise 8.3.
pub const CLOSEST: Exercise = Exercise {
    number: "8.3",
    chapter: "08",
    chapter_title: "Ray casting",
    function: "closest",
    file: "src/course/exercises/ch08.rs",
};
/// Coding exercise 8.7.
pub const LAMBERT: Exercise = Exercise {
    number: "8.7",
    chapter: "08",
    chapter_title: "Ray casting",
    function: "lambert",
    file: "src/course/exercises/ch08.rs",
};

type ClosestArgs = (Ray, Vec<Shape>, Interval);

// ANCHOR: solution
/// A worked solution of exercise 8.3, written as lesson 08 teaches it: ask every
/// shape for its nearest crossing in `range`, and let each hit shrink `range.max`,
/// so that a later shape counts only if it is nearer.
pub fn closest_solution(
    ray: &Ray,
    shapes: &[Shape],
    range: Interval,
) -> Option<SceneHit> {
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
/// shrinking the range: what the two typical mistakes of exercise 8.3 pick from.
pub fn each_hit<'a>(
    ray: &'a Ray,
    shapes: &'a [Shape],
    range: Interval,
) -> impl DoubleEndedIterator<Item = SceneHit> + 'a {
    shapes.iter().enumerate().filter_map(move |(object, s)| {
        s.hit(ray, range).map(|hit| SceneHit { hit, object })
    })
}

/// Checks `closest(ray, shapes, range)`: the closest hit within `range` over all
/// `shapes`, with the index of the shape hit, or `None`.
pub fn check_closest(
    f: impl Fn(&Ray, &[Shape], Interval) -> Option<SceneHit> + Send + Sync + 'static,
) -> Outcome {
    closest_checked(Box::new(f))
}

/// [`check_closest`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn closest_checked(
    f: Box<dyn Fn(&Ray, &[Shape], Interval) -> Option<SceneHit> + Send + Sync>,
) -> Outcome {
    let sphere = |z: f32, r: f32| {
        Shape::Sphere(Sphere::new(v(0.0, 0.0, z), r).expect("valid sphere"))
    };
    let floor =
        Shape::Plane(Plane::new(v(0.0, -1.0, 0.0), Vec3::Y).expect("valid plane"));
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
        move |(ray, shapes, range)| f(&ray, &shapes, range),
        &[
            Mistake {
                looks_like: &|(_, _, range): &ClosestArgs, got: &Option<SceneHit>| {
                    got.as_ref().is_some_and(|found| {
                        !(found.hit.t > range.min && found.hit.t < range.max)
                    })
                },
                hint: "that hit lies outside range: count only range.min < t < range.max. Pass \
                       range itself to shape.hit (not Interval::AHEAD or a range of your own), \
                       and shrink its max as you go; a hit at t <= 0 is behind the ray's \
                       origin, where the camera cannot see",
            },
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

/// The arguments of `lambert`: p, n, albedo, the light, visible.
type LambertArgs = (Vec3, Vec3, Vec3, PointLight, bool);

/// Lambert's law with the parts the mistakes below change: the direct term
/// I cos / `falloff(d)`, kept for cos <= 0 unless `clamp`, added to the ambient
/// share `ambient` if the light is `visible`.
fn lambert_with(
    &(p, n, albedo, light, visible): &LambertArgs,
    falloff: fn(f32) -> f32,
    clamp: bool,
    ambient: f32,
) -> Vec3 {
    let to_light = light.position - p;
    let d = to_light.length();
    let cos = n.dot(to_light / d);
    let lit = visible && (cos > 0.0 || !clamp);
    let direct = if lit {
        light.intensity * cos / falloff(d)
    } else {
        Vec3::ZERO
    };
    albedo * (Vec3::splat(ambient) + direct)
}

/// Checks `lambert(p, n, albedo, light, visible)`: Lambert's cosine law from a point
/// light, with the ambient share [`AMBIENT`].
pub fn check_lambert(
    f: impl Fn(Vec3, Vec3, Vec3, &PointLight, bool) -> Vec3 + Send + Sync + 'static,
) -> Outcome {
    lambert_checked(Box::new(f))
}

/// [`check_lambert`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn lambert_checked(
    f: Box<dyn Fn(Vec3, Vec3, Vec3, &PointLight, bool) -> Vec3 + Send + Sync>,
) -> Outcome {
    let white = PointLight {
        position: v(0.0, 4.0, 0.0),
        intensity: Vec3::splat(60.0),
    };
    let warm = PointLight {
        position: v(3.0, 6.0, 4.0),
        intensity: v(40.0, 30.0, 20.0),
    };
    let grey = Vec3::splat(0.75);
    let red = v(0.85, 0.2, 0.15);
    let slanted = v(0.0, 0.6, 0.8);
    let cases: Vec<Case<LambertArgs>> = [
        (
            "head on, 4 below the light",
            Vec3::ZERO,
            Vec3::Y,
            grey,
            white,
            true,
        ),
        (
            "head on, in shadow",
            Vec3::ZERO,
            Vec3::Y,
            grey,
            white,
            false,
        ),
        ("at an angle", v(3.0, 0.0, 0.0), Vec3::Y, grey, white, true),
        (
            "a tilted normal",
            v(1.0, 1.0, 2.0),
            slanted,
            red,
            warm,
            true,
        ),
        (
            "facing away from the light",
            v(0.0, 2.0, 0.0),
            -Vec3::Y,
            red,
            white,
            true,
        ),
        (
            "the light exactly at the horizon (cos = 0)",
            v(2.0, 4.0, 0.0),
            Vec3::Y,
            red,
            white,
            true,
        ),
        (
            "far from the light, a coloured light",
            v(-20.0, 0.0, -30.0),
            Vec3::Y,
            red,
            warm,
            true,
        ),
    ]
    .into_iter()
    .map(|(what, p, n, albedo, light, visible)| {
        let case = format!(
            "{what}: p = {}, n = {}, albedo = {}, light at {} of intensity {}, visible = {visible}",
            p.show(),
            n.show(),
            albedo.show(),
            light.position.show(),
            light.intensity.show()
        );
        (case, (p, n, albedo, light, visible))
    })
    .collect();
    let squared: fn(f32) -> f32 = |d| d * d;
    let with = |falloff: fn(f32) -> f32, clamp: bool, ambient: f32| {
        move |a: &LambertArgs| Some(lambert_with(a, falloff, clamp, ambient))
    };
    let no_ambient = with(squared, true, 0.0);
    let no_falloff = with(|_| 1.0, true, AMBIENT);
    let over_d = with(|d| d, true, AMBIENT);
    let unclamped = with(squared, false, AMBIENT);
    run(
        &cases,
        |&(p, n, albedo, light, visible)| {
            crate::lighting::lambert(p, n, albedo, &light, || visible)
        },
        move |(p, n, albedo, light, visible)| f(p, n, albedo, &light, visible),
        &[
            Mistake {
                looks_like: &gives(&no_ambient),
                hint: "the ambient share is missing: albedo (AMBIENT + V I cos / d^2), so that \
                       a surface in shadow or facing away is dim, not black",
            },
            Mistake {
                looks_like: &|a: &LambertArgs, got: &Vec3| {
                    !a.4 && got.close(&Vec3::ZERO)
                },
                hint: "a point in shadow keeps its ambient share: albedo AMBIENT, not black",
            },
            Mistake {
                looks_like: &|a: &LambertArgs, got: &Vec3| {
                    !a.4 && got.close(&lambert_with(
                        &(a.0, a.1, a.2, a.3, true),
                        squared,
                        true,
                        AMBIENT,
                    ))
                },
                hint: "the shadow ray found the light hidden (visible = false): V = 0, no direct \
                       term, only albedo AMBIENT",
            },
            Mistake {
                looks_like: &gives(&no_falloff),
                hint: "the light of a point source spreads over a sphere: divide I cos by d^2, \
                       the squared distance to the light",
            },
            Mistake {
                looks_like: &gives(&over_d),
                hint: "the light falls off as 1/d here, not as 1/d^2: either the fall-off \
                       divides by d instead of d^2, or cos(theta) was taken as n . (x_L - p), \
                       which is d cos(theta): l must be the unit direction (x_L - p) / d",
            },
            Mistake {
                looks_like: &gives(&unclamped),
                hint: "a surface facing away from the light (cos <= 0) gets no direct light: a \
                       negative term would darken it below the ambient share",
            },
            Mistake {
                looks_like: &|a: &LambertArgs, got: &Vec3| {
                    let expected = lambert_with(a, squared, true, AMBIENT);
                    got.close(&(expected / a.2))
                },
                hint: "the light is reflected in the surface's colour: multiply the whole \
                       (AMBIENT + V I cos / d^2) by the albedo",
            },
        ],
        "l = (x_L - p) / d, cos = n . l; albedo (AMBIENT + I cos / d^2) if cos > 0 and \
         visible, albedo AMBIENT otherwise",
    )
}
