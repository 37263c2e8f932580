//! Lesson 02: the ray model r(t) = o + t d (Lecture 4).
//!
//! Points along one ray at several t: with a unit direction, |t| is the distance
//! from the origin, and a negative t lies behind it.
//!
//!     cargo run --example 02_ray_model
//!     cargo run --example 02_ray_model -- --origin 0,0,0 --direction 1,1,0

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::parsers;
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::ray::Ray;

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let ray = Ray::new(args.origin, args.direction)?;
        lesson::print(&numbers(&ray));
        args.output.diagram("02_ray.png", &ray_figure(&ray)?)?;
        Ok(())
    })
}

/// The values of t the lesson samples.
pub const TS: [f32; 6] = [-2.0, -1.0, 0.0, 1.0, 2.5, 4.0];

/// The lesson's table: the points of `ray` at the sampled t.
pub fn numbers(ray: &Ray) -> String {
    // ANCHOR: points
    let mut table = Table::new(
        &format!(
            "r(t) = o + t d with o = {}, d = {} (unit)",
            vec3(ray.origin(), 3),
            vec3(ray.direction(), 3)
        ),
        &["t", "r(t)", "|r(t) - o|", "where"],
    );
    for t in TS {
        let p = ray.at(t);
        let side = if t < 0.0 {
            "behind"
        } else if t == 0.0 {
            "origin"
        } else {
            "in front"
        };
        table.row(vec![
            num(t as f64, 2),
            vec3(p, 3),
            num((p - ray.origin()).length() as f64, 3),
            side.into(),
        ]);
    }
    // ANCHOR_END: points
    table.to_string()
}

/// The figure: the ray in the XY plane with its t ticks; the part behind the origin
/// dashed.
pub fn ray_figure(ray: &Ray) -> Result<Diagram> {
    let xy = |p: Vec3| Vec2::new(p.x, p.y);
    let (first, last) = (ray.at(TS[0] - 0.5), ray.at(TS[TS.len() - 1] + 0.8));
    let lo = xy(first).min(xy(last)).min(Vec2::ZERO) - 1.0;
    let hi = xy(first).max(xy(last)).max(Vec2::ZERO) + 1.0;
    let mut d = Diagram::new(800, 600, (lo.x, hi.x), (lo.y, hi.y))?;
    d.title("r(t) = o + t d: t is the distance along d; t < 0 lies behind the origin");
    d.axes((lo.x, hi.x), (lo.y, hi.y), 1.0, ("x", "y"));
    d.dashed(xy(first), xy(ray.origin()), palette::RAY, 2.0);
    d.arrow(xy(ray.origin()), xy(last), palette::RAY, 2.5);
    let dir = xy(ray.direction()).normalize_or_zero();
    let below = Vec2::new(dir.y, -dir.x) * 0.2;
    for t in TS {
        let p = xy(ray.at(t));
        let color = if t < 0.0 { palette::INK } else { palette::RAY };
        d.dot(p, 4.0, color);
        let label = if t == 0.0 {
            "o (t = 0)".to_string()
        } else {
            format!("t = {}", num(t as f64, 1))
        };
        d.text(p + below, &label, color, Place::Right);
    }
    let above = -below * 1.5;
    let o = xy(ray.origin()) + above;
    d.arrow(o, o + xy(ray.direction()), palette::NORMAL, 3.0);
    d.text(
        o + xy(ray.direction()) * 0.5 + above * 0.5,
        "d (length 1)",
        palette::NORMAL,
        Place::Left,
    );
    Ok(d)
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 02: the ray r(t) = o + t d")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Ray origin o, as x,y,z.
    #[arg(long, default_value = "1,1,0", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub origin: Vec3,
    /// Ray direction d, as x,y,z (normalised by the ray).
    #[arg(long, default_value = "4,3,0", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub direction: Vec3,
    #[command(flatten)]
    pub output: Output,
}
