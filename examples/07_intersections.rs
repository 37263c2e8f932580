//! Lesson 07: ray/primitive intersections (Lecture 4: sphere, triangle, infinite
//! plane, box, quadrics).
//!
//! One ray against each primitive, first by the naive method and by the robust one
//! side by side (and two rays on which the naive one fails), then every crossing's t,
//! the nearest hit's point and outward normal, and whether the ray met the front face.
//! Each shape's figure is a cross-section through the ray, drawn from the same
//! intersection code.
//!
//!     cargo run --example 07_intersections

use std::process::ExitCode;

use clap::Parser;
use glam::Vec3;
use render_lessons::Result;
use render_lessons::course::diagram::cross_section;
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::report::{Table, nums, vec3};
use render_lessons::ray::{ClosedSpan, Interval, Ray};
use render_lessons::shapes::{Aabb, Plane, Quadric, Shape, Sphere, Triangle};

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let cases = cases()?;
        let hard = hard_cases()?;
        lesson::print(&naive_and_robust(cases.iter().chain(&hard)));
        lesson::print(&numbers(&cases));
        for Case { name, shape, ray } in &cases {
            let figure = cross_section(name, shape, ray)?;
            args.output.diagram(&format!("07_{name}.png"), &figure)?;
        }
        Ok(())
    })
}

// ANCHOR: naive_and_robust
/// The lesson's loop: each ray against its shape by the naive method and by the
/// robust one, side by side; every crossing of the whole line, or "miss".
pub fn naive_and_robust<'a>(cases: impl IntoIterator<Item = &'a Case>) -> String {
    let columns = ["shape", "", "method", "crossings t"];
    let mut table = Table::new("Naive and robust methods on the same rays", &columns);
    let ts = |ts: Vec<f32>| match ts.is_empty() {
        true => "miss".to_string(),
        false => nums(&ts, 4),
    };
    // Two rows a shape, so the table fits a page's code column.
    for Case { name, shape, ray } in cases {
        let [(naive, a), (robust, b)] = methods(shape, ray);
        table.row(vec![name.to_string(), "naive".into(), naive.into(), ts(a)]);
        table.row(vec![String::new(), "robust".into(), robust.into(), ts(b)]);
    }
    table.to_string()
}

/// The naive and the robust method of `shape`, each named, and the crossings of the
/// ray's whole line that each finds. The plane has one method only.
pub fn methods(shape: &Shape, ray: &Ray) -> [(&'static str, Vec<f32>); 2] {
    let line = Interval::EVERYWHERE;
    let one = |t: Option<f32>| Vec::from_iter(t);
    let pair = |p: Option<ClosedSpan>| p.map_or(vec![], |s| vec![s.t0, s.t1]);
    match shape {
        Shape::Sphere(s) => [
            ("textbook roots", s.roots_textbook(ray).to_vec()),
            ("Hearn-Baker, stable roots", s.roots_stable(ray).to_vec()),
        ],
        Shape::Quadric(q) => [
            ("textbook roots", q.roots_textbook(ray).to_vec()),
            ("stable roots", q.roots_stable(ray).to_vec()),
        ],
        Shape::Triangle(t) => [
            (
                "Möller-Trumbore",
                one(t.moller_trumbore(ray, line).map(|c| c.t)),
            ),
            ("watertight", one(t.watertight(ray, line).map(|c| c.t))),
        ],
        Shape::Aabb(b) => [
            ("slab test", pair(b.slab(ray, line))),
            ("slab test, widened", pair(b.slab_conservative(ray, line))),
        ],
        other => ["one method", "the same"].map(|m| (m, other.crossings(ray).to_vec())),
    }
}
// ANCHOR_END: naive_and_robust

/// One ray against one primitive; the name labels the table's row and the figure.
pub struct Case {
    pub name: &'static str,
    pub shape: Shape,
    pub ray: Ray,
}

// ANCHOR: cases
/// The lesson's five cases. Every ray lies in the plane z = 0, but the paraboloid's,
/// which lies in y = 0; each figure is a cross-section in that plane.
pub fn cases() -> Result<Vec<Case>> {
    let v = Vec3::new;
    let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)?);
    let sphere_ray = Ray::new(v(-3.0, 0.5, 0.0), Vec3::X)?;
    let plane = Shape::Plane(Plane::new(v(0.0, -0.5, 0.0), v(1.0, 2.0, 0.0))?);
    let plane_ray = Ray::new(v(-2.0, 2.0, 0.0), v(1.0, -1.0, 0.0))?;
    let cube = Shape::Aabb(Aabb::new(Vec3::splat(-1.0), Vec3::splat(1.0))?);
    let cube_ray = Ray::new(v(-3.0, -0.5, 0.0), v(2.0, 1.0, 0.0))?;
    let triangle =
        Triangle::new(v(1.0, -1.0, -1.0), v(1.0, 1.5, 0.0), v(1.0, -1.0, 1.0))?;
    let triangle_ray = Ray::new(v(-2.0, 0.2, 0.0), v(1.0, 0.1, 0.0))?;
    let paraboloid = Shape::Quadric(Quadric::paraboloid()?);
    let paraboloid_ray = Ray::new(v(-2.0, 0.0, 3.0), v(1.0, 0.0, -1.0))?;
    let case = |name, shape, ray| Case { name, shape, ray };
    Ok(vec![
        case("sphere", sphere, sphere_ray),
        case("plane", plane, plane_ray),
        case("box", cube, cube_ray),
        case("triangle", Shape::Triangle(triangle), triangle_ray),
        case("paraboloid", paraboloid, paraboloid_ray),
    ])
}
// ANCHOR_END: cases

