//! Lesson 04: one vector, two orthonormal bases (Lecture 4, "Coordinate System
//! Change").
//!
//! The vector s has coordinates b in the basis (u, v, w) and coordinates a in the
//! standard basis; a = B b with B = [u v w], and back with b = B^T a.
//!
//!     cargo run --example 04_basis_change
//!     cargo run --example 04_basis_change -- --angle 60 --b 1,2,0

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::basis::Basis;
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::parsers;
use render_lessons::course::report::{Table, num, vec3};

fn main() -> ExitCode {
    let Args { angle, b, output } = lesson::parse::<Args>();
    lesson::run(|| {
        lesson::print(&numbers(angle, b)?);
        output.diagram("04_two_bases.png", &bases_figure(angle, b)?)?;
        Ok(())
    })
}

// ANCHOR: basis
/// The basis (u, v, w): the standard basis turned by the angle about z.
pub fn turned_basis(angle_degrees: f32) -> Result<Basis> {
    let (s, c) = angle_degrees.to_radians().sin_cos();
    Basis::new(Vec3::new(c, s, 0.0), Vec3::new(-s, c, 0.0), Vec3::Z)
}
// ANCHOR_END: basis

/// The lesson's tables: the basis turned by `degrees`, and the vector whose
/// coordinates in it are `b`.
pub fn numbers(degrees: f32, b: Vec3) -> Result<String> {
    let basis = turned_basis(degrees)?;
    let mut vectors = Table::new(
        &format!(
            "The basis (u, v, w), turned {} degrees about z",
            num(degrees as f64, 1)
        ),
        &["vector", "world coordinates"],
    );
    for (name, v) in [("u", basis.u()), ("v", basis.v()), ("w", basis.w())] {
        vectors.row(vec![name.into(), vec3(v, 4)]);
    }
    // ANCHOR: round_trip
    let a = basis.to_world(b); // a = B b
    let back = basis.to_local(a); // b = B^T a
    // ANCHOR_END: round_trip
    let mut change = Table::new(
        "One vector s, two sets of coordinates",
        &["quantity", "value"],
    );
    change.row(vec!["b (in u, v, w)".into(), vec3(b, 4)]);
    change.row(vec!["a = B b (in x, y, z)".into(), vec3(a, 4)]);
    change.row(vec!["B^T a".into(), vec3(back, 4)]);
    change.row(vec![
        "|B^T a - b|".into(),
        format!("{:.1e}", (back - b).length()),
    ]);
    change.row(vec![
        "|a| and |b|".into(),
        format!(
            "{} and {}",
            num(a.length() as f64, 4),
            num(b.length() as f64, 4)
        ),
    ]);
    change.row(vec![
        "max |B^T B - I|".into(),
        format!("{:.1e}", basis.orthonormality_error()),
    ]);
    change.row(vec![
        "right-handed (u x v = w)".into(),
        basis.is_right_handed().to_string(),
    ]);
    Ok(format!("{vectors}\n{change}"))
}

/// The figure: both frames in the xy plane and the one vector s, with its
/// coordinates read off along each frame.
pub fn bases_figure(degrees: f32, b: Vec3) -> Result<Diagram> {
    let basis = turned_basis(degrees)?;
    let xy = |p: Vec3| Vec2::new(p.x, p.y);
    let a = basis.to_world(b);
    let extent = a.length().max(1.0) + 1.0;
    let mut d = Diagram::new(760, 640, (-extent, extent), (-extent, extent))?;
    d.title("s = a1 e1 + a2 e2 = b1 u + b2 v: the same arrow in two bases");
    d.axes((-extent, extent), (-extent, extent), 1.0, ("x", "y"));
    // Coordinates along each frame, as dashed guides.
    let along_u = basis.u() * b.x;
    d.dashed(Vec2::ZERO, xy(along_u), palette::CAMERA, 1.5);
    d.dashed(xy(along_u), xy(a), palette::CAMERA, 1.5);
    d.dashed(Vec2::new(a.x, 0.0), xy(a), palette::GRID, 1.5);
    d.dashed(Vec2::new(0.0, a.y), xy(a), palette::GRID, 1.5);
    for (v, name, color) in [
        (Vec3::X, "e1", palette::INK),
        (Vec3::Y, "e2", palette::INK),
        (basis.u(), "u", palette::X_AXIS),
        (basis.v(), "v", palette::Y_AXIS),
    ] {
        d.arrow(Vec2::ZERO, xy(v), color, 3.0);
        d.text(xy(v), name, color, Place::Right);
    }
    d.arrow(Vec2::ZERO, xy(a), palette::RAY, 3.0);
    d.dot(xy(a), 4.0, palette::RAY);
    let label = format!(
        "s: a = ({}, {}), b = ({}, {})",
        num(a.x as f64, 2),
        num(a.y as f64, 2),
        num(b.x as f64, 2),
        num(b.y as f64, 2)
    );
    d.text(xy(a), &label, palette::RAY, Place::Right);
    Ok(d)
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 04: a vector in two orthonormal bases")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// The angle in degrees by which (u, v) is turned from (x, y) about z (within
    /// ±36000).
    #[arg(long, default_value = "30", value_parser = parsers::degrees)]
    pub angle: f32,
    /// The vector's coordinates b in the basis (u, v, w), as b1,b2,b3.
    #[arg(long, default_value = "2,1,0", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub b: Vec3,
    #[command(flatten)]
    pub output: Output,
}
