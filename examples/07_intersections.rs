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
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::ray::Ray;
use render_lessons::shapes::quadric::Roots;
use render_lessons::shapes::{Aabb, Plane, Quadric, Shape, Sphere, Triangle};

/// The lesson's parameters.
#[derive(Parser, Debug)]
#[command(about = "Lesson 07: ray/primitive intersections")]
pub struct Args {
    #[command(flatten)]
    pub output: Output,
}

/// One ray against one shape, and how to draw their cross-section.
pub struct Case {
    /// The figure's file name and the table's row label.
    pub name: &'static str,
    /// The primitive.
    pub shape: Shape,
    /// The ray.
    pub ray: Ray,
    /// The plane of the cross-section: world point to diagram point.
    pub view: fn(Vec3) -> Vec2,
    /// The axis names of that plane.
    pub axes: (&'static str, &'static str),
    /// The surface's outline in that plane (for the figure only).
    pub outline: Vec<Vec2>,
}

fn circle(centre: Vec2, r: f32) -> Vec<Vec2> {
    (0..=96)
        .map(|i| centre + r * Vec2::from_angle(i as f32 / 96.0 * std::f32::consts::TAU))
        .collect()
}

// ANCHOR: cases
/// The lesson's five cases: each ray lies in the plane of its figure.
pub fn cases() -> Result<Vec<Case>> {
    let xy = |p: Vec3| Vec2::new(p.x, p.y);
    let xz = |p: Vec3| Vec2::new(p.x, p.z);
    Ok(vec![
        Case {
            name: "sphere",
            shape: Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)?),
            ray: Ray::new(Vec3::new(-3.0, 0.5, 0.0), Vec3::X)?,
            view: xy,
            axes: ("x", "y"),
            outline: circle(Vec2::ZERO, 1.0),
        },
        Case {
            name: "plane",
            shape: Shape::Plane(Plane::new(
                Vec3::new(0.0, -0.5, 0.0),
                Vec3::new(1.0, 2.0, 0.0),
            )?),
            ray: Ray::new(Vec3::new(-2.0, 2.0, 0.0), Vec3::new(1.0, -1.0, 0.0))?,
            view: xy,
            axes: ("x", "y"),
            outline: vec![Vec2::new(-2.5, 0.75), Vec2::new(2.5, -1.75)],
        },
        Case {
            name: "box",
            shape: Shape::Aabb(Aabb::new(Vec3::splat(-1.0), Vec3::splat(1.0))?),
            ray: Ray::new(Vec3::new(-3.0, -0.5, 0.0), Vec3::new(2.0, 1.0, 0.0))?,
            view: xy,
            axes: ("x", "y"),
            outline: [
                (-1.0, -1.0),
                (1.0, -1.0),
                (1.0, 1.0),
                (-1.0, 1.0),
                (-1.0, -1.0),
            ]
            .map(Vec2::from)
            .to_vec(),
        },
        Case {
            name: "triangle",
            shape: Shape::Triangle(Triangle::new(
                Vec3::new(1.0, -1.0, -1.0),
                Vec3::new(1.0, 1.5, 0.0),
                Vec3::new(1.0, -1.0, 1.0),
            )?),
            ray: Ray::new(Vec3::new(-2.0, 0.2, 0.0), Vec3::new(1.0, 0.1, 0.0))?,
            view: xy,
            axes: ("x", "y"),
            outline: vec![Vec2::new(1.0, -1.0), Vec2::new(1.0, 1.5)],
        },
        Case {
            name: "paraboloid",
            shape: Shape::Quadric(Quadric::paraboloid()?),
            ray: Ray::new(Vec3::new(-2.0, 0.0, 3.0), Vec3::new(1.0, 0.0, -1.0))?,
            view: xz,
            axes: ("x", "z"),
            outline: (0..=80)
                .map(|i| {
                    let x = -1.8 + 3.6 * i as f32 / 80.0;
                    Vec2::new(x, x * x)
                })
                .collect(),
        },
    ])
}
// ANCHOR_END: cases