/// Two rays on which the naive methods fail: a sphere 10^4 radii away (STABILITY S1),
/// and a ray 10^-4 radians off the paraboloid's axis (S9).
pub fn hard_cases() -> Result<Vec<Case>> {
    let far = Shape::Sphere(Sphere::new(Vec3::new(0.0, 0.0, -1e4), 1.0)?);
    let towards_far = Ray::new(Vec3::ZERO, Vec3::new(0.5e-4, 0.0, -1.0))?;
    let (sin, cos) = 1e-4f32.sin_cos();
    let paraboloid = Shape::Quadric(Quadric::paraboloid()?);
    let along_axis = Ray::new(Vec3::new(0.3, 0.2, 5.0), Vec3::new(sin, 0.0, -cos))?;
    let case = |name, shape, ray| Case { name, shape, ray };
    Ok(vec![
        case("sphere 10^4 away", far, towards_far),
        case("paraboloid, near its axis", paraboloid, along_axis),
    ])
}

/// The lesson's table: each case's crossings, then its nearest hit with t > 0.
pub fn numbers(cases: &[Case]) -> String {
    // Two tables, the ray and then its hit, so each fits a page's code column.
    let columns = ["shape", "ray origin", "ray direction", "crossings t"];
    let mut rays = Table::new("One ray per primitive: every crossing", &columns);
    let columns = ["shape", "hit point", "outward normal", "face"];
    let mut hits = Table::new("Then the nearest hit with t > 0", &columns);
    for Case { name, shape, ray } in cases {
        let (origin, direction) = (vec3(ray.origin(), 2), vec3(ray.direction(), 4));
        let crossings = nums(&shape.crossings(ray), 4);
        rays.row(vec![name.to_string(), origin, direction, crossings]);
        let mut hit = vec![name.to_string()];
        hit.extend(match shape.hit(ray, Interval::AHEAD) {
            Some(h) => [vec3(h.point, 4), vec3(h.normal, 4), face(h.front_face)],
            None => ["miss", "-", "-"].map(String::from),
        });
        hits.row(hit);
    }
    format!("{rays}\n{hits}")
}

/// The side of the surface a ray arrives from.
fn face(front: bool) -> String {
    if front { "front" } else { "back" }.into()
}

/// The lesson's parameters.
#[derive(Parser, Debug)]
#[command(about = "Lesson 07: ray/primitive intersections")]
pub struct Args {
    #[command(flatten)]
    pub output: Output,
}
