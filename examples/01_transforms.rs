//! Lesson 01: geometric transformations in homogeneous coordinates (Lecture 3).
//!
//! Scale, the three rotations and translation as 4x4 matrices, applied to a point
//! (w = 1) and to a vector (w = 0); then the same two transformations composed in
//! both orders, to see that order matters.
//!
//!     cargo run --example 01_transforms
//!     cargo run --example 01_transforms -- --angle 45 --point 1,0,0

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::mine;
use render_lessons::course::parsers;
use render_lessons::course::report::{Table, vec3};
use render_lessons::error::Problem;
use render_lessons::transform::Transform;
use render_lessons::{Error, Result};

fn main() -> ExitCode {
    let Args {
        angle,
        point,
        mine,
        output,
    } = lesson::parse::<Args>();
    lesson::run(|| {
        let compose = mine.then(mine::my_compose).transpose()?;
        lesson::print(&numbers(angle, point)?);
        output.diagram("01_transform_order.png", &order_figure(angle)?)?;
        if let Some(compose) = compose {
            let figure = my_order_figure(angle, compose)?;
            output.diagram("01_transform_order_mine.png", &figure)?;
        }
        Ok(())
    })
}

/// The lesson's loop: the point (and vector) `p` under each of the slides'
/// transformations, then under the two orders of one composition, as tables. An
/// error if `p` is so large that a transform of it overflows f32.
pub fn numbers(degrees: f32, p: Vec3) -> Result<String> {
    let mut table = Table::new(
        &format!(
            "The slides' matrices, angle {1} degrees, applied to\nthe point {0} (w = 1) and the vector {0} (w = 0)",
            vec3(p, 3),
            degrees
        ),
        &["transform", "point", "vector"],
    );
    for (name, t) in slide_transforms(degrees)? {
        let (point, vector) = (finite(t.point(p))?, t.vector(p));
        table.row(vec![name.into(), vec3(point, 3), vec3(vector, 3)]);
    }
    let mut order = Table::new(
        &format!("Order matters: the point {} under", vec3(p, 3)),
        &["composition", "point"],
    );
    for (name, t) in two_orders(degrees)? {
        order.row(vec![name.into(), vec3(finite(t.point(p))?, 3)]);
    }
    Ok(format!("{table}\n{order}"))
}

/// `p` if it is finite; otherwise the error that `--point` was too large.
fn finite(p: Vec3) -> Result<Vec3> {
    p.is_finite().then_some(p).ok_or(Error::Value {
        param: "point",
        problem: Problem::Invalid {
            reason: "is so large that a transform of it overflows f32",
        },
    })
}

/// The five transformations of the slides; the rotations turn by `degrees`.
pub fn slide_transforms(degrees: f32) -> Result<Vec<(&'static str, Transform)>> {
    let theta = degrees.to_radians();
    Ok(vec![
        ("scale(2, 0.5, 1)", Transform::scale(2.0, 0.5, 1.0)),
        ("rotation_x(angle)", Transform::rotation_x(theta)),
        ("rotation_y(angle)", Transform::rotation_y(theta)),
        ("rotation_z(angle)", Transform::rotation_z(theta)),
        (
            "translation(1, 2, 3)",
            Transform::translation(1.0, 2.0, 3.0),
        ),
    ])
}

// ANCHOR: order
/// Rotate by `degrees` about Z, and translate by (3, 0, 0): in both orders.
pub fn two_orders(degrees: f32) -> Result<[(&'static str, Transform); 2]> {
    let rotate = Transform::rotation_z(degrees.to_radians());
    let translate = Transform::translation(3.0, 0.0, 0.0);
    Ok([
        ("rotate, then translate", rotate.then(translate)),
        ("translate, then rotate", translate.then(rotate)),
    ])
}
// ANCHOR_END: order

/// A little house in the XY plane, the shape the figure transforms.
pub fn house() -> Vec<Vec3> {
    [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.5, 1.6), (0.0, 1.0)]
        .map(|(x, y)| Vec3::new(x, y, 0.0))
        .to_vec()
}

/// The figure: the house, and the house moved by both compositions.
pub fn order_figure(degrees: f32) -> Result<Diagram> {
    figure_of(degrees, two_orders(degrees)?)
}

/// The figure drawn with `compose`, the student's own once it passes its check
/// (coding exercise 1.6, `src/course/exercises/ch01.rs`): the same two orders, each
/// composed by it.
pub fn my_order_figure(degrees: f32, compose: mine::Compose) -> Result<Diagram> {
    let rotate = Transform::rotation_z(degrees.to_radians());
    let translate = Transform::translation(3.0, 0.0, 0.0);
    let yours = |first: &Transform, second: &Transform| {
        Transform::from_matrix(compose(first, second))
    };
    figure_of(
        degrees,
        [
            ("rotate, then translate", yours(&rotate, &translate)?),
            ("translate, then rotate", yours(&translate, &rotate)?),
        ],
    )
}

/// The house, and the house moved by each of `orders`.
fn figure_of(degrees: f32, orders: [(&str, Transform); 2]) -> Result<Diagram> {
    let mut d = Diagram::new(800, 560, (-2.5, 6.5), (-1.5, 4.2))?;
    d.title(&format!(
        "Rotate {degrees} degrees about Z and translate by (3, 0, 0): the order matters"
    ));
    d.axes((-2.0, 6.0), (-1.0, 3.7), 1.0, ("x", "y"));
    let xy = |p: Vec3| Vec2::new(p.x, p.y);
    let shape: Vec<Vec2> = house().into_iter().map(xy).collect();
    d.fill(&shape, palette::GRID, 200);
    d.outline(&shape, palette::INK, 1.5);
    d.text(Vec2::new(0.5, 0.4), "original", palette::INK, Place::Centre);
    for ((name, t), color) in orders.into_iter().zip([palette::RAY, palette::HIT]) {
        let moved: Vec<Vec2> = house().into_iter().map(|p| xy(t.point(p))).collect();
        d.fill(&moved, color, 60);
        d.outline(&moved, color, 2.0);
        let right = moved
            .iter()
            .copied()
            .fold(moved[0], |a, b| if b.x > a.x { b } else { a });
        d.text(right, name, color, Place::Right);
    }
    Ok(d)
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 01: 4x4 transformations in homogeneous coordinates")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Rotation angle in degrees (within ±36000).
    #[arg(long, default_value = "30", value_parser = parsers::degrees)]
    pub angle: f32,
    /// The point (and vector) to transform, as x,y,z.
    #[arg(long, default_value = "1,2,3", value_parser = parsers::vec3)]
    pub point: Vec3,
    /// Also draw the figure with your own `compose` (coding exercise 1.6):
    /// `cargo run --example 01_transforms -- --mine`.
    #[arg(long)]
    pub mine: bool,
    #[command(flatten)]
    pub output: Output,
}