// ANCHOR: crossings
/// Every crossing of the ray's whole line with the surface, ascending (t < 0 included):
/// the roots for the sphere and the quadric, the entry and exit for the box, the one
/// crossing for the plane and the triangle.
pub fn crossings(shape: &Shape, ray: &Ray) -> Vec<f32> {
    let all = (f32::NEG_INFINITY, f32::INFINITY);
    match shape {
        Shape::Sphere(s) => s.roots_stable(ray).map_or(vec![], |(t0, t1)| vec![t0, t1]),
        Shape::Plane(p) => p.t(ray).into_iter().collect(),
        Shape::Aabb(b) => b
            .slab(ray, all.0, all.1)
            .map_or(vec![], |(t0, t1)| vec![t0, t1]),
        Shape::Triangle(t) => t
            .watertight(ray, all.0, all.1)
            .map(|h| h.0)
            .into_iter()
            .collect(),
        Shape::Quadric(q) => match q.roots_stable(ray) {
            Roots::None => vec![],
            Roots::One(t) => vec![t],
            Roots::Two(t0, t1) => vec![t0, t1],
        },
        _ => vec![],
    }
}
// ANCHOR_END: crossings

/// The lesson's table.
pub fn numbers() -> Result<String> {
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
    for case in cases()? {
        let ts: Vec<String> = crossings(&case.shape, &case.ray)
            .iter()
            .map(|t| num(*t as f64, 4))
            .collect();
        let mut row = vec![
            case.name.to_string(),
            vec3(case.ray.origin(), 2),
            vec3(case.ray.direction(), 4),
            ts.join(", "),
        ];
        match case.shape.hit(&case.ray, 0.0, f32::INFINITY) {
            Some(hit) => row.extend([
                vec3(hit.point, 4),
                vec3(hit.normal, 4),
                if hit.front_face { "front" } else { "back" }.to_string(),
            ]),
            None => row.extend(["miss".to_string(), "-".to_string(), "-".to_string()]),
        }
        table.row(row);
    }
    Ok(table.to_string())
}

/// The cross-section figure of one case.
pub fn figure(case: &Case) -> Result<Diagram> {
    let view = case.view;
    let mut d = Diagram::new(600, 460, (-3.2, 3.2), (-2.0, 3.3))?;
    d.title(&format!(
        "Ray and {}: crossings, and the normal at the nearest hit",
        case.name
    ));
    d.axes((-3.2, 3.2), (-2.0, 3.2), 1.0, case.axes);
    for pair in case.outline.windows(2) {
        d.line(pair[0], pair[1], palette::PLANE, 3.0);
    }
    let ts = crossings(&case.shape, &case.ray);
    let far = ts.iter().copied().fold(1.0f32, f32::max) + 1.5;
    d.arrow(
        view(case.ray.origin()),
        view(case.ray.at(far)),
        palette::RAY,
        2.0,
    );
    d.dot(view(case.ray.origin()), 4.0, palette::RAY);
    d.text(view(case.ray.origin()), "o", palette::RAY, Place::Left);
    for (i, t) in ts.iter().enumerate() {
        let p = view(case.ray.at(*t));
        d.dot(p, 5.0, palette::HIT);
        let place = if i == 0 { Place::Below } else { Place::Right };
        d.text(
            p,
            &format!("t = {}", num(*t as f64, 3)),
            palette::HIT,
            place,
        );
    }
    if let Some(hit) = case.shape.hit(&case.ray, 0.0, f32::INFINITY) {
        let p = view(hit.point);
        d.arrow(p, p + view(hit.normal) * 0.8, palette::NORMAL, 2.5);
        d.text(
            p + view(hit.normal) * 0.8,
            "n",
            palette::NORMAL,
            Place::Right,
        );
    }
    Ok(d)
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        lesson::print(&numbers()?);
        for case in cases()? {
            args.output
                .diagram(&format!("07_{}.png", case.name), &figure(&case)?)?;
        }
        Ok(())
    })
}
