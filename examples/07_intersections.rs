//! Lesson 07: ray/primitive intersections (Lecture 4: sphere, triangle, infinite
//! plane, box, quadrics).
//!
//! One ray against each primitive: every crossing's t, the nearest hit's point and
//! outward normal, and whether the ray met the front face. Each shape's figure is a
//! cross-section through the ray, drawn from the same intersection code.
//!
//!     cargo run --example 07_intersections

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::report::{Table, num, nums, vec3};
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{Aabb, Plane, Quadric, Shape, Sphere, Triangle};

/// The lesson's parameters.
#[derive(Parser, Debug)]
#[command(about = "Lesson 07: ray/primitive intersections")]
pub struct Args {
    #[command(flatten)]
    pub output: Output,
}

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
    let triangle = Triangle::new(v(1.0, -1.0, -1.0), v(1.0, 1.5, 0.0), v(1.0, -1.0, 1.0))?;
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

/// The lesson's table: each case's crossings, then its nearest hit with t > 0.
pub fn numbers(cases: &[Case]) -> String {
    let mut table = Table::new(
        "One ray per primitive: every crossing, then the nearest hit with t > 0",
        &[
            "shape",
            "ray origin",
            "ray direction",
            "crossings t",
            "hit point",
            "outward normal",
            "face",
        ],
    );
    for Case { name, shape, ray } in cases {
        let mut row = vec![name.to_string(), vec3(ray.origin(), 2)];
        row.extend([vec3(ray.direction(), 4), nums(&shape.crossings(ray), 4)]);
        row.extend(match shape.hit(ray, Interval::AHEAD) {
            Some(h) => [vec3(h.point, 4), vec3(h.normal, 4), face(h.front_face)],
            None => ["miss", "-", "-"].map(String::from),
        });
        table.row(row);
    }
    table.to_string()
}

/// The side of the surface a ray arrives from.
fn face(front: bool) -> String {
    if front { "front" } else { "back" }.into()
}

/// The cross-section figure of one case: the surface, the ray, every crossing, and the
/// normal at the nearest hit.
pub fn figure(case: &Case) -> Result<Diagram> {
    let (shape, ray) = (&case.shape, &case.ray);
    // The figure's plane: spanned by x and y, or by x and z for a ray in y = 0.
    let in_xy = ray.origin().z == 0.0 && ray.direction().z == 0.0;
    let up = if in_xy { Vec3::Y } else { Vec3::Z };
    let view = |p: Vec3| Vec2::new(p.x, p.dot(up));
    let (lo, hi) = (Vec2::new(-3.2, -2.0), Vec2::new(3.2, 3.2));
    let mut d = Diagram::new(600, 460, (lo.x, hi.x), (lo.y, 3.3))?;
    d.title(&format!(
        "Ray and {}: crossings, and the normal at the nearest hit",
        case.name
    ));
    let names = ("x", if in_xy { "y" } else { "z" });
    d.axes((lo.x, hi.x), (lo.y, hi.y), 1.0, names);
    // The surface's trace in the plane, found by the same `Shape::crossings`: a dot wherever a
    // grid of rays along x and along the plane's second axis crosses it.
    for i in -400..=400 {
        let s = i as f32 / 100.0;
        for (o, dir) in [(up * s, Vec3::X), (Vec3::X * s, up)] {
            let probe = Ray::new(o, dir)?;
            for &t in shape.crossings(&probe).iter() {
                let q = view(probe.at(t));
                if q.clamp(lo, hi) == q {
                    d.dot(q, 1.5, palette::PLANE);
                }
            }
        }
    }
    let ts = shape.crossings(ray);
    let far = ts.iter().copied().fold(1.0f32, f32::max) + 1.5;
    d.arrow(view(ray.origin()), view(ray.at(far)), palette::RAY, 2.0);
    d.dot(view(ray.origin()), 4.0, palette::RAY);
    d.text(view(ray.origin()), "o", palette::RAY, Place::Left);
    for t in ts.iter() {
        d.dot(view(ray.at(*t)), 5.0, palette::HIT);
    }
    let normal = shape.hit(ray, Interval::AHEAD).map(|hit| {
        let (p, tip) = (view(hit.point), view(hit.point) + view(hit.normal) * 0.8);
        d.arrow(p, tip, palette::NORMAL, 2.5);
        tip
    });
    // The labels once everything is drawn, each where it covers nothing.
    for (i, t) in ts.iter().enumerate() {
        let place = if i == 0 { Place::Below } else { Place::Right };
        let label = format!("t = {}", num(*t as f64, 3));
        d.text_clear(
            view(ray.at(*t)),
            &label,
            palette::HIT,
            &place.nearest_first(),
        );
    }
    if let Some(tip) = normal {
        d.text_clear(tip, "n", palette::NORMAL, &Place::Right.nearest_first());
    }
    Ok(d)
}

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let cases = cases()?;
        lesson::print(&numbers(&cases));
        for case in &cases {
            let file = format!("07_{}.png", case.name);
            args.output.diagram(&file, &figure(case)?)?;
        }
        Ok(())
    })
}
