//! Lesson 05: an orthographic camera anywhere (Lecture 4, "Arbitrary Orthographic Camera").
//!
//! From the camera position p, view direction d and up vector k we build the
//! camera basis w, u, v; each ray is made in camera space as in lesson 03 and then
//! carried to the world: origin B o + p, direction B d.
//!
//!     cargo run --example 05_arbitrary_ortho_camera
//!     cargo run --example 05_arbitrary_ortho_camera -- --position 0,5,0 --direction 0,-1,0 --up 0,0,-1

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::camera::{Film, Frame, OrthoCamera};
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::{self, Output, parse_vec3};
use render_lessons::course::report::{Table, vec3};

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 05: an arbitrary orthographic camera")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Camera position p, as x,y,z.
    #[arg(long, default_value = "6,0,6", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub position: Vec3,
    /// View direction d, as x,y,z.
    #[arg(long, default_value = "-1,0,-1", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub direction: Vec3,
    /// Up vector k, as x,y,z.
    #[arg(long, default_value = "0,1,0", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub up: Vec3,
    /// Image width in pixels.
    #[arg(long, default_value_t = 4)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 3)]
    pub height: u32,
    #[command(flatten)]
    pub output: Output,
}

// ANCHOR: camera
/// The lesson's camera: lesson 03's plane [-8, 8] x [-6, 6], placed by p, d and k.
pub fn camera(args: &Args) -> Result<OrthoCamera> {
    let film = Film::new(args.width, args.height, (-8.0, 8.0), (-6.0, 6.0))?;
    let frame = Frame::look(args.position, args.direction, args.up)?;
    Ok(OrthoCamera::new(film, frame))
}
// ANCHOR_END: camera

/// The lesson's tables: the basis, then every pixel's ray in both spaces.
pub fn numbers(args: &Args) -> Result<String> {
    let cam = camera(args)?;
    let b = cam.frame().basis();
    let mut basis = Table::new(
        &format!(
            "Camera basis from p = {}, d = {}, k = {}",
            vec3(args.position, 3),
            vec3(args.direction, 3),
            vec3(args.up, 3)
        ),
        &["vector", "formula", "world coordinates"],
    );
    basis.row(vec!["w".into(), "-d/|d|".into(), vec3(b.w(), 4)]);
    basis.row(vec!["u".into(), "(k x w)/|k x w|".into(), vec3(b.u(), 4)]);
    basis.row(vec!["v".into(), "w x u".into(), vec3(b.v(), 4)]);
    let mut rays = Table::new(
        "Rays: made in camera space, then origin B o + p and direction B d",
        &["pixel", "camera origin", "world origin", "world direction"],
    );
    for y in 0..cam.film().height().min(6) {
        for x in 0..cam.film().width().min(6) {
            let (local, _) = cam.local_ray(x, y);
            let ray = cam.ray(x, y);
            rays.row(vec![
                format!("({x}, {y})"),
                vec3(local, 3),
                vec3(ray.origin(), 3),
                vec3(ray.direction(), 3),
            ]);
        }
    }
    Ok(format!("{basis}\n{rays}"))
}

/// The figure, seen from above (x to the right, -z up the page): the world axes, the
/// camera with its u and w, the plane edge-on, and the parallel rays of one image row.
pub fn top_figure(args: &Args) -> Result<Diagram> {
    let cam = camera(args)?;
    let frame = cam.frame();
    let top = |p: Vec3| Vec2::new(p.x, -p.z);
    let length = 14.0;
    let row = cam.film().height() / 2;
    let mut points = vec![Vec2::ZERO, top(frame.position())];
    for x in 0..cam.film().width() {
        let ray = cam.ray(x, row);
        points.extend([top(ray.origin()), top(ray.at(length))]);
    }
    let lo = points
        .iter()
        .copied()
        .fold(Vec2::splat(f32::MAX), Vec2::min)
        - 2.0;
    let hi = points
        .iter()
        .copied()
        .fold(Vec2::splat(f32::MIN), Vec2::max)
        + 2.0;
    let mut d = Diagram::new(800, 700, (lo.x, hi.x), (lo.y, hi.y))?;
    d.title("Seen from above: the camera basis and the rays of one image row, in world space");
    d.axes((lo.x, hi.x), (lo.y, hi.y), 2.0, ("x", "-z"));
    let (x0, x1) = cam.film().x_extent();
    let edge = [x0, x1].map(|x| top(frame.point_to_world(Vec3::new(x, 0.0, 0.0))));
    d.line(edge[0], edge[1], palette::PLANE, 4.0);
    d.text(edge[0], "projection plane", palette::PLANE, Place::Below);
    for x in 0..cam.film().width() {
        let ray = cam.ray(x, row);
        d.arrow(top(ray.origin()), top(ray.at(length)), palette::RAY, 1.5);
        d.dot(top(ray.origin()), 3.5, palette::HIT);
    }
    let p = top(frame.position());
    let basis = frame.basis();
    for (v, name, color) in [
        (basis.u(), "u", palette::X_AXIS),
        (basis.w(), "w", palette::Z_AXIS),
    ] {
        d.arrow(p, p + top(v) * 3.0, color, 3.5);
        d.text(p + top(v) * 3.0, name, color, Place::Right);
    }
    d.dot(p, 6.0, palette::CAMERA);
    d.text(p, "p", palette::CAMERA, Place::Below);
    Ok(d)
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        lesson::print(&numbers(&args)?);
        args.output
            .diagram("05_camera_from_above.png", &top_figure(&args)?)
    })
}
